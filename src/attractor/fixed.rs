//! The attractors' arithmetic: 32-bit fixed point with a kind's fraction bits, products
//! in 64 bits, and every value that feeds another product checked back into 32 bits, so
//! an orbit that leaves its range stops with an error instead of wrapping.

use crate::math::trig::{binary_angle_of_radians, cos_of_binary, sin_of_binary};
use crate::math::wide::{mul_i32_wide, mul_u32_wide};
use crate::math::Real;

/// `a·b` with `F` fraction bits, rounded down, in 64 bits (never overflows).
#[inline(always)]
pub(super) fn mul<const F: u32>(a: i32, b: i32) -> i64 {
    mul_i32_wide(a, b) >> F
}

/// `a·b` with 32 fraction bits, rounded down: the high word of the product. For a factor
/// `a` of `F` fraction bits given as `a << (32 − F)` (see [`scaled_rate`]), exactly
/// `mul::<F>(a, b)`, and never beyond 32 bits.
#[inline(always)]
pub(super) fn high_word(a: i32, b: i32) -> i32 {
    crate::math::wide::mul_high(a, b)
}

/// A rate of `F` fraction bits below ½ as a factor of [`high_word`]: `rate << (32 − F)`,
/// or `None` where it does not fit (a rate of ½ or more).
pub(super) fn scaled_rate<const F: u32>(rate: i32) -> Option<i32> {
    let scaled = i64::from(rate) << (32 - F);
    i32::try_from(scaled).ok()
}

/// `a·b` with `F` fraction bits, rounded down, or `None` where it leaves 32 bits: the
/// same value as `narrow(mul::<F>(a, b))`, checked on the product's high word alone.
#[inline(always)]
pub(super) fn mul_narrow<const F: u32>(a: i32, b: i32) -> Option<i32> {
    let product = mul_i32_wide(a, b);
    let high = (product >> 32) as i32;
    // The shifted product fits where the high word's bits from F − 1 up are all equal.
    if high >> (F - 1) == high >> 31 {
        Some((product >> F) as i32)
    } else {
        None
    }
}

/// `value` back in 32 bits, or `None` where it left them.
#[inline(always)]
pub(super) fn narrow(value: i64) -> Option<i32> {
    i32::try_from(value).ok()
}

/// `value / 6`, rounded half away from zero.
#[inline(always)]
pub(super) fn sixth(value: i32) -> i32 {
    // |value| + 3 fits a u32; n / 6 = ⌊n·⌈2³⁴/6⌉ / 2³⁴⌋ for every u32 n (no division,
    // which ARMv6-M does not have).
    let magnitude = (mul_u32_wide(value.unsigned_abs() + 3, 0xAAAA_AAAB) >> 34) as i32;
    if value < 0 {
        -magnitude
    } else {
        magnitude
    }
}

/// A Q30 sine or cosine in `F` fraction bits, rounded down.
#[inline(always)]
fn from_q30<const F: u32>(value: i32) -> i32 {
    value >> (30 - F)
}

/// sin(x) in Q30 for x with `F` fraction bits.
#[inline(always)]
pub(super) fn sin_q30<const F: u32>(x: i32) -> i32 {
    sin_of_binary(binary_angle_of_radians(x, F))
}

/// cos(x) in Q30 for x with `F` fraction bits.
#[inline(always)]
pub(super) fn cos_q30<const F: u32>(x: i32) -> i32 {
    cos_of_binary(binary_angle_of_radians(x, F))
}

/// sin(x) for x with `F` fraction bits, in `F` fraction bits.
#[inline(always)]
pub(super) fn sin<const F: u32>(x: i32) -> i32 {
    from_q30::<F>(sin_q30::<F>(x))
}

/// cos(x) for x with `F` fraction bits, in `F` fraction bits.
#[inline(always)]
pub(super) fn cos<const F: u32>(x: i32) -> i32 {
    from_q30::<F>(cos_q30::<F>(x))
}

/// `c·sin(x)` or `c·cos(x)` from the Q30 value of the sine: one product, rounded down.
#[inline(always)]
pub(super) fn times_q30(c: i32, trig_q30: i32) -> i64 {
    mul_i32_wide(c, trig_q30) >> 30
}

/// A value in the fixed point of `bits` fraction bits, rounded to nearest; `None` beyond
/// the 32-bit range.
pub(super) fn to_fixed(value: Real, bits: u32) -> Option<i32> {
    let shift = Real::FRAC_BITS - bits;
    let bits = crate::math::wide::shift_round(i128::from(value.to_bits()), shift);
    i32::try_from(bits).ok()
}

/// A fixed-point value as a [`Real`] (exact).
pub(super) fn to_real(value: i32, bits: u32) -> Real {
    Real::from_bits(i64::from(value) << (Real::FRAC_BITS - bits))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// A sixth rounded half away from zero, against exact rationals in i64.
    #[test]
    fn sixth_rounds_half_away_from_zero() {
        let exact = |v: i32| -> i32 {
            let v = i64::from(v);
            let rounded = (2 * v.abs() + 6) / 12;
            (if v < 0 { -rounded } else { rounded }) as i32
        };
        for v in [
            i32::MIN,
            i32::MIN + 1,
            i32::MAX,
            i32::MAX - 2,
            -3,
            -2,
            2,
            3,
            0,
        ] {
            assert_eq!(sixth(v), exact(v), "{v}");
        }
        let mut runner = TestRunner::deterministic();
        runner
            .run(&any::<i32>(), |v| {
                prop_assert_eq!(sixth(v), exact(v));
                Ok(())
            })
            .unwrap();
    }
}
