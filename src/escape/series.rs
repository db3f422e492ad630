//! Series approximation: the first iterations of every pixel of a perturbed view at once.
//!
//! While the pixels stay close to the reference, a pixel's difference δₙ is a polynomial
//! in its offset δc that the whole view shares: δₙ ≈ Σₖ bₙ,ₖ·uᵏ with u = δc/R (R a power
//! of two at least the view's half diagonal, so |u| ≤ 1). The coefficients follow the
//! reference: bₙ₊₁,₁ = 2Zₙbₙ,₁ + R and bₙ₊₁,ₖ = 2Zₙbₙ,ₖ + Σᵢ₊ⱼ₌ₖ bₙ,ᵢbₙ,ⱼ. A pixel then
//! starts at iteration n from the polynomial's value instead of iterating n times.
//!
//! How far the series holds is measured, not assumed: probe points on the view's border
//! (its corners and the middles of its sides) are iterated exactly beside the
//! coefficients, and the series stops at the last checked iteration where it matches
//! every probe to within 2⁻⁸ of a pixel's image there (|bₙ,₁|·spacing/R). The error of
//! a truncated series is an analytic function of u, largest on the border of the region
//! (the maximum modulus principle), so the probes bound it inside; the tests compare the
//! dwells with and without the series and against an independent big-number model.
//!
//! The coefficients share one exponent (block floating point, 56-bit parts): an update
//! and a pixel's evaluation are exact 64×64 products and shifts, with nothing normalised
//! per term, and rounding that does not grow with the iterations skipped (the designs
//! measured before this one: docs/performance.md).

use super::scaled::{
    escaped, may_rebase, normalise, rebased, shr, step, ReferencePoint, Scaled, ZERO_EXPONENT,
};
use crate::math::wide::mul_wide;

/// Terms of the series: each costs every pixel a multiply-add, and the coefficients about
/// `SERIES_TERMS`/4 products an iteration each. 16 is within a few per cent of the
/// fastest count measured and takes the least flash (docs/performance.md).
pub const SERIES_TERMS: usize = 16;

/// Probe points on the view's border: its four corners and the middles of its sides.
const PROBES: usize = 8;

/// Tolerance: the series must match every probe to 2^-`TOLERANCE_BITS` of a pixel. 2⁻⁸ keeps the
/// dwells of the boards' deep zoom identical to `Deep`'s while skipping more iterations
/// than finer tolerances (docs/performance.md).
const TOLERANCE_BITS: i32 = 8;

/// The probes are compared with the series every `CHECK_EVERY` iterations (the check
/// costs as much as the coefficients' update); the series is kept from the last check
/// passed.
const CHECK_EVERY: u32 = 8;

/// The series of a view: its coefficients at the iteration it skips to.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Series {
    /// bₙ,₁ … bₙ,ₖ at n = `skip`, in one fixed-point scale.
    polynomial: Polynomial,
    /// Iterations every pixel skips (0: the series does not hold past the start).
    skip: u32,
    /// R = 2^−`scale`: u = δc·2^`scale`.
    scale: i32,
    /// A pixel's spacing: at least 2^`spacing_log2`.
    spacing_log2: i32,
}

impl Series {
    /// No series: every pixel starts at iteration 0.
    pub(crate) const NONE: Self = Self {
        polynomial: Polynomial::ZERO,
        skip: 0,
        scale: 0,
        spacing_log2: 0,
    };

