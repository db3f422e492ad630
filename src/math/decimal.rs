//! Decimal text to fixed point, exactly rounded: the one parser behind `Real`, `Coord`
//! and angles in degrees.

use super::wide::div_round;

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
