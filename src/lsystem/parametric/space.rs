//! The 3D turtle (ABOP 1.5): a position and an orientation (heading, left, up) in fixed
//! point, turned by `+ - & ^ \ / |` and `$`, and the segments it draws.
//!
//! | module | turns |
//! |---|---|
//! | `+(a)` `-(a)` | about up: the heading towards left, or right |
//! | `&(a)` `^(a)` | about left: pitch down, or up |
//! | `\(a)` `/(a)` | about the heading: roll left, or right |
//! | `\|` | half a turn about up |
//! | `$` | roll until left is horizontal |
//!
//! Without a parameter a turn is the system's `angle:`. The turtle starts at the origin
//! heading up (+y), left towards −x and up towards the viewer (+z), so a system turned only
//! by `+` and `-` draws in the plane z = 0 exactly as the 2D turtle heading up would.
//! `F(l)`, `f(l)`, `[ ]`, `r`, `R` and the colour modules act as in 2D. It also draws
//! the book's surfaces and widths: polygons (`{ . }`, see [`surface`](super::surface)),
//! line widths (`!(w)` and `_(w)` set it in turtle units, `!` and `_` lower and raise it
//! by the system's width step), and bends each step under a tropism
//! ([`tropism`](super::tropism)).

use heapless::Vec;

use super::action::{turtle_action, Action, WidthChange};
use super::environment::TurtleState;
use super::grammar::ParametricGrammar;
use super::matrix::MatrixTurtle;
use super::surface::Polygons;
use super::tropism::{Bend, Tropism};
use super::values::DerivedModule;
use crate::error::{Error, WalkError};
use crate::math::frame3::{Axis, Frame3};
use crate::math::trig::BinaryAngle;
use crate::math::{Angle, Real};

pub use crate::render::space::Segment3;

/// Everything `[` saves.
#[derive(Debug, Clone, Copy)]
struct State3 {
    position: [Real; 3],
    frame: Frame3,
    step: Real,
    color: u8,
    /// The line width in turtle units (0: one pixel).
    width: Real,
}

/// What a module drew.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Drawn {
    /// A line, `width` turtle units wide (0: one pixel).
    Line { segment: Segment3, width: Real },
    /// A polygon closed (its vertices are the turtle's
    /// [`closed_polygon`](AnyTurtle::closed_polygon)), in colour `color`.
    Polygon { color: u8 },
}

/// The system's turn as a binary angle.
pub(crate) fn binary_angle(angle: Angle) -> BinaryAngle {
    match angle {
        Angle::Divisions(n) => {
            let n = u64::from(n.max(1));
            BinaryAngle(u32::try_from(((1u64 << 32) + n / 2) / n).unwrap_or(0))
        }
        Angle::Degrees(degrees) => BinaryAngle::from_degrees_bits(degrees.to_bits()),
    }
}

/// The 3D turtle: a state and a stack of saved states (`STACK` deep), the polygons it is
/// recording, and the tropism that bends it.
#[derive(Debug, Clone)]
pub(crate) struct Turtle3<const STACK: usize> {
    turn: BinaryAngle,
    state: State3,
    stack: Vec<State3, STACK>,
    /// The step of `!` and `_` without a parameter.
    width_step: Real,
    bend: Option<Bend>,
    polygons: Polygons,
}

impl<const STACK: usize> Turtle3<STACK> {
    /// Where it is and heads, for an environment.
    pub(crate) fn state(&self) -> TurtleState {
        TurtleState {
            position: self.state.position,
            heading: self
                .state
                .frame
                .heading
                .map(|h| Real::from_bits(i64::from(h) << 2)),
        }
    }

    /// A turtle turning by `turn`, with lines `width.0` wide (changed by `width.1` a `!`
    /// or `_`), bent by `tropism` after each step.
    pub(crate) fn new(turn: BinaryAngle, width: (Real, Real), tropism: Option<Tropism>) -> Self {
        Self {
            turn,
            state: State3 {
                position: [Real::ZERO; 3],
                frame: Frame3::default(),
                step: Real::ONE,
                color: 0,
                width: width.0,
            },
            stack: Vec::new(),
            width_step: width.1,
            bend: tropism.and_then(|t| t.bend()),
            polygons: Polygons::default(),
        }
    }

    /// The vertices of the polygon the last module closed (empty if it closed none).
    pub(crate) fn closed_polygon(&self) -> &[[Real; 3]] {
        self.polygons.closed()
    }

    /// At the end of the walk: an error if a polygon is still open.
    pub(crate) fn finish(&mut self) -> Result<(), Error> {
        self.polygons.finish()
    }

    fn rotate(&mut self, axis: Axis, degrees: Option<Real>, positive: bool) {
        let angle = degrees.map_or(self.turn, |d| BinaryAngle::from_degrees_bits(d.to_bits()));
        let angle = if positive {
            angle
        } else {
            BinaryAngle(angle.0.wrapping_neg())
        };
        self.state.frame.rotate(axis, angle);
    }

    /// Moves `length` steps along the heading, then bends under the tropism; the line if
    /// `draw` (none inside a polygon, where the move records a vertex if `vertex`).
    fn advance(&mut self, length: Real, draw: bool, vertex: bool) -> Result<Option<Drawn>, Error> {
        let overflow = Error::Walk(WalkError::Overflow);
        let length = length.checked_mul(self.state.step).ok_or(overflow)?;
        let delta = self.state.frame.step(length);
        let start = self.state.position;
        let mut end = start;
        for (e, d) in end.iter_mut().zip(delta) {
            *e = e.checked_add(d).ok_or(overflow)?;
        }
        self.state.position = end;
        if let Some(bend) = self.bend {
            self.state.frame.bend(bend.towards, bend.strength);
        }
        if self.polygons.recording() {
            if vertex {
                self.polygons.moved(end)?;
            }
            return Ok(None);
        }
        Ok(draw.then_some(Drawn::Line {
            segment: Segment3 {
                start,
                end,
                color: self.state.color,
            },
            width: self.state.width,
        }))
    }

