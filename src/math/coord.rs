//! `Coord`: a point's coordinate on the complex plane, Q4.60.

use core::fmt;

use super::decimal::{parse_fixed, write_fixed};

/// A coordinate of the complex plane: signed fixed point with 60 fractional bits (Q4.60),
/// enough for the deepest tier. Built from decimal text exactly rounded, or checked `f64`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Coord(i64);

impl Coord {
    /// Fractional bits.
    pub const FRAC_BITS: u32 = 60;

    /// From the raw bits (the value times 2⁶⁰).
    pub const fn from_bits(bits: i64) -> Self {
        Self(bits)
    }

    /// The raw bits.
    pub const fn to_bits(self) -> i64 {
        self.0
    }

    /// Parses decimal text such as `-0.743643887037151`; `None` if malformed or |value| ≥ 8.
    pub const fn parse(text: &str) -> Option<Self> {
        match parse_fixed(text, Self::FRAC_BITS) {
            Some(bits) if bits >= i64::MIN as i128 && bits <= i64::MAX as i128 => {
                Some(Self(bits as i64))
            }
            _ => None,
        }
    }

    /// The nearest coordinate to an `f64` (set-up only); `None` if not finite or |value| ≥ 8.
    pub fn from_f64(value: f64) -> Option<Self> {
        let scaled = value * (1u64 << 60) as f64;
        // Checked by hand: `as` saturates silently, and fixed's `from_num` wraps in release.
        (scaled.is_finite() && scaled.abs() < 9.2e18).then_some(Self(scaled as i64))
    }

    /// The value as `f64` (for tests and host output).
    pub fn to_f64(self) -> f64 {
        self.0 as f64 / (1u64 << 60) as f64
    }
}

/// Six significant digits, scientific below 10⁻⁴: for messages, not for reading back.
impl fmt::Display for Coord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_fixed(f, i128::from(self.0), Self::FRAC_BITS)
    }
}
