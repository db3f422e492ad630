//! Sums of octaves a block of columns at a time, in the plane or at one depth: a column's
//! x half of every octave's sample (lattice column, place in it, fade) is the same in
//! every row, so a drawing computes it once for the block's whole height instead of once
//! a pixel.

use super::fractal::{times, Ladder, Weight, MAX_OCTAVES};
use super::perlin::{CellCorners, ColumnPart, CubeCorners, GradientTable, Perlin, RowPart, Sample};
use crate::math::Real;
use core::ops::AddAssign;

/// Columns in a block: the x parts and cells of 16 octaves for 32 columns are 4.5 KiB of
/// stack, and the block keeps a 512-byte gradient table beside them (a wider block shares
/// each row's set-up among more columns).
pub(super) const BLOCK_COLUMNS: usize = 32;

/// A column's x part at one octave as a block keeps it: its place (2⁻³¹, a multiple of
/// 2⁻²⁴, so its low [`RUN_BITS`] bits are free) and fade (2⁻³⁰). The first column of a
/// run of columns in one cell keeps the run's length in those bits, and whether the run's
/// cell is the one after the last run's ([`FOLLOWS`]), so that a row's loop takes each
/// cell's corners once (sharing an edge with the last cell where it follows it) and then
/// runs over its columns with no test of their cell; the run's cell is kept apart
/// ([`ColumnBlock`]'s `cells`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct BlockColumn {
    place_and_run: i32,
    fade: i32,
}

/// The low bits of a [`BlockColumn`]'s place that hold a run's length and [`FOLLOWS`].
const RUN_BITS: u32 = 7;

/// The bit of a run's first column that says its cell follows the last run's.
const FOLLOWS: i32 = 1 << (RUN_BITS - 1);

const _: () = assert!(BLOCK_COLUMNS < FOLLOWS as usize);

impl BlockColumn {
    const ZERO: Self = Self {
        place_and_run: 0,
        fade: 0,
    };

    /// The place, in 2⁻³¹.
    #[inline(always)]
    fn place(self) -> i32 {
        self.place_and_run & !((1 << RUN_BITS) - 1)
    }

    /// How many columns from this one share its cell, where it is the first of them; 0
    /// for the others.
    #[inline(always)]
    fn run(self) -> usize {
        (self.place_and_run & (FOLLOWS - 1)) as usize
    }

    /// Whether this run's cell is the one after the last run's (modulo 256).
    #[inline(always)]
    fn follows(self) -> bool {
        self.place_and_run & FOLLOWS != 0
    }
}

/// A row's sums of octaves across a block, a column each, in 2⁻³²: the coarse octaves'
/// terms in 64 bits, the fine ones' in 32 (from [`Ladder::narrow_from`] on), read
/// together so that no pass adds the two; with the buffer of an octave's samples, kept
/// from row to row so that no row clears it.
pub(super) struct RowSums {
    wide: [i64; BLOCK_COLUMNS],
    narrow: [i32; BLOCK_COLUMNS],
    samples: [i32; BLOCK_COLUMNS],
}

impl RowSums {
    /// No sums yet.
    pub(super) const ZERO: Self = Self {
        wide: [0; BLOCK_COLUMNS],
        narrow: [0; BLOCK_COLUMNS],
        samples: [0; BLOCK_COLUMNS],
    };

    /// Each column's sum, the block's columns first (past them, what a last row left).
    #[inline(always)]
    pub(super) fn iter(&self) -> impl Iterator<Item = i64> + '_ {
        let parts = self.wide.iter().zip(&self.narrow);
        parts.map(|(&wide, &narrow)| wide + i64::from(narrow))
    }
}

