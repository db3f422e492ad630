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
        // Δt = 1, every preset's: a product fewer a cell, and a rate fewer to hold.
        if self.coefficients.dt == i32::from(ONE) {
            self.one_step_with::<true>();
        } else {
            self.one_step_with::<false>();
        }
        self.steps += 1;
    }

    /// [`one_step`](Self::one_step) with Δt = 1 known where `UNIT_DT`: every row in one
    /// call. On ARMv6-M the row step is inlined into it, so that the rates are taken once
    /// a step rather than once a row; elsewhere each row's two passes are a call.
    #[inline(never)]
    fn one_step_with<const UNIT_DT: bool>(&mut self) {
        let w = self.width as usize;
        let h = self.height as usize;
        let c = &self.coefficients;
        // Split, not `chunks_exact_mut`, whose division is a library call on cores
        // without a divide.
        let (first, ring) = self.ring.split_at_mut(w.min(self.ring.len()));
        let (kept, spare) = ring.split_at_mut(w.min(ring.len()));
        let (Some(mut kept), Some(mut spare)) = (kept.get_mut(..w), spare.get_mut(..w)) else {
            return;
        };
        let mut carry = Carry::default();
        // Each row is updated in place, its old values kept in the ring as the update
        // passes them: the next row's row above. The first row's are kept apart, as the
        // last row's row below; above the first row is the last, which changes last.
        let (top, rest) = self.cells.split_at_mut(w);
        let (Some(below), Some(bottom)) = (rest.get(..w), rest.get(rest.len().wrapping_sub(w)..))
        else {
            return;
        };
        first_row::<UNIT_DT>(bottom, top, below, first, c, &mut carry);
        let first: &[Cell] = first;
        for y in 1..h {
            let (head, tail) = self.cells.split_at_mut((y + 1) * w);
            let Some(row) = head.get_mut(y * w..) else {
                break;
            };
            let below = tail.get(..w).unwrap_or(first);
            let above: &[Cell] = if y == 1 { first } else { spare };
            row_loop::<UNIT_DT>(above, row, below, kept, c, &mut carry);
            core::mem::swap(&mut kept, &mut spare);
        }
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

/// The row loop for the first row, out of line: inlined twice, the loop of the other
/// rows was scheduled worse.
#[inline(never)]
fn first_row<const UNIT_DT: bool>(
    above: &[Cell],
    row: &mut [Cell],
    below: &[Cell],
    kept: &mut [Cell],
    coefficients: &Coefficients,
    carry: &mut Carry,
) {
    row_loop::<UNIT_DT>(above, row, below, kept, coefficients, carry);
}

// The row loop this core takes: a chemical at a time where the core has registers for it;
// on ARMv6-M's eight the one-pass loop spills less than two passes do. The same cells.
#[cfg(not(tinyfractal_few_registers))]
use self::update_row_by_chemical as row_loop;
#[cfg(tinyfractal_few_registers)]
use self::update_row_with as row_loop;

/// A row's next state from the old rows `above` and `below` and its own old values (all
/// one width long, wrapping at the row's ends), keeping those old values in `kept` as it
/// goes; Δt = 1 known where `UNIT_DT`.
///
/// A cell is written once its right neighbour's old value has been read (and kept), so
/// the row needs no copy of its own; the first column, the last cell's right neighbour, is
/// taken before anything is written.
#[cfg_attr(not(tinyfractal_few_registers), allow(dead_code))]
#[cfg_attr(tinyfractal_few_registers, inline(always))]
fn update_row_with<const UNIT_DT: bool>(
    above: &[Cell],
    row: &mut [Cell],
    below: &[Cell],
    kept: &mut [Cell],
    coefficients: &Coefficients,
    carry: &mut Carry,
) {
    // The rows as long as the row, so that their bounds are checked once.
    let width = row.len();
    let (Some(above), Some(below), Some(kept), Some(&old_first), Some(&old_last)) = (
        above.get(..width),
        below.get(..width),
        kept.get_mut(..width),
        row.first(),
        row.last(),
    ) else {
        return;
    };
    let column_at = |x: usize, old: Cell| {
        let cell = |row: &[Cell]| row.get(x).copied().unwrap_or(Cell::REST);
        Column::of(cell(above), old, cell(below))
    };
    let first = column_at(0, old_first);
    let mut left = column_at(width - 1, old_last);
    let mut here = first;
    if let Some(kept) = kept.first_mut() {
        *kept = old_first;
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
    // A width of a multiple of three ends in a whole turn too, the last cell's right
    // neighbour the first column. Written out rather than shared with the turn above:
    // as one function taking the third column from a closure, ARMv6-M's loop measured
    // slower.
    if let (Some([o0, o1, o2]), Some([k1, k2]), Some([u1, u2]), Some([d1, d2])) = (
        row.get_mut(x..),
        kept.get_mut(x + 1..),
        above.get(x + 1..),
        below.get(x + 1..),
    ) {
        let (m1, m2) = (*o1, *o2);
        (*k1, *k2) = (m1, m2);
        let r1 = Column::of(*u1, m1, *d1);
        *o0 = next_cell::<UNIT_DT>(left, here, r1, &c, (&mut carry_a, &mut carry_b));
        let r2 = Column::of(*u2, m2, *d2);
        *o1 = next_cell::<UNIT_DT>(here, r1, r2, &c, (&mut carry_a, &mut carry_b));
        *o2 = next_cell::<UNIT_DT>(r1, r2, first, &c, (&mut carry_a, &mut carry_b));
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
/// cell's loop holds half as many values: A's pass keeps the row's old values in `kept`
/// as it goes, and B's pass reads only old values. The same cells and carries, since the two
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
    let c = *coefficients;
    carry.a = keeping_pass_a::<UNIT_DT>([above, below], row, kept, &c, carry.a);
    carry.b = chemical_pass::<UNIT_DT, true>([above, kept, below], row, &c, carry.b);
}

/// A's pass of [`update_row_by_chemical`], which also keeps the row's old values in
/// `kept` as it reads them (a copy of the row first cost more on Cortex-M4); returns the
/// carry.
///
/// A cell's A is written once its right neighbour's old value has been read, and the
/// first column, the last cell's right neighbour, is taken first.
#[inline(always)]
fn keeping_pass_a<const UNIT_DT: bool>(
    [above, below]: [&[Cell]; 2],
    row: &mut [Cell],
    kept: &mut [Cell],
    c: &Coefficients,
    mut carry: i32,
) -> i32 {
    let a = |cell: &Cell| i32::from(cell.a);
    let old = |cell: Cell| (i32::from(cell.a), i32::from(cell.b));
    let (Some(&old_first), Some(&old_last)) = (row.first(), row.last()) else {
        return carry;
    };
    let column_at = |x: usize, middle: Cell| {
        let cell = |row: &[Cell]| row.get(x).map_or(0, a);
        cell(above) + 4 * a(&middle) + cell(below)
    };
    let first = column_at(0, old_first);
    let mut left = column_at(row.len().wrapping_sub(1), old_last);
    let mut here = first;
    let mut centre = old_first;
    let mut cells = row.iter_mut();
    let (Some(mut previous), Some(kept_first)) = (cells.next(), kept.first_mut()) else {
        return carry;
    };
    *kept_first = old_first;
    let columns = above.iter().zip(below).zip(kept).skip(1);
    for (cell, ((up, down), keep)) in cells.zip(columns) {
        let middle = *cell;
        *keep = middle;
        let right = a(up) + 4 * a(&middle) + a(down);
        previous.a = next_chemical::<UNIT_DT, false>(left, here, right, old(centre), c, &mut carry);
        (left, here, centre) = (here, right, middle);
        previous = cell;
    }
    // The last cell's right neighbour is the first column.
    previous.a = next_chemical::<UNIT_DT, false>(left, here, first, old(centre), c, &mut carry);
    carry
}

/// One chemical's pass of [`update_row_by_chemical`] (B's where `B`): each cell's value
/// in `row` from the old rows `above`, `kept` (the row's own) and `below`; returns the
/// carry.
///
/// Only B's instance is used (A's pass is [`keeping_pass_a`]); a pass written for B alone
/// was laid out worse on Cortex-M3 (docs/performance.md, The textures against the loops a
/// user writes).
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
    let own = if B { b } else { a };
    let reaction = reaction::<UNIT_DT>(a, b, c);
    let sum = left + right + 4 * here;
    settle(own, change::<B>(sum, own, reaction, c), carry)
}

/// A chemical's change in units of 2⁻³⁰ (B's where `B`), from the weighted sum of its
/// cell's neighbourhood (`sum`: the three columns' sums weighted [1 4 1], 20·∇² before
/// the centre's −36), the cell's own value and the reaction AB²·Δt: D·sum − own·value −
/// AB²·Δt + f·1 for A, D·sum − own·value + AB²·Δt for B, with [`Coefficients`]' folded
/// rates. That is D·20∇² − AB²·Δt + f·(1 − A) and D·20∇² + AB²·Δt − (k + f)·B exactly:
/// the change is within ±2³¹ (see [`next_cell`]), so the wrapping sum of its terms is
/// exact although own·value alone may pass 2³¹.
#[inline(always)]
fn change<const B: bool>(sum: i32, own: i32, reaction: i32, c: &Coefficients) -> i32 {
    if B {
        (c.diffusion_b * sum)
            .wrapping_sub(c.own_b.wrapping_mul(own))
            .wrapping_add(reaction)
    } else {
        (c.diffusion_a * sum)
            .wrapping_sub(c.own_a.wrapping_mul(own))
            .wrapping_sub(reaction)
            .wrapping_add(c.feed_one)
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
    // 20·∇² (4 × the four edges + the four corners − 20 × the centre) is each sum less
    // 36 × the centre, which `change` takes with the rates.
    let sum_a = left.sum_a + right.sum_a + 4 * here.sum_a;
    let sum_b = left.sum_b + right.sum_b + 4 * here.sum_b;
    let reaction = reaction::<UNIT_DT>(here.a, here.b, c);
    let change_a = change::<false>(sum_a, here.a, reaction, c);
    let change_b = change::<true>(sum_b, here.b, reaction, c);
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

    /// A cell's next state from the rates folded as [`Coefficients`] folds them is the
    /// one the model's equations give, computed here in 64 bits from the nine cells with
    /// the kernel's weights (edges 4, corners 1, centre −20) and the unfolded rates: for
    /// random neighbourhoods, carries and rates across the accepted ranges (D·Δt/20 up to
    /// 1,638, f·Δt and (k + f)·Δt up to 2¹⁵), their extremes included, at Δt = 1 and below.
    #[test]
    fn folded_rates_give_the_equations_cells() {
        let mut random = Generator::new(41);
        let one = i64::from(ONE);
        let mut pick = |extremes: &[i32], high: u32| {
            let r = random.next_u32();
            match extremes.get((r % 8) as usize) {
                Some(&extreme) => extreme,
                None => (random.next_u32() % (high + 1)) as i32,
            }
        };
        for case in 0..200_000 {
            let diffusion = [pick(&[0, 1638], 1638), pick(&[1638, 819], 1638)];
            let feed = pick(&[0, 1 << 15], 1 << 15);
            let decay = pick(&[feed, 1 << 15], 1 << 15).max(feed);
            let dt = if case % 2 == 0 {
                1 << 15
            } else {
                pick(&[1], 1 << 15).max(1)
            };
            let c = Coefficients::of_rates(diffusion, [feed, decay], dt);
            let mut cell = || Cell {
                a: pick(&[0, 1 << 15], 1 << 15) as u16,
                b: pick(&[0, 1 << 15], 1 << 15) as u16,
            };
            let cells: [[Cell; 3]; 3] = core::array::from_fn(|_| core::array::from_fn(|_| cell()));
            let carries = [
                pick(&[0, (1 << 15) - 1], (1 << 15) - 1),
                pick(&[0], (1 << 15) - 1),
            ];
            let columns: [Column; 3] =
                core::array::from_fn(|x| Column::of(cells[0][x], cells[1][x], cells[2][x]));
            let (mut carry_a, mut carry_b) = (carries[0], carries[1]);
            let step = if dt == 1 << 15 {
                next_cell::<true>
            } else {
                next_cell::<false>
            };
            let [left, here, right] = columns;
            let next = step(left, here, right, &c, (&mut carry_a, &mut carry_b));
            // The equations in 64 bits.
            let laplacian = |of: fn(Cell) -> i64| {
                let weight = |x: usize, y: usize| match (x, y) {
                    (1, 1) => -20,
                    (1, _) | (_, 1) => 4,
                    _ => 1,
                };
                (0..3)
                    .flat_map(|y| (0..3).map(move |x| (x, y)))
                    .map(|(x, y)| weight(x, y) * of(cells[y][x]))
                    .sum::<i64>()
            };
            let (a, b) = (i64::from(cells[1][1].a), i64::from(cells[1][1].b));
            let half = 1 << 14;
            let ab = (a * b + half) >> 15;
            let ab_dt = (ab * i64::from(dt) + half) >> 15;
            let reaction = ab_dt * b;
            let change_a = i64::from(diffusion[0]) * laplacian(|cell| i64::from(cell.a)) - reaction
                + i64::from(feed) * (one - a);
            let change_b = i64::from(diffusion[1]) * laplacian(|cell| i64::from(cell.b)) + reaction
                - i64::from(decay) * b;
            let settle = |value: i64, change: i64, carry: i32| {
                let total = change + i64::from(carry);
                let next = (value + total.div_euclid(1 << 15)).clamp(0, one);
                (next as u16, total.rem_euclid(1 << 15) as i32)
            };
            let (want_a, want_carry_a) = settle(a, change_a, carries[0]);
            let (want_b, want_carry_b) = settle(b, change_b, carries[1]);
            let case = (diffusion, feed, decay, dt, cells, carries);
            assert_eq!((next.a, carry_a), (want_a, want_carry_a), "{case:?}");
            assert_eq!((next.b, carry_b), (want_b, want_carry_b), "{case:?}");
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
