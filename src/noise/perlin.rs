//! Ken Perlin's improved noise (2002) in fixed point: his permutation, fade and gradients.

use crate::math::random::Generator;
use crate::math::wide::mul_i32_wide;
use crate::math::Real;

/// Fraction bits of a noise value ([`Sample`]): values lie in about ±1.04, and 29 bits keep
/// every value the f64 reference computes exactly (see [`Perlin`]).
pub const SAMPLE_FRAC_BITS: u32 = 29;

/// Fraction bits of a coordinate inside the lattice cell: inputs are taken to 2⁻²⁴, which
/// moves a value by less than 2⁻²² (the noise's slope is below 3 per unit).
const CELL_FRAC_BITS: u32 = 24;

/// Fraction bits of a fade weight.
const FADE_FRAC_BITS: u32 = 30;

/// Perlin's reference permutation of 0..=255, from his 2002 Java implementation.
const REFERENCE: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// Perlin's twelve gradients, the midpoints of a cube's edges, padded to sixteen by
/// repeating four (his `grad` with `h = hash & 15`): `(gx, gy, gz)` in −1, 0, 1.
const GRADIENTS: [(i8, i8, i8); 16] = [
    (1, 1, 0),
    (-1, 1, 0),
    (1, -1, 0),
    (-1, -1, 0),
    (1, 0, 1),
    (-1, 0, 1),
    (1, 0, -1),
    (-1, 0, -1),
    (0, 1, 1),
    (0, -1, 1),
    (0, 1, -1),
    (0, -1, -1),
    (1, 1, 0),
    (0, -1, 1),
    (-1, 1, 0),
    (0, -1, -1),
];

/// A noise value: [`SAMPLE_FRAC_BITS`] fraction bits in an `i32`, about ±1.04 at most.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Sample(pub i32);

impl Sample {
    /// The value as a [`Real`], exactly.
    pub const fn to_real(self) -> Real {
        Real::from_bits((self.0 as i64) << (Real::FRAC_BITS - SAMPLE_FRAC_BITS))
    }

    /// The value as an `f64`, exactly.
    pub fn to_f64(self) -> f64 {
        f64::from(self.0) / f64::from(1u32 << SAMPLE_FRAC_BITS)
    }

    /// Writes every digit of the value: a sample is a multiple of 2⁻²⁹, so its decimal
    /// expansion ends within 29 places (`-0.25`, `0.136919975280761718750`).
    pub fn write_exact(self, out: &mut impl core::fmt::Write) -> core::fmt::Result {
        let magnitude = self.0.unsigned_abs();
        if self.0 < 0 {
            out.write_char('-')?;
        }
        let whole = magnitude >> SAMPLE_FRAC_BITS;
        write!(out, "{whole}")?;
        // The fraction times 10 each place: below 2²⁹ · 10 < 2³³, so it needs 64 bits.
        let mut fraction = u64::from(magnitude & ((1 << SAMPLE_FRAC_BITS) - 1));
        if fraction != 0 {
            out.write_char('.')?;
        }
        while fraction != 0 {
            fraction *= 10;
            let digit = (fraction >> SAMPLE_FRAC_BITS) as u8;
            out.write_char(char::from(b'0' + digit))?;
            fraction &= (1 << SAMPLE_FRAC_BITS) - 1;
        }
        Ok(())
    }
}

/// Ken Perlin's improved noise: his permutation (seed 0) or a seeded shuffle of it, 256
/// bytes.
///
/// The value is his, computed in fixed point: inputs are taken to 2⁻²⁴, each fade weight
/// carries 30 fraction bits and each interpolated value 29, with every product taken in 64
/// bits. 3D takes his seven interpolations; 2D his three in another order, the same sum:
/// the lattice's edges each side of the point joined by the y fade first, then one
/// interpolation between them by the x fade, each step rounded to 2⁻²⁹. Where 29 fraction
/// bits hold his value, the samples are the f64 reference's values
/// exactly: at multiples of ¼ in 2D and of ½ in 3D (noise(0.5, 0.5, 0.5) = −0.25); elsewhere
/// they are within 2⁻²⁰ of the reference (`tests/noise.rs` checks both against an f64 model
/// written there).
// 256 bytes: a copy should be asked for (`clone`), not made by a move.
#[allow(missing_copy_implementations)]
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Perlin {
    permutation: [u8; 256],
}

impl Default for Perlin {
    fn default() -> Self {
        Self::reference()
    }
}