/// The x parts of up to [`BLOCK_COLUMNS`] columns, octave by octave, for sums whose
/// octaves double (lacunarity 2), in the plane or at one depth of 3D noise.
pub(super) struct ColumnBlock {
    parts: [[BlockColumn; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
    cells: [[u8; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
    columns: usize,
    /// The noise's corner gradients in 2D, looked up once a cell edge.
    gradients: GradientTable,
}

impl ColumnBlock {
    /// A block of no columns yet, for sums of any noise: [`set_noise`](Self::set_noise) names one.
    pub(super) const EMPTY: Self = Self {
        parts: [[BlockColumn::ZERO; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
        cells: [[0; BLOCK_COLUMNS]; MAX_OCTAVES as usize],
        columns: 0,
        gradients: GradientTable::EMPTY,
    };

    /// Makes the block's sums those of `noise` (its gradient table, in place).
    pub(super) fn set_noise(&mut self, noise: &Perlin) {
        self.gradients.fill(noise);
    }

    /// Takes the columns at `xs` (the first [`BLOCK_COLUMNS`] of them). Each octave
    /// doubles the last one's coordinate: `xs` must be points whose finest octave stays in
    /// `Real`'s range, as a texture's fit checks.
    pub(super) fn fill(&mut self, ladder: &Ladder, xs: &[Real]) {
        let columns = xs.len().min(BLOCK_COLUMNS);
        let octaves = ladder.amplitudes().len();
        let rows = self.parts.iter_mut().zip(&mut self.cells).take(octaves);
        for (octave, (parts, cells)) in rows.enumerate() {
            let slots = parts.iter_mut().zip(cells.iter_mut());
            for ((slot, cell), x) in slots.zip(xs).take(columns) {
                // Doubled once an octave; in range: see above.
                let x = Real::from_bits(x.to_bits().wrapping_shl(octave as u32));
                let part = ColumnPart::of(x);
                *slot = BlockColumn {
                    place_and_run: part.place(),
                    fade: part.fade(),
                };
                // A cell is 0 to 255.
                *cell = part.cell() as u8;
            }
            // Each run's first column counts it (at most BLOCK_COLUMNS: below FOLLOWS) and
            // says whether its cell follows the last run's.
            let (mut first, mut last) = (0, None::<u8>);
            for (column, &cell) in cells.iter().enumerate().take(columns) {
                if last != Some(cell) {
                    let follows = last.is_some_and(|last| last.wrapping_add(1) == cell);
                    if let Some(slot) = parts.get_mut(column) {
                        slot.place_and_run |= if follows { FOLLOWS } else { 0 };
                    }
                    (first, last) = (column, Some(cell));
                }
                if let Some(slot) = parts.get_mut(first) {
                    slot.place_and_run += 1;
                }
            }
        }
        self.columns = columns;
    }

    /// Each column's sum of the octaves of `noise` (of |noise| for `turbulence`) at the
    /// row whose y parts are `rows`, in 2⁻³², written to `sums`: the same values as the
    /// ladder's sum at each point, octave by octave along the block, a cell's corners
    /// taken once for the columns that share it.
    pub(super) fn sums(
        &self,
        noise: &Perlin,
        ladder: &Ladder,
        rows: &[RowPart; MAX_OCTAVES as usize],
        turbulence: bool,
        sums: &mut RowSums,
    ) {
        if turbulence {
            self.sums_of::<true>(noise, ladder, rows, sums);
        } else {
            self.sums_of::<false>(noise, ladder, rows, sums);
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
        sums: &mut RowSums,
    ) {
        let block = sums.wide.get_mut(..self.columns).unwrap_or(&mut []);
        block.fill(0);
        // No narrow octaves in 3D: the sums are the wide ones.
        sums.narrow
            .get_mut(..self.columns)
            .unwrap_or(&mut [])
            .fill(0);
        // All ones to take |noise|: x ^ −1 − (−1) = −x for a negative sample.
        let absolute = -i32::from(turbulence);
        let octaves = self.parts.iter().zip(&self.cells).zip(rows).zip(layers);
        for ((((parts, cells), &row), &layer), &amplitude) in octaves.zip(ladder.amplitudes()) {
            // The first column takes its cell's corners.
            let mut corners = CubeCorners::NONE;
            for ((total, &column), &cell) in block.iter_mut().zip(parts).zip(cells) {
                if column.run() > 0 {
                    corners = noise.cube_corners(i32::from(cell), row, layer);
                }
                let value = corners.sample(column.place(), column.fade, row, layer).0;
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
        sums: &mut RowSums,
    ) {
        let columns = self.columns;
        let block = sums.wide.get_mut(..columns).unwrap_or(&mut []);
        // The finer octaves' terms, summed in 32 bits (see `Ladder::narrow_from`).
        let narrow = sums.narrow.get_mut(..columns).unwrap_or(&mut []);
        // Each sum starts as its first octave's terms; one no octave adds to is 0.
        let narrow_from = ladder.narrow_from();
        if narrow_from == 0 {
            block.fill(0);
        }
        if narrow_from >= ladder.weights().len() {
            narrow.fill(0);
        }
        let samples = sums.samples.get_mut(..columns).unwrap_or(&mut []);
        let octaves = self.parts.iter().zip(&self.cells).zip(rows);
        for (octave, (((parts, cells), &row), &weight)) in octaves.zip(ladder.weights()).enumerate()
        {
            sample_octave((noise, &self.gradients), (parts, cells), row, samples);
            // One loop for each kind of weight and width: chosen once an octave.
            let samples = &*samples;
            let first = octave == 0 || octave == narrow_from;
            let sums = (&mut *block, &mut *narrow, octave < narrow_from, first);
            match weight {
                Weight::Eighths(m) => {
                    add_octave::<ABSOLUTE>(samples, sums, |value| Weight::Eighths(m).term(value))
                }
                Weight::Halving(k) => {
                    add_octave::<ABSOLUTE>(samples, sums, |value| Weight::Halving(k).term(value))
                }
                Weight::Any(a) => {
                    add_octave::<ABSOLUTE>(samples, sums, |value| Weight::Any(a).term(value))
                }
            }
        }
    }
}

/// Adds one octave's terms (`term` of each of its `samples`, of |sample| where
/// `ABSOLUTE`) to the columns' 64-bit `totals` where `wide`, otherwise to their 32-bit
/// `narrow` sums (the octaves from [`Ladder::narrow_from`] on, whose terms' magnitudes
/// together stay below 2³¹: the same sums, in one word); or, for the `first` octave of
/// either, writes them.
#[inline(always)]
fn add_octave<const ABSOLUTE: bool>(
    samples: &[i32],
    (totals, narrow, wide, first): (&mut [i64], &mut [i32], bool, bool),
    term: impl Fn(Sample) -> i64,
) {
    if wide {
        add_terms::<ABSOLUTE, _>(samples, totals, first, term);
    } else {
        // Within ±2³¹ (see above): the low word is the term.
        add_terms::<ABSOLUTE, _>(samples, narrow, first, |value| term(value) as i32);
    }
}

/// Adds `term` of each of `samples` (of |sample| where `ABSOLUTE`) to `sums`, or writes
/// it where `first`: each term within ±2, 16 of them, so no sum overflows.
#[inline(always)]
fn add_terms<const ABSOLUTE: bool, T: AddAssign>(
    samples: &[i32],
    sums: &mut [T],
    first: bool,
    term: impl Fn(Sample) -> T,
) {
    let terms = samples.iter().map(|&value| {
        let value = if ABSOLUTE { value.abs() } else { value };
        term(Sample(value))
    });
    if first {
        for (sum, term) in sums.iter_mut().zip(terms) {
            *sum = term;
        }
    } else {
        for (sum, term) in sums.iter_mut().zip(terms) {
            *sum += term;
        }
    }
}

/// The noise at each of the block's columns in the row whose part is `row` (`parts` and
/// `cells` the columns' x parts and cells at one octave), written to `samples`: cell by
/// cell, the first column of each run taking its cell's corners for the run.
#[inline(always)]
fn sample_octave(
    (noise, gradients): (&Perlin, &GradientTable),
    (parts, cells): (&[BlockColumn; BLOCK_COLUMNS], &[u8; BLOCK_COLUMNS]),
    row: RowPart,
    samples: &mut [i32],
) {
    let mut corners = CellCorners::NONE;
    let mut columns = parts.iter().zip(cells).zip(samples);
    while let Some(((head, &cell), value)) = columns.next() {
        let cell = i32::from(cell);
        // A cell after the last one shares its left edge with the last one's right.
        corners = if head.follows() {
            noise.next_corners(&corners, cell, row, gradients)
        } else {
            noise.corners(cell, row, gradients)
        };
        *value = corners.sample(head.place(), head.fade).0;
        // The rest of the run: their places' low bits are clear.
        let rest = head.run().saturating_sub(1);
        for ((part, _), value) in columns.by_ref().take(rest) {
            *value = corners.sample(part.place_and_run, part.fade).0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The block is the 5 KiB its documentation and the drawing's state: 4.5 KiB of
    /// columns' parts and cells, and the 512-byte gradient table.
    #[test]
    fn a_block_is_five_kib() {
        let parts = MAX_OCTAVES as usize * BLOCK_COLUMNS * (8 + 1);
        assert_eq!(parts, 4608);
        assert_eq!(size_of::<GradientTable>(), 512);
        assert_eq!(size_of::<ColumnBlock>(), parts + 512 + size_of::<usize>());
    }
}
