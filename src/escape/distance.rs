//! Distance estimation: how far an escaping point lies from the set, d ≈ |z|·ln|z| / |dz|,
//! so strands thinner than a pixel can be drawn as the set (Fractint's `distest`).
//!
//! The orbit is run again from its start, in Q28 with 32×32 → 64-bit products for the
//! 32-bit tiers and in Q60 with products' high words (perturbation's finish: within 2⁻⁵⁵ a
//! product) for `Deep` and `Wide`, one copy of the code each, with the derivative dz
//! (dz ← 2·z·dz + 1 for the Mandelbrot set, from
//! dz₁ = 1; dz ← 2·z·dz for a Julia set, from dz₀ = 1) carried beside it as a mantissa pair
//! and a shared exponent, since it grows as fast as the orbit runs (`derivative`'s
//! `LooseDerivative`, renormalised only when it leaves a window). A perturbed pixel
//! carries its derivative beside its differences instead (`perturbation`), from the
//! series' own derivative at the skip, each step from the full point Zₘ + δ in a mantissa
//! and exponent of its own: at a deep zoom z passes far closer to 0 than any fixed point
//! holds while dz is huge. Past the escape both go on to |z| ≥ 256, where the estimate
//! holds, and d is compared through the log table: no floats.

use super::arithmetic::{Arithmetic, HighWords};
use super::derivative::LooseDerivative;
use super::estimate::Estimate;
use super::kernel::{Kernel, Orbit};
use super::view::Tier;
use crate::math::log::{log2, LOG2_FRAC_BITS};
use crate::math::wide::{mul_i32_wide, mul_u32_wide, square_i32_wide};

/// log₂(ln 2 / 2) in Q16: ln|z| = log₂|z|² · ln 2 / 2.
const LOG2_HALF_LN2: i64 = -100_189;

/// Most steps the estimate takes past the escape to reach |z| ≥ 256.
const STEPS_PAST_ESCAPE: u32 = 32;

/// The escape radius of the estimate, in Q20.
const RADIUS_Q20: i64 = 256 << 20;

/// Below this |z| (Q20) the next point of the walk past the escape is stepped in 32 bits.
const NARROW_NEXT_Q20: i64 = 32 << 20;

impl Kernel {
    /// The estimated distance of the orbit from `first` (z₁ = c for the Mandelbrot set,
    /// the pixel z₀ for a Julia set; Q60), d ≈ |z|·ln|z| / |dz| over the pixel spacing;
    /// `None` if the orbit does not escape by the cap. Also the steps it took.
    fn log2_distance<const WIDE: bool>(
        &self,
        first: (i64, i64),
        c: (i64, i64),
    ) -> (Option<Distance>, u32) {
        let mandelbrot = self.julia.is_none();
        let start = (u32::from(mandelbrot), self.max);
        // z in Q60 (`WIDE`: products' high words) or Q28 (32-bit values, 64-bit products).
        let (escaped, k) = if WIDE {
            q60_orbit(first, c, start, LooseDerivative::one(mandelbrot))
        } else {
            let q28 = |v: i64| (v >> 32) as i32;
            let (escaped, k) = q28_orbit(
                (q28(first.0), q28(first.1)),
                (q28(c.0), q28(c.1)),
                start,
                LooseDerivative::one(mandelbrot),
            );
            let q60 = |v: i32| i64::from(v) << 32;
            (escaped.map(|((x, y), dz)| ((q60(x), q60(y)), dz)), k)
        };
        let Some((z, dz)) = escaped else {
            return (None, k);
        };
        let (estimate, steps) = log2_pixels_past_escape((z, k), c, dz, self.spacing_log2);
        (estimate, k + steps)
    }

