//! Escape-time views: the window onto the complex plane and the iteration cap.

use core::fmt;

/// The view cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ViewError {
    /// The iteration cap is 0 or above `max`.
    IterationsOutOfRange {
        /// The value given.
        value: u32,
        /// The highest cap ([`MAX_ITERATIONS`](crate::MAX_ITERATIONS)).
        max: u32,
    },
    /// The view has no positive width, reaches beyond ±3.5, or a Julia parameter has |k| > 2.
    ViewOutOfRange,
    /// The pixel spacing is finer than the deepest tier resolves (2⁻⁵⁴).
    ZoomTooDeep,
}

impl fmt::Display for ViewError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::IterationsOutOfRange { value, max } => {
                write!(f, "max-iter {value} is out of range: use 1 to {max}")
            }
            Self::ViewOutOfRange => write!(
                f,
                "the view is out of range: the width must be positive, every point within \
                 ±3.5, and a Julia parameter at most 2 from 0"
            ),
            Self::ZoomTooDeep => write!(
                f,
                "the zoom is too deep: pixel spacing below 2^-54 is finer than the deepest tier"
            ),
        }
    }
}
