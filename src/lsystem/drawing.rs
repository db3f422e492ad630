//! L-systems as embedded-graphics drawables: fit to a target (or place explicitly), then draw.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::grammar::Grammar;
use super::pen::Pen;
use super::segments::{Decision, Drawn, Segments, WalkStats};
use super::sizing::{
    bounds, fitted_placement, pixel_box, pixel_of, point, predicted_box, start_heading, unit_start,
    widen, Bounds, Sizing, MIN_UNIT_EXPONENT,
};
use super::table::{Cell, Summary, Table};
use super::turtle::{Start, TurtlePoint, DEFAULT_STACK};
use super::walker::{DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::error::{DrawError, Error, FitError, WalkError};
use crate::math::Real;
use crate::render::fit::{Orientation, DEFAULT_MARGIN};
use crate::render::palette::{Colors, Palette};

/// An L-system at an order, ready to be fitted or placed on a target.
///
/// `DEPTH` and `STACK` are the walker's and the turtle's capacities (see [`Segments`]).
#[derive(Debug, Clone, Copy)]
pub struct LSystem<'g, 'a, const DEPTH: usize = DEFAULT_DEPTH, const STACK: usize = DEFAULT_STACK> {
    grammar: &'g Grammar<'a>,
    order: u32,
    budget: u64,
    margin: u32,
    orientation: Orientation,
}

/// Where an L-system goes on the target, when it is not fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Placement {
    /// The pixel the turtle starts on.
    pub origin: Point,
    /// One step, in pixels.
    pub step: Real,
    /// The first heading in turns of the system's angle, counter-clockwise from +x.
    pub turns: i32,
}

impl<'g, 'a> LSystem<'g, 'a> {
    /// `grammar` derived `order` times, with the default capacities (orders up to 16,
    /// branches 20 deep).
    pub const fn new(grammar: &'g Grammar<'a>, order: u32) -> Self {
        Self::with_capacity(grammar, order)
    }
}

impl<'g, 'a, const DEPTH: usize, const STACK: usize> LSystem<'g, 'a, DEPTH, STACK> {
    /// `grammar` derived `order` times, with the capacities in the type:
    /// `LSystem::<'_, '_, 40, 64>::with_capacity(..)`.
    pub const fn with_capacity(grammar: &'g Grammar<'a>, order: u32) -> Self {
        Self {
            grammar,
            order,
            budget: DEFAULT_BUDGET,
            margin: DEFAULT_MARGIN,
            orientation: Orientation::Right,
        }
    }

    /// Which way the first heading points on screen (default: right).
    #[must_use]
    pub const fn with_orientation(mut self, orientation: Orientation) -> Self {
        self.orientation = orientation;
        self
    }

    /// Caps every walk at `symbols` symbols ([`WalkError::BudgetExhausted`](crate::error::WalkError::BudgetExhausted) beyond).
    #[must_use]
    pub const fn with_budget(mut self, symbols: u64) -> Self {
        self.budget = symbols;
        self
    }

    /// Pixels left free on each side when fitting.
    #[must_use]
    pub const fn with_margin(mut self, pixels: u32) -> Self {
        self.margin = pixels;
        self
    }

    /// The segments, with an explicit start.
    pub fn segments(&self, start: Start) -> Result<Segments<'g, 'a, DEPTH, STACK>, Error> {
        Ok(Segments::with_capacity(self.grammar, self.order, start)?.with_budget(self.budget))
    }

    /// The segments in pixels (any step taken; see `Segments::in_pixels`).
    fn pixel_segments(&self, start: Start) -> Result<Segments<'g, 'a, DEPTH, STACK>, Error> {
        Ok(Segments::in_pixels(self.grammar, self.order, start)?.with_budget(self.budget))
    }

    /// Walks once in turtle units and returns the bounding box of what is drawn
    /// ([`FitError::EmptyDrawing`] if nothing is).
    pub fn bounds(&self) -> Result<Bounds, Error> {
        self.bounds_from(Start::default(), false)?
            .ok_or(Error::Fit(FitError::EmptyDrawing))
    }

