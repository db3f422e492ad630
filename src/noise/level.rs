//! A texture's value, or a sum of octaves, as one of a palette's [`LEVELS`]: rounded from
//! the value, or for a drawing's every pixel from the sum by one product, the same level.

use crate::math::wide::mul_u32_wide;
use crate::math::Real;

/// Levels a texture takes, 0 to 255: a palette of 256 entries shows each one.
pub const LEVELS: u16 = 256;

/// |sum|·n in 2⁻³², rounded, from the magnitude's halves (h, l) and a normaliser n below
/// 1: h·n + (l·n + 2³¹)/2³², where only the second part rounds. h < 2³¹, so it is below
/// 2⁶³: no overflow.
#[inline(always)]
pub(super) fn normalised_magnitude((high, low): (u32, u32), normaliser: u32) -> i64 {
    let rounded_low = (mul_u32_wide(low, normaliser) + (1 << 31)) >> 32;
    (mul_u32_wide(high, normaliser) + rounded_low) as i64
}

/// The level of a sum's texture (fBm's, `centred`, or turbulence's and the ridged
/// multifractal's) from the sum of octaves `sum` (2⁻³²) and a normaliser below 1 (in
/// 2⁻³², so two or more octaves): [`level_of`] the value [`Texture::finish`](super::Texture::finish) gives, the
/// same steps (normalise, centre, clamp, scale) in 32-bit parts and no checks, for a
/// drawing's every pixel. `sum` must be within ±2⁶² (a sum of 16 octaves is within ±17).
#[inline(always)]
pub(super) fn sum_level(sum: i64, normaliser: u32, centred: bool) -> u8 {
    let magnitude = sum.unsigned_abs();
    let rounded = normalised_magnitude(((magnitude >> 32) as u32, magnitude as u32), normaliser);
    let one = 1_i64 << Real::FRAC_BITS;
    let unit = if centred {
        // (value + 1) / 2, rounded half away from zero, as `finish` centres: a value
        // below −1 halves to at most 0, level 0.
        let shifted = if sum < 0 {
            one - rounded
        } else {
            one + rounded
        };
        if shifted < 0 {
            return 0;
        }
        (shifted + 1) >> 1
    } else if sum < 0 {
        return 0;
    } else {
        rounded
    };
    // As `level_of`, whose clamp below is spent here already (every path above is at
    // least 0).
    unit_level(unit)
}

/// A row of sums' levels by one product each: [`sum_level`]'s levels, for a drawing's
/// every pixel, where its rounding steps cost more than the sum's level needs.
///
/// The level is ⌊F⌋ clamped to 0 to 255, F being the level's real value before rounding
/// (128 + 127.5·n·s centred, ½ + 255·n·s otherwise, for the sum s and normaliser n),
/// which `sum_level`'s roundings move by under 2⁻²³. Here F is taken in 2⁻¹⁵ from the sum
/// in 2⁻²⁴ (rounded down) times the slope rounded to 2⁻²³, the product's high word: within
/// 2⁻¹⁴ of F for sums within ±17 (16 octaves). Where that lands within 2⁻¹³ of a whole
/// level (about one sum in 4,000), the level is `sum_level`'s own.
#[derive(Debug, Clone, Copy)]
pub(super) struct SumLevels {
    /// 127.5·n (centred) or 255·n, in 2⁻²³, rounded to an even number.
    slope: u32,
    /// F's start (128 or ½, in 2⁻¹⁵) less half the slope: the product is taken of the
    /// sum plus 2³¹ (unsigned, one `umull`), which adds exactly slope/2 to its high word.
    start: i32,
    normaliser: u32,
    centred: bool,
}

impl SumLevels {
    /// F in 2⁻¹⁵ beside the level's bits (a level is F's bits from 15 up).
    const FRACTION_BITS: u32 = 15;
    /// How far (in 2⁻¹⁵) the product may land from F: at most 2, twice that for margin.
    const MARGIN: i32 = 4;

    /// The levels of sums normalised by `normaliser` (below 1, in 2⁻³²), centred (fBm's)
    /// or not (turbulence's and the ridged multifractal's), as [`sum_level`] takes them.
    pub(super) fn new(normaliser: u32, centred: bool) -> Self {
        // 255·n·2²² (or half of it), rounded, doubled: below 255·2²³ < 2³².
        let shift = if centred { 11 } else { 10 };
        // A 32 × 32-bit product: no 64-bit multiply (a library call on ARMv6-M) a row.
        let times_last = mul_u32_wide(normaliser, u32::from(LEVELS - 1));
        let half = (times_last + (1 << (shift - 1))) >> shift;
        let slope = (half as u32) << 1;
        // 128, or ½.
        let offset: i32 = if centred {
            128 << Self::FRACTION_BITS
        } else {
            1 << (Self::FRACTION_BITS - 1)
        };
        Self {
            slope,
            start: offset - half as i32,
            normaliser,
            centred,
        }
    }

