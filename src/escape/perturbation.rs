//! Perturbation: one reference orbit in wide fixed point, every pixel as a small
//! difference from it in 62-bit mantissas with an exponent, so a zoom far past 2⁻⁵⁴
//! needs no wider numbers per pixel than a shallow one.
//!
//! The reference Z₀ = 0, Zₙ₊₁ = Zₙ² + C is computed once per view at the view's centre
//! C, in [`DeepCoord`] limbs (as many as the spacing and the cap need), and stored as
//! [`ReferencePoint`]s: a complex 62-bit mantissa with one exponent, 24 bytes per
//! iteration, in storage the caller provides. A pixel c = C + δc then iterates
//! δₙ₊₁ = 2Zₙδₙ + δₙ² + δc, its δ in the same format: the two parts of a point share a
//! scale. Rounding grows about as the iterations times the mantissa's precision, hence
//! 62 bits (docs/performance.md).
//!
//! Glitches are handled by rebasing (Zhuoran's method): when the pixel's own point
//! z = Zₙ + δₙ is smaller than δₙ, or the reference has ended (escaped), δ becomes z and
//! the reference restarts from Z₀ = 0. So one reference suffices for the Mandelbrot set,
//! and a pixel never follows a reference it has left behind (the glitch tests check a view
//! whose pixels must rebase against an independent big-number model). The test costs
//! nothing while the reference is far larger than δ (it is only made when the exponents
//! say |Zₙ| < 8|δₙ|).
//!
//! Everything is integer arithmetic with floor shifts: every core draws the same bits.
//! Repeats are found by Brent's method on a pixel's state (m, δ), m its place in the
//! reference, taken just after each rebase (m = 0, z = δ: no cancellation against Z), so
//! the steps between rebases test nothing more. An interior pixel that rebases where the
//! reference passes near 0 (inside a minibrot) comes back to nearly the same δ each time:
//! `Fast` stops it at a repeat within a sixteenth of a pixel, as the fixed tiers do
//! (tested); `Exact` only at an exact repeat, which 62-bit mantissas hardly ever make,
//! so its interior pixels run to the cap. A pixel that never rebases is never tested. The
//! cardioid and bulb test is made at the reference's precision.

use super::derivative::{Derivative, LooseDerivative};
use super::distance::{estimated, log2_pixels_past_escape};
use super::estimate::Estimate;
use super::kernel::MAX_FAST_TOLERANCE;
use super::kernel::{Kernel, Orbit, Periodicity};
use super::modes::Outside;
use super::orbit::{in_cardioid_or_bulb, smooth_value};
use super::scaled::{
    clamp_i32, escaped, may_rebase, normalise, rebased, step, to_q28, ReferencePoint, Scaled,
    MANTISSA_BITS,
};
use super::series::Series;
use super::view::{half_spacings, Fractal, Shading, View};
use crate::error::{Error, ViewError};
use crate::math::big::{DeepCoord, DEEP_LIMBS};
use crate::math::log::{log2, LOG2_FRAC_BITS};
use crate::math::wide::mul_wide;

/// Bytes of one [`ReferencePoint`]: the reference orbit's RAM per iteration.
pub const REFERENCE_POINT_BYTES: usize = size_of::<ReferencePoint>();

/// Bits the reference keeps below the pixel spacing, at least: rounding in a long orbit
/// is magnified, so it keeps 4 more for every doubling of the cap (96 at 4096
/// iterations), as the limbs allow.
const GUARD_BITS: u32 = 48;

/// A reference orbit computed into caller storage, ready for a perturbed render.
#[derive(Debug, Clone, Copy)]
pub struct ReferenceOrbit<'r> {
    points: &'r [ReferencePoint],
    limbs: u32,
    escaped: bool,
}

impl<'r> ReferenceOrbit<'r> {
    /// Points a view's reference may need: one per iteration and Z₀.
    pub const fn points_needed(view: &View) -> usize {
        view.max_iterations as usize + 1
    }

