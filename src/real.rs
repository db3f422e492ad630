//! `Real`: the turtle's number, signed fixed point with 32 integer and 32 fractional bits.
//!
//! Why I32F32: a sizing pass walks in turtle units (step 1), and deep curves reach millions
//! of units (the Koch curve at order 16 spans 3¹⁶ ≈ 4.3·10⁷), so 16 integer bits are too few;
//! 32 fractional bits keep the rounding of one step below 2⁻³², so even 2³¹ steps drift by
//! at most half a unit. Every operation is integer arithmetic, so results are bit-identical
//! on every target.

use core::fmt;

use fixed::types::I32F32;

/// A signed fixed-point number with 32 integer and 32 fractional bits.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Real(I32F32);

impl Real {
    /// Zero.
    pub const ZERO: Self = Self(I32F32::ZERO);
    /// One.
    pub const ONE: Self = Self(I32F32::ONE);
    /// Number of fractional bits.
    pub const FRAC_BITS: u32 = 32;

    /// From the raw bits (the value times 2³²).
    pub const fn from_bits(bits: i64) -> Self {
        Self(I32F32::from_bits(bits))
    }

    /// The raw bits (the value times 2³²).
    pub const fn to_bits(self) -> i64 {
        self.0.to_bits()
    }

    /// An integer, exactly.
    pub const fn from_int(value: i32) -> Self {
        Self::from_bits((value as i64) << 32)
    }

    /// The ratio `numerator / denominator`, rounded to the nearest representable value;
    /// `None` if the denominator is 0 or the result is out of range.
    pub fn from_ratio(numerator: i64, denominator: i64) -> Option<Self> {
        if denominator == 0 {
            return None;
        }
        let scaled = i128::from(numerator) << 32;
        let bits = div_round(scaled, i128::from(denominator));
        i64::try_from(bits).ok().map(Self::from_bits)
    }

    /// Parses an unsigned decimal number such as `1.618034` or `.5`, rounded to nearest.
    pub fn parse_decimal(text: &str) -> Option<Self> {
        if text.starts_with(['-', '+']) {
            return None;
        }
        let bits = parse_fixed(text, Self::FRAC_BITS)?;
        i64::try_from(bits).ok().map(Self::from_bits)
    }

    /// Checked addition.
    pub fn checked_add(self, other: Self) -> Option<Self> {
        self.0.checked_add(other.0).map(Self)
    }

    /// Checked subtraction.
    pub fn checked_sub(self, other: Self) -> Option<Self> {
        self.0.checked_sub(other.0).map(Self)
    }

    /// Checked multiplication, rounded to nearest.
    pub fn checked_mul(self, other: Self) -> Option<Self> {
        let product = i128::from(self.to_bits()) * i128::from(other.to_bits());
        i64::try_from(shift_round(product, 32))
            .ok()
            .map(Self::from_bits)
    }

