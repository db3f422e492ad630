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
//! `F(l)`, `f(l)`, `[ ]`, `r`, `R` and the colour modules act as in 2D.

use embedded_graphics::prelude::*;
use heapless::Vec;

use super::action::{turtle_action, Action};
use super::context::MAX_CONTEXT_SLOTS;
use super::environment::{Environment, Held, TurtleState};
use super::grammar::ParametricGrammar;
use super::matrix::MatrixTurtle;
use super::values::DerivedModule;
use super::walker::ParametricWalker;
use crate::error::{DrawError, Error, WalkError};
use crate::lsystem::segments::next_segment;
use crate::lsystem::turtle::DEFAULT_STACK;
use crate::lsystem::walker::{check_order, DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::math::frame3::{Axis, Frame3};
use crate::math::trig::BinaryAngle;
use crate::math::{Angle, Real};
use crate::render::palette::Palette;
use crate::render::raster::draw_line;
#[cfg(doc)]
use crate::render::space::DEPTH_LEVELS;
use crate::render::space::{middle, SpaceFit};

pub use crate::render::space::Segment3;

/// Everything `[` saves.
#[derive(Debug, Clone, Copy)]
struct State3 {
    position: [Real; 3],
    frame: Frame3,
    step: Real,
    color: u8,
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

/// The 3D turtle: a state and a stack of saved states (`STACK` deep).
#[derive(Debug, Clone)]
pub(crate) struct Turtle3<const STACK: usize> {
    turn: BinaryAngle,
    state: State3,
    stack: Vec<State3, STACK>,
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

    pub(crate) fn new(turn: BinaryAngle) -> Self {
        Self {
            turn,
            state: State3 {
                position: [Real::ZERO; 3],
                frame: Frame3::default(),
                step: Real::ONE,
                color: 0,
            },
            stack: Vec::new(),
        }
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

    /// Moves `length` steps along the heading; the segment if `draw`.
    fn advance(&mut self, length: Real, draw: bool) -> Result<Option<Segment3>, Error> {
        let overflow = Error::Walk(WalkError::Overflow);
        let length = length.checked_mul(self.state.step).ok_or(overflow)?;
        let delta = self.state.frame.step(length);
        let start = self.state.position;
        let mut end = start;
        for (e, d) in end.iter_mut().zip(delta) {
            *e = e.checked_add(d).ok_or(overflow)?;
        }
        self.state.position = end;
        Ok(draw.then_some(Segment3 {
            start,
            end,
            color: self.state.color,
        }))
    }

    /// Does what `module` says; the segment it draws, if any.
    pub(crate) fn execute(&mut self, module: &DerivedModule) -> Result<Option<Segment3>, Error> {
        let value = module.values.first();
        let positive = matches!(module.symbol, '+' | '&' | '\\');
        match module.symbol {
            '+' | '-' => self.rotate(Axis::Up, value, positive),
            '&' | '^' => self.rotate(Axis::Left, value, positive),
            '\\' | '/' => self.rotate(Axis::Heading, value, positive),
            '|' => self.state.frame.rotate(Axis::Up, BinaryAngle(1 << 31)),
            '$' => self.state.frame.roll_to_horizontal(),
            _ => match turtle_action(module) {
                Action::Step { length, draw } => return self.advance(length, draw),
                Action::Scale(factor) => {
                    self.state.step = self
                        .state
                        .step
                        .checked_mul(factor)
                        .ok_or(Error::Walk(WalkError::Overflow))?;
                }
                Action::Color(color) => self.state.color = color.apply(self.state.color),
                Action::Push => self
                    .stack
                    .push(self.state)
                    .map_err(|_| Error::Walk(WalkError::StackTooDeep { capacity: STACK }))?,
                Action::Pop => {
                    if let Some(state) = self.stack.pop() {
                        self.state = state;
                    }
                }
                Action::Nothing => {}
            },
        }
        Ok(None)
    }
}

/// The 3D turtle, or the matrix turtle for a system in the matrix notation.
#[derive(Debug, Clone)]
enum AnyTurtle<const STACK: usize> {
    Space(Turtle3<STACK>),
    Matrix(MatrixTurtle<STACK>),
}

impl<const STACK: usize> AnyTurtle<STACK> {
    fn state(&self) -> TurtleState {
        match self {
            Self::Space(turtle) => turtle.state(),
            Self::Matrix(turtle) => {
                let (position, heading) = turtle.position_and_heading();
                TurtleState { position, heading }
            }
        }
    }

    fn execute(&mut self, module: &DerivedModule) -> Result<Option<Segment3>, Error> {
        match self {
            Self::Space(turtle) => turtle.execute(module),
            Self::Matrix(turtle) => turtle.execute(module),
        }
    }
}

/// The segments a 3D system draws at an order, in turtle units, computed on the fly.
#[derive(Debug, Clone)]
pub struct Segments3<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    walker: ParametricWalker<'g, DEPTH, SLOTS>,
    turtle: AnyTurtle<STACK>,
    environment: Option<Held<'g>>,
    segments: u64,
    failed: bool,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    Segments3<'g, DEPTH, STACK, SLOTS>
{
    /// The segments of `grammar` at `order`, from the origin, one unit a step.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        Ok(Self::starting(grammar, order, DEFAULT_BUDGET, None))
    }

    /// Built in one piece, as [`ParametricWalker::starting`] is.
    #[inline(always)]
    pub(crate) fn starting(
        grammar: &'g ParametricGrammar,
        order: u32,
        budget: u64,
        environment: Option<Held<'g>>,
    ) -> Self {
        Self {
            walker: ParametricWalker::starting(grammar, order, budget),
            turtle: if grammar.is_matrix() {
                AnyTurtle::Matrix(MatrixTurtle::new(binary_angle(grammar.angle())))
            } else {
                AnyTurtle::Space(Turtle3::new(binary_angle(grammar.angle())))
            },
            environment,
            segments: 0,
            failed: false,
        }
    }

    /// Caps the walk at `symbols` modules.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.walker = self.walker.with_budget(symbols);
        self
    }

    /// Grows an open system in `environment`: `env(k)` asks it about the turtle.
    #[must_use]
    pub fn with_environment(mut self, environment: &'g dyn Environment) -> Self {
        self.environment = Some(Held(environment));
        self
    }

    /// Segments drawn so far.
    pub const fn segments(&self) -> u64 {
        self.segments
    }
}

impl<const DEPTH: usize, const STACK: usize, const SLOTS: usize> Iterator
    for Segments3<'_, DEPTH, STACK, SLOTS>
{
    type Item = Result<Segment3, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let (walker, turtle, environment) = (&mut self.walker, &mut self.turtle, self.environment);
        next_segment(&mut self.failed, &mut self.segments, || {
            let module = match environment {
                Some(Held(environment)) => {
                    // Every module expanded before the next one is handed out is where
                    // the turtle stands now.
                    let state = turtle.state();
                    let ask = |query: Real| environment.query(query, &state);
                    walker.next_queried(Some(&ask))
                }
                None => walker.next(),
            }?;
            Some(module.and_then(|module| turtle.execute(&module)))
        })
    }
}

/// Draws `segments` fitted by `space`: each line in its colour index, or with depth cue
/// in the palette's colour for its middle's depth ([`DEPTH_LEVELS`] levels, nearer later).
pub(crate) fn draw_segments<D, P>(
    space: &SpaceFit,
    target: &mut D,
    segments: impl Iterator<Item = Result<Segment3, Error>>,
    palette: &P,
) -> Result<(), DrawError<D::Error>>
where
    D: DrawTarget<Color = P::Color>,
    P: Palette,
{
    let clip = target.bounding_box();
    let mut last_end = None;
    for segment in segments {
        let segment = segment?;
        let ((from, near), (to, far)) = (space.place(segment.start), space.place(segment.end));
        let (value, max) = space.color_value(middle(near, far), u16::from(segment.color));
        draw_line(
            target,
            from,
            to,
            last_end == Some(from),
            palette.color(value, max),
            &clip,
        )
        .map_err(DrawError::Target)?;
        last_end = Some(to);
    }
    Ok(())
}
