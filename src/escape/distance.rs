//! Distance estimation: how far an escaping point lies from the set, d ≈ |z|·ln|z| / |dz|,
//! so strands thinner than a pixel can be drawn as the set (Fractint's `distest`).
//!
//! The orbit is run again from its start, in Q28 with 32×32 → 64-bit products for the
//! 32-bit tiers and in Q60 with products' high words (perturbation's finish: within 2⁻⁵⁵ a
//! product) for `Deep` and `Wide`, one copy of the code each, with the derivative dz
//! (dz ← 2·z·dz + 1 for the Mandelbrot set, from
//! dz₁ = 1; dz ← 2·z·dz for a Julia set, from dz₀ = 1) carried beside it as a mantissa pair
//! and a shared exponent, since it grows as fast as the orbit runs. A perturbed pixel
//! carries its derivative beside its differences instead (`perturbation`), from the
//! series' own derivative at the skip, each step from the full point Zₘ + δ in a mantissa
//! and exponent of its own: at a deep zoom z passes far closer to 0 than any fixed point
//! holds while dz is huge. Past the escape both go on to |z| ≥ 256, where the estimate
//! holds, and d is compared through the log table: no floats.

use super::arithmetic::{Arithmetic, HighWords};
use super::kernel::Kernel;
use super::scaled::Scaled;
use super::view::Tier;
use crate::math::log::{log2, LOG2_FRAC_BITS};
use crate::math::wide::mul_i32_wide;

/// log₂(ln 2 / 2) in Q16: ln|z| = log₂|z|² · ln 2 / 2.
const LOG2_HALF_LN2: i64 = -100_189;

/// Most steps the estimate takes past the escape to reach |z| ≥ 256.
const STEPS_PAST_ESCAPE: u32 = 32;

/// The escape radius of the estimate, in Q20.
const RADIUS_Q20: i64 = 256 << 20;

/// A derivative as a mantissa pair in Q30 and a shared exponent: (x + iy)·2^e, the larger
/// mantissa kept in [2²⁹, 2³¹) while e > −30, so each fits 32 bits and a step's products
/// are 32×32 → 64 (one instruction on Cortex-M3 and M4).
pub(super) struct Derivative {
    x: i32,
    y: i32,
    e: i32,
}

impl Derivative {
    const ONE: Self = Self {
        x: 1 << 30,
        y: 0,
        e: 0,
    };

    /// dz₀ = 0: the derivative of the Mandelbrot set's z₀ = 0.
    pub(super) const ZERO: Self = Self { x: 0, y: 0, e: -30 };

    /// dz ← 2·z·dz, plus 1 if `plus_one`, z with `bits` fraction bits and |re|, |im| < 2³⁰
    /// in them (every product below 2⁶¹).
    #[inline(always)]
    fn step(&mut self, (zx, zy): (i32, i32), bits: u32, plus_one: bool) {
        let shift = bits - 1;
        let mut x = (mul_i32_wide(zx, self.x) - mul_i32_wide(zy, self.y)) >> shift;
        let y = (mul_i32_wide(zx, self.y) + mul_i32_wide(zy, self.x)) >> shift;
        // 1 is 2^(30 − e) in the mantissa; below its last bit past e = 30.
        if plus_one && (-30..=30).contains(&self.e) {
            x += 1 << (30 - self.e);
        }
        self.normalise(x, y);
    }

    /// dz ← 2·z·dz + 1, z = (x + iy)·2^−`s` with mantissas below 2⁶² (a perturbed pixel's
    /// point, of any size): its top 31 bits are taken, so the product keeps as many bits
    /// as [`step`](Self::step)'s.
    pub(super) fn step_scaled(&mut self, z: Scaled) {
        let (zx, zy) = ((z.x >> 31) as i32, (z.y >> 31) as i32);
        // z = (zx + i·zy)·2^(31 − s) and dz = (x + iy)·2^(e − 30): 2·z·dz is the
        // product p·2^(2 − s + e); taken down 30 bits, a mantissa in Q30 at exponent
        // e + 62 − s.
        let mut x = (mul_i32_wide(zx, self.x) - mul_i32_wide(zy, self.y)) >> 30;
        let mut y = (mul_i32_wide(zx, self.y) + mul_i32_wide(zy, self.x)) >> 30;
        let mut e = i64::from(self.e) + 62 - i64::from(z.s);
        if e < -30 {
            // Far below 1: kept at 1's exponent, where 1 has the mantissa's top bits.
            let down = (-30 - e).min(63);
            (x, y) = (x >> down, y >> down);
            e = -30;
        }
        self.e = e.min(i64::from(i32::MAX / 2)) as i32;
        if self.e <= 30 {
            x += 1 << (30 - self.e);
        }
        self.normalise(x, y);
    }

    /// The derivative (x + iy)·2^−`s` (mantissas below 2⁶², as [`Scaled`] keeps them).
    pub(super) fn of_scaled(value: Scaled) -> Self {
        let mut dz = Self {
            x: 0,
            y: 0,
            e: 62 - value.s,
        };
        dz.normalise(value.x >> 32, value.y >> 32);
        dz
    }

    /// The mantissas `x`, `y` (at the current exponent) brought back to [2²⁹, 2³¹).
    #[inline(always)]
    fn normalise(&mut self, x: i64, y: i64) {
        let top = 63 - (x.unsigned_abs() | y.unsigned_abs() | 1).leading_zeros() as i32;
        let (x, y) = if top > 30 {
            let down = top - 30;
            self.e += down;
            (x >> down, y >> down)
        } else if top < 29 && self.e > -30 {
            let up = (29 - top).min(self.e + 30);
            self.e -= up;
            (x << up, y << up)
        } else {
            (x, y)
        };
        // Below 2³¹ in magnitude either way.
        (self.x, self.y) = (x as i32, y as i32);
    }

