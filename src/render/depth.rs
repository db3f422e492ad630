//! A depth buffer in front of a draw target: each primitive is drawn at one depth, and a
//! pixel is written only where nothing nearer has been, so surfaces in space hide each
//! other whatever order they are drawn in.
//!
//! Depths are `u16`, larger nearer; the buffer holds one a pixel of the target's bounding
//! box, row by row, and starts at 0 (farthest). A pixel is drawn when the primitive's depth
//! is at least the buffer's there (equal depths: the later wins, walk order). Runs stay
//! runs: a `fill_solid` leaves as the `fill_solid`s of its visible stretches.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError};

/// Where drawing goes with a depth: through a depth buffer, or straight (walk order).
pub(crate) trait Layered: DrawTarget {
    /// Whether depths are kept: where not, a drawing need not compute them.
    const KEEPS_DEPTH: bool;
    /// The depth of what is drawn next (larger nearer).
    fn at_depth(&mut self, depth: u16);
}

/// A target drawn in walk order: depths ignored.
pub(crate) struct Unsorted<'a, D>(pub(crate) &'a mut D);

/// A target behind a depth buffer.
pub(crate) struct DepthTested<'a, D> {
    target: &'a mut D,
    buffer: &'a mut [u16],
    area: Rectangle,
    depth: u16,
}

impl<'a, D: DrawTarget> DepthTested<'a, D> {
    /// `target` behind `buffer` (one cell a pixel of its bounding box, emptied here).
    pub(crate) fn new(target: &'a mut D, buffer: &'a mut [u16]) -> Result<Self, Error> {
        let area = target.bounding_box();
        let needed = area.size.width as usize * area.size.height as usize;
        let given = buffer.len();
        let buffer = buffer
            .get_mut(..needed)
            .ok_or(Error::Fit(FitError::BufferTooSmall { needed, given }))?;
        buffer.fill(0);
        Ok(Self {
            target,
            buffer,
            area,
            depth: 0,
        })
    }

    /// The buffer cell of `point`, if inside.
    fn cell(&self, point: Point) -> Option<usize> {
        let offset = point - self.area.top_left;
        let (x, y) = (u32::try_from(offset.x).ok()?, u32::try_from(offset.y).ok()?);
        (x < self.area.size.width && y < self.area.size.height)
            .then(|| y as usize * self.area.size.width as usize + x as usize)
    }

    /// Whether the pixel at `cell` shows what is drawn now (and if so, its depth is now).
    fn visible(&mut self, cell: usize) -> bool {
        match self.buffer.get_mut(cell) {
            Some(held) if *held <= self.depth => {
                *held = self.depth;
                true
            }
            _ => false,
        }
    }
}

impl<D: DrawTarget> Dimensions for DepthTested<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<D: DrawTarget> DrawTarget for DepthTested<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        for Pixel(point, color) in pixels {
            if let Some(cell) = self.cell(point) {
                if self.visible(cell) {
                    self.target
                        .draw_iter(core::iter::once(Pixel(point, color)))?;
                }
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        let area = area.intersection(&self.area);
        let Some(end) = area.bottom_right() else {
            return Ok(());
        };
        for y in area.top_left.y..=end.y {
            let mut run: Option<i32> = None;
            for x in area.top_left.x..=end.x + 1 {
                let shown = x <= end.x
                    && self
                        .cell(Point::new(x, y))
                        .is_some_and(|cell| self.visible(cell));
                match (shown, run) {
                    (true, None) => run = Some(x),
                    (false, Some(start)) => {
                        let width = u32::try_from(x - start).unwrap_or(0);
                        self.target.fill_solid(
                            &Rectangle::new(Point::new(start, y), Size::new(width, 1)),
                            color,
                        )?;
                        run = None;
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }
}

impl<D: DrawTarget> Layered for DepthTested<'_, D> {
    const KEEPS_DEPTH: bool = true;

    fn at_depth(&mut self, depth: u16) {
        self.depth = depth;
    }
}

impl<D: DrawTarget> Dimensions for Unsorted<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.0.bounding_box()
    }
}

impl<D: DrawTarget> DrawTarget for Unsorted<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    #[inline]
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        self.0.draw_iter(pixels)
    }

    #[inline]
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Self::Color>,
    {
        self.0.fill_contiguous(area, colors)
    }

    #[inline]
    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        self.0.fill_solid(area, color)
    }

    #[inline]
    fn clear(&mut self, color: Self::Color) -> Result<(), Self::Error> {
        self.0.clear(color)
    }
}

impl<D: DrawTarget> Layered for Unsorted<'_, D> {
    const KEEPS_DEPTH: bool = false;

    #[inline]
    fn at_depth(&mut self, _depth: u16) {}
}