    /// Computes the reference orbit of `view` (a Mandelbrot view) at its centre into
    /// `storage`, which must hold [`points_needed`](Self::points_needed) points
    /// ([`REFERENCE_POINT_BYTES`], 24, each): 1001 points, 24 KiB, for 1000 iterations.
    pub fn compute(view: &View, storage: &'r mut [ReferencePoint]) -> Result<Self, Error> {
        if let Fractal::Julia { .. } = view.fractal {
            return Err(Error::View(ViewError::PerturbationNeedsMandelbrot));
        }
        let needed = Self::points_needed(view);
        if storage.len() < needed {
            return Err(Error::View(ViewError::ReferenceTooShort {
                needed,
                given: storage.len(),
            }));
        }
        let limbs = limbs_for(view);
        let (cx, cy) = (
            view.deep_centre.0.truncated(limbs),
            view.deep_centre.1.truncated(limbs),
        );
        let four = DeepCoord::from_coord(crate::math::Coord::from_bits(1 << 62));
        let (mut x, mut y) = (DeepCoord::ZERO, DeepCoord::ZERO);
        let mut length = 0;
        let mut escaped = false;
        for slot in storage.iter_mut().take(needed) {
            *slot = normalise_pair(x, y);
            length += 1;
            let (x2, y2) = (x.mul(x, limbs), y.mul(y, limbs));
            if !four.sub(x2.add(y2)).is_negative() {
                // |Z|² ≤ 4: the next value stays within ±8.
                let xy = x.mul(y, limbs);
                (x, y) = (x2.sub(y2).add(cx), xy.add(xy).add(cy));
            } else {
                escaped = true;
                break;
            }
        }
        let points = storage.get(..length).unwrap_or(&[]);
        Ok(Self {
            points,
            limbs: limbs as u32,
            escaped,
        })
    }

    /// The orbit's points: Z₀ (0) first, to the first that escaped or to max-iter.
    pub const fn points(&self) -> &'r [ReferencePoint] {
        self.points
    }

    /// Limbs of 32 bits the orbit was computed in.
    pub const fn limbs(&self) -> u32 {
        self.limbs
    }

    /// Whether the reference point itself escaped (its last point is past radius 2).
    pub const fn escaped(&self) -> bool {
        self.escaped
    }
}

/// Limbs the reference of `view` needs: its integer bits and fraction down to
/// the guard bits below the pixel spacing.
fn limbs_for(view: &View) -> usize {
    let spacing_bit = view.deep_spacing.top_bit().unwrap_or(0);
    let iteration_bits = 32 - view.max_iterations.saturating_sub(1).leading_zeros();
    let guard = GUARD_BITS + 4 * iteration_bits;
    let fraction = DeepCoord::FRAC_BITS - spacing_bit.min(DeepCoord::FRAC_BITS) + guard;
    let bits = fraction + (32 * DEEP_LIMBS as u32 - DeepCoord::FRAC_BITS);
    (bits.div_ceil(32) as usize).min(DEEP_LIMBS)
}

/// A pair of wide numbers as a normalised reference point.
fn normalise_pair(x: DeepCoord, y: DeepCoord) -> ReferencePoint {
    // Keep the top 63 bits of the larger part (its sign bit included), then normalise
    // (zero stays zero).
    let top = x.top_bit().max(y.top_bit()).unwrap_or(0);
    let shift = top.saturating_sub(MANTISSA_BITS);
    ReferencePoint(normalise(
        i128::from(x.bits_from(shift)),
        i128::from(y.bits_from(shift)),
        DeepCoord::FRAC_BITS as i32 - shift as i32,
    ))
}

/// The pixels of a perturbed render: the reference, the spacing, the view's cap, the
/// series that skips the pixels' first iterations, and where the view allows it, the
/// Q60 kernel that finishes them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Perturbation<'r> {
    reference: &'r [ReferencePoint],
    /// Half the pixel spacing: `spacing_mantissa`·2^−`spacing_exponent`, the mantissa in
    /// [2⁶¹, 2⁶²).
    spacing_mantissa: i64,
    spacing_exponent: i32,
    /// log₂ of the pixel spacing, Q16 (distance estimation's unit).
    spacing_log2: i32,
    /// The centre in Q28, for the cardioid test and the smooth value.
    centre: (i32, i32),
    max: u32,
    inside: u32,
    smooth: bool,
    /// Fractint's `outside=` (see `modes`).
    outside: Outside,
    /// What the view asks of distance estimation, if anything.
    estimate: Option<Estimate>,
    series: Series,
    finish: Option<Finish>,
    /// Repeats: exact (`None`), or within 2^`repeat_log2` (a sixteenth of a pixel's
    /// spacing at most, and at most `Fast`'s cap of 2⁻²²).
    repeat_log2: Option<i32>,
}

/// Where the view allows it (`finishes_in_high_words`), pixels finish after the series
/// as z itself in Q60 by the products' high words: from the skipped-to iteration on that
/// costs far fewer instructions a step than δ.
#[derive(Debug, Clone, Copy)]
struct Finish {
    kernel: Kernel,
    /// The view's centre and spacing in Q60, as `Deep` takes its pixels' points.
    centre: (i64, i64),
    spacing: i64,
    /// The reference at the skip in Q60: each pixel's z there is it plus its δ.
    reference: (i64, i64),
}

