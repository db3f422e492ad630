//! Orientations in space: three unit vectors in Q30 (heading, left, up; ABOP 1.5), turned
//! about each other by integer sines and kept orthonormal.
//!
//! Each rotation rounds, so over many turns the vectors would drift from unit length and
//! from each other. After every rotation the frame is renormalised without a square root:
//! one Newton step rescales the heading to unit length (`v · (3 − |v|²) / 2`), the left
//! vector loses its component along the heading and is rescaled the same way, and up is
//! their cross product. The frame then stays orthonormal to within a few 2⁻³⁰ whatever the
//! number of turns (a test turns it 10⁶ times).

use super::divide::{div_u64_by_u32, isqrt_u64};
use super::real::Real;
use super::trig::{binary_angle_of_radians, BinaryAngle, ONE_Q30};

/// A vector with Q30 components (2³⁰ = 1.0).
pub(crate) type Unit = [i32; 3];

/// The product of two Q30 values, in Q30, rounded half up: 64-bit arithmetic (the product
/// of two values below 2³¹ fits), not a 128-bit library call on Cortex-M.
fn mul(a: i32, b: i32) -> i64 {
    (i64::from(a) * i64::from(b) + (1 << 29)) >> 30
}

/// `a·cos + b·sin` for Q30 vectors and a Q30 cosine and sine.
fn combine(a: Unit, cos: i32, b: Unit, sin: i32) -> Unit {
    let mut out = [0; 3];
    for ((o, &x), &y) in out.iter_mut().zip(&a).zip(&b) {
        *o = clamp(mul(x, cos) + mul(y, sin));
    }
    out
}

fn clamp(v: i64) -> i32 {
    v.clamp(-i64::from(i32::MAX), i64::from(i32::MAX)) as i32
}

fn dot(a: Unit, b: Unit) -> i64 {
    a.iter().zip(&b).map(|(&x, &y)| mul(x, y)).sum()
}

fn cross(a: Unit, b: Unit) -> Unit {
    let [ax, ay, az] = a;
    let [bx, by, bz] = b;
    [
        clamp(mul(ay, bz) - mul(az, by)),
        clamp(mul(az, bx) - mul(ax, bz)),
        clamp(mul(ax, by) - mul(ay, bx)),
    ]
}

/// `v` rescaled towards unit length by one Newton step: exact enough for a vector already
/// within 2⁻²⁰ of it, as every rotated one is.
fn renormalised(v: Unit) -> Unit {
    // |x| <= 2^31 and factor < 2^32: the product fits in 64 bits.
    let factor = 3 * i64::from(ONE_Q30) - dot(v, v);
    v.map(|x| clamp((i64::from(x) * factor + (1 << 30)) >> 31))
}

/// |v|² in Q60: three squares of values below 2³¹, below 2⁶³.
fn squared_length(v: Unit) -> u64 {
    v.iter().map(|&x| u64::from(x.unsigned_abs()).pow(2)).sum()
}

/// Vectors shorter than this (2⁻²⁰, in Q30) have no direction worth the name: rounding
/// alone makes them.
const SHORTEST: i64 = 1 << 10;

/// `v` scaled to unit length (a square root: for `$`, whose vector may be short); `None`
/// if it is shorter than [`SHORTEST`].
fn normalised(v: Unit) -> Option<Unit> {
    let squared = squared_length(v);
    let length = i64::try_from(isqrt_u64(squared))
        .ok()
        .filter(|&l| l >= SHORTEST)?;
    let over = Reciprocal::of(length.unsigned_abs());
    Some(v.map(|x| {
        let quotient = i64::from(over.scaled(x.unsigned_abs()));
        clamp(if x < 0 { -quotient } else { quotient })
    }))
}

/// Division by a vector's length, three times: ⌊a·2³⁰ / length⌋ for each component a
/// (|a| ≤ length, so the quotient is at most 2³⁰) by one multiply with the length's
/// reciprocal and one correction, the same quotients as dividing.
#[derive(Debug, Clone, Copy)]
struct Reciprocal {
    length: u64,
    /// ⌊2⁶² / length⌋, in two words.
    high: u64,
    low: u64,
}

impl Reciprocal {
    /// The reciprocal of `length` (at least [`SHORTEST`], below 2³²).
    fn of(length: u64) -> Self {
        // Below 2³², as the length is: a 64-by-32 division.
        let inverse = div_u64_by_u32(1 << 62, u32::try_from(length).unwrap_or(u32::MAX).max(1));
        Self {
            length,
            high: inverse >> 32,
            low: inverse & 0xFFFF_FFFF,
        }
    }

    /// ⌊`a`·2³⁰ / length⌋ for `a` ≤ length.
    ///
    /// a·⌊2⁶²/length⌋ / 2³² falls short of a·2³⁰/length by less than a / 2³² < ½, so its
    /// floor is the quotient or one less: one product with the length decides.
    fn scaled(&self, a: u32) -> u32 {
        let a = u64::from(a);
        let estimate = a * self.high + ((a * self.low) >> 32);
        let numerator = a << 30;
        let quotient = if (estimate + 1) * self.length <= numerator {
            estimate + 1
        } else {
            estimate
        };
        u32::try_from(quotient).unwrap_or(u32::MAX)
    }
}

