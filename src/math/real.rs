//! `Real`: the turtle's number, signed fixed point with 32 integer and 32 fractional bits.
//!
//! Why I32F32: a sizing pass walks in turtle units (step 1), and deep curves reach millions
//! of units (the Koch curve at order 16 spans 3¹⁶ ≈ 4.3·10⁷), so 16 integer bits are too few;
//! 32 fractional bits keep the rounding of one step below 2⁻³², so even 2³¹ steps drift by
//! at most half a unit. Every operation is integer arithmetic, so results are bit-identical
//! on every target.

use core::fmt;

use fixed::types::I32F32;

use super::decimal::{parse_fixed, write_four_decimals};
use super::wide::{div_round, shift_round};

/// A signed fixed-point number with 32 integer and 32 fractional bits.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Real(I32F32);

/// Fixed-point `bits` with `fraction_bits` (1 to 32) fraction bits rounded to the nearest
/// integer, half away from zero, saturating at the i32 range: [`Real::round_to_i32`]'s
/// rule for any fixed point (the figure's Q16.16 pixels), in 64 bits on the magnitude.
#[inline(always)]
pub(crate) fn round_half_away(bits: i64, fraction_bits: u32) -> i32 {
    let magnitude = (bits.unsigned_abs() + (1 << (fraction_bits - 1))) >> fraction_bits;
    // At most 2³¹: the negative end reaches i32::MIN exactly, the positive one saturates.
    let magnitude = i64::try_from(magnitude).unwrap_or(i64::MAX);
    let rounded = if bits < 0 { -magnitude } else { magnitude };
    rounded.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

impl Real {
    /// Zero.
    pub const ZERO: Self = Self(I32F32::ZERO);
    /// One.
    pub const ONE: Self = Self(I32F32::ONE);
    /// Number of fractional bits.
    pub const FRAC_BITS: u32 = 32;

    /// From the raw bits (the value times 2³²).
    #[inline]
    pub const fn from_bits(bits: i64) -> Self {
        Self(I32F32::from_bits(bits))
    }

    /// The raw bits (the value times 2³²).
    #[inline]
    pub const fn to_bits(self) -> i64 {
        self.0.to_bits()
    }

    /// An integer, exactly.
    pub const fn from_int(value: i32) -> Self {
        Self::from_bits((value as i64) << 32)
    }

    /// The ratio `numerator / denominator`, rounded to the nearest representable value;
    /// `None` if the denominator is 0 or the result is out of range. A `const fn`, so tables
    /// can hold exact values such as 22.5 (`from_ratio(45, 2)`).
    pub const fn from_ratio(numerator: i64, denominator: i64) -> Option<Self> {
        if denominator == 0 {
            return None;
        }
        let bits = div_round((numerator as i128) << 32, denominator as i128);
        if bits < i64::MIN as i128 || bits > i64::MAX as i128 {
            return None;
        }
        Some(Self::from_bits(bits as i64))
    }

    /// Parses an unsigned decimal number such as `1.618034` or `.5`, rounded to nearest.
    pub fn parse_decimal(text: &str) -> Option<Self> {
        if text.starts_with(['-', '+']) {
            return None;
        }
        let bits = parse_fixed(text, Self::FRAC_BITS)?;
        i64::try_from(bits).ok().map(Self::from_bits)
    }

    /// Parses a decimal number with an optional sign (`-22.5`, `+3`, `.5`), rounded to
    /// nearest.
    pub fn parse_signed(text: &str) -> Option<Self> {
        let bits = parse_fixed(text, Self::FRAC_BITS)?;
        i64::try_from(bits).ok().map(Self::from_bits)
    }

    /// Checked addition.
    #[inline]
    pub fn checked_add(self, other: Self) -> Option<Self> {
        self.0.checked_add(other.0).map(Self)
    }

    /// Checked subtraction.
    #[inline]
    pub fn checked_sub(self, other: Self) -> Option<Self> {
        self.0.checked_sub(other.0).map(Self)
    }

    /// Saturating addition.
    #[inline]
    pub fn saturating_add(self, other: Self) -> Self {
        Self(self.0.saturating_add(other.0))
    }

    /// Saturating subtraction.
    #[inline]
    pub fn saturating_sub(self, other: Self) -> Self {
        Self(self.0.saturating_sub(other.0))
    }

    /// Checked multiplication, rounded to nearest.
    pub fn checked_mul(self, other: Self) -> Option<Self> {
        let product = i128::from(self.to_bits()) * i128::from(other.to_bits());
        i64::try_from(shift_round(product, 32))
            .ok()
            .map(Self::from_bits)
    }

    /// Checked division, rounded to nearest (halves away from zero); `None` on division by
    /// zero or overflow. In 64-bit arithmetic (a 128-bit division is a long library call on
    /// Cortex-M): |a|·2³² = (|a| div d)·d·2³² + (|a| mod d)·2³², and the second part's 32
    /// quotient bits come one at a time (the remainder stays below d ≤ 2⁶³, so doubling it
    /// fits).
    pub fn checked_div(self, other: Self) -> Option<Self> {
        let d = other.to_bits().unsigned_abs();
        if d == 0 {
            return None;
        }
        let a = self.to_bits().unsigned_abs();
        let (whole, mut rest) = (a / d, a % d);
        if whole >> 32 != 0 {
            return None;
        }
        let mut low = 0u64;
        for _ in 0..32 {
            rest <<= 1;
            low <<= 1;
            if rest >= d {
                rest -= d;
                low |= 1;
            }
        }
        // Round: the remainder and half the divisor (both below d) reach d at most once.
        let up = u64::from(rest >= d - d / 2);
        let magnitude = ((whole << 32) | low).checked_add(up)?;
        let negative = (self.to_bits() < 0) != (other.to_bits() < 0);
        let bits = if negative {
            0i64.checked_sub_unsigned(magnitude)?
        } else {
            i64::try_from(magnitude).ok()?
        };
        Some(Self::from_bits(bits))
    }

    /// The square root of a non-negative value (`None` for negatives), rounded down.
    pub fn checked_sqrt(self) -> Option<Self> {
        let bits = u128::try_from(self.to_bits()).ok()?;
        let root = (bits << 32).isqrt();
        i64::try_from(root).ok().map(Self::from_bits)
    }

    /// Times a Q30 factor (a sine or cosine), rounded half away from zero so that
    /// `x.mul_q30(-c) == -x.mul_q30(c)` exactly: symmetric headings give exactly opposite steps.
    ///
    /// Two 32×32→64 products instead of an i128 multiply, which is a library call on
    /// Cortex-M: |self|·|factor| = hi·|factor|·2³² + lo·|factor|, and 2³² is a multiple of
    /// 2³⁰, so the rounding only looks at the low product.
    #[inline]
    pub(crate) fn mul_q30(self, factor: i32) -> Self {
        let negative = (self.to_bits() < 0) != (factor < 0);
        let (a, b) = (
            self.to_bits().unsigned_abs(),
            u64::from(factor.unsigned_abs()),
        );
        let low = (a & 0xFFFF_FFFF) * b; // < 2^62
        let high = (a >> 32) * b; // < 2^62
        let magnitude = (high << 2).wrapping_add((low + (1 << 29)) >> 30);
        // |self·factor| / 2^30 <= |self| < 2^63: the magnitude fits in i64.
        let magnitude = magnitude as i64;
        Self::from_bits(if negative { -magnitude } else { magnitude })
    }

    /// Rounds to the nearest integer, half away from zero (saturating at the i32 range).
    /// In 64 bits on the magnitude (|bits| + 2³¹ fits a u64), not 128: this places every
    /// point an L-system draws.
    #[inline]
    pub fn round_to_i32(self) -> i32 {
        round_half_away(self.to_bits(), 32)
    }

    /// The value as `f64` (exact to 53 significant bits); for tests and host output.
    pub fn to_f64(self) -> f64 {
        self.to_bits() as f64 / 4_294_967_296.0
    }

    /// The nearest value to an `f64`; `None` if out of range or not finite. Set-up only.
    pub fn from_f64(value: f64) -> Option<Self> {
        I32F32::checked_from_num(value).map(Self)
    }

    /// The absolute value, saturating.
    pub fn abs(self) -> Self {
        Self(self.0.saturating_abs())
    }

    /// Writes the value rounded half away from zero to 4 decimals, trailing zeros dropped:
    /// how derived strings print numbers (`A(1.1429,0)`, `@0.5`).
    pub(crate) fn write_four_decimals(self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_four_decimals(f, self.to_bits(), Self::FRAC_BITS)
    }
}

impl fmt::Debug for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

/// Exact decimal; trailing digits are as many as the value needs to round-trip.
impl fmt::Display for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding to i32 in 64 bits against the 128-bit half-away-from-zero shift, at the
    /// halves, the ends of the range and over random values.
    #[test]
    fn rounds_to_i32_as_the_wide_shift_does() {
        use proptest::prelude::*;
        let wide = |bits: i64| {
            shift_round(i128::from(bits), 32).clamp(i128::from(i32::MIN), i128::from(i32::MAX))
                as i32
        };
        let half = 1i64 << 31;
        for bits in [
            0,
            half,
            -half,
            half - 1,
            -half + 1,
            3 * half,
            -3 * half,
            i64::MAX,
            i64::MIN,
            i64::MIN + 1,
            i64::from(i32::MAX) << 32,
            (i64::from(i32::MAX) << 32) + half,
            (i64::from(i32::MIN) << 32) + half,
            (i64::from(i32::MIN) << 32) + half + 1,
        ] {
            assert_eq!(Real::from_bits(bits).round_to_i32(), wide(bits), "{bits}");
        }
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(&any::<i64>(), |bits| {
                prop_assert_eq!(Real::from_bits(bits).round_to_i32(), wide(bits));
                Ok(())
            })
            .unwrap();
    }

    #[test]
    fn parses_decimals_exactly_rounded() {
        assert_eq!(Real::parse_decimal("0.5"), Some(Real::from_bits(1 << 31)));
        assert_eq!(Real::parse_decimal(".25"), Some(Real::from_bits(1 << 30)));
        assert_eq!(Real::parse_decimal("3"), Some(Real::from_int(3)));
        let golden = Real::parse_decimal("1.618034").map(Real::to_f64);
        assert!((golden.unwrap_or(0.0) - 1.618034).abs() < 1e-9);
        assert_eq!(Real::parse_decimal("1e5"), Some(Real::from_int(100_000)));
        for bad in ["", ".", "1.2.3", "-1", "1e", "99999999999", "-"] {
            assert_eq!(Real::parse_decimal(bad), None, "{bad}");
        }
        assert_eq!(Real::parse_signed("-22.5"), Real::from_ratio(-45, 2));
        assert_eq!(Real::parse_signed("+25.7"), Real::from_ratio(257, 10));
        assert_eq!(Real::parse_signed("--1"), None);
    }

    #[test]
    fn q30_products_are_symmetric() {
        let step = Real::from_bits(0x1_2345_6789);
        for c in [1 << 30, -(1 << 30), 123_456_789, 7, -7] {
            assert_eq!(step.mul_q30(c).to_bits(), -step.mul_q30(-c).to_bits());
        }
    }

    /// The split multiply equals the exact i128 product rounded half away from zero.
    #[test]
    fn q30_product_matches_the_wide_product() {
        let values = [
            0i64,
            1,
            -1,
            3,
            1 << 31,
            -(1 << 40) - 7,
            i64::MAX / 3,
            -(i64::MAX / 5),
            0x1234_5678_9ABC,
        ];
        let factors = [
            0i32,
            1,
            -1,
            1 << 30,
            -(1 << 30),
            536_870_912,
            -123_456_789,
            7,
        ];
        for &v in &values {
            for &f in &factors {
                let wide = shift_round(i128::from(v) * i128::from(f), 30) as i64;
                assert_eq!(Real::from_bits(v).mul_q30(f).to_bits(), wide, "{v} × {f}");
            }
        }
    }

    /// Division in 64 bits against the 128-bit rounded division, at the edges and over
    /// random values.
    #[test]
    fn divides_as_the_wide_division_does() {
        use proptest::prelude::*;
        let wide = |a: i64, b: i64| {
            (b != 0)
                .then(|| div_round(i128::from(a) << 32, i128::from(b)))
                .and_then(|q| i64::try_from(q).ok())
        };
        let edges = [
            0,
            1,
            -1,
            2,
            3,
            (1 << 31) - 1,
            1 << 31,
            1 << 32,
            (1 << 32) + 1,
            3 << 31,
            i64::from(u32::MAX),
            i64::MAX,
            i64::MIN,
            i64::MIN + 1,
            i64::MAX / 3,
            -(1 << 40),
        ];
        for a in edges {
            for b in edges {
                let got = Real::from_bits(a).checked_div(Real::from_bits(b));
                assert_eq!(got.map(Real::to_bits), wide(a, b), "{a} / {b}");
            }
        }
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let value = prop_oneof![any::<i64>(), (-1i64 << 40..1i64 << 40), (-1000i64..1000)];
        runner
            .run(&(value.clone(), value), |(a, b)| {
                let got = Real::from_bits(a).checked_div(Real::from_bits(b));
                prop_assert_eq!(got.map(Real::to_bits), wide(a, b));
                Ok(())
            })
            .unwrap();
    }

    #[test]
    fn sqrt_and_div() {
        let nine = Real::from_int(9);
        assert_eq!(nine.checked_sqrt(), Some(Real::from_int(3)));
        assert_eq!(Real::ONE.checked_div(Real::ZERO), None);
        assert_eq!(nine.checked_div(Real::from_int(3)), Some(Real::from_int(3)));
    }
}
