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
        let (w, h) = (self.area.size.width, self.area.size.height);
        let (columns, wide) = (self.grid.0, u64::from(w));
        let colors = (0..h).flat_map(|y| {
            let start = self.row(y) * columns as usize;
            let row = self.cells.get(start..).unwrap_or_default();
            // Column ⌊x·W/width⌋ stepped along the row, no division a pixel: `column·width
            // + over = x·W` with `over` below the width.
            (0..w)
                .scan((0, 0), move |(column, over): &mut (usize, u64), _| {
                    let here = *column;
                    *over += u64::from(columns);
                    while *over >= wide {
                        *over -= wide;
                        *column += 1;
                    }
                    Some(here)
                })
                .map(move |column| {
                    let b = row.get(column).map_or(0, |cell| cell.b);
                    self.palette.color(u16::from(level_of(b)), u16::MAX)
                })
        });
        target.fill_contiguous(&self.area, colors)
    }
}