    /// The bounding box of what is drawn, by a walk in turtle units, and the exponent of
    /// the first step in them: 1, or 2¹⁰, 2²⁰ or 2³⁰ where `@` shrinks steps below what
    /// one resolves. A system whose steps span more than that (`@` shrinking or growing
    /// them by many orders of magnitude, as spirals and shells do) is measured taking
    /// steps of any size, from a first step of 2³⁰ down (by 2¹⁰, then squaring, to
    /// 2^[`MIN_UNIT_EXPONENT`]) to where it fits, then again in the unit that makes it
    /// about 2²⁴ units across: its smallest steps then round by 2⁻³³ units, far below a
    /// pixel, the fit's scale keeps its bits, and the drawing pass is checked by a walk of
    /// its own (see `Sizing::wide`).
    fn sized_bounds(&self) -> Result<(Sizing, i32), Error> {
        let mut result = Err(Error::Walk(WalkError::StepUnderflow));
        for exponent in [0, 10, 20, 30] {
            result = self
                .sizing_from(unit_start(exponent), false)
                .map(|sizing| (sizing, exponent));
            if !matches!(result, Err(Error::Walk(WalkError::StepUnderflow))) {
                break;
            }
        }
        if !matches!(
            result,
            Err(Error::Walk(WalkError::StepUnderflow | WalkError::Overflow))
        ) {
            return result;
        }
        let wide = |exponent: i32| {
            self.sizing_from(unit_start(exponent), true).map(|sizing| {
                (
                    Sizing {
                        wide: true,
                        ..sizing
                    },
                    exponent,
                )
            })
        };
        let mut exponent = 30;
        let (sizing, exponent) = loop {
            match wide(exponent) {
                Err(Error::Walk(WalkError::Overflow)) if exponent > MIN_UNIT_EXPONENT => {
                    exponent = if exponent > -30 {
                        exponent - 10
                    } else {
                        (2 * exponent).max(MIN_UNIT_EXPONENT)
                    };
                }
                other => break other?,
            }
        };
        // The extent scales with the unit: about 2²⁴ units gives the fit's scale more bits.
        let across = sizing.bounds.map_or(0, |b| {
            let span = |low: Real, high: Real| high.to_bits().saturating_sub(low.to_bits());
            span(b.min.x, b.max.x).max(span(b.min.y, b.max.y))
        });
        // Whole units across, in bits: 24 leaves the scale (pixels a unit, in Q32) about 24
        // significant bits on a display up to 2⁸ wide, 2¹⁶ for 2¹⁶, and 7 bits of margin.
        let bits = 32 - across.leading_zeros() as i32;
        if across > 0 && !(23..=25).contains(&bits) {
            if let Ok(refined) = wide(exponent + 24 - bits) {
                return Ok(refined);
            }
        }
        Ok((sizing, exponent))
    }

    /// The bounding box of what is drawn from `start`, by a walk; `None` if nothing is.
    /// `in_pixels`: the walk's unit is a pixel (see `Segments::in_pixels`).
    fn bounds_from(&self, start: Start, in_pixels: bool) -> Result<Option<Bounds>, Error> {
        self.sizing_from(start, in_pixels)
            .map(|sizing| sizing.bounds)
    }

    /// [`bounds_from`](Self::bounds_from), with the segments counted.
    fn sizing_from(&self, start: Start, in_pixels: bool) -> Result<Sizing, Error> {
        let mut walk = if in_pixels {
            self.pixel_segments(start)?
        } else {
            self.segments(start)?
        };
        let mut bounds: Option<Bounds> = None;
        walk.for_each_segment(|segment| {
            widen(&mut bounds, segment);
            Ok::<(), Error>(())
        })?;
        let stats = walk.stats();
        Ok(Sizing {
            bounds,
            segments: stats.segments,
            symbols: stats.symbols,
            scalings: walk.scalings(),
            wide: false,
        })
    }

