//! Fitting a picture to a target, for every family.

use core::fmt;

/// The picture cannot be placed on the target as asked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum FitError {
    /// Nothing is drawn at this order, so there is nothing to fit.
    EmptyDrawing,
    /// The target has no pixels to draw into.
    ZeroSizeTarget,
    /// The palette has no colours.
    EmptyPalette,
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::EmptyDrawing => write!(f, "the system draws nothing at this order"),
            Self::ZeroSizeTarget => write!(f, "the draw target has zero width or height"),
            Self::EmptyPalette => write!(f, "the palette is empty: give at least one colour"),
        }
    }
}
