//! A drawing pass's pen: segments in pixels to the target as runs, each pixel drawn once.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::sizing::pixel_of;
use super::turtle::{Segment, TurtlePoint};
use crate::render::fit::Orientation;
use crate::render::raster;

/// A drawing pass's pen: where the last segment ended, in turtle space and in pixels, so
/// that a line going on from there neither rounds its start again nor draws its first
/// pixel twice, and a step that stays within that pixel (a picture finer than its pixels)
/// draws nothing at no cost.
///
/// Single pixels it draws one after another along a row or column go out as one run
/// (see [`raster::draw_line_on`]); [`finish`](Self::finish) sends the last.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pen<C> {
    point: Option<TurtlePoint>,
    pixel: Option<Point>,
    run: raster::PendingRun<C>,
}

impl<C> Default for Pen<C> {
    fn default() -> Self {
        Self {
            point: None,
            pixel: None,
            run: raster::PendingRun::default(),
        }
    }
}

impl<C: PixelColor> Pen<C> {
    /// Draws one segment in pixels with `color`.
    #[inline(always)]
    pub(crate) fn draw<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        orientation: Orientation,
        segment: Segment,
        color: C,
        clip: &Rectangle,
    ) -> Result<(), D::Error> {
        let from = match (self.point, self.pixel) {
            (Some(point), Some(pixel)) if point == segment.start => pixel,
            _ => pixel_of(orientation, segment.start),
        };
        let to = pixel_of(orientation, segment.end);
        let continuing = self.pixel == Some(from);
        (self.point, self.pixel) = (Some(segment.end), Some(to));
        raster::draw_line_on(target, &mut self.run, from, to, continuing, color, clip)
    }

    /// Draws a dot at `pixel` (the turtle is elsewhere).
    pub(crate) fn dot<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        pixel: Point,
        color: C,
        clip: &Rectangle,
    ) -> Result<(), D::Error> {
        (self.point, self.pixel) = (None, Some(pixel));
        if clip.contains(pixel) {
            self.run.add(target, pixel, color)?;
        }
        Ok(())
    }

    /// Sends what is still pending: call it once drawing is done.
    pub(crate) fn finish<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
    ) -> Result<(), D::Error> {
        self.run.send(target)
    }
}
