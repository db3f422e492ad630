//! Mariani–Silver subdivision: a rectangle's border computed, filled if it is one value,
//! split in four otherwise.

use heapless::Vec;

use super::render::{Render, TILE};
use super::tile::{Cells, TileDwells};

/// A block whose border is not one dwell and which spans fewer than this many cells past
/// its first, across or down (at most 5 cells), is computed whole rather than split: its
/// inside is a few cells, fewer than the scans of four sub-blocks would visit. 5 against 4
/// was measured on every board scene (docs/performance.md).
pub(super) const WHOLE_BELOW: u32 = 5;

/// A rectangle of a tile, corners inclusive, in tile coordinates.
#[derive(Debug, Clone, Copy)]
pub(super) struct Block {
    pub(super) x0: u32,
    pub(super) y0: u32,
    pub(super) x1: u32,
    pub(super) y1: u32,
}

impl<'r, const CELLS: usize> Render<'r, CELLS> {
    /// The border of `b`'s dwell if it has only one, computing it as far as it must: the
    /// scan stops at the first other dwell, since the four blocks `b` is then split into
    /// have its border as theirs (their scans, or a small block's whole computation,
    /// compute the rest). The same cells are computed as by a whole scan.
    pub(super) fn border<C: Cells>(&mut self, cells: &C, b: Block) -> Option<u16> {
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
        self.fills(b, first).then_some(first)
    }

    /// Computes every cell of block `b` not yet computed.
    #[inline(always)]
    pub(super) fn compute_block<C: Cells>(&mut self, cells: &C, b: Block) {
        for ty in b.y0..b.y1 + 1 {
            for tx in b.x0..b.x1 + 1 {
                self.known(cells, tx, ty);
            }
        }
    }

    /// Whether block `b`, its border all `value`, fills with it. With distance estimation
    /// a block whose border escapes may hide a strand drawn as the set: it fills only if
    /// every cell of its border (all computed) proves the set so far that no pixel inside
    /// is drawn as the set. Each pixel inside lies within D = ⌊min(width, height)/2⌋
    /// pixels of a border cell q, so it is at least δ_q − D from the set; where that is at
    /// least 4w for the width w, its estimate is at least w (the estimate is more than a
    /// quarter of the distance for every point of a view: see `distance::proven_far`). So
    /// every border cell must prove δ_q ≥ D + 4w. Out of line: one copy for every tier's
    /// subdivision.
    #[inline(never)]
    fn fills(&self, b: Block, value: u16) -> bool {
        if !self.view.estimates_distance() || value == self.view.inside_value() {
            return true;
        }
        if self.far_at == 0 {
            return false;
        }
        let need = far_needed(min_half(b), self.view.distance);
        let (far_at, width) = (self.far_at as usize, self.width as usize);
        let (x0, y0, x1, y1) = (b.x0 as usize, b.y0 as usize, b.x1 as usize, b.y1 as usize);
        let (across, down) = (b.x1 - b.x0 + 1, b.y1 - b.y0 + 1);
        let far = |x: usize, y: usize| far_at + y * width + x;
        let proves = |from: usize, count: u32, step: usize| {
            all_at_least(&self.tile, from, count, step, need)
        };
        proves(far(x0, y0), across, 1)
            && proves(far(x0, y1), across, 1)
            && proves(far(x0, y0), down, width)
            && proves(far(x1, y0), down, width)
    }

    /// Mariani–Silver over the current tile, of size w×h: every cell, or the tile's dwell
    /// if it is uniform.
    pub(super) fn subdivide<C: Cells>(&mut self, cells: &C, w: u32, h: u32) -> TileDwells {
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
                self.compute_block(cells, b);
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

/// ⌊min(width, height)/2⌋ of a block, in cells from corner to corner: how far a cell
/// inside can be from the nearest border cell along its row or column.
fn min_half(b: Block) -> u32 {
    (b.x1 - b.x0).min(b.y1 - b.y0) / 2
}

/// 2^(k/4) for k = 0..4, Q16, rounded down.
const QUARTER_POWERS: [u32; 4] = [65_536, 77_935, 92_681, 110_217];

/// The `far` (quarters of log₂ pixels) a border cell must prove for a block whose
/// inside lies within `reach` pixels of its border, at the width `distance` (256ths of
/// a pixel): the least q with 2^(q/4) ≥ reach + 4w (or one more, where the powers'
/// rounding leaves them just short). A reach is at most half a tile's side.
fn far_needed(reach: u32, distance: u16) -> u32 {
    // reach + 4w in Q16: below 2^18.1, so 2^(q/4) in Q16 reaches it before 2^32.
    let needed = ((reach % TILE) * 256 + 4 * u32::from(distance)) << 8;
    // 2^whole ≤ reach + 4w < 2^(whole + 1), or whole = 0 below 1.
    let whole = (31 - (needed | 1).leading_zeros()).saturating_sub(16);
    let mut q = 4 * whole;
    for power in QUARTER_POWERS {
        if power << whole >= needed {
            return q;
        }
        q += 1;
    }
    q
}

/// Whether `count` values of `cells` from `from`, `step` apart, are all at least `need`.
#[inline(never)]
fn all_at_least(cells: &[u16], mut from: usize, count: u32, step: usize, need: u32) -> bool {
    for _ in 0..count {
        match cells.get(from) {
            Some(&value) if u32::from(value) >= need => from += step,
            _ => return false,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The far a border must prove is ⌈4·log₂(reach + 4w)⌉ (at least 0), in f64, over reaches and
    /// widths (or one more within 10⁻⁵ of a quarter), and 2^(q/4) is at least reach + 4w.
    #[test]
    fn the_far_needed_is_the_quarter_log_of_the_reach_and_four_widths() {
        for reach in 0..32u32 {
            for distance in (0..=4096u16).step_by(13) {
                let pixels = f64::from(reach) + 4.0 * f64::from(distance) / 256.0;
                let q = far_needed(reach, distance);
                assert!(
                    2f64.powf(f64::from(q) / 4.0) >= pixels,
                    "{reach} {distance}"
                );
                if pixels > 0.0 {
                    let exact = (4.0 * pixels.log2()).ceil().max(0.0);
                    let near = (4.0 * pixels.log2() - exact).abs() < 1e-5;
                    assert!(
                        f64::from(q) == exact || (near && f64::from(q) == exact + 1.0),
                        "{reach} {distance}: {q} for {exact}"
                    );
                }
            }
        }
    }
}