    /// The series of the view whose pixels are offset from the reference by δc = `offset`
    /// (a pixel's δc from its offsets in half spacings), `corner` the offsets of its
    /// top-right corner pixel, against `reference`, for at most `max` iterations. In line
    /// in its one caller, `Perturbation::new`: apart, the two frames took the perturbed
    /// scene 48 bytes more stack.
    #[inline(always)]
    pub(crate) fn new(
        reference: &[ReferencePoint],
        corner: (i64, i64),
        offset: impl Fn(i64, i64) -> Scaled,
        max: u32,
    ) -> Self {
        let (w, h) = corner;
        // R: above the corner's distance (the larger part below 2^62 in units 2^-s, the
        // modulus below 2^63).
        let far = offset(w, h);
        if far.x == 0 && far.y == 0 {
            return Self::NONE;
        }
        let scale = far.s - 63;
        // One pixel's spacing: two half spacings.
        let spacing_log2 = offset(2, 0).lower_log2();
        // The pixel's image is |b1|·spacing/R: the error may be 2^(-TOLERANCE_BITS) of it.
        let tolerance_shift = -scale - spacing_log2 + TOLERANCE_BITS;
        let probe_steps = [
            (-w, h),
            (0, h),
            (w, h),
            (w, 0),
            (w, -h),
            (0, -h),
            (-w, -h),
            (-w, 0),
        ];
        let probe_offsets = probe_steps.map(|(re, im)| offset(re, im));
        let probe_u = probe_offsets.map(|c| c.times_pow2(scale));
        let mut probes = [Scaled::ZERO; PROBES];
        let mut terms = Polynomial::ZERO;
        let mut series = Self {
            scale,
            spacing_log2,
            ..Self::NONE
        };
        let last = reference.len().min(max as usize);
        let pairs = reference.get(..last).unwrap_or(&[]).windows(2);
        for (n, pair) in (1..).zip(pairs) {
            let [ReferencePoint(z), ReferencePoint(next)] = *pair else {
                break;
            };
            terms = terms.advance(z, scale);
            for (d, c) in probes.iter_mut().zip(probe_offsets) {
                *d = step(*d, z, c);
                // A probe that escapes, or would rebase, ends the series there.
                if escaped(next, *d).is_some()
                    || (may_rebase(next, *d) && rebased(next, *d, false).is_some())
                {
                    return series;
                }
            }
            if n % CHECK_EVERY != 0 {
                continue;
            }
            let image = terms.linear().lower_log2() - tolerance_shift;
            let holds = probes
                .iter()
                .zip(probe_u)
                .all(|(d, u)| terms.evaluate(u).sub(*d).upper_log2() <= image);
            if !holds {
                break;
            }
            series.polynomial = terms;
            series.skip = n;
        }
        series
    }

    /// A pixel's image at the skip, |b₁|·spacing/R, is at least 2^`image_log2`: how far
    /// apart neighbouring pixels' orbits are there.
    pub(crate) fn image_log2(&self) -> i32 {
        self.polynomial.linear().lower_log2() + self.spacing_log2 + self.scale
    }

    /// Iterations every pixel skips.
    pub(crate) const fn skip(&self) -> u32 {
        self.skip
    }

    /// δ at iteration [`skip`](Self::skip) of the pixel offset by `offset`.
    pub(crate) fn delta(&self, offset: Scaled) -> Scaled {
        self.polynomial.evaluate(offset.times_pow2(self.scale))
    }

    /// dδ/dδc at iteration [`skip`](Self::skip) of the pixel offset by `offset`: the
    /// series' derivative, Σₖ k·bₖ·uᵏ⁻¹ over R (distance estimation's dz there).
    pub(crate) fn slope(&self, offset: Scaled) -> Scaled {
        self.polynomial
            .slope(offset.times_pow2(self.scale))
            .times_pow2(self.scale)
    }
}

/// The coefficients b₁ … bₖ in one scale (block floating point), bₖ = (x + iy)·2^−`exponent`,
/// the largest part in [2⁵⁵, 2⁵⁶): an iteration of them and a pixel's Horner steps are
/// then exact 64×64 products and shifts, with no normalising of each (far cheaper
/// than a [`Scaled`] value per term). Every modulus is below 2^56.5,
/// so their sum, and every partial sum of Horner's rule (|u| < 1), stays below 2⁶². A
/// coefficient far below the largest keeps fewer bits; its error is no larger than the
/// largest one's, and the probes check the result.
#[derive(Debug, Clone, Copy)]
struct Polynomial {
    coefficients: [(i64, i64); SERIES_TERMS],
    exponent: i32,
}

/// Bits of the block's largest part: parts below 2^`BLOCK_BITS`.
const BLOCK_BITS: u32 = 56;

impl Polynomial {
    const ZERO: Self = Self {
        coefficients: [(0, 0); SERIES_TERMS],
        exponent: ZERO_EXPONENT,
    };

    /// b₁.
    fn linear(&self) -> Scaled {
        let (x, y) = self.coefficients.first().copied().unwrap_or_default();
        scaled((x, y), self.exponent)
    }

