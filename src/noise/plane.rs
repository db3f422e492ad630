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
        // Column by column, so that each octave's coordinate is the last one's doubled (a
        // 64-bit shift by a count is a library call on ARMv6-M).
        for (column, x) in xs.iter().enumerate().take(columns) {
            let mut bits = x.to_bits();
            for (parts, cells) in self.parts.iter_mut().zip(&mut self.cells).take(octaves) {
                let part = ColumnPart::of(Real::from_bits(bits));
                if let (Some(slot), Some(cell)) = (parts.get_mut(column), cells.get_mut(column)) {
                    *slot = BlockColumn {
                        place_and_run: part.place(),
                        fade: part.fade(),
                    };
                    // A cell is 0 to 255.
                    *cell = part.cell() as u8;
                }
                // In range: see above.
                bits = bits.wrapping_add(bits);
            }
        }
        for (parts, cells) in self.parts.iter_mut().zip(&mut self.cells).take(octaves) {
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
        // Where there is no long multiply, coarse octaves that are all eighths (fBm's) sum
        // as halves (`add_eighths_in_halves`).
        let halves = EIGHTHS_IN_HALVES
            && ladder
                .weights()
                .get(..narrow_from)
                .is_some_and(|coarse| coarse.iter().all(|w| matches!(w, Weight::Eighths(_))));
        let octaves = self.parts.iter().zip(&self.cells).zip(rows);
        for (octave, (((parts, cells), &row), &weight)) in octaves.zip(ladder.weights()).enumerate()
        {
            sample_octave((noise, &self.gradients), (parts, cells), row, samples);
            // One loop for each kind of weight and width: chosen once an octave.
            let samples = &*samples;
            if let (true, true, Weight::Eighths(m)) = (halves, octave < narrow_from, weight) {
                let (first, last) = (octave == 0, octave + 1 == narrow_from);
                add_eighths_in_halves::<ABSOLUTE>(samples, block, m, first, last);
                continue;
            }
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

/// Whether a block sums coarse octaves of eighths in halves ([`add_eighths_in_halves`]):
/// where there is no long multiply (ARMv6-M), since there a 64-bit term and its 64-bit
/// sum cost several 32-bit ones (measured in docs/performance.md, The textures against
/// the loops a user writes).
const EIGHTHS_IN_HALVES: bool = cfg!(tinyfractal_no_long_multiply);

/// Adds an octave of weight m/8 (of |sample| where `ABSOLUTE`) to the coarse `totals` in
/// halves: each term m·s as (m·sₕ)·2¹⁶ + m·sₗ for s = sₕ·2¹⁶ + sₗ, the two parts summed in
/// the total's two words apart (a coarse octave's sₕ within ±2¹³·¹, m at most 8, at most
/// 16 octaves: far within 32 bits each), from the `first` octave on; the `last` puts the
/// parts together as the 64-bit total. The same sums as the terms' 64-bit ones.
#[inline(always)]
fn add_eighths_in_halves<const ABSOLUTE: bool>(
    samples: &[i32],
    totals: &mut [i64],
    m: i32,
    first: bool,
    last: bool,
) {
    match (first, last) {
        (true, true) => add_halves::<ABSOLUTE, true, true>(samples, totals, m),
        (true, false) => add_halves::<ABSOLUTE, true, false>(samples, totals, m),
        (false, true) => add_halves::<ABSOLUTE, false, true>(samples, totals, m),
        (false, false) => add_halves::<ABSOLUTE, false, false>(samples, totals, m),
    }
}

/// [`add_eighths_in_halves`] with its place among the coarse octaves known: the parts
/// kept as a total's high word (m·sₕ's) and low word (m·sₗ's) until the `LAST`.
#[inline(always)]
fn add_halves<const ABSOLUTE: bool, const FIRST: bool, const LAST: bool>(
    samples: &[i32],
    totals: &mut [i64],
    m: i32,
) {
    for (total, &value) in totals.iter_mut().zip(samples) {
        let value = if ABSOLUTE { value.abs() } else { value };
        let (mut high, mut low) = if FIRST {
            (0, 0)
        } else {
            ((*total >> 32) as i32, *total as i32)
        };
        high += (value >> 16) * m;
        low += (value & 0xFFFF) * m;
        *total = if LAST {
            // high·2¹⁶ + low in two words (low is at least 0): the low word with its
            // carry, the high word high's upper half.
            let lower = ((high as u32) << 16).wrapping_add(low as u32);
            let upper = (high >> 16) + i32::from(lower < low as u32);
            (i64::from(upper) << 32) | i64::from(lower)
        } else {
            (i64::from(high) << 32) | i64::from(low as u32)
        };
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
///
/// The columns are walked by index where there is no long multiply (ARMv6-M) and by
/// iterators elsewhere: each is the faster there (`boards/profile m0|m3 noise-fbm`; on
/// Cortex-M3 the compiler unrolls an index loop over a run by four, which runs of one to
/// three columns pay for).
#[inline(always)]
fn sample_octave(
    (noise, gradients): (&Perlin, &GradientTable),
    (parts, cells): (&[BlockColumn; BLOCK_COLUMNS], &[u8; BLOCK_COLUMNS]),
    row: RowPart,
    samples: &mut [i32],
) {
    let mut corners = CellCorners::NONE;
    if cfg!(tinyfractal_no_long_multiply) {
        let columns = samples.len().min(BLOCK_COLUMNS);
        let mut column = 0;
        while let (Some(head), Some(&cell)) = (parts.get(column), cells.get(column)) {
            if column >= columns {
                break;
            }
            corners = run_corners((noise, gradients), &corners, (head, cell), row);
            let end = (column + head.run().max(1)).min(columns);
            if let Some(value) = samples.get_mut(column) {
                *value = corners.sample(head.place(), head.fade).0;
            }
            column += 1;
            // The rest of the run: their places' low bits are clear.
            while column < end {
                if let (Some(part), Some(value)) = (parts.get(column), samples.get_mut(column)) {
                    *value = corners.sample(part.place_and_run, part.fade).0;
                }
                column += 1;
            }
        }
    } else {
        let mut columns = parts.iter().zip(cells).zip(samples);
        while let Some(((head, &cell), value)) = columns.next() {
            corners = run_corners((noise, gradients), &corners, (head, cell), row);
            *value = corners.sample(head.place(), head.fade).0;
            // The rest of the run: their places' low bits are clear.
            let rest = head.run().saturating_sub(1);
            for ((part, _), value) in columns.by_ref().take(rest) {
                *value = corners.sample(part.place_and_run, part.fade).0;
            }
        }
    }
}

/// The corners of the run whose first column is `head` and cell `cell`, in `row`: a cell
/// after the `last` run's shares its left edge with the last one's right.
#[inline(always)]
fn run_corners(
    (noise, gradients): (&Perlin, &GradientTable),
    last: &CellCorners,
    (head, cell): (&BlockColumn, u8),
    row: RowPart,
) -> CellCorners {
    let cell = i32::from(cell);
    if head.follows() {
        noise.next_corners(last, cell, row, gradients)
    } else {
        noise.corners(cell, row, gradients)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coarse octaves of eighths summed in halves (ARMv6-M's) are the 64-bit sums of their
    /// terms m·s: for one to sixteen octaves, samples of either sign up to ±2³⁰ (past the
    /// noise's ±1.04·2²⁹), and their magnitudes.
    #[test]
    fn eighths_in_halves_are_the_wide_sums() {
        use proptest::prelude::*;
        let octave = (
            0..=8i32,
            prop::array::uniform32(any::<i32>().prop_map(|v| v >> 1)),
        );
        let octaves = prop::collection::vec(octave, 1..=16);
        proptest::test_runner::TestRunner::deterministic()
            .run(&octaves, |octaves| {
                let last = octaves.len() - 1;
                let (mut signed, mut absolute) = ([0i64; BLOCK_COLUMNS], [0i64; BLOCK_COLUMNS]);
                let (mut expected, mut expected_absolute) = ([0i64; 32], [0i64; 32]);
                for (k, (m, samples)) in octaves.iter().enumerate() {
                    add_eighths_in_halves::<false>(samples, &mut signed, *m, k == 0, k == last);
                    add_eighths_in_halves::<true>(samples, &mut absolute, *m, k == 0, k == last);
                    for (i, &s) in samples.iter().enumerate() {
                        expected[i] += i64::from(*m) * i64::from(s);
                        expected_absolute[i] += i64::from(*m) * i64::from(s.abs());
                    }
                }
                prop_assert_eq!(signed, expected);
                prop_assert_eq!(absolute, expected_absolute);
                Ok(())
            })
            .unwrap();
        // The ends: every sample ±2³⁰, every weight 8, sixteen octaves.
        let mut totals = [0i64; BLOCK_COLUMNS];
        let ends: [i32; BLOCK_COLUMNS] =
            core::array::from_fn(|i| if i % 2 == 0 { 1 << 30 } else { -(1 << 30) });
        for k in 0..16 {
            add_eighths_in_halves::<false>(&ends, &mut totals, 8, k == 0, k == 15);
        }
        assert!(totals
            .iter()
            .zip(&ends)
            .all(|(&t, &s)| t == 128 * i64::from(s)));
    }

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