    /// log₂|dz| in Q16.
    fn log2_magnitude(&self) -> Option<i64> {
        let square = (mul_i32_wide(self.x, self.x) + mul_i32_wide(self.y, self.y)).unsigned_abs();
        let log = i64::from(log2(square, 60)?);
        Some(log / 2 + (i64::from(self.e) << LOG2_FRAC_BITS))
    }
}

impl Kernel {
    /// log₂ of the estimated distance, in pixels, of the orbit from `first` (z₁ = c for
    /// the Mandelbrot set, the pixel z₀ for a Julia set; Q60), Q16: d ≈ |z|·ln|z| / |dz|
    /// over the pixel spacing; `None` if the orbit does not escape by the cap. Also the
    /// steps it took.
    fn log2_distance<const WIDE: bool>(
        &self,
        first: (i64, i64),
        c: (i64, i64),
    ) -> (Option<i64>, u32) {
        let mandelbrot = self.julia.is_none();
        let mut dz = Derivative::ONE;
        let mut k = u32::from(mandelbrot);
        // z in Q60 (`WIDE`: products' high words) or Q28 (32-bit values, 64-bit products).
        let z = if WIDE {
            let mut z = first;
            loop {
                let (x2, y2) = (HighWords::mul(z.0, z.0), HighWords::mul(z.1, z.1));
                if HighWords::escapes(x2, y2) {
                    break;
                }
                if k >= self.max {
                    return (None, k);
                }
                dz.step(((z.0 >> 32) as i32, (z.1 >> 32) as i32), 28, mandelbrot);
                z = HighWords::square_plus(z, (x2, y2), c);
                k += 1;
            }
            z
        } else {
            let q28 = |v: i64| (v >> 32) as i32;
            let (cr, ci) = (q28(c.0), q28(c.1));
            let (mut x, mut y) = (q28(first.0), q28(first.1));
            loop {
                let (x2, y2) = (mul_i32_wide(x, x) >> 28, mul_i32_wide(y, y) >> 28);
                if x2 + y2 > 4 << 28 {
                    break;
                }
                if k >= self.max {
                    return (None, k);
                }
                dz.step((x, y), 28, mandelbrot);
                // |z| ≤ 2 and |c| < 3.5: both parts stay below 8 (2³¹ in Q28).
                let xy = (mul_i32_wide(x, y) >> 27) as i32;
                (x, y) = ((x2 - y2) as i32 + cr, xy + ci);
                k += 1;
            }
            (i64::from(x) << 32, i64::from(y) << 32)
        };
        let (estimate, steps) = log2_pixels_past_escape(z, c, dz, mandelbrot, self.spacing_log2);
        (estimate, k + steps)
    }

    /// The value of an escaped orbit from `first` (Q60) as distance estimation has it (see
    /// [`Estimate::value`]): `None` for the ordinary value. Also the steps the estimate
    /// took.
    pub(super) fn estimated(&self, first: (i64, i64), c: (i64, i64)) -> (Option<u32>, u32) {
        let (log2_pixels, steps) = match self.tier {
            Tier::Narrow | Tier::Medium | Tier::Standard => self.log2_distance::<false>(first, c),
            _ => self.log2_distance::<true>(first, c),
        };
        let value = self
            .estimate
            .and_then(|estimate| estimate.value(log2_pixels, self.inside));
        (value, steps)
    }
}

/// log₂ of the estimated distance in pixels (Q16) of an orbit that escaped at z with
/// derivative `dz` (z and c in Q60), the pixel spacing 2^`spacing_log2` (Q16), taken on
/// to |z| ≥ 256 in Q20 as the smooth value goes (`smooth_value`); also the steps that
/// took.
pub(super) fn log2_pixels_past_escape(
    (x, y): (i64, i64),
    c: (i64, i64),
    mut dz: Derivative,
    plus_one: bool,
    spacing_log2: i32,
) -> (Option<i64>, u32) {
    let q20 = |v: i64| v >> 40;
    let (cr, ci) = (q20(c.0), q20(c.1));
    let (mut x, mut y) = (q20(x), q20(y));
    let mut steps = 0;
    while steps < STEPS_PAST_ESCAPE && x.abs() < RADIUS_Q20 && y.abs() < RADIUS_Q20 {
        let (x2, y2) = (x * x, y * y);
        if x2 + y2 >= RADIUS_Q20 * RADIUS_Q20 {
            break;
        }
        dz.step((x as i32, y as i32), 20, plus_one);
        (x, y) = (((x2 - y2) >> 20) + cr, ((2 * x * y) >> 20) + ci);
        steps += 1;
    }
    // |z|² in Q16 from Q8 parts (|z| < 2¹⁷ after the last step).
    let (x, y) = (x >> 12, y >> 12);
    let estimate = (|| {
        let log_square = i64::from(log2((x * x + y * y).unsigned_abs(), 16)?);
        let log_log = i64::from(log2(u64::try_from(log_square).ok()?, LOG2_FRAC_BITS)?);
        let numerator = log_square / 2 + log_log + LOG2_HALF_LN2;
        Some(numerator - dz.log2_magnitude()? - i64::from(spacing_log2))
    })();
    (estimate, steps)
}
