//! Decimal text to fixed point, exactly rounded: the one parser behind `Real`, `Coord`
//! and angles in degrees.

use super::wide::div_round;

/// Significant digits a number keeps: 10¹⁹ < 2⁶⁴, so that shifted by up to 62 bits it still
/// fits 128.
const SIGNIFICANT_DIGITS: u32 = 19;

/// Decimal text split into its parts, `[±]digits[.digits][(e|E)[±]digits]`: the one
/// grammar behind every parser of numbers (`parse_fixed`, `DeepCoord::parse`).
pub(crate) struct DecimalText<'a> {
    /// A leading `-`.
    pub(crate) negative: bool,
    /// The digits, with at most one `.` among them, and at least one digit.
    pub(crate) digits: &'a [u8],
    /// The power of ten written after `e` (0 if none): at most five digits.
    pub(crate) power: i64,
}

/// Splits `text` into its parts; `None` if it is not a decimal number.
pub(crate) const fn split_decimal(text: &str) -> Option<DecimalText<'_>> {
    // Written with index loops so that it is a `const fn`: constant tables of scenes are
    // checked when they are compiled.
    let bytes = text.as_bytes();
    let (negative, start) = match bytes.first() {
        Some(b'-') => (true, 1),
        Some(b'+') => (false, 1),
        _ => (false, 0),
    };
    let mut at = start;
    let (mut any_digit, mut after_point) = (false, false);
    while let Some(&byte) = byte_at(bytes, at) {
        if byte == b'.' && !after_point {
            after_point = true;
        } else if byte.is_ascii_digit() {
            any_digit = true;
        } else {
            break;
        }
        at += 1;
    }
    if !any_digit {
        return None;
    }
    let digits = bytes.split_at(at).0.split_at(start).1;
    let mut power: i64 = 0;
    if let Some(b'e' | b'E') = byte_at(bytes, at) {
        at += 1;
        let (minus, first) = match byte_at(bytes, at) {
            Some(b'-') => (true, at + 1),
            Some(b'+') => (false, at + 1),
            _ => (false, at),
        };
        at = first;
        while let Some(&byte) = byte_at(bytes, at) {
            if !byte.is_ascii_digit() || power > 9_999 {
                return None;
            }
            power = power * 10 + (byte - b'0') as i64;
            at += 1;
        }
        if at == first {
            return None;
        }
        if minus {
            power = -power;
        }
    }
    if at != bytes.len() {
        return None;
    }
    Some(DecimalText {
        negative,
        digits,
        power,
    })
}

/// `numerator / divisor` rounded half up, as [`div_round`] has it for these magnitudes
/// (below 2¹²⁷; the divisor not 0): by a 64-bit division where the sum it divides fits 64
/// bits, since a 128-bit one is a long library routine on a 32-bit core.
const fn divide_rounded(numerator: u128, divisor: u128) -> i128 {
    let rounded = numerator + divisor / 2;
    if rounded <= u64::MAX as u128 {
        ((rounded as u64) / (divisor as u64)) as i128
    } else {
        div_round(numerator as i128, divisor as i128)
    }
}

/// Parses a decimal number with an optional sign and exponent (`-0.75`, `.5`, `3`, `1e-9`,
/// `2.5E-3`) into fixed point with `frac_bits` fractional bits (at most 62), rounded to
/// nearest from its first 19 significant digits (beyond them a digit moves the value by
/// less than 10⁻¹⁹ of itself). `None` if malformed or beyond ±2⁶³.
pub(crate) const fn parse_fixed(text: &str, frac_bits: u32) -> Option<i128> {
    let Some(DecimalText {
        negative,
        digits: text_digits,
        power,
    }) = split_decimal(text)
    else {
        return None;
    };
    // The value is `digits` × 10^`exponent`.
    let mut digits: u128 = 0;
    let mut kept = 0;
    let mut exponent: i64 = power;
    let mut after_point = false;
    let mut at = 0;
    while let Some(&byte) = byte_at(text_digits, at) {
        if byte == b'.' {
            after_point = true;
        } else {
            let digit = (byte - b'0') as u128;
            if kept < SIGNIFICANT_DIGITS && (digits > 0 || digit > 0) {
                digits = digits * 10 + digit;
                kept += 1;
                if after_point {
                    exponent -= 1;
                }
            } else if digits == 0 {
                // A leading zero: after the point it still moves the value down.
                if after_point {
                    exponent -= 1;
                }
            } else if !after_point {
                // A digit past the kept ones, before the point: a power of ten.
                exponent += 1;
            }
        }
        at += 1;
    }
    let magnitude = if digits == 0 {
        0
    } else if exponent >= 0 {
        if exponent > 38 {
            return None;
        }
        let Some(whole) = digits.checked_mul(10u128.pow(exponent as u32)) else {
            return None;
        };
        if whole > i64::MAX as u128 {
            return None;
        }
        (whole << frac_bits) as i128
    } else if exponent < -38 {
        // Below 10⁻¹⁹: less than half a unit of 62 fractional bits.
        0
    } else {
        divide_rounded(digits << frac_bits, 10u128.pow((-exponent) as u32))
    };
    Some(if negative { -magnitude } else { magnitude })
}

/// The byte at `index`, if any (`<[u8]>::get` is not const).
const fn byte_at(bytes: &[u8], index: usize) -> Option<&u8> {
    if index < bytes.len() {
        bytes.split_at(index).1.first()
    } else {
        None
    }
}

