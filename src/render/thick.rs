//! Lines wider than a pixel: a rectangle about the ideal line and a round cap at each end
//! (an octagon), filled by rows, so a plant's widening branches join without notches and
//! every pixel leaves in a run.
//!
//! The rectangle is `width` across, measured square to the line, so a line covers `width`
//! pixels across whatever its direction (within a pixel: the half-open fill rule decides
//! the pixels on its edges). The caps reach `width / 2` beyond each end.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::polygon::{fill_convex, SubPixel, SUBPIXEL_BITS};

/// Widths below this (Q16 pixels: 1.5) draw as one-pixel lines.
pub(crate) const THICK_FROM: i64 = 3 << (SUBPIXEL_BITS - 1);

/// Widths from this (Q16 pixels: 3) get round caps; narrower ends are square.
const CAPPED_FROM: i64 = 3 << SUBPIXEL_BITS;

/// cos and sin of 22.5° and 67.5° in Q16, the octagon's corners.
const NEAR: i64 = 60_547;
const FAR: i64 = 25_080;

/// Fills the line from `from` to `to` (Q16 pixels, on the pixel grid of the fill rule),
/// `width` Q16 pixels across, in `color`, clipped to `clip`.
pub(crate) fn fill_thick_line<D: DrawTarget>(
    target: &mut D,
    (from, to): (SubPixel, SubPixel),
    width: i64,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let half = width / 2;
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let squared = u128::from(dx.unsigned_abs()).pow(2) + u128::from(dy.unsigned_abs()).pow(2);
    let length = i64::try_from(squared.isqrt()).unwrap_or(i64::MAX);
    if length > 0 {
        // The half-width square to the line: (−dy, dx) · half / length.
        let across = |d: i64| {
            i64::try_from(i128::from(d) * i128::from(half) / i128::from(length)).unwrap_or(0)
        };
        let (nx, ny) = (across(-dy), across(dx));
        let quad = [
            (from.0 + nx, from.1 + ny),
            (to.0 + nx, to.1 + ny),
            (to.0 - nx, to.1 - ny),
            (from.0 - nx, from.1 - ny),
        ];
        fill_convex(target, &quad, color, clip)?;
    }
    if width >= CAPPED_FROM || length == 0 {
        fill_cap(target, from, half, color, clip)?;
        fill_cap(target, to, half, color, clip)?;
    }
    Ok(())
}

/// A regular octagon of circumradius `radius` about `centre`.
fn fill_cap<D: DrawTarget>(
    target: &mut D,
    centre: SubPixel,
    radius: i64,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let (near, far) = (
        (radius * NEAR) >> SUBPIXEL_BITS,
        (radius * FAR) >> SUBPIXEL_BITS,
    );
    let (x, y) = centre;
    let octagon = [
        (x + near, y + far),
        (x + far, y + near),
        (x - far, y + near),
        (x - near, y + far),
        (x - near, y - far),
        (x - far, y - near),
        (x + far, y - near),
        (x + near, y - far),
    ];
    fill_convex(target, &octagon, color, clip)
}
