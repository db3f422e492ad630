//! The dwell of one pixel: z ← z² + c in the view's fixed-point tier.
//!
//! Overflow cannot happen, by invariant: an orbit is only squared while |z|² ≤ 4 (so |x|,
//! |y| ≤ 2), and every c is within ±3.5 (checked by the view), so the next value is below
//! 7.5 and its square below 57: inside every tier's range (Q12 in i32, Q28 in i32 with the
//! high word of i64 squares (Q24) or whole i64 squares, Q60 in i64 with i128 squares). A
//! Julia start outside radius 2 escapes at once (|z₁| ≥ |z₀|² − |k| > 2 because |k| ≤ 2)
//! and is never squared.
//!
//! The deep tier's 64×64→128 products are built from 32-bit halves (see `mul_wide`), since
//! an i128 multiply is a library call on Cortex-M.
//!
//! Mirrored points have the same dwell by construction: a Mandelbrot point is iterated as
//! its twin in the upper half-plane (|im|), so products round down with a plain shift
//! instead of toward zero (which costs a correction per step). A Julia set's half turn
//! needs nothing: z₀ and −z₀ have the same z₁ however products round.
//!
//! Each tier is a type implementing `Arithmetic` (its value and product types, how it
//! multiplies and shifts back), and one generic `orbit` iterates them all, so each tier's
//! loop is compiled with its arithmetic in line (why not a macro: docs/performance.md).

use super::estimate::Estimate;
use super::modes::{Inside, Outside};
use super::view::{Fractal, Parts, Shading, Tier, View};
use crate::math::log::log2;
use crate::math::wide::shift_round_i64;

/// Largest periodicity tolerance of a fast render, 2⁻²² in Q60 bits.
///
/// A tolerance of 1/16 of a pixel alone grows with the pixel, and on large pixels orbits
/// that escape later were called inside; 2⁻²² is four times below the largest cap that
/// changed no dwell over random small views (docs/performance.md).
pub const MAX_FAST_TOLERANCE: i64 = 1 << 38;

/// The periodicity tolerance of a fast render with pixel spacing `spacing` (Q60 bits):
/// 1/16 of a pixel, at most [`MAX_FAST_TOLERANCE`].
pub(crate) const fn fast_tolerance(spacing: i64) -> i64 {
    let sixteenth = spacing >> 4;
    if sixteenth < MAX_FAST_TOLERANCE {
        sixteenth
    } else {
        MAX_FAST_TOLERANCE
    }
}

/// How an orbit that repeats is recognised (Brent: compare with a point saved at
/// iterations 64, 128, 256, ...; see `FIRST_SAVE`).
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
    /// The pixel's value: the dwell 1..=max, max meaning "did not escape"; or with smooth
    /// shading the normalised count in sixteenths, max·16 meaning "did not escape". At most
    /// the inside value, a u16 ([`value`](Self::value)); with distance estimation the bits
    /// above hold [`far`](Self::far).
    pub(crate) dwell: u32,
    /// z ← z² + c steps taken.
    pub(crate) iterations: u32,
}

impl Orbit {
    /// The pixel's value: the dwell's low 16 bits.
    #[inline(always)]
    pub(crate) const fn value(&self) -> u16 {
        self.dwell as u16
    }

    /// With distance estimation, the set is proven at least 2^(`far`/4) pixels from an
    /// escaping pixel (0: nothing proven, or not estimated): what a block's border must
    /// show before the block is filled (see `subdivide`). Kept in the dwell above its
    /// value, so that an orbit stays two words.
    #[inline(always)]
    pub(crate) const fn far(&self) -> u16 {
        (self.dwell >> 16) as u16
    }

    /// Did not escape (a repeat, or the cap), found after `iterations` steps.
    #[inline(always)]
    pub(super) const fn inside_after(kernel: &Kernel, iterations: u32) -> Self {
        Self {
            dwell: kernel.inside,
            iterations,
        }
    }
}

/// Which [`Arithmetic`] a kernel iterates in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Narrow,
    Medium,
    RoundedMedium,
    Standard,
    Deep,
    Wide,
}

/// One coordinate of a pixel's point in the tier's units, converted once per column or
/// row rather than once per pixel.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Part(pub(crate) i64);

/// What is the same for every pixel of a render, in the tier's units: converted once, so
/// a pixel costs its cardioid test and its iterations, nothing more.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Kernel {
    pub(super) tier: Tier,
    /// The arithmetic the tier iterates in, for this fractal (see `RoundedMedium`).
    pub(super) arithmetic: Kind,
    pub(super) max: u32,
    /// The value of a point that does not escape (`max`, or `max`·16 when smooth).
    pub(super) inside: u32,
    pub(super) smooth: bool,
    /// Fractint's `outside=` and `inside=` (see `modes`).
    pub(super) outside: Outside,
    pub(super) inside_mode: Inside,
    /// Whether an escaping orbit's value is its dwell: no smooth value or outside mode to
    /// compute.
    pub(super) plain_escape: bool,
    /// What the view asks of distance estimation, if anything: escaping orbits are then
    /// run again for their distance (see `distance`).
    pub(super) estimate: Option<Estimate>,
    /// log₂ of the pixel spacing, Q16.
    pub(super) spacing_log2: i32,
    /// The Julia parameter, or `None` for the Mandelbrot set.
    pub(super) julia: Option<(i64, i64)>,
    /// How close a repeat must be (0: exactly).
    pub(super) tolerance: i64,
    /// Steps before the first point is saved for the repeat test: FIRST_SAVE, or fewer if
    /// the cap is lower.
    pub(super) plain: u32,
}

