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
//!
//! RAM: a [`Render`] holds the tile's dwells (32×64×2 = 4 KiB), the tile's 32 column and
//! 64 row coordinates (768 bytes: points are separable, so they are computed once per
//! tile, not once per pixel), the view and its kernel constants, about 5.4 KiB with a
//! perturbed render's series (and it adds the reference orbit, in storage the caller
//! gives: 24 bytes an iteration); while a tile is computed, the tracing's two bits a cell
//! (512 bytes) or a subdivision stack of 32 rectangles (512 bytes) is on the stack. That
//! is the worst case for a 320×240 view or any other: nothing is read back from the
//! target. The tile's cells are a const generic (`Render::<'_, 1024>` traces 32×32 tiles
//! and holds 2 KiB less; see [`Render::with_capacity`]).

use embedded_graphics::{prelude::*, primitives::Rectangle};
use heapless::Vec;

use super::kernel::{fast_tolerance, Kernel, Orbit, Part, Periodicity, TierOrbit, TierVisitor};
use super::perturbation::{Perturbation, Perturbed, ReferenceOrbit};
use super::scaled::ReferencePoint;
use super::view::{Parts, Symmetry, Tier, View};
use crate::error::Error;
use crate::render::sink::DwellSink;

/// Width of a fast-mode tile, in pixels, and the most rows of a subdivided one.
pub const TILE: u32 = 32;

/// The most rows of a fast-mode tile: a [`Render`] of [`TILE_CELLS`] traces tiles this
/// tall (see `Render::tile_rows`).
pub const TILE_ROWS: usize = 64;

/// A [`Render`]'s tile cells unless its type says otherwise (`CELLS`): 32×64.
pub const TILE_CELLS: usize = TILE as usize * TILE_ROWS;

/// A block whose border is not one dwell and which spans fewer than this many cells past
/// its first, across or down (at most 5 cells), is computed whole rather than split: its
/// inside is a few cells, fewer than the scans of four sub-blocks would visit. Against 4
/// (at most 4 cells), the full view at 320×240 took 1.7 % fewer instructions on M3 and
/// M4F, the 128×64 views 4–6 % fewer, and the boards' 128×64 Julia set and deep zoom
/// agree with the exact render in 2 and 1 pixels more (0 and 3 differ); the deep zoom
/// took 1.3 % more, and on Cortex-M0 the 320×240 frames 0.6–0.9 % more.
const WHOLE_BELOW: u32 = 5;

/// How the pixels are scheduled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Algorithm {
    /// Every pixel computed (the cardioid/bulb test and exact periodicity never change a
    /// dwell).
    Exact,
    /// Boundary tracing for Mandelbrot dwells, Mariani–Silver subdivision for the rest,
    /// mirror symmetry and periodicity within 1/16 of a pixel, at most
    /// [`MAX_FAST_TOLERANCE`](super::kernel::MAX_FAST_TOLERANCE). The repeat test agrees with the exact orbit (tested over
    /// random views). Tracing and subdivision can miss a speck: an escaping pixel inside
    /// the region that does not escape, joined to the outside by a channel narrower than
    /// a pixel. Over 150 random Mandelbrot views near the boundary (128×96, widths 10⁻⁵ to
    /// 0.3), tracing missed 310 of 1.84 million pixels, subdivision 26; tracing computed
    /// 36 % fewer pixels of the full view at 320×240.
    #[default]
    Fast,
}

impl Algorithm {
    /// How the algorithm's renders of `view` recognise repeats.
    fn periodicity(self, view: &View) -> Periodicity {
        match self {
            Self::Exact => Periodicity::Exact,
            Self::Fast => Periodicity::Within(fast_tolerance(view.spacing)),
        }
    }
}

/// What a render did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RenderStats {
    /// z ← z² + c steps, in total.
    pub iterations: u64,
    /// Pixels whose dwell was computed (the rest were filled or mirrored).
    pub pixels: u32,
    /// Calls into the sink (draw calls, for a display).
    pub draw_calls: u32,
    /// The tier computed in.
    pub tier: Tier,
    /// Times a perturbed pixel left the reference orbit for its start (0 in a fixed
    /// tier): each a glitch avoided.
    pub rebases: u64,
    /// Iterations the series approximation skipped, in total (0 in a fixed tier): not
    /// counted in `iterations`, which are the steps computed.
    pub skipped: u64,
}