impl Perlin {
    /// Perlin's own permutation: the reference values.
    pub const fn reference() -> Self {
        Self {
            permutation: REFERENCE,
        }
    }

    /// The permutation for `seed`: Perlin's own for 0, otherwise his shuffled by the seeded
    /// generator (Fisher–Yates), the same on every target.
    pub fn seeded(seed: u32) -> Self {
        let mut permutation = REFERENCE;
        if seed != 0 {
            let mut generator = Generator::new(u64::from(seed));
            for i in (1..permutation.len()).rev() {
                // A draw below 2³² mapped onto 0..=i by a multiply: unbiased enough for a
                // shuffle, and the same on every target.
                let j = ((u64::from(generator.next_u32()) * (i as u64 + 1)) >> 32) as usize;
                permutation.swap(i, j);
            }
        }
        Self { permutation }
    }

    /// The permutation: a lattice point's hash is looked up here, as in Perlin's code.
    pub const fn permutation(&self) -> &[u8; 256] {
        &self.permutation
    }

    /// The permutation's entry for a lattice index (below 512: taken modulo 256, as Perlin's
    /// doubled table does).
    #[inline(always)]
    fn hash(&self, index: i32) -> i32 {
        // Masked to the table's length, so the lookup always finds its entry.
        let entry = self.permutation.get((index & 255) as usize);
        i32::from(entry.copied().unwrap_or(0))
    }

    /// The noise at a point: 3D where it has a z, 2D (Perlin's at z = 0) where it has none.
    #[inline]
    pub fn sample(&self, (x, y, z): (Real, Real, Option<Real>)) -> Sample {
        match z {
            Some(z) => self.noise3(x, y, z),
            None => self.noise2(x, y),
        }
    }

    /// The noise at (`x`, `y`, `z`).
    pub fn noise3(&self, x: Real, y: Real, z: Real) -> Sample {
        let column = ColumnPart::of(x);
        let (row, layer) = (RowPart::of(y), RowPart::of(z));
        self.cube_corners(column.cell(), row, layer).sample(
            column.place(),
            column.fade(),
            row,
            layer,
        )
    }

    /// The noise at (`x`, `y`): Perlin's noise at z = 0, where the far layer of the cell has
    /// no weight, computed from the near layer's four corners.
    pub fn noise2(&self, x: Real, y: Real) -> Sample {
        self.noise2_in_row(x, RowPart::of(y))
    }

    /// [`noise2`](Self::noise2) at `x` in the row whose y part is `row`: a row of points
    /// shares its y's cell, place and fade.
    #[inline]
    pub(super) fn noise2_in_row(&self, x: Real, row: RowPart) -> Sample {
        let column = ColumnPart::of(x);
        self.corners(column.cell(), row, self)
            .sample(column.place(), column.fade())
    }

    /// The four corners of lattice cell `cell` of `row` (2D, z = 0), as the cell's left
    /// and right edges: what every point of the cell in that row shares.
    #[inline]
    pub(super) fn corners(
        &self,
        cell: i32,
        row: RowPart,
        gradients: &impl PlaneGradients,
    ) -> CellCorners {
        CellCorners {
            left: self.edge(cell, row, gradients),
            right: self.edge(cell + 1, row, gradients),
        }
    }

    /// The eight corners of lattice cell `cell` of `row` in `layer` (3D; a layer is z's
    /// part, as a row is y's): what every point of the cell in that row and layer shares.
    #[inline]
    pub(super) fn cube_corners(&self, cell: i32, row: RowPart, layer: RowPart) -> CubeCorners {
        let a = self.hash(cell) + row.cell;
        let (aa, ab) = (self.hash(a) + layer.cell, self.hash(a + 1) + layer.cell);
        let b = self.hash(cell + 1) + row.cell;
        let (ba, bb) = (self.hash(b) + layer.cell, self.hash(b + 1) + layer.cell);
        let one = 1 << CELL_FRAC_BITS;
        let (near_y, far_y) = (row.place, row.place - one);
        let (near_z, far_z) = (layer.place, layer.place - one);
        CubeCorners {
            near: [
                self.line(aa, 0, near_y, near_z),
                self.line(ba, -one, near_y, near_z),
                self.line(ab, 0, far_y, near_z),
                self.line(bb, -one, far_y, near_z),
            ],
            far: [
                self.line(aa + 1, 0, near_y, far_z),
                self.line(ba + 1, -one, near_y, far_z),
                self.line(ab + 1, 0, far_y, far_z),
                self.line(bb + 1, -one, far_y, far_z),
            ],
        }
    }

