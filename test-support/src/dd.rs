//! Double-double numbers (about 106 bits) and the escape-time dwell in them.
//!
//! For the escape-time tests and the tier calibration.
//!
//! The reference where f64 runs out of bits (at the deep zoom a pixel is 2^-41.5, and f64 keeps
//! 2^-53).

/// A value as the sum of two f64s, the second below half an ulp of the first.
#[derive(Debug, Clone, Copy)]
pub struct Dd(pub f64, pub f64);

// Named like the operators, and called by name, so that a formula reads in the order of
// its rounding.
#[allow(clippy::should_implement_trait)]
impl Dd {
    /// From Q60 bits.
    pub fn from_q60(bits: i128) -> Self {
        let scale = (1u64 << 60) as f64;
        let hi = bits as f64 / scale;
        let rest = bits - (hi * scale) as i128;
        Dd(hi, rest as f64 / scale)
    }
    fn quick(a: f64, b: f64) -> Self {
        let s = a + b;
        Dd(s, b - (s - a))
    }
    /// The sum.
    pub fn add(self, o: Dd) -> Dd {
        let s = self.0 + o.0;
        let v = s - self.0;
        let e = (self.0 - (s - v)) + (o.0 - v) + self.1 + o.1;
        Dd::quick(s, e)
    }
    /// The negation.
    pub fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    /// The product.
    pub fn mul(self, o: Dd) -> Dd {
        let p = self.0 * o.0;
        let e = self.0.mul_add(o.0, -p) + self.0 * o.1 + self.1 * o.0;
        Dd::quick(p, e)
    }
    /// The product with `k`.
    pub fn scale(self, k: f64) -> Dd {
        self.mul(Dd(k, 0.0))
    }
}

/// The dwell of the point `p` in double-double: the smallest n ≥ 1 with |zₙ|² > 4, capped at
/// `max`. For a Julia set (`julia: Some(k)`) z₀ = p and c = k; for the Mandelbrot set
/// z₀ = 0 and c = p.
pub fn dwell(julia: Option<(Dd, Dd)>, p: (Dd, Dd), max: u32) -> u32 {
    let zero = Dd(0.0, 0.0);
    let (c, mut z) = match julia {
        None => (p, (zero, zero)),
        Some(k) => (k, p),
    };
    for n in 1..=max {
        let (x2, y2) = (z.0.mul(z.0), z.1.mul(z.1));
        z = (x2.add(y2.neg()).add(c.0), z.0.mul(z.1).scale(2.0).add(c.1));
        let m = z.0.mul(z.0).add(z.1.mul(z.1));
        if m.0 + m.1 > 4.0 {
            return n;
        }
    }
    max
}