    /// An escaped `orbit` from `first` (Q60) as distance estimation has it (see
    /// [`estimated`]), the estimate's steps added.
    ///
    /// The run again starts from the point of a mirrored pair the fast render computes, so
    /// both of a pair get one estimate, whichever is computed: a Mandelbrot point's twin
    /// in the upper half-plane (where the orbit takes it too), and of a Julia set's z₀ and
    /// −z₀ (whose orbits meet at z₁) the one above the real axis, or right of 0 on it. The
    /// derivative's products round down, so from the other of a pair its last bits differ.
    pub(super) fn estimated(&self, orbit: Orbit, first: (i64, i64), c: (i64, i64)) -> Orbit {
        let Some(estimate) = self.estimate else {
            return orbit;
        };
        let first = match self.julia {
            None if self.outside.symmetric() => (first.0, first.1.abs()),
            Some(_) if first.1 < 0 || (first.1 == 0 && first.0 < 0) => (-first.0, -first.1),
            _ => first,
        };
        // A Mandelbrot point's z₁ is c.
        let c = if self.julia.is_none() { first } else { c };
        let (distance, steps) = match self.tier {
            Tier::Narrow | Tier::Medium | Tier::Standard => self.log2_distance::<false>(first, c),
            _ => self.log2_distance::<true>(first, c),
        };
        estimated(estimate, orbit, distance, steps, self.inside)
    }
}

/// An orbit's point where it escaped and its derivative there (`None` at the cap), and
/// the steps counted.
type Escaped<T> = (Option<((T, T), LooseDerivative)>, u32);

/// The orbit from `z` (Q60, products' high words) with the derivative `d` carried
/// beside it, counting steps from `k` up to `max`: the point where it escapes and its
/// derivative there, or `None` at the cap; and the steps counted.
///
/// Each turn's products are taken together, 2xy before the escape test: the compiler
/// would otherwise share a value's 32-bit halves between the squares (at the end of one
/// turn) and 2xy (in the next), carry them as 64-bit values and multiply them 64 × 64.
#[inline(always)]
fn q60_orbit(
    mut z: (i64, i64),
    c: (i64, i64),
    (mut k, max): (u32, u32),
    mut d: LooseDerivative,
) -> Escaped<i64> {
    loop {
        let (x2, y2) = (HighWords::square(z.0), HighWords::square(z.1));
        let xy = HighWords::twice_xy(z.0, z.1, x2, y2);
        if HighWords::escapes(x2, y2) {
            return (Some((z, d)), k);
        }
        if k >= max {
            return (None, k);
        }
        let high = |v: i64| (v >> 32) as i32;
        d.step_q28(high(z.0), high(z.1));
        z = (HighWords::to_value(x2 - y2) + c.0, xy + c.1);
        k += 1;
    }
}

/// The orbit from `z` (Q28, 32×32 → 64-bit products) with the derivative `d` carried
/// beside it, as [`q60_orbit`]: it escapes where x² + y² > 4, each square rounded down to
/// Q28. The squares are taken from the magnitudes, so that the next turn's products keep
/// their 32-bit factors, and in 32 bits: a part beyond 2 (2²⁹) escapes by its square alone
/// (at least 4 + 2⁻²⁶), and below it each square is at most 4.
#[inline(always)]
fn q28_orbit(
    (mut x, mut y): (i32, i32),
    (cr, ci): (i32, i32),
    (mut k, max): (u32, u32),
    mut d: LooseDerivative,
) -> Escaped<i32> {
    loop {
        let (ax, ay) = (x.unsigned_abs(), y.unsigned_abs());
        if ax.max(ay) > 2 << 28 {
            return (Some(((x, y), d)), k);
        }
        let square = |v: u32| (mul_u32_wide(v, v) >> 28) as u32;
        let (x2, y2) = (square(ax), square(ay));
        if x2 + y2 > 4 << 28 {
            return (Some(((x, y), d)), k);
        }
        if k >= max {
            return (None, k);
        }
        d.step_q28(x, y);
        // |z| ≤ 2 and |c| < 3.5: both parts stay below 8 (2³¹ in Q28).
        let xy = (mul_i32_wide(x, y) >> 27) as i32;
        (x, y) = (x2 as i32 - y2 as i32 + cr, xy + ci);
        k += 1;
    }
}

/// The steps from the point whose Green's function is the pixel's to the `n`th point of an
/// orbit counted from z₀ (0 for the Mandelbrot set, the pixel for a Julia set), so that
/// the pixel's G is lim ln|z| / 2^steps: for a Julia set G(z₀) itself, n; for the
/// Mandelbrot set G(c) = G_c(z₁) (the Böttcher map Φ(c) = Φ_c(c)), from z₁ = c, n − 1.
/// Counted from z₀ the Mandelbrot set's G would be half its own, and the distance it
/// proves (see [`proven_far`]) too far where G is large.
const fn green_steps(n: u32, mandelbrot: bool) -> u32 {
    n.saturating_sub(mandelbrot as u32)
}

