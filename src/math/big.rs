//! `DeepCoord`: a coordinate with as many bits as the deepest zoom needs (192, Q4.188),
//! parsed exactly from decimal text, and the few operations a reference orbit needs:
//! add, subtract, and a product that only works on the limbs a view asks for.
//!
//! Limbs are `u32`, least significant first, in two's complement: the carry chains and the
//! 32×32→64 products are single instructions on Cortex-M3/M4, and the same on every core.

use core::fmt;

use super::coord::Coord;
use super::decimal::{split_decimal, write_scientific_digits, DecimalText};
use super::wide::mul_u32_wide;

/// Limbs of a [`DeepCoord`].
pub const DEEP_LIMBS: usize = 6;

/// Most digits after the decimal point a [`DeepCoord`] takes: 10⁻⁵⁶ is above its unit
/// (2⁻¹⁸⁸ ≈ 2.5·10⁻⁵⁷), so every such digit moves the value; a 57th could not.
pub const MAX_DECIMAL_PLACES: u32 = 56;

/// Scratch limbs for parsing: the digits (below 10⁵⁸ < 2¹⁹³) times 2¹⁸⁹.
const SCRATCH: usize = 13;

/// A coordinate of the complex plane with 188 fractional bits (Q4.188, within ±8): the
/// centre of a deep zoom, and the numbers of its reference orbit.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct DeepCoord {
    limbs: [u32; DEEP_LIMBS],
}

/// Why decimal text is not a [`DeepCoord`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DeepParseError {
    /// Not a decimal number (`-0.75`, `.5`, `1e-30`, `1.25E+2`).
    Malformed,
    /// The number's last digit is further than [`MAX_DECIMAL_PLACES`] places after the
    /// point: finer than the deepest precision tells apart.
    TooManyDigits {
        /// Places after the point of its last non-zero digit.
        places: u32,
        /// The most there may be.
        max: u32,
    },
    /// The magnitude is 8 or more.
    OutOfRange,
}

impl fmt::Display for DeepParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Malformed => {
                f.write_str("not a decimal number (examples: -0.743643887, .5, 1e-30, -1.25E-2)")
            }
            Self::TooManyDigits { places, max } => write!(
                f,
                "its last digit is {places} places after the point; the deepest precision \
                 (2^-188) tells apart at most {max}"
            ),
            Self::OutOfRange => f.write_str("its magnitude is 8 or more; coordinates are below 8"),
        }
    }
}

impl DeepCoord {
    /// Fractional bits.
    pub const FRAC_BITS: u32 = 32 * DEEP_LIMBS as u32 - 4;

    /// Zero.
    pub const ZERO: Self = Self {
        limbs: [0; DEEP_LIMBS],
    };

