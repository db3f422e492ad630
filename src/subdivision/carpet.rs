//! The Sierpiński carpet: a square split into a 3×3 grid whose centre is removed, and the
//! same in each of the 8 others, to the order asked.
//!
//! The square's side S is the target's shorter side; a cell `i` of level k spans pixels
//! `⌊S·i/3ᵏ⌋` to `⌊S·(i+1)/3ᵏ⌋`, so the levels nest exactly, and at S = 3ᴺ each cell of the
//! last level is one pixel: a pixel is removed exactly when, at some base-3 digit, both of
//! its coordinates have the digit 1.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::order::{centred_square, check_order, depth_first, power, MAX_SUBDIVISION_ORDER};
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
/// of the square once, a `fill_solid` per hole and per row of kept squares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CarpetDrawing<C> {
    order: u32,
    square: Rectangle,
    ink: C,
    background: C,
}

/// A cell edge's exact position S·k/3ᴸ at its level L, as a whole number of pixels and a
/// remainder in 3ᴸths: children's edges come from their parent's by additions (no division
/// a cell, a library call on Cortex-M0), and the pixel is the whole part, ⌊S·k/3ᴸ⌋.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
struct Edge {
    whole: u32,
    part: u32,
}

/// A level's cell side S/3ᴸ as a whole and a remainder in 3ᴸths, and 3ᴸ.
#[derive(Debug, Clone, Copy, Default)]
struct Step {
    whole: u32,
    part: u32,
    cells: u32,
}

impl Edge {
    /// The parent's edge (in 3ᴸ⁻¹ths) `count` cells of `step` (level L) further on.
    #[inline(always)]
    fn advanced(self, step: Step, count: u32) -> Self {
        let mut edge = Self {
            whole: self.whole + count * step.whole,
            part: 3 * self.part + count * step.part,
        };
        // 3·part < 3ᴸ and count·step.part ≤ 3·(3ᴸ − 1): at most three carries.
        for _ in 0..3 {
            if edge.part >= step.cells {
                edge.part -= step.cells;
                edge.whole += 1;
            }
        }
        edge
    }

    /// This edge one cell of `step` further on, at the same level.
    #[inline(always)]
    fn next(self, step: Step) -> u32 {
        self.whole + step.whole + u32::from(self.part + step.part >= step.cells)
    }
}

impl<C: PixelColor> CarpetDrawing<C> {
    /// The pixels of the cell whose left and top edges are `x` and `y`, of a level of
    /// `step`.
    fn cell(&self, (x, y): (Edge, Edge), step: Step) -> Rectangle {
        self.pixels((x.whole, y.whole), (x.next(step), y.next(step)))
    }

    /// The pixels from `(x0, y0)` to `(x1, y1)`, exclusive, in the square.
    fn pixels(&self, (x0, y0): (u32, u32), (x1, y1): (u32, u32)) -> Rectangle {
        Rectangle::new(
            self.square.top_left + Point::new(x0 as i32, y0 as i32),
            Size::new(x1 - x0, y1 - y0),
        )
    }

    /// A cell of the level above the last (edges `x`, `y`) and its nine children of the
    /// last level (`step`): the top and bottom rows of three as one rectangle each, the
    /// middle row as its two squares and the hole between, every pixel once.
    fn group<D: DrawTarget<Color = C>>(
        &self,
        target: &mut D,
        (x, y): (Edge, Edge),
        step: Step,
        stats: &mut CarpetStats,
    ) -> Result<(), D::Error> {
        let edges = |e: Edge| [0, 1, 2, 3].map(|k| e.advanced(step, k).whole);
        let ([x0, x1, x2, x3], [y0, y1, y2, y3]) = (edges(x), edges(y));
        target.fill_solid(&self.pixels((x0, y0), (x3, y1)), self.ink)?;
        target.fill_solid(&self.pixels((x0, y1), (x1, y2)), self.ink)?;
        target.fill_solid(&self.pixels((x1, y1), (x2, y2)), self.background)?;
        target.fill_solid(&self.pixels((x2, y1), (x3, y2)), self.ink)?;
        target.fill_solid(&self.pixels((x0, y2), (x3, y3)), self.ink)?;
        stats.squares += 8;
        stats.holes += 1;
        Ok(())
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
    /// painted as a hole, the others split again or, above the last level, drawn as a group
    /// of the last level's squares: the top and bottom rows of three as one rectangle
    /// each, the middle row's two squares and the hole apart, so every pixel is painted
    /// once, in five calls a group instead of nine.
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
        // Each level's cell side, found once: S = whole·3ᴸ + part, 3ᴸ at most S (`fit`
        // checks), so every sum below fits 32 bits.
        let side = self.square.size.width;
        let mut steps = [Step::default(); MAX_SUBDIVISION_ORDER as usize + 1];
        let mut cells = 1u32;
        for step in steps.iter_mut().skip(1).take(self.order as usize) {
            cells = cells.saturating_mul(3);
            *step = Step {
                whole: side / cells,
                part: side % cells,
                cells,
            };
        }
        let last = steps.get(self.order as usize).copied().unwrap_or_default();
        if self.order == 1 {
            self.group(target, (Edge::default(), Edge::default()), last, &mut stats)?;
            return Ok(stats);
        }
        // Down to the groups (the cells above the last level), each drawn whole.
        depth_first(self.order - 1, 9, |level, (x, y): (Edge, Edge), child| {
            let step = steps.get(level as usize).copied().unwrap_or_default();
            let c = u32::from(child);
            let at = (x.advanced(step, c % 3), y.advanced(step, c / 3));
            if c == 4 {
                target.fill_solid(&self.cell(at, step), self.background)?;
                stats.holes += 1;
            } else if level + 1 == self.order {
                self.group(target, at, last, &mut stats)?;
            } else {
                return Ok(Some(at));
            }
            Ok(None)
        })?;
        Ok(stats)
    }
}
