//! The loops a user would write for the newer families, to measure the engine against.
//!
//! Perlin's reference code in `f32` as an Arduino sketch ports it, a first Gray–Scott
//! sketch in `f32`, the Hénon map and the Lorenz flow as sketches iterate them, and the
//! lecture's fern by the chaos game in `f32` and in careful Q16.16. Each draws its picture
//! pixel by pixel into the target, as such sketches do; Sierpiński's carpet and gasket,
//! recursive in `f32` and in Q16.16, fill their last level's squares and triangles with
//! embedded-graphics' styled primitives (Adafruit's `fillRect` and `fillTriangle`); the
//! walking figure by a float matrix stack draws lines and circles with them (`drawLine`,
//! `drawCircle`); a deterministic L-system expands its string in a byte buffer and draws
//! it with a float turtle, and ABOP's monopodial tree, parametric and 3D, the same way
//! ([`monopodial_tree_f32`]).
//!
//! Beside most `f32` sketches a careful fixed-point one (`*_fixed`: Q16 or Q16.16 with
//! 64-bit products, Hénon in Q4.28). The fixed sketches share helpers among themselves,
//! not with the `f32` ones, whose code stays as a sketch writes it: sharing changed their
//! instruction counts, which are the baselines.

use core::ops::{Add, Neg};

use embedded_graphics::{pixelcolor::Gray4, prelude::*};
use micromath::F32Ext;

mod bounds;
mod figure_fixed;
mod lsystem_fixed;
mod shared;
mod sine;
mod terrain_fixed;
mod tree;
mod tree_fixed;

use bounds::Bounds;
use shared::{c_rand, expand, mul_q16, q16, NAIVE_TURTLE_STACK};

pub use figure_fixed::figure_fixed;
pub use lsystem_fixed::{lsystem_fixed, turn_divisions, MAX_DIVISIONS};
pub use shared::{NAIVE_LANDSCAPE_SIDE, NAIVE_PROFILE, NAIVE_STRING};
pub use terrain_fixed::{landscape_fixed, terrain_fixed};
pub use tree::{monopodial_tree_f32, NAIVE_TREE_STRING};
pub use tree_fixed::monopodial_tree_fixed;

/// A grey for a value in [0, 1].
fn grey(value: f32) -> Gray4 {
    Gray4::new((value.clamp(0.0, 1.0) * 15.0 + 0.5) as u8)
}

/// `(int)floor(x)`, as the ports write it without a maths library.
fn fast_floor(x: f32) -> i32 {
    let i = x as i32;
    if (i as f32) > x {
        i - 1
    } else {
        i
    }
}

/// Perlin's improved noise in 2D (his reference code at z = 0, the near layer), in `f32`:
/// his `fade`, `lerp` and `grad`, over his permutation doubled.
struct NaivePerlin {
    p: [u8; 512],
}

impl NaivePerlin {
    fn new(permutation: &[u8; 256]) -> Self {
        let mut p = [0; 512];
        for (i, slot) in p.iter_mut().enumerate() {
            *slot = permutation[i % 256];
        }
        Self { p }
    }

    fn fade(t: f32) -> f32 {
        t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
    }

    fn lerp(t: f32, a: f32, b: f32) -> f32 {
        a + t * (b - a)
    }

    /// His gradient of `hash` dotted with (x, y), in any number that negates and adds (0 is
    /// its default).
    fn grad<T: Copy + Default + Neg<Output = T> + Add<Output = T>>(hash: u8, x: T, y: T) -> T {
        let h = hash & 15;
        let u = if h < 8 { x } else { y };
        let v = if h < 4 {
            y
        } else if h == 12 || h == 14 {
            x
        } else {
            T::default()
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    }

    /// The hashes of the lattice cell (cx, cy)'s corners: (0, 0), (1, 0), (0, 1), (1, 1).
    fn corners(&self, cx: usize, cy: usize) -> [u8; 4] {
        let p = &self.p;
        let a = p[cx] as usize + cy;
        let b = p[cx + 1] as usize + cy;
        [
            p[p[a] as usize],
            p[p[b] as usize],
            p[p[a + 1] as usize],
            p[p[b + 1] as usize],
        ]
    }

    fn noise(&self, x: f32, y: f32) -> f32 {
        let (fx, fy) = (fast_floor(x), fast_floor(y));
        let [aa, ba, ab, bb] = self.corners((fx & 255) as usize, (fy & 255) as usize);
        let (x, y) = (x - fx as f32, y - fy as f32);
        let (u, v) = (Self::fade(x), Self::fade(y));
        Self::lerp(
            v,
            Self::lerp(u, Self::grad(aa, x, y), Self::grad(ba, x - 1.0, y)),
            Self::lerp(
                u,
                Self::grad(ab, x, y - 1.0),
                Self::grad(bb, x - 1.0, y - 1.0),
            ),
        )
    }
}

/// fBm of `octaves` octaves (persistence ½, lacunarity 2) of Perlin's 2D noise over the
/// target, `scale` lattice cells across it, in `f32`; returns the samples taken.
pub fn noise_f32<D: DrawTarget<Color = Gray4>>(
    permutation: &[u8; 256],
    octaves: u32,
    scale: f32,
    target: &mut D,
) -> u64 {
    let noise = NaivePerlin::new(permutation);
    let size = target.bounding_box().size;
    let step = scale / size.width as f32;
    let mut samples = 0;
    for j in 0..size.height {
        for i in 0..size.width {
            let (x, y) = (i as f32 * step, j as f32 * step);
            let (mut sum, mut amplitude, mut frequency, mut total) = (0.0, 1.0, 1.0, 0.0);
            for _ in 0..octaves {
                sum += amplitude * noise.noise(x * frequency, y * frequency);
                total += amplitude;
                amplitude *= 0.5;
                frequency *= 2.0;
                samples += 1;
            }
            let value = (sum / total + 1.0) / 2.0;
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(i as i32, j as i32),
                grey(value),
            )));
        }
    }
    samples
}

/// fBm of Perlin's 2D noise as a careful fixed-point sketch writes it: [`noise_f32`]'s
/// loop in Q16.16; returns the samples taken.
///
/// A coordinate's lattice cell is its high half and its place in the cell its low half;
/// `fade`, `grad` and `lerp` are his, with Q16 products (32 × 32 → 64 bits); the octaves'
/// weights are halvings, and the sum is scaled to [0, 1] by its total's reciprocal once.
pub fn noise_fixed<D: DrawTarget<Color = Gray4>>(
    permutation: &[u8; 256],
    octaves: u32,
    scale: f32,
    target: &mut D,
) -> u64 {
    const ONE: i32 = 1 << 16;
    fn fade(t: i32) -> i32 {
        mul_q16(
            mul_q16(mul_q16(t, t), t),
            mul_q16(t, mul_q16(t, 6 * ONE) - 15 * ONE) + 10 * ONE,
        )
    }
    let lerp = |t: i32, a: i32, b: i32| a + mul_q16(t, b - a);
    let grad = NaivePerlin::grad::<i32>;
    let perlin = NaivePerlin::new(permutation);
    let noise = |x: i32, y: i32| {
        let [aa, ba, ab, bb] =
            perlin.corners(((x >> 16) & 255) as usize, ((y >> 16) & 255) as usize);
        let (x, y) = (x & 0xFFFF, y & 0xFFFF);
        let (u, v) = (fade(x), fade(y));
        lerp(
            v,
            lerp(u, grad(aa, x, y), grad(ba, x - ONE, y)),
            lerp(u, grad(ab, x, y - ONE), grad(bb, x - ONE, y - ONE)),
        )
    };
    let size = target.bounding_box().size;
    let step = (scale * 65536.0) as i32 / size.width.max(1) as i32;
    // The octaves' total weight, 2 − 2^(1 − octaves), and its reciprocal, Q16.
    let total = (0..octaves).fold(0, |total, octave| total + (ONE >> octave));
    let reciprocal = ((1i64 << 32) / i64::from(total.max(1))) as i32;
    let mut samples = 0;
    for j in 0..size.height as i32 {
        for i in 0..size.width as i32 {
            let (x, y) = (i * step, j * step);
            let mut sum = 0;
            for octave in 0..octaves {
                sum += noise(x << octave, y << octave) >> octave;
                samples += 1;
            }
            let value = (mul_q16(sum, reciprocal) + ONE) / 2;
            let level = ((value.clamp(0, ONE) * 15 + ONE / 2) >> 16) as u8;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(i, j), Gray4::new(level))));
        }
    }
    samples
}