    /// The corners of cell `cell` of `row`, the one after `corners`' (modulo 256): its
    /// left edge is the last cell's right one, so only one is new.
    #[inline]
    pub(super) fn next_corners(
        &self,
        corners: &CellCorners,
        cell: i32,
        row: RowPart,
        gradients: &impl PlaneGradients,
    ) -> CellCorners {
        CellCorners {
            left: corners.right,
            right: self.edge(cell + 1, row, gradients),
        }
    }

    /// The lattice's edge at column `column` in `row`: its near and far corners (rows y
    /// and y + 1) joined by the row's fade, their gradients from `gradients`.
    #[inline(always)]
    fn edge(&self, column: i32, row: RowPart, gradients: &impl PlaneGradients) -> Edge {
        let hash = self.hash(column) + row.cell;
        let near = gradients.of(hash);
        let far = gradients.of(hash + 1);
        Edge::between(near, far, row)
    }

    /// The line of the corner whose (x, y, z) hash is `hash`, `dx` from the corner to the
    /// cell's left edge, `dy` to the row's points and `dz` to the layer's (2⁻²⁴ units).
    #[inline(always)]
    fn line(&self, hash: i32, dx: i32, dy: i32, dz: i32) -> Line {
        let (gx, gy, gz) = gradient_of(self.hash(hash));
        let (gx, gy, gz) = (i32::from(gx), i32::from(gy), i32::from(gz));
        let shift = SAMPLE_FRAC_BITS - CELL_FRAC_BITS;
        Line {
            slope: gx << shift,
            offset: (gx * dx + gy * dy + gz * dz) << shift,
        }
    }
}

/// Where 2D noise finds a corner's gradient's x and y parts from `h`, its x hash plus its
/// lattice row (`perm[x] + y`): the gradient `perm[perm[h]] & 15` picks (z = 0). [`Perlin`]
/// looks it up through its permutation and Perlin's table; [`GradientTable`] keeps the
/// answers for every `h`.
pub(super) trait PlaneGradients {
    /// The (gx, gy) of the corner whose x hash plus lattice row is `h` (taken modulo 256).
    fn of(&self, h: i32) -> (i32, i32);
}

impl PlaneGradients for Perlin {
    #[inline(always)]
    fn of(&self, h: i32) -> (i32, i32) {
        let (gx, gy, _) = gradient_of(self.hash(self.hash(h)));
        (i32::from(gx), i32::from(gy))
    }
}

/// Each corner's gradient in 2D by its x hash plus lattice row, x and y parts apart: one
/// load each where the permutation and Perlin's table take six steps. 512 bytes, made
/// once a drawing.
#[derive(Debug, Clone)]
pub(super) struct GradientTable {
    x: [i8; 256],
    y: [i8; 256],
}

impl GradientTable {
    /// An empty table (every gradient 0), to be [`fill`](Self::fill)ed in place.
    pub(super) const EMPTY: Self = Self {
        x: [0; 256],
        y: [0; 256],
    };

    /// Makes this the table of `noise`'s gradients.
    pub(super) fn fill(&mut self, noise: &Perlin) {
        for (h, (x, y)) in self.x.iter_mut().zip(&mut self.y).enumerate() {
            let (gx, gy) = PlaneGradients::of(noise, h as i32);
            // Within −1 to 1.
            (*x, *y) = (gx as i8, gy as i8);
        }
    }
}

impl PlaneGradients for GradientTable {
    #[inline(always)]
    fn of(&self, h: i32) -> (i32, i32) {
        // Masked to the tables' length.
        let index = (h & 255) as usize;
        let x = self.x.get(index).copied().unwrap_or(0);
        let y = self.y.get(index).copied().unwrap_or(0);
        (i32::from(x), i32::from(y))
    }
}

/// A corner's gradient dotted with the offset from the corner, as a line in the point's
/// place in its cell: `slope · place + offset` in 2⁻²⁹ (the same integers as
/// Perlin's `grad`, shifted to 2⁻²⁹: the shift distributes over the sum, which stays within ±2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Line {
    slope: i32,
    offset: i32,
}

impl Line {
    const ZERO: Self = Self {
        slope: 0,
        offset: 0,
    };

    #[inline(always)]
    fn at(self, place: i32) -> i32 {
        self.slope * place + self.offset
    }
}

