//! Which pixels to compute, in what order, and how they leave: rows, tiles and uniform
//! blocks handed to a [`DwellSink`], in steps with a work budget.
//!
//! `Exact` computes every pixel, a row at a time. `Fast` splits the picture into tiles 32
//! wide, taken a column of tiles at a time, each tile's first row the last of the tile
//! above where that adds no tile (see `Render::tile_stride`), and traces the outlines of
//! each tile's regions of one dwell in tiles 64 rows high: only the cells on both sides of
//! an outline are computed, and the rest take the dwell of the cell before them as the
//! tile is sent (see `Render::trace`). Julia sets, smooth values and perturbed renders run
//! Mariani–Silver subdivision instead, in 32×32 tiles (see `Kernel::traceable`): compute a
//! rectangle's border; if it is one value, fill the rectangle; otherwise split it in four.
//! A tile that comes out uniform leaves as one `uniform` block (`fill_solid`); a traced
//! tile leaves in bands of rows, each band of one-dwell rows as a `uniform` block and the
//! rest as `dwells` blocks (`fill_contiguous`); a subdivided one as one `dwells` block:
//! an address window per block on an SPI display, each pixel sent once. When the view is
//! symmetric, only the top half is computed and each tile is also sent, upside down, to
//! the bottom half: mirrored for a Mandelbrot view centred on the real axis, turned half
//! round for a Julia view centred on the origin (the kernel keeps both symmetries
//! exactly).

use embedded_graphics::{prelude::*, primitives::Rectangle};

use super::emit::Order;
use super::kernel::{Kernel, Orbit, Part};
use super::modes::Inside;
use super::perturbation::{Perturbation, ReferenceOrbit};
use super::render::{
    coordinate, Algorithm, Pixels, Progress, Render, RenderStats, TILE, TILE_ROWS,
};
use super::scaled::ReferencePoint;
use super::tile::{AnyCells, Cells};
use super::view::{Shading, Symmetry, View};
use crate::error::{Error, ViewError};
use crate::render::sink::DwellSink;

impl Render<'static> {
    /// A render of `view`, nothing computed yet, in the view's fixed-point tier, with
    /// tiles of [`TILE_ROWS`] rows. A [`Tier::Perturbation`](super::view::Tier::Perturbation) view needs storage for its
    /// reference orbit, so it is made with [`Render::perturbed`]; given here, it is
    /// computed in `Deep`, whose stats say so, and which does not resolve pixels finer
    /// than 2⁻⁵⁴.
    pub fn new(view: View, algorithm: Algorithm) -> Self {
        Self::with_capacity(view, algorithm)
    }
}

impl<const CELLS: usize> Render<'static, CELLS> {
    /// As [`new`](Render::new), with the tile's cells in the type (32 times a power of
    /// two from 2 to 64): `Render::<'_, 1024>::with_capacity(view, algorithm)` holds
    /// 2,048 bytes fewer and traces 32×32 tiles, a little slower (docs/performance.md).
    ///
    /// ```
    /// use embedded_graphics::prelude::Size;
    /// use tinyfractal::{Coord, Fractal, View, escape::{Algorithm, Render}, render::DwellBuffer};
    ///
    /// let centre = (Coord::parse("-0.75").unwrap(), Coord::default());
    /// let size = Size::new(128, 64);
    /// let width = Coord::parse("3.5").unwrap();
    /// let view = View::new(Fractal::Mandelbrot, centre, width, size, 64)?;
    /// let mut dwells = [0u16; 128 * 64];
    /// let mut small = Render::<'_, 1024>::with_capacity(view, Algorithm::Fast);
    /// let Ok(_) = small.run(&mut DwellBuffer::new(&mut dwells, 128));
    /// let mut again = [0u16; 128 * 64];
    /// let Ok(_) = Render::new(view, Algorithm::Fast).run(&mut DwellBuffer::new(&mut again, 128));
    /// assert_eq!(dwells, again);
    /// # Ok::<(), tinyfractal::Error>(())
    /// ```
    ///
    /// Other sizes do not build:
    ///
    /// ```compile_fail
    /// use embedded_graphics::prelude::Size;
    /// use tinyfractal::{Coord, Fractal, View, escape::{Algorithm, Render}};
    ///
    /// let centre = (Coord::parse("-0.75").unwrap(), Coord::default());
    /// let size = Size::new(128, 64);
    /// let width = Coord::parse("3.5").unwrap();
    /// let view = View::new(Fractal::Mandelbrot, centre, width, size, 64)?;
    /// let _render = Render::<'_, 1000>::with_capacity(view, Algorithm::Fast);
    /// # Ok::<(), tinyfractal::Error>(())
    /// ```
    pub fn with_capacity(view: View, algorithm: Algorithm) -> Self {
        Self::with_pixels(
            view,
            algorithm,
            Pixels::Fixed(Kernel::new(&view, algorithm.periodicity(&view))),
        )
    }
}

