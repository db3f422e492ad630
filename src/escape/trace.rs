//! Boundary tracing: a Mandelbrot tile's regions of one dwell found by following their
//! outlines, only the cells on both sides of an outline computed.

use super::render::{Render, TILE, TILE_ROWS};
use super::subdivide::Block;
use super::tile::{low_bits, Cells, TileDwells};

/// Directions along a crack between cells, in quarter turns clockwise from rightward (y
/// grows downward).
pub(super) const RIGHT: u32 = 0;
pub(super) const DOWN: u32 = 1;
pub(super) const LEFT: u32 = 2;
pub(super) const UP: u32 = 3;

/// The sampling of a traced tile for dust (`Render::dusty`): every `DUST_SPACING`-th row
/// and column.
pub(super) const DUST_SPACING: u32 = 8;

/// Cells escaping in the last half of the iterations, on a tile's sampled rows, that make
/// it worth sampling for dust: few tiles of the full view or seahorse valley have as
/// many, a view of dust's most (docs/escape-time.md).
pub(super) const DUST_CELLS: usize = 24;

// A row of a tile is a word of `Outlines`.
const _: () = assert!(TILE <= u32::BITS);

/// What a tile's boundary tracing knows of its cells, a bit a cell and a word a row.
pub(super) struct Outlines {
    /// Cells on a followed outline.
    followed: [u32; TILE_ROWS],
    /// Cells computed across a followed outline: where new regions start.
    across: [u32; TILE_ROWS],
}

impl Outlines {
    #[inline(always)]
    pub(super) fn mark_followed(&mut self, x: u32, y: u32) {
        set_bit(&mut self.followed, x, y);
    }

    #[inline(always)]
    pub(super) fn mark_across(&mut self, x: u32, y: u32) {
        set_bit(&mut self.across, x, y);
    }

    /// The rows, a bit each, of a traced tile `w` cells wide and `h` high that are sent as
    /// blocks of one dwell: rows all one dwell once gaps are filled, and the same dwell as
    /// the row above if that is one too. A cell is computed only on a followed outline or
    /// across one (and marked), or by the first scan of the tile's edge: a row with no
    /// marked cell between its first and last has only gaps between them, and is one
    /// dwell if its last cell is a gap or the first's dwell. The first and last rows, on
    /// the tile's edge, are checked cell by cell.
    pub(super) fn quiet_rows(&self, tile: &[u16], w: u32, h: u32) -> u64 {
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
pub(super) fn set_bit(bits: &mut [u32; TILE_ROWS], x: u32, y: u32) {
    if let Some(row) = bits.get_mut(y as usize & (TILE_ROWS - 1)) {
        *row |= 1 << (x & (TILE - 1));
    }
}

impl<'r, const CELLS: usize> Render<'r, CELLS> {
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
    /// rather than one of its own, so each cell is read once. Only the cells along
    /// outlines are computed, far fewer than subdivision computes (docs/performance.md).
    ///
    /// A region inside another without touching the tile's edge would be missed; in a
    /// Mandelbrot view the sets of points with dwell above k are connected, so there is
    /// none except where a pixel grid breaks a connection narrower than a pixel (see
    /// `Kernel::traceable`). Where those come in crowds (dust escaping just before the
    /// cap), [`dusty`](Self::dusty) finds most tiles that hold them, and they are computed
    /// whole.
    pub(super) fn trace<C: Cells>(&mut self, cells: &C, w: u32, h: u32) -> TileDwells {
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
        if self.dusty(cells, w, h, &outlines) {
            return self.compute_all(cells, w, h);
        }
        // Cells not computed take the dwell before them as the tile is sent.
        TileDwells::Gaps(outlines.quiet_rows(&self.tile, self.width, h))
    }

    /// Whether a traced tile's regions at the cap hide dust, as far as a sparse sample
    /// shows: on every [`DUST_SPACING`]-th row (from the middle of the first such band),
    /// if at least [`DUST_CELLS`] of the computed cells escape in the last half of the
    /// iterations, computes the cells not yet computed at every [`DUST_SPACING`]-th
    /// column that the tile would fill with the cap, and tells whether one escapes.
    ///
    /// Outlines find every region that touches another one or the tile's edge; what they
    /// cannot see is a region enclosed in a single other one, in a Mandelbrot view a speck
    /// cut off by a channel narrower than a pixel. Nearly all such specks are dust escaping
    /// just before the cap, which comes in crowds: a tile of it has many computed cells
    /// escaping late, and a sample of one cell in 64 of its cap regions finds most such
    /// tiles. Views without dust seldom pass the first test, so they pay only its scan.
    fn dusty<C: Cells>(&mut self, cells: &C, w: u32, h: u32, outlines: &Outlines) -> bool {
        if self.late_cells(h, outlines) < DUST_CELLS {
            return false;
        }
        let inside = self.view.inside_value();
        let half = DUST_SPACING / 2;
        for ty in (half..h.saturating_sub(1)).step_by(DUST_SPACING as usize) {
            // The first cell of a row, on the tile's edge, is computed; a cell not computed
            // takes the dwell before it.
            let mut before = self.known(cells, 0, ty);
            for tx in 1..w.saturating_sub(1) {
                let value = self.tile.get(self.cell_index(tx, ty)).copied().unwrap_or(0);
                if value != 0 {
                    before = value;
                } else if tx % DUST_SPACING == half
                    && before == inside
                    && self.known(cells, tx, ty) != inside
                {
                    return true;
                }
            }
        }
        false
    }

    /// The cells on [`dusty`](Self::dusty)'s rows of a traced tile `h` rows high computed
    /// by its `outlines` (those on or across one) that escape in the last half of the
    /// iterations. Apart from the tier, so that the firmware has one copy.
    #[inline(never)]
    fn late_cells(&self, h: u32, outlines: &Outlines) -> usize {
        let inside = self.view.inside_value();
        let rows = (DUST_SPACING / 2..h.saturating_sub(1)).step_by(DUST_SPACING as usize);
        let mut late = 0;
        for ty in rows {
            let row = ty as usize & (TILE_ROWS - 1);
            let followed = outlines.followed.get(row).copied().unwrap_or(0);
            let mut marked = followed | outlines.across.get(row).copied().unwrap_or(0);
            while marked != 0 {
                let tx = marked.trailing_zeros();
                marked &= marked - 1;
                let value = self.tile.get(self.cell_index(tx, ty)).copied().unwrap_or(0);
                late += usize::from(value > inside / 2 && value < inside);
            }
        }
        late
    }

    /// Computes every cell of the tile not yet computed: a dusty tile is sent cell by cell.
    #[inline(never)]
    fn compute_all<C: Cells>(&mut self, cells: &C, w: u32, h: u32) -> TileDwells {
        let whole = Block {
            x0: 0,
            y0: 0,
            x1: w - 1,
            y1: h - 1,
        };
        self.compute_block(cells, whole);
        TileDwells::Cells
    }

    /// Follows the outline of the region of the cell in `start` (a cell and a direction
    /// along one of its cracks with another dwell or the tile's edge on its left, the
    /// region on its right) around, back to `start`: computes the cells on both sides of
    /// each crack, marks the region's as followed and the others as across. The walk is
    /// reversible (each state, a cell and a crack, has one successor and one predecessor)
    /// and starts on the outline, so it comes back to `start`, within 4·w·h steps.
    pub(super) fn follow<C: Cells>(
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
    pub(super) fn crack<C: Cells, const DX: i32, const DY: i32>(
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
}