/// An edge of the lattice in a row of 2D noise: the corners at one lattice column in the
/// row's two lattice rows, their lines joined by the row's fade `v` into one line in x
/// measured from the column, `slope · dx + offset`. Its slope, (1 − v)·g_near + v·g_far
/// (the corners' x gradients), is exact in 2⁻³⁰; its offset, the corners' dots at the
/// column joined the same way, is rounded to nearest in 2⁻²⁹. A cell's points then take
/// one interpolation each, across the cell between its left and right edges, not three;
/// and the cell after it shares its right edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Edge {
    /// In 2⁻³⁰ per unit of x, within ±1.
    slope: i32,
    /// In 2⁻²⁹.
    offset: i32,
}

impl Edge {
    const ZERO: Self = Self {
        slope: 0,
        offset: 0,
    };

    /// The edge in `row` whose near and far corners' gradients are `near` and `far`
    /// (`(gx, gy)`): each corner's line in x is gx·dx + gy·dy (dy from the corner to the
    /// row, q and q − 1), and the edge is their `lerp` by the row's fade v.
    #[inline(always)]
    fn between((near_x, near_y): (i32, i32), (far_x, far_y): (i32, i32), row: RowPart) -> Self {
        let one = 1 << CELL_FRAC_BITS;
        // The dots at the column, gy·dy, in 2⁻²⁹ (dy in 2⁻²⁴): within ±1.
        let shift = SAMPLE_FRAC_BITS - CELL_FRAC_BITS;
        let (near_dot, far_dot) = (
            (near_y * row.place) << shift,
            (far_y * (row.place - one)) << shift,
        );
        Self {
            // g_near·2³⁰ + v·(g_far − g_near): within ±2³⁰, exactly.
            slope: (near_x << FADE_FRAC_BITS) + row.fade * (far_x - near_x),
            // The dots at most 2 apart.
            offset: lerp_close(row.fade, near_dot, far_dot),
        }
    }

    /// The edge's value at `dx` from its column (2⁻³¹, −1 to 1), in 2⁻²⁹: the slope's
    /// product taken down to 2⁻²⁹ (the high word of one 32 × 32-bit product) plus the
    /// offset. (ARMv6-M takes a cell's two edges together instead:
    /// [`CellCorners::edges_at`].)
    #[cfg(any(test, not(tinyfractal_no_long_multiply)))]
    #[inline(always)]
    fn at(self, dx: i32) -> i32 {
        self.offset + crate::math::wide::mul_high(self.slope, dx)
    }
}

/// The corners of a lattice cell in a row of 2D noise, as its left and right edges
/// ([`Edge`]): a row's points in one cell need only their x place and fade to be sampled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct CellCorners {
    left: Edge,
    right: Edge,
}

impl CellCorners {
    /// No cell's corners (a block's first column takes its own).
    pub(super) const NONE: Self = Self {
        left: Edge::ZERO,
        right: Edge::ZERO,
    };

    /// The noise at the point of the cell whose place in it is `place` (2⁻³¹, 0 to 1, as
    /// [`ColumnPart::place`]) and whose fade is `fade`: the left and right edges' values
    /// there (`place` from the left one, `place` − 1 from the right), joined by the fade.
    #[inline(always)]
    pub(super) fn sample(&self, place: i32, fade: i32) -> Sample {
        let (left, right) = self.edges_at(place);
        Sample(lerp_close(fade, left, right))
    }

    /// The left edge's value at `place` and the right edge's at `place` − 1 (2⁻²⁹): one
    /// high word each where there is a long multiply, and on cores without one
    /// ([`edges_at_in_halves`](Self::edges_at_in_halves)) 16-bit halves.
    #[inline(always)]
    fn edges_at(&self, place: i32) -> (i32, i32) {
        #[cfg(tinyfractal_no_long_multiply)]
        {
            self.edges_at_in_halves(place)
        }
        #[cfg(not(tinyfractal_no_long_multiply))]
        {
            // place − 2³¹, for a place below 2³¹.
            (self.left.at(place), self.right.at(place ^ i32::MIN))
        }
    }