    /// The level of `sum` (in 2⁻³², within ±17): the same as [`sum_level`]'s.
    #[inline(always)]
    pub(super) fn level(&self, sum: i64) -> u8 {
        let fine = self.product(sum) + self.start;
        let edge =
            (fine.wrapping_add(Self::MARGIN) & ((1 << Self::FRACTION_BITS) - 1)) < 2 * Self::MARGIN;
        if edge {
            return self.exact(sum);
        }
        (fine >> Self::FRACTION_BITS).clamp(0, i32::from(LEVELS - 1)) as u8
    }

    /// The slope times the sum in 2⁻²⁴ (rounded down; within ±17·2²⁴, so it fits a word)
    /// plus 2³¹, the product's high word: one `umull` of unsigned factors where there is a
    /// long multiply, and 16-bit halves where there is not
    /// ([`product_in_halves`](Self::product_in_halves)).
    #[inline(always)]
    fn product(&self, sum: i64) -> i32 {
        #[cfg(tinyfractal_no_long_multiply)]
        {
            self.product_in_halves(sum)
        }
        #[cfg(not(tinyfractal_no_long_multiply))]
        {
            (mul_u32_wide((sum >> 8) as u32 ^ (1 << 31), self.slope) >> 32) as i32
        }
    }

    /// [`product`](Self::product) from the sum in 2⁻²⁴ as it is, below 2²⁹ in magnitude:
    /// its product's high word plus half the slope (the slope is even, so the half is
    /// whole), in 16-bit halves whose middle products fit one word
    /// ([`mul_high_near`](crate::math::wide::mul_high_near)).
    #[cfg(any(test, tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn product_in_halves(&self, sum: i64) -> i32 {
        // The slope is below 255·2²³ < 2³¹.
        let slope = self.slope as i32;
        crate::math::wide::mul_high_near(slope, (sum >> 8) as i32) + (slope >> 1)
    }

    /// [`sum_level`], for the sums whose product lands near a level's edge.
    #[cold]
    #[inline(never)]
    fn exact(&self, sum: i64) -> u8 {
        sum_level(sum, self.normaliser, self.centred)
    }
}

/// A value in [0, 1] as a level 0 to 255, rounded to nearest (clamped first): the
/// value's 2⁻³² units times 255, in one 32×32 → 64-bit product below 1.
#[inline]
pub(super) fn level_of(value: Real) -> u8 {
    unit_level(value.clamp(Real::ZERO, Real::ONE).to_bits())
}

/// A value of at least 0 in 2⁻³² as a level: times 255, rounded to nearest; 1 and above
/// the last level. What [`level_of`] and [`sum_level`] end with.
#[inline(always)]
fn unit_level(unit: i64) -> u8 {
    match u32::try_from(unit) {
        Ok(unit) => ((mul_u32_wide(unit, u32::from(LEVELS - 1)) + (1 << 31)) >> 32) as u8,
        Err(_) => (LEVELS - 1) as u8,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sum's level by [`SumLevels`] is [`sum_level`]'s: over random sums, and at every
    /// level's edge (the sums about where F, found in f64, is a whole level), where the
    /// product alone would round either way.
    #[test]
    fn sum_levels_by_one_product_are_sum_levels() {
        use proptest::prelude::*;
        use proptest::test_runner::TestRunner;
        let bound = 17_i64 << 32;
        let cases = (1..(1_i64 << 32), any::<bool>(), -bound..bound);
        TestRunner::deterministic()
            .run(&cases, |(normaliser, centred, sum)| {
                let normaliser = normaliser as u32;
                let levels = SumLevels::new(normaliser, centred);
                prop_assert_eq!(levels.level(sum), sum_level(sum, normaliser, centred));
                // ARMv6-M's product from halves, here and at the sums' ends.
                for sum in [sum, -bound, bound - 1] {
                    let unsigned = (sum >> 8) as u32 ^ (1 << 31);
                    let product = (u64::from(unsigned) * u64::from(levels.slope)) >> 32;
                    prop_assert_eq!(levels.product_in_halves(sum), product as i32);
                }
                // Every edge: F = L at s = (L − 128)/(127.5·n) centred, (L − ½)/(255·n) not.
                let n = f64::from(normaliser) / 2f64.powi(32);
                for edge in 0..=256 {
                    let s = if centred {
                        (f64::from(edge) - 128.0) / (127.5 * n)
                    } else {
                        (f64::from(edge) - 0.5) / (255.0 * n)
                    };
                    let at = (s * 2f64.powi(32)) as i64;
                    if !(-bound..bound).contains(&at) {
                        continue;
                    }
                    for sum in (at - 600..at + 600).step_by(7).chain([at - 1, at, at + 1]) {
                        prop_assert_eq!(
                            levels.level(sum),
                            sum_level(sum, normaliser, centred),
                            "sum {} normaliser {} centred {}",
                            sum,
                            normaliser,
                            centred
                        );
                    }
                }
                Ok(())
            })
            .unwrap();
    }
}
