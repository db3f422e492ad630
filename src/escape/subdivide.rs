//! Mariani–Silver subdivision: a rectangle's border computed, filled if it is one value,
//! split in four otherwise.

use heapless::Vec;

use super::render::Render;
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
        // With distance estimation a block whose border escapes may hide a strand drawn
        // as the set: only an inside border fills.
        if self.view.estimates_distance() && first != self.view.inside_value() {
            return None;
        }
        Some(first)
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