    /// Checked division, rounded to nearest; `None` on division by zero or overflow.
    pub fn checked_div(self, other: Self) -> Option<Self> {
        if other.to_bits() == 0 {
            return None;
        }
        let quotient = div_round(
            i128::from(self.to_bits()) << 32,
            i128::from(other.to_bits()),
        );
        i64::try_from(quotient).ok().map(Self::from_bits)
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
    pub fn round_to_i32(self) -> i32 {
        let rounded = shift_round(i128::from(self.to_bits()), 32);
        rounded.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32
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

/// Parses a decimal number with an optional sign (`-0.75`, `.5`, `3`) into fixed point with
/// `frac_bits` fractional bits (at most 62), rounded to nearest. Digits beyond the 19th
/// after the point are checked but cannot matter at 62 bits or fewer (10⁻¹⁹ < 2⁻⁶²·2),
/// so they are not used. `None` if malformed or beyond ±2⁶³.
pub(crate) fn parse_fixed(text: &str, frac_bits: u32) -> Option<i128> {
    let (negative, unsigned) = match text.as_bytes().first() {
        Some(b'-') => (true, text.get(1..)?),
        Some(b'+') => (false, text.get(1..)?),
        _ => (false, text),
    };
    let (int_part, frac_part) = unsigned.split_once('.').unwrap_or((unsigned, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if (int_part.is_empty() && frac_part.is_empty())
        || !all_digits(int_part)
        || !all_digits(frac_part)
    {
        return None;
    }
    let mut int: i128 = 0;
    for digit in int_part.bytes() {
        int = int.checked_mul(10)?.checked_add(i128::from(digit - b'0'))?;
        if int > i128::from(i64::MAX) {
            return None;
        }
    }
    let mut numerator: i128 = 0;
    let mut denominator: i128 = 1;
    for digit in frac_part.bytes().take(19) {
        numerator = numerator * 10 + i128::from(digit - b'0');
        denominator *= 10;
    }
    let magnitude =
        (int << frac_bits).checked_add(div_round(numerator << frac_bits, denominator))?;
    Some(if negative { -magnitude } else { magnitude })
}

/// The exact product of two u32. A single instruction on Cortex-M3/M4 (`umull`); on cores
/// without one (the `tinyfractal_no_long_multiply` cfg, set by build.rs for ARMv6-M) four
/// 16×16 products inline, about a third of the `__aeabi_lmul` call the compiler would make.
#[inline(always)]
pub(crate) fn mul_u32_wide(a: u32, b: u32) -> u64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_u32_halves(a, b)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        u64::from(a) * u64::from(b)
    }
}

/// The exact product of two u32 from 16-bit halves, in 32-bit arithmetic only.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_u32_halves(a: u32, b: u32) -> u64 {
    let (a_low, a_high) = (a & 0xFFFF, a >> 16);
    let (b_low, b_high) = (b & 0xFFFF, b >> 16);
    let (middle, middle_carry) = (a_low * b_high).overflowing_add(a_high * b_low);
    let (low, low_carry) = (a_low * b_low).overflowing_add(middle << 16);
    let high =
        a_high * b_high + (middle >> 16) + (u32::from(middle_carry) << 16) + u32::from(low_carry);
    (u64::from(high) << 32) | u64::from(low)
}

/// The exact product of two i32 (`smull`, or 16-bit halves: see [`mul_u32_wide`]).
#[inline(always)]
pub(crate) fn mul_i32_wide(a: i32, b: i32) -> i64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_i32_halves(a, b)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        i64::from(a) * i64::from(b)
    }
}

/// The exact product of two i32 from 16-bit halves of their magnitudes.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_i32_halves(a: i32, b: i32) -> i64 {
    // |a·b| ≤ 2^62: the magnitude fits in an i64.
    let magnitude = mul_u32_halves(a.unsigned_abs(), b.unsigned_abs()) as i64;
    if (a ^ b) < 0 {
        -magnitude
    } else {
        magnitude
    }
}

/// 2ab as (a + b)² − a² − b², given the squares, with (a + b)² from 16-bit halves: where
/// there is no long multiply (ARMv6-M) a square needs neither signs nor a fourth 16×16
/// product, so this costs about half a signed product. `a + b` must fit in an i32.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn twice_product_by_squares(a: i32, b: i32, a_squared: i64, b_squared: i64) -> i64 {
    let sum = (a + b).unsigned_abs();
    // (a + b)² ≤ 2^62 for a sum within i32. The compiler shares the two equal cross
    // products of a square: three 16×16 multiplies.
    let sum_squared = mul_u32_halves(sum, sum) as i64;
    sum_squared - a_squared - b_squared
}

