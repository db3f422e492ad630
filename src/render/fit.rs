//! Fitting a picture into a target: which way its axes point on screen, and the scale and
//! offset that centre its bounding box in an area, less a margin. Every family that draws
//! in its own units (turtle steps, IFS coordinates) places its picture through this.

use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError, WalkError};
use crate::math::Real;

/// Pixels left free around a fitted picture by default.
pub const DEFAULT_MARGIN: u32 = 2;

/// Which way on screen a picture's +x axis points (its +y is a quarter turn
/// counter-clockwise from it, as in mathematics).
///
/// Fractint draws heading right; *The Algorithmic Beauty of Plants* heading up, so plants
/// grow upward. Quarter turns are exact: they only swap and negate coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Orientation {
    /// Heading right (Fractint).
    #[default]
    Right,
    /// Heading up (ABOP).
    Up,
    /// Heading left.
    Left,
    /// Heading down.
    Down,
}

impl Orientation {
    /// Picture space (y up) to screen space (y down), same units.
    pub(crate) fn to_screen(self, (x, y): (Real, Real)) -> (Real, Real) {
        match self {
            Self::Right => (x, neg(y)),
            Self::Up => (neg(y), neg(x)),
            Self::Left => (neg(x), y),
            Self::Down => (y, x),
        }
    }

    /// Screen space back to picture space.
    pub(crate) fn to_picture(self, (sx, sy): (Real, Real)) -> (Real, Real) {
        match self {
            Self::Right => (sx, neg(sy)),
            Self::Up => (neg(sy), neg(sx)),
            Self::Left => (neg(sx), sy),
            Self::Down => (sy, sx),
        }
    }
}

fn neg(value: Real) -> Real {
    Real::from_bits(value.to_bits().saturating_neg())
}

/// How a picture lands on the target: pixels per picture unit, and the screen position of
/// the picture's origin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Fitted {
    pub(crate) scale: Real,
    pub(crate) origin: (Real, Real),
}

/// Scales and centres a picture whose corners are `a` and `b` (picture units, in any
/// order) into `area` less `margin` pixels on each side (dropped where the area cannot
/// afford it). Pixel centres span size − 1 pixels. A picture too large for fixed point to
/// place truthfully is [`WalkError::Overflow`]; the area must not be empty.
pub(crate) fn fit(
    a: (Real, Real),
    b: (Real, Real),
    orientation: Orientation,
    area: &Rectangle,
    margin: u32,
) -> Result<Fitted, Error> {
    let (a, b) = (orientation.to_screen(a), orientation.to_screen(b));
    let (min_x, max_x) = (a.0.min(b.0), a.0.max(b.0));
    let (min_y, max_y) = (a.1.min(b.1), a.1.max(b.1));
    let span = |size: u32| {
        let inner = size.saturating_sub(1);
        let margin = if inner > 2 * margin { margin } else { 0 };
        Real::from_int(i32::try_from(inner - 2 * margin).unwrap_or(i32::MAX))
    };
    let overflow = Error::Walk(WalkError::Overflow);
    let extent_x = max_x.checked_sub(min_x).ok_or(overflow)?;
    let extent_y = max_y.checked_sub(min_y).ok_or(overflow)?;
    // Pixels per picture unit: the tighter of the two axes.
    let scale = [
        span(area.size.width).checked_div(extent_x),
        span(area.size.height).checked_div(extent_y),
    ]
    .into_iter()
    .flatten()
    .min()
    .unwrap_or(Real::ONE);
    let flat = |size: u32, extent: Real| size <= 1 && extent.to_bits() > 0;
    if flat(area.size.width, extent_x) || flat(area.size.height, extent_y) {
        return Err(Error::Fit(FitError::TargetTooSmall {
            width: area.size.width,
            height: area.size.height,
        }));
    }
    // The origin lands where the scaled picture's middle falls on the area's middle.
    let placed_middle = |low: Real, high: Real, start: i32, size: u32| -> Option<Real> {
        let middle = Real::from_bits(low.checked_add(high)?.to_bits() / 2);
        let centre = Real::from_ratio(2 * i64::from(start) + i64::from(size) - 1, 2)?;
        centre.checked_sub(middle.checked_mul(scale)?)
    };
    let origin = (
        placed_middle(min_x, max_x, area.top_left.x, area.size.width).ok_or(overflow)?,
        placed_middle(min_y, max_y, area.top_left.y, area.size.height).ok_or(overflow)?,
    );
    Ok(Fitted { scale, origin })
}