    /// `[`: the state saved, a field at a time (inline copies, where the whole 80-byte
    /// state went through the library's `memcpy`).
    fn push(&mut self) -> Result<(), Error> {
        let state = &self.state;
        let saved = State3 {
            position: state.position,
            frame: state.frame,
            step: state.step,
            color: state.color,
            width: state.width,
        };
        self.stack
            .push(saved)
            .map_err(|_| Error::Walk(WalkError::StackTooDeep { capacity: STACK }))
    }

    /// `]`: the state saved last, back (nothing where none is saved), a value at a time:
    /// copied whole, or an array at a time, it went through the library's `memmove`.
    fn pop(&mut self) {
        if let Some(saved) = self.stack.last() {
            // Every field named, so that a field added to the state cannot be left out.
            let State3 {
                position,
                frame,
                step,
                color,
                width,
            } = saved;
            let state = &mut self.state;
            let [x, y, z] = *position;
            state.position = [x, y, z];
            let Frame3 { heading, left, up } = frame;
            let unit = |&[a, b, c]: &[i32; 3]| [a, b, c];
            state.frame.heading = unit(heading);
            state.frame.left = unit(left);
            state.frame.up = unit(up);
            state.step = *step;
            state.color = *color;
            state.width = *width;
            let depth = self.stack.len() - 1;
            self.stack.truncate(depth);
        }
    }

    /// `!`, `_`: the new line width (never below 0).
    fn change_width(&mut self, change: WidthChange) {
        let width = self.state.width;
        self.state.width = match change {
            WidthChange::Set(w) => w,
            WidthChange::Lower => width.saturating_sub(self.width_step),
            WidthChange::Raise => width.saturating_add(self.width_step),
        }
        .max(Real::ZERO);
    }

    /// Does what `module` says; what it draws, if anything.
    pub(crate) fn execute(&mut self, module: &DerivedModule) -> Result<Option<Drawn>, Error> {
        self.polygons.settle();
        let value = module.values.first();
        let positive = matches!(module.symbol, '+' | '&' | '\\');
        match module.symbol {
            '+' | '-' => self.rotate(Axis::Up, value, positive),
            '&' | '^' => self.rotate(Axis::Left, value, positive),
            '\\' | '/' => self.rotate(Axis::Heading, value, positive),
            '|' => self.state.frame.rotate(Axis::Up, BinaryAngle(1 << 31)),
            '$' => self.state.frame.roll_to_horizontal(),
            _ => match turtle_action(module) {
                Action::Step {
                    length,
                    draw,
                    vertex,
                } => return self.advance(length, draw, vertex),
                Action::Scale(factor) => {
                    self.state.step = self
                        .state
                        .step
                        .checked_mul(factor)
                        .ok_or(Error::Walk(WalkError::Overflow))?;
                }
                Action::Color(color) => self.state.color = color.apply(self.state.color),
                Action::Push => self.push()?,
                Action::Pop => self.pop(),
                Action::Width(change) => self.change_width(change),
                Action::StartPolygon => self.polygons.start(self.state.position)?,
                Action::Vertex => self.polygons.vertex(self.state.position)?,
                Action::EndPolygon => {
                    self.polygons.end()?;
                    return Ok(Some(Drawn::Polygon {
                        color: self.state.color,
                    }));
                }
                Action::Nothing => {}
            },
        }
        Ok(None)
    }
}

/// The 3D turtle, or the matrix turtle for a system in the matrix notation.
// Not boxed: no heap; a walk holds one turtle, whichever it is.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub(crate) enum AnyTurtle<const STACK: usize> {
    Space(Turtle3<STACK>),
    Matrix(MatrixTurtle<STACK>),
}

impl<const STACK: usize> AnyTurtle<STACK> {
    /// The turtle for `grammar`, bent by `tropism`.
    pub(crate) fn for_grammar(grammar: &ParametricGrammar, tropism: Option<Tropism>) -> Self {
        let turn = binary_angle(grammar.angle());
        if grammar.is_matrix() {
            Self::Matrix(MatrixTurtle::new(turn))
        } else {
            Self::Space(Turtle3::new(turn, grammar.width(), tropism))
        }
    }

    /// The vertices of the polygon the last module closed.
    pub(crate) fn closed_polygon(&self) -> &[[Real; 3]] {
        match self {
            Self::Space(turtle) => turtle.closed_polygon(),
            Self::Matrix(_) => &[],
        }
    }

    /// At the end of the walk: an error if a polygon is still open.
    pub(crate) fn finish(&mut self) -> Result<(), Error> {
        match self {
            Self::Space(turtle) => turtle.finish(),
            Self::Matrix(_) => Ok(()),
        }
    }

    pub(crate) fn state(&self) -> TurtleState {
        match self {
            Self::Space(turtle) => turtle.state(),
            Self::Matrix(turtle) => {
                let (position, heading) = turtle.position_and_heading();
                TurtleState { position, heading }
            }
        }
    }

    pub(crate) fn execute(&mut self, module: &DerivedModule) -> Result<Option<Drawn>, Error> {
        match self {
            Self::Space(turtle) => turtle.execute(module),
            Self::Matrix(turtle) => Ok(turtle.execute(module)?.map(|segment| Drawn::Line {
                segment,
                width: Real::ZERO,
            })),
        }
    }
}