impl<'r> Render<'r> {
    /// A render of a Mandelbrot `view` by perturbation, whatever its tier: computes the
    /// reference orbit at the view's centre into `storage`, which must hold
    /// [`ReferenceOrbit::points_needed`] points (24 bytes each). Fails if the view is a
    /// Julia set or the storage is too short.
    pub fn perturbed(
        view: View,
        algorithm: Algorithm,
        storage: &'r mut [ReferencePoint],
    ) -> Result<Self, Error> {
        Self::perturbed_with_capacity(view, algorithm, storage)
    }
}

impl<'r, const CELLS: usize> Render<'r, CELLS> {
    /// As [`perturbed`](Render::perturbed), with the tile's cells in the type (see
    /// [`with_capacity`](Render::with_capacity)). A perturbed render subdivides tiles of
    /// 32 rows, never traces, so `Render::<'_, 1024>` draws it as fast and leaves 2,048
    /// bytes more for the reference.
    pub fn perturbed_with_capacity(
        view: View,
        algorithm: Algorithm,
        storage: &'r mut [ReferencePoint],
    ) -> Result<Self, Error> {
        if view.inside != Inside::MaxIter {
            return Err(Error::View(ViewError::NotWithPerturbation));
        }
        let reference = ReferenceOrbit::compute(&view, storage)?;
        Ok(Self::with_pixels(
            view,
            algorithm,
            Pixels::Perturbed(Perturbation::new(
                &view,
                reference,
                algorithm.periodicity(&view),
            )),
        ))
    }

    /// Where cells keep how far the set is proven to be (see [`Render::far_at`]): past
    /// half the cells with distance estimation (not its shading, whose values are not
    /// filled), where tiles of half the cells still have 4 rows.
    #[inline(never)]
    fn far_offset(view: &View) -> u32 {
        if view.distance != 0 && view.shading != Shading::Distance && Self::ROWS >= 4 {
            (CELLS / 2) as u32
        } else {
            0
        }
    }

    pub(super) fn with_pixels(view: View, algorithm: Algorithm, pixels: Pixels<'r>) -> Self {
        let () = Self::ROWS_FIT;
        Self {
            pixels,
            view,
            algorithm,
            next: 0,
            preview: 0,
            previewed: 0,
            stats: RenderStats {
                iterations: 0,
                pixels: 0,
                draw_calls: 0,
                tier: pixels.tier(),
                rebases: 0,
                skipped: 0,
            },
            tile: [0; CELLS],
            far_at: Self::far_offset(&view),
            width: TILE,
            columns: [Part::default(); TILE as usize],
            rows: [Part::default(); TILE_ROWS],
            columns_from: u32::MAX,
            in_tile: u32::MAX,
            tile_steps: 0,
            tile_pixels: 0,
        }
    }

    /// Starts with a coarse preview: one dwell per `block`×`block` square (its middle
    /// pixel's), sent as one `uniform` call, so a slow core or a window shows the whole
    /// picture at once, blocky; then the render proper overwrites every pixel with the
    /// same picture it draws without a preview. It computes one pixel in `block`² more
    /// (tested to cost under a tenth more iterations).
    /// A `block` below 2 means no preview; a render already under way keeps its plan.
    #[must_use]
    pub const fn with_preview(mut self, block: u32) -> Self {
        if self.next == 0 && self.previewed == 0 {
            self.preview = if block < 2 { 0 } else { block };
        }
        self
    }