/// The most cells the naive Gray–Scott grid has: two copies of A and B in `f32`, 9 KiB.
pub const NAIVE_REACTION_CELLS: usize = 24 * 24;

/// Gray–Scott as a first sketch writes it, in `f32`; returns the cell-steps.
///
/// Two grids, the 3×3 kernel as a table walked with `%` at every neighbour, each value
/// constrained to [0, 1], the grids swapped after each step; Sims's square start; then each
/// pixel the cell under it. Nothing is done (0) if the grid is larger than
/// [`NAIVE_REACTION_CELLS`].
pub fn gray_scott_f32<D: DrawTarget<Color = Gray4>>(
    (feed, kill): (f32, f32),
    (w, h): (usize, usize),
    steps: u32,
    target: &mut D,
) -> u64 {
    const KERNEL: [[f32; 3]; 3] = [[0.05, 0.2, 0.05], [0.2, -1.0, 0.2], [0.05, 0.2, 0.05]];
    const D_A: f32 = 1.0;
    const D_B: f32 = 0.5;
    if w * h > NAIVE_REACTION_CELLS || w == 0 || h == 0 {
        return 0;
    }
    let mut grids = [[[1.0f32, 0.0]; NAIVE_REACTION_CELLS]; 2];
    let side = (w.min(h) / 8).max(1);
    let (x0, y0) = ((w - side) / 2, (h - side) / 2);
    for y in y0..y0 + side {
        for x in x0..x0 + side {
            grids[0][y * w + x][1] = 1.0;
        }
    }
    let mut current = 0;
    for _ in 0..steps {
        let (old, new) = if current == 0 {
            let (a, b) = grids.split_at_mut(1);
            (&a[0], &mut b[0])
        } else {
            let (a, b) = grids.split_at_mut(1);
            (&b[0], &mut a[0])
        };
        for y in 0..h {
            for x in 0..w {
                let (mut la, mut lb) = (0.0, 0.0);
                for (dy, row) in KERNEL.iter().enumerate() {
                    for (dx, weight) in row.iter().enumerate() {
                        let cell = old[((y + h + dy - 1) % h) * w + (x + w + dx - 1) % w];
                        la += cell[0] * weight;
                        lb += cell[1] * weight;
                    }
                }
                let [a, b] = old[y * w + x];
                let abb = a * b * b;
                new[y * w + x] = [
                    (a + D_A * la - abb + feed * (1.0 - a)).clamp(0.0, 1.0),
                    (b + D_B * lb + abb - (kill + feed) * b).clamp(0.0, 1.0),
                ];
            }
        }
        current = 1 - current;
    }
    let size = target.bounding_box().size;
    for j in 0..size.height {
        for i in 0..size.width {
            let cell = grids[current][(j as usize * h / size.height as usize) * w
                + i as usize * w / size.width as usize];
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(i as i32, j as i32),
                grey(cell[1]),
            )));
        }
    }
    u64::from(steps) * (w * h) as u64
}

/// Gray–Scott as a careful fixed-point sketch writes it; returns the cell-steps.
///
/// The same two grids, start, rates and picture as [`gray_scott_f32`], in Q16 (1.0 is
/// 65,536) with 64-bit products: the kernel's weights as whole numbers (corners 1, edges 4,
/// centre −20) and their sum times 1/20 once, the neighbours' rows and columns found once a
/// row and a cell instead of by `%`, each value constrained to [0, 1].
pub fn gray_scott_fixed<D: DrawTarget<Color = Gray4>>(
    (feed, kill): (f32, f32),
    (w, h): (usize, usize),
    steps: u32,
    target: &mut D,
) -> u64 {
    const ONE: i32 = 1 << 16;
    if w * h > NAIVE_REACTION_CELLS || w == 0 || h == 0 {
        return 0;
    }
    let (feed, kill) = ((feed * 65536.0) as i32, (kill * 65536.0) as i32);
    let twentieth = ONE / 20;
    let mut grids = [[[ONE, 0i32]; NAIVE_REACTION_CELLS]; 2];
    let last = reaction_steps(&mut grids, (w, h), ONE, steps, |old, new| {
        for y in 0..h {
            let (up, down) = (
                if y == 0 { h - 1 } else { y - 1 },
                if y + 1 == h { 0 } else { y + 1 },
            );
            let rows = [up * w, y * w, down * w];
            for x in 0..w {
                let (left, right) = (
                    if x == 0 { w - 1 } else { x - 1 },
                    if x + 1 == w { 0 } else { x + 1 },
                );
                let at = |row: usize, column: usize| old[rows[row] + column];
                let (mut corners, mut edges) = ([0i32; 2], [0i32; 2]);
                for (row, column) in [(0, left), (0, right), (2, left), (2, right)] {
                    let cell = at(row, column);
                    corners = [corners[0] + cell[0], corners[1] + cell[1]];
                }
                for (row, column) in [(0, x), (2, x), (1, left), (1, right)] {
                    let cell = at(row, column);
                    edges = [edges[0] + cell[0], edges[1] + cell[1]];
                }
                let [a, b] = at(1, x);
                let la = mul_q16(corners[0] + 4 * edges[0] - 20 * a, twentieth);
                let lb = mul_q16(corners[1] + 4 * edges[1] - 20 * b, twentieth);
                let abb = mul_q16(a, mul_q16(b, b));
                new[y * w + x] = [
                    (a + la - abb + mul_q16(feed, ONE - a)).clamp(0, ONE),
                    (b + lb / 2 + abb - mul_q16(kill + feed, b)).clamp(0, ONE),
                ];
            }
        }
    });
    let level = |cell: [i32; 2]| Gray4::new(((cell[1] * 15 + ONE / 2) >> 16) as u8);
    draw_cells(last, (w, h), level, target);
    u64::from(steps) * (w * h) as u64
}

/// Sims's square start (B = `one` in a centred square of side ⌊min(w, h)/8⌋) in the
/// first of two grids, then `steps` steps, each writing one grid from the other; the grid
/// written last.
fn reaction_steps<T: Copy>(
    grids: &mut [[[T; 2]; NAIVE_REACTION_CELLS]; 2],
    (w, h): (usize, usize),
    one: T,
    steps: u32,
    mut step: impl FnMut(&[[T; 2]; NAIVE_REACTION_CELLS], &mut [[T; 2]; NAIVE_REACTION_CELLS]),
) -> &[[T; 2]; NAIVE_REACTION_CELLS] {
    let side = (w.min(h) / 8).max(1);
    let (x0, y0) = ((w - side) / 2, (h - side) / 2);
    for y in y0..y0 + side {
        for x in x0..x0 + side {
            grids[0][y * w + x][1] = one;
        }
    }
    let [first, second] = grids;
    for n in 0..steps {
        if n.is_multiple_of(2) {
            step(first, second);
        } else {
            step(second, first);
        }
    }
    if steps.is_multiple_of(2) {
        first
    } else {
        second
    }
}

/// Each pixel of the target the grey of the grid's cell under it.
fn draw_cells<T: Copy, D: DrawTarget<Color = Gray4>>(
    cells: &[[T; 2]],
    (w, h): (usize, usize),
    grey: impl Fn([T; 2]) -> Gray4,
    target: &mut D,
) {
    let size = target.bounding_box().size;
    for j in 0..size.height {
        for i in 0..size.width {
            let cell = cells[(j as usize * h / size.height as usize) * w
                + i as usize * w / size.width as usize];
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(i as i32, j as i32),
                grey(cell),
            )));
        }
    }
}

/// Steps from the start before a sketch plots, as the scenes skip.
const NAIVE_SKIP: u32 = 1000;

