//! The grid a reaction runs on: the caller's cells, a ring of three rows, and the step.

use crate::error::{Error, FitError, ParameterError};
use crate::math::Generator;

use super::model::{Coefficients, GrayScott, COEFFICIENT_BITS, ONE};

/// One cell of the grid: the concentrations of A and B, each a multiple of 2⁻¹⁵ in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Cell {
    /// Chemical A (the substrate), 1.0 = [`ONE`].
    pub a: u16,
    /// Chemical B (the catalyst), 1.0 = [`ONE`].
    pub b: u16,
}

impl Cell {
    /// The homogeneous state, A = 1 and B = 0: a fixed point of every step.
    pub const REST: Self = Self { a: ONE, b: 0 };
}

impl Default for Cell {
    fn default() -> Self {
        Self::REST
    }
}

/// How a reaction starts: A = 1 everywhere and B = 0, except where B is seeded to 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Start {
    /// B = 1 in a centred square of side ⌊min(W, H)/8⌋ (at least 1 cell).
    Square,
    /// B = 1 in max(1, ⌊W·H/2048⌋) squares of side max(1, ⌊min(W, H)/16⌋), each placed at a
    /// seeded position (its top-left cell at (r₁ mod W, r₂ mod H) for two numbers of the
    /// seeded generator, wrapping at the edges).
    Spots {
        /// The generator's seed.
        seed: u64,
    },
}

/// A Gray–Scott reaction on the caller's grid of `width × height` [`Cell`]s, stepped in
/// place from a main loop.
///
/// Memory: the caller gives the cells (4 bytes each) and a ring of three rows
/// ([`Reaction::ring_len`] cells, 12 bytes a column); the reaction itself is under 100
/// bytes. A step reads each cell's old neighbours from the ring, so it needs no second copy
/// of the grid.
///
/// Arithmetic: every cell changes by an integer sum in units of 2⁻³⁰ (products of the
/// cells and the rates, each rate rounded to 2⁻¹⁵, in 32 bits), rounded down to the cell's
/// 2⁻¹⁵ with the remainder carried to the next cell in row order (error diffusion), then
/// clamped to [0, 1] as the [model](GrayScott) says. The carry makes a step keep any total
/// the equations keep: a pure-diffusion step leaves the grid's sum of A (and of B) exactly
/// as it was (rounding towards the neighbours' range never leaves it, so the clamp never
/// acts there).
#[derive(Debug)]
pub struct Reaction<'a> {
    width: u32,
    height: u32,
    cells: &'a mut [Cell],
    ring: &'a mut [Cell],
    coefficients: Coefficients,
    steps: u64,
}

impl<'a> Reaction<'a> {
    /// The narrowest and lowest grid: the kernel reaches one cell each way.
    pub const MIN_SIDE: u32 = 3;
    /// The widest and highest grid.
    pub const MAX_SIDE: u32 = 4096;

    /// Cells the ring of rows needs for a grid `width` cells wide: three rows.
    pub const fn ring_len(width: u32) -> usize {
        3 * width as usize
    }

    /// A reaction of `model` on `cells` (row by row, the first `width × height` used),
    /// with `ring` for the rows a step keeps. The cells are set to the rest state (A = 1,
    /// B = 0); seed B with [`start`](Self::start). Refuses rates the step cannot take
    /// stably, a side out of range and buffers too small.
    pub fn new(
        model: &GrayScott,
        (width, height): (u32, u32),
        cells: &'a mut [Cell],
        ring: &'a mut [Cell],
    ) -> Result<Self, Error> {
        let coefficients = model.coefficients()?;
        let side = Self::MIN_SIDE..=Self::MAX_SIDE;
        if !side.contains(&width) || !side.contains(&height) {
            return Err(Error::Parameter(ParameterError::GridOutOfRange {
                width,
                height,
                min: Self::MIN_SIDE,
                max: Self::MAX_SIDE,
            }));
        }
        let needed = width as usize * height as usize;
        let too_small = |needed, given| Error::Fit(FitError::BufferTooSmall { needed, given });
        let (given, ring_len, ring_given) = (cells.len(), Self::ring_len(width), ring.len());
        let cells = cells.get_mut(..needed).ok_or(too_small(needed, given))?;
        let ring = ring
            .get_mut(..ring_len)
            .ok_or(too_small(ring_len, ring_given))?;
        cells.fill(Cell::REST);
        Ok(Self {
            width,
            height,
            cells,
            ring,
            coefficients,
            steps: 0,
        })
    }

