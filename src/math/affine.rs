//! Affine maps of the plane in fixed point: the turtle of the lecture's matrix notation,
//! the joints of an articulated figure. Each product rounds to 2⁻³²; a map built from a
//! few dozen rotations and scalings is exact to about 10⁻⁸ of its scale, and `[`/`]`
//! (a stack of saved maps) restores one bitwise.

use crate::error::{Error, WalkError};
use crate::math::trig::{sin_cos_near, BinaryAngle};
use crate::math::Real;

fn overflow() -> Error {
    Error::Walk(WalkError::Overflow)
}

fn mul_add(x: Real, y: Real, z: Real, w: Real) -> Result<Real, Error> {
    x.checked_mul(y)
        .and_then(|p| z.checked_mul(w).and_then(|q| p.checked_add(q)))
        .ok_or_else(overflow)
}

/// C: x' = a·x + b·y + e, y' = c·x + d·y + f.
///
/// Products that leave the fixed-point range are [`WalkError::Overflow`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Affine2 {
    a: Real,
    b: Real,
    c: Real,
    d: Real,
    e: Real,
    f: Real,
}

impl Affine2 {
    /// The identity.
    pub const IDENTITY: Self = Self {
        a: Real::ONE,
        b: Real::ZERO,
        c: Real::ZERO,
        d: Real::ONE,
        e: Real::ZERO,
        f: Real::ZERO,
    };

    /// C·(x, y), in space at z = 0.
    pub fn apply(&self, x: Real, y: Real) -> Result<[Real; 3], Error> {
        Ok([
            mul_add(self.a, x, self.b, y)?
                .checked_add(self.e)
                .ok_or_else(overflow)?,
            mul_add(self.c, x, self.d, y)?
                .checked_add(self.f)
                .ok_or_else(overflow)?,
            Real::ZERO,
        ])
    }

    /// C · translate(dx, dy).
    pub fn translate(&mut self, dx: Real, dy: Real) -> Result<(), Error> {
        let [e, f, _] = self.apply(dx, dy)?;
        (self.e, self.f) = (e, f);
        Ok(())
    }

    /// C · rotate(angle), counter-clockwise.
    pub(crate) fn rotate(&mut self, angle: BinaryAngle) -> Result<(), Error> {
        let (cos, sin) = angle.cos_sin();
        self.rotate_by(cos, sin)
    }

    /// C · rotate, given the cosine and sine in Q30.
    fn rotate_by(&mut self, cos: i32, sin: i32) -> Result<(), Error> {
        let (cos, sin) = (
            Real::from_bits(i64::from(cos) << 2),
            Real::from_bits(i64::from(sin) << 2),
        );
        let minus_sin = Real::ZERO.checked_sub(sin).ok_or_else(overflow)?;
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        self.a = mul_add(a, cos, b, sin)?;
        self.b = mul_add(a, minus_sin, b, cos)?;
        self.c = mul_add(c, cos, d, sin)?;
        self.d = mul_add(c, minus_sin, d, cos)?;
        Ok(())
    }

    /// C · scale(sx, sy).
    pub fn scale(&mut self, sx: Real, sy: Real) -> Result<(), Error> {
        let times = |v: Real, s: Real| v.checked_mul(s).ok_or_else(overflow);
        self.a = times(self.a, sx)?;
        self.c = times(self.c, sx)?;
        self.b = times(self.b, sy)?;
        self.d = times(self.d, sy)?;
        Ok(())
    }

    /// C · rotate(degrees), with the sine and cosine within 2·10⁻⁹ (the table turned by the
    /// angle-sum formulas, not the interpolated table's 3·10⁻⁷): a hierarchy of joints
    /// keeps its limbs' lengths to 10⁻⁸.
    pub fn rotate_degrees(&mut self, degrees: Real) -> Result<(), Error> {
        // The angle as a fraction of a turn: degrees (Q32) over 360 · 2^32.
        const TURN: i128 = 360 << 32;
        let numerator = i128::from(degrees.to_bits()).rem_euclid(TURN);
        let (cos, sin) = sin_cos_near(numerator as u64, TURN as u64);
        self.rotate_by(cos, sin)
    }

    /// Where C puts the origin.
    pub const fn origin(&self) -> (Real, Real) {
        (self.e, self.f)
    }

    /// C's x axis (the turtle's heading, scaled).
    pub const fn x_axis(&self) -> (Real, Real) {
        (self.a, self.c)
    }
}