/// The Hénon map (a = 1.4, b = 0.3) as a sketch writes it, in `f32`.
///
/// From (0, 0): 1,000 steps skipped, then each point a pixel of the target scaled from the attractor's
/// hard-coded box [−1.5, 1.5] × [−0.45, 0.45]; returns the points plotted.
pub fn henon_f32<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    let size = target.bounding_box().size;
    let (sx, sy) = (size.width as f32 / 3.0, size.height as f32 / 0.9);
    let (mut x, mut y) = (0.0f32, 0.0f32);
    for step in 0..NAIVE_SKIP + points {
        let x_next = 1.0 - 1.4 * x * x + y;
        y = 0.3 * x;
        x = x_next;
        if step >= NAIVE_SKIP {
            let px = ((x + 1.5) * sx) as i32;
            let py = ((0.45 - y) * sy) as i32;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// The Lorenz flow (σ = 10, ρ = 28, β = 8/3) as a sketch writes it, in `f32`.
///
/// From (1, 1, 1) by RK4 with Δt = 0.01: 1,000 steps skipped, then each point a pixel of the
/// target, x and z scaled from the hard-coded box [−25, 25] × [0, 50]; returns the points
/// plotted.
pub fn lorenz_f32<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    fn f([x, y, z]: [f32; 3]) -> [f32; 3] {
        [10.0 * (y - x), x * (28.0 - z) - y, x * y - 8.0 / 3.0 * z]
    }
    fn ahead(s: [f32; 3], k: [f32; 3], h: f32) -> [f32; 3] {
        [s[0] + h * k[0], s[1] + h * k[1], s[2] + h * k[2]]
    }
    const DT: f32 = 0.01;
    let size = target.bounding_box().size;
    let (sx, sz) = (size.width as f32 / 50.0, size.height as f32 / 50.0);
    let mut s = [1.0f32; 3];
    for step in 0..NAIVE_SKIP + points {
        let k1 = f(s);
        let k2 = f(ahead(s, k1, DT / 2.0));
        let k3 = f(ahead(s, k2, DT / 2.0));
        let k4 = f(ahead(s, k3, DT));
        for i in 0..3 {
            s[i] += DT / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        if step >= NAIVE_SKIP {
            let px = ((s[0] + 25.0) * sx) as i32;
            let py = ((50.0 - s[2]) * sz) as i32;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// The Hénon map as a careful fixed-point sketch writes it.
///
/// Q4.28 with 64-bit products (Q16.16 is too coarse: its orbit falls into a cycle that
/// misses part of the attractor), the same start, skip and box as [`henon_f32`], the scale
/// to pixels one multiply an axis; returns the points plotted.
pub fn henon_fixed<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    const FRAC: u32 = 28;
    const fn q28(value: f64) -> i32 {
        (value * (1u32 << FRAC) as f64) as i32
    }
    fn mul(a: i32, b: i32) -> i32 {
        ((i64::from(a) * i64::from(b)) >> FRAC) as i32
    }
    let size = target.bounding_box().size;
    // Pixels a unit, Q16.16; a distance in Q4.28 times it is pixels in Q(28 + 16).
    let (sx, sy) = (
        q16_of(size.width as i32) / 3,
        q16_of(size.height as i32) / 9 * 10,
    );
    let pixel = |v: i32, scale: i32| ((i64::from(v) * i64::from(scale)) >> (FRAC + 16)) as i32;
    let (mut x, mut y) = (0i32, 0i32);
    for step in 0..NAIVE_SKIP + points {
        let x_next = q28(1.0) - mul(q28(1.4), mul(x, x)) + y;
        y = mul(q28(0.3), x);
        x = x_next;
        if step >= NAIVE_SKIP {
            let px = pixel(x + q28(1.5), sx);
            let py = pixel(q28(0.45) - y, sy);
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// The Lorenz flow as a careful fixed-point sketch writes it.
///
/// Q16.16 with 64-bit products (the state stays within ±64, a product of two within
/// 2,500), RK4 with Δt = 0.01 as [`lorenz_f32`], the sixth of Δt folded into one
/// constant; the same start, skip and box; returns the points plotted.
pub fn lorenz_fixed<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    fn f([x, y, z]: [i32; 3]) -> [i32; 3] {
        [
            mul_q16(q16(10.0), y - x),
            mul_q16(x, q16(28.0) - z) - y,
            mul_q16(x, y) - mul_q16(q16(8.0 / 3.0), z),
        ]
    }
    fn ahead(s: [i32; 3], k: [i32; 3], h: i32) -> [i32; 3] {
        [
            s[0] + mul_q16(h, k[0]),
            s[1] + mul_q16(h, k[1]),
            s[2] + mul_q16(h, k[2]),
        ]
    }
    const DT: i32 = q16(0.01);
    const HALF_DT: i32 = q16(0.005);
    const SIXTH_DT: i32 = q16(0.01 / 6.0);
    let size = target.bounding_box().size;
    let (sx, sz) = (
        q16_of(size.width as i32) / 50,
        q16_of(size.height as i32) / 50,
    );
    let mut s = [q16(1.0); 3];
    for step in 0..NAIVE_SKIP + points {
        let k1 = f(s);
        let k2 = f(ahead(s, k1, HALF_DT));
        let k3 = f(ahead(s, k2, HALF_DT));
        let k4 = f(ahead(s, k3, DT));
        for i in 0..3 {
            s[i] += mul_q16(SIXTH_DT, k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        }
        if step >= NAIVE_SKIP {
            let px = mul_q16(s[0] + q16(25.0), sx) >> 16;
            let py = mul_q16(q16(50.0) - s[2], sz) >> 16;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// A fountain of particles as a sketch writes it, in `f32`.
///
/// `frames` ticks of 1/30 s, four particles a tick from the bottom's middle into a pool of 128 (a dead slot, else the
/// oldest), each tick every live particle moved under gravity and bounced on the ground,
/// then the display cleared and each particle a pixel; returns the particle-steps.
///
/// A sketch draws its directions from a cheap generator, as here, without sines.
pub fn fountain_f32<D: DrawTarget<Color = Gray4>>(frames: u32, target: &mut D) -> u64 {
    const N: usize = 128;
    let size = target.bounding_box().size;
    let (w, h) = (size.width as f32, size.height as f32);
    let scale = h / 240.0 / 30.0;
    let (gravity, ground) = (300.0 * scale / 30.0, h * 0.95);
    let mut seed: u32 = 1;
    let mut random = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        (seed >> 8) as f32 / 16_777_216.0
    };
    let (mut x, mut y, mut vx, mut vy) = ([0f32; N], [0f32; N], [0f32; N], [0f32; N]);
    let (mut age, mut life) = ([0u16; N], [0u16; N]);
    let mut steps = 0;
    for _ in 0..frames {
        for _ in 0..4 {
            let slot = (0..N)
                .find(|&i| age[i] >= life[i])
                .unwrap_or_else(|| (0..N).max_by_key(|&i| age[i]).unwrap_or(0));
            x[slot] = w * 0.5;
            y[slot] = ground;
            vx[slot] = (random() - 0.5) * 90.0 * scale;
            vy[slot] = -(250.0 + (random() - 0.5) * 60.0) * scale;
            age[slot] = 0;
            life[slot] = 57 + (random() * 18.0) as u16;
        }
        for i in 0..N {
            if age[i] < life[i] {
                vy[i] += gravity;
                x[i] += vx[i];
                y[i] += vy[i];
                if y[i] > ground {
                    y[i] = ground;
                    vy[i] = -vy[i] * 0.25;
                }
                age[i] += 1;
                steps += 1;
            }
        }
        let _ = target.clear(Gray4::BLACK);
        for i in 0..N {
            if age[i] < life[i] {
                let p = Point::new(x[i] as i32, y[i] as i32);
                let _ = target.draw_iter(core::iter::once(Pixel(p, Gray4::WHITE)));
            }
        }
    }
    steps
}

/// A fountain of particles as a careful fixed-point sketch writes it.
///
/// [`fountain_f32`]'s pool, generator, spawns and forces with positions and velocities in
/// Q16.16 (a product by a rate one 64-bit multiply, the rates scaled to the display once);
/// returns the particle-steps.
pub fn fountain_fixed<D: DrawTarget<Color = Gray4>>(frames: u32, target: &mut D) -> u64 {
    const N: usize = 128;
    const HALF: i32 = 1 << 15;
    let size = target.bounding_box().size;
    let (w, h) = (size.width as i32, size.height as i32);
    // Pixels a tick a pixel a second of the 240-high design, Q16.16.
    let scale = q16_of(h) / (240 * 30);
    let (gravity, ground) = (10 * scale, q16_of(h) / 100 * 95);
    let mut seed: u32 = 1;
    let mut random = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        (seed >> 16) as i32
    };
    let (mut x, mut y, mut vx, mut vy) = ([0i32; N], [0i32; N], [0i32; N], [0i32; N]);
    let (mut age, mut life) = ([0u16; N], [0u16; N]);
    let mut steps = 0;
    for _ in 0..frames {
        for _ in 0..4 {
            let slot = (0..N)
                .find(|&i| age[i] >= life[i])
                .unwrap_or_else(|| (0..N).max_by_key(|&i| age[i]).unwrap_or(0));
            x[slot] = q16_of(w) / 2;
            y[slot] = ground;
            vx[slot] = mul_q16(random() - HALF, 90 * scale);
            vy[slot] = -(250 * scale + mul_q16(random() - HALF, 60 * scale));
            age[slot] = 0;
            life[slot] = 57 + ((random() * 18) >> 16) as u16;
        }
        for i in 0..N {
            if age[i] < life[i] {
                vy[i] += gravity;
                x[i] += vx[i];
                y[i] += vy[i];
                if y[i] > ground {
                    y[i] = ground;
                    vy[i] = -vy[i] / 4;
                }
                age[i] += 1;
                steps += 1;
            }
        }
        let _ = target.clear(Gray4::BLACK);
        for i in 0..N {
            if age[i] < life[i] {
                let p = Point::new(x[i] >> 16, y[i] >> 16);
                let _ = target.draw_iter(core::iter::once(Pixel(p, Gray4::WHITE)));
            }
        }
    }
    steps
}

/// The lecture's fern as a sketch writes it, in `f32`.
///
/// The table's four maps, probabilities 1, 85, 7 and 7 in 100, a map chosen by
/// `rand() % 100`, 1,000 points skipped, then each point a pixel of the target scaled from
/// the fern's hard-coded box [−2.2, 2.7] × [0, 10]; returns the points plotted.
pub fn fern_f32<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    let size = target.bounding_box().size;
    let (sx, sy) = (size.width as f32 / 4.9, size.height as f32 / 10.0);
    let mut seed = 1u32;
    let (mut x, mut y) = (0.0f32, 0.0f32);
    for step in 0..NAIVE_SKIP + points {
        let r = c_rand(&mut seed) % 100;
        (x, y) = if r < 1 {
            (0.0, 0.16 * y)
        } else if r < 86 {
            (0.85 * x + 0.04 * y, -0.04 * x + 0.85 * y + 1.6)
        } else if r < 93 {
            (0.2 * x - 0.26 * y, 0.23 * x + 0.22 * y + 1.6)
        } else {
            (-0.15 * x + 0.28 * y, 0.26 * x + 0.24 * y + 0.44)
        };
        if step >= NAIVE_SKIP {
            let px = ((x + 2.2) * sx) as i32;
            let py = ((10.0 - y) * sy) as i32;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// The fern as a careful fixed-point sketch writes it.
///
/// Q16.16 with 64-bit products, the same choice and box as [`fern_f32`], the scale to
/// pixels folded into one multiply an axis.
pub fn fern_fixed<D: DrawTarget<Color = Gray4>>(points: u32, target: &mut D) -> u64 {
    const MAPS: [[i32; 6]; 4] = [
        [0, 0, 0, q16(0.16), 0, 0],
        [q16(0.85), q16(0.04), q16(-0.04), q16(0.85), 0, q16(1.6)],
        [q16(0.2), q16(-0.26), q16(0.23), q16(0.22), 0, q16(1.6)],
        [q16(-0.15), q16(0.28), q16(0.26), q16(0.24), 0, q16(0.44)],
    ];
    let size = target.bounding_box().size;
    // Pixels a unit, Q16.16.
    let (sx, sy) = (
        (size.width as i32) * 65536 / 49 * 10,
        (size.height as i32) * 65536 / 10,
    );
    let mut seed = 1u32;
    let (mut x, mut y) = (0i32, 0i32);
    for step in 0..NAIVE_SKIP + points {
        let r = c_rand(&mut seed) % 100;
        let [a, b, c, d, e, f] = MAPS[match r {
            0 => 0,
            1..=85 => 1,
            86..=92 => 2,
            _ => 3,
        }];
        (x, y) = (
            mul_q16(a, x) + mul_q16(b, y) + e,
            mul_q16(c, x) + mul_q16(d, y) + f,
        );
        if step >= NAIVE_SKIP {
            let px = mul_q16(x + q16(2.2), sx) >> 16;
            let py = mul_q16(q16(10.0) - y, sy) >> 16;
            let _ = target.draw_iter(core::iter::once(Pixel(Point::new(px, py), Gray4::WHITE)));
        }
    }
    u64::from(points)
}

/// A value in Q16.16 from an integer.
const fn q16_of(value: i32) -> i32 {
    value << 16
}

/// The largest square centred in `target`: its top-left corner and side, in pixels.
fn centred_square<D: DrawTarget>(target: &D) -> (i32, i32, i32) {
    let size = target.bounding_box().size;
    let side = size.width.min(size.height) as i32;
    (
        (size.width as i32 - side) / 2,
        (size.height as i32 - side) / 2,
        side,
    )
}

/// A filled rectangle as a sketch draws one: embedded-graphics' styled primitive
/// (Adafruit's `fillRect`).
fn fill_rect<D: DrawTarget<Color = Gray4>>(target: &mut D, (x, y): (i32, i32), (w, h): (i32, i32)) {
    use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
    let size = Size::new(w.max(0) as u32, h.max(0) as u32);
    let _ = Rectangle::new(Point::new(x, y), size)
        .into_styled(PrimitiveStyle::with_fill(Gray4::WHITE))
        .draw(target);
}

/// Sierpiński's carpet as a sketch writes it, in `f32`.
///
/// The screen cleared, the largest centred square divided in nine to `order`, the middle
/// left out, each kept square of the last level filled; returns the squares drawn
/// (8^order).
pub fn carpet_f32<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    // A sketch clears the screen first: the picture is every pixel, as the scene's.
    let _ = target.clear(Gray4::BLACK);
    fn square<D: DrawTarget<Color = Gray4>>(
        target: &mut D,
        (x, y, side): (f32, f32, f32),
        depth: u32,
    ) -> u64 {
        if depth == 0 {
            let (left, top) = (x as i32, y as i32);
            let size = ((x + side) as i32 - left, (y + side) as i32 - top);
            fill_rect(target, (left, top), size);
            return 1;
        }
        let third = side / 3.0;
        let mut drawn = 0;
        for row in 0..3 {
            for column in 0..3 {
                if row != 1 || column != 1 {
                    let at = (x + column as f32 * third, y + row as f32 * third, third);
                    drawn += square(target, at, depth - 1);
                }
            }
        }
        drawn
    }
    let (x, y, side) = centred_square(target);
    square(target, (x as f32, y as f32, side as f32), order)
}

/// The carpet as a careful fixed-point sketch writes it: the same recursion in Q16.16.
pub fn carpet_fixed<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    // A sketch clears the screen first: the picture is every pixel, as the scene's.
    let _ = target.clear(Gray4::BLACK);
    fn square<D: DrawTarget<Color = Gray4>>(
        target: &mut D,
        (x, y, side): (i32, i32, i32),
        depth: u32,
    ) -> u64 {
        if depth == 0 {
            let (left, top) = (x >> 16, y >> 16);
            let size = (((x + side) >> 16) - left, ((y + side) >> 16) - top);
            fill_rect(target, (left, top), size);
            return 1;
        }
        let third = side / 3;
        let mut drawn = 0;
        for row in 0..3 {
            for column in 0..3 {
                if row != 1 || column != 1 {
                    let at = (x + column * third, y + row * third, third);
                    drawn += square(target, at, depth - 1);
                }
            }
        }
        drawn
    }
    let (x, y, side) = centred_square(target);
    square(target, (q16_of(x), q16_of(y), q16_of(side)), order)
}

/// A filled triangle as a sketch draws one: embedded-graphics' styled primitive
/// (Adafruit's `fillTriangle`).
fn fill_triangle<D: DrawTarget<Color = Gray4>>(target: &mut D, corners: [(i32, i32); 3]) {
    use embedded_graphics::primitives::{PrimitiveStyle, Triangle};
    let [a, b, c] = corners.map(|(x, y)| Point::new(x, y));
    let _ = Triangle::new(a, b, c)
        .into_styled(PrimitiveStyle::with_fill(Gray4::WHITE))
        .draw(target);
}

/// Sierpiński's gasket as a sketch writes it, in `f32`.
///
/// The screen cleared, the triangle on the centred square's base with its apex at the top,
/// split at its sides' midpoints to `order`, each corner triangle of the last level filled;
/// returns the triangles drawn (3^order).
pub fn gasket_f32<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    // A sketch clears the screen first: the picture is every pixel, as the scene's.
    let _ = target.clear(Gray4::BLACK);
    fn triangle<D: DrawTarget<Color = Gray4>>(
        target: &mut D,
        corners: [(f32, f32); 3],
        depth: u32,
    ) -> u64 {
        if depth == 0 {
            fill_triangle(target, corners.map(|(x, y)| (x as i32, y as i32)));
            return 1;
        }
        let [a, b, c] = corners;
        let mid = |p: (f32, f32), q: (f32, f32)| ((p.0 + q.0) * 0.5, (p.1 + q.1) * 0.5);
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        triangle(target, [a, ab, ca], depth - 1)
            + triangle(target, [ab, b, bc], depth - 1)
            + triangle(target, [ca, bc, c], depth - 1)
    }
    let (x, y, side) = centred_square(target);
    let (x, y, side) = (x as f32, y as f32, side as f32);
    let corners = [(x + side * 0.5, y), (x, y + side), (x + side, y + side)];
    triangle(target, corners, order)
}

/// The gasket as a careful fixed-point sketch writes it: the same recursion in Q16.16.
pub fn gasket_fixed<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    // A sketch clears the screen first: the picture is every pixel, as the scene's.
    let _ = target.clear(Gray4::BLACK);
    fn triangle<D: DrawTarget<Color = Gray4>>(
        target: &mut D,
        corners: [(i32, i32); 3],
        depth: u32,
    ) -> u64 {
        if depth == 0 {
            fill_triangle(target, corners.map(|(x, y)| (x >> 16, y >> 16)));
            return 1;
        }
        let [a, b, c] = corners;
        let mid = |p: (i32, i32), q: (i32, i32)| ((p.0 + q.0) >> 1, (p.1 + q.1) >> 1);
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        triangle(target, [a, ab, ca], depth - 1)
            + triangle(target, [ab, b, bc], depth - 1)
            + triangle(target, [ca, bc, c], depth - 1)
    }
    let (x, y, side) = centred_square(target);
    let (x, y, side) = (q16_of(x), q16_of(y), q16_of(side));
    let corners = [(x + side / 2, y), (x, y + side), (x + side, y + side)];
    triangle(target, corners, order)
}

/// A 2D affine map as a sketch's matrix stack keeps it: x′ = a·x + b·y + tx,
/// y′ = c·x + d·y + ty.
#[derive(Clone, Copy)]
struct Matrix([f32; 6]);

impl Matrix {
    /// This map after a move by `(x, y)` and a turn by `degrees`, as `translate` then
    /// `rotate` compose on a sketch's stack.
    fn then(self, (x, y): (f32, f32), degrees: f32) -> Self {
        let [a, b, c, d, tx, ty] = self.0;
        let radians = degrees * (core::f32::consts::PI / 180.0);
        let (sin, cos) = (F32Ext::sin(radians), F32Ext::cos(radians));
        let (tx, ty) = (a * x + b * y + tx, c * x + d * y + ty);
        Self([
            a * cos + b * sin,
            -a * sin + b * cos,
            c * cos + d * sin,
            -c * sin + d * cos,
            tx,
            ty,
        ])
    }

    /// A point of the part's frame in pixels.
    fn pixel(&self, (x, y): (f32, f32)) -> Point {
        let [a, b, c, d, tx, ty] = self.0;
        Point::new((a * x + b * y + tx) as i32, (c * x + d * y + ty) as i32)
    }
}

/// The walking figure's joints at `time` (cycles), in degrees, as the lecture's walk has
/// them: hips ±25° in opposition, knees bending on the way forward, arms against the legs.
fn walk_angles(time: f32) -> [f32; 8] {
    let swing =
        |amplitude: f32, phase: f32| amplitude * F32Ext::sin(phase * core::f32::consts::TAU);
    let bend = |phase: f32| -swing(35.0, phase + 0.25).max(0.0);
    let other = time + 0.5;
    [
        swing(25.0, time),         // left hip
        swing(25.0, other),        // right hip
        bend(time),                // left knee
        bend(other),               // right knee
        swing(20.0, other),        // left shoulder
        swing(20.0, time),         // right shoulder
        swing(10.0, other) + 10.0, // left elbow
        swing(10.0, time) + 10.0,  // right elbow
    ]
}

/// A bone of the figure: a line from `from` to `to` in its part's frame, with
/// embedded-graphics' `Line` (a sketch's `drawLine`).
fn bone<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    ends: [(f32, f32); 2],
    color: Gray4,
) -> u64 {
    use embedded_graphics::primitives::{Line, PrimitiveStyle};
    let _ = Line::new(m.pixel(ends[0]), m.pixel(ends[1]))
        .into_styled(PrimitiveStyle::with_stroke(color, 1))
        .draw(target);
    1
}

/// A box `length` along and `width` across its part's x axis: four bones.
fn boxed<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    (length, width): (f32, f32),
    color: Gray4,
) -> u64 {
    let w = width / 2.0;
    let corners = [(0.0, -w), (length, -w), (length, w), (0.0, w)];
    (0..4)
        .map(|k| bone(target, m, [corners[k], corners[(k + 1) % 4]], color))
        .sum()
}

/// A circle of `radius` whose leftmost point is its part's origin, with embedded-graphics'
/// `Circle` (a sketch's `drawCircle`).
fn round<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    radius: f32,
    scale: f32,
    color: Gray4,
) -> u64 {
    use embedded_graphics::primitives::{Circle, PrimitiveStyle};
    let diameter = (2.0 * radius * scale) as u32;
    let _ = Circle::with_center(m.pixel((radius, 0.0)), diameter.max(1))
        .into_styled(PrimitiveStyle::with_stroke(color, 1))
        .draw(target);
    1
}

/// One pose of the figure by a float matrix stack, every part in `color`. Returns the
/// lines and circles drawn.
fn figure_pose<D: DrawTarget<Color = Gray4>>(target: &mut D, time: f32, color: Gray4) -> u64 {
    let [left_hip, right_hip, left_knee, right_knee, left_shoulder, right_shoulder, left_elbow, right_elbow] =
        walk_angles(time);
    // The hips a little above the picture's middle, a tenth of its height a unit, y down.
    let size = target.bounding_box().size;
    let scale = size.height as f32 / 10.0;
    let root = Matrix([
        scale,
        0.0,
        0.0,
        -scale,
        size.width as f32 / 2.0,
        size.height as f32 * 0.45,
    ]);
    let hips = root.then((0.0, 0.0), 90.0);
    let mut drawn = boxed(target, &hips, (0.3, 0.8), color);
    let torso = hips.then((0.3, 0.0), -5.0);
    drawn += boxed(target, &torso, (3.0, 1.0), color);
    let neck = torso.then((3.0, 0.0), 0.0);
    drawn += bone(target, &neck, [(0.0, 0.0), (0.4, 0.0)], color);
    drawn += round(target, &neck.then((0.4, 0.0), 0.0), 0.6, scale, color);
    for (shoulder, elbow) in [(left_shoulder, left_elbow), (right_shoulder, right_elbow)] {
        let upper = torso.then((2.8, 0.0), -175.0 + shoulder);
        drawn += bone(target, &upper, [(0.0, 0.0), (1.5, 0.0)], color);
        let fore = upper.then((1.5, 0.0), 20.0 + elbow);
        drawn += bone(target, &fore, [(0.0, 0.0), (1.3, 0.0)], color);
        drawn += round(target, &fore.then((1.3, 0.0), 0.0), 0.2, scale, color);
    }
    for (side, hip, knee) in [(0.25, left_hip, left_knee), (-0.25, right_hip, right_knee)] {
        let thigh = hips.then((0.0, side), 180.0 + hip);
        drawn += bone(target, &thigh, [(0.0, 0.0), (1.8, 0.0)], color);
        let shin = thigh.then((1.8, 0.0), knee);
        drawn += bone(target, &shin, [(0.0, 0.0), (1.8, 0.0)], color);
        let foot = shin.then((1.8, 0.0), 90.0);
        drawn += bone(target, &foot, [(0.0, 0.0), (0.6, 0.0)], color);
    }
    drawn
}

/// The walking figure as a sketch writes it: a float matrix stack.
///
/// Each part's map is its parent's times a move and a turn (sines from `micromath`);
/// `frames` frames of one walk cycle, each erasing the last by drawing it again in black,
/// as the scene does. Returns the lines and circles drawn (erasing not counted).
pub fn figure_f32<D: DrawTarget<Color = Gray4>>(frames: u32, target: &mut D) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let mut drawn = 0;
    let mut last = None;
    for frame in 0..frames {
        let time = frame as f32 / frames.max(1) as f32;
        if let Some(last) = last {
            figure_pose(target, last, Gray4::BLACK);
        }
        drawn += figure_pose(target, time, Gray4::WHITE);
        last = Some(time);
    }
    drawn
}

/// How far a system's `+` and `-` turn, in degrees, as a sketch's constant has it.
pub fn turn_degrees(angle: tinyfractal::Angle) -> f32 {
    match angle {
        tinyfractal::Angle::Divisions(n) => 360.0 / f32::from(n.max(1)),
        tinyfractal::Angle::Degrees(d) => d.to_f64() as f32,
    }
}

/// An L-system as a sketch draws it, in `f32`: the string expanded `order` times in a
/// byte buffer, then read twice by a float turtle, once for its box and once to draw.
///
/// The expansion rewrites the buffer in place (the current string moved to the buffer's
/// end, its expansion written from the start), as a sketch short of RAM does; `F` (and
/// `draw_symbols`) moves a unit and draws, `f` moves, `+`/`-` turn by `degrees` (the
/// heading's sine and cosine from `micromath` at each step), `[`/`]` push and pop the
/// turtle. The box scaled to fit the target less a 2-pixel margin and centred, each line
/// drawn with embedded-graphics' `Line` (a sketch's `drawLine`). Returns the lines drawn,
/// or 0 if the string outgrows [`NAIVE_STRING`].
pub fn lsystem_f32<D: DrawTarget<Color = Gray4>>(
    (axiom, rules, draw_symbols): (&str, &[(char, &str)], &str),
    degrees: f32,
    order: u32,
    up: bool,
    target: &mut D,
) -> u64 {
    use embedded_graphics::primitives::{Line, PrimitiveStyle};
    let _ = target.clear(Gray4::BLACK);
    let mut buffer = [0u8; NAIVE_STRING];
    let Some(length) = expand(&mut buffer, axiom, rules, order) else {
        return 0;
    };
    let string = &buffer[..length];
    let draws = |s: u8| s == b'F' || draw_symbols.as_bytes().contains(&s);
    let turn = degrees.to_radians();
    let start_heading = if up {
        core::f32::consts::FRAC_PI_2
    } else {
        0.0
    };
    // Walks the string, calling `line` with each drawn line's ends in turtle units.
    let walk = |line: &mut dyn FnMut((f32, f32), (f32, f32))| {
        let (mut x, mut y, mut heading) = (0.0f32, 0.0f32, start_heading);
        let mut stack = [(0.0f32, 0.0f32, 0.0f32); NAIVE_TURTLE_STACK];
        let mut depth = 0;
        for &symbol in string {
            match symbol {
                b'+' => heading += turn,
                b'-' => heading -= turn,
                b'[' if depth < NAIVE_TURTLE_STACK => {
                    stack[depth] = (x, y, heading);
                    depth += 1;
                }
                b']' if depth > 0 => {
                    depth -= 1;
                    (x, y, heading) = stack[depth];
                }
                b'f' => {
                    x += F32Ext::cos(heading);
                    y += F32Ext::sin(heading);
                }
                s if draws(s) => {
                    let (nx, ny) = (x + F32Ext::cos(heading), y + F32Ext::sin(heading));
                    line((x, y), (nx, ny));
                    (x, y) = (nx, ny);
                }
                _ => {}
            }
        }
    };
    let mut bounds = Bounds::new();
    walk(&mut |a, b| bounds.add([a, b]));
    let (_, pixel) = bounds.fitted(target.bounding_box().size);
    let mut drawn = 0;
    walk(&mut |a, b| {
        let _ = Line::new(pixel(a), pixel(b))
            .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, 1))
            .draw(target);
        drawn += 1;
    });
    drawn
}