    /// One iteration: bₖ ← 2Zbₖ + Σᵢ₊ⱼ₌ₖ bᵢbⱼ (+ R = 2^−`scale` for k = 1), every
    /// product exact, the sums floored to one unit, the block normalised once.
    #[inline(never)]
    fn advance(&self, z: Scaled, scale: i32) -> Self {
        let e = self.exponent;
        if self.coefficients.iter().all(|&c| c == (0, 0)) {
            // From zero every term but R vanishes.
            let mut start = Self::ZERO;
            if let Some(b1) = start.coefficients.first_mut() {
                *b1 = (1 << (BLOCK_BITS - 1), 0);
            }
            start.exponent = BLOCK_BITS as i32 - 1 + scale;
            return start;
        }
        // 2Zbₖ is in units 2^-(z.s + e - 1), the pairs in 2^-2e: sum in the coarser.
        let unit = (z.s + e - 1).min(2 * e);
        let (z_shift, pair_shift) = (z.s + e - 1 - unit, 2 * e - unit);
        let mut sums = [(0i128, 0i128); SERIES_TERMS];
        let mut magnitude = 0u128;
        for (k, sum) in core::hint::black_box(&mut sums[..]).iter_mut().enumerate() {
            *sum = self.next_term(k, z, (z_shift, pair_shift));
            if k == 0 {
                // R = 2^-scale in units 2^-unit.
                sum.0 += shl_or_shr(unit - scale);
            }
            magnitude |= sum.0.unsigned_abs() | sum.1.unsigned_abs();
        }
        // The largest part in [2^55, 2^56).
        let shift = 128 - magnitude.leading_zeros() as i32 - BLOCK_BITS as i32;
        let mut next = Self::ZERO;
        for (c, &(x, y)) in next
            .coefficients
            .iter_mut()
            .zip(core::hint::black_box(&sums[..]))
        {
            *c = (shifted(x, shift), shifted(y, shift));
        }
        next.exponent = unit - shift;
        next
    }

    /// 2Zbₖ + Σᵢ₊ⱼ₌ₖ bᵢbⱼ for the term at `index` (from 0), the two kinds of product
    /// floored by their `shifts` to one unit.
    #[inline(never)]
    fn next_term(
        &self,
        index: usize,
        z: Scaled,
        (z_shift, pair_shift): (i32, i32),
    ) -> (i128, i128) {
        let b = |i: usize| self.coefficients.get(i).copied().unwrap_or_default();
        let (zx, zy) = product((z.x, z.y), b(index));
        let (mut sx, mut sy) = (shr(zx, z_shift), shr(zy, z_shift));
        // Indices from 0 sum to index - 1: the pairs i < j twice, a middle one once.
        let (mut px, mut py) = (0i128, 0i128);
        for i in 0..index / 2 {
            let (x, y) = product(b(i), b(index - 1 - i));
            px += x;
            py += y;
        }
        (px, py) = (2 * px, 2 * py);
        if index % 2 == 1 {
            let (x, y) = product(b(index / 2), b(index / 2));
            px += x;
            py += y;
        }
        sx += shr(px, pair_shift);
        sy += shr(py, pair_shift);
        (sx, sy)
    }

    /// Σₖ bₖuᵏ by Horner's rule, for |u| < 1.
    #[inline(never)]
    fn evaluate(&self, u: Scaled) -> Scaled {
        let (x, y) = horner(&self.coefficients, in_q62(u));
        scaled((x, y), self.exponent)
    }

    /// Σₖ k·bₖ·uᵏ⁻¹ by Horner's rule, for |u| < 1: each k·bₖ taken down 3 bits, so the
    /// sum (at most 136 of the largest coefficient) stays below 2⁶².
    #[inline(never)]
    fn slope(&self, u: Scaled) -> Scaled {
        let (ux, uy) = in_q62(u);
        let (mut x, mut y) = (0i64, 0i64);
        let coefficients = core::hint::black_box(&self.coefficients[..]);
        for (index, &(bx, by)) in coefficients.iter().enumerate().rev() {
            let k = index as i64 + 1;
            let (px, py) = product((x, y), (ux, uy));
            x = (px >> 62) as i64 + ((k * bx) >> 3);
            y = (py >> 62) as i64 + ((k * by) >> 3);
        }
        scaled((x, y), self.exponent - 3)
    }
}

/// `u`'s parts in Q62 (below 1 for |u| < 1).
fn in_q62(u: Scaled) -> (i64, i64) {
    let q62 = |m: i64| {
        if u.s >= 62 {
            m >> (u.s - 62).min(63)
        } else {
            m << (62 - u.s)
        }
    };
    (q62(u.x), q62(u.y))
}

/// (x + iy)·2^−`exponent`, normalised (not inlined: flash).
#[inline(never)]
fn scaled((x, y): (i64, i64), exponent: i32) -> Scaled {
    normalise(i128::from(x), i128::from(y), exponent)
}