/// How far below a pixel the finish's rounding must stay, beyond 2 bits for each doubling
/// of the iterations, for pixels to finish in Q60; otherwise they go on by perturbation. Eight bits keep
/// every dwell where it was measured (docs/performance.md).
const FINISH_BITS: i32 = 8;

/// The high-word finish's precision: each product within 2^-55, x² − y² within 2^-54.
const HIGH_WORDS_BITS: i32 = 54;

/// A perturbed pixel's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Perturbed {
    /// Its value, and the steps computed.
    pub(crate) orbit: Orbit,
    /// Times it rebased.
    pub(crate) rebases: u32,
    /// Iterations the series skipped.
    pub(crate) skipped: u32,
}

impl<'r> Perturbation<'r> {
    /// The pixels of `view` against `reference` (computed for that view).
    pub(crate) fn new(
        view: &View,
        reference: ReferenceOrbit<'r>,
        periodicity: Periodicity,
    ) -> Self {
        let spacing = view.deep_spacing;
        let top = spacing.top_bit().unwrap_or(0);
        let mantissa = if top >= 61 {
            spacing.bits_from(top - 61)
        } else {
            spacing.shl(61 - top).bits_from(0)
        };
        // spacing = mantissa·2^(top − 61 − FRAC_BITS); half of it one more.
        let exponent = DeepCoord::FRAC_BITS as i32 + 61 - top as i32 + 1;
        let q28 = |value: DeepCoord| value.bits_from(DeepCoord::FRAC_BITS - 28) as i32;
        let mut pixels = Self {
            reference: reference.points,
            spacing_mantissa: mantissa,
            spacing_exponent: exponent,
            // The spacing is mantissa·2^(62 − exponent) with the mantissa in [2⁶¹, 2⁶²).
            spacing_log2: log2(mantissa.unsigned_abs(), 61).unwrap_or(0)
                + ((62 - exponent) << LOG2_FRAC_BITS),
            centre: (q28(view.deep_centre.0), q28(view.deep_centre.1)),
            max: view.max_iterations,
            inside: u32::from(view.inside_value()),
            smooth: view.shading == Shading::Smooth,
            outside: view.outside,
            estimate: Estimate::of(view),
            series: Series::NONE,
            finish: None,
            // Half the spacing is at least 2^(61 - exponent): a sixteenth of the spacing at
            // least 2^(58 - exponent).
            repeat_log2: match periodicity {
                Periodicity::Exact => None,
                Periodicity::Within(_) => {
                    Some((58 - exponent).min(MAX_FAST_TOLERANCE.trailing_zeros() as i32 - 60))
                }
            },
        };
        let corner = (
            view.column_steps(i64::from(view.size.width) - 1),
            view.row_steps(0),
        );
        pixels.series = Series::new(
            pixels.reference,
            corner,
            |re, im| pixels.offset(re, im),
            pixels.max,
        );
        let skip = pixels.series.skip();
        if let Some(z) = pixels
            .reference
            .get(skip as usize)
            // The finish carries no derivative: estimating pixels go on by perturbation.
            .filter(|_| {
                skip > 0
                    && pixels.estimate.is_none()
                    && finishes_in_high_words(view, &pixels.series)
            })
        {
            pixels.finish = Some(Finish {
                kernel: Kernel::new(view, Periodicity::Exact),
                centre: (view.centre.0.to_bits(), view.centre.1.to_bits()),
                spacing: view.spacing().to_bits(),
                reference: (to_q60(z.0.x, z.0.s), to_q60(z.0.y, z.0.s)),
            });
        }
        pixels
    }

    /// δc of the pixel whose offsets from the centre are `re`·spacing/2 and
    /// `im`·spacing/2 (odd integers, as the view's points are).
    #[inline(never)]
    fn offset(&self, re: i64, im: i64) -> Scaled {
        normalise(
            mul_wide(re, self.spacing_mantissa),
            mul_wide(im, self.spacing_mantissa),
            self.spacing_exponent,
        )
    }

    /// The value of the pixel offset by (`re`, `im`) half spacings from the centre.
    pub(crate) fn dwell(&self, re: i64, im: i64) -> Perturbed {
        if self.estimate.is_some() {
            self.estimating(re, im)
        } else {
            self.iterate::<false>(re, im)
        }
    }

    /// [`dwell`](Self::dwell) with the view's distance estimate: out of line, so the plain
    /// pixels' code and frame carry nothing for it.
    #[inline(never)]
    fn estimating(&self, re: i64, im: i64) -> Perturbed {
        self.iterate::<true>(re, im)
    }