/// What an escaped pixel's `orbit` becomes at `distance` from the set, with `steps` more
/// taken: its value as `estimate` has it ([`Estimate::value`]), and how far the set is
/// proven to be.
pub(super) fn estimated(
    estimate: Estimate,
    orbit: Orbit,
    distance: Option<Distance>,
    steps: u32,
    inside: u32,
) -> Orbit {
    let value = estimate
        .value(distance.map(|d| d.log2_pixels), inside)
        .unwrap_or(orbit.dwell);
    Orbit {
        dwell: value | u32::from(distance.map_or(0, |d| d.far)) << 16,
        iterations: orbit.iterations.saturating_add(steps),
    }
}

/// An escaped point's distance from the set, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Distance {
    /// log₂ of the estimate d = |z|·ln|z| / |dz|, Q16.
    pub(super) log2_pixels: i64,
    /// The set is at least 2^(`far`/4) pixels away: proven from d (see [`proven_far`]);
    /// 0 proves nothing.
    pub(super) far: u8,
}

/// The estimated distance (see [`Distance`]) of an orbit that escaped at z, the `n`th
/// point of its orbit (z₀ = 0 for the Mandelbrot set, whose derivative adds 1 at each
/// step, the pixel for a Julia set), with derivative `dz` (z and c in Q60), the pixel
/// spacing 2^`spacing_log2` (Q16), taken on to |z| ≥ 256 in Q20 as the smooth value goes
/// (`smooth_value`); also the steps that took.
///
/// Which set it is comes from the derivative (see [`green_steps`]): a flag the caller
/// kept across the orbit's loop for it cost that loop a register on Cortex-M3.
pub(super) fn log2_pixels_past_escape(
    ((x, y), n): ((i64, i64), u32),
    c: (i64, i64),
    mut dz: LooseDerivative,
    spacing_log2: i32,
) -> (Option<Distance>, u32) {
    let green_n = green_steps(n, dz.adds_one());
    let q20 = |v: i64| v >> 40;
    let (cr, ci) = (q20(c.0), q20(c.1));
    let (x, y) = (q20(x), q20(y));
    let ((x, y), steps) = walk_past_escape((x, y), (cr, ci), &mut dz);
    // |z|² in Q16 from Q8 parts (|z| < 2¹⁷ after the last step).
    let (x, y) = (x >> 12, y >> 12);
    let estimate = (|| {
        let log_square = i64::from(log2(square_of_modulus(x, y), 16)?);
        let log_log = i64::from(log2(u64::try_from(log_square).ok()?, LOG2_FRAC_BITS)?);
        let log_ln = log_log + LOG2_HALF_LN2;
        let log2_pixels = log_square / 2 + log_ln - dz.log2_magnitude()? - i64::from(spacing_log2);
        // G = ln|z| / 2^n, n steps from the Green's function's point.
        let log2_green = log_ln - (i64::from(green_n + steps) << LOG2_FRAC_BITS);
        Some(Distance {
            log2_pixels,
            far: proven_far(log2_pixels, log2_green),
        })
    })();
    (estimate, steps)
}