    /// [`edges_at`](Self::edges_at) from 16-bit halves whose middle products are summed
    /// whole, not split again as a product of any two values must be.
    ///
    /// A slope (within ±2³⁰) is lifted by 2³⁰ to an unsigned s′ of at most 2³¹, and the
    /// place p (0 to 2³¹, a multiple of 2⁷ as every [`ColumnPart`]'s is) taken as it is
    /// from the left and less 2³¹ from the right: slope·p / 2³² is s′·p / 2³² − p/4
    /// exactly, a quarter of p being whole. With s′ = sₕ·2¹⁶ + sₗ and p = pₕ·2¹⁶ + pₗ
    /// (pₗ at most 2¹⁶ − 2⁷), sₕpₗ + sₗpₕ + ⌊sₗpₗ/2¹⁶⌋ is below 2³² from the left (pₕ
    /// unsigned) and within ±2³¹ from the right (pₕ from −2¹⁵ to 0): one word either way.
    #[cfg(any(test, tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn edges_at_in_halves(&self, place: i32) -> (i32, i32) {
        let (high, low) = ((place >> 16) as u32, (place & 0xFFFF) as u32);
        let quarter = place >> 2;
        let lifted = |slope: i32| {
            let lifted = slope.wrapping_add(1 << 30) as u32;
            (lifted >> 16, lifted & 0xFFFF)
        };
        let (left_high, left_low) = lifted(self.left.slope);
        let sum = left_high * low + left_low * high + ((left_low * low) >> 16);
        let left = (left_high * high + (sum >> 16)) as i32;
        let (right_high, right_low) = lifted(self.right.slope);
        // From the right the place's high half is less 2¹⁵, and the products signed.
        let (high, right_high, right_low) =
            (high as i32 - (1 << 15), right_high as i32, right_low as i32);
        let sum =
            right_high * low as i32 + right_low * high + ((right_low as u32 * low) >> 16) as i32;
        let right = right_high * high + (sum >> 16);
        (
            self.left.offset.wrapping_add(left).wrapping_sub(quarter),
            self.right
                .offset
                .wrapping_add(right)
                .wrapping_sub(quarter)
                .wrapping_add(1 << 29),
        )
    }
}

/// The eight corners of a lattice cell of 3D noise in one row and layer, as lines in the
/// point's place (near layer, then far; in each the near row's left and right corners,
/// then the far row's): a row's points in one cell need only their x place and fade.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct CubeCorners {
    near: [Line; 4],
    far: [Line; 4],
}

impl CubeCorners {
    /// No cell's corners (a block's first column takes its own).
    pub(super) const NONE: Self = Self {
        near: [Line::ZERO; 4],
        far: [Line::ZERO; 4],
    };

    /// The noise at the point of the cell whose place in it is `place` (2⁻³¹) and whose
    /// fade is `u`, in `row` and `layer`: Perlin's seven interpolations, each in 64 bits
    /// (in 3D the values joined may be 2³¹ apart).
    #[inline(always)]
    pub(super) fn sample(&self, place: i32, u: i32, row: RowPart, layer: RowPart) -> Sample {
        let place = place >> PLACE_SHIFT;
        let square = |[near_left, near_right, far_left, far_right]: [Line; 4]| {
            lerp(
                row.fade,
                lerp(u, near_left.at(place), near_right.at(place)),
                lerp(u, far_left.at(place), far_right.at(place)),
            )
        };
        Sample(lerp(layer.fade, square(self.near), square(self.far)))
    }
}

/// What noise takes from a point's x: its lattice column (modulo 256), its place in the
/// column in 2⁻³¹ (a multiple of 2⁻²⁴: see [`cell`]) and the place's fade in 2⁻³⁰.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct ColumnPart {
    cell: i32,
    place: i32,
    fade: i32,
}

impl ColumnPart {
    /// The part of `x`.
    #[inline(always)]
    pub(super) fn of(x: Real) -> Self {
        let (cell, place) = cell(x);
        Self {
            cell,
            place: place << PLACE_SHIFT,
            fade: fade(place),
        }
    }

    /// The lattice column, 0 to 255.
    #[inline(always)]
    pub(super) fn cell(self) -> i32 {
        self.cell
    }

    /// The place in the column, in 2⁻³¹.
    #[inline(always)]
    pub(super) fn place(self) -> i32 {
        self.place
    }

    /// The fade of the place, in 2⁻³⁰.
    #[inline(always)]
    pub(super) fn fade(self) -> i32 {
        self.fade
    }
}

/// What a place in 2⁻²⁴ is shifted by to be in 2⁻³¹, the unit [`Edge::at`] takes.
const PLACE_SHIFT: u32 = 31 - CELL_FRAC_BITS;

/// What 2D noise takes from a point's y: its lattice row (modulo 256), its place in the
/// row in 2⁻²⁴, and the fade of that place in 2⁻³⁰.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct RowPart {
    cell: i32,
    place: i32,
    fade: i32,
}

impl RowPart {
    /// The part of `y`.
    #[inline]
    pub(super) fn of(y: Real) -> Self {
        let (cell, place) = cell(y);
        Self {
            cell,
            place,
            fade: fade(place),
        }
    }
}