/// Significant digits [`write_fixed`] shows.
const SHOWN_DIGITS: u32 = 6;

/// Writes fixed point `bits` with `frac_bits` fractional bits (at most 62) in decimal, for
/// messages: six significant digits rounded half up, trailing zeros dropped, and
/// scientific notation below 10⁻⁴ (`1.38778e-17`). Integer parts of a million or more are
/// written whole.
pub(crate) fn write_fixed(
    f: &mut core::fmt::Formatter<'_>,
    bits: i128,
    frac_bits: u32,
) -> core::fmt::Result {
    let sign = if bits < 0 { "-" } else { "" };
    let magnitude = bits.unsigned_abs();
    let mask = (1u128 << frac_bits) - 1;
    let (integer, mut fraction) = (magnitude >> frac_bits, magnitude & mask);
    if integer >= 10u128.pow(SHOWN_DIGITS) || magnitude == 0 {
        return write!(f, "{sign}{integer}");
    }
    // `count` significant digits in `mantissa`; the first is worth 10^exponent.
    let mut mantissa = u64::try_from(integer).unwrap_or(0);
    let mut count = if integer > 0 { integer.ilog10() + 1 } else { 0 };
    let mut exponent = count as i32 - 1;
    while count <= SHOWN_DIGITS && fraction != 0 {
        fraction *= 10;
        let digit = u64::try_from(fraction >> frac_bits).unwrap_or(0);
        fraction &= mask;
        if count == 0 && digit == 0 {
            exponent -= 1;
        } else {
            mantissa = mantissa * 10 + digit;
            count += 1;
        }
    }
    if count > SHOWN_DIGITS {
        mantissa = (mantissa + 5) / 10;
        count -= 1;
        if mantissa == 10u64.pow(count) {
            mantissa /= 10;
            exponent += 1;
        }
    }
    while count > 1 && mantissa % 10 == 0 {
        mantissa /= 10;
        count -= 1;
    }
    let split = |digits_before: u32| {
        let unit = 10u64.pow(count.saturating_sub(digits_before));
        (
            mantissa / unit,
            mantissa % unit,
            count.saturating_sub(digits_before) as usize,
        )
    };
    if exponent < -4 {
        let (first, rest, width) = split(1);
        return write_scientific_digits(f, sign, (first, rest, width), exponent);
    }
    if exponent < 0 {
        let zeros = exponent.unsigned_abs() as usize - 1;
        let width = count as usize;
        return write!(f, "{sign}0.{:0<zeros$}{mantissa:0width$}", "");
    }
    let whole = exponent.unsigned_abs() + 1;
    if count <= whole {
        return write!(f, "{sign}{}", mantissa * 10u64.pow(whole - count));
    }
    let (int, rest, width) = split(whole);
    write!(f, "{sign}{int}.{rest:0width$}")
}

/// `first.rest`·10^`exponent`, `rest` written in `width` digits (none, and no point, if
/// 0): `1.38778e-17`, `5e-1`.
pub(crate) fn write_scientific_digits(
    f: &mut core::fmt::Formatter<'_>,
    sign: &str,
    (first, rest, width): (u64, u64, usize),
    exponent: i32,
) -> core::fmt::Result {
    if width == 0 {
        write!(f, "{sign}{first}e{exponent}")
    } else {
        write!(f, "{sign}{first}.{rest:0width$}e{exponent}")
    }
}

/// Fixed point `bits` with `frac_bits` fractional bits rounded half away from zero to 4
/// decimals, trailing zeros dropped: how derived strings print numbers (`A(1.1429,0)`,
/// `@0.5`).
pub(crate) fn write_four_decimals(
    f: &mut core::fmt::Formatter<'_>,
    bits: i64,
    frac_bits: u32,
) -> core::fmt::Result {
    let scaled = div_round(i128::from(bits) * 10_000, 1 << frac_bits);
    let sign = if scaled < 0 { "-" } else { "" };
    let (whole, fraction) = (
        scaled.unsigned_abs() / 10_000,
        scaled.unsigned_abs() % 10_000,
    );
    write!(f, "{sign}{whole}")?;
    if fraction > 0 {
        let mut digits = fraction;
        let mut width = 4;
        while digits % 10 == 0 {
            digits /= 10;
            width -= 1;
        }
        write!(f, ".{digits:0width$}")?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The division by 64 bits rounds as the 128-bit one, either side of 64 bits.
    #[test]
    fn divisions_round_as_the_wide_one() {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let numerator = (any::<u128>(), 1u32..128).prop_map(|(v, s)| v >> s);
        let divisor = prop_oneof![
            (0u32..39).prop_map(|e| 10u128.pow(e)),
            1u128..u128::MAX >> 1
        ];
        runner
            .run(&(numerator, divisor), |(n, d)| {
                prop_assert_eq!(divide_rounded(n, d), div_round(n as i128, d as i128));
                Ok(())
            })
            .unwrap();
        let edge = u128::from(u64::MAX);
        for (n, d) in [
            (edge, 2),
            (edge - 1, 2),
            (edge - 1, 3),
            (edge / 2, edge),
            (0, 7),
            (5, 10),
        ] {
            assert_eq!(
                divide_rounded(n, d),
                div_round(n as i128, d as i128),
                "{n} {d}"
            );
        }
    }
}
