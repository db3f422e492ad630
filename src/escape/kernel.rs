//! The dwell of one pixel: z ← z² + c in the view's fixed-point tier.
//!
//! Overflow cannot happen, by invariant: an orbit is only squared while |z|² ≤ 4 (so |x|,
//! |y| ≤ 2), and every c is within ±3.5 (checked by the view), so the next value is below
//! 7.5 and its square below 57: inside every tier's range (Q12 in i32, Q28 in i32 with i64
//! squares, Q60 in i64 with i128 squares). A Julia start outside radius 2 escapes at once
//! (|z₁| ≥ |z₀|² − |k| > 2 because |k| ≤ 2) and is never squared.
//!
//! The deep tier's 64×64→128 products are built from 32-bit halves (see `mul_wide`), since
//! an i128 multiply is a library call on Cortex-M.
//!
//! Mirrored points stay mirrored exactly: 2xy is truncated toward zero, the only product
//! whose sign depends on y.

use super::view::{Fractal, Tier, View};
#[cfg(tinyfractal_no_long_multiply)]
use crate::real::twice_product_by_squares;
use crate::real::{mul_i32_wide, mul_wide, shift_round_i64};

/// How an orbit that repeats is recognised (Brent: compare with a point saved at
/// iterations 1, 2, 4, 8, ...).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Periodicity {
    /// Only an exact repeat of the fixed-point orbit: it can never change a dwell.
    Exact,
    /// Within a tolerance (Q60 bits), tied to the pixel spacing: faster, may differ.
    Within(i64),
}

/// A pixel's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Orbit {
    /// 1..=max; max means "did not escape".
    pub(crate) dwell: u32,
    /// z ← z² + c steps taken.
    pub(crate) iterations: u32,
}

/// The dwell of the point `point` (Q60, within ±3.5 as the view guarantees) of `view`.
/// Everything per pixel is 64-bit or narrower: a 128-bit step is a dozen instructions on a
/// 32-bit core.
pub(crate) fn dwell(view: &View, point: (i64, i64), periodicity: Periodicity) -> Orbit {
    let max = view.max_iterations;
    let (c, z0) = match view.fractal {
        Fractal::Mandelbrot => {
            if in_cardioid_or_bulb(point) {
                return Orbit {
                    dwell: max,
                    iterations: 0,
                };
            }
            (point, (0, 0))
        }
        Fractal::Julia { re, im } => ((re.to_bits(), im.to_bits()), point),
    };
    let tolerance = match periodicity {
        Periodicity::Exact => 0,
        Periodicity::Within(bits) => bits,
    };
    match view.tier {
        Tier::Narrow => narrow(c, z0, max, tolerance),
        Tier::Standard => standard(c, z0, max, tolerance),
        Tier::Deep => deep(c, z0, max, tolerance),
    }
}

/// Q60 to `frac` fractional bits, rounded half away from zero (so negation commutes).
const fn from_q60(bits: i64, frac: u32) -> i64 {
    if frac >= 60 {
        bits
    } else {
        shift_round_i64(bits, 60 - frac)
    }
}

/// One tier's iteration: value type `$v` (unsigned twin `$u`), product type `$w`, `$frac`
/// fractional bits, exact product `$mul`, and `$twice_xy(x, y, x², y²)`: 2xy in the tier,
/// truncated toward zero (so a mirrored orbit stays exact).
macro_rules! tier_kernel {
    ($name:ident, $v:ty, $u:ty, $w:ty, $frac:expr, $mul:expr, $twice_xy:expr) => {
        // In the narrow tier products are as wide as values, so some casts are no-ops.
        #[allow(trivial_numeric_casts)]
        fn $name(c: (i64, i64), z0: (i64, i64), max: u32, tolerance: i64) -> Orbit {
            const FRAC: u32 = $frac;
            // Casts are exact: the view keeps |c|, |z0| ≤ 3.5 (see the module docs).
            let to = |q60: i64| from_q60(q60, FRAC) as $v;
            let (cr, ci) = (to(c.0), to(c.1));
            let (mut x, mut y) = (to(z0.0), to(z0.1));
            // A tolerance below one unit of this tier means exact comparison.
            let tolerance = from_q60(tolerance, FRAC) as $v;
            // |d| ≤ tolerance as one unsigned comparison: d + tolerance in 0..=2·tolerance.
            // Orbit points compared have |x|, |y| ≤ 2, so nothing wraps.
            let span = (tolerance as $u).wrapping_mul(2);
            let near = move |d: $v| (d.wrapping_add(tolerance) as $u) <= span;
            let four: $w = 4 << (2 * FRAC);
            let mul: fn($v, $v) -> $w = $mul;
            let twice_xy: fn($v, $v, $w, $w) -> $v = $twice_xy;
            let mut x2 = mul(x, x);
            let mut y2 = mul(y, y);
            if x2 + y2 > four {
                return Orbit {
                    dwell: 1,
                    iterations: 0,
                };
            }
            let (mut saved_x, mut saved_y) = (x, y);
            // At most 2·max ≤ 2^17 (the view caps max at u16::MAX): it cannot overflow.
            let mut next_save: u32 = 1;
            let mut n: u32 = 0;
            while n < max {
                n += 1;
                y = twice_xy(x, y, x2, y2) + ci;
                x = ((x2 - y2) >> FRAC) as $v + cr;
                x2 = mul(x, x);
                y2 = mul(y, y);
                if x2 + y2 > four {
                    return Orbit {
                        dwell: n,
                        iterations: n,
                    };
                }
                if near(x - saved_x) && near(y - saved_y) {
                    return Orbit {
                        dwell: max,
                        iterations: n,
                    };
                }
                if n == next_save {
                    (saved_x, saved_y) = (x, y);
                    next_save *= 2;
                }
            }
            Orbit {
                dwell: max,
                iterations: max,
            }
        }
    };
}

