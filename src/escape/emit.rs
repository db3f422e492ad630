//! How a computed tile leaves: uniform blocks and runs of dwells to the sink, and the same
//! tile mirrored or turned half round into the other half of a symmetric view.

use embedded_graphics::{prelude::*, primitives::Rectangle};

use super::render::{coordinate, Render};
use super::tile::{low_bits, TileDwells};
use crate::render::sink::DwellSink;

impl<'r, const CELLS: usize> Render<'r, CELLS> {
    /// Sends `area.size.height` of the tile's rows from row `first` to `area` in `order`:
    /// one dwell if uniform, else in bands of rows, each band of one-dwell rows as a block
    /// (see `Outlines::quiet_rows`). A display takes a block as one colour repeated, which costs
    /// it less than the same dwells one by one.
    pub(super) fn emit<S: DwellSink>(
        &mut self,
        sink: &mut S,
        area: Rectangle,
        first: u32,
        order: Order,
        dwells: TileDwells,
    ) -> Result<(), S::Error> {
        let quiet = match dwells {
            TileDwells::Uniform(value) => {
                self.stats.draw_calls += 1;
                return sink.uniform(&area, value);
            }
            TileDwells::Cells => 0,
            TileDwells::Gaps(quiet) => {
                if let Order::HalfTurn = order {
                    // Read backwards, a row's gaps come before the cell they take their
                    // dwell from.
                    self.fill_gaps();
                }
                quiet
            }
        };
        let rows = area.size.height;
        let forward = matches!(order, Order::Forward);
        // Bit k: whether the row sent kth is one dwell.
        let bits = quiet.checked_shr(first).unwrap_or(0) & low_bits(rows);
        let bits = if forward {
            bits
        } else {
            bits.reverse_bits().checked_shr(64 - rows).unwrap_or(0)
        };
        let mut sent = 0;
        while sent < rows {
            let ahead = bits.checked_shr(sent).unwrap_or(0);
            let one_dwell = ahead & 1 == 1;
            let band_rows = if one_dwell {
                ahead.trailing_ones()
            } else {
                ahead.trailing_zeros()
            };
            let end = rows.min(sent + band_rows);
            let band = Rectangle::new(
                area.top_left + Point::new(0, coordinate(sent)),
                Size::new(area.size.width, end - sent),
            );
            // The band's first row in the tile.
            let top = if forward {
                first + sent
            } else {
                first + rows - end
            };
            self.send(sink, band, top, (order, dwells), one_dwell)?;
            sent = end;
        }
        Ok(())
    }

    /// Sends the tile's rows from row `first` to `area` in `order`, as one dwell (the
    /// first cell's) if they are `one_dwell`.
    pub(super) fn send<S: DwellSink>(
        &mut self,
        sink: &mut S,
        area: Rectangle,
        first: u32,
        (order, dwells): (Order, TileDwells),
        one_dwell: bool,
    ) -> Result<(), S::Error> {
        self.stats.draw_calls += 1;
        let w = self.width as usize;
        let start = w * first as usize;
        if one_dwell {
            let value = self.tile.get(start).copied().unwrap_or(0);
            return sink.uniform(&area, value);
        }
        let cells = self
            .tile
            .get_mut(start..start + w * area.size.height as usize)
            .unwrap_or(&mut []);
        match (dwells, order) {
            (TileDwells::Gaps(_), Order::Forward) => {
                // Filled in place as they are read, for the tile below and the mirror image.
                let last_gap = cells.iter().rposition(|&cell| cell == 0);
                let mut before = 0;
                let filled = cells
                    .iter_mut()
                    .map(move |cell| fill_gap(cell, &mut before));
                let sent = sink.dwells(&area, filled);
                if last_gap.is_some_and(|at| self.tile.get(start + at) == Some(&0)) {
                    // The sink stopped reading early.
                    self.fill_gaps();
                }
                sent
            }
            (_, Order::Forward) => sink.dwells(&area, cells.iter().copied()),
            (_, Order::RowsReversed) => sink.dwells(&area, RowsBackward::new(cells, w)),
            (_, Order::HalfTurn) => sink.dwells(&area, cells.iter().rev().copied()),
        }
    }

    /// Gives each cell of the current tile not computed (0) the dwell of the cell before
    /// it (see [`TileDwells::Gaps`]).
    pub(super) fn fill_gaps(&mut self) {
        let mut before = 0;
        for cell in &mut self.tile {
            fill_gap(cell, &mut before);
        }
    }
}

/// Cells row by row, last row first: a slice walk per row, a few instructions a cell.
pub(super) struct RowsBackward<'a> {
    /// The rows not yet started.
    rest: &'a [u16],
    row: core::slice::Iter<'a, u16>,
    w: usize,
}

impl<'a> RowsBackward<'a> {
    pub(super) fn new(cells: &'a [u16], w: usize) -> Self {
        Self {
            rest: cells,
            row: [].iter(),
            // A zero width would never finish a row.
            w: w.max(1),
        }
    }
}

impl Iterator for RowsBackward<'_> {
    type Item = u16;

    fn next(&mut self) -> Option<u16> {
        loop {
            if let Some(&dwell) = self.row.next() {
                return Some(dwell);
            }
            let start = self.rest.len().checked_sub(self.w)?;
            let (rest, last) = self.rest.split_at_checked(start)?;
            (self.rest, self.row) = (rest, last.iter());
        }
    }
}

/// A cell read in order with the dwell `before` it: a gap (0) takes that dwell, written in
/// place (unconditionally, no branch); the cell's dwell, now `before` the next.
#[inline(always)]
pub(super) fn fill_gap(cell: &mut u16, before: &mut u16) -> u16 {
    let value = if *cell == 0 { *before } else { *cell };
    (*cell, *before) = (value, value);
    value
}

/// The order a tile's rows and columns are sent in.
#[derive(Debug, Clone, Copy)]
pub(super) enum Order {
    /// As computed.
    Forward,
    /// Rows bottom to top (a mirror about the real axis).
    RowsReversed,
    /// Rows bottom to top and columns right to left (a half turn).
    HalfTurn,
}