    /// Block rows of the preview.
    pub(super) fn preview_units(&self) -> u32 {
        match self.preview {
            0 => 0,
            block => self.view.size.height.div_ceil(block),
        }
    }

    /// One block row of the preview: each block filled with its middle pixel's dwell.
    pub(super) fn preview_row<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
        let (block, size) = (self.preview, self.view.size);
        let y0 = self.previewed * block;
        let h = block.min(size.height - y0);
        let im = self.pixels.row(&self.view, i64::from(y0 + h / 2));
        let mut x0 = 0;
        while x0 < size.width {
            let w = block.min(size.width - x0);
            let re = self.pixels.column(&self.view, i64::from(x0 + w / 2));
            let dwell = self.compute_at(re, im);
            self.stats.draw_calls += 1;
            let area = Rectangle::new(Point::new(coordinate(x0), coordinate(y0)), Size::new(w, h));
            sink.uniform(&area, dwell)?;
            x0 += w;
        }
        Ok(())
    }

    /// What has been done so far.
    pub const fn stats(&self) -> RenderStats {
        self.stats
    }

    /// How far the render is.
    pub fn progress(&self) -> Progress {
        Progress {
            done: self.previewed + self.next,
            total: self.preview_units() + self.units(),
        }
    }

    /// Works until at least `iterations` z ← z² + c steps are spent (whole rows or tiles:
    /// a row costs at most W × max-iter) or the picture is complete.
    pub fn step<S: DwellSink>(
        &mut self,
        sink: &mut S,
        iterations: u64,
    ) -> Result<Progress, S::Error> {
        let start = self.stats.iterations;
        while self.next < self.units() && self.stats.iterations - start < iterations {
            if self.previewed < self.preview_units() {
                self.preview_row(sink)?;
                self.previewed += 1;
                continue;
            }
            match self.algorithm {
                Algorithm::Exact => self.exact_row(sink)?,
                Algorithm::Fast => self.fast_tile(sink)?,
            }
            self.next += 1;
        }
        Ok(self.progress())
    }

    /// Finishes the render.
    pub fn run<S: DwellSink>(&mut self, sink: &mut S) -> Result<RenderStats, S::Error> {
        self.step(sink, u64::MAX)?;
        Ok(self.stats)
    }

    /// How the render splits into parts a thread each: its units (rows for `Exact`, tiles
    /// for `Fast`) and how many make one independent part (a row; a column of tiles, whose
    /// tiles share rows). Parts computed apart ([`run_part`](Self::run_part)) give every
    /// pixel the dwell the whole render gives it.
    pub fn parts(&self) -> (u32, u32) {
        let grain = match self.algorithm {
            Algorithm::Exact => 1,
            Algorithm::Fast => self.tiles_down().max(1),
        };
        (self.units(), grain)
    }

    /// Computes units `units` only (no preview), for a host that splits a render between
    /// threads, each with a render of the same view: the range should start and end on
    /// whole parts ([`parts`](Self::parts)). Returns this part's stats.
    pub fn run_part<S: DwellSink>(
        &mut self,
        sink: &mut S,
        units: core::ops::Range<u32>,
    ) -> Result<RenderStats, S::Error> {
        self.previewed = self.preview_units();
        self.next = units.start;
        let end = units.end.min(self.units());
        while self.next < end {
            match self.algorithm {
                Algorithm::Exact => self.exact_row(sink)?,
                Algorithm::Fast => self.fast_tile(sink)?,
            }
            self.next += 1;
        }
        Ok(self.stats)
    }

    pub(super) fn units(&self) -> u32 {
        match self.algorithm {
            Algorithm::Exact => self.view.size.height,
            Algorithm::Fast => self.tiles_across() * self.tiles_down(),
        }
    }

    /// The dwell of the point with column part `re` and row part `im`.
    pub(super) fn compute_at(&mut self, re: Part, im: Part) -> u16 {
        let orbit = AnyCells.orbit(&self.pixels, re, im, &mut self.stats);
        self.record(orbit)
    }

    /// Counts a computed pixel's orbit in the stats; its dwell.
    #[inline(always)]
    pub(super) fn record(&mut self, orbit: Orbit) -> u16 {
        self.stats.iterations += u64::from(orbit.iterations);
        self.stats.pixels += 1;
        // A dwell is at most the view's inside value, a u16 (the view checks the cap): the
        // cast keeps it whole, and costs less a pixel than a checked conversion.
        orbit.value()
    }

    pub(super) fn exact_row<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
        let j = self.next;
        let width = self.view.size.width;
        let area = Rectangle::new(Point::new(0, coordinate(j)), Size::new(width, 1));
        self.stats.draw_calls += 1;
        let im = self.pixels.row(&self.view, i64::from(j));
        let dwells = (0..width).map(|i| {
            let re = self.pixels.column(&self.view, i64::from(i));
            self.compute_at(re, im)
        });
        sink.dwells(&area, dwells)
    }

    pub(super) fn fast_tile<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
        let (down, stride) = (self.tiles_down(), self.tile_stride());
        let (column, row) = (self.next / down, self.next % down);
        let (x0, y0) = (column * TILE, row * stride);
        let w = TILE.min(self.view.size.width - x0);
        let tile_rows = self.tile_rows();
        let h = tile_rows.min(self.computed_rows() - y0);
        // The tile above was the last one computed, as wide and tile_rows high: where the
        // stride shares it, its last row is this tile's first, known (unless sending this
        // tile failed before, and `tile` holds it).
        let shared = u32::from(row > 0 && stride < tile_rows);
        let known = if shared == 1 && self.in_tile.wrapping_add(1) == self.next {
            w as usize
        } else {
            0
        };
        // Copied out and back round the tile's clearing, cheaper than moving it within
        // the tile and clearing the rest by a fill.
        let last_row = self.cell_index(0, tile_rows - 1);
        let mut kept = [0u16; TILE as usize];
        if let (Some(to), Some(from)) = (
            kept.get_mut(..known),
            self.tile.get(last_row..last_row + known),
        ) {
            to.copy_from_slice(from);
        }
        if let Some(used) = self.tile.get_mut(..(w * h) as usize) {
            used.fill(0);
        }
        if let (Some(to), Some(from)) = (self.tile.get_mut(..known), kept.get(..known)) {
            to.copy_from_slice(from);
        }

        self.width = w;
        // Rows and columns past the view's edge are not used. The columns are the same
        // for a whole column of tiles.
        let rows = self.rows.get_mut(..h as usize).unwrap_or_default();
        self.pixels.fill(self.view.rows_from(i64::from(y0)), rows);
        if self.columns_from != x0 {
            self.columns_from = x0;
            self.pixels
                .fill(self.view.columns_from(i64::from(x0)), &mut self.columns);
        }
        let dwells = self.compute_tile(w, h);
        self.in_tile = self.next;
        self.stats.iterations += u64::from(self.tile_steps);
        self.stats.pixels += self.tile_pixels;
        (self.tile_steps, self.tile_pixels) = (0, 0);
        // The tile's rows not sent with the tile above.
        let (y0, h) = (y0 + shared, h - shared);
        let area = Rectangle::new(Point::new(coordinate(x0), coordinate(y0)), Size::new(w, h));
        self.emit(sink, area, shared, Order::Forward, dwells)?;
        let symmetry = self.view.symmetry();
        if symmetry != Symmetry::None {
            // Row r mirrors to H-1-r. The middle row of an odd height is its own mirror and
            // is not sent twice.
            let size = self.view.size;
            let mirror_top = size.height - y0 - h;
            let overlap = (y0 + h).saturating_sub(mirror_top);
            let half_turn = symmetry == Symmetry::HalfTurn;
            // A half turn also mirrors columns: i to W-1-i.
            let x = if half_turn { size.width - x0 - w } else { x0 };
            if overlap < h {
                let mirrored = Rectangle::new(
                    Point::new(coordinate(x), coordinate(mirror_top + overlap)),
                    Size::new(w, h - overlap),
                );
                let order = if half_turn {
                    Order::HalfTurn
                } else {
                    Order::RowsReversed
                };
                self.emit(sink, mirrored, shared, order, dwells)?;
            }
        }
        Ok(())
    }
}