/// Cubic Bézier curves as a sketch draws them, in `f32`: each curve evaluated by its
/// polynomial at `steps` equal steps of t and the points joined with embedded-graphics'
/// `Line`; returns the lines drawn.
///
/// `place` puts a control point of the design on the target (the scene's placement).
pub fn bezier_f32<D: DrawTarget<Color = Gray4>>(
    curves: &[[(i16, i16); 4]],
    place: impl Fn((i16, i16)) -> Point,
    steps: u32,
    target: &mut D,
) -> u64 {
    use embedded_graphics::primitives::{Line, PrimitiveStyle};
    let _ = target.clear(Gray4::BLACK);
    let mut drawn = 0;
    for curve in curves {
        let [p0, p1, p2, p3] = curve.map(&place);
        let at = |t: f32| {
            let u = 1.0 - t;
            let (a, b, c, d) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
            let axis = |v0: i32, v1: i32, v2: i32, v3: i32| {
                a * v0 as f32 + b * v1 as f32 + c * v2 as f32 + d * v3 as f32
            };
            Point::new(
                (axis(p0.x, p1.x, p2.x, p3.x) + 0.5) as i32,
                (axis(p0.y, p1.y, p2.y, p3.y) + 0.5) as i32,
            )
        };
        let mut last = at(0.0);
        for step in 1..=steps {
            let next = at(step as f32 / steps as f32);
            let _ = Line::new(last, next)
                .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, 1))
                .draw(target);
            last = next;
            drawn += 1;
        }
    }
    drawn
}