    /// The grid's width and height in cells.
    pub const fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Steps taken since the reaction was made.
    pub const fn steps(&self) -> u64 {
        self.steps
    }

    /// The cells, row by row.
    pub fn cells(&self) -> &[Cell] {
        self.cells
    }

    /// The cells, row by row, to set a state of one's own.
    pub fn cells_mut(&mut self) -> &mut [Cell] {
        self.cells
    }

    /// The cell at column `x`, row `y`; `None` outside the grid.
    pub fn cell(&self, x: u32, y: u32) -> Option<Cell> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.cells
            .get(y as usize * self.width as usize + x as usize)
            .copied()
    }

    /// Resets the grid to rest and seeds B as `start` says.
    pub fn start(&mut self, start: Start) {
        self.cells.fill(Cell::REST);
        let (w, h) = (self.width, self.height);
        match start {
            Start::Square => {
                let side = (w.min(h) / 8).max(1);
                self.seed_square((w - side) / 2, (h - side) / 2, side);
            }
            Start::Spots { seed } => {
                let mut random = Generator::new(seed);
                let count = (w as usize * h as usize / 2048).max(1);
                let side = (w.min(h) / 16).max(1);
                for _ in 0..count {
                    let x = random.next_u32() % w;
                    let y = random.next_u32() % h;
                    self.seed_square(x, y, side);
                }
            }
        }
    }

    /// B = 1 in the square of `side` cells with top-left cell (`x`, `y`), wrapping.
    fn seed_square(&mut self, x: u32, y: u32, side: u32) {
        let (w, h) = (self.width, self.height);
        for dy in 0..side {
            for dx in 0..side {
                let index = ((y + dy) % h) as usize * w as usize + ((x + dx) % w) as usize;
                if let Some(cell) = self.cells.get_mut(index) {
                    cell.b = ONE;
                }
            }
        }
    }

    /// Takes `steps` steps of the model.
    pub fn step(&mut self, steps: u32) {
        for _ in 0..steps {
            self.one_step();
        }
    }

    fn one_step(&mut self) {
        let w = self.width as usize;
        let h = self.height as usize;
        let mut ring = self.ring.chunks_exact_mut(w);
        let (Some(first), Some(mut above), Some(mut centre)) =
            (ring.next(), ring.next(), ring.next())
        else {
            return;
        };
        // The rows the first and last rows see across the edge, before they change.
        let (Some(top), Some(bottom)) = (self.cells.get(..w), self.cells.get((h - 1) * w..)) else {
            return;
        };
        first.copy_from_slice(top);
        above.copy_from_slice(bottom);
        let mut carry = Carry::default();
        // Each row is updated in place, its old values kept in the ring's `centre` as the
        // update passes them: the next row's `above`.
        for y in 0..h {
            let (head, tail) = self.cells.split_at_mut((y + 1) * w);
            let (Some(row), Some(below)) = (head.get_mut(y * w..), tail.get(..w)) else {
                // The last row: the first row below it, as it was.
                if let Some(row) = head.get_mut(y * w..) {
                    update_row(above, row, first, centre, &self.coefficients, &mut carry);
                }
                break;
            };
            update_row(above, row, below, centre, &self.coefficients, &mut carry);
            core::mem::swap(&mut above, &mut centre);
        }
        self.steps += 1;
    }
}

/// The remainders (below a cell's 2⁻¹⁵, in units of 2⁻³⁰) carried to the next cell, one
/// for each chemical.
#[derive(Debug, Default, Clone, Copy)]
struct Carry {
    a: i32,
    b: i32,
}

