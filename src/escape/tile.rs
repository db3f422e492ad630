//! A tile's geometry and its cells: where tiles fall in the view, which cell is where, and
//! how a cell gets its orbit in the render's tier.

use super::kernel::{Orbit, Part};
use super::orbit::{TierOrbit, TierVisitor};
use super::perturbation::{Perturbation, Perturbed};
use super::render::{Pixels, Render, RenderStats, TILE, TILE_ROWS};
use super::view::Symmetry;

impl<'r, const CELLS: usize> Render<'r, CELLS> {
    /// Rows to compute: the top half when mirrored (the middle row of an odd height is
    /// its own mirror and is computed too).
    pub(super) fn computed_rows(&self) -> u32 {
        let h = self.view.size.height;
        if self.view.symmetry() != Symmetry::None {
            h.div_ceil(2)
        } else {
            h
        }
    }

    pub(super) fn tiles_across(&self) -> u32 {
        self.view.size.width.div_ceil(TILE)
    }

    /// Rows from one tile's first to the next's, down a column of tiles: where it adds no
    /// tile, a tile's last row is the first of the tile below, computed once (tiles go
    /// down a column before the next, so the shared row is still in `tile`). A tile's
    /// edge is on the outline of every region along it, so its cells are all computed,
    /// and sharing them computes fewer; not where it would add a row of tiles (64 rows:
    /// three tiles of 31, not two of 32), nor where cells keep how far the set is (the
    /// shared row's would have to move with it).
    pub(super) fn tile_stride(&self) -> u32 {
        let rows = self.computed_rows();
        let tile_rows = self.tile_rows();
        if self.far_at != 0
            || rows.saturating_sub(1).div_ceil(tile_rows - 1) > rows.div_ceil(tile_rows)
        {
            tile_rows
        } else {
            tile_rows - 1
        }
    }

    /// A tile's height: traced tiles as tall as the render holds (taller tiles share more
    /// of their outlines); subdivided ones at most 32, where taller ones cost more
    /// (docs/performance.md).
    pub(super) fn tile_rows(&self) -> u32 {
        match self.pixels {
            Pixels::Fixed(kernel) if kernel.traceable() => Self::ROWS as u32,
            _ if self.far_at != 0 => TILE.min(Self::ROWS as u32 / 2),
            _ => TILE.min(Self::ROWS as u32),
        }
    }

    /// Tiles in a column.
    pub(super) fn tiles_down(&self) -> u32 {
        let stride = self.tile_stride();
        // A tile covers rows y0..y0 + tile_rows; the next starts at y0 + stride.
        (self.computed_rows() + stride)
            .saturating_sub(self.tile_rows())
            .div_ceil(stride)
            .max(1)
    }

    /// [`trace`](Self::trace) or [`subdivide`](Self::subdivide) the current tile, compiled
    /// once per way of computing a cell (each fixed tier, its orbit in line, and any
    /// other). No cell tests the tier. In line in `fast_tile`, so that it is
    /// compiled with the sink's code (docs/performance.md).
    #[inline(always)]
    pub(super) fn compute_tile(&mut self, w: u32, h: u32) -> TileDwells {
        match self.pixels {
            Pixels::Fixed(kernel) => kernel.visit(TileCells {
                render: self,
                size: (w, h),
                traced: kernel.traceable(),
            }),
            Pixels::Perturbed(_) => self.subdivide(&AnyCells, w, h),
        }
    }

    /// Where cell (tx, ty) of the current tile is in `tile`.
    pub(super) const fn cell_index(&self, tx: u32, ty: u32) -> usize {
        (ty * self.width + tx) as usize
    }

    /// The dwell of tile cell (tx, ty), computed on first use (0 marks "not yet").
    #[inline(always)]
    pub(super) fn known<C: Cells>(&mut self, cells: &C, tx: u32, ty: u32) -> u16 {
        // A dwell is a u16: the cast keeps it whole.
        self.cell_at(cells, tx, ty, self.cell_index(tx, ty) as u32) as u16
    }

    /// Computes tile cell (tx, ty), at `index` in `tile`.
    #[inline(never)]
    pub(super) fn compute_cell<C: Cells>(
        &mut self,
        cells: &C,
        tx: u32,
        ty: u32,
        index: usize,
    ) -> u32 {
        let mask = TILE as usize - 1;
        let re = self
            .columns
            .get(tx as usize & mask)
            .copied()
            .unwrap_or_default();
        let im = self
            .rows
            .get(ty as usize & (TILE_ROWS - 1))
            .copied()
            .unwrap_or_default();
        let orbit = cells.orbit(&self.pixels, re, im, &mut self.stats);
        // On Cortex-M0 every caller passes true: one copy, no test of the cells' kind.
        self.keep(
            orbit,
            index,
            C::ESTIMATES || cfg!(tinyfractal_no_long_multiply),
        )
    }