/// A coordinate's lattice cell modulo 256 and its place in the cell in 2⁻²⁴ (rounded to
/// nearest). The permutation sees a cell modulo 256 only, so the index sums that hash a
/// corner stay small at any coordinate: no overflow at the ends of `Real`'s range.
#[inline(always)]
fn cell(value: Real) -> (i32, i32) {
    let shift = Real::FRAC_BITS - CELL_FRAC_BITS;
    // Rounding may wrap past the largest coordinate; the low bits the cell keeps are right.
    let bits = value.to_bits().wrapping_add(1 << (shift - 1)) >> shift;
    (
        ((bits >> CELL_FRAC_BITS) & 255) as i32,
        (bits & ((1 << CELL_FRAC_BITS) - 1)) as i32,
    )
}

/// Perlin's fade 6t⁵ − 15t⁴ + 10t³ of `t` (2⁻²⁴ units, 0 ≤ t < 1), in 2⁻³⁰, by Horner's rule.
/// Each product is exact while t has at most 6 fraction bits; past that each rounds down by
/// less than 2⁻³⁰. In 64-bit products where the core multiplies 32 × 32 → 64 bits; in
/// 32-bit ones where it does not (ARMv6-M), so no core calls a library multiply: the same
/// values.
#[inline(always)]
pub(crate) fn fade(t: i32) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        fade_in_halves(t)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        let t = i64::from(t);
        // 6t² − 15t + 10 in 2⁻⁴⁸ (below 2⁵²), taken to 2⁻³⁰.
        let inner = (t * (6 * t - (15 << CELL_FRAC_BITS)) + (10 << (2 * CELL_FRAC_BITS)))
            >> (2 * CELL_FRAC_BITS - FADE_FRAC_BITS);
        // Times t three times, each product below 2⁵⁸ and taken back to 2⁻³⁰.
        let cubic = (t * inner) >> CELL_FRAC_BITS;
        let quartic = (t * cubic) >> CELL_FRAC_BITS;
        ((t * quartic) >> CELL_FRAC_BITS) as i32
    }
}

/// [`fade`] in 32 × 32 → 64-bit products of 32-bit halves.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
fn fade_in_halves(t: i32) -> i32 {
    // 6t² − 15t + 10 in 2⁻⁴⁸ (from 1 to 10, so positive and below 2⁵²), taken to 2⁻³⁰.
    let quadratic = mul_i32_wide(t, 6 * t - (15 << CELL_FRAC_BITS)) + (10 << (2 * CELL_FRAC_BITS));
    let inner = (quadratic >> (2 * CELL_FRAC_BITS - FADE_FRAC_BITS)) as u64;
    // Times t three times, each product taken back to 2⁻³⁰. The first factor is below 2³⁴:
    // the product of t and x = h·2³² + l is t·l + t·h·2³², and the second part (t·h < 2²⁶)
    // loses nothing to the shift.
    let t = t as u32;
    let times_t = |x: u64| {
        let high = t * (x >> 32) as u32;
        (crate::math::wide::mul_u32_wide(t, x as u32) >> CELL_FRAC_BITS)
            + (u64::from(high) << (32 - CELL_FRAC_BITS))
    };
    // The next two are below 2.02·2³⁰ (6t³ − 15t² + 10t is at most 2.011), and t below 2²⁴:
    // in halves t = tₕ·2¹⁶ + tₗ (tₕ < 2⁸) and x = xₕ·2¹⁶ + xₗ, t·x / 2²⁴ is tₕxₕ·2⁸ +
    // (tₕxₗ + tₗxₕ + tₗxₗ/2¹⁶) / 2⁸, every part and sum below 2³², taken down in steps.
    let (t_high, t_low) = (t >> 16, t & 0xFFFF);
    let times_t_narrow = |x: u32| {
        let (high, low) = (x >> 16, x & 0xFFFF);
        let middle = t_high * low + t_low * high + ((t_low * low) >> 16);
        ((t_high * high) << 8) + (middle >> 8)
    };
    times_t_narrow(times_t_narrow(times_t(inner) as u32)) as i32
}

/// The gradient `hash` picks: `hash & 15`, as Perlin's `grad`.
#[inline(always)]
fn gradient_of(hash: i32) -> (i8, i8, i8) {
    GRADIENTS
        .get((hash & 15) as usize)
        .copied()
        .unwrap_or_default()
}