tier_kernel!(narrow, i32, u32, i32, 12, |a, b| a * b, |x, y, _, _| {
    x * y / (1 << 11)
});
tier_kernel!(standard, i32, u32, i64, 28, mul_i32_wide, standard_twice_xy);
tier_kernel!(deep, i64, u64, i128, 60, mul_wide, |x, y, _, _| {
    (mul_wide(x, y) / (1 << 59)) as i64
});

/// The standard tier's 2xy (Q28, truncated toward zero): `smull` and a shift where there is
/// a long multiply; from the squares the loop already has where there is not (ARMv6-M).
/// Both are exact, so every core gets the same bits.
#[inline(always)]
fn standard_twice_xy(x: i32, y: i32, x2: i64, y2: i64) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        // |x|, |y| ≤ 2 (Q28) here, so x + y fits in an i32.
        (twice_product_by_squares(x, y, x2, y2) / (1 << 28)) as i32
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        let _ = (x2, y2);
        (mul_i32_wide(x, y) / (1 << 27)) as i32
    }
}

/// Inside the main cardioid or the period-2 bulb, decided in Q28 with 64-bit products (no
/// 128-bit library calls on Cortex-M) and a margin of 2⁻²⁰, which covers every rounding
/// below (at most about 2⁻²¹·⁷): a point it accepts is inside for certain, and a point on
/// or next to the boundary is iterated instead.
fn in_cardioid_or_bulb((x, y): (i64, i64)) -> bool {
    const ONE: i32 = 1 << 28;
    // 2^-20 in Q56.
    const MARGIN: i64 = 1 << 36;
    // Outside |re|, |im| < 2 nothing is inside, and the values below fit in an i32.
    if x.abs() >= 2 << 60 || y.abs() >= 2 << 60 {
        return false;
    }
    let (x, y) = (shift_round_i64(x, 32) as i32, shift_round_i64(y, 32) as i32);
    // Q56.
    let y2 = mul_i32_wide(y, y);
    // Period-2 bulb: (x + 1)² + y² < 1/16.
    let x1 = x + ONE;
    if mul_i32_wide(x1, x1) + y2 + MARGIN < 1 << 52 {
        return true;
    }
    // Cardioid: q(q + x - 1/4) < y²/4 with q = (x - 1/4)² + y², all below 2^63.
    let xq = x - ONE / 4;
    // Q28, rounded down: the margin covers it.
    let q = (mul_i32_wide(xq, xq) + y2) >> 28;
    // From q ≥ 2 on, q + xq ≥ 1/4 and q ≥ y², so q(q + xq) ≥ y²/4: outside. Below it, q and
    // q + xq fit in an i32.
    if q >= 2 << 28 {
        return false;
    }
    let q = q as i32;
    mul_i32_wide(q, q + xq) + MARGIN < y2 / 4
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q60(v: f64) -> i64 {
        (v * (1u64 << 60) as f64) as i64
    }

    #[test]
    fn cardioid_and_bulb_contain_their_centres_only() {
        for (re, im) in [
            (0.0, 0.0),
            (-0.5, 0.3),
            (-1.0, 0.0),
            (-1.2, 0.1),
            (0.2, 0.0),
        ] {
            assert!(in_cardioid_or_bulb((q60(re), q60(im))), "{re},{im}");
        }
        for (re, im) in [
            (0.3, 0.0),
            (-0.75, 0.2),
            (-1.3, 0.0),
            (0.26, 0.0),
            (-2.0, 0.0),
            (1.9, 1.9),
        ] {
            assert!(!in_cardioid_or_bulb((q60(re), q60(im))), "{re},{im}");
        }
    }

    #[test]
    fn tiers_agree_on_simple_points() {
        for (re, im, dwell) in [(1.0, 0.0, 3), (-0.1, 0.1, u32::MAX), (-2.1, 0.0, 1)] {
            let c = (q60(re), q60(im));
            let expected = if dwell == u32::MAX { 500 } else { dwell };
            for kernel in [narrow, standard, deep] {
                assert_eq!(kernel(c, (0, 0), 500, 0).dwell, expected, "{re},{im}");
            }
        }
    }
}
