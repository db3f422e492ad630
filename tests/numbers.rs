//! Numbers as people write them and as messages show them.

use tinyfractal::{math::DeepCoord, Coord};

/// `Coord`'s display: six significant digits, rounded half up, trailing zeros dropped,
/// scientific below 10⁻⁴. Expected texts are worked out by hand from the exact values.
#[test]
fn coordinates_display_six_significant_digits() {
    let shown = |text: &str| Coord::parse(text).unwrap().to_string();
    assert_eq!(shown("0"), "0");
    assert_eq!(shown("-0.75"), "-0.75");
    assert_eq!(shown("3.5"), "3.5");
    assert_eq!(shown("7"), "7");
    assert_eq!(shown("0.0001"), "0.0001");
    assert_eq!(shown("0.00012345649"), "0.000123456");
    assert_eq!(shown("0.000012345651"), "1.23457e-5");
    assert_eq!(shown("-0.3333333333"), "-0.333333");
    assert_eq!(shown("0.9999996"), "1");
    assert_eq!(shown("7.9999996"), "8");
    assert_eq!(shown("1.0000004"), "1");
    assert_eq!(shown("2.500006"), "2.50001");
    assert_eq!(shown("-0.0123"), "-0.0123");
    // 2⁻⁵⁴ = 5.5511151231257827e-17 exactly to 17 digits.
    assert_eq!(Coord::from_bits(1 << 6).to_string(), "5.55112e-17");
    // The smallest step, 2⁻⁶⁰ = 8.673617379884035e-19.
    assert_eq!(Coord::from_bits(1).to_string(), "8.67362e-19");
    assert_eq!(Coord::from_bits(i64::MAX).to_string(), "8");
}

/// Scientific notation, as people write it, exactly rounded: the Q60 bits equal those of
/// the value worked out here as an exact fraction (mantissa × 2⁶⁰ / 10ᵏ, rounded half up).
#[test]
fn coordinates_accept_scientific_notation_exactly_rounded() {
    let q60 = |mantissa: u128, k: u32| -> i64 {
        let numerator = mantissa << 60;
        let denominator = 10u128.pow(k);
        ((numerator + denominator / 2) / denominator) as i64
    };
    let cases: [(&str, u128, u32, bool); 8] = [
        ("1e-9", 1, 9, false),
        ("2.5E-3", 25, 4, false),
        ("-7.4e-1", 74, 2, true),
        ("3.14159e+0", 314159, 5, false),
        ("0.0001234e2", 1234, 5, false),
        ("12345678901234567e-20", 12345678901234567, 20, false),
        ("7E0", 7, 0, false),
        (".5e1", 5, 0, false),
    ];
    for (text, mantissa, k, negative) in cases {
        let bits = q60(mantissa, k);
        let expected = if negative { -bits } else { bits };
        assert_eq!(
            Coord::parse(text).map(Coord::to_bits),
            Some(expected),
            "{text}"
        );
    }
    assert_eq!(Coord::parse("1e-9"), Coord::parse("0.000000001"));
    assert_eq!(Coord::parse("1e-400"), Some(Coord::default()));
    for bad in [
        "1e", "1e+", "e5", "1e5.5", "1e-", "1ee5", "1e400", "8e0", "1e1", "--1e-3", "1e-3x",
    ] {
        assert_eq!(Coord::parse(bad), None, "{bad}");
    }
}

/// `Real::round_to_i32`: half away from zero, saturating at the i32 range, over the whole
/// range of bits, against the rule written out in 128 bits.
#[test]
fn reals_round_half_away_from_zero_over_every_bit_pattern() {
    use tinyfractal::Real;
    let model = |bits: i64| -> i32 {
        let half = 1i128 << 31;
        let value = i128::from(bits);
        let rounded = if value >= 0 {
            (value + half) >> 32
        } else {
            -((-value + half) >> 32)
        };
        rounded.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32
    };
    let by_hand = [
        (Real::from_ratio(1, 2).unwrap(), 1),
        (Real::from_ratio(-1, 2).unwrap(), -1),
        (Real::from_ratio(5, 2).unwrap(), 3),
        (Real::from_ratio(-5, 2).unwrap(), -3),
        (Real::from_bits((3 << 31) - 1), 1),
        (Real::from_bits(-(3 << 31) + 1), -1),
        (Real::from_bits(i64::MIN), i32::MIN),
        (Real::from_bits(i64::MAX), i32::MAX),
    ];
    for (value, expected) in by_hand {
        assert_eq!(value.round_to_i32(), expected, "{:?}", value.to_bits());
    }
    // Every half-bit and carry boundary, and a deterministic spread of all 64-bit patterns.
    let mut bits = 0x9E37_79B9_7F4A_7C15u64;
    for shift in 0..64 {
        for delta in [-1i64, 0, 1] {
            let edge = (1i64 << shift.min(62)).wrapping_add(delta);
            for value in [edge, edge.wrapping_neg(), edge | 1 << 31, -(edge | 1 << 31)] {
                assert_eq!(
                    Real::from_bits(value).round_to_i32(),
                    model(value),
                    "{value}"
                );
            }
        }
    }
    for _ in 0..100_000 {
        bits ^= bits << 13;
        bits ^= bits >> 7;
        bits ^= bits << 17;
        let value = bits as i64;
        assert_eq!(
            Real::from_bits(value).round_to_i32(),
            model(value),
            "{value}"
        );
    }
}

/// `DeepCoord`'s scientific notation, written without core's float formatting, matches
/// `f64`'s at four decimals for values from 10⁻⁴⁵ to 10³ (mantissas whose fifth decimal
/// onwards is within 10⁻⁹ of a tie are left out: there the two may round apart), and
/// without a precision writes at most six decimals, trailing zeros dropped.
#[test]
fn deep_coordinates_write_scientific_notation_as_f64_does() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut compared = 0;
    for _ in 0..20_000 {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let mantissa = state % 9_000_000_000 + 1_000_000_000;
        let exponent = (state >> 40) % 49;
        let (whole, fraction) = (mantissa / 1_000_000_000, mantissa % 1_000_000_000);
        let text = format!("{whole}.{fraction:09}e-{exponent}");
        let beyond = mantissa % 100_000;
        if (49_999..=50_001).contains(&beyond) {
            continue;
        }
        let sign = if state & 1 == 0 { "" } else { "-" };
        let Ok(deep) = DeepCoord::parse(&format!("{sign}{text}")) else {
            continue;
        };
        if deep.is_zero() {
            continue;
        }
        assert_eq!(
            format!("{deep:.4e}"),
            format!("{:.4e}", deep.to_f64()),
            "{sign}{text}"
        );
        compared += 1;
    }
    assert!(compared > 15_000, "{compared}");
    let deep = |text: &str| DeepCoord::parse(text).unwrap();
    assert_eq!(format!("{:e}", deep("0.000125")), "1.25e-4");
    assert_eq!(format!("{:e}", deep("-1.5")), "-1.5e0");
    assert_eq!(format!("{:e}", deep("0")), "0e0");
    assert_eq!(format!("{:?}", deep("0.5")), "DeepCoord(5e-1)");
    assert_eq!(format!("{:.2e}", deep("0.9999")), "1.00e0");
}