/// Lines joining each point to the next (embedded-graphics' `Line`, a sketch's
/// `drawLine`); returns how many.
fn polyline<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    points: impl IntoIterator<Item = Point>,
) -> u64 {
    use embedded_graphics::primitives::{Line, PrimitiveStyle};
    let mut points = points.into_iter();
    let Some(mut last) = points.next() else {
        return 0;
    };
    let mut drawn = 0;
    for next in points {
        let _ = Line::new(last, next)
            .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, 1))
            .draw(target);
        last = next;
        drawn += 1;
    }
    drawn
}

/// Cubic Bézier curves as a careful fixed-point sketch draws them; returns the lines drawn.
///
/// Each curve's polynomial stepped by forward differences in Q16.16 (three additions a
/// point, the differences from the control points once a curve; exact where `steps` is a
/// power of two up to 16), the points rounded and joined with `Line` as [`bezier_f32`].
pub fn bezier_fixed<D: DrawTarget<Color = Gray4>>(
    curves: &[[(i16, i16); 4]],
    place: impl Fn((i16, i16)) -> Point,
    steps: u32,
    target: &mut D,
) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let steps = steps.max(1);
    let n = i64::from(steps);
    let mut drawn = 0;
    for curve in curves {
        let [p0, p1, p2, p3] = curve.map(&place);
        // p(t) = a·t³ + b·t² + c·t + d; with h = 1/steps the differences, Q16.16, are
        // Δ = a·h³ + b·h² + c·h, Δ² = 6a·h³ + 2b·h², Δ³ = 6a·h³.
        let differences = |v0: i32, v1: i32, v2: i32, v3: i32| {
            let (v0, v1, v2, v3) = (i64::from(v0), i64::from(v1), i64::from(v2), i64::from(v3));
            let (a, b, c) = (
                -v0 + 3 * v1 - 3 * v2 + v3,
                3 * v0 - 6 * v1 + 3 * v2,
                3 * (v1 - v0),
            );
            let q = |numerator: i64, denominator: i64| ((numerator << 16) / denominator) as i32;
            [
                (v0 << 16) as i32,
                q(a + b * n + c * n * n, n * n * n),
                q(6 * a + 2 * b * n, n * n * n),
                q(6 * a, n * n * n),
            ]
        };
        let mut x = differences(p0.x, p1.x, p2.x, p3.x);
        let mut y = differences(p0.y, p1.y, p2.y, p3.y);
        let point =
            |x: [i32; 4], y: [i32; 4]| Point::new((x[0] + 0x8000) >> 16, (y[0] + 0x8000) >> 16);
        let start = point(x, y);
        let ahead = (0..steps).map(|_| {
            for v in [&mut x, &mut y] {
                v[0] += v[1];
                v[1] += v[2];
                v[2] += v[3];
            }
            point(x, y)
        });
        drawn += polyline(target, core::iter::once(start).chain(ahead));
    }
    drawn
}