    /// [`dwell`](Self::dwell)'s orbit; with `ESTIMATE`, its derivative dz carried beside
    /// δ (from the series' derivative at the skip, each step from the full point Zₘ + δ,
    /// see `distance`) and an escaping pixel's value the estimate's. One source, two
    /// copies of the code. The finish in Q60 carries no derivative: estimating pixels go
    /// on by perturbation.
    #[inline(always)]
    fn iterate<const ESTIMATE: bool>(&self, re: i64, im: i64) -> Perturbed {
        let c = self.offset(re, im);
        let point = (
            i64::from(self.centre.0) + to_q28(c.x, c.s),
            i64::from(self.centre.1) + to_q28(c.y, c.s),
        );
        let point = (clamp_i32(point.0), clamp_i32(point.1));
        let inside = |iterations| Orbit {
            dwell: self.inside,
            iterations,
        };
        if in_cardioid_or_bulb(point.0, point.1) {
            return Perturbed {
                orbit: inside(0),
                rebases: 0,
                skipped: 0,
            };
        }
        let skip = self.series.skip();
        // Steps computed are those past the skip.
        let result = |orbit: Orbit, rebases| Perturbed {
            orbit: Orbit {
                iterations: orbit.iterations.saturating_sub(skip),
                ..orbit
            },
            rebases,
            skipped: skip,
        };
        let mut delta = Scaled::ZERO;
        let mut dz = Derivative::ZERO;
        if skip > 0 {
            delta = self.series.delta(c);
            if ESTIMATE {
                dz = Derivative::of_scaled(self.series.slope(c));
            }
            if let Some(finish) = self.finish.as_ref().filter(|_| !ESTIMATE) {
                let z = (
                    finish.reference.0.saturating_add(to_q60(delta.x, delta.s)),
                    finish.reference.1.saturating_add(to_q60(delta.y, delta.s)),
                );
                let c = (
                    finish.point(finish.centre.0, re),
                    finish.point(finish.centre.1, im),
                );
                return result(finish.kernel.resume(c, z, skip), 0);
            }
        }
        let last = self.reference.len().saturating_sub(1);
        let mut m = skip as usize;
        let mut n = skip;
        let mut rebases = 0;
        let mut repeats = Repeats::default();
        while n < self.max {
            let Some(&z) = self.reference.get(m) else {
                break;
            };
            if ESTIMATE {
                // z = Zₘ + δ in its own exponent (the sum is always made).
                if let Some(point) = rebased(z.0, delta, true) {
                    dz.step_scaled(point);
                }
            }
            delta = step(delta, z.0, c);
            m += 1;
            n += 1;
            let Some(&next) = self.reference.get(m) else {
                break;
            };
            let next = next.0;
            if let Some(z) = escaped(next, delta) {
                let dwell = if self.smooth {
                    smooth_value(n, z, point, self.max, self.inside)
                } else if self.outside == Outside::Iter {
                    n
                } else {
                    self.outside.value(n, z, self.max)
                };
                let orbit = Orbit {
                    dwell,
                    iterations: n,
                };
                if ESTIMATE {
                    return result(self.estimated(orbit, z, point, dz), rebases);
                }
                return result(orbit, rebases);
            }
            if m == last || may_rebase(next, delta) {
                if let Some(z) = rebased(next, delta, m == last) {
                    delta = z;
                    m = 0;
                    rebases += 1;
                    if repeats.after_rebase(delta, rebases, self.repeat_log2) {
                        return result(inside(n), rebases);
                    }
                }
            }
        }
        result(inside(n), rebases)
    }

    /// An escaped pixel's `orbit` as distance estimation has it, from its point `z` past
    /// the escape (Q28), its c (`point`, Q28) and its derivative: its value, and the steps
    /// on to |z| ≥ 256 added.
    fn estimated(&self, orbit: Orbit, z: (i32, i32), point: (i32, i32), dz: Derivative) -> Orbit {
        let Some(estimate) = self.estimate else {
            return orbit;
        };
        let q60 = |(x, y): (i32, i32)| (i64::from(x) << 32, i64::from(y) << 32);
        let (distance, steps) = log2_pixels_past_escape(
            (q60(z), orbit.iterations),
            q60(point),
            LooseDerivative::of(dz, true),
            self.spacing_log2,
        );
        estimated(estimate, orbit, distance, steps, self.inside)
    }
}

