//! A reaction's B field scaled onto an area through a palette.

use embedded_graphics::{
    draw_target::DrawTarget, prelude::Dimensions, primitives::Rectangle, Drawable,
};

use crate::error::{Error, FitError};
use crate::render::Palette;

use super::grid::{Cell, Reaction};
use super::model::{CELL_FRAC_BITS, ONE};

/// The levels a cell's B is drawn in, 0 (B = 0) to 255 (B = 1).
pub const LEVELS: u16 = 256;

/// The level of a concentration in [0, 1]: ⌊B·255 + ½⌋.
pub fn level_of(b: u16) -> u8 {
    let b = u32::from(b.min(ONE));
    ((b * 255 + (1 << (CELL_FRAC_BITS - 1))) >> CELL_FRAC_BITS) as u8
}

/// A reaction's grid fitted to an area, sent as one `fill_contiguous`.
///
/// Each pixel shows the cell under it (nearest, the grid stretched to the area), its B's
/// level `l` drawn as `palette.color(l, u16::MAX)`.
#[derive(Debug, Clone, Copy)]
pub struct ReactionDrawing<'r, P> {
    cells: &'r [Cell],
    grid: (u32, u32),
    area: Rectangle,
    palette: P,
}

impl Reaction<'_> {
    /// The grid as it is now, over `area` with `palette`.
    pub fn fit<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
    ) -> Result<ReactionDrawing<'_, P>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        Ok(ReactionDrawing {
            cells: self.cells(),
            grid: self.size(),
            area,
            palette,
        })
    }
}

impl<P> ReactionDrawing<'_, P> {
    /// The cell under pixel (`x`, `y`) of the area: column ⌊x·W/width⌋, row ⌊y·H/height⌋.
    pub fn cell_at(&self, x: u32, y: u32) -> Cell {
        let column = self.column(x);
        let row = self.row(y);
        self.cells
            .get(row * self.grid.0 as usize + column)
            .copied()
            .unwrap_or_default()
    }

    fn column(&self, x: u32) -> usize {
        (u64::from(x) * u64::from(self.grid.0) / u64::from(self.area.size.width)) as usize
    }

    fn row(&self, y: u32) -> usize {
        (u64::from(y) * u64::from(self.grid.1) / u64::from(self.area.size.height)) as usize
    }
}

impl<P> Dimensions for ReactionDrawing<'_, P> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<P: Palette> Drawable for ReactionDrawing<'_, P> {
    type Color = P::Color;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Self::Color>,
    {
        let colors = Pixels::new(self);
        target.fill_contiguous(&self.area, colors)
    }
}

/// A drawing's colours in the order `fill_contiguous` takes them, a row of the area after
/// another: the grid row taken once a row, and the grid column stepped along it with no
/// division a pixel (`column·width + over = x·W`, `over` below the width, in 32 bits).
struct Pixels<'d, 'r, P: Palette> {
    drawing: &'d ReactionDrawing<'r, P>,
    /// The grid row under the area's row `y`.
    row: &'r [Cell],
    /// The area's row being sent, and the next pixel's column in it.
    y: u32,
    x: u32,
    /// The grid column under the next pixel, and what is over: x·W − column·width.
    column: usize,
    over: u32,
    /// W = whole·width + part: a pixel's step is `whole` columns and `part` over.
    whole: usize,
    part: u32,
    /// The last column coloured in this row, and its colour: the pixels a cell is
    /// stretched over take it once.
    last: Option<(usize, P::Color)>,
}

impl<'d, 'r, P: Palette> Pixels<'d, 'r, P> {
    fn new(drawing: &'d ReactionDrawing<'r, P>) -> Self {
        let (columns, width) = (drawing.grid.0, drawing.area.size.width);
        let mut pixels = Self {
            drawing,
            row: &[],
            y: 0,
            x: 0,
            column: 0,
            over: 0,
            whole: (columns / width) as usize,
            part: columns % width,
            last: None,
        };
        pixels.start_row();
        pixels
    }

    /// The area's row `y` from its first pixel.
    fn start_row(&mut self) {
        let start = self.drawing.row(self.y) * self.drawing.grid.0 as usize;
        self.row = self.drawing.cells.get(start..).unwrap_or_default();
        (self.x, self.column, self.over, self.last) = (0, 0, 0, None);
    }
}

impl<P: Palette> Iterator for Pixels<'_, '_, P> {
    type Item = P::Color;

    #[inline]
    fn next(&mut self) -> Option<P::Color> {
        let size = self.drawing.area.size;
        if self.x == size.width {
            self.y += 1;
            if self.y >= size.height {
                return None;
            }
            self.start_row();
        }
        let color = match self.last {
            Some((column, color)) if column == self.column => color,
            _ => {
                let b = self.row.get(self.column).map_or(0, |cell| cell.b);
                let color = self.drawing.palette.color(u16::from(level_of(b)), u16::MAX);
                self.last = Some((self.column, color));
                color
            }
        };
        self.x += 1;
        // over + part, less the width where it reaches it (with part below the width,
        // neither wraps).
        let left = size.width - self.part;
        if self.over >= left {
            self.over -= left;
            self.column += self.whole + 1;
        } else {
            self.over += self.part;
            self.column += self.whole;
        }
        Some(color)
    }
}