    /// Parses decimal text with an optional sign and exponent (`-0.743643887037158704752191506114774`,
    /// `1e-30`, `2.5E-3`), rounded to nearest from every digit given (half away from zero).
    pub fn parse(text: &str) -> Result<Self, DeepParseError> {
        let DecimalText {
            negative,
            digits: text,
            power,
        } = split_decimal(text).ok_or(DeepParseError::Malformed)?;
        // The value is `digits` × 10^`exponent`; `digits` as decimal digit values.
        let mut digits = [0u8; 64];
        let mut count = 0usize;
        let mut exponent: i64 = 0;
        let mut after_point = false;
        for &byte in text {
            if byte == b'.' {
                after_point = true;
            } else if count > 0 || byte != b'0' {
                // Too many significant digits are too many places, or too large a number.
                let Some(slot) = digits.get_mut(count) else {
                    return Err(if after_point {
                        DeepParseError::TooManyDigits {
                            places: u32::try_from(1 - exponent).unwrap_or(u32::MAX),
                            max: MAX_DECIMAL_PLACES,
                        }
                    } else {
                        DeepParseError::OutOfRange
                    });
                };
                *slot = byte - b'0';
                count += 1;
                if after_point {
                    exponent -= 1;
                }
            } else if after_point {
                exponent -= 1;
            }
        }
        exponent += power;
        // Trailing zeros of the digits say nothing.
        while count > 0 && digits.get(count - 1) == Some(&0) {
            count -= 1;
            exponent += 1;
        }
        if count == 0 {
            return Ok(Self::ZERO);
        }
        // The magnitude is below 10^(count + exponent); 8 or more is out of range.
        if count as i64 + exponent > 1 {
            return Err(DeepParseError::OutOfRange);
        }
        if exponent < -i64::from(MAX_DECIMAL_PLACES) {
            return Err(DeepParseError::TooManyDigits {
                places: u32::try_from(-exponent).unwrap_or(u32::MAX),
                max: MAX_DECIMAL_PLACES,
            });
        }
        // digits × 2^(FRAC_BITS + 1), then divided by 10^-exponent (or multiplied by
        // 10^exponent): floor division in steps of ten is floor division by the power.
        let mut scratch = [0u32; SCRATCH];
        for &digit in digits.iter().take(count) {
            scale_add(&mut scratch, 10, u32::from(digit));
        }
        shift_left(&mut scratch, Self::FRAC_BITS + 1);
        if exponent >= 0 {
            for _ in 0..exponent {
                scale_add(&mut scratch, 10, 0);
            }
        } else {
            for _ in 0..-exponent {
                divide_small(&mut scratch, 10);
            }
        }
        // Round half up on the magnitude: (floor(2x) + 1) / 2.
        scale_add(&mut scratch, 1, 1);
        shift_right(&mut scratch, 1);
        // Below 8: the top bit of the value's limbs and everything above them are clear.
        let top = scratch.get(DEEP_LIMBS - 1).copied().unwrap_or(0);
        if top >= 1 << 31 || scratch.iter().skip(DEEP_LIMBS).any(|&limb| limb != 0) {
            return Err(DeepParseError::OutOfRange);
        }
        let mut value = Self::ZERO;
        for (to, from) in value.limbs.iter_mut().zip(scratch) {
            *to = from;
        }
        Ok(if negative { value.neg() } else { value })
    }

    /// The same value as a [`Coord`] (exact: Q60 is a prefix of Q188).
    pub const fn from_coord(value: Coord) -> Self {
        let bits = value.to_bits();
        // Q60 to Q188: shifted 128 bits, four limbs, with the sign extended above.
        let high = if bits < 0 { u32::MAX } else { 0 };
        let mut limbs = [high; DEEP_LIMBS];
        limbs[0] = 0;
        limbs[1] = 0;
        limbs[2] = 0;
        limbs[3] = 0;
        limbs[4] = bits as u32;
        limbs[5] = (bits >> 32) as u32;
        Self { limbs }
    }

    /// The nearest [`Coord`], rounded half up (the 128 bits it cannot hold).
    pub fn to_coord(self) -> Coord {
        let rounded = self.add(Self::unit_at(127));
        let limbs = rounded.limbs;
        let high = i64::from(limbs[5] as i32) << 32 | i64::from(limbs[4]);
        Coord::from_bits(high)
    }

    /// The value as `f64` (for tests and host output).
    pub fn to_f64(self) -> f64 {
        let magnitude = self.magnitude();
        let mut value = 0.0;
        for (k, &limb) in magnitude.iter().enumerate() {
            value += f64::from(limb) * pow2(32 * k as i32 - Self::FRAC_BITS as i32);
        }
        if self.is_negative() {
            -value
        } else {
            value
        }
    }

    /// Whether the value is zero.
    pub const fn is_zero(&self) -> bool {
        matches!(self.limbs, [0, 0, 0, 0, 0, 0])
    }

    /// Whether the value is below zero.
    pub const fn is_negative(&self) -> bool {
        self.limbs[DEEP_LIMBS - 1] >= 1 << 31
    }

    /// 2^(bit − FRAC_BITS): one in bit `bit` of the limbs.
    pub(crate) fn unit_at(bit: u32) -> Self {
        let mut limbs = [0; DEEP_LIMBS];
        if let Some(limb) = limbs.get_mut((bit / 32) as usize) {
            *limb = 1 << (bit % 32);
        }
        Self { limbs }
    }