/// A column of a cell's 3×3 neighbourhood, as the step needs it.
///
/// The kernel is separable: 20·∇² = [1 4 1]ᵀ·[1 4 1] − 36·centre, so a column contributes
/// its weighted sum `up + 4·centre + down` once, whichever neighbour it is.
#[derive(Debug, Clone, Copy)]
struct Column {
    /// A above + 4 × A at the centre row + A below.
    sum_a: i32,
    /// The same for B.
    sum_b: i32,
    /// A in the centre row.
    a: i32,
    /// B in the centre row.
    b: i32,
}

impl Column {
    #[inline(always)]
    fn of(above: Cell, centre: Cell, below: Cell) -> Self {
        let (a, b) = (i32::from(centre.a), i32::from(centre.b));
        Self {
            sum_a: i32::from(above.a) + 4 * a + i32::from(below.a),
            sum_b: i32::from(above.b) + 4 * b + i32::from(below.b),
            a,
            b,
        }
    }
}

/// Updates `row` to its next state from the old rows `above` and `below` and its own old
/// values (all one width long, wrapping at the row's ends), keeping those old values in
/// `kept` as it goes.
fn update_row(
    above: &[Cell],
    row: &mut [Cell],
    below: &[Cell],
    kept: &mut [Cell],
    coefficients: &Coefficients,
    carry: &mut Carry,
) {
    // Δt = 1, every preset's: a product fewer a cell, and a rate fewer to hold.
    if coefficients.dt == i32::from(ONE) {
        row_loop::<true>(above, row, below, kept, coefficients, carry);
    } else {
        row_loop::<false>(above, row, below, kept, coefficients, carry);
    }
}

// The row loop this core takes: a chemical at a time where the core has registers for it;
// on ARMv6-M's eight the one-pass loop spills less than two passes do. The same cells.
#[cfg(not(tinyfractal_few_registers))]
use self::update_row_by_chemical as row_loop;
#[cfg(tinyfractal_few_registers)]
use self::update_row_with as row_loop;

/// [`update_row`], with Δt = 1 known where `UNIT_DT`.
///
/// A cell is written once its right neighbour's old value has been read (and kept), so
/// the row needs no copy of its own; the first column, the last cell's right neighbour, is
/// taken before anything is written.
#[cfg_attr(not(tinyfractal_few_registers), allow(dead_code))]
#[inline(never)]
fn update_row_with<const UNIT_DT: bool>(
    above: &[Cell],
    row: &mut [Cell],
    below: &[Cell],
    kept: &mut [Cell],
    coefficients: &Coefficients,
    carry: &mut Carry,
) {
    let column_at = |x: usize| {
        let cell = |row: &[Cell]| row.get(x).copied().unwrap_or(Cell::REST);
        Column::of(cell(above), cell(row), cell(below))
    };
    let width = row.len();
    let first = column_at(0);
    let mut left = column_at(width.wrapping_sub(1));
    let mut here = first;
    if let (Some(kept), Some(&old)) = (kept.first_mut(), row.first()) {
        *kept = old;
    }
    // In locals, so that they live in registers through the row.
    let c = *coefficients;
    let (mut carry_a, mut carry_b) = (carry.a, carry.b);
    // Three cells a turn, so that the columns change roles in the code rather than move
    // from one variable to another at every cell (indices, not `chunks_exact`, whose
    // division by 3 is a library call on cores without a divide).
    let mut x = 0;
    while let (Some([o0, o1, o2, o3]), Some([k1, k2, k3]), Some([u1, u2, u3]), Some([d1, d2, d3])) = (
        row.get_mut(x..x + 4),
        kept.get_mut(x + 1..x + 4),
        above.get(x + 1..x + 4),
        below.get(x + 1..x + 4),
    ) {
        let (m1, m2, m3) = (*o1, *o2, *o3);
        (*k1, *k2, *k3) = (m1, m2, m3);
        let r1 = Column::of(*u1, m1, *d1);
        *o0 = next_cell::<UNIT_DT>(left, here, r1, &c, (&mut carry_a, &mut carry_b));
        let r2 = Column::of(*u2, m2, *d2);
        *o1 = next_cell::<UNIT_DT>(here, r1, r2, &c, (&mut carry_a, &mut carry_b));
        let r3 = Column::of(*u3, m3, *d3);
        *o2 = next_cell::<UNIT_DT>(r1, r2, r3, &c, (&mut carry_a, &mut carry_b));
        left = r2;
        here = r3;
        x += 3;
    }
    while let (Some([o0, o1]), Some(k1), Some(&u1), Some(&d1)) = (
        row.get_mut(x..x + 2),
        kept.get_mut(x + 1),
        above.get(x + 1),
        below.get(x + 1),
    ) {
        let m1 = *o1;
        *k1 = m1;
        let right = Column::of(u1, m1, d1);
        *o0 = next_cell::<UNIT_DT>(left, here, right, &c, (&mut carry_a, &mut carry_b));
        left = here;
        here = right;
        x += 1;
    }
    // The last cell's right neighbour is the first column.
    if let Some(last) = row.get_mut(x) {
        *last = next_cell::<UNIT_DT>(left, here, first, &c, (&mut carry_a, &mut carry_b));
    }
    *carry = Carry {
        a: carry_a,
        b: carry_b,
    };
}

