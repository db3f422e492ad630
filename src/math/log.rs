//! Base-2 logarithms of fixed-point numbers from a table: what smooth escape-time colouring
//! needs per pixel, without floats.
use super::bits::leading_zeros;

/// log₂(1 + k/64) in Q16, k = 0..=64. A `static`, not a `const`: a constant array is
/// copied into every codegen unit that reads it, and the smallest boards' flash holds one.
static LOG2_TABLE: [u32; 65] = [
    0, 1466, 2909, 4331, 5732, 7112, 8473, 9814, 11136, 12440, 13727, 14996, 16248, 17484, 18704,
    19909, 21098, 22272, 23433, 24579, 25711, 26830, 27936, 29029, 30109, 31178, 32234, 33279,
    34312, 35334, 36346, 37346, 38336, 39316, 40286, 41246, 42196, 43137, 44068, 44990, 45904,
    46809, 47705, 48593, 49472, 50344, 51207, 52063, 52911, 53751, 54584, 55410, 56229, 57040,
    57845, 58643, 59434, 60219, 60997, 61769, 62534, 63294, 64047, 64794, 65536,
];

/// Fractional bits of [`log2`]'s result.
pub(crate) const LOG2_FRAC_BITS: u32 = 16;

/// log₂ of `value`, a number with `frac_bits` fractional bits (at most 63), in Q16: the
/// integer part from the leading bit, the rest from 64 table entries joined by straight
/// lines (within 2⁻¹² of the true logarithm). `None` for 0, whose logarithm is −∞.
///
/// In 32-bit operations, a word at a time: escape-time colouring and distance estimation
/// take two or three of these an escaping pixel, on cores without 64-bit shifts.
pub(crate) fn log2(value: u64, frac_bits: u32) -> Option<i32> {
    if value == 0 {
        return None;
    }
    let (high, low) = ((value >> 32) as u32, value as u32);
    // The leading one's place, and the 32 bits below it (zeros past the value's last bit)
    // as a fraction of it in Q32: the mantissa minus 1. Each shift is below 32 bits, and
    // the leading one is shifted out of the word.
    let (top, fraction) = if high == 0 {
        let zeros = leading_zeros(low);
        (31 - zeros, (low << zeros) << 1)
    } else {
        let zeros = leading_zeros(high);
        (63 - zeros, ((high << zeros) << 1) | (low >> (31 - zeros)))
    };
    // Entry k (below 64) and the 26 bits between k and k + 1.
    let (k, between) = ((fraction >> 26) as usize, fraction & ((1 << 26) - 1));
    let low = LOG2_TABLE.get(k).copied().unwrap_or(0);
    let high = LOG2_TABLE
        .get(k + 1)
        .copied()
        .unwrap_or(1 << LOG2_FRAC_BITS);
    let mantissa = (low + line_step(high - low, between)) as i32;
    // Within ±63·2¹⁶ + 2¹⁶: no overflow.
    let whole = top as i32 - frac_bits.min(63) as i32;
    Some((whole << LOG2_FRAC_BITS) + mantissa)
}

/// ⌊(`rise`·`between` + 2²⁵) / 2²⁶⌋: the line between two entries `rise` apart (below 2¹¹)
/// at `between` (below 2²⁶) of the way, rounded.
#[inline(always)]
fn line_step(rise: u32, between: u32) -> u32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        line_step_in_words(rise, between)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        ((u64::from(rise) * u64::from(between) + (1 << 25)) >> 26) as u32
    }
}

/// [`line_step`] in 32-bit products, for cores without a long multiply (where the 64-bit
/// product is a library call): `between`'s 13-bit halves times `rise` are each below
/// 2²⁴, and the floor of the sum of the high half's product and the low half's, taken
/// down 13 bits first, is the same.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
fn line_step_in_words(rise: u32, between: u32) -> u32 {
    let (high, low) = (between >> 13, between & 0x1FFF);
    (rise * high + ((rise * low + (1 << 25)) >> 13)) >> 13
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The line's step from 13-bit halves is the 64-bit one for every rise below 2¹¹ and
    /// betweens at their ends and spread over 2²⁶.
    #[test]
    fn line_steps_in_words_are_the_wide_ones() {
        for rise in 0..1u32 << 11 {
            for k in 0..=64u32 {
                let between = (k * 1_048_573).min((1 << 26) - 1) ^ (rise & 0x7F);
                let wide = ((u64::from(rise) * u64::from(between) + (1 << 25)) >> 26) as u32;
                assert_eq!(line_step_in_words(rise, between), wide, "{rise} {between}");
            }
        }
    }

    #[test]
    fn table_and_lines_follow_the_logarithm() {
        for (k, &entry) in LOG2_TABLE.iter().enumerate() {
            let exact = (1.0 + k as f64 / 64.0).log2() * 65536.0;
            assert!((f64::from(entry) - exact).abs() <= 0.5, "entry {k}");
        }
        let mut worst: f64 = 0.0;
        for i in 1..200_000u64 {
            let value = i * i * 7 + 13;
            for frac in [0, 16, 40] {
                let got = f64::from(log2(value, frac).unwrap()) / 65536.0;
                let exact = (value as f64).log2() - f64::from(frac);
                worst = worst.max((got - exact).abs());
            }
        }
        assert!(worst < 1.0 / 4096.0, "worst error {worst}");
        assert_eq!(log2(0, 3), None);
        assert_eq!(log2(1 << 20, 20), Some(0));
        assert_eq!(log2(3 << 19, 20), Some(38336));
    }

    /// The rule in 64-bit arithmetic, as the documentation states it: the leading bit's
    /// place, and the bits below it as a Q32 fraction placed between two table entries.
    fn log2_in_64_bits(value: u64, frac_bits: u32) -> Option<i32> {
        let top = value.checked_ilog2()?;
        let below = value ^ (1 << top);
        let fraction = if top >= 32 {
            below >> (top - 32)
        } else {
            below << (32 - top)
        };
        let k = (fraction >> 26) as usize;
        let (low, high) = (u64::from(LOG2_TABLE[k]), u64::from(LOG2_TABLE[k + 1]));
        let mantissa = low + (((high - low) * (fraction & ((1 << 26) - 1)) + (1 << 25)) >> 26);
        let whole = i64::from(top) - i64::from(frac_bits.min(63));
        i32::try_from((whole << LOG2_FRAC_BITS) + mantissa as i64).ok()
    }

    /// The 32-bit operations give the 64-bit rule's value at every leading bit's place,
    /// around every word boundary and at random values.
    #[test]
    fn words_give_the_rules_value() {
        let check = |value: u64| {
            for frac_bits in [0, 16, 20, 60, 63, 70] {
                assert_eq!(
                    log2(value, frac_bits),
                    log2_in_64_bits(value, frac_bits),
                    "{value:#x} with {frac_bits} fraction bits"
                );
            }
        };
        for value in [0, 1, 2, 3, u64::MAX, u64::MAX - 1, 1 << 63] {
            check(value);
        }
        for bit in 0..64 {
            let one = 1u64 << bit;
            let pattern = 0x5555_5555_5555_5555 >> (63 - bit);
            for value in [one, one - 1, one + 1, one | (one >> 1), one | pattern] {
                check(value);
            }
        }
        let mut random = crate::math::Generator::new(7);
        for _ in 0..200_000 {
            let value = u64::from(random.next_u32()) << 32 | u64::from(random.next_u32());
            check(value >> (value % 64));
        }
    }
}