/// The walk past the escape (z and c in Q20): z ← z² + c with dz stepped beside it
/// ([`LooseDerivative::step_q20`]) until |z| ≥ 256 or a part of z is beyond 256, at most
/// [`STEPS_PAST_ESCAPE`] steps; the point it ends at and the steps taken. Each step rounds
/// z² down to Q20, its parts taken apart.
///
/// Parts within 2²⁸ are stepped as 32-bit values. While |z| < 32 the next point's parts
/// are within 2³⁰ + |c| (|c| < 12 in a view), so they stay 32-bit values, and a part past
/// 2²⁸ ends the walk at the next test; from |z| ≥ 32 the next point is beyond 32² − |c| >
/// 256, where the walk ends: it is taken in 64 bits and returned at once.
#[inline(always)]
fn walk_past_escape(
    (x, y): (i64, i64),
    (cr, ci): (i64, i64),
    dz: &mut LooseDerivative,
) -> ((i64, i64), u32) {
    let narrow = |v: i64| (v + RADIUS_Q20 - 1) as u64 <= 2 * RADIUS_Q20 as u64 - 2;
    if !(narrow(x) && narrow(y)) {
        return ((x, y), 0);
    }
    let (mut xs, mut ys) = (x as i32, y as i32);
    let (cr, ci) = (cr as i32, ci as i32);
    let mut steps = 0;
    loop {
        let (x2, y2) = (square_i32_wide(xs), square_i32_wide(ys));
        let modulus = x2 + y2;
        if steps >= STEPS_PAST_ESCAPE || modulus >= RADIUS_Q20 * RADIUS_Q20 {
            return ((i64::from(xs), i64::from(ys)), steps);
        }
        let xy = mul_i32_wide(xs, ys);
        dz.step_q20(xs, ys);
        steps += 1;
        let (re, im) = ((x2 - y2) >> 20, xy >> 19);
        if modulus >= NARROW_NEXT_Q20 * NARROW_NEXT_Q20 {
            return ((re + i64::from(cr), im + i64::from(ci)), steps);
        }
        (xs, ys) = (re as i32 + cr, im as i32 + ci);
    }
}

/// |z|² = x² + y² of parts below 2²⁵ (|z| < 2¹⁷ in Q8): 64-bit products where there is a
/// long multiply, 32-bit factors' products from 16-bit halves elsewhere (ARMv6-M, where a
/// 64-bit product is a library call).
#[inline(always)]
fn square_of_modulus(x: i64, y: i64) -> u64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        // Both parts fit 32 bits: the casts keep them.
        (mul_i32_wide(x as i32, x as i32) + mul_i32_wide(y as i32, y as i32)).unsigned_abs()
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        (x * x + y * y).unsigned_abs()
    }
}

/// How far the set is proven to be from a point whose estimate is 2^`log2_pixels` pixels
/// and whose Green's function G is 2^`log2_green` (both Q16), in quarters of log₂
/// (0: nothing proven).
///
/// Koebe's quarter theorem on the Böttcher map bounds the distance δ to the set by
/// d·(1 − e^(−2G))/(4G) < δ < 2d·sinh(G)/G, where d = G/|∇G| is the estimate at the
/// limit (d/2 < δ < 2d as G → 0). The lower bound is taken by classes of G
/// ([`KOEBE_CLASSES`]), each below the bound over its range by more than the log table's
/// errors; every point of a view (|re|, |im| ≤ 3.5) has G below 1.8.
fn proven_far(log2_pixels: i64, log2_green: i64) -> u8 {
    let Some(&(_, below)) = KOEBE_CLASSES.iter().find(|&&(most, _)| log2_green <= most) else {
        return 0;
    };
    // Quarters of log₂, rounded down.
    ((log2_pixels - below) >> (LOG2_FRAC_BITS - 2)).clamp(0, i64::from(u8::MAX)) as u8
}

