//! Escape-time views: the window onto the complex plane and the iteration cap.

use core::fmt;

use crate::math::{Coord, DeepCoord};

/// The view cannot be computed. Each variant names the one condition that failed and the
/// value that failed it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ViewError {
    /// The iteration cap is 0 or above `max`.
    IterationsOutOfRange {
        /// The value given.
        value: u32,
        /// The highest cap ([`View::MAX_ITERATIONS`](crate::escape::View::MAX_ITERATIONS)).
        max: u32,
    },
    /// Smooth shading asked of a view whose cap is above `max`.
    SmoothIterationsOutOfRange {
        /// The view's cap.
        value: u32,
        /// The highest cap for smooth shading
        /// ([`View::MAX_SMOOTH_ITERATIONS`](crate::escape::View::MAX_SMOOTH_ITERATIONS)).
        max: u32,
    },
    /// The width is zero or negative.
    WidthNotPositive {
        /// The width given.
        width: Coord,
    },
    /// A pixel's point is beyond ±`limit` on an axis (orbits of such points could overflow
    /// a tier before they escape).
    BeyondLimit {
        /// The farthest coordinate of the view from 0, at most [`Coord`]'s range (just
        /// under 8; farther is shown as that).
        reach: Coord,
        /// The limit, 3.5.
        limit: Coord,
    },
    /// The Julia parameter is more than 2 from 0 (its set is then dust).
    JuliaParameterTooFar {
        /// The parameter's real part.
        re: Coord,
        /// The parameter's imaginary part.
        im: Coord,
    },
    /// The pixel spacing (width ÷ pixels across) is finer than the deepest tier resolves.
    ZoomTooDeep {
        /// The spacing.
        spacing: Coord,
        /// The finest spacing supported, 2⁻⁵⁴.
        finest: Coord,
    },
    /// The pixel spacing is finer than perturbation resolves (its reference keeps 40 bits
    /// below a pixel in at most 188 fractional bits).
    PerturbationTooDeep {
        /// The spacing.
        spacing: DeepCoord,
        /// The finest spacing supported, 2⁻¹⁴⁸.
        finest: DeepCoord,
    },
    /// Perturbation asked of a Julia view: one reference orbit with rebasing serves the
    /// Mandelbrot set only.
    PerturbationNeedsMandelbrot,
    /// The storage given for a reference orbit holds fewer points than the view may need.
    ReferenceTooShort {
        /// Points needed: max-iter + 1.
        needed: usize,
        /// Points given.
        given: usize,
    },
    /// A zoom frame asked to compute a view whose tier is perturbation: a frame computes
    /// each pixel alone in a fixed-point tier, and past `Deep`'s rule it would draw what
    /// `Deep` draws, not the view. Render such a frame with a perturbed
    /// [`Render`](crate::escape::Render).
    ZoomNeedsFixedTier,
    /// Fractint's `outside=` modes colour dwells, not smooth values: both were asked.
    OutsideModeWithSmooth,
    /// An `inside=` mode asked of a perturbed render: its pixels' last points are not kept
    /// (render the view in a fixed tier, or without it).
    NotWithPerturbation,
}

impl fmt::Display for ViewError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::IterationsOutOfRange { value, max } => {
                write!(f, "max-iter {value} is out of range: use 1 to {max}")
            }
            Self::SmoothIterationsOutOfRange { value, max } => write!(
                f,
                "max-iter {value} is too high for smooth colouring (sixteenths of an iteration \
                 in 16 bits): use 1 to {max}, or a palette that is not smooth"
            ),
            Self::WidthNotPositive { width } => {
                write!(f, "the width {width} is not positive: give a width above 0")
            }
            Self::BeyondLimit { reach, limit } => write!(
                f,
                "the view reaches {reach} from 0 on an axis, beyond ±{limit}: every point \
                 must be within ±{limit} (narrow the view or move its centre)"
            ),
            Self::JuliaParameterTooFar { re, im } => write!(
                f,
                "the Julia parameter ({re}, {im}) is more than 2 from 0: its set is dust; \
                 give a parameter with re² + im² ≤ 4"
            ),
            Self::ZoomTooDeep { spacing, finest } => write!(
                f,
                "the zoom is too deep: a pixel spacing of {spacing} (width ÷ pixels across) \
                 is finer than the deepest tier's {finest}; widen the view or use fewer pixels"
            ),
            Self::PerturbationTooDeep { spacing, finest } => write!(
                f,
                "the zoom is too deep: a pixel spacing of {spacing:.4e} (width ÷ pixels across) is \
                 finer than perturbation's finest, {finest:.4e} (2^-148); widen the view or use \
                 fewer pixels"
            ),
            Self::PerturbationNeedsMandelbrot => f.write_str(
                "perturbation computes the Mandelbrot set only: a Julia view is limited to the \
                 deep tier's spacing of 2^-54",
            ),
            Self::ReferenceTooShort { needed, given } => write!(
                f,
                "the reference orbit needs {needed} points (max-iter + 1) but its storage holds \
                 {given}: give more storage or fewer iterations"
            ),
            Self::OutsideModeWithSmooth => f.write_str(
                "an outside mode other than iter colours dwells, not smooth values: choose a \
                 palette that is not smooth, or leave out the outside mode",
            ),
            Self::NotWithPerturbation => f.write_str(
                "an inside mode other than maxiter needs a fixed-point tier, and this view is \
                 rendered by perturbation: leave it out, or widen the view to a fixed tier's \
                 depth",
            ),
            Self::ZoomNeedsFixedTier => f.write_str(
                "a zoom frame computes in a fixed-point tier, and this view needs \
                 perturbation: render the frame with a perturbed render instead",
            ),
        }
    }
}
