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

use super::action::{turtle_action, Action};
use super::values::DerivedModule;
use crate::error::{Error, WalkError};
use crate::math::affine::Affine2;
use crate::math::trig::BinaryAngle;
use crate::math::Real;
use crate::render::space::Segment3;

/// The matrix turtle: C and a stack of saved ones (`STACK` deep).
#[derive(Debug, Clone)]
pub(crate) struct MatrixTurtle<const STACK: usize> {
    turn: BinaryAngle,
    matrix: Affine2,
    color: u8,
    stack: Vec<(Affine2, u8), STACK>,
}

impl<const STACK: usize> MatrixTurtle<STACK> {
    pub(crate) fn new(turn: BinaryAngle) -> Self {
        Self {
            turn,
            matrix: Affine2::IDENTITY,
            color: 0,
            stack: Vec::new(),
        }
    }

    /// Where it is, and heads (C's x axis), for an environment.
    pub(crate) fn position_and_heading(&self) -> ([Real; 3], [Real; 3]) {
        let ((x, y), (hx, hy)) = (self.matrix.origin(), self.matrix.x_axis());
        ([x, y, Real::ZERO], [hx, hy, Real::ZERO])
    }

    fn segment(&self, length: Real) -> Result<Segment3, Error> {
        Ok(Segment3 {
            start: self.matrix.apply(Real::ZERO, Real::ZERO)?,
            end: self.matrix.apply(length, Real::ZERO)?,
            color: self.color,
        })
    }

    /// Does what `module` says; the segment it draws, if any.
    pub(crate) fn execute(&mut self, module: &DerivedModule) -> Result<Option<Segment3>, Error> {
        let values = module.values.as_slice();
        let first = values.first().copied();
        let second = values.get(1).copied();
        let negated = |a: BinaryAngle| BinaryAngle(a.0.wrapping_neg());
        match (module.symbol, first) {
            ('D', _) => return self.segment(Real::ONE).map(Some),
            ('T', _) => self
                .matrix
                .translate(first.unwrap_or(Real::ONE), second.unwrap_or(Real::ZERO))?,
            ('R', Some(d)) => self.matrix.rotate_degrees(d)?,
            ('S', Some(s)) => self.matrix.scale(s, second.unwrap_or(s))?,
            ('+', Some(d)) => self.matrix.rotate_degrees(d)?,
            ('-', Some(d)) => self.matrix.rotate_degrees(Real::ZERO.saturating_sub(d))?,
            ('+', None) => self.matrix.rotate(self.turn)?,
            ('-', None) => self.matrix.rotate(negated(self.turn))?,
            ('|', _) => self.matrix.rotate(BinaryAngle(1 << 31))?,
            _ => match turtle_action(module) {
                Action::Step { length, draw, .. } => {
                    let segment = draw.then(|| self.segment(length)).transpose()?;
                    self.matrix.translate(length, Real::ZERO)?;
                    return Ok(segment);
                }
                Action::Scale(factor) => self.matrix.scale(factor, factor)?,
                Action::Color(change) => self.color = change.apply(self.color),
                Action::Push => self
                    .stack
                    .push((self.matrix, self.color))
                    .map_err(|_| Error::Walk(WalkError::StackTooDeep { capacity: STACK }))?,
                Action::Pop => {
                    if let Some((matrix, color)) = self.stack.pop() {
                        (self.matrix, self.color) = (matrix, color);
                    }
                }
                // The matrix notation draws lines only.
                Action::Width(_)
                | Action::StartPolygon
                | Action::Vertex
                | Action::EndPolygon
                | Action::Nothing => {}
            },
        }
        Ok(None)
    }
}
