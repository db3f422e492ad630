//! The perturbed pixels' number: a complex value with two 62-bit mantissas and one
//! exponent, and the steps a perturbed pixel takes in it.
//!
//! The reference orbit is stored in this format and the pixels' differences δ iterate in
//! it, so a zoom far past 2⁻⁵⁴ needs no wider numbers per pixel than a shallow one; the
//! series approximation evaluates into it. Every shift floors, so every core draws the
//! same bits. Why 62 bits: [docs/performance.md](../../docs/performance.md).

use crate::math::big::pow2;
use crate::math::wide::{mul_i32_wide, mul_wide};

/// The exponent of zero: larger than any other, so zero's terms shift away.
pub(super) const ZERO_EXPONENT: i32 = 1 << 12;

/// Bits of a normalised mantissa: the larger part's magnitude is in [2⁶¹, 2⁶²).
pub(super) const MANTISSA_BITS: u32 = 62;

/// One value of a reference orbit: (x + iy)·2^−exponent, the larger of |x|, |y| in
/// [2⁶¹, 2⁶²] (or both 0): the pixels' own format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ReferencePoint(pub(super) Scaled);

impl ReferencePoint {
    /// The value as `f64` (for tests and host output).
    pub fn to_f64(self) -> (f64, f64) {
        let scale = pow2(-self.0.s);
        (self.0.x as f64 * scale, self.0.y as f64 * scale)
    }
}

/// A complex value (x + iy)·2^−s with a shared exponent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Scaled {
    pub(super) x: i64,
    pub(super) y: i64,
    pub(super) s: i32,
}

impl Scaled {
    pub(super) const ZERO: Self = Self {
        x: 0,
        y: 0,
        s: ZERO_EXPONENT,
    };

    /// The sum, in the larger one's units (the other's mantissas shifted down, floor).
    #[inline(never)]
    pub(super) fn add(self, other: Self) -> Self {
        let (big, small) = if self.s <= other.s {
            (self, other)
        } else {
            (other, self)
        };
        let shift = (small.s - big.s).min(63);
        normalise(
            i128::from(big.x) + i128::from(small.x >> shift),
            i128::from(big.y) + i128::from(small.y >> shift),
            big.s,
        )
    }

    /// The difference.
    pub(super) fn sub(self, other: Self) -> Self {
        self.add(Self {
            x: -other.x,
            y: -other.y,
            s: other.s,
        })
    }

    /// 2^`k`·`self`.
    pub(super) const fn times_pow2(self, k: i32) -> Self {
        Self {
            s: self.s - k,
            ..self
        }
    }

    /// Bits of the larger part's magnitude (0 for zero).
    const fn bits(self) -> i32 {
        64 - (self.x.unsigned_abs() | self.y.unsigned_abs()).leading_zeros() as i32
    }

    /// |self| < 2^`upper_log2` (the larger part below 2^bits, the modulus below √2 times
    /// it). Zero: very negative.
    pub(super) const fn upper_log2(self) -> i32 {
        match self.bits() {
            0 => -ZERO_EXPONENT,
            bits => bits + 1 - self.s,
        }
    }

    /// |self| ≥ 2^`lower_log2`. Zero: very large.
    pub(super) const fn lower_log2(self) -> i32 {
        match self.bits() {
            0 => ZERO_EXPONENT,
            bits => bits - 1 - self.s,
        }
    }
}

/// (x + iy)·2^−s normalised: the larger part's top bit at bit 61. Shifts floor.
#[inline(always)]
pub(super) fn normalise(x: i128, y: i128, s: i32) -> Scaled {
    let magnitude = x.unsigned_abs() | y.unsigned_abs();
    if magnitude == 0 {
        return Scaled::ZERO;
    }
    let shift = (128 - magnitude.leading_zeros()) as i32 - MANTISSA_BITS as i32;
    if shift >= 0 {
        Scaled {
            x: (x >> shift) as i64,
            y: (y >> shift) as i64,
            s: s - shift,
        }
    } else {
        Scaled {
            x: (x << -shift) as i64,
            y: (y << -shift) as i64,
            s: s - shift,
        }
    }
}

/// `value` >> `shift` for any shift ≥ 0 (past 127: the sign).
#[inline(always)]
pub(super) fn shr(value: i128, shift: i32) -> i128 {
    value >> shift.clamp(0, 127)
}

/// A mantissa with exponent in Q28, to the floor; the exponent must be at least 54
/// (callers check), so the result is below 2³⁶.
#[inline(always)]
pub(super) fn to_q28(mantissa: i64, exponent: i32) -> i64 {
    mantissa >> (exponent - 28).clamp(0, 63)
}