    /// Scales and centres the drawing into `area` (less the margin), colours from `palette`.
    ///
    /// A sizing pass measures the drawing in turtle units. The drawing pass is that walk
    /// scaled, each position within a margin of rounding (half an ulp a step, more for each
    /// `@`), where no `@` factor is larger than 1, there are no lengths, and moves (`f`, `G`,
    /// `M`) come at a step of at most half a pixel: then its pixel bounding box follows from
    /// the sizing pass's and it cannot fail, and fitting and drawing take two walks.
    /// Otherwise, or where an edge of the box lies within that margin of a pixel's boundary,
    /// a second pass at the chosen scale checks the drawing and measures the box (three
    /// walks).
    /// A drawing wider than 2³¹ turtle units is [`WalkError::Overflow`](crate::error::WalkError::Overflow): fitted, its step would
    /// be below 2⁻²³ pixels, too fine for fixed point to place it truthfully.
    pub fn fit<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
    ) -> Result<LSystemDrawing<'g, 'a, Colors<'p, C>, DEPTH, STACK>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        self.fit_with(area, colors(palette)?)
    }

    /// [`fit`](Self::fit) with any [`Palette`] for the colour indices (a [`Gradient`], say).
    ///
    /// [`Gradient`]: crate::render::Gradient
    pub fn fit_with<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        self.fit_inner(area, palette, None)
    }

    /// [`fit_with`](Self::fit_with), measuring and drawing through the expansion table held
    /// in `cells` ([`cells_needed`](crate::lsystem::cells_needed) of them): the picture's box comes
    /// from the table instead of a sizing walk (the same box). Where the picture has more
    /// segments than the area has pixels, drawing skips what lies outside the target and
    /// draws what lies within one pixel as that pixel, so its cost follows the picture, not
    /// the segment count (the same pixels as a full draw); below that it walks, which costs
    /// less than consulting the table at every expansion. With too few cells, or a system
    /// the table does not cover (free angles, `@`, `\`, `/`, `D`, `M`), it walks as
    /// `fit_with` does.
    pub fn fit_in<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
        cells: &'g mut [Cell],
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        self.fit_inner(area, palette, Some(cells))
    }

    fn fit_inner<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
        mut cells: Option<&'g mut [Cell]>,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let tabled = match cells.as_deref_mut() {
            Some(cells) => self.table_sizing(cells)?,
            None => None,
        };
        let (sizing, unit) = match tabled {
            Some(sizing) => (sizing, 0),
            None => self.sized_bounds()?,
        };
        let bounds = sizing.bounds;
        let (start, scale) = fitted_placement(bounds, unit, self.orientation, &area, self.margin)?;
        // A first step below 2⁻²⁰ pixel: positions round by up to 2⁻³³ pixel a step, so a
        // picture that many steps across could drift by pixels (Koch at order 18 on 64
        // pixels). A system measured in a unit of its own (`@` over many orders of
        // magnitude) takes it while its walk is under 2³¹ symbols: a quarter pixel at most.
        if start.too_fine() && (!sizing.wide || sizing.symbols >= 1 << 31) {
            return Err(Error::Walk(WalkError::StepTooFine));
        }
        // Known from the sizing where the drawing pass is that walk scaled (see
        // `predicted_box`): then the pass that would measure it is not walked.
        let predicted = sizing
            .margin(self.grammar, scale, start)
            .and_then(|margin| predicted_box(self.orientation, bounds, scale, start, margin));
        // Level of detail pays where segments outnumber the pixels they are drawn into; below
        // that, consulting the table at every expansion costs more than it saves (the same
        // pixels either way).
        let pixels = u64::from(area.size.width) * u64::from(area.size.height);
        let cells = cells.filter(|_| sizing.segments > pixels);
        self.prepared(start, palette, cells, predicted)
    }

    /// The sizing from the expansion table in `cells`, in turtle units, without a walk:
    /// `None` where the table does not cover the system or the cells are too few.
    fn table_sizing(&self, cells: &mut [Cell]) -> Result<Option<Sizing>, Error> {
        let Some(summary) = Table::build(self.grammar, self.order, Real::ONE, 0, cells)
            .map(|table| *table.picture())
        else {
            return Ok(None);
        };
        Self::check_nesting(&summary)?;
        Ok(Some(Sizing {
            bounds: summary.drawn.map(bounds),
            segments: summary.segments,
            symbols: summary.symbols,
            scalings: 0,
            wide: false,
        }))
    }

    /// Draws from an explicit placement, colours from `palette`. The drawing is walked once
    /// here to check it and to measure its bounding box.
    pub fn place<'p, C: PixelColor>(
        &self,
        placement: Placement,
        palette: &'p [C],
    ) -> Result<LSystemDrawing<'g, 'a, Colors<'p, C>, DEPTH, STACK>, Error> {
        self.place_with(placement, colors(palette)?)
    }

    /// [`place`](Self::place) with any [`Palette`] for the colour indices.
    pub fn place_with<P: Palette>(
        &self,
        placement: Placement,
        palette: P,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        let (x, y) = self.orientation.to_picture((
            Real::from_int(placement.origin.x),
            Real::from_int(placement.origin.y),
        ));
        let position = TurtlePoint { x, y };
        let start = Start {
            position,
            step: placement.step,
            step_shift: 0,
            turns: placement.turns,
        };
        if start.too_fine() {
            return Err(Error::Walk(WalkError::StepTooFine));
        }
        self.prepared(start, palette, None, None)
    }

    /// Checks the drawing from `start` and measures its pixel box: from the table at this
    /// step if `cells` can hold one, else the `predicted` box if there is one, else by a
    /// walk.
    fn prepared<P: Palette>(
        &self,
        start: Start,
        palette: P,
        cells: Option<&'g mut [Cell]>,
        predicted: Option<Rectangle>,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        let table = cells.and_then(|cells| {
            let heading = start_heading(self.grammar, start.turns);
            Table::build(self.grammar, self.order, start.step, heading, cells)
        });
        let walked = |system: &Self| -> Result<Rectangle, Error> {
            if let Some(predicted) = predicted {
                // What the pass would refuse before its first step (the order).
                system.pixel_segments(start)?;
                return Ok(predicted);
            }
            let pixels = system.bounds_from(start, true)?;
            Ok(pixel_box(system.orientation, pixels, start))
        };
        let (bounding_box, table) = match table {
            Some(table) => match self.checked_picture(&table, start)? {
                Some(pixels) => (pixel_box(self.orientation, pixels, start), Some(table)),
                None => (walked(self)?, None),
            },
            None => (walked(self)?, None),
        };
        Ok(LSystemDrawing {
            system: *self,
            start,
            palette,
            bounding_box,
            table,
        })
    }

    /// What the walk from `start` would check, from the table: every position in range and
    /// the branches within the turtle stack. The drawn box, if any is drawn; `Ok(None)` inside
    /// the outer `Option` when the table cannot say (then the caller walks).
    fn checked_picture(
        &self,
        table: &Table<'_>,
        start: Start,
    ) -> Result<Option<Option<Bounds>>, Error> {
        let summary = table.picture();
        let origin = (start.position.x, start.position.y);
        // Every position within reach of the start stays in range; where the bound cannot
        // say so, the walk checks each step.
        let in_range = |o: Real| {
            o.to_bits()
                .unsigned_abs()
                .checked_add(summary.reach)
                .is_some_and(|far| far <= i64::MAX.unsigned_abs())
        };
        if !(in_range(origin.0) && in_range(origin.1)) {
            return Ok(None);
        }
        Self::check_nesting(summary)?;
        Ok(Some(
            summary
                .drawn
                .and_then(|drawn| drawn.offset(origin))
                .map(bounds),
        ))
    }

    /// What a walk of the picture `summary` sums up would refuse: branches nested deeper
    /// than the turtle stack holds.
    fn check_nesting(summary: &Summary) -> Result<(), Error> {
        if usize::try_from(summary.nesting).map_or(true, |nesting| nesting > STACK) {
            return Err(Error::Walk(WalkError::StackTooDeep { capacity: STACK }));
        }
        Ok(())
    }

    /// The pixel for a point of a drawing pass (whose turtle works in pixels).
    fn pixel_of(&self, p: TurtlePoint) -> Point {
        pixel_of(self.orientation, p)
    }
}