/// A normal deviate as a sketch draws one: Box–Muller from two of the C library's
/// `rand` values (`state` its seed, advanced), with `micromath`'s logarithm, root and
/// cosine.
pub fn normal_f32(state: &mut u32) -> f32 {
    let u1 = (c_rand(state) as f32 + 1.0) / 32_769.0;
    let u2 = (c_rand(state) as f32 + 1.0) / 32_769.0;
    F32Ext::sqrt(-2.0 * F32Ext::ln(u1)) * F32Ext::cos(2.0 * core::f32::consts::PI * u2)
}

/// A mountain profile by 1D midpoint displacement as a sketch writes it, in `f32`.
///
/// `samples` (2ᵏ + 1) heights in an array, the ends at 0, each midpoint the mean of its
/// ends plus a normal deviate ([`normal_f32`]) times σ·roughnessˡᵉᵛᵉˡ; then each pixel
/// column's height scaled from the lowest and highest, and drawn as a column of ground
/// and one of sky with embedded-graphics' filled rectangles (`fillRect`). Returns the
/// heights made, or 0 for more than [`NAIVE_PROFILE`].
pub fn terrain_f32<D: DrawTarget<Color = Gray4>>(
    (roughness, sigma, seed): (f32, f32, u32),
    samples: usize,
    target: &mut D,
) -> u64 {
    if !(2..=NAIVE_PROFILE).contains(&samples) {
        return 0;
    }
    let mut heights = [0.0f32; NAIVE_PROFILE];
    let mut state = seed;
    let mut step = samples - 1;
    let mut scale = sigma;
    while step > 1 {
        let half = step / 2;
        let mut left = 0;
        while left + step < samples {
            let normal = normal_f32(&mut state);
            heights[left + half] = (heights[left] + heights[left + step]) * 0.5 + normal * scale;
            left += step;
        }
        step = half;
        scale *= roughness;
    }
    let (low, high) = heights[..samples]
        .iter()
        .fold((f32::MAX, f32::MIN), |(l, h), &v| (l.min(v), h.max(v)));
    let size = target.bounding_box().size;
    let (w, h) = (size.width as i32, size.height as i32);
    for x in 0..w {
        let sample = heights[x as usize * (samples - 1) / (w.max(2) - 1) as usize];
        let ground = ((sample - low) / (high - low).max(1e-6) * (h - 1) as f32) as i32 + 1;
        fill_rect_in(target, (x, 0), (1, h - ground), Gray4::BLACK);
        fill_rect_in(target, (x, h - ground), (1, ground), Gray4::WHITE);
    }
    samples as u64
}