/// Koebe's lower bound by classes of G, for [`proven_far`]: the largest log₂ G of each
/// (Q16, rounded down) and the bound taken there, d/2^b with b in sixteenths. Over G up to
/// 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.55, 0.79, 1, 1.2, 1.5 and 1.9, −log₂((1 − e^(−2G))/(4G))
/// rises to 1.072, 1.142, 1.211, 1.279, 1.411, 1.539, 1.721, 1.993, 2.210, 2.400, 2.659 and
/// 2.959, and each b is above it by 0.07 to 0.12.
const KOEBE_CLASSES: [(i64, i64); 12] = {
    const SIXTEENTH: i64 = 1 << (LOG2_FRAC_BITS - 4);
    [
        (-283_242, 19 * SIXTEENTH),
        (-217_706, 20 * SIXTEENTH),
        (-179_370, 21 * SIXTEENTH),
        (-152_170, 22 * SIXTEENTH),
        (-113_834, 24 * SIXTEENTH),
        (-86_634, 26 * SIXTEENTH),
        (-56_525, 29 * SIXTEENTH),
        (-22_288, 33 * SIXTEENTH),
        (0, 37 * SIXTEENTH),
        (17_238, 40 * SIXTEENTH),
        (38_336, 44 * SIXTEENTH),
        (60_685, 49 * SIXTEENTH),
    ]
};

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::escape::kernel::Periodicity;
    use crate::escape::view::{Fractal, View};
    use crate::math::Coord;
    use proptest::prelude::*;
    use proptest::test_runner::{TestRng, TestRunner};

    /// The Q28 orbit escapes, stops at the cap and steps its derivative as its rule says:
    /// a model in 128 bits escapes where x² + y² > 4, each square rounded down to Q28, and
    /// steps z ← z² + c (2xy rounded down too); from points anywhere in 32 bits, near
    /// parts of 2 (where one square is 4 and the sum reaches 2³¹), just beyond 2 and near
    /// 0, c within ±3.5. It fails with the 32-bit squares taken from parts up to 2 − 2⁻²⁸
    /// or 3.
    #[test]
    fn the_q28_orbit_follows_its_rule() {
        type End = (Option<((i32, i32), LooseDerivative)>, u32);
        let model = |(x, y): (i32, i32),
                     (cr, ci): (i32, i32),
                     (k, max): (u32, u32),
                     mut d: LooseDerivative|
         -> End {
            let (mut x, mut y, mut k) = (i128::from(x), i128::from(y), k);
            loop {
                let (x2, y2) = ((x * x) >> 28, (y * y) >> 28);
                let z = (i32::try_from(x).unwrap(), i32::try_from(y).unwrap());
                if x2 + y2 > 1 << 30 {
                    return (Some((z, d)), k);
                }
                if k >= max {
                    return (None, k);
                }
                d.step_q28(z.0, z.1);
                (x, y) = (x2 - y2 + i128::from(cr), ((x * y) >> 27) + i128::from(ci));
                k += 1;
            }
        };
        let two = 1i32 << 29;
        let part = prop_oneof![
            any::<i32>(),
            two - 4..two + 4,
            -two - 4..-two + 4,
            -(1i32 << 28)..1 << 28,
            -(1i32 << 14)..1 << 14,
            two..two + (1 << 28),
            Just(two),
            Just(-two),
        ];
        let c = -(7i32 << 27)..7 << 27;
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(
                    (part.clone(), part),
                    (c.clone(), c),
                    0u32..2,
                    0u32..40,
                    any::<bool>(),
                ),
                |(z, c, k, max, mandelbrot)| {
                    let d = LooseDerivative::one(mandelbrot);
                    prop_assert_eq!(q28_orbit(z, c, (k, max), d), model(z, c, (k, max), d));
                    Ok(())
                },
            )
            .unwrap();
        // Both parts at 2: the squares' sum is 2³¹, and the point escapes.
        let d = LooseDerivative::one(true);
        assert_eq!(q28_orbit((two, two), (0, 0), (1, 8), d).1, 1);
        assert!(q28_orbit((two, two), (0, 0), (1, 8), d).0.is_some());
        // Both parts at 1.45 · 2: their squares alone would pass 2³².
        let beyond = two + two / 100 * 45;
        assert_eq!(q28_orbit((beyond, beyond), (0, 0), (1, 8), d).1, 1);
    }

    /// The walk past the escape ends where its rule says, with the derivative stepped at
    /// the same points: a model in 128 bits steps z ← z² + c (z² rounded down to Q20, its
    /// parts apart) while |z| < 256, both parts are within 2²⁸ and fewer than
    /// [`STEPS_PAST_ESCAPE`] steps are taken; from points of every size (inside 2⁻², near
    /// 32 and 256 where the walk changes its arithmetic, and beyond 256) and c within the
    /// Q60 range's ±8 (and near −8, where |z| = 16 steps to below 256).
    #[test]
    fn the_walk_past_the_escape_follows_its_rule() {
        let model = |(x, y): (i64, i64), (cr, ci): (i64, i64), dz: &mut LooseDerivative| {
            let narrow = |v: i128| v.unsigned_abs() < 1 << 28;
            let mut steps = 0;
            let (mut x, mut y) = (i128::from(x), i128::from(y));
            while steps < STEPS_PAST_ESCAPE && x * x + y * y < 1 << 56 && narrow(x) && narrow(y) {
                dz.step_q20(x as i32, y as i32);
                (x, y) = (
                    ((x * x - y * y) >> 20) + i128::from(cr),
                    ((2 * x * y) >> 20) + i128::from(ci),
                );
                steps += 1;
            }
            (
                (i64::try_from(x).unwrap(), i64::try_from(y).unwrap()),
                steps,
            )
        };
        let part = prop_oneof![
            1 => -(1i64 << 29)..1 << 29,
            1 => -(1i64 << 26)..1 << 26,
            1 => -(32i64 << 20) - 4096..-(32 << 20) + 4096,
            1 => (32i64 << 20) - 4096..(32 << 20) + 4096,
            1 => (22i64 << 20)..(23 << 20),
            1 => (16i64 << 20) - 4096..(16 << 20) + 4096,
            1 => -(1i64 << 20)..1 << 20,
            2 => -(1i64 << 21)..1 << 21,
            1 => Just((1i64 << 28) - 1),
            1 => Just(-(1i64 << 28) + 1),
        ];
        let c = prop_oneof![
            -(8i64 << 20)..8 << 20,
            -(1i64 << 20)..1 << 20,
            -(8i64 << 20)..-(7 << 20),
        ];
        let config = ProptestConfig {
            cases: 4096,
            ..ProptestConfig::default()
        };
        let rng = TestRng::deterministic_rng(config.rng_algorithm);
        let mut runner = TestRunner::new_with_rng(config, rng);
        let ends = core::cell::Cell::new([0u32; 3]);
        runner
            .run(
                &((part.clone(), part), (c.clone(), c), any::<bool>()),
                |(z, c, mandelbrot)| {
                    let (mut walked, mut modelled) = (
                        LooseDerivative::one(mandelbrot),
                        LooseDerivative::one(mandelbrot),
                    );
                    let end = walk_past_escape(z, c, &mut walked);
                    prop_assert_eq!(end, model(z, c, &mut modelled));
                    prop_assert_eq!(walked, modelled);
                    let mut seen = ends.get();
                    seen[usize::from(end.1 > 0) + usize::from(end.1 > 2)] += 1;
                    ends.set(seen);
                    Ok(())
                },
            )
            .unwrap();
        // Walks of none, few and several steps were all seen.
        let ends = ends.get();
        assert!(ends.iter().all(|&n| n > 10), "{ends:?}");
    }

    /// The distance proven is below the lower bound Koebe's theorem gives, d·(1 −
    /// e^(−2G))/(4G), in f64, over G from 2⁻²⁰ to 1.9 and estimates from 2⁻⁴ to 2⁴⁰
    /// pixels, and within a factor 2^1.5 of it (the classes' steps and the quarters);
    /// past G = 1.9 (outside every view) nothing is proven.
    #[test]
    fn the_distance_proven_is_below_koebes_bound() {
        let q16 = |v: f64| (v * 65536.0).floor() as i64;
        let mut checked = 0;
        for g_step in 0..=400 {
            let green = 2f64.powf(-20.0 + f64::from(g_step) * (20.0 + 1.899f64.log2()) / 400.0);
            for d_step in 0..=88 {
                let log2_d = -4.0 + f64::from(d_step) / 2.0;
                let far = proven_far(q16(log2_d), q16(green.log2()));
                let bound = 2f64.powf(log2_d) * (1.0 - (-2.0 * green).exp()) / (4.0 * green);
                let proven = 2f64.powf(f64::from(far) / 4.0);
                if far > 0 {
                    assert!(
                        proven <= bound,
                        "G {green} d 2^{log2_d}: {proven} > {bound}"
                    );
                    checked += 1;
                }
                if bound >= 2.0 && far < u8::MAX {
                    assert!(
                        proven * 2f64.powf(1.5) >= bound,
                        "G {green}: {proven} ≪ {bound}"
                    );
                }
            }
        }
        assert!(checked > 20_000);
        assert_eq!(proven_far(q16(30.0), q16(1.95f64.log2())), 0);
    }

    /// What an estimate proves holds for the point's Green's function as the theory has
    /// it: for the Mandelbrot set G(c) = lim ln|zₙ| / 2ⁿ⁻¹ (z₁ = c, G(c) = G_c(c)), for a
    /// Julia set G(z₀) = lim ln|zₙ| / 2ⁿ. An f64 model runs each orbit to |z| = 10⁵⁰ with
    /// its derivative and takes Koebe's lower bound d·(1 − e^(−2G))/(4G) on the distance;
    /// the distance proven (2^(far/4) pixels) must be below it, on a grid over a view's
    /// range (|re|, |im| ≤ 3.5) and for a Julia set's z₀ over the same. It fails with G
    /// taken from 2ⁿ for the Mandelbrot set (half of it), which proves too much far out.
    #[test]
    fn the_distance_proven_holds_for_the_sets_green_function() {
        let spacing_log2 = -6.0;
        let model = |z0: (f64, f64), c: (f64, f64), mandelbrot: bool| -> Option<f64> {
            let (mut x, mut y) = z0;
            let (mut dx, mut dy) = (f64::from(u8::from(!mandelbrot)), 0.0);
            let mut n = 0;
            while x * x + y * y < 1e100 {
                if n > 200 {
                    return None;
                }
                (dx, dy) = (
                    2.0 * (x * dx - y * dy) + f64::from(u8::from(mandelbrot)),
                    2.0 * (x * dy + y * dx),
                );
                (x, y) = (x * x - y * y + c.0, 2.0 * x * y + c.1);
                n += 1;
            }
            let modulus = (x * x + y * y).sqrt();
            // zₙ, counted from z₀ = 0 for the Mandelbrot set: G(c) takes 2ⁿ⁻¹.
            let green = modulus.ln() / 2f64.powi(n - i32::from(mandelbrot));
            let d = modulus * modulus.ln() / (dx * dx + dy * dy).sqrt();
            let bound = d * (1.0 - (-2.0 * green).exp()) / (4.0 * green);
            Some(bound / 2f64.powf(spacing_log2))
        };
        // Views 4 wide over 256 pixels: a spacing of 2⁻⁶.
        let julia = (-0.8, 0.156);
        let kernel = |fractal| {
            let size = embedded_graphics::geometry::Size::new(256, 256);
            let view = View::new(
                fractal,
                (Coord::default(), Coord::default()),
                Coord::from_f64(4.0).unwrap(),
                size,
                1000,
            );
            Kernel::new(&view.unwrap(), Periodicity::Exact)
        };
        let (mandelbrot_kernel, julia_kernel) = (
            kernel(Fractal::Mandelbrot),
            kernel(Fractal::Julia {
                re: Coord::from_f64(julia.0).unwrap(),
                im: Coord::from_f64(julia.1).unwrap(),
            }),
        );
        assert_eq!(mandelbrot_kernel.spacing_log2, -6 << LOG2_FRAC_BITS);
        let q60 = |(x, y): (f64, f64)| {
            let q60 = |v: f64| Coord::from_f64(v).unwrap().to_bits();
            (q60(x), q60(y))
        };
        let estimate = |first: (f64, f64), c: (f64, f64), mandelbrot: bool| {
            let kernel = if mandelbrot {
                &mandelbrot_kernel
            } else {
                &julia_kernel
            };
            kernel.log2_distance::<false>(q60(first), q60(c)).0
        };
        let mut proofs = [0; 2];
        for i in -35..=35 {
            for j in -35..=35 {
                let p = (f64::from(i) / 10.0 + 0.003, f64::from(j) / 10.0 + 0.007);
                // A Mandelbrot point's orbit is run again from z₁ = c.
                for (mandelbrot, z0, c) in [(true, (0.0, 0.0), p), (false, p, julia)] {
                    let (Some(distance), Some(bound)) =
                        (estimate(p, c, mandelbrot), model(z0, c, mandelbrot))
                    else {
                        continue;
                    };
                    if distance.far > 0 {
                        let proven = 2f64.powf(f64::from(distance.far) / 4.0);
                        assert!(
                            proven <= bound,
                            "{p:?} (Mandelbrot: {mandelbrot}): {proven} > {bound}"
                        );
                        proofs[usize::from(mandelbrot)] += 1;
                    }
                }
            }
        }
        assert!(proofs.iter().all(|&n| n > 1000), "{proofs:?}");
    }
}
