//! Sums of octaves a block of columns at a time, in the plane or at one depth: a column's
//! x half of every octave's sample (lattice column, place in it, fade) is the same in
//! every row, so a drawing computes it once for the block's whole height instead of once
//! a pixel.

use super::fractal::{times, Ladder, Weight, MAX_OCTAVES};
use super::perlin::{CellCorners, ColumnPart, CubeCorners, Perlin, RowPart, Sample};
use crate::math::Real;

/// Columns in a block: the x parts of 16 octaves for 32 columns are 4 KiB of stack (a
/// wider block shares each row's set-up among more columns).
pub(super) const BLOCK_COLUMNS: usize = 32;

/// The x parts of up to [`BLOCK_COLUMNS`] columns, octave by octave, for sums whose
/// octaves double (lacunarity 2), in the plane or at one depth of 3D noise.
pub(super) struct ColumnBlock {
    parts: [[ColumnPart; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
    columns: usize,
}

impl ColumnBlock {
    /// A block of no columns yet.
    pub(super) const EMPTY: Self = Self {
        parts: [[ColumnPart::ZERO; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
        columns: 0,
    };

    /// Takes the columns at `xs` (the first [`BLOCK_COLUMNS`] of them). Each octave
    /// doubles the last one's coordinate: `xs` must be points whose finest octave stays in
    /// `Real`'s range, as a texture's fit checks.
    pub(super) fn fill(&mut self, ladder: &Ladder, xs: &[Real]) {
        let columns = xs.len().min(BLOCK_COLUMNS);
        for (column, x) in xs.iter().take(columns).enumerate() {
            let mut x = x.to_bits();
            let octaves = self.parts.iter_mut().take(ladder.amplitudes().len());
            for (octave, slots) in octaves.enumerate() {
                if octave > 0 {
                    // In range: see above.
                    x = x.wrapping_mul(2);
                }
                if let Some(slot) = slots.get_mut(column) {
                    *slot = ColumnPart::of(Real::from_bits(x));
                }
            }
        }
        self.columns = columns;
    }

    /// Each column's sum of the octaves of `noise` (of |noise| for `turbulence`) at the
    /// row whose y parts are `rows`, in 2⁻³², written to `totals`: the same values as the
    /// ladder's sum at each point, octave by octave along the block, a cell's corners
    /// taken once for the columns that share it.
    pub(super) fn sums(
        &self,
        noise: &Perlin,
        ladder: &Ladder,
        rows: &[RowPart; MAX_OCTAVES as usize],
        turbulence: bool,
        totals: &mut [i64; BLOCK_COLUMNS],
    ) {
        if turbulence {
            self.sums_of::<true>(noise, ladder, rows, totals);
        } else {
            self.sums_of::<false>(noise, ladder, rows, totals);
        }
    }

    /// [`sums`](Self::sums) of 3D noise, in the layer whose z parts are `layers`. One loop
    /// for every weight and for turbulence (|noise| by a mask), to spare flash: a 3D
    /// sample's seven 64-bit interpolations outweigh the choices.
    pub(super) fn sums_in_layer(
        &self,
        noise: &Perlin,
        ladder: &Ladder,
        rows: &[RowPart; MAX_OCTAVES as usize],
        layers: &[RowPart; MAX_OCTAVES as usize],
        turbulence: bool,
        totals: &mut [i64; BLOCK_COLUMNS],
    ) {
        let block = totals.get_mut(..self.columns).unwrap_or(&mut []);
        block.fill(0);
        // All ones to take |noise|: x ^ −1 − (−1) = −x for a negative sample.
        let absolute = -i32::from(turbulence);
        let octaves = self.parts.iter().zip(rows).zip(layers);
        for (((parts, &row), &layer), &amplitude) in octaves.zip(ladder.amplitudes()) {
            // The first column takes its cell's corners.
            let mut corners = CubeCorners::NONE;
            for (total, &column) in block.iter_mut().zip(parts) {
                if column.cell() != corners.cell() {
                    corners = noise.cube_corners(column.cell(), row, layer);
                }
                let value = corners.sample(column, row, layer).0;
                let flip = (value >> 31) & absolute;
                // Each term within ±1.04, 16 of them: no overflow.
                *total += times(Sample((value ^ flip) - flip), amplitude).to_bits();
            }
        }
    }

    /// [`sums`](Self::sums), of |noise| where `ABSOLUTE`: one loop for each.
    fn sums_of<const ABSOLUTE: bool>(
        &self,
        noise: &Perlin,
        ladder: &Ladder,
        rows: &[RowPart; MAX_OCTAVES as usize],
        totals: &mut [i64; BLOCK_COLUMNS],
    ) {
        let block = totals.get_mut(..self.columns).unwrap_or(&mut []);
        block.fill(0);
        let octaves = self.parts.iter().zip(rows).zip(ladder.weights());
        for ((parts, &row), weight) in octaves {
            // One loop for each kind of weight: the kind is chosen once an octave.
            match weight {
                Weight::Eighths(m) => add_octave::<ABSOLUTE>(noise, parts, row, block, |value| {
                    Weight::Eighths(m).term(value)
                }),
                Weight::Halving(k) => add_octave::<ABSOLUTE>(noise, parts, row, block, |value| {
                    Weight::Halving(k).term(value)
                }),
                Weight::Any(a) => add_octave::<ABSOLUTE>(noise, parts, row, block, |value| {
                    Weight::Any(a).term(value)
                }),
            }
        }
    }
}

/// Adds one octave's terms (`term` of each sample, of |sample| where `ABSOLUTE`) at the
/// row whose part is `row` to the columns' `totals`, `parts` the columns' parts at this
/// octave.
#[inline(always)]
fn add_octave<const ABSOLUTE: bool>(
    noise: &Perlin,
    parts: &[ColumnPart; BLOCK_COLUMNS],
    row: RowPart,
    totals: &mut [i64],
    term: impl Fn(Sample) -> i64,
) {
    // The first column takes its cell's corners.
    let mut corners = CellCorners::NONE;
    for (total, &column) in totals.iter_mut().zip(parts) {
        if column.cell() != corners.cell() {
            // The next column's corners share two with the last one's.
            corners = if corners.cell() == (column.cell() + 255) & 255 {
                noise.next_corners(&corners, row)
            } else {
                noise.corners(column.cell(), row)
            };
        }
        let mut value = corners.sample(column, row);
        if ABSOLUTE {
            value = Sample(value.0.abs());
        }
        // Each term within ±1.04, 16 of them: no overflow.
        *total += term(value);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The block is the 4 KiB its documentation and the drawing's state.
    #[test]
    fn a_block_is_four_kib() {
        let parts = MAX_OCTAVES as usize * BLOCK_COLUMNS * 8;
        assert_eq!(parts, 4096);
        assert_eq!(size_of::<ColumnBlock>(), parts + size_of::<usize>());
    }
}