/// A filled rectangle in `color` (Adafruit's `fillRect`).
fn fill_rect_in<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    (x, y): (i32, i32),
    (w, h): (i32, i32),
    color: Gray4,
) {
    use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
    let size = Size::new(w.max(0) as u32, h.max(0) as u32);
    let _ = Rectangle::new(Point::new(x, y), size)
        .into_styled(PrimitiveStyle::with_fill(color))
        .draw(target);
}

/// The three faces a sponge sketch paints of the cube at `(x, y, z)` with side `s`: those
/// at x + s, y + s and z + s, each in its grey, two filled triangles each (Adafruit's
/// `fillTriangle`), the corners placed by `pixel`. Inlined into each sponge sketch, so
/// the `f32` one's code is what it was when written out in it.
#[inline(always)]
fn cube_faces<T, D>(target: &mut D, (x, y, z): (T, T, T), s: T, pixel: impl Fn((T, T, T)) -> Point)
where
    T: Copy + Add<Output = T>,
    D: DrawTarget<Color = Gray4>,
{
    use embedded_graphics::primitives::{PrimitiveStyle, Triangle};
    let faces = [
        (
            [
                (x + s, y, z),
                (x + s, y + s, z),
                (x + s, y + s, z + s),
                (x + s, y, z + s),
            ],
            9,
        ),
        (
            [
                (x, y + s, z),
                (x + s, y + s, z),
                (x + s, y + s, z + s),
                (x, y + s, z + s),
            ],
            15,
        ),
        (
            [
                (x, y, z + s),
                (x + s, y, z + s),
                (x + s, y + s, z + s),
                (x, y + s, z + s),
            ],
            12,
        ),
    ];
    for (corners, grey) in faces {
        let [a, b, c, d] = corners.map(&pixel);
        let style = PrimitiveStyle::with_fill(Gray4::new(grey));
        let _ = Triangle::new(a, b, c).into_styled(style).draw(target);
        let _ = Triangle::new(a, c, d).into_styled(style).draw(target);
    }
}

/// The Menger sponge as a sketch draws it, in `f32`; returns the cubes drawn.
///
/// The cube split in 27 recursively, the 20 kept (all but the centre and the face
/// centres), each kept cube of the last level drawn as its three faces towards an
/// isometric camera, two filled triangles each (Adafruit's `fillTriangle`) in three
/// greys, back to front. The camera's axes are projected once (`micromath` sines), each
/// corner then three multiply-adds an axis; the sponge's projected box fitted to the target less a 2-pixel
/// margin, centred. Every face of a drawn cube is painted, hidden or not: a sketch does
/// not cull.
pub fn sponge_f32<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let (azimuth, elevation) = (45f32.to_radians(), 35.264f32.to_radians());
    let (sa, ca) = (F32Ext::sin(azimuth), F32Ext::cos(azimuth));
    let (se, ce) = (F32Ext::sin(elevation), F32Ext::cos(elevation));
    // Screen x right, y up: the images of the unit x, y and z axes.
    let axes = [(ca, -sa * se), (0.0, ce), (-sa, -ca * se)];
    let project = |(x, y, z): (f32, f32, f32)| {
        (
            x * axes[0].0 + y * axes[1].0 + z * axes[2].0,
            x * axes[0].1 + y * axes[1].1 + z * axes[2].1,
        )
    };
    // The unit cube's projected box.
    let (mut low, mut high) = ((f32::MAX, f32::MAX), (f32::MIN, f32::MIN));
    for corner in 0..8 {
        let p = project((
            (corner & 1) as f32,
            ((corner >> 1) & 1) as f32,
            ((corner >> 2) & 1) as f32,
        ));
        low = (low.0.min(p.0), low.1.min(p.1));
        high = (high.0.max(p.0), high.1.max(p.1));
    }
    let size = target.bounding_box().size;
    let (w, h) = (size.width as f32 - 4.0, size.height as f32 - 4.0);
    let scale = (w / (high.0 - low.0)).min(h / (high.1 - low.1));
    let left = 2.0 + (w - (high.0 - low.0) * scale) / 2.0;
    let bottom = 2.0 + h - (h - (high.1 - low.1) * scale) / 2.0;
    let pixel = |p: (f32, f32, f32)| {
        let (x, y) = project(p);
        Point::new(
            (left + (x - low.0) * scale + 0.5) as i32,
            (bottom - (y - low.1) * scale + 0.5) as i32,
        )
    };
    fn visit(
        corner: (f32, f32, f32),
        side: f32,
        depth: u32,
        draw: &mut dyn FnMut((f32, f32, f32), f32),
    ) -> u64 {
        if depth == 0 {
            draw(corner, side);
            return 1;
        }
        let third = side / 3.0;
        let mut drawn = 0;
        // Back to front for a camera at +x, +y, +z: the far thirds first.
        for i in 0..3 {
            for j in 0..3 {
                for k in 0..3 {
                    if u8::from(i == 1) + u8::from(j == 1) + u8::from(k == 1) >= 2 {
                        continue;
                    }
                    let at = (
                        corner.0 + i as f32 * third,
                        corner.1 + j as f32 * third,
                        corner.2 + k as f32 * third,
                    );
                    drawn += visit(at, third, depth - 1, draw);
                }
            }
        }
        drawn
    }
    let mut draw = |corner: (f32, f32, f32), s: f32| cube_faces(target, corner, s, pixel);
    visit((0.0, 0.0, 0.0), 1.0, order, &mut draw)
}

