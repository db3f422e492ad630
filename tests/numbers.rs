//! Numbers as people write them and as messages show them.

use tinyfractal::Coord;

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