/// How far a render has come.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Units (rows or tiles) done.
    pub done: u32,
    /// Units in all.
    pub total: u32,
}

impl Progress {
    /// Whether the picture is complete.
    pub const fn is_complete(&self) -> bool {
        self.done >= self.total
    }
}

/// How a render computes a pixel: in a fixed-point tier, or by perturbation against a
/// reference orbit in storage borrowed for `'r`.
// A perturbed render keeps its series' terms in place (no heap in the core): a few
// hundred bytes beside the render's tile of dwells.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy)]
enum Pixels<'r> {
    Fixed(Kernel),
    Perturbed(Perturbation<'r>),
}

impl Pixels<'_> {
    /// The tier the pixels are computed in.
    const fn tier(&self) -> Tier {
        match self {
            Self::Fixed(kernel) => kernel.tier(),
            Self::Perturbed(_) => Tier::Perturbation,
        }
    }

    /// Column i's part of its pixels' points.
    #[inline(always)]
    fn column(&self, view: &View, i: i64) -> Part {
        match self {
            Self::Fixed(kernel) => kernel.part(in_view(view.column(i))),
            Self::Perturbed(_) => Part(view.column_steps(i)),
        }
    }

    /// Row j's part of its pixels' points.
    #[inline(always)]
    fn row(&self, view: &View, j: i64) -> Part {
        match self {
            Self::Fixed(kernel) => kernel.part(in_view(view.row(j))),
            Self::Perturbed(_) => Part(view.row_steps(j)),
        }
    }

    /// The parts of the columns or rows `coordinates` runs over, into `parts`: one
    /// function for both (in line, each took 2.7 KiB of flash).
    #[inline(never)]
    fn fill(&self, coordinates: Parts, parts: &mut [Part]) {
        match self {
            Self::Fixed(kernel) => kernel.fill_parts(coordinates, parts),
            Self::Perturbed(_) => {
                // A perturbed pixel's parts are its offsets in half spacings.
                let (mut steps, stride) = coordinates.steps();
                for slot in parts {
                    *slot = Part(steps);
                    steps = steps.wrapping_add(stride);
                }
            }
        }
    }
}

/// A render in progress.
///
/// Call [`step`](Self::step) from a main loop with a budget, or [`run`](Self::run) to
/// finish in one go. A perturbed render borrows its reference
/// orbit's storage for `'r`; any other is a `Render<'static>`. `CELLS` is the tile's
/// cells (see [`with_capacity`](Render::with_capacity)).
#[derive(Debug, Clone)]
#[repr(C)]
pub struct Render<'r, const CELLS: usize = TILE_CELLS> {
    view: View,
    algorithm: Algorithm,
    next: u32,
    /// The preview's block side (0: no preview) and its block rows done.
    preview: u32,
    previewed: u32,
    stats: RenderStats,
    pixels: Pixels<'r>,
    /// The current tile's width: the row stride in `tile`.
    width: u32,
    /// The current tile's column and row parts of its points.
    columns: [Part; TILE as usize],
    rows: [Part; TILE_ROWS],
    /// The first column `columns` are for (`u32::MAX`: none yet).
    columns_from: u32,
    /// The tile (`next` then) whose dwells are in `tile` (`u32::MAX`: none).
    in_tile: u32,
    /// Steps and pixels computed in the current tile, not yet in `stats`.
    tile_steps: u32,
    tile_pixels: u32,
    /// The current tile's dwells, row by row with no gaps (w×h of them): a tile leaves as
    /// one slice. Last (`repr(C)`), so that the other fields are a load's short offset
    /// away: laid out by the compiler, the full view at 320×240 took 0.5 % more on the
    /// M4F.
    tile: [u16; CELLS],
}

