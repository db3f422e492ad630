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
    /// The target is one pixel across an axis the picture extends along: the picture
    /// would shrink to a point.
    TargetTooSmall {
        /// The target's width in pixels.
        width: u32,
        /// The target's height in pixels.
        height: u32,
    },
    /// A caller's buffer has fewer cells than the area (or the landscape) it must cover.
    BufferTooSmall {
        /// Cells needed (the area's width × height, or the landscape's heights).
        needed: usize,
        /// Cells given.
        given: usize,
    },
    /// A frame's cells are too narrow for the view's values (a `u8` cell and a cap above
    /// 255, or smooth values).
    CellTooNarrow {
        /// The largest value the view gives (its inside value).
        largest: u32,
        /// The largest value a cell holds.
        cell_max: u32,
    },
    /// On this target a part of the picture would be [`MAX_PART_PIXELS`] pixels long or
    /// more: longer than the pixel walk's 16.16 fixed point holds.
    PartTooLong,
}

/// The longest part of a figure, in pixels of the target, that its walk holds.
pub const MAX_PART_PIXELS: u32 = 1 << 15;

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::EmptyDrawing => write!(f, "the system draws nothing at this order"),
            Self::ZeroSizeTarget => write!(f, "the draw target has zero width or height"),
            Self::EmptyPalette => write!(f, "the palette is empty: give at least one colour"),
            Self::TargetTooSmall { width, height } => write!(
                f,
                "the target ({width}x{height} pixels) is too small for this picture: it needs \
                 at least 2 pixels along each axis the picture extends along"
            ),
            Self::BufferTooSmall { needed, given } => write!(
                f,
                "the buffer has {given} cells and {needed} are needed (one a pixel of the area, \
                 or one a height of a landscape): give a larger buffer"
            ),
            Self::CellTooNarrow { largest, cell_max } => write!(
                f,
                "the view's values reach {largest} but a cell holds at most {cell_max}: use \
                 u16 cells or a lower iteration cap"
            ),
            Self::PartTooLong => write!(
                f,
                "on this target a part of the figure would be {MAX_PART_PIXELS} pixels long or \
                 more, beyond its walk's fixed point: fit it into a smaller area"
            ),
        }
    }
}
