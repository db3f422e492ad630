//! The lecture's matrix notation: the turtle as a transformation matrix C, post-multiplied
//! as modules are read, kept on a bounded stack by `[` and `]`.
//!
//! | module | C becomes |
//! |---|---|
//! | `T(dx[,dy])` (`T`: `T(1)`) | C · translate(dx, dy) |
//! | `R(deg)` | C · rotate(deg), counter-clockwise |
//! | `S(s[,sy])` | C · scale(s, sy) (sy = s if not given) |
//! | `D` | draws C·(0,0) to C·(1,0); C stays |
//! | `F(l)`, `f(l)` | draws (or not) C·(0,0) to C·(l,0), then C · translate(l, 0) |
//! | `+(a)`, `-(a)` | C · rotate(±a) (without a parameter, the system's angle) |
//! | `r`, `R` | C · scale(1/√2), C · scale(√2) |
//!
//! C is an affine map of the plane in fixed point; the picture is drawn in the plane z = 0,
//! from the front. A system is read in this notation when it uses `D`, `T`, `R(deg)` or
//! `S(s)`.

use heapless::Vec;

use super::draw::{turtle_action, Action};
use super::space::Segment3;
use super::DerivedModule;
use crate::error::{Error, WalkError};
use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// C: x' = a·x + b·y + e, y' = c·x + d·y + f.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Matrix {
    a: Real,
    b: Real,
    c: Real,
    d: Real,
    e: Real,
    f: Real,
    color: u8,
}

fn overflow() -> Error {
    Error::Walk(WalkError::Overflow)
}

fn mul_add(x: Real, y: Real, z: Real, w: Real) -> Result<Real, Error> {
    x.checked_mul(y)
        .and_then(|p| z.checked_mul(w).and_then(|q| p.checked_add(q)))
        .ok_or_else(overflow)
}

impl Matrix {
    const IDENTITY: Self = Self {
        a: Real::ONE,
        b: Real::ZERO,
        c: Real::ZERO,
        d: Real::ONE,
        e: Real::ZERO,
        f: Real::ZERO,
        color: 0,
    };

    /// C·(x, y).
    fn apply(&self, x: Real, y: Real) -> Result<[Real; 3], Error> {
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

    fn translate(&mut self, dx: Real, dy: Real) -> Result<(), Error> {
        let [e, f, _] = self.apply(dx, dy)?;
        (self.e, self.f) = (e, f);
        Ok(())
    }

    fn rotate(&mut self, angle: BinaryAngle) -> Result<(), Error> {
        let (cos, sin) = angle.cos_sin();
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

    fn scale(&mut self, sx: Real, sy: Real) -> Result<(), Error> {
        let times = |v: Real, s: Real| v.checked_mul(s).ok_or_else(overflow);
        self.a = times(self.a, sx)?;
        self.c = times(self.c, sx)?;
        self.b = times(self.b, sy)?;
        self.d = times(self.d, sy)?;
        Ok(())
    }
}

/// The matrix turtle: C and a stack of saved ones (`STACK` deep).
#[derive(Debug, Clone)]
pub(crate) struct MatrixTurtle<const STACK: usize> {
    turn: BinaryAngle,
    matrix: Matrix,
    stack: Vec<Matrix, STACK>,
}

impl<const STACK: usize> MatrixTurtle<STACK> {
    pub(crate) fn new(turn: BinaryAngle) -> Self {
        Self {
            turn,
            matrix: Matrix::IDENTITY,
            stack: Vec::new(),
        }
    }

    /// Where it is, and heads (C's x axis), for an environment.
    pub(crate) fn position_and_heading(&self) -> ([Real; 3], [Real; 3]) {
        let m = &self.matrix;
        ([m.e, m.f, Real::ZERO], [m.a, m.c, Real::ZERO])
    }

    fn segment(&self, length: Real) -> Result<Segment3, Error> {
        Ok(Segment3 {
            start: self.matrix.apply(Real::ZERO, Real::ZERO)?,
            end: self.matrix.apply(length, Real::ZERO)?,
            color: self.matrix.color,
        })
    }

    /// Does what `module` says; the segment it draws, if any.
    pub(crate) fn execute(&mut self, module: &DerivedModule) -> Result<Option<Segment3>, Error> {
        let values = module.values.as_slice();
        let first = values.first().copied();
        let second = values.get(1).copied();
        let degrees = |d: Real| BinaryAngle::from_degrees_bits(d.to_bits());
        let negated = |a: BinaryAngle| BinaryAngle(a.0.wrapping_neg());
        match (module.symbol, first) {
            ('D', _) => return self.segment(Real::ONE).map(Some),
            ('T', _) => self
                .matrix
                .translate(first.unwrap_or(Real::ONE), second.unwrap_or(Real::ZERO))?,
            ('R', Some(d)) => self.matrix.rotate(degrees(d))?,
            ('S', Some(s)) => self.matrix.scale(s, second.unwrap_or(s))?,
            ('+', d) => self.matrix.rotate(d.map_or(self.turn, degrees))?,
            ('-', d) => self.matrix.rotate(negated(d.map_or(self.turn, degrees)))?,
            ('|', _) => self.matrix.rotate(BinaryAngle(1 << 31))?,
            _ => match turtle_action(module) {
                Action::Step { length, draw } => {
                    let segment = draw.then(|| self.segment(length)).transpose()?;
                    self.matrix.translate(length, Real::ZERO)?;
                    return Ok(segment);
                }
                Action::Scale(factor) => self.matrix.scale(factor, factor)?,
                Action::Color(change) => self.matrix.color = change.apply(self.matrix.color),
                Action::Push => self
                    .stack
                    .push(self.matrix)
                    .map_err(|_| Error::Walk(WalkError::StackTooDeep { capacity: STACK }))?,
                Action::Pop => {
                    if let Some(matrix) = self.stack.pop() {
                        self.matrix = matrix;
                    }
                }
                Action::Nothing => {}
            },
        }
        Ok(None)
    }
}
