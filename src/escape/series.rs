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
//! every probe to within 2⁻²⁰ of a pixel's image there (|bₙ,₁|·spacing/R). The error of
//! a truncated series is an analytic function of u, largest on the border of the region
//! (the maximum modulus principle), so the probes bound it inside; the tests compare the
//! dwells with and without the series and against an independent big-number model.
//!
//! The coefficients and the evaluation are in the pixels' own 62-bit mantissas. 30-bit
//! ones were tried first: their rounding grows with the iterations skipped (a few parts in
//! 10⁷ of δ after 600), and at the deep-zoom view a shift of 10⁻⁵ of a pixel already
//! changes some dwells, so 6 of its 8192 pixels came out wrong.

use super::perturbation::{escaped, may_rebase, rebased, step, ReferencePoint, Scaled};

/// Terms of the series: each costs every pixel a multiply-add, and the coefficients about
/// `SERIES_TERMS`/4 products an iteration each. Measured on Cortex-M3 at the deep-zoom
/// view (10⁻⁷ over 128×64, 1000 iterations): 12 terms 247 M instructions a frame, 16
/// terms 221 M, 24 terms 224 M.
pub const SERIES_TERMS: usize = 16;

/// Probe points on the view's border: its four corners and the middles of its sides.
const PROBES: usize = 8;

/// Tolerance: the series must match every probe to 2^-`TOLERANCE_BITS` of a pixel.
const TOLERANCE_BITS: i32 = 20;

/// The probes are compared with the series every `CHECK_EVERY` iterations (the check
/// costs as much as the coefficients' update); the series is kept from the last check
/// passed.
const CHECK_EVERY: u32 = 8;

/// The series of a view: its coefficients at the iteration it skips to.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Series {
    /// bₙ,₁ … bₙ,ₖ at n = `skip`.
    terms: [Scaled; SERIES_TERMS],
    /// Iterations every pixel skips (0: the series does not hold past the start).
    skip: u32,
    /// R = 2^−`scale`: u = δc·2^`scale`.
    scale: i32,
}

impl Series {
    /// No series: every pixel starts at iteration 0.
    pub(crate) const NONE: Self = Self {
        terms: [Scaled::ZERO; SERIES_TERMS],
        skip: 0,
        scale: 0,
    };

    /// The series of the view whose pixels are offset from the reference by δc = `offset`
    /// (a pixel's δc from its offsets in half spacings), `corner` the offsets of its
    /// top-right corner pixel, against `reference`, for at most `max` iterations.
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
        let radius = Scaled {
            x: 1 << 61,
            y: 0,
            s: 61 + scale,
        };
        let mut terms = [Scaled::ZERO; SERIES_TERMS];
        let mut series = Self {
            scale,
            ..Self::NONE
        };
        let last = reference.len().min(max as usize);
        let pairs = reference.get(..last).unwrap_or(&[]).windows(2);
        for (n, pair) in (1..).zip(pairs) {
            let [ReferencePoint(z), ReferencePoint(next)] = *pair else {
                break;
            };
            advance(&mut terms, z, radius);
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
            let image = terms.first().map_or(0, |b1| b1.lower_log2()) - tolerance_shift;
            let holds = probes
                .iter()
                .zip(probe_u)
                .all(|(d, u)| evaluate(&terms, u).sub(*d).upper_log2() <= image);
            if !holds {
                break;
            }
            series.terms = terms;
            series.skip = n;
        }
        series
    }

    /// Iterations every pixel skips.
    pub(crate) const fn skip(&self) -> u32 {
        self.skip
    }

    /// δ at iteration [`skip`](Self::skip) of the pixel offset by `offset`.
    pub(crate) fn delta(&self, offset: Scaled) -> Scaled {
        evaluate(&self.terms, offset.times_pow2(self.scale))
    }
}

/// One iteration of the coefficients, highest term first (each uses the lower ones'
/// previous values): bₖ ← 2Zbₖ + Σᵢ₊ⱼ₌ₖ bᵢbⱼ (+ R for k = 1).
fn advance(terms: &mut [Scaled; SERIES_TERMS], z: Scaled, radius: Scaled) {
    for k in (1..=SERIES_TERMS).rev() {
        let term = |i: usize| terms.get(i - 1).copied().unwrap_or(Scaled::ZERO);
        let mut sum = z.mul(term(k));
        // The pairs (i, k − i) with i < k − i count twice; a middle one once.
        let mut pairs = Scaled::ZERO;
        for i in 1..k.div_ceil(2) {
            pairs = pairs.add(term(i).mul(term(k - i)));
        }
        sum = sum.add(pairs).times_pow2(1);
        if k % 2 == 0 {
            let middle = term(k / 2);
            sum = sum.add(middle.mul(middle));
        }
        if k == 1 {
            sum = sum.add(radius);
        }
        if let Some(slot) = terms.get_mut(k - 1) {
            *slot = sum;
        }
    }
}

/// Σₖ bₖuᵏ by Horner's rule.
fn evaluate(terms: &[Scaled; SERIES_TERMS], u: Scaled) -> Scaled {
    terms
        .iter()
        .rev()
        .fold(Scaled::ZERO, |sum, term| sum.add(*term).mul(u))
}
