//! L-systems as embedded-graphics drawables: fit to a target (or place explicitly), then draw.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::grammar::Grammar;
use super::turtle::{Segments, Start, TurtlePoint, WalkStats, DEFAULT_STACK};
use super::walker::{DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::error::{DrawError, Error, FitError};
use crate::math::Real;
use crate::render::fit::{fit, Orientation, DEFAULT_MARGIN};
use crate::render::palette::{Colors, Palette};
use crate::render::raster;

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

/// The extent of a drawing in turtle space.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bounds {
    /// Smallest x and y of any segment end.
    pub min: TurtlePoint,
    /// Largest x and y of any segment end.
    pub max: TurtlePoint,
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

    /// Caps every walk at `symbols` symbols ([`WalkError::BudgetExhausted`](crate::WalkError::BudgetExhausted) beyond).
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

    /// Walks once in turtle units and returns the bounding box of what is drawn.
    pub fn bounds(&self) -> Result<Bounds, Error> {
        self.bounds_from(Start::default())
    }

    fn bounds_from(&self, start: Start) -> Result<Bounds, Error> {
        let mut bounds: Option<Bounds> = None;
        self.segments(start)?.try_for_each_segment(|segment| {
            for p in [segment.start, segment.end] {
                let b = bounds.get_or_insert(Bounds { min: p, max: p });
                b.min.x = b.min.x.min(p.x);
                b.min.y = b.min.y.min(p.y);
                b.max.x = b.max.x.max(p.x);
                b.max.y = b.max.y.max(p.y);
            }
            Ok(())
        })?;
        bounds.ok_or(Error::Fit(FitError::EmptyDrawing))
    }

    /// Scales and centres the drawing into `area` (less the margin), colours from `palette`.
    ///
    /// A sizing pass measures the drawing in turtle units; a second pass at the chosen scale
    /// checks it and measures its pixel bounding box, so that drawing cannot fail.
    /// A drawing wider than 2³¹ turtle units is [`WalkError::Overflow`](crate::WalkError::Overflow): fitted, its step would
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
    /// [`Gradient`]: crate::Gradient
    pub fn fit_with<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let bounds = self.bounds()?;
        let fitted = fit(
            (bounds.min.x, bounds.min.y),
            (bounds.max.x, bounds.max.y),
            self.orientation,
            &area,
            self.margin,
        )?;
        let (x, y) = self.orientation.to_picture(fitted.origin);
        self.prepared(
            Start {
                position: TurtlePoint { x, y },
                step: fitted.scale,
                turns: 0,
            },
            palette,
        )
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
        self.prepared(
            Start {
                position,
                step: placement.step,
                turns: placement.turns,
            },
            palette,
        )
    }

    fn prepared<P: Palette>(
        &self,
        start: Start,
        palette: P,
    ) -> Result<LSystemDrawing<'g, 'a, P, DEPTH, STACK>, Error> {
        let pixels = self.bounds_from(start)?;
        let corners = [self.pixel_of(pixels.min), self.pixel_of(pixels.max)];
        let top_left = Point::new(
            corners[0].x.min(corners[1].x),
            corners[0].y.min(corners[1].y),
        );
        let bottom_right = Point::new(
            corners[0].x.max(corners[1].x),
            corners[0].y.max(corners[1].y),
        );
        Ok(LSystemDrawing {
            system: *self,
            start,
            palette,
            bounding_box: Rectangle::with_corners(top_left, bottom_right),
        })
    }

    /// The pixel for a point of a drawing pass (whose turtle works in pixels).
    fn pixel_of(&self, p: TurtlePoint) -> Point {
        let (x, y) = self.orientation.to_screen((p.x, p.y));
        Point::new(x.round_to_i32(), y.round_to_i32())
    }
}

/// A slice of colours as a palette; an empty one is [`FitError::EmptyPalette`].
fn colors<C: PixelColor>(palette: &[C]) -> Result<Colors<'_, C>, Error> {
    Colors::new(palette).ok_or(Error::Fit(FitError::EmptyPalette))
}

/// A fitted or placed L-system with its palette: an embedded-graphics [`Drawable`].
///
/// Colour index `i` of the system is drawn as `palette.color(i, u16::MAX)` (never
/// "inside"): with a list of colours ([`Colors`], what `fit` and `place` build from a
/// slice), `colours[i % len]`. Lines go to the target as horizontal and vertical runs
/// through `fill_solid`; clipping is the target's.
#[derive(Debug, Clone, Copy)]
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
        let mut segments = self.system.segments(self.start)?;
        let mut last_end = None;
        for segment in segments.by_ref() {
            let segment = segment?;
            let (from, to) = (
                self.system.pixel_of(segment.start),
                self.system.pixel_of(segment.end),
            );
            let color = self.palette.color(u16::from(segment.color), u16::MAX);
            // A continuing line does not draw its first pixel twice.
            raster::draw_line(target, from, to, last_end == Some(from), color, &clip)
                .map_err(DrawError::Target)?;
            last_end = Some(to);
        }
        Ok(segments.stats())
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
        match self.try_draw(target) {
            Ok(stats) => Ok(stats),
            Err(DrawError::Target(error)) => Err(error),
            // Unreachable: construction walked the same derivation without error.
            Err(DrawError::Fractal(_)) => Ok(WalkStats::default()),
        }
    }
}

impl<P, const DEPTH: usize, const STACK: usize> Dimensions
    for LSystemDrawing<'_, '_, P, DEPTH, STACK>
{
    fn bounding_box(&self) -> Rectangle {
        self.bounding_box
    }
}