/// Which axis a rotation turns about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    /// About up: the heading turns towards left (`+`; `-` the other way).
    Up,
    /// About left: the heading turns towards down (`&`, pitch down; `^` up).
    Left,
    /// About the heading: left turns towards up (`\\`, roll left; `/` right).
    Heading,
}

/// The turtle's orientation: heading, left and up, orthonormal and right-handed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Frame3 {
    pub(crate) heading: Unit,
    pub(crate) left: Unit,
    pub(crate) up: Unit,
}

impl Default for Frame3 {
    /// Heading up the screen (+y), left to −x, up towards the viewer (+z): a 2D system
    /// turned only by `+` and `-` draws as the 2D turtle heading up draws it.
    fn default() -> Self {
        Self {
            heading: [0, ONE_Q30, 0],
            left: [-ONE_Q30, 0, 0],
            up: [0, 0, ONE_Q30],
        }
    }
}

impl Frame3 {
    /// Turns by `angle` about `axis` (counter-clockwise seen from the axis's tip).
    pub(crate) fn rotate(&mut self, axis: Axis, angle: BinaryAngle) {
        let (cos, sin) = angle.cos_sin();
        let (h, l, u) = (self.heading, self.left, self.up);
        match axis {
            Axis::Up => {
                self.heading = combine(h, cos, l, sin);
                self.left = combine(l, cos, h, -sin);
            }
            Axis::Left => {
                self.heading = combine(h, cos, u, -sin);
                self.up = combine(u, cos, h, sin);
            }
            Axis::Heading => {
                self.left = combine(l, cos, u, sin);
                self.up = combine(u, cos, l, -sin);
            }
        }
        self.renormalise();
    }

    /// Orthonormal again: heading rescaled, left made square to it and rescaled, up their
    /// cross product.
    fn renormalise(&mut self) {
        let heading = renormalised(self.heading);
        let along = dot(self.left, heading);
        let mut left = self.left;
        for (l, &h) in left.iter_mut().zip(&heading) {
            *l = clamp(i64::from(*l) - mul(clamp(along), h));
        }
        let left = renormalised(left);
        self.heading = heading;
        self.left = left;
        self.up = cross(heading, left);
    }

    /// `$`: rolls about the heading until left is horizontal (square to the vertical +y),
    /// as ABOP defines it; a heading within 2⁻²⁰ of straight up or down leaves the frame as
    /// it is (left has no horizontal direction to take).
    pub(crate) fn roll_to_horizontal(&mut self) {
        let vertical = [0, ONE_Q30, 0];
        if let Some(left) = normalised(cross(vertical, self.heading)) {
            self.left = left;
            self.up = cross(self.heading, left);
        }
    }

    /// Bends the heading towards `towards` (a Q30 unit vector) by `strength`·|H × T|
    /// radians about H × T (ABOP eq. 2.4, with `strength` the elasticity times |T|), the
    /// whole frame turning with it. A heading within 2⁻²⁰ of T (or of −T) is not bent: the
    /// axis has no direction. The angle is clamped to ±2 radians (a Q30 `i32`).
    pub(crate) fn bend(&mut self, towards: Unit, strength: Real) {
        let across = cross(self.heading, towards);
        let Some(axis) = normalised(across) else {
            return;
        };
        let sine = i64::try_from(isqrt_u64(squared_length(across))).unwrap_or(i64::MAX);
        // strength (Q32) · sine (Q30) >> 32: radians in Q30.
        let radians = clamp(((i128::from(strength.to_bits()) * i128::from(sine)) >> 32) as i64);
        let angle = BinaryAngle(binary_angle_of_radians(radians, 30));
        let (cos, sin) = angle.cos_sin();
        let turn = |v: Unit| -> Unit {
            // Rodrigues: v·cos + (a × v)·sin + a·(a · v)·(1 − cos).
            let along = clamp(mul(clamp(dot(axis, v)), ONE_Q30 - cos));
            let crossed = cross(axis, v);
            let mut out = [0; 3];
            for (((o, &x), &c), &a) in out.iter_mut().zip(&v).zip(&crossed).zip(&axis) {
                *o = clamp(mul(x, cos) + mul(c, sin) + mul(a, along));
            }
            out
        };
        self.heading = turn(self.heading);
        self.left = turn(self.left);
        self.renormalise();
    }

    /// The step `length` along the heading.
    pub(crate) fn step(&self, length: Real) -> [Real; 3] {
        self.heading.map(|h| length.mul_q30(h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reciprocal's quotients are the divisions', for lengths of every size and
    /// components up to them.
    #[test]
    fn reciprocal_quotients_are_divisions() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let length = (state >> (32 + state % 22)).max(SHORTEST as u64);
            let over = Reciprocal::of(length);
            let a = (state.rotate_left(17) % (length + 1)) as u32;
            for a in [a, length as u32, 0, 1, a / 2] {
                let exact = (u64::from(a) << 30) / length;
                assert_eq!(u64::from(over.scaled(a)), exact, "{a} {length}");
            }
        }
    }
}