/// [`update_row_with`] in two passes over the row, one for each chemical, so that a
/// cell's loop holds half as many values: the row's old values are copied to `kept`
/// first, and each pass reads only old values. The same cells and carries, since the two
/// chemicals' remainders are carried apart anyway.
#[cfg_attr(tinyfractal_few_registers, allow(dead_code))]
#[inline(never)]
fn update_row_by_chemical<const UNIT_DT: bool>(
    above: &[Cell],
    row: &mut [Cell],
    below: &[Cell],
    kept: &mut [Cell],
    coefficients: &Coefficients,
    carry: &mut Carry,
) {
    let width = row.len();
    let (Some(kept), Some(above), Some(below)) = (
        kept.get_mut(..width),
        above.get(..width),
        below.get(..width),
    ) else {
        return;
    };
    kept.copy_from_slice(row);
    let c = *coefficients;
    carry.a = chemical_pass::<UNIT_DT, false>([above, kept, below], row, &c, carry.a);
    carry.b = chemical_pass::<UNIT_DT, true>([above, kept, below], row, &c, carry.b);
}

/// One chemical's pass of [`update_row_by_chemical`] (B's where `B`): each cell's value
/// in `row` from the old rows `above`, `kept` (the row's own) and `below`; returns the
/// carry.
#[inline(always)]
fn chemical_pass<const UNIT_DT: bool, const B: bool>(
    [above, kept, below]: [&[Cell]; 3],
    row: &mut [Cell],
    c: &Coefficients,
    mut carry: i32,
) -> i32 {
    let of = |cell: &Cell| i32::from(if B { cell.b } else { cell.a });
    let old = |cell: Cell| (i32::from(cell.a), i32::from(cell.b));
    let sum_at = |x: usize| {
        let cell = |row: &[Cell]| row.get(x).map_or(0, of);
        cell(above) + 4 * cell(kept) + cell(below)
    };
    let first = sum_at(0);
    let mut left = sum_at(row.len().wrapping_sub(1));
    let mut here = first;
    let mut centre = kept.first().copied().unwrap_or(Cell::REST);
    let set = |out: &mut Cell, value: u16| {
        if B {
            out.b = value;
        } else {
            out.a = value;
        }
    };
    let columns = above.iter().zip(kept).zip(below).skip(1);
    for (out, ((up, middle), down)) in row.iter_mut().zip(columns) {
        let right = of(up) + 4 * of(middle) + of(down);
        set(
            out,
            next_chemical::<UNIT_DT, B>(left, here, right, old(centre), c, &mut carry),
        );
        (left, here, centre) = (here, right, *middle);
    }
    // The last cell's right neighbour is the first column.
    if let Some(out) = row.last_mut() {
        set(
            out,
            next_chemical::<UNIT_DT, B>(left, here, first, old(centre), c, &mut carry),
        );
    }
    carry
}

