//! A render's state: the view, the tier's pixels, progress, statistics and the tile of
//! dwells being computed; [`schedule`](super::schedule) drives it.
//!
//! RAM: a [`Render`] holds the tile's dwells (32×64×2 = 4 KiB), the tile's 32 column and
//! 64 row coordinates (768 bytes: points are separable, so they are computed once per
//! tile, not once per pixel), the view and its kernel constants, about 5.4 KiB with a
//! perturbed render's series (and it adds the reference orbit, in storage the caller
//! gives: 24 bytes an iteration); while a tile is computed, the tracing's two bits a cell
//! (512 bytes) or a subdivision stack of 32 rectangles (512 bytes) is on the stack. That
//! is the worst case for a 320×240 view or any other: nothing is read back from the
//! target. The tile's cells are a const generic (`Render::<'_, 1024>` traces 32×32 tiles
//! and holds 2 KiB less; see `Render::with_capacity`).

use super::kernel::{fast_tolerance, Kernel, Part, Periodicity};
use super::perturbation::Perturbation;
use super::view::{Parts, Tier, View};

/// Width of a fast-mode tile, in pixels, and the most rows of a subdivided one.
pub const TILE: u32 = 32;

/// The most rows of a fast-mode tile: a [`Render`] of [`TILE_CELLS`] traces tiles this
/// tall (see `Render::tile_rows`).
pub const TILE_ROWS: usize = 64;

/// A [`Render`]'s tile cells unless its type says otherwise (`CELLS`): 32×64.
pub const TILE_CELLS: usize = TILE as usize * TILE_ROWS;

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
    /// a pixel (how often: docs/escape-time.md). Use `Exact` where no pixel may differ.
    #[default]
    Fast,
}

impl Algorithm {
    /// How the algorithm's renders of `view` recognise repeats.
    pub(super) fn periodicity(self, view: &View) -> Periodicity {
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
pub(super) enum Pixels<'r> {
    Fixed(Kernel),
    Perturbed(Perturbation<'r>),
}

impl Pixels<'_> {
    /// The tier the pixels are computed in.
    pub(super) const fn tier(&self) -> Tier {
        match self {
            Self::Fixed(kernel) => kernel.tier(),
            Self::Perturbed(_) => Tier::Perturbation,
        }
    }

    /// Column i's part of its pixels' points.
    #[inline(always)]
    pub(super) fn column(&self, view: &View, i: i64) -> Part {
        match self {
            Self::Fixed(kernel) => kernel.part(in_view(view.column(i))),
            Self::Perturbed(_) => Part(view.column_steps(i)),
        }
    }

    /// Row j's part of its pixels' points.
    #[inline(always)]
    pub(super) fn row(&self, view: &View, j: i64) -> Part {
        match self {
            Self::Fixed(kernel) => kernel.part(in_view(view.row(j))),
            Self::Perturbed(_) => Part(view.row_steps(j)),
        }
    }

    /// The parts of the columns or rows `coordinates` runs over, into `parts`: one
    /// function for both, so its code is in flash once.
    #[inline(never)]
    pub(super) fn fill(&self, coordinates: Parts, parts: &mut [Part]) {
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
    pub(super) view: View,
    pub(super) algorithm: Algorithm,
    pub(super) next: u32,
    /// The preview's block side (0: no preview) and its block rows done.
    pub(super) preview: u32,
    pub(super) previewed: u32,
    pub(super) stats: RenderStats,
    pub(super) pixels: Pixels<'r>,
    /// The current tile's width: the row stride in `tile`.
    pub(super) width: u32,
    /// The current tile's column and row parts of its points.
    pub(super) columns: [Part; TILE as usize],
    pub(super) rows: [Part; TILE_ROWS],
    /// The first column `columns` are for (`u32::MAX`: none yet).
    pub(super) columns_from: u32,
    /// The tile (`next` then) whose dwells are in `tile` (`u32::MAX`: none).
    pub(super) in_tile: u32,
    /// Steps and pixels computed in the current tile, not yet in `stats`.
    pub(super) tile_steps: u32,
    pub(super) tile_pixels: u32,
    /// Where each cell's [`far`](super::kernel::Orbit::far) is kept in `tile`, this many
    /// cells past its value: with distance estimation (not its shading), in the tile's
    /// second half, and tiles of at most half the cells, so that a block whose border
    /// escapes can be filled (see `subdivide`); 0 when not kept.
    pub(super) far_at: u32,
    /// The current tile's dwells, row by row with no gaps (w×h of them): a tile leaves as
    /// one slice. Last (`repr(C)`), so that the other fields are a load's short offset
    /// away.
    pub(super) tile: [u16; CELLS],
}

impl<const CELLS: usize> Render<'_, CELLS> {
    /// Tile rows are masked and are bits of a word, so they are a power of two up to 64
    /// (and at least 2: a tile shares its first row with the tile above).
    pub(super) const ROWS_FIT: () = assert!(
        Self::ROWS.is_power_of_two()
            && Self::ROWS >= 2
            && Self::ROWS <= TILE_ROWS
            && CELLS.is_multiple_of(TILE as usize),
        "a Render's CELLS is 32 times a power of two from 2 to 64"
    );

    /// Rows in the tile.
    pub(super) const ROWS: usize = CELLS / TILE as usize;
}

/// A point part of a pixel in the view: within ±3.5 (checked by `View::new`), so it fits an
/// i64; 0 for parts past the view's edge, which are never used.
pub(super) fn in_view(q60: i128) -> i64 {
    i64::try_from(q60).unwrap_or(0)
}

/// A tile position as a pixel coordinate.
pub(super) fn coordinate(value: u32) -> i32 {
    i32::try_from(value).unwrap_or(i32::MAX)
}