/// A perturbed pixel's dwell, out of line wherever a render is (in line, perturbation's
/// finish took 7 KiB more flash).
#[inline(never)]
fn perturbed_dwell(pixels: &Perturbation<'_>, re: Part, im: Part) -> Perturbed {
    pixels.dwell(re.0, im.0)
}

/// How a tile's cells get their orbits: a fixed tier's (compiled once per tier, the
/// orbit in line) or by perturbation.
trait Cells {
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
struct Traced<T>(T);

impl<T: TierOrbit> Cells for Traced<T> {
    #[inline(always)]
    fn orbit(&self, _: &Pixels<'_>, re: Part, im: Part, _: &mut RenderStats) -> Orbit {
        self.0.traced_dwell(re, im)
    }
}

/// Whatever the render computes, found at each cell: a perturbed render's cells (its
/// state stays in the render, not copied to the stack).
struct AnyCells;

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
struct TileCells<'a, 'r, const CELLS: usize> {
    render: &'a mut Render<'r, CELLS>,
    size: (u32, u32),
    /// Whether the tile's regions are traced (see [`Render::trace`]), not subdivided.
    traced: bool,
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

/// Directions along a crack between cells, in quarter turns clockwise from rightward (y
/// grows downward).
const RIGHT: u32 = 0;
const DOWN: u32 = 1;
const LEFT: u32 = 2;
const UP: u32 = 3;

// A row of a tile is a word of `Outlines`.
const _: () = assert!(TILE <= u32::BITS);

/// What a tile's boundary tracing knows of its cells, a bit a cell and a word a row.
struct Outlines {
    /// Cells on a followed outline.
    followed: [u32; TILE_ROWS],
    /// Cells computed across a followed outline: where new regions start.
    across: [u32; TILE_ROWS],
}

impl Outlines {
    #[inline(always)]
    fn mark_followed(&mut self, x: u32, y: u32) {
        set_bit(&mut self.followed, x, y);
    }

    #[inline(always)]
    fn mark_across(&mut self, x: u32, y: u32) {
        set_bit(&mut self.across, x, y);
    }

    /// The rows, a bit each, of a traced tile `w` cells wide and `h` high that are sent as
    /// blocks of one dwell: rows all one dwell once gaps are filled, and the same dwell as
    /// the row above if that is one too. A cell is computed only on a followed outline or
    /// across one (and marked), or by the first scan of the tile's edge: a row with no
    /// marked cell between its first and last has only gaps between them, and is one
    /// dwell if its last cell is a gap or the first's dwell. The first and last rows, on
    /// the tile's edge, are checked cell by cell.
    fn quiet_rows(&self, tile: &[u16], w: u32, h: u32) -> u64 {
        let between = low_bits(w.saturating_sub(1)) & !1;
        let marked = self.followed.iter().zip(&self.across);
        let mut quiet = 0;
        // The dwell of the row above if it is sent as a block.
        let mut above = None;
        for (y, (followed, across)) in (0..h).zip(marked) {
            let dwell = above.take();
            if u64::from(followed | across) & between != 0 {
                continue;
            }
            let start = (y * w) as usize;
            let Some(row) = tile.get(start..start + w as usize) else {
                break;
            };
            let (Some(&first), Some(&last)) = (row.first(), row.last()) else {
                break;
            };
            let one_dwell = |cell: u16| cell == 0 || cell == first;
            let uniform = if y == 0 || y + 1 == h {
                row.iter().all(|&cell| one_dwell(cell))
            } else {
                one_dwell(last)
            };
            // The first cell is on the tile's edge, so computed; were it not (0), the row
            // would go as cells.
            if uniform && first != 0 && dwell.is_none_or(|above| above == first) {
                quiet |= 1 << y;
                above = Some(first);
            }
        }
        quiet
    }
}

/// Sets cell (x, y)'s bit in a tile's bits, a word a row (indexed by masking: no bounds
/// checks).
#[inline(always)]
fn set_bit(bits: &mut [u32; TILE_ROWS], x: u32, y: u32) {
    if let Some(row) = bits.get_mut(y as usize & (TILE_ROWS - 1)) {
        *row |= 1 << (x & (TILE - 1));
    }
}

/// A rectangle of a tile, corners inclusive, in tile coordinates.
#[derive(Debug, Clone, Copy)]
struct Block {
    x0: u32,
    y0: u32,
    x1: u32,
    y1: u32,
}

impl Render<'static> {
    /// A render of `view`, nothing computed yet, in the view's fixed-point tier, with
    /// tiles of [`TILE_ROWS`] rows. A [`Tier::Perturbation`] view needs storage for its
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
    /// 2,048 bytes fewer and traces 32×32 tiles (on Cortex-M4F, the full view at 320×240
    /// took 2.1 % more instructions, the boards' deep zoom 8.9 % more).
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