/// One chemical's next value (B's where `B`) at a cell whose old values are `(a, b)`,
/// from its column's weighted sum and its neighbours' (see [`Column`]): what
/// [`next_cell`] gives that chemical.
#[inline(always)]
fn next_chemical<const UNIT_DT: bool, const B: bool>(
    left: i32,
    here: i32,
    right: i32,
    (a, b): (i32, i32),
    c: &Coefficients,
    carry: &mut i32,
) -> u16 {
    let laplacian = left + right + 4 * here - 36 * if B { b } else { a };
    let reaction = reaction::<UNIT_DT>(a, b, c);
    if B {
        settle(b, c.diffusion_b * laplacian + reaction - c.decay * b, carry)
    } else {
        let feed = c.feed * (i32::from(ONE) - a);
        settle(a, c.diffusion_a * laplacian - reaction + feed, carry)
    }
}

/// One cell's next state from its column and the columns left and right of it.
///
/// Every product fits 32 bits: a cell is at most 2¹⁵ (1.0), each rate at most 2¹⁵ (D·Δt/20
/// at most 1638), 20·∇² within ±20·2¹⁵; so each term is within ±2³⁰, and the sums for A
/// and for B, with the carry, within ±2³¹ (the checks in [`GrayScott`] keep them there).
/// Both chemicals in one expression: built from [`next_chemical`] twice, ARMv6-M's loop,
/// the one that takes this, is scheduled worse.
#[inline(always)]
fn next_cell<const UNIT_DT: bool>(
    left: Column,
    here: Column,
    right: Column,
    c: &Coefficients,
    (carry_a, carry_b): (&mut i32, &mut i32),
) -> Cell {
    // 20·∇² exactly: 4 × (the four edges) + (the four corners) − 20 × the centre.
    let laplacian_a = left.sum_a + right.sum_a + 4 * here.sum_a - 36 * here.a;
    let laplacian_b = left.sum_b + right.sum_b + 4 * here.sum_b - 36 * here.b;
    let reaction = reaction::<UNIT_DT>(here.a, here.b, c);
    let change_a = c.diffusion_a * laplacian_a - reaction + c.feed * (i32::from(ONE) - here.a);
    let change_b = c.diffusion_b * laplacian_b + reaction - c.decay * here.b;
    Cell {
        a: settle(here.a, change_a, carry_a),
        b: settle(here.b, change_b, carry_b),
    }
}

/// The reaction AB²·Δt in Q30 at a cell of old values `a` and `b`: A·B rounded to Q15,
/// times Δt rounded to Q15 (exact when Δt is 1, `UNIT_DT`), times B.
#[inline(always)]
fn reaction<const UNIT_DT: bool>(a: i32, b: i32, c: &Coefficients) -> i32 {
    let half = 1 << (CELL_BITS - 1);
    let ab = (a * b + half) >> CELL_BITS;
    // With Δt = 1 (2¹⁵) the rounding of ab·Δt leaves ab as it was.
    let ab_dt = if UNIT_DT {
        ab
    } else {
        (ab * c.dt + half) >> COEFFICIENT_BITS
    };
    ab_dt * b
}

/// `value` plus `change` (in units of 2⁻³⁰), rounded down to 2⁻¹⁵ with the remainder
/// carried on, clamped to [0, 1].
#[inline(always)]
fn settle(value: i32, change: i32, carry: &mut i32) -> u16 {
    // The change is within ±(2³¹ − 2¹⁵) (see `next_cell`) and the carry below 2¹⁵.
    let total = change + *carry;
    *carry = total & ((1 << COEFFICIENT_BITS) - 1);
    let next = value + (total >> COEFFICIENT_BITS);
    next.clamp(0, i32::from(ONE)) as u16
}