impl Kernel {
    /// The kernel of `view`, recognising repeats as `periodicity` says.
    pub(crate) fn new(view: &View, periodicity: Periodicity) -> Self {
        // A perturbation view rendered without a reference: `Render::new` documents it.
        let tier = match view.tier {
            Tier::Perturbation => Tier::Deep,
            tier => tier,
        };
        let frac = tier.frac_bits();
        let tolerance = match periodicity {
            Periodicity::Exact => 0,
            Periodicity::Within(bits) => bits,
        };
        let kernel = Self {
            tier,
            arithmetic: match (tier, view.fractal) {
                (Tier::Narrow, _) => Kind::Narrow,
                (Tier::Medium, Fractal::Mandelbrot) => Kind::Medium,
                (Tier::Medium, Fractal::Julia { .. }) => Kind::RoundedMedium,
                (Tier::Standard, _) => Kind::Standard,
                (Tier::Deep | Tier::Perturbation, _) => Kind::Deep,
                (Tier::Wide, _) => Kind::Wide,
            },
            max: view.max_iterations,
            inside: u32::from(view.inside_value()),
            smooth: view.shading == Shading::Smooth,
            outside: view.outside,
            inside_mode: view.inside,
            plain_escape: view.shading == Shading::Dwell && view.outside == Outside::Iter,
            estimate: Estimate::of(view),
            spacing_log2: log2(view.spacing.unsigned_abs(), 60).unwrap_or(0),
            julia: match view.fractal {
                Fractal::Mandelbrot => None,
                Fractal::Julia { re, im } => {
                    Some((from_q60(re.to_bits(), frac), from_q60(im.to_bits(), frac)))
                }
            },
            // A tolerance below one unit of the tier means exact comparison.
            tolerance: from_q60(tolerance, frac),
            plain: FIRST_SAVE.min(view.max_iterations),
        };
        if kernel.inside_mode != Inside::MaxIter || kernel.is_dust() {
            // An inside mode's value is z at the cap; or no orbit settles into a cycle:
            // its pixels are never tested for repeats.
            return Self {
                plain: kernel.max,
                ..kernel
            };
        }
        kernel
    }

    /// Whether this is a Julia set whose critical point 0 escapes (k outside the
    /// Mandelbrot set): dust, with no attracting cycle. Repeat tests there could only find
    /// rounding's own cycles (which never escape either, so an exact render keeps every
    /// dwell) or call a slow escape inside within a tolerance. The critical orbit runs to
    /// `CRITICAL_STEPS` whatever the view's cap: a parameter just outside the set escapes
    /// late (−0.8 + 0.156i, the boards' Julia set, at 252).
    fn is_dust(&self) -> bool {
        if self.julia.is_none() {
            return false;
        }
        let critical = Self {
            max: CRITICAL_STEPS,
            inside: u32::MAX,
            smooth: false,
            outside: Outside::Iter,
            inside_mode: Inside::MaxIter,
            estimate: None,
            plain_escape: true,
            ..*self
        };
        critical.dwell(Part(0), Part(0)).dwell != u32::MAX
    }

    /// Whether a tile of this kernel's values may be drawn by tracing the outlines of its
    /// regions (see `schedule`): a Mandelbrot view's dwells. Every set of points with
    /// dwell above k is connected there, so a region lies inside another only where a
    /// pixel grid breaks a connection narrower than a pixel. A Julia set's filaments break
    /// often at display sizes, and smooth values change every few cells, where following
    /// outlines costs more than subdivision's scans (docs/performance.md); Fractint's
    /// modes' values change as often.
    pub(crate) const fn traceable(&self) -> bool {
        self.julia.is_none()
            && !self.smooth
            && matches!(self.outside, Outside::Iter)
            && matches!(self.inside_mode, Inside::MaxIter)
            && self.estimate.is_none()
    }

    /// The tier the kernel computes in.
    pub(crate) const fn tier(&self) -> Tier {
        self.tier
    }

    /// A point coordinate (Q60, within ±3.5 as the view guarantees) ready for
    /// [`dwell`](Self::dwell).
    pub(crate) fn part(&self, q60: i64) -> Part {
        Part(from_q60(q60, self.tier.frac_bits()))
    }

    /// [`part`](Self::part) of each coordinate of `q60s`, into `parts`: the rounding's
    /// shift and half found once, not once a coordinate.
    pub(crate) fn fill_parts(&self, q60s: Parts, parts: &mut [Part]) {
        // As `shift_round_i64`, half away from zero (`Deep`: no shift, half 0). Nothing
        // wraps in the view (|q60| ≤ 3.5·2⁶⁰); past its edge the parts are not used.
        let shift = 60u32.saturating_sub(self.tier.frac_bits());
        let half = (1i64 << shift) >> 1;
        let round = |q60: i64, shift: u32| {
            Part(if q60 >= 0 {
                q60.wrapping_add(half) >> shift
            } else {
                (half.wrapping_sub(q60) >> shift).wrapping_neg()
            })
        };
        // Q28's shift by a constant 32: a word, not a double-word shift.
        if shift == 32 {
            for (slot, q60) in parts.iter_mut().zip(q60s) {
                *slot = round(q60, 32);
            }
        } else {
            for (slot, q60) in parts.iter_mut().zip(q60s) {
                *slot = round(q60, shift);
            }
        }
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

/// Steps before the first point is saved for the repeat test: most points escape before,
/// and a plain step costs less than a step of Brent's stretches (docs/performance.md).
pub(super) const FIRST_SAVE: u32 = 64;

/// Steps of a Julia parameter's critical orbit that decide whether the set is dust (see
/// [`Kernel::new`]): once per render, a few thousand instructions at most where it escapes.
pub(super) const CRITICAL_STEPS: u32 = 1024;