pub(crate) use crate::error::only_target_errors;

/// A slice of colours as a palette; an empty one is [`FitError::EmptyPalette`].
pub(crate) fn colors<C: PixelColor>(palette: &[C]) -> Result<Colors<'_, C>, Error> {
    Colors::new(palette).ok_or(Error::Fit(FitError::EmptyPalette))
}

/// A fitted or placed L-system with its palette: an embedded-graphics [`Drawable`].
///
/// Colour index `i` of the system is drawn as `palette.color(i, u16::MAX)` (never
/// "inside"): with a list of colours ([`Colors`], what `fit` and `place` build from a
/// slice), `colours[i % len]`. Lines go to the target as horizontal and vertical runs
/// through `fill_solid`; clipping is the target's.
#[derive(Debug, Clone)]
pub struct LSystemDrawing<
    'g,
    'a,
    P,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
> {
    system: LSystem<'g, 'a, DEPTH, STACK>,
    start: Start,
    palette: P,
    bounding_box: Rectangle,
    /// The expansion table at this drawing's step, when fitted with one.
    table: Option<Table<'g>>,
}

impl<P: Palette, const DEPTH: usize, const STACK: usize> LSystemDrawing<'_, '_, P, DEPTH, STACK> {
    /// Where the turtle starts and its step, in pixels (turtle space: y up).
    pub const fn start(&self) -> Start {
        self.start
    }