    /// The sum (wrapping outside ±8, which no caller reaches).
    #[must_use]
    pub(crate) fn add(self, other: Self) -> Self {
        let mut limbs = [0; DEEP_LIMBS];
        let mut carry = 0u64;
        for ((sum, a), b) in limbs.iter_mut().zip(self.limbs).zip(other.limbs) {
            let total = u64::from(a) + u64::from(b) + carry;
            *sum = total as u32;
            carry = total >> 32;
        }
        Self { limbs }
    }

    /// The difference.
    #[must_use]
    pub(crate) fn sub(self, other: Self) -> Self {
        self.add(other.neg())
    }

    /// The negation.
    #[must_use]
    pub(crate) fn neg(self) -> Self {
        let mut limbs = self.limbs.map(|limb| !limb);
        for limb in &mut limbs {
            let (sum, carry) = limb.overflowing_add(1);
            *limb = sum;
            if !carry {
                break;
            }
        }
        Self { limbs }
    }

    /// The magnitude's limbs.
    fn magnitude(self) -> [u32; DEEP_LIMBS] {
        if self.is_negative() {
            self.neg().limbs
        } else {
            self.limbs
        }
    }

    /// The value with only its top `limbs` limbs kept (the rest of the magnitude cut,
    /// toward zero): the precision a view works in.
    #[must_use]
    pub(crate) fn truncated(self, limbs: usize) -> Self {
        let mut magnitude = self.magnitude();
        let drop = DEEP_LIMBS.saturating_sub(limbs);
        for limb in magnitude.iter_mut().take(drop) {
            *limb = 0;
        }
        Self::with_sign(magnitude, self.is_negative())
    }

    fn with_sign(magnitude: [u32; DEEP_LIMBS], negative: bool) -> Self {
        let value = Self { limbs: magnitude };
        if negative {
            value.neg()
        } else {
            value
        }
    }

    /// The product, its magnitude cut toward zero to the top `limbs` limbs. Only the top
    /// `limbs` limbs of each factor are read (both are expected to have been truncated
    /// to them), so a view pays for the precision it needs. Both magnitudes must be below
    /// 8 and the product's too.
    #[must_use]
    pub(crate) fn mul(self, other: Self, limbs: usize) -> Self {
        let (a, b) = (self.magnitude(), other.magnitude());
        let low = DEEP_LIMBS.saturating_sub(limbs.clamp(1, DEEP_LIMBS));
        // Limb k of a product is at bit 32·k of 2^(2·FRAC_BITS) units.
        let mut product = [0u32; 2 * DEEP_LIMBS + 1];
        for (i, &x) in a.iter().enumerate().skip(low) {
            let mut carry = 0u64;
            let row = product.iter_mut().skip(i);
            for (slot, &y) in row.zip(b.iter()).skip(low) {
                let total = mul_u32_wide(x, y) + u64::from(*slot) + carry;
                *slot = total as u32;
                carry = total >> 32;
            }
            for slot in product.iter_mut().skip(i + DEEP_LIMBS) {
                if carry == 0 {
                    break;
                }
                let total = u64::from(*slot) + carry;
                *slot = total as u32;
                carry = total >> 32;
            }
        }
        shift_right(&mut product, Self::FRAC_BITS);
        let mut magnitude = [0u32; DEEP_LIMBS];
        for (limb, &from) in magnitude.iter_mut().zip(product.iter()).skip(low) {
            *limb = from;
        }
        Self::with_sign(magnitude, self.is_negative() != other.is_negative())
    }

    /// The value divided by `divisor` (not 0), the magnitude cut toward zero.
    #[must_use]
    pub(crate) fn div_small(self, divisor: u32) -> Self {
        let mut magnitude = self.magnitude();
        divide_small(&mut magnitude, divisor.max(1));
        Self::with_sign(magnitude, self.is_negative())
    }