/// Whether a view's pixels may finish in Q60 by high words after the series skipped its
/// first steps. Two rules, each with `FINISH_BITS` to spare and 2 bits for each doubling
/// of the iterations the rounding has to grow in (as the fixed tiers' calibration found
/// rounding to grow): `Deep`'s own rounding from the start must stay below a pixel's
/// spacing (so the view's c are distinct in Q60), and the high words' rounding after the
/// skip below a pixel's image there, which is how far apart neighbouring pixels' orbits
/// are by then (at the deep-zoom view 2^-20 against a spacing of 2^-30).
fn finishes_in_high_words(view: &View, series: &Series) -> bool {
    let bits = |n: u32| 32 - n.leading_zeros() as i32;
    let spacing_bits = 63 - view.spacing().to_bits().max(1).leading_zeros() as i32;
    let deep_margin = spacing_bits - 2 * bits(view.max_iterations);
    let remaining = view.max_iterations.saturating_sub(series.skip());
    let image_margin = series.image_log2() + HIGH_WORDS_BITS - 2 * bits(remaining);
    view.fixed_point_resolves() && deep_margin >= FINISH_BITS && image_margin >= FINISH_BITS
}

/// Brent's repeat test over a pixel's rebases: δ just after one is compared with δ saved
/// just after rebase 1, 2, 4, 8, ... The pixel's state (m, δ), of which the step is a
/// function, is then back where it was, since m is 0 after every rebase (and z = δ there:
/// no cancellation against Z). Kept in memory and out of line: the steps between rebases
/// do not touch it.
#[derive(Debug, Default)]
struct Repeats {
    saved: Option<Scaled>,
    save_at: u32,
}

impl Repeats {
    /// Whether δ just after the pixel's rebase number `rebases` repeats the saved one:
    /// exactly (`tolerance_log2` `None`), or within 2^`tolerance_log2`.
    #[inline(never)]
    fn after_rebase(&mut self, delta: Scaled, rebases: u32, tolerance_log2: Option<i32>) -> bool {
        if let Some(saved) = self.saved {
            let repeat = match tolerance_log2 {
                None => delta == saved,
                Some(log2) => delta.sub(saved).upper_log2() <= log2,
            };
            if repeat {
                return true;
            }
        }
        if rebases >= self.save_at {
            self.saved = Some(delta);
            self.save_at = rebases.saturating_mul(2);
        }
        false
    }
}

impl Finish {
    /// A pixel's coordinate in Q60 from the centre's and its offset in half spacings.
    fn point(&self, centre: i64, steps: i64) -> i64 {
        let q60 = i128::from(centre) + half_spacings(self.spacing, steps);
        q60.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64
    }
}

/// A mantissa with exponent in Q60, saturating (the values converted are below 8).
fn to_q60(mantissa: i64, exponent: i32) -> i64 {
    if exponent >= 60 {
        mantissa >> (exponent - 60).min(63)
    } else {
        let shift = (60 - exponent) as u32;
        if mantissa.unsigned_abs().leading_zeros() > shift {
            mantissa << shift
        } else if mantissa < 0 {
            i64::MIN
        } else {
            i64::MAX
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pixel inside a period-78 minibrot (beside the nucleus at the view's centre)
    /// rebases every 78 steps and its δ there converges: `Fast`'s repeat test, within a
    /// sixteenth of a pixel, stops it early; the exact test finds no exact repeat of 62-bit
    /// mantissas and runs it to the cap. Both say inside.
    #[test]
    fn an_interior_pixel_stops_at_a_repeat_within_the_tolerance() {
        extern crate std;
        let parse = |text: &str| DeepCoord::parse(text).unwrap();
        let view = View::deep(
            Fractal::Mandelbrot,
            (
                parse("-0.10109636410757091114366614915908574412568301067472"),
                parse("0.95628651094936751151473189358592427640764366257311"),
            ),
            parse("1e-20"),
            embedded_graphics::geometry::Size::new(48, 36),
            2000,
        )
        .unwrap();
        let mut storage = std::vec![ReferencePoint::default(); 2001];
        let reference = ReferenceOrbit::compute(&view, &mut storage).unwrap();
        let pixel = |periodicity| Perturbation::new(&view, reference, periodicity).dwell(1, 1);
        let (exact, within) = (pixel(Periodicity::Exact), pixel(Periodicity::Within(0)));
        assert_eq!((exact.orbit.dwell, within.orbit.dwell), (2000, 2000));
        assert!(exact.rebases > 20, "{exact:?}");
        // Saved after rebase 16, matched at 17: a quarter of the steps or more saved.
        assert!(
            4 * within.orbit.iterations <= 3 * exact.orbit.iterations,
            "{within:?} against {exact:?}"
        );
    }
}