/// `a + t(b − a)`, `t` in 2⁻³⁰, `a` and `b` in 2⁻²⁹ within ±2, rounded to nearest. Where
/// there is no long multiply (ARMv6-M), a difference within 32 bits (every one but 2³¹)
/// takes [`fade_step`]'s 16-bit parts, not a call of the library's 64-bit multiply.
#[inline(always)]
fn lerp(t: i32, a: i32, b: i32) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        if let Some(d) = b.checked_sub(a) {
            return a + fade_step_in_halves(t, d);
        }
    }
    let step = i64::from(t) * (i64::from(b) - i64::from(a));
    a + ((step + (1 << (FADE_FRAC_BITS - 1))) >> FADE_FRAC_BITS) as i32
}

/// [`lerp`] of `a` and `b` less than 2³¹ apart, so that their difference is an `i32` and
/// the product one 32×32 → 64-bit multiply: the same value.
///
/// In 2D every pair interpolated is that close. A corner's dot is gx·dx + gy·dy with
/// |dx|, |dy| ≤ 1, and below 2 in magnitude except at the far-right corner, where it is 2
/// only at place 0, whose fade is 0 (there the step is 0 whatever the difference). An
/// [`Edge`] joins a near and a far corner whose dots at its column, gy·dy and
/// gy′(dy − 1), are within ±1. Each edge's value at a point lies between its corners'
/// dots, so a cell's left and right edges' values are below 2 in magnitude, and their
/// difference below 4 (2³¹ in 2⁻²⁹).
#[inline(always)]
fn lerp_close(t: i32, a: i32, b: i32) -> i32 {
    a + fade_step(t, b.wrapping_sub(a))
}

/// t·d in 2⁻³⁰ rounded to nearest (half up), for a fade `t` from 0 to 2³⁰ and any `d`:
/// one `smull` and a shift where there is a long multiply; on cores without one (ARMv6-M)
/// four 16-bit products summed in one word ([`fade_step_in_halves`]), where a signed
/// 64-bit product from halves would take its signs off and put them back.
#[inline(always)]
fn fade_step(t: i32, d: i32) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        fade_step_in_halves(t, d)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        ((mul_i32_wide(t, d) + (1 << (FADE_FRAC_BITS - 1))) >> FADE_FRAC_BITS) as i32
    }
}