    /// Where the magnitude's highest set bit is (0 for the unit 2⁻¹⁸⁸), `None` for zero.
    pub(crate) fn top_bit(self) -> Option<u32> {
        let magnitude = self.magnitude();
        magnitude
            .iter()
            .enumerate()
            .rev()
            .find(|(_, &limb)| limb != 0)
            .map(|(k, &limb)| 32 * k as u32 + 31 - limb.leading_zeros())
    }

    /// The value times 2^(shift − FRAC_BITS)... that is, bits `shift` and up of the value
    /// as an integer: the value divided by 2^`shift` units, rounded toward −∞ like an
    /// arithmetic shift. The result must fit an i64 (the caller picks `shift` so).
    pub(crate) fn bits_from(self, shift: u32) -> i64 {
        let mut limbs = self.limbs;
        let negative = self.is_negative();
        shift_right(&mut limbs, shift);
        if negative && shift > 0 {
            // Sign-extend what the logical shift cleared.
            let fill = 32 * DEEP_LIMBS as u32 - shift.min(32 * DEEP_LIMBS as u32);
            set_bits_from(&mut limbs, fill);
        }
        (i64::from(limbs[1]) << 32) | i64::from(limbs[0])
    }

    /// The value times 2^`shift` (within ±8 for the result; bits shifted out are lost).
    #[must_use]
    pub(crate) fn shl(self, shift: u32) -> Self {
        let mut limbs = self.limbs;
        shift_left(&mut limbs, shift);
        Self { limbs }
    }
}

/// The nearest `f64`'s digits: for messages, not for reading back.
impl fmt::Display for DeepCoord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.to_f64(), f)
    }
}

/// The nearest `f64` in scientific notation, for messages about tiny spacings: with the
/// precision given (`{:.4e}`), as `f64` writes it but for a last digit that may differ by
/// one where the value is within 10⁻¹⁴ of a tie; without, six decimals at most.
impl fmt::LowerExp for DeepCoord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_scientific(f, self.to_f64(), f.precision())
    }
}

impl fmt::Debug for DeepCoord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("DeepCoord(")?;
        write_scientific(f, self.to_f64(), None)?;
        f.write_str(")")
    }
}

/// Writes `value` (finite) in scientific notation, `precision` decimals (at most 15), or
/// up to six with trailing zeros dropped if `None`. In f64 arithmetic, scaled by tens:
/// `f64`'s own exact formatting would cost a firmware far more flash, for error messages.
fn write_scientific(
    f: &mut fmt::Formatter<'_>,
    value: f64,
    precision: Option<usize>,
) -> fmt::Result {
    let decimals = precision.map_or(6, |p| p.min(15));
    let sign = if value < 0.0 { "-" } else { "" };
    let mut magnitude = if value < 0.0 { -value } else { value };
    let mut exponent = 0i32;
    if magnitude > 0.0 {
        while magnitude >= 10.0 {
            magnitude /= 10.0;
            exponent += 1;
        }
        while magnitude < 1.0 {
            magnitude *= 10.0;
            exponent -= 1;
        }
    }
    let scale = (0..decimals).fold(1u64, |scale, _| scale * 10);
    // Rounded half up; 9.99995 may round to 10.0000, one more power of ten.
    let mut digits = (magnitude * scale as f64 + 0.5) as u64;
    if digits >= 10 * scale {
        digits /= 10;
        exponent += 1;
    }
    let (whole, mut fraction) = (digits / scale, digits % scale);
    let mut width = decimals;
    if precision.is_none() {
        while width > 0 && fraction % 10 == 0 {
            fraction /= 10;
            width -= 1;
        }
    }
    write_scientific_digits(f, sign, (whole, fraction, width), exponent)
}

/// 2^`power` as f64, for the `to_f64`s of wide numbers (no `powi` in `core`).
pub(crate) fn pow2(power: i32) -> f64 {
    let mut value = 1.0;
    let step = if power < 0 { 0.5 } else { 2.0 };
    for _ in 0..power.unsigned_abs() {
        value *= step;
    }
    value
}

