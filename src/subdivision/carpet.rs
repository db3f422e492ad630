//! The Sierpiński carpet: a square split into a 3×3 grid whose centre is removed, and the
//! same in each of the 8 others, to the order asked.
//!
//! The square's side S is the target's shorter side; a cell `i` of level k spans pixels
//! `⌊S·i/3ᵏ⌋` to `⌊S·(i+1)/3ᵏ⌋`, so the levels nest exactly, and at S = 3ᴺ each cell of the
//! last level is one pixel: a pixel is removed exactly when, at some base-3 digit, both of
//! its coordinates have the digit 1.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::order::{centred_square, check_order, depth_first, power};
use crate::error::Error;

/// The Sierpiński carpet at an order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Carpet {
    /// Levels of subdivision (0: a filled square).
    pub order: u32,
}

/// What drawing a carpet did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CarpetStats {
    /// Kept squares of the last level drawn in ink: 8ᴺ.
    pub squares: u64,
    /// Removed squares drawn in the background colour: (8ᴺ − 1)/7.
    pub holes: u64,
}

impl Carpet {
    /// The carpet at `order`.
    pub const fn new(order: u32) -> Self {
        Self { order }
    }

    /// Kept squares at this order: 8ᴺ.
    pub const fn squares(&self) -> u64 {
        power(8, self.order)
    }

    /// The carpet in the largest square centred in `area`, kept squares in `ink`, removed
    /// ones in `background`. Fails when a cell of the last level would be under a pixel.
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        ink: C,
        background: C,
    ) -> Result<CarpetDrawing<C>, Error> {
        let square = centred_square(area)?;
        check_order(self.order, 3, u64::from(square.size.width))?;
        Ok(CarpetDrawing {
            order: self.order,
            square,
            ink,
            background,
        })
    }
}

/// A carpet fitted to a square: an embedded-graphics [`Drawable`] that paints every pixel
/// of the square once, one `fill_solid` per square.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CarpetDrawing<C> {
    order: u32,
    square: Rectangle,
    ink: C,
    background: C,
}

impl<C: PixelColor> CarpetDrawing<C> {
    /// The pixels of cell (i, j) of a level with `cells` cells across.
    fn cell(&self, (i, j): (u64, u64), cells: u64) -> Rectangle {
        let side = u64::from(self.square.size.width);
        let edge = |k: u64| (side * k / cells) as i32;
        let (x0, x1, y0, y1) = (edge(i), edge(i + 1), edge(j), edge(j + 1));
        Rectangle::new(
            self.square.top_left + Point::new(x0, y0),
            Size::new((x1 - x0) as u32, (y1 - y0) as u32),
        )
    }
}

impl<C: PixelColor> Dimensions for CarpetDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.square
    }
}

impl<C: PixelColor> Drawable for CarpetDrawing<C> {
    type Color = C;
    type Output = CarpetStats;

    /// Depth first (`depth_first`): the 9 children of a kept cell in row order, the centre
    /// painted as a hole, the others split again or, at the last level, painted in ink.
    fn draw<D>(&self, target: &mut D) -> Result<CarpetStats, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut stats = CarpetStats::default();
        if self.order == 0 {
            target.fill_solid(&self.square, self.ink)?;
            stats.squares = 1;
            return Ok(stats);
        }
        depth_first(self.order, 9, |level, (x, y): (u64, u64), child| {
            let c = u64::from(child);
            let at = (3 * x + c % 3, 3 * y + c / 3);
            let cells = power(3, level);
            if c == 4 {
                target.fill_solid(&self.cell(at, cells), self.background)?;
                stats.holes += 1;
            } else if level == self.order {
                target.fill_solid(&self.cell(at, cells), self.ink)?;
                stats.squares += 1;
            } else {
                return Ok(Some(at));
            }
            Ok(None)
        })?;
        Ok(stats)
    }
}