/// The exact product of two i64 as i128, from four 32×32→64 products: an i128 multiply is
/// a library call on Cortex-M, and these are single instructions on M3/M4.
pub(crate) fn mul_wide(a: i64, b: i64) -> i128 {
    let negative = (a < 0) != (b < 0);
    let (a, b) = (a.unsigned_abs(), b.unsigned_abs());
    let (a_low, a_high) = (a as u32, (a >> 32) as u32);
    let (b_low, b_high) = (b as u32, (b >> 32) as u32);
    let middle = u128::from(mul_u32_wide(a_low, b_high)) + u128::from(mul_u32_wide(a_high, b_low));
    let magnitude = (u128::from(mul_u32_wide(a_high, b_high)) << 64)
        + (middle << 32)
        + u128::from(mul_u32_wide(a_low, b_low));
    // |a·b| < 2^126: the magnitude fits in i128.
    let magnitude = magnitude as i128;
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// `value / 2^shift` rounded half away from zero (so negation commutes), for one width.
macro_rules! shift_round_in {
    ($(#[$doc:meta])* $name:ident, $t:ty) => {
        $(#[$doc])*
        pub(crate) const fn $name(value: $t, shift: u32) -> $t {
            let half: $t = 1 << (shift - 1);
            if value >= 0 {
                (value + half) >> shift
            } else {
                -((-value + half) >> shift)
            }
        }
    };
}

shift_round_in!(
    /// `value / 2^shift`, rounded half away from zero.
    shift_round,
    i128
);
shift_round_in!(
    /// [`shift_round`] in 64 bits, for per-pixel work on 32-bit cores (a 128-bit shift costs
    /// a dozen instructions there). `|value| + 2^(shift-1)` must fit in an i64.
    shift_round_i64,
    i64
);

/// `numerator / denominator` rounded half away from zero; the denominator must not be 0.
pub(crate) const fn div_round(numerator: i128, denominator: i128) -> i128 {
    let negative = (numerator < 0) != (denominator < 0);
    let n = numerator.unsigned_abs();
    let d = denominator.unsigned_abs();
    let q = (n + d / 2) / d;
    if negative {
        -(q as i128)
    } else {
        q as i128
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_from_halves_are_exact() {
        let edges = [
            0,
            1,
            2,
            0xFFFF,
            0x1_0000,
            0x1_0001,
            0x7FFF_FFFF,
            0x8000_0000,
            u32::MAX,
        ];
        let mut state = 0x2545_F491_u32;
        let mut values = edges.to_vec();
        for _ in 0..2000 {
            // xorshift32: a spread of bit patterns, reproducible.
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            values.push(state);
        }
        for &a in &values {
            for &b in values.iter().step_by(37).chain(&edges) {
                assert_eq!(mul_u32_halves(a, b), u64::from(a) * u64::from(b), "{a} {b}");
                let (a, b) = (a as i32, b as i32);
                assert_eq!(mul_i32_halves(a, b), i64::from(a) * i64::from(b), "{a} {b}");
                // The sum must fit in an i32: halve both.
                let (a, b) = (a / 2, b / 2);
                let (a2, b2) = (i64::from(a) * i64::from(a), i64::from(b) * i64::from(b));
                assert_eq!(
                    twice_product_by_squares(a, b, a2, b2),
                    2 * i64::from(a) * i64::from(b),
                    "{a} {b}"
                );
            }
        }
    }

    #[test]
    fn parses_decimals_exactly_rounded() {
        assert_eq!(Real::parse_decimal("0.5"), Some(Real::from_bits(1 << 31)));
        assert_eq!(Real::parse_decimal(".25"), Some(Real::from_bits(1 << 30)));
        assert_eq!(Real::parse_decimal("3"), Some(Real::from_int(3)));
        let golden = Real::parse_decimal("1.618034").map(Real::to_f64);
        assert!((golden.unwrap_or(0.0) - 1.618034).abs() < 1e-9);
        for bad in ["", ".", "1.2.3", "-1", "1e5", "99999999999", "-"] {
            assert_eq!(Real::parse_decimal(bad), None, "{bad}");
        }
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

    #[test]
    fn wide_products_are_exact() {
        let values = [
            0i64,
            1,
            -1,
            i64::MAX,
            i64::MIN + 1,
            1 << 40,
            -(1 << 33) + 5,
            0x7FFF_FFFF,
            -0x8000_0001,
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(mul_wide(a, b), i128::from(a) * i128::from(b), "{a} × {b}");
            }
        }
    }

    #[test]
    fn sqrt_and_div() {
        let nine = Real::from_int(9);
        assert_eq!(nine.checked_sqrt(), Some(Real::from_int(3)));
        assert_eq!(Real::ONE.checked_div(Real::ZERO), None);
        assert_eq!(nine.checked_div(Real::from_int(3)), Some(Real::from_int(3)));
    }
}