/// limbs ← limbs × factor + addend.
fn scale_add(limbs: &mut [u32], factor: u32, addend: u32) {
    let mut carry = u64::from(addend);
    for limb in limbs.iter_mut() {
        let total = mul_u32_wide(*limb, factor) + carry;
        *limb = total as u32;
        carry = total >> 32;
    }
}

/// limbs ← ⌊limbs / divisor⌋.
fn divide_small(limbs: &mut [u32], divisor: u32) {
    let mut remainder = 0u64;
    for limb in limbs.iter_mut().rev() {
        let current = (remainder << 32) | u64::from(*limb);
        *limb = (current / u64::from(divisor)) as u32;
        remainder = current % u64::from(divisor);
    }
}

/// limbs ← limbs × 2^shift (bits past the top lost).
fn shift_left(limbs: &mut [u32], shift: u32) {
    let (words, bits) = ((shift / 32) as usize, shift % 32);
    for k in (0..limbs.len()).rev() {
        let from = k.checked_sub(words);
        let high = from.and_then(|f| limbs.get(f)).copied().unwrap_or(0);
        let low = from
            .and_then(|f| f.checked_sub(1))
            .and_then(|f| limbs.get(f))
            .copied()
            .unwrap_or(0);
        let value = if bits == 0 {
            high
        } else {
            (high << bits) | (low >> (32 - bits))
        };
        if let Some(slot) = limbs.get_mut(k) {
            *slot = value;
        }
    }
}

/// limbs ← ⌊limbs / 2^shift⌋, as unsigned.
fn shift_right(limbs: &mut [u32], shift: u32) {
    let (words, bits) = ((shift / 32) as usize, shift % 32);
    for k in 0..limbs.len() {
        let low = limbs.get(k + words).copied().unwrap_or(0);
        let high = limbs.get(k + words + 1).copied().unwrap_or(0);
        let value = if bits == 0 {
            low
        } else {
            (low >> bits) | (high << (32 - bits))
        };
        if let Some(slot) = limbs.get_mut(k) {
            *slot = value;
        }
    }
}

/// Sets bits `from` and up.
fn set_bits_from(limbs: &mut [u32], from: u32) {
    for (k, limb) in limbs.iter_mut().enumerate() {
        let start = 32 * k as u32;
        if start >= from {
            *limb = u32::MAX;
        } else if start + 32 > from {
            *limb |= u32::MAX << (from - start);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_like_coord_where_both_reach() {
        for text in [
            "0",
            "-0.75",
            ".5",
            "3",
            "1e-9",
            "-2.5E-3",
            "0.131825904205330",
        ] {
            let deep = DeepCoord::parse(text).unwrap();
            assert_eq!(deep.to_coord(), Coord::parse(text).unwrap(), "{text}");
        }
    }

    #[test]
    fn rejects_with_the_reason() {
        assert_eq!(DeepCoord::parse("1x"), Err(DeepParseError::Malformed));
        assert_eq!(DeepCoord::parse("8"), Err(DeepParseError::OutOfRange));
        assert_eq!(DeepCoord::parse("1e1"), Err(DeepParseError::OutOfRange));
        assert_eq!(
            DeepCoord::parse("1e-57"),
            Err(DeepParseError::TooManyDigits {
                places: 57,
                max: MAX_DECIMAL_PLACES
            })
        );
        assert!(DeepCoord::parse("1.000e-56").is_ok());
    }

    #[test]
    fn products_and_sums() {
        let a = DeepCoord::parse("-1.5").unwrap();
        let b = DeepCoord::parse("0.25").unwrap();
        assert_eq!(a.mul(b, DEEP_LIMBS).to_f64(), -0.375);
        assert_eq!(a.add(b).to_f64(), -1.25);
        assert_eq!(a.sub(b).to_f64(), -1.75);
        assert_eq!(a.bits_from(DeepCoord::FRAC_BITS - 2), -6);
        assert_eq!(b.div_small(5).to_f64(), 0.05);
    }
}