    /// Tile rows are masked and are bits of a word, so they are a power of two up to 64
    /// (and at least 2: a tile shares its first row with the tile above).
    const ROWS_FIT: () = assert!(
        Self::ROWS.is_power_of_two()
            && Self::ROWS >= 2
            && Self::ROWS <= TILE_ROWS
            && CELLS.is_multiple_of(TILE as usize),
        "a Render's CELLS is 32 times a power of two from 2 to 64"
    );

    /// Rows in the tile.
    const ROWS: usize = CELLS / TILE as usize;

    fn with_pixels(view: View, algorithm: Algorithm, pixels: Pixels<'r>) -> Self {
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
    /// (about 4 % more iterations for the full view at 8; tested to stay under 10 %).
    /// A `block` below 2 means no preview; a render already under way keeps its plan.
    #[must_use]
    pub const fn with_preview(mut self, block: u32) -> Self {
        if self.next == 0 && self.previewed == 0 {
            self.preview = if block < 2 { 0 } else { block };
        }
        self
    }

    /// Block rows of the preview.
    fn preview_units(&self) -> u32 {
        match self.preview {
            0 => 0,
            block => self.view.size.height.div_ceil(block),
        }
    }

    /// One block row of the preview: each block filled with its middle pixel's dwell.
    fn preview_row<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
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

    /// Rows to compute: the top half when mirrored (the middle row of an odd height is
    /// its own mirror and is computed too).
    fn computed_rows(&self) -> u32 {
        let h = self.view.size.height;
        if self.view.symmetry() != Symmetry::None {
            h.div_ceil(2)
        } else {
            h
        }
    }

    fn tiles_across(&self) -> u32 {
        self.view.size.width.div_ceil(TILE)
    }

    /// Rows from one tile's first to the next's, down a column of tiles: where it adds no
    /// tile, a tile's last row is the first of the tile below, computed once (tiles go
    /// down a column before the next, so the shared row is still in `tile`). A tile's
    /// edge is on the outline of every region along it, so its cells are all computed;
    /// on the full view at 320×240, sharing them computed 683 pixels fewer. Where it
    /// would add a row of tiles (64 rows: three tiles of 31, not two of 32), the deep
    /// zoom took 0.15 % more instructions.
    fn tile_stride(&self) -> u32 {
        let rows = self.computed_rows();
        let tile_rows = self.tile_rows();
        if rows.saturating_sub(1).div_ceil(tile_rows - 1) > rows.div_ceil(tile_rows) {
            tile_rows
        } else {
            tile_rows - 1
        }
    }

    /// A tile's height: traced tiles as tall as the render holds (on the full view at
    /// 320×240, 32×64 tiles computed 11,245 pixels where 32×32 computed 11,694, and the
    /// frame took 2.0 % fewer instructions on Cortex-M4F, the boards' deep zoom 8.2 %
    /// fewer); subdivided ones at most 32 (at 32×64, the boards' Julia set at 320×240
    /// took 2 % more).
    fn tile_rows(&self) -> u32 {
        match self.pixels {
            Pixels::Fixed(kernel) if kernel.traceable() => Self::ROWS as u32,
            _ => TILE.min(Self::ROWS as u32),
        }
    }

    /// Tiles in a column.
    fn tiles_down(&self) -> u32 {
        let stride = self.tile_stride();
        // A tile covers rows y0..y0 + tile_rows; the next starts at y0 + stride.
        (self.computed_rows() + stride)
            .saturating_sub(self.tile_rows())
            .div_ceil(stride)
            .max(1)
    }

    fn units(&self) -> u32 {
        match self.algorithm {
            Algorithm::Exact => self.view.size.height,
            Algorithm::Fast => self.tiles_across() * self.tiles_down(),
        }
    }

    /// The dwell of the point with column part `re` and row part `im`.
    fn compute_at(&mut self, re: Part, im: Part) -> u16 {
        let orbit = AnyCells.orbit(&self.pixels, re, im, &mut self.stats);
        self.record(orbit)
    }

    /// Counts a computed pixel's orbit in the stats; its dwell.
    #[inline(always)]
    fn record(&mut self, orbit: Orbit) -> u16 {
        self.stats.iterations += u64::from(orbit.iterations);
        self.stats.pixels += 1;
        // A dwell is at most the view's inside value, a u16 (the view checks the cap): the
        // cast keeps it whole, one instruction fewer a pixel than a checked conversion.
        orbit.dwell as u16
    }

    fn exact_row<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
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

    fn fast_tile<S: DwellSink>(&mut self, sink: &mut S) -> Result<(), S::Error> {
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
        // Copied out and back round the tile's clearing: moved within the tile and the rest
        // cleared by a fill, the full view took 25 K more instructions on the M4F.
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

    /// Sends `area.size.height` of the tile's rows from row `first` to `area` in `order`:
    /// one dwell if uniform, else in bands of rows, each band of one-dwell rows as a block
    /// (see `Outlines::quiet_rows`). A display takes a block as one colour repeated: with
    /// 32×32 tiles, the full view at 320×240 took 3.1 % fewer instructions on Cortex-M4F
    /// than with one `fill_contiguous` a tile.
    fn emit<S: DwellSink>(
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
    fn send<S: DwellSink>(
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
    fn fill_gaps(&mut self) {
        let mut before = 0;
        for cell in &mut self.tile {
            fill_gap(cell, &mut before);
        }
    }

    /// [`trace`](Self::trace) or [`subdivide`](Self::subdivide) the current tile, compiled
    /// once per way of computing a cell (each fixed tier, its orbit in line, and any
    /// other). Against one subdivision testing the tier at each cell, the full view at
    /// 320×240 took 1.8 % fewer instructions on Cortex-M4F (M3 1.5 %, M0 2.2 %), the Julia
    /// set 1.8 % (M3 1.1 %, M0 2.3 %). In line in `fast_tile`: compiled apart, in this
    /// crate rather than the sink's, the full view took 1.1 % more on Cortex-M4F (both
    /// measured with subdivision alone).
    #[inline(always)]
    fn compute_tile(&mut self, w: u32, h: u32) -> TileDwells {
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
    const fn cell_index(&self, tx: u32, ty: u32) -> usize {
        (ty * self.width + tx) as usize
    }

    /// The dwell of tile cell (tx, ty), computed on first use (0 marks "not yet").
    #[inline(always)]
    fn known<C: Cells>(&mut self, cells: &C, tx: u32, ty: u32) -> u16 {
        // A dwell is a u16: the cast keeps it whole.
        self.cell_at(cells, tx, ty, self.cell_index(tx, ty) as u32) as u16
    }

    /// Computes tile cell (tx, ty), at `index` in `tile`.
    #[inline(never)]
    fn compute_cell<C: Cells>(&mut self, cells: &C, tx: u32, ty: u32, index: usize) -> u32 {
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
        // Counted in 32 bits (a tile's cells take at most 2,048 × 65,535 steps) and added
        // to the stats once a tile.
        self.tile_steps += orbit.iterations;
        self.tile_pixels += 1;
        // A dwell is at most the view's inside value, a u16 (see `record`).
        let value = orbit.dwell as u16;
        if let Some(cell) = self.tile.get_mut(index) {
            *cell = value;
        }
        // Widened here, once: the callers compare it with cells read as u32.
        u32::from(value)
    }

    /// The border of `b`'s dwell if it has only one, computing it as far as it must: the
    /// scan stops at the first other dwell, since the four blocks `b` is then split into
    /// have its border as theirs (their scans, or a small block's whole computation,
    /// compute the rest). The same cells are computed as by a whole scan.
    fn border<C: Cells>(&mut self, cells: &C, b: Block) -> Option<u16> {
        let first = self.known(cells, b.x0, b.y0);
        for tx in b.x0 + 1..b.x1 + 1 {
            if self.known(cells, tx, b.y0) != first {
                return None;
            }
        }
        for ty in b.y0 + 1..b.y1 + 1 {
            if self.known(cells, b.x1, ty) != first || self.known(cells, b.x0, ty) != first {
                return None;
            }
        }
        for tx in b.x0 + 1..b.x1 {
            if self.known(cells, tx, b.y1) != first {
                return None;
            }
        }
        Some(first)
    }

    /// Boundary tracing over the current tile, of size w×h: the tile's dwell if it is
    /// uniform, else its cells with gaps.
    ///
    /// A tile whose edge is one dwell is that dwell, as in subdivision. Otherwise the
    /// outline of the first cell's region is followed ([`follow`](Self::follow)),
    /// computing the cells on both sides of each crack between it and another dwell (or the
    /// tile's edge). Then, row by row, each computed cell not on a followed outline whose
    /// neighbour above or before has another dwell is the first met of a new region: its
    /// outline is followed in turn. Each cell not computed takes the dwell of the cell
    /// before it, as the tile is sent (`emit`): it could only differ if the crack between
    /// them were on an outline, and every region's has been followed. Filled in that pass
    /// rather than one of its own, the full view at 320×240 took 1.4 % fewer instructions
    /// on Cortex-M4F. Only the cells along outlines are computed: on the full view at
    /// 320×240, 12,377 where subdivision computed 19,262 (11,694 with tiles sharing rows).
    ///
    /// A region inside another without touching the tile's edge would be missed; in a
    /// Mandelbrot view the sets of points with dwell above k are connected, so there is
    /// none except where a pixel grid breaks a connection narrower than a pixel (see
    /// `Kernel::traceable`).
    fn trace<C: Cells>(&mut self, cells: &C, w: u32, h: u32) -> TileDwells {
        let mut outlines = Outlines {
            followed: [0; TILE_ROWS],
            across: [0; TILE_ROWS],
        };
        let whole = Block {
            x0: 0,
            y0: 0,
            x1: w - 1,
            y1: h - 1,
        };
        if let Some(value) = self.border(cells, whole) {
            // The tile's edge is one region's outline, and the region fills the tile: found
            // by one scan that stops at the first other dwell, cheaper than a walk round.
            return TileDwells::Uniform(value);
        }
        self.follow(cells, (0, 0, RIGHT), (w, h), &mut outlines);
        let width = self.width as usize;
        for ty in 0..h {
            let row = ty as usize & (TILE_ROWS - 1);
            // Bits from here on are still to be looked at.
            let mut from = 0u32;
            loop {
                let followed = outlines.followed.get(row).copied().unwrap_or(0);
                let across = outlines.across.get(row).copied().unwrap_or(0);
                let unseen = u32::MAX.checked_shl(from).unwrap_or(0);
                let candidates = across & !followed & unseen;
                if candidates == 0 {
                    break;
                }
                let tx = candidates.trailing_zeros();
                from = tx + 1;
                let index = self.cell_index(tx, ty);
                let value = self.tile.get(index).copied().unwrap_or(0);
                // A neighbour not computed has this cell's dwell: were it another, the crack
                // between them would be on the neighbour's region's outline, followed.
                let differs = |at: Option<usize>| {
                    at.and_then(|at| self.tile.get(at))
                        .is_some_and(|&other| other != 0 && other != value)
                };
                let start = if ty == 0 || differs(index.checked_sub(width)) {
                    Some(RIGHT)
                } else if tx == 0 || differs(index.checked_sub(1)) {
                    Some(UP)
                } else {
                    // Not the first cell of its region met: that one starts its outline.
                    None
                };
                if let Some(direction) = start {
                    self.follow(cells, (tx, ty, direction), (w, h), &mut outlines);
                }
            }
        }
        // Cells not computed take the dwell before them as the tile is sent.
        TileDwells::Gaps(outlines.quiet_rows(&self.tile, self.width, h))
    }

    /// Follows the outline of the region of the cell in `start` (a cell and a direction
    /// along one of its cracks with another dwell or the tile's edge on its left, the
    /// region on its right) around, back to `start`: computes the cells on both sides of
    /// each crack, marks the region's as followed and the others as across. The walk is
    /// reversible (each state, a cell and a crack, has one successor and one predecessor)
    /// and starts on the outline, so it comes back to `start`, within 4·w·h steps.
    fn follow<C: Cells>(
        &mut self,
        cells: &C,
        (sx, sy, direction): (u32, u32, u32),
        (w, h): (u32, u32),
        outlines: &mut Outlines,
    ) {
        let value = u32::from(self.known(cells, sx, sy));
        let start = sy * w + sx;
        let mut at = (sx, sy, start);
        let mut k = direction;
        outlines.mark_followed(sx, sy);
        loop {
            // Each direction's step compiled apart: its tests of the tile's edges are one
            // comparison each, its neighbours one addition away.
            let turn = match k {
                RIGHT => self.crack::<C, 1, 0>(cells, &mut at, value, (w, h), outlines),
                DOWN => self.crack::<C, 0, 1>(cells, &mut at, value, (w, h), outlines),
                LEFT => self.crack::<C, -1, 0>(cells, &mut at, value, (w, h), outlines),
                _ => self.crack::<C, 0, -1>(cells, &mut at, value, (w, h), outlines),
            };
            k = (k + turn) & 3;
            if at.2 == start && k == direction {
                break;
            }
        }
    }

    /// One step of [`follow`](Self::follow) from the cell `at` (x, y and its index) in
    /// direction (DX, DY): to the cell ahead if it is in the region and the one left of
    /// it is not, to the left one if it is (a left turn), or none if the cell ahead is not
    /// (a right turn). Returns the turn in quarters clockwise (0, 1 or 3).
    #[inline(always)]
    fn crack<C: Cells, const DX: i32, const DY: i32>(
        &mut self,
        cells: &C,
        at: &mut (u32, u32, u32),
        value: u32,
        (w, h): (u32, u32),
        outlines: &mut Outlines,
    ) -> u32 {
        let (x, y, index) = *at;
        // Whether a step from (x, y) by (dx, dy) stays in the tile: one test each.
        let stays = |dx: i32, dy: i32| match (dx, dy) {
            (1, _) => x + 1 < w,
            (-1, _) => x > 0,
            (_, 1) => y + 1 < h,
            _ => y > 0,
        };
        let offset = |dx: i32, dy: i32| (dx + dy * w as i32) as u32;
        if !stays(DX, DY) {
            return 1;
        }
        let (ax, ay) = (x.wrapping_add_signed(DX), y.wrapping_add_signed(DY));
        let ahead_index = index.wrapping_add(offset(DX, DY));
        if self.cell_at(cells, ax, ay, ahead_index) != value {
            outlines.mark_across(ax, ay);
            return 1;
        }
        // Left of the cell ahead: (DY, −DX) from it, one step from (x, y) across.
        if stays(DY, -DX) {
            let (lx, ly) = (ax.wrapping_add_signed(DY), ay.wrapping_add_signed(-DX));
            let left_index = ahead_index.wrapping_add(offset(DY, -DX));
            if self.cell_at(cells, lx, ly, left_index) == value {
                *at = (lx, ly, left_index);
                outlines.mark_followed(lx, ly);
                return 3;
            }
            outlines.mark_across(lx, ly);
        }
        *at = (ax, ay, ahead_index);
        outlines.mark_followed(ax, ay);
        0
    }

    /// The dwell of tile cell (x, y) at `index`, computed on first use (0 marks "not
    /// yet").
    #[inline(always)]
    fn cell_at<C: Cells>(&mut self, cells: &C, x: u32, y: u32, index: u32) -> u32 {
        // Cells and coordinates are indexed within their arrays by masking: no bounds checks.
        let index = index as usize & (CELLS - 1);
        match self.tile.get(index).copied() {
            Some(0) | None => self.compute_cell(cells, x, y, index),
            Some(value) => u32::from(value),
        }
    }

    /// Mariani–Silver over the current tile, of size w×h: every cell, or the tile's dwell
    /// if it is uniform.
    fn subdivide<C: Cells>(&mut self, cells: &C, w: u32, h: u32) -> TileDwells {
        let whole = Block {
            x0: 0,
            y0: 0,
            x1: w - 1,
            y1: h - 1,
        };
        // A tile whose outline is one dwell is filled with it: uniform.
        let uniform = self.border(cells, whole);
        let mut stack: Vec<Block, 32> = Vec::new();
        let mut next = Some((whole, uniform));
        while let Some((b, border)) = next {
            let (bw, bh) = (b.x1 - b.x0, b.y1 - b.y0);
            if let Some(value) = border {
                for ty in b.y0 + 1..b.y1 {
                    let row = self.cell_index(0, ty);
                    if let Some(inside) = self
                        .tile
                        .get_mut(row + b.x0 as usize + 1..row + b.x1 as usize)
                    {
                        inside.fill(value);
                    }
                }
            } else if bw < WHOLE_BELOW || bh < WHOLE_BELOW {
                // The whole block: its border's scan may have stopped early.
                for ty in b.y0..b.y1 + 1 {
                    for tx in b.x0..b.x1 + 1 {
                        self.known(cells, tx, ty);
                    }
                }
            } else {
                let (xm, ym) = (b.x0 + bw / 2, b.y0 + bh / 2);
                for block in [
                    Block {
                        x0: b.x0,
                        y0: b.y0,
                        x1: xm,
                        y1: ym,
                    },
                    Block {
                        x0: xm,
                        y0: b.y0,
                        x1: b.x1,
                        y1: ym,
                    },
                    Block {
                        x0: b.x0,
                        y0: ym,
                        x1: xm,
                        y1: b.y1,
                    },
                    Block {
                        x0: xm,
                        y0: ym,
                        x1: b.x1,
                        y1: b.y1,
                    },
                ] {
                    // Depth is at most 5 levels of 3 pending blocks: 32 never fills.
                    let _ = stack.push(block);
                }
            }
            next = stack.pop().map(|b| (b, self.border(cells, b)));
        }
        uniform.map_or(TileDwells::Cells, TileDwells::Uniform)
    }
}

/// Cells row by row, last row first: a slice walk per row, a few instructions a cell.
struct RowsBackward<'a> {
    /// The rows not yet started.
    rest: &'a [u16],
    row: core::slice::Iter<'a, u16>,
    w: usize,
}

impl<'a> RowsBackward<'a> {
    fn new(cells: &'a [u16], w: usize) -> Self {
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

/// A word with its `n` lowest bits set (a tile's cells in a row, or its rows).
fn low_bits(n: u32) -> u64 {
    1u64.checked_shl(n).map_or(u64::MAX, |bit| bit - 1)
}

/// A cell read in order with the dwell `before` it: a gap (0) takes that dwell, written in
/// place (unconditionally, no branch); the cell's dwell, now `before` the next.
#[inline(always)]
fn fill_gap(cell: &mut u16, before: &mut u16) -> u16 {
    let value = if *cell == 0 { *before } else { *cell };
    (*cell, *before) = (value, value);
    value
}

/// A tile's dwells once computed.
#[derive(Debug, Clone, Copy)]
enum TileDwells {
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

/// The order a tile's rows and columns are sent in.
#[derive(Debug, Clone, Copy)]
enum Order {
    /// As computed.
    Forward,
    /// Rows bottom to top (a mirror about the real axis).
    RowsReversed,
    /// Rows bottom to top and columns right to left (a half turn).
    HalfTurn,
}

/// A point part of a pixel in the view: within ±3.5 (checked by `View::new`), so it fits an
/// i64; 0 for parts past the view's edge, which are never used.
fn in_view(q60: i128) -> i64 {
    i64::try_from(q60).unwrap_or(0)
}

fn coordinate(value: u32) -> i32 {
    i32::try_from(value).unwrap_or(i32::MAX)
}
