//! Distance estimation: how far an escaping point lies from the set, d ≈ |z|·ln|z| / |dz|,
//! so strands thinner than a pixel can be drawn as the set (Fractint's `distest`).
//!
//! The orbit is run again from its start in Q60 with products' high words (perturbation's
//! finish: within 2⁻⁵⁵ a product; one copy of the code for every tier), with the derivative dz (dz ← 2·z·dz + 1 for the Mandelbrot set, from
//! dz₁ = 1; dz ← 2·z·dz for a Julia set, from dz₀ = 1) carried beside it as a mantissa pair
//! and a shared exponent, since it grows as fast as the orbit runs. Past the escape both
//! go on to |z| ≥ 256, where the estimate holds, and d is compared through the log table:
//! no floats.

use super::arithmetic::{Arithmetic, HighWords};
use super::kernel::Kernel;
use super::view::DISTANCE_INSIDE;
use crate::math::log::{log2, LOG2_FRAC_BITS};

/// log₂(ln 2 / 2) in Q16: ln|z| = log₂|z|² · ln 2 / 2.
const LOG2_HALF_LN2: i64 = -100_189;

/// Most steps the estimate takes past the escape to reach |z| ≥ 256.
const STEPS_PAST_ESCAPE: u32 = 32;

/// The escape radius of the estimate, in Q20.
const RADIUS_Q20: i64 = 256 << 20;

/// A derivative as a mantissa pair in Q30 and a shared exponent: (x + iy)·2^e, the larger
/// mantissa kept in [2²⁹, 2³¹) while e > −30.
struct Derivative {
    x: i64,
    y: i64,
    e: i32,
}

impl Derivative {
    const ONE: Self = Self {
        x: 1 << 30,
        y: 0,
        e: 0,
    };

    /// dz ← 2·z·dz, plus 1 if `plus_one`, z with `bits` fraction bits and |re|, |im| < 2²⁹
    /// in them (every product below 2⁶⁰).
    fn step(&mut self, (zx, zy): (i64, i64), bits: u32, plus_one: bool) {
        let shift = bits - 1;
        let x = (zx * self.x - zy * self.y) >> shift;
        let y = (zx * self.y + zy * self.x) >> shift;
        (self.x, self.y) = (x, y);
        // 1 is 2^(30 − e) in the mantissa; below its last bit past e = 30.
        if plus_one && (-30..=30).contains(&self.e) {
            self.x += 1 << (30 - self.e);
        }
        self.normalise();
    }

    fn normalise(&mut self) {
        let top = 63 - (self.x.unsigned_abs() | self.y.unsigned_abs() | 1).leading_zeros() as i32;
        if top > 30 {
            let down = top - 30;
            (self.x, self.y, self.e) = (self.x >> down, self.y >> down, self.e + down);
        } else if top < 29 && self.e > -30 {
            let up = (29 - top).min(self.e + 30);
            (self.x, self.y, self.e) = (self.x << up, self.y << up, self.e - up);
        }
    }

    /// log₂|dz| in Q16.
    fn log2_magnitude(&self) -> Option<i64> {
        let square = (self.x * self.x + self.y * self.y).unsigned_abs();
        let log = i64::from(log2(square, 60)?);
        Some(log / 2 + (i64::from(self.e) << LOG2_FRAC_BITS))
    }
}

impl Kernel {
    /// log₂ of the estimated distance, in pixels, of the orbit from `first` (z₁ = c for
    /// the Mandelbrot set, the pixel z₀ for a Julia set; Q60), Q16: d ≈ |z|·ln|z| / |dz|
    /// over the pixel spacing; `None` if the orbit does not escape by the cap. Also the
    /// steps it took.
    fn log2_distance(&self, first: (i64, i64), c: (i64, i64)) -> (Option<i64>, u32) {
        let mandelbrot = self.julia.is_none();
        let mut z = first;
        let mut dz = Derivative::ONE;
        let mut k = u32::from(mandelbrot);
        loop {
            let (x2, y2) = (HighWords::mul(z.0, z.0), HighWords::mul(z.1, z.1));
            if HighWords::escapes(x2, y2) {
                break;
            }
            if k >= self.max {
                return (None, k);
            }
            dz.step((z.0 >> 32, z.1 >> 32), 28, mandelbrot);
            z = HighWords::square_plus(z, (x2, y2), c);
            k += 1;
        }
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
            dz.step((x, y), 20, mandelbrot);
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
        let (log2_pixels, steps) = self.log2_distance(first, c);
        // The orbit run again in Q60 may not escape where the tier's did (a point at the
        // boundary): the nearest the shading has, or the ordinary value.
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