/// `value` saturated to `i32`.
pub(super) fn clamp_i32(value: i64) -> i32 {
    value.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// δ ← 2Zδ + δ² + δc.
///
/// The three terms are summed in the units of the largest one's bound (each below 2¹²⁴
/// there, the sum below 2¹²⁶), not in δ's: when Zₙ is near 0 (a reference passing through
/// its own minibrot's period) δ² and δc can be far smaller than δ, and summed in δ's
/// units they would be lost.
#[inline(never)]
pub(super) fn step(d: Scaled, z: Scaled, c: Scaled) -> Scaled {
    // Mantissas below 2^62 + 1: 2Zδ in units 2^-(e+s) is below 2^126, δ² in 2^-2s below
    // 2^125, δc in 2^-sc below 2^62.
    let u = (z.s + d.s - 2).min(2 * d.s - 2).min(c.s + 61);
    let px = mul_wide(z.x, d.x) - mul_wide(z.y, d.y);
    let py = mul_wide(z.x, d.y) + mul_wide(z.y, d.x);
    let k = z.s + d.s - 1 - u;
    let (mut x, mut y) = (shr(px, k), shr(py, k));
    let k = 2 * d.s - u;
    if k < 126 {
        x += shr(mul_wide(d.x, d.x) - mul_wide(d.y, d.y), k);
        y += shr(2 * mul_wide(d.x, d.y), k);
    }
    let k = c.s - u;
    if k >= 0 {
        x += shr(i128::from(c.x), k);
        y += shr(i128::from(c.y), k);
    } else {
        // At most 61 bits up: below 2^123.
        x += i128::from(c.x) << -k;
        y += i128::from(c.y) << -k;
    }
    normalise(x, y, u)
}

/// z = Z + δ in Q28 if |z| > 2 (escaped), else `None`.
#[inline(always)]
pub(super) fn escaped(z: Scaled, d: Scaled) -> Option<(i32, i32)> {
    // A part of δ beyond 2⁷: certainly out (|Z| ≤ 8 for a reference point).
    if d.s < 54 {
        return Some((clamp_i32(to_q28(z.x, z.s)), clamp_i32(to_q28(z.y, z.s))));
    }
    let x = to_q28(z.x, z.s) + to_q28(d.x, d.s);
    let y = to_q28(z.y, z.s) + to_q28(d.y, d.s);
    // Beyond 4 in a part: out, without squaring.
    const FOUR: u64 = 1 << 30;
    if x.unsigned_abs() > FOUR || y.unsigned_abs() > FOUR {
        return Some((clamp_i32(x), clamp_i32(y)));
    }
    let (x, y) = (x as i32, y as i32);
    let modulus = mul_i32_wide(x, x) + mul_i32_wide(y, y);
    (modulus > 4 << 56).then_some((x, y))
}

/// Whether |Z + δ| < |δ| is possible: only when Z's exponent is within 3 of δ's (|Z| < 8|δ|),
/// so the full test costs nothing while the reference is far larger.
#[inline(always)]
pub(super) const fn may_rebase(z: Scaled, d: Scaled) -> bool {
    z.s + 3 > d.s
}

/// z = Z + δ as the new δ if |z| < |δ| or `always`, else `None`.
#[inline(never)]
pub(super) fn rebased(z: Scaled, d: Scaled, always: bool) -> Option<Scaled> {
    // Both in the larger one's units (the smaller exponent): each below 2^62, sums below
    // 2^63, squares below 2^126.
    let u = z.s.min(d.s);
    let align = |m: i64, s: i32| m >> (s - u).clamp(0, 63);
    let (dx, dy) = (align(d.x, d.s), align(d.y, d.s));
    let (x, y) = (align(z.x, z.s) + dx, align(z.y, z.s) + dy);
    let square = |a: i64, b: i64| mul_wide(a, a) + mul_wide(b, b);
    (always || square(x, y) < square(dx, dy)).then(|| normalise(i128::from(x), i128::from(y), u))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalise_keeps_sixty_two_bits() {
        let value = normalise(3, -1, 10);
        assert_eq!(value.x, 3 << 60);
        assert_eq!(value.y, -(1 << 60));
        assert_eq!(value.x as f64 * pow2(-value.s), 3.0 / 1024.0);
        assert_eq!(normalise(0, 0, 5), Scaled::ZERO);
    }

    #[test]
    fn a_step_from_zero_is_the_offset() {
        let c = normalise(5, 7, 40);
        assert_eq!(step(Scaled::ZERO, Scaled::ZERO, c), c);
    }
}