/// The Menger sponge as a careful fixed-point sketch draws it; returns the cubes drawn.
///
/// [`sponge_f32`]'s cubes, faces, greys and order, with the corners on an integer lattice
/// (3^order units a side), the isometric axes as Q16 constants, and the fit a Q32 scale
/// found once, so that a corner is three integer products an axis and one 64-bit one.
pub fn sponge_fixed<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    type Corner = (i32, i32, i32);
    let _ = target.clear(Gray4::BLACK);
    let n = 3i32.pow(order.min(6));
    // cos 45°, sin 45°·sin 35.264° and cos 35.264°: screen x right, y up.
    let (c, s, e) = (
        q16(core::f32::consts::FRAC_1_SQRT_2),
        q16(0.408_248_3),
        q16(0.816_496_6),
    );
    let project = |(x, y, z): Corner| ((x - z) * c, y * e - (x + z) * s);
    let (mut low, mut high) = ((i32::MAX, i32::MAX), (i32::MIN, i32::MIN));
    for corner in 0..8 {
        let p = project((corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
        let p = (p.0 * n, p.1 * n);
        low = (low.0.min(p.0), low.1.min(p.1));
        high = (high.0.max(p.0), high.1.max(p.1));
    }
    let size = target.bounding_box().size;
    let (w, h) = (i64::from(size.width) - 4, i64::from(size.height) - 4);
    let span = (i64::from(high.0 - low.0), i64::from(high.1 - low.1));
    // Pixels a projected unit, Q32, the smaller axis's; the box centred less 2 pixels.
    let scale = ((w << 32) / span.0).min((h << 32) / span.1);
    let left = (2 << 32) + ((w << 32) - span.0 * scale) / 2;
    let bottom = ((2 + h) << 32) - ((h << 32) - span.1 * scale) / 2;
    let pixel = |corner: Corner| {
        let (x, y) = project(corner);
        Point::new(
            ((left + i64::from(x - low.0) * scale + (1 << 31)) >> 32) as i32,
            ((bottom - i64::from(y - low.1) * scale + (1 << 31)) >> 32) as i32,
        )
    };
    fn visit(corner: Corner, side: i32, depth: u32, draw: &mut dyn FnMut(Corner, i32)) -> u64 {
        if depth == 0 {
            draw(corner, side);
            return 1;
        }
        let third = side / 3;
        let mut drawn = 0;
        for i in 0..3 {
            for j in 0..3 {
                for k in 0..3 {
                    if u8::from(i == 1) + u8::from(j == 1) + u8::from(k == 1) >= 2 {
                        continue;
                    }
                    let at = (
                        corner.0 + i * third,
                        corner.1 + j * third,
                        corner.2 + k * third,
                    );
                    drawn += visit(at, third, depth - 1, draw);
                }
            }
        }
        drawn
    }
    let mut draw = |corner: Corner, t: i32| cube_faces(target, corner, t, pixel);
    visit((0, 0, 0), n, order.min(6), &mut draw)
}

/// A landscape as a sketch draws it, in `f32`; returns the heights made.
///
/// `side`² heights by diamond-square, then each pixel read from them bilinearly, banded
/// and hill-shaded as [`relief_f32`] does; nothing (0) for a side other than 2ᵏ + 1 up to
/// [`NAIVE_LANDSCAPE_SIDE`]. The corners at 0; each diamond and square step adds a normal
/// deviate ([`normal_f32`]) times σ·roughnessˡᵉᵛᵉˡ to the mean of its four (or three, at
/// an edge) neighbours.
pub fn landscape_f32<D: DrawTarget<Color = Gray4>>(
    (roughness, sigma, seed): (f32, f32, u32),
    side: usize,
    target: &mut D,
) -> u64 {
    if !(3..=NAIVE_LANDSCAPE_SIDE).contains(&side) || !(side - 1).is_power_of_two() {
        return 0;
    }
    let mut heights = [0.0f32; NAIVE_LANDSCAPE_SIDE * NAIVE_LANDSCAPE_SIDE];
    let mut state = seed;
    let mut normal = || normal_f32(&mut state);
    let at = |x: usize, y: usize| y * side + x;
    let (mut step, mut scale) = (side - 1, sigma);
    while step > 1 {
        let half = step / 2;
        // Diamonds: each square's centre from its four corners.
        for y in (half..side).step_by(step) {
            for x in (half..side).step_by(step) {
                let mean = (heights[at(x - half, y - half)]
                    + heights[at(x + half, y - half)]
                    + heights[at(x - half, y + half)]
                    + heights[at(x + half, y + half)])
                    * 0.25;
                heights[at(x, y)] = mean + normal() * scale;
            }
        }
        // Squares: each edge midpoint from its neighbours inside the grid.
        for y in (0..side).step_by(half) {
            let first = if (y / half) % 2 == 0 { half } else { 0 };
            for x in (first..side).step_by(step) {
                let (mut sum, mut count) = (0.0, 0.0);
                for (dx, dy) in [(-1i32, 0i32), (1, 0), (0, -1), (0, 1)] {
                    let (nx, ny) = (x as i32 + dx * half as i32, y as i32 + dy * half as i32);
                    if (0..side as i32).contains(&nx) && (0..side as i32).contains(&ny) {
                        sum += heights[at(nx as usize, ny as usize)];
                        count += 1.0;
                    }
                }
                heights[at(x, y)] = sum / count + normal() * scale;
            }
        }
        step = half;
        scale *= roughness;
    }
    relief_f32(&heights[..side * side], side, target);
    (side * side) as u64
}

/// A grid of heights drawn from above as a sketch does, in `f32`.
///
/// Each pixel's height read bilinearly, banded (water, sand, grass, rock, snow) by where
/// it lies between the lowest and highest, and above the sea lit by the slope towards the
/// upper left; each pixel a grey through `draw_iter`.
pub fn relief_f32<D: DrawTarget<Color = Gray4>>(heights: &[f32], side: usize, target: &mut D) {
    const BANDS: [(f32, f32); 6] = [
        (0.0, 0.2),
        (80.0 / 255.0, 0.4),
        (100.0 / 255.0, 0.75),
        (110.0 / 255.0, 0.5),
        (180.0 / 255.0, 0.45),
        (225.0 / 255.0, 0.95),
    ];
    let (low, high) = heights
        .iter()
        .fold((f32::MAX, f32::MIN), |(l, h), &v| (l.min(v), h.max(v)));
    let spread = (high - low).max(1e-6);
    let size = target.bounding_box().size;
    let last = (side - 1) as f32;
    let height = |x: usize, y: usize| heights[y.min(side - 1) * side + x.min(side - 1)];
    for py in 0..size.height {
        for px in 0..size.width {
            let gx = px as f32 * last / (size.width.max(2) - 1) as f32;
            let gy = py as f32 * last / (size.height.max(2) - 1) as f32;
            let (x, y) = (gx as usize, gy as usize);
            let (fx, fy) = (gx - x as f32, gy - y as f32);
            let top = height(x, y) * (1.0 - fx) + height(x + 1, y) * fx;
            let bottom = height(x, y + 1) * (1.0 - fx) + height(x + 1, y + 1) * fx;
            let level = ((top * (1.0 - fy) + bottom * fy) - low) / spread;
            let band = BANDS.iter().rev().find(|(start, _)| level >= *start);
            let mut grey = band.map_or(0.0, |(_, grey)| *grey);
            if level >= 100.0 / 255.0 {
                let slope = (height(x.saturating_sub(1), y.saturating_sub(1))
                    - height(x + 1, y + 1))
                    * last
                    / spread;
                grey *= (1.0 - slope / 8.0).clamp(0.5, 1.4);
            }
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(px as i32, py as i32),
                self::grey(grey),
            )));
        }
    }
}