    /// Keeps cell `index`'s `orbit`: its value (returned, widened once: the callers
    /// compare it with cells read as u32), its steps, and how far the set is where that
    /// is kept and the cells may carry it (`estimates`). A call on Cortex-M0, where each
    /// tier's copy of it would take flash; in line elsewhere.
    #[cfg_attr(tinyfractal_no_long_multiply, inline(never))]
    #[cfg_attr(not(tinyfractal_no_long_multiply), inline(always))]
    fn keep(&mut self, orbit: Orbit, index: usize, estimates: bool) -> u32 {
        // Counted in 32 bits (a tile's cells take at most 2,048 × 65,535 steps) and added
        // to the stats once a tile.
        self.tile_steps += orbit.iterations;
        self.tile_pixels += 1;
        let value = orbit.value();
        if estimates && self.far_at != 0 {
            if let Some(far) = self
                .tile
                .get_mut((self.far_at as usize + index) & (CELLS - 1))
            {
                *far = orbit.far();
            }
        }
        if let Some(cell) = self.tile.get_mut(index) {
            *cell = value;
        }
        u32::from(value)
    }

    /// The dwell of tile cell (x, y) at `index`, computed on first use (0 marks "not
    /// yet").
    #[inline(always)]
    pub(super) fn cell_at<C: Cells>(&mut self, cells: &C, x: u32, y: u32, index: u32) -> u32 {
        // Cells and coordinates are indexed within their arrays by masking: no bounds checks.
        let index = index as usize & (CELLS - 1);
        match self.tile.get(index).copied() {
            Some(0) | None => self.compute_cell(cells, x, y, index),
            Some(value) => u32::from(value),
        }
    }
}

/// A perturbed pixel's dwell, out of line wherever a render is: in line, perturbation's
/// finish would be copied into every caller's flash.
#[inline(never)]
pub(super) fn perturbed_dwell(pixels: &Perturbation<'_>, re: Part, im: Part) -> Perturbed {
    pixels.dwell(re.0, im.0)
}

/// How a tile's cells get their orbits: a fixed tier's (compiled once per tier, the
/// orbit in line) or by perturbation.
pub(super) trait Cells {
    /// Whether an orbit may carry how far the set is (a traced kernel's never does).
    const ESTIMATES: bool = true;

    /// The orbit of the point (`re`, `im`) of a render computing `pixels`, counting a
    /// perturbed pixel's extra stats.
    fn orbit(&self, pixels: &Pixels<'_>, re: Part, im: Part, stats: &mut RenderStats) -> Orbit;
}

impl<T: TierOrbit> Cells for T {
    #[inline(always)]
    fn orbit(&self, _: &Pixels<'_>, re: Part, im: Part, _: &mut RenderStats) -> Orbit {
        self.dwell(re, im)
    }
}

/// A traceable kernel's cells (see [`TierOrbit::traced_dwell`]).
pub(super) struct Traced<T>(T);

impl<T: TierOrbit> Cells for Traced<T> {
    const ESTIMATES: bool = false;

    #[inline(always)]
    fn orbit(&self, _: &Pixels<'_>, re: Part, im: Part, _: &mut RenderStats) -> Orbit {
        self.0.traced_dwell(re, im)
    }
}

/// Whatever the render computes, found at each cell: a perturbed render's cells (its
/// state stays in the render, not copied to the stack).
pub(super) struct AnyCells;

impl Cells for AnyCells {
    #[inline(always)]
    fn orbit(&self, pixels: &Pixels<'_>, re: Part, im: Part, stats: &mut RenderStats) -> Orbit {
        match pixels {
            Pixels::Fixed(kernel) => kernel.dwell(re, im),
            Pixels::Perturbed(pixels) => {
                let Perturbed {
                    orbit,
                    rebases,
                    skipped,
                } = perturbed_dwell(pixels, re, im);
                stats.rebases += u64::from(rebases);
                stats.skipped += u64::from(skipped);
                orbit
            }
        }
    }
}

/// A tile's tracing or subdivision, run by [`Kernel::visit`] in the kernel's tier.
pub(super) struct TileCells<'a, 'r, const CELLS: usize> {
    pub(super) render: &'a mut Render<'r, CELLS>,
    pub(super) size: (u32, u32),
    /// Whether the tile's regions are traced (see [`Render::trace`]), not subdivided.
    pub(super) traced: bool,
}

impl<const CELLS: usize> TierVisitor for TileCells<'_, '_, CELLS> {
    type Output = TileDwells;

    fn visit<T: TierOrbit>(self, orbit: T) -> TileDwells {
        let (w, h) = self.size;
        if self.traced {
            self.render.trace(&Traced(orbit), w, h)
        } else {
            self.render.subdivide(&orbit, w, h)
        }
    }
}

/// A tile's dwells once computed.
#[derive(Debug, Clone, Copy)]
pub(super) enum TileDwells {
    /// One dwell for the whole tile, whatever `tile` holds.
    Uniform(u16),
    /// Every cell in `tile`.
    Cells,
    /// Cells not computed are 0, and take the dwell of the cell before them (the first of
    /// each row is computed): filled as the tile is sent, not in a pass of their own (see
    /// `Render::trace`). Rows whose bit is set are one dwell, their first cell's (see
    /// `Outlines::quiet_rows`), sent as blocks and not filled.
    Gaps(u64),
}

/// A word with its `n` lowest bits set (a tile's cells in a row, or its rows).
pub(super) fn low_bits(n: u32) -> u64 {
    1u64.checked_shl(n).map_or(u64::MAX, |bit| bit - 1)
}