/// Fraction bits of a cell.
const CELL_BITS: u32 = super::model::CELL_FRAC_BITS;

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::reaction::Preset;
    use std::vec;
    use std::vec::Vec;

    /// A row step's signature, to compare two of them.
    type RowStep = fn(&[Cell], &mut [Cell], &[Cell], &mut [Cell], &Coefficients, &mut Carry);

    /// Steps the middle one of three random rows of every width in `widths` by `first` and
    /// by `second` and asserts that both write the same cells, carry the same remainders
    /// and keep the row's old values whole; and that the row changed.
    fn assert_same_rows(
        (first, second): (RowStep, RowStep),
        coefficients: &Coefficients,
        widths: &[usize],
        random: &mut Generator,
    ) {
        let mut cell = || Cell {
            a: (random.next_u32() % (u32::from(ONE) + 1)) as u16,
            b: (random.next_u32() % (u32::from(ONE) + 1)) as u16,
        };
        for &width in widths {
            let rows: [Vec<Cell>; 3] =
                core::array::from_fn(|_| (0..width).map(|_| cell()).collect());
            let [above, centre, below] = &rows;
            let start = Carry {
                a: 4_567,
                b: 30_001,
            };
            let (mut rows, mut kept, mut carries) = (
                [centre.clone(), centre.clone()],
                [vec![Cell::REST; width], vec![Cell::REST; width]],
                [start, start],
            );
            for (step, ((row, kept), carry)) in [first, second]
                .into_iter()
                .zip(rows.iter_mut().zip(&mut kept).zip(&mut carries))
            {
                step(above, row, below, kept, coefficients, carry);
            }
            let case = (coefficients, width);
            assert_ne!(&rows[0], centre, "{case:?}");
            assert_eq!(rows[0], rows[1], "{case:?}");
            let [one, two] = carries.map(|carry| (carry.a, carry.b));
            assert_eq!(one, two, "{case:?}");
            assert_eq!(&kept[0], centre, "{case:?}");
            assert_eq!(&kept[1], centre, "{case:?}");
        }
    }

    /// The row step that knows Δt = 1 writes the cells and carries the remainders the
    /// general one does with Δt = 1, for every preset, on random rows of random widths
    /// (each width modulo 3, as the one-pass step takes three cells a turn), in both
    /// loops.
    #[test]
    fn unit_time_step_is_the_general_step_at_one() {
        let mut random = Generator::new(11);
        for preset in Preset::ALL {
            let coefficients = preset.model().coefficients().unwrap();
            assert_eq!(coefficients.dt, i32::from(ONE));
            let widths = [3, 4, 5, 7, 24, 33];
            let one_pass: (RowStep, RowStep) = (update_row_with::<false>, update_row_with::<true>);
            assert_same_rows(one_pass, &coefficients, &widths, &mut random);
            let by_chemical: (RowStep, RowStep) = (
                update_row_by_chemical::<false>,
                update_row_by_chemical::<true>,
            );
            assert_same_rows(by_chemical, &coefficients, &widths, &mut random);
        }
    }

    /// A chemical at a time, as most cores step, writes the cells, carries and kept
    /// values of the one-pass loop ARMv6-M takes, for every preset and a time step below
    /// 1, on random rows of random widths.
    #[test]
    fn both_row_loops_give_the_same_cells() {
        let mut random = Generator::new(29);
        let mut slow = Preset::Mitosis.model();
        slow.dt = crate::math::Real::from_ratio(73, 100).unwrap();
        let models = Preset::ALL
            .iter()
            .map(|preset| preset.model())
            .chain([slow]);
        for model in models {
            let coefficients = model.coefficients().unwrap();
            let loops: (RowStep, RowStep) = if coefficients.dt == i32::from(ONE) {
                (update_row_with::<true>, update_row_by_chemical::<true>)
            } else {
                (update_row_with::<false>, update_row_by_chemical::<false>)
            };
            let widths = [3, 4, 5, 6, 7, 8, 24, 33, 64];
            assert_same_rows(loops, &coefficients, &widths, &mut random);
        }
    }
}
