//! Affine maps in fixed point. [`Affine2`], of the plane: the turtle of the lecture's
//! matrix notation, the joints of an articulated figure. Each product rounds to 2⁻³²; a
//! map built from a few dozen rotations and scalings is exact to about 10⁻⁸ of its scale,
//! and `[`/`]` (a stack of saved maps) restores one bitwise. [`Affine3`], of space: the
//! maps of a 3D IFS and the camera that turns the Sierpiński cube.

use super::real::Real;
use super::trig::{sin_cos_near, BinaryAngle};

/// A product or sum left the fixed-point range of [`Real`].
///
/// The number layer's own small result, so that it knows nothing of walks; the crate's
/// `Error` converts it with `?`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Overflow;

fn mul_add(x: Real, y: Real, z: Real, w: Real) -> Result<Real, Overflow> {
    x.checked_mul(y)
        .and_then(|p| z.checked_mul(w).and_then(|q| p.checked_add(q)))
        .ok_or(Overflow)
}

/// C: x' = a·x + b·y + e, y' = c·x + d·y + f.
///
/// Products that leave the fixed-point range are an [`Overflow`].
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
    pub fn apply(&self, x: Real, y: Real) -> Result<[Real; 3], Overflow> {
        Ok([
            mul_add(self.a, x, self.b, y)?
                .checked_add(self.e)
                .ok_or(Overflow)?,
            mul_add(self.c, x, self.d, y)?
                .checked_add(self.f)
                .ok_or(Overflow)?,
            Real::ZERO,
        ])
    }

    /// C · translate(dx, dy).
    pub fn translate(&mut self, dx: Real, dy: Real) -> Result<(), Overflow> {
        let [e, f, _] = self.apply(dx, dy)?;
        (self.e, self.f) = (e, f);
        Ok(())
    }

    /// C · rotate(angle), counter-clockwise.
    pub(crate) fn rotate(&mut self, angle: BinaryAngle) -> Result<(), Overflow> {
        let (cos, sin) = angle.cos_sin();
        self.rotate_by(cos, sin)
    }

    /// C · rotate, given the cosine and sine in Q30.
    fn rotate_by(&mut self, cos: i32, sin: i32) -> Result<(), Overflow> {
        let (cos, sin) = (
            Real::from_bits(i64::from(cos) << 2),
            Real::from_bits(i64::from(sin) << 2),
        );
        let minus_sin = Real::ZERO.checked_sub(sin).ok_or(Overflow)?;
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        self.a = mul_add(a, cos, b, sin)?;
        self.b = mul_add(a, minus_sin, b, cos)?;
        self.c = mul_add(c, cos, d, sin)?;
        self.d = mul_add(c, minus_sin, d, cos)?;
        Ok(())
    }

    /// C · scale(sx, sy).
    pub fn scale(&mut self, sx: Real, sy: Real) -> Result<(), Overflow> {
        let times = |v: Real, s: Real| v.checked_mul(s).ok_or(Overflow);
        self.a = times(self.a, sx)?;
        self.c = times(self.c, sx)?;
        self.b = times(self.b, sy)?;
        self.d = times(self.d, sy)?;
        Ok(())
    }

    /// C · rotate(degrees), with the sine and cosine within 2·10⁻⁹ (the table turned by the
    /// angle-sum formulas, not the interpolated table's 3·10⁻⁷): a hierarchy of joints
    /// keeps its limbs' lengths to 10⁻⁸.
    pub fn rotate_degrees(&mut self, degrees: Real) -> Result<(), Overflow> {
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

/// p' = matrix · p + translation, a map of space (a map of the plane has z rows of 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Affine3 {
    /// Row by row.
    pub matrix: [[Real; 3]; 3],
    /// Added after the matrix.
    pub translation: [Real; 3],
}

impl Affine3 {
    /// The identity.
    pub const IDENTITY: Self = Self {
        matrix: [
            [Real::ONE, Real::ZERO, Real::ZERO],
            [Real::ZERO, Real::ONE, Real::ZERO],
            [Real::ZERO, Real::ZERO, Real::ONE],
        ],
        translation: [Real::ZERO; 3],
    };

    /// Fractint's 2D map `a b c d e f`: x' = a·x + b·y + e, y' = c·x + d·y + f.
    pub fn planar([a, b, c, d, e, f]: [Real; 6]) -> Self {
        let zero = Real::ZERO;
        Self {
            matrix: [[a, b, zero], [c, d, zero], [zero, zero, zero]],
            translation: [e, f, zero],
        }
    }

    /// `p` mapped; `None` if it leaves the fixed-point range.
    #[inline]
    pub fn apply(&self, p: [Real; 3]) -> Option<[Real; 3]> {
        let mut out = self.translation;
        for (o, row) in out.iter_mut().zip(&self.matrix) {
            *o = o.checked_add(dot(row, &p)?)?;
        }
        Some(out)
    }

    /// `next` after `self` (p ↦ next(self(p))); `None` if an entry leaves the range.
    pub fn then(&self, next: &Self) -> Option<Self> {
        let mut matrix = [[Real::ZERO; 3]; 3];
        for (out_row, row) in matrix.iter_mut().zip(&next.matrix) {
            for (column, out) in out_row.iter_mut().enumerate() {
                let of_self = self
                    .matrix
                    .map(|r| r.get(column).copied().unwrap_or(Real::ZERO));
                *out = dot(row, &of_self)?;
            }
        }
        Some(Self {
            matrix,
            translation: next.apply(self.translation)?,
        })
    }

    /// The orthographic camera at `azimuth` degrees around the vertical z axis and
    /// `elevation` degrees above the horizontal plane: its rows are the world's screen
    /// right, screen up and towards the viewer (azimuth 45°, elevation 35.264° is the
    /// isometric view). Entries are Q30 sines and their Q30 products (rounded down),
    /// held as [`Real`]s.
    pub fn camera(azimuth: Real, elevation: Real) -> Self {
        let (cos_a, sin_a) = BinaryAngle::from_degrees_bits(azimuth.to_bits()).cos_sin();
        let (cos_e, sin_e) = BinaryAngle::from_degrees_bits(elevation.to_bits()).cos_sin();
        let q30 = |a: i32, b: i32| ((i64::from(a) * i64::from(b)) >> 30) as i32;
        let rows = [
            [-sin_a, cos_a, 0],
            [-q30(sin_e, cos_a), -q30(sin_e, sin_a), cos_e],
            [q30(cos_e, cos_a), q30(cos_e, sin_a), sin_e],
        ];
        Self {
            matrix: rows.map(|row| row.map(|v| Real::from_bits(i64::from(v) << 2))),
            translation: [Real::ZERO; 3],
        }
    }
}

/// `row · p`, `None` out of range.
fn dot(row: &[Real; 3], p: &[Real; 3]) -> Option<Real> {
    row.iter().zip(p).try_fold(Real::ZERO, |sum, (&m, &v)| {
        sum.checked_add(m.checked_mul(v)?)
    })
}