/// `value`·2^−`shift`, floored, as an i64 (it fits: callers' values are below 2^(63 +
/// shift)). Not inlined: a 128-bit shift by a variable amount is long code on a 32-bit
/// core.
#[inline(never)]
fn shifted(value: i128, shift: i32) -> i64 {
    if shift >= 0 {
        shr(value, shift) as i64
    } else {
        (value << (-shift).min(127)) as i64
    }
}

/// Σₖ bₖuᵏ for `u` in Q62 (|u| < 1), in the coefficients' units, floored at each step.
#[inline(never)]
fn horner(coefficients: &[(i64, i64)], (ux, uy): (i64, i64)) -> (i64, i64) {
    let coefficients = core::hint::black_box(coefficients);
    let (mut x, mut y) = (0i64, 0i64);
    for &(bx, by) in coefficients.iter().rev() {
        let (px, py) = product((x + bx, y + by), (ux, uy));
        (x, y) = ((px >> 62) as i64, (py >> 62) as i64);
    }
    (x, y)
}

/// The exact complex product. Not inlined, nor are the loops that call it unrolled
/// (their lengths are hidden from the optimiser): written out for every term, the
/// series would not fit the measuring firmware's flash.
#[inline(never)]
fn product((ax, ay): (i64, i64), (bx, by): (i64, i64)) -> (i128, i128) {
    (
        mul_wide(ax, bx) - mul_wide(ay, by),
        mul_wide(ax, by) + mul_wide(ay, bx),
    )
}

/// 2^`bits` as an i128, 0 below 2⁰ (a value far below the unit) and saturated above 2¹²⁵
/// (never reached: R is below b₁ after the first iteration).
fn shl_or_shr(bits: i32) -> i128 {
    if bits < 0 {
        0
    } else {
        1i128 << bits.min(125)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(s: Scaled) -> (f64, f64) {
        ReferencePoint(s).to_f64()
    }

    /// The block's update and Horner's rule against the same steps in f64, from R at
    /// 2^-30 through a short orbit: the coefficients' values agree to 2^-40 of the
    /// largest (f64 keeps 53 bits; the block 56 for the largest).
    #[test]
    fn the_block_follows_the_recurrence_in_f64() {
        let orbit = [
            (0.0, 0.0),
            (-0.75, 0.1),
            (-0.2, -0.15),
            (-0.69, 0.16),
            (-0.3, -0.12),
        ];
        let scale = 30;
        let mut block = Polynomial::ZERO;
        let mut model = [(0.0f64, 0.0f64); SERIES_TERMS];
        for &(zx, zy) in &orbit {
            let z = normalise(
                (zx * 2f64.powi(60)) as i128,
                (zy * 2f64.powi(60)) as i128,
                60,
            );
            let (zx, zy) = value(z);
            block = block.advance(z, scale);
            let old = model;
            for k in 0..SERIES_TERMS {
                let (bx, by) = old[k];
                let (mut x, mut y) = (2.0 * (zx * bx - zy * by), 2.0 * (zx * by + zy * bx));
                for i in 0..k {
                    let ((ax, ay), (cx, cy)) = (old[i], old[k - 1 - i]);
                    x += ax * cx - ay * cy;
                    y += ax * cy + ay * cx;
                }
                if k == 0 {
                    x += 2f64.powi(-scale);
                }
                model[k] = (x, y);
            }
        }
        let largest = model
            .iter()
            .fold(0.0f64, |m, &(x, y)| m.max(x.abs()).max(y.abs()));
        for (k, (&(x, y), &(bx, by))) in model.iter().zip(&block.coefficients).enumerate() {
            let unit = crate::math::big::pow2(-block.exponent);
            let (bx, by) = (bx as f64 * unit, by as f64 * unit);
            assert!(
                (bx - x).abs() <= largest * 2f64.powi(-40)
                    && (by - y).abs() <= largest * 2f64.powi(-40),
                "term {k}: ({bx}, {by}) against ({x}, {y})"
            );
        }
        let u = normalise(3 << 58, -(5 << 57), 62);
        let (ux, uy) = value(u);
        let (mut x, mut y) = (0.0, 0.0);
        for &(bx, by) in model.iter().rev() {
            let (sx, sy) = (x + bx, y + by);
            (x, y) = (sx * ux - sy * uy, sx * uy + sy * ux);
        }
        let (ex, ey) = value(block.evaluate(u));
        assert!(
            (ex - x).abs() <= largest * 2f64.powi(-40)
                && (ey - y).abs() <= largest * 2f64.powi(-40),
            "({ex}, {ey}) against ({x}, {y})"
        );
        assert!(
            x.abs() > largest * 2f64.powi(-8),
            "a value that tests something"
        );
    }
}
