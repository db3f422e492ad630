//! Distance estimation: how far an escaping point lies from the set, d ≈ |z|·ln|z| / |dz|,
//! so strands thinner than a pixel can be drawn as the set (Fractint's `distest`).
//!
//! The orbit is run again from its start, in Q28 with 32×32 → 64-bit products for the
//! 32-bit tiers and in Q60 with products' high words (perturbation's finish: within 2⁻⁵⁵ a
//! product) for `Deep` and `Wide`, one copy of the code each, with the derivative dz
//! (dz ← 2·z·dz + 1 for the Mandelbrot set, from
//! dz₁ = 1; dz ← 2·z·dz for a Julia set, from dz₀ = 1) carried beside it as a mantissa pair
//! and a shared exponent, since it grows as fast as the orbit runs. Past the escape both
//! go on to |z| ≥ 256, where the estimate holds, and d is compared through the log table:
//! no floats.

use super::arithmetic::{Arithmetic, HighWords};
use super::kernel::Kernel;
use super::view::{Tier, DISTANCE_INSIDE};
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
struct Derivative {
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
        let (x, y) = z;
        // On to |z| ≥ 256 in Q20, as the smooth value goes (`smooth_value`).
        let q20 = |v: i64| v >> 40;
        let (cr, ci) = (q20(c.0), q20(c.1));
        let (mut x, mut y) = (q20(x), q20(y));
        let mut steps = 0;
        while steps < STEPS_PAST_ESCAPE && x.abs() < RADIUS_Q20 && y.abs() < RADIUS_Q20 {
            let (x2, y2) = (x * x, y * y);
            if x2 + y2 >= RADIUS_Q20 * RADIUS_Q20 {
                break;
            }
            dz.step((x as i32, y as i32), 20, mandelbrot);
            (x, y) = (((x2 - y2) >> 20) + cr, ((2 * x * y) >> 20) + ci);
            steps += 1;
        }
        // |z|² in Q16 from Q8 parts (|z| < 2¹⁷ after the last step).
        let (x, y) = (x >> 12, y >> 12);
        let estimate = (|| {
            let log_square = i64::from(log2((x * x + y * y).unsigned_abs(), 16)?);
            let log_log = i64::from(log2(u64::try_from(log_square).ok()?, LOG2_FRAC_BITS)?);
            let numerator = log_square / 2 + log_log + LOG2_HALF_LN2;
            Some(numerator - dz.log2_magnitude()? - i64::from(self.spacing_log2))
        })();
        (estimate, k + steps)
    }

    /// The value of an escaped orbit from `first` (Q60) as distance estimation has it:
    /// one above the inside value if it lies within the estimate's width of the set (drawn
    /// as the set, told from it), the distance shading's value if the view shades by
    /// distance; `None` for the ordinary value. Also the steps the estimate took.
    pub(super) fn estimated(&self, first: (i64, i64), c: (i64, i64)) -> (Option<u32>, u32) {
        let (log2_pixels, steps) = match self.tier {
            Tier::Narrow | Tier::Medium | Tier::Standard => self.log2_distance::<false>(first, c),
            _ => self.log2_distance::<true>(first, c),
        };
        // The orbit run again in its own arithmetic may not escape where the tier's did (a
        // point at the boundary): the nearest the shading has, or the ordinary value.
        let Some(log2_pixels) = log2_pixels else {
            return (self.distance_shading.then_some(1), steps);
        };
        if self
            .near_log2
            .is_some_and(|near| log2_pixels < i64::from(near))
        {
            return (Some((self.inside + 1).min(u32::from(u16::MAX))), steps);
        }
        if self.distance_shading {
            let value = 1 + ((log2_pixels + (4 << LOG2_FRAC_BITS)) >> 12);
            let value = value.clamp(1, i64::from(DISTANCE_INSIDE) - 1);
            return (Some(value as u32), steps);
        }
        (None, steps)
    }
}