    /// Draws, reporting the engine's errors too (there are none once constructed: the same
    /// walk was checked when fitting or placing).
    pub fn try_draw<D>(&self, target: &mut D) -> Result<WalkStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let clip = target.bounding_box();
        let mut segments = self.system.pixel_segments(self.start)?;
        let mut pen = Pen::default();
        if let Some(table) = &self.table {
            let decide = |cell: &Summary, start: TurtlePoint| self.decide(cell, start, &clip);
            while let Some(drawn) = segments.next_guided(table, decide) {
                match drawn? {
                    Drawn::Segment(segment) => {
                        self.draw_segment(target, segment, &mut pen, &clip)?
                    }
                    Drawn::Dot(at, color) => {
                        let pixel = self.system.pixel_of(at);
                        let color = self.palette.color(u16::from(color), u16::MAX);
                        pen.dot(target, pixel, color, &clip)
                            .map_err(DrawError::Target)?;
                    }
                }
            }
        } else {
            segments
                .for_each_segment(|segment| self.draw_segment(target, segment, &mut pen, &clip))?;
        }
        pen.finish(target).map_err(DrawError::Target)?;
        Ok(segments.stats())
    }

    /// Draws one segment with `pen`.
    #[inline(always)]
    fn draw_segment<D>(
        &self,
        target: &mut D,
        segment: super::turtle::Segment,
        pen: &mut Pen<P::Color>,
        clip: &Rectangle,
    ) -> Result<(), DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let color = self.palette.color(u16::from(segment.color), u16::MAX);
        pen.draw(target, self.system.orientation, segment, color, clip)
            .map_err(DrawError::Target)
    }

    /// What to do with an expansion starting at `start`: skip it if none of it is on the
    /// target, draw it as a dot if it lies within one pixel in one colour, else walk in.
    fn decide(&self, cell: &Summary, start: TurtlePoint, clip: &Rectangle) -> Decision {
        let Some(drawn) = cell.drawn else {
            return Decision::Skip;
        };
        let Some(drawn) = drawn.offset((start.x, start.y)) else {
            return Decision::Expand;
        };
        let (a, b) = (
            self.system.pixel_of(point(drawn.min)),
            self.system.pixel_of(point(drawn.max)),
        );
        let (low, high) = (
            Point::new(a.x.min(b.x), a.y.min(b.y)),
            Point::new(a.x.max(b.x), a.y.max(b.y)),
        );
        let clip_end = clip.top_left + clip.size;
        let outside = high.x < clip.top_left.x
            || high.y < clip.top_left.y
            || low.x >= clip_end.x
            || low.y >= clip_end.y;
        if outside {
            Decision::Skip
        } else if a == b && cell.colorless {
            Decision::Dot
        } else {
            Decision::Expand
        }
    }
}

impl<P: Palette, const DEPTH: usize, const STACK: usize> Drawable
    for LSystemDrawing<'_, '_, P, DEPTH, STACK>
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
    for LSystemDrawing<'_, '_, P, DEPTH, STACK>
{
    fn bounding_box(&self) -> Rectangle {
        self.bounding_box
    }
}