/// [`fade_step`] from 16-bit parts: t = tₕ·2¹⁶ + tₗ with tₗ signed, in [−2¹⁵, 2¹⁵) (so
/// tₕ is 0 to 2¹⁴), and d = dₕ·2¹⁶ + dₗ with dₗ in [0, 2¹⁶): t·d = P·2³² + M·2¹⁶ + L with
/// P = tₕdₕ, M = tₕdₗ + tₗdₕ and L = tₗdₗ, and (t·d + 2²⁹) / 2³⁰ rounded down is 4P +
/// ⌊(M + ⌊L/2¹⁶⌋ + 2¹³) / 2¹⁴⌋. The sum is tₕdₗ + tₗ·d/2¹⁶ at most, below 2³⁰ + 2³⁰, so it
/// fits 32 bits with no part split again (4P may wrap: the result fits).
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
fn fade_step_in_halves(t: i32, d: i32) -> i32 {
    let tl = i32::from(t as i16);
    // t is at most 2³⁰: t − tₗ fits.
    let th = (t - tl) >> 16;
    let (dh, dl) = (d >> 16, d & 0xFFFF);
    let sum = (th * dl)
        .wrapping_add(tl * dh)
        .wrapping_add((tl * dl) >> 16)
        .wrapping_add(1 << 13);
    (th * dh).wrapping_mul(4).wrapping_add(sum >> 14)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Perlin's fade at ¾, as published: 0.896484375, exactly.
    #[test]
    fn fade_is_perlins_quintic() {
        let three_quarters = 3 << (CELL_FRAC_BITS - 2);
        assert_eq!(
            f64::from(fade(three_quarters)) / f64::from(1u32 << FADE_FRAC_BITS),
            0.896484375
        );
        assert_eq!(fade(0), 0);
        assert_eq!(fade(1 << (CELL_FRAC_BITS - 1)), 1 << (FADE_FRAC_BITS - 1));
    }

    /// A cell's edges' values from 16-bit halves (ARMv6-M's) are the high words' for every
    /// slope and offset within their ranges and every place (a multiple of 2⁷), their ends
    /// included.
    #[test]
    fn edges_from_halves_are_the_high_words() {
        use proptest::prelude::*;
        let corners =
            |[left_slope, left_offset, right_slope, right_offset]: [i32; 4]| CellCorners {
                left: Edge {
                    slope: left_slope,
                    offset: left_offset,
                },
                right: Edge {
                    slope: right_slope,
                    offset: right_offset,
                },
            };
        let exact = |corners: &CellCorners, place: i32| {
            (corners.left.at(place), corners.right.at(place ^ i32::MIN))
        };
        let slope = -(1i32 << 30)..=(1 << 30);
        let offset = -(1i32 << 30)..(1 << 30);
        let place = (0..1i32 << 24).prop_map(|p| p << 7);
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(
                &(slope.clone(), offset.clone(), slope, offset, place),
                |(left_slope, left_offset, right_slope, right_offset, place)| {
                    let cell = corners([left_slope, left_offset, right_slope, right_offset]);
                    prop_assert_eq!(cell.edges_at_in_halves(place), exact(&cell, place));
                    prop_assert_eq!(cell.edges_at(place), exact(&cell, place));
                    Ok(())
                },
            )
            .unwrap();
        let slopes = [
            -(1 << 30),
            (1 << 30),
            0,
            1,
            -1,
            0xFFFF,
            -0x1_0000,
            (1 << 30) - 1,
        ];
        let places = [0, 1 << 7, i32::MAX - 127, 0xFF80, 0x1_0000, 1 << 30];
        for left in slopes {
            for right in slopes {
                for place in places {
                    let cell = corners([left, -(1 << 30), right, (1 << 30) - 1]);
                    assert_eq!(
                        cell.edges_at_in_halves(place),
                        exact(&cell, place),
                        "{left} {right} {place}"
                    );
                }
            }
        }
    }

    /// The fade's step from 16-bit parts is the 64-bit product's, rounded, for every fade
    /// and difference, the ends of both included.
    #[test]
    fn fade_steps_from_parts_are_the_wide_ones() {
        use proptest::prelude::*;
        let wide = |t: i32, d: i32| ((i64::from(t) * i64::from(d) + (1 << 29)) >> 30) as i32;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let difference = (any::<i32>(), 0u32..32).prop_map(|(v, s)| v >> s);
        runner
            .run(&(0..=(1i32 << 30), difference), |(t, d)| {
                prop_assert_eq!(fade_step_in_halves(t, d), wide(t, d));
                prop_assert_eq!(fade_step(t, d), wide(t, d));
                Ok(())
            })
            .unwrap();
        let fades = [0, 1, 0xFFFF, 0x1_0000, (1 << 30) - 1, 1 << 30];
        let differences = [
            i32::MIN,
            i32::MIN + 1,
            -1,
            0,
            1,
            0xFFFF,
            -0x1_0000,
            i32::MAX,
        ];
        for t in fades {
            for d in differences {
                assert_eq!(fade_step_in_halves(t, d), wide(t, d), "{t} {d}");
            }
        }
    }

    /// The fade, in either set of products, is Horner's rule in exact ones (ARMv6-M's at
    /// every place).
    #[test]
    fn fade_is_horners_rule() {
        let horner = |t: i32| {
            let t = i128::from(t);
            let inner = (t * (6 * t - (15 << CELL_FRAC_BITS)) + (10 << (2 * CELL_FRAC_BITS)))
                >> (2 * CELL_FRAC_BITS - FADE_FRAC_BITS);
            let cubic = (t * inner) >> CELL_FRAC_BITS;
            let quartic = (t * cubic) >> CELL_FRAC_BITS;
            ((t * quartic) >> CELL_FRAC_BITS) as i32
        };
        let last = (1 << CELL_FRAC_BITS) - 1;
        let places = (0..last)
            .step_by(61)
            .chain(0..4096)
            .chain(last - 4096..=last);
        for t in places {
            assert_eq!(fade(t), horner(t), "{t}");
        }
        // Every place, for the one built on bounds (overflow checks on in tests).
        for t in 0..=last {
            assert_eq!(fade_in_halves(t), horner(t), "{t}");
        }
    }

    /// The exact digits of a sample end where its bits do.
    #[test]
    fn samples_print_every_digit() {
        let text = |bits: i32| {
            let mut out = heapless::String::<48>::new();
            Sample(bits).write_exact(&mut out).unwrap();
            out
        };
        assert_eq!(text(-(1 << (SAMPLE_FRAC_BITS - 2))), "-0.25");
        assert_eq!(text(1 << SAMPLE_FRAC_BITS), "1");
        assert_eq!(text(1), "0.00000000186264514923095703125");
        assert_eq!(text(0), "0");
    }
}
