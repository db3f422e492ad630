//! Drawing parametric systems: the derived modules read as turtle commands in ABOP's
//! notation, `F(l)` and `f(l)` a step of `l` units, `+(a)` and `-(a)` a turn of `a` degrees
//! (without a parameter: one step, the system's angle), `|`, `[`, `]`; fitted and drawn
//! like every L-system (a sizing walk, a checking walk in pixels, the draw).

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::{DerivedModule, ParametricGrammar, ParametricWalker};
use crate::error::{DrawError, Error, FitError};
use crate::lsystem::alphabet::{Command, Dialect};
use crate::lsystem::drawing::{
    colors, draw_segment, fitted_start, measure, only_target_errors, pixel_box, Bounds,
};
use crate::lsystem::turtle::{next_segment, Segment, Start, Turtle, WalkStats, DEFAULT_STACK};
use crate::lsystem::walker::{DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::math::trig::BinaryAngle;
use crate::math::Real;
use crate::render::fit::{Orientation, DEFAULT_MARGIN};
use crate::render::palette::{Colors, Palette};

/// What the turtle does for a derived module.
fn command(module: &DerivedModule) -> Command {
    let value = module.values.first();
    let turn = |degrees: Real| BinaryAngle::from_degrees_bits(degrees.to_bits());
    match (module.symbol, value) {
        ('F', None) => Command::Draw,
        ('F', Some(length)) => Command::DrawBy(length),
        ('f', None) => Command::Move,
        ('f', Some(length)) => Command::MoveBy(length),
        ('+', None) => Command::Left,
        ('+', Some(degrees)) => Command::FreeLeft(turn(degrees)),
        ('-', None) => Command::Right,
        ('-', Some(degrees)) => Command::FreeRight(turn(degrees)),
        ('|', _) => Command::Around,
        ('[', _) => Command::Push,
        (']', _) => Command::Pop,
        _ => Command::Nothing,
    }
}

/// The segments a parametric system draws at an order, computed on the fly.
#[derive(Debug, Clone)]
pub struct ParametricSegments<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
> {
    walker: ParametricWalker<'g, DEPTH>,
    turtle: Turtle<'g, STACK>,
    segments: u64,
    failed: bool,
}

impl<'g, const DEPTH: usize, const STACK: usize> ParametricSegments<'g, DEPTH, STACK> {
    /// The segments of `grammar` at `order` from `start`.
    pub fn new(grammar: &'g ParametricGrammar, order: u32, start: Start) -> Result<Self, Error> {
        Ok(Self {
            walker: ParametricWalker::new(grammar, order)?,
            turtle: Turtle::new(grammar.headings(), Dialect::Abop, start)?,
            segments: 0,
            failed: false,
        })
    }

    fn budget(mut self, symbols: u64) -> Self {
        self.walker = self.walker.with_budget(symbols);
        self
    }

    /// Segments drawn so far.
    pub const fn segments(&self) -> u64 {
        self.segments
    }
}

impl<const DEPTH: usize, const STACK: usize> Iterator for ParametricSegments<'_, DEPTH, STACK> {
    type Item = Result<Segment, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let (walker, turtle) = (&mut self.walker, &mut self.turtle);
        next_segment(&mut self.failed, &mut self.segments, || {
            Some(
                walker
                    .next()?
                    .and_then(|module| turtle.execute(command(&module))),
            )
        })
    }
}

/// A parametric system at an order, ready to be fitted to a target.
#[derive(Debug, Clone, Copy)]
pub struct ParametricLSystem<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
> {
    grammar: &'g ParametricGrammar,
    order: u32,
    orientation: Orientation,
    budget: u64,
}

impl<'g, const DEPTH: usize, const STACK: usize> ParametricLSystem<'g, DEPTH, STACK> {
    /// `grammar` derived `order` times, heading up (ABOP's plants grow up).
    pub const fn new(grammar: &'g ParametricGrammar, order: u32) -> Self {
        Self {
            grammar,
            order,
            orientation: Orientation::Up,
            budget: DEFAULT_BUDGET,
        }
    }

    /// Which way the first heading points on screen.
    #[must_use]
    pub const fn with_orientation(mut self, orientation: Orientation) -> Self {
        self.orientation = orientation;
        self
    }

    /// Caps every walk at `symbols` modules.
    #[must_use]
    pub const fn with_budget(mut self, symbols: u64) -> Self {
        self.budget = symbols;
        self
    }

    fn segments(&self, start: Start) -> Result<ParametricSegments<'g, DEPTH, STACK>, Error> {
        Ok(ParametricSegments::new(self.grammar, self.order, start)?.budget(self.budget))
    }

    /// Scales and centres the drawing into `area` (less a margin), colours from `palette`
    /// by the turtle's colour index.
    pub fn fit<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
    ) -> Result<ParametricDrawing<'g, Colors<'p, C>, DEPTH, STACK>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let palette = colors(palette)?;
        let bounds = measure(self.segments(Start::default())?)?;
        let start = fitted_start(bounds, Real::ONE, self.orientation, &area, DEFAULT_MARGIN)?;
        let pixels: Option<Bounds> = measure(self.segments(start)?)?;
        Ok(ParametricDrawing {
            system: *self,
            start,
            palette,
            bounding_box: pixel_box(self.orientation, pixels, start),
        })
    }
}

/// A fitted parametric system: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct ParametricDrawing<
    'g,
    P,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
> {
    system: ParametricLSystem<'g, DEPTH, STACK>,
    start: Start,
    palette: P,
    bounding_box: Rectangle,
}

impl<P: Palette, const DEPTH: usize, const STACK: usize> ParametricDrawing<'_, P, DEPTH, STACK> {
    /// Draws, reporting the engine's errors too.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<WalkStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let clip = target.bounding_box();
        let mut segments = self.system.segments(self.start)?;
        let mut last_end = None;
        for segment in segments.by_ref() {
            let segment = segment?;
            let color = self.palette.color(u16::from(segment.color), u16::MAX);
            let end = draw_segment(
                target,
                self.system.orientation,
                segment,
                color,
                last_end,
                &clip,
            )
            .map_err(DrawError::Target)?;
            last_end = Some(end);
        }
        Ok(WalkStats {
            segments: segments.segments(),
            ..WalkStats::default()
        })
    }
}

impl<P: Palette, const DEPTH: usize, const STACK: usize> Drawable
    for ParametricDrawing<'_, P, DEPTH, STACK>
{
    type Color = P::Color;
    type Output = WalkStats;

    fn draw<D>(&self, target: &mut D) -> Result<WalkStats, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}

impl<P, const DEPTH: usize, const STACK: usize> Dimensions
    for ParametricDrawing<'_, P, DEPTH, STACK>
{
    fn bounding_box(&self) -> Rectangle {
        self.bounding_box
    }
}
