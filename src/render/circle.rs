//! A circle's outline in runs: every pixel its curve passes through, for a centre and a
//! radius anywhere between pixels, two runs a row (one where the ring closes).
//!
//! The plane is Q16.16 with pixel (x, y) covering [x − ½, x + ½) × [y − ½, y + ½). In the
//! band of row y the curve's points lie at horizontal distances from wᵢ to wₒ of the
//! centre, wₒ² = r² − (nearest dy)² and wᵢ² = r² − (farthest dy)²; the pixels touched are
//! those meeting [cx − wₒ, cx − wᵢ] or [cx + wᵢ, cx + wₒ]. Each boundary moves a pixel
//! at a time from the last row's, with squares of 32-bit distances compared in 64 bits: no square roots, and
//! the work is the circle's perimeter in pixels. The outline reaches exactly the pixels
//! holding cx ± r and cy ± r, so a fit that measured centre ± radius is tight.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::math::wide::square_i32_wide as square;

/// The largest radius drawn, in pixels: larger circles are a caller's polygon.
pub(crate) const MAX_CIRCLE_RADIUS: i64 = 1 << 12;

/// Whether a circle of `radius` (Q16.16 pixels) is drawn by [`draw_circle`].
pub(crate) const fn drawn_as_circle(radius: i64) -> bool {
    radius >= 0 && radius <= MAX_CIRCLE_RADIUS << 16
}

/// The pixel holding a Q16.16 coordinate (ties to the higher pixel).
#[inline(always)]
fn holding(v: i64) -> i64 {
    (v + (1 << 15)) >> 16
}

/// Draws the outline of the circle about `centre` of `radius` (Q16.16 pixels, at most
/// [`MAX_CIRCLE_RADIUS`]; larger ones draw nothing) in `color`, rows outside `clip`
/// skipped and runs cut to it.
///
/// The edges are measured from the centre's pixel, so every distance fits 32 bits (at
/// most the radius and a pixel) and each square is one 32 × 32 → 64-bit product.
#[inline(never)]
pub(crate) fn draw_circle<D: DrawTarget>(
    target: &mut D,
    (cx, cy): (i64, i64),
    radius: i64,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    if !drawn_as_circle(radius) {
        return Ok(());
    }
    let Some(clip_end) = clip.bottom_right() else {
        return Ok(());
    };
    let (clip_start, clip_end) = (clip.top_left, clip_end);
    let top = holding(cy - radius).max(i64::from(clip_start.y));
    let bottom = holding(cy + radius).min(i64::from(clip_end.y));
    if top > bottom {
        return Ok(());
    }
    // The radius is at most 2^28 (MAX_CIRCLE_RADIUS pixels in Q16.16).
    let r2 = square(radius as i32);
    let (middle, centre_row) = (holding(cx), holding(cy));
    // Pixel middle + k: its left edge less cx is (k << 16) + left, cx less its right edge
    // is right − (k << 16); both start within a pixel of 0.
    let left = ((middle << 16) - (1 << 15) - cx) as i32;
    let right = (cx - (middle << 16) - (1 << 15)) as i32;
    // Pixel middle + k meets [cx, cx + w] (w² = w2) on the right, [cx − w, cx] on the left.
    let meets_right = |k: i32, w2: i64| {
        let d = (k << 16) + left;
        d <= 0 || square(d) <= w2
    };
    let meets_left = |k: i32, w2: i64| {
        let e = right - (k << 16);
        e < 0 || square(e) < w2
    };
    // The clip's columns as offsets from the centre's pixel.
    let offset = |x: i32| (i64::from(x) - middle).clamp(i32::MIN.into(), i32::MAX.into()) as i32;
    let (clip_left, clip_right) = (offset(clip_start.x), offset(clip_end.x));
    // Row centre_row + j: its band's top edge less cy is (j << 16) + band.
    let band = ((centre_row << 16) - (1 << 15) - cy) as i32;
    // Within a pixel and the radius of the centre's row.
    let (first, last) = ((top - centre_row) as i32, (bottom - centre_row) as i32);
    let (mut outer_right, mut outer_left) = (0, 0);
    for j in first..=last {
        let low = (j << 16) + band;
        let high = low + (1 << 16);
        let near = if low > 0 {
            low
        } else if high < 0 {
            -high
        } else {
            0
        };
        let far = low.unsigned_abs().max(high.unsigned_abs()) as i32;
        let outer = r2 - square(near);
        if outer < 0 {
            continue;
        }
        while meets_right(outer_right + 1, outer) {
            outer_right += 1;
        }
        while outer_right > 0 && !meets_right(outer_right, outer) {
            outer_right -= 1;
        }
        while meets_left(outer_left - 1, outer) {
            outer_left -= 1;
        }
        while outer_left < 0 && !meets_left(outer_left, outer) {
            outer_left += 1;
        }
        // The hole: pixels between the ring's two sides in this row.
        let inner = r2 - square(far);
        let (mut inner_right, mut inner_left) = (outer_right, outer_left);
        if inner > 0 {
            while inner_right > 0 && !meets_right(inner_right, inner) {
                inner_right -= 1;
            }
            while inner_left < 0 && !meets_left(inner_left, inner) {
                inner_left += 1;
            }
        }
        let row = (centre_row + i64::from(j)) as i32;
        let mut send = |from: i32, to: i32| -> Result<(), D::Error> {
            let (from, to) = (from.max(clip_left), to.min(clip_right));
            if from > to {
                return Ok(());
            }
            let run = Rectangle::new(
                Point::new((middle + i64::from(from)) as i32, row),
                Size::new(to.abs_diff(from) + 1, 1),
            );
            target.fill_solid(&run, color)
        };
        if inner <= 0 || inner_left + 1 >= inner_right {
            send(outer_left, outer_right)?;
        } else {
            send(outer_left, inner_left)?;
            send(inner_right, outer_right)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;

    /// Whether the circle's curve passes through pixel (x, y), in f64: it does if the
    /// pixel's square holds points both inside and outside the circle, or touches it (the
    /// nearest point within r and the farthest at least r).
    fn passes(cx: f64, cy: f64, r: f64, x: i32, y: i32) -> bool {
        let (x0, x1) = (f64::from(x) - 0.5, f64::from(x) + 0.5);
        let (y0, y1) = (f64::from(y) - 0.5, f64::from(y) + 0.5);
        let nx = cx.clamp(x0, x1) - cx;
        let ny = cy.clamp(y0, y1) - cy;
        let fx = (cx - x0).abs().max((x1 - cx).abs());
        let fy = (cy - y0).abs().max((y1 - cy).abs());
        let near = (nx * nx + ny * ny).sqrt();
        let far = (fx * fx + fy * fy).sqrt();
        near <= r && far >= r
    }

    /// The runs light the pixels the curve passes through (an f64 model of the square and
    /// the circle), apart from pixels the curve only grazes within 10⁻⁶ of a pixel.
    #[test]
    fn the_outline_is_the_pixels_the_curve_passes_through() {
        let mut seed = 12345u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        for case in 0..400 {
            let cx = 20.0 + f64::from(next() % 2_000_000) / 100_000.0;
            let cy = 20.0 + f64::from(next() % 2_000_000) / 100_000.0;
            let r = match case % 4 {
                0 => f64::from(next() % 100_000) / 100_000.0,
                _ => f64::from(next() % 1_600_000) / 100_000.0,
            };
            let q16 = |v: f64| (v * 65536.0).round() as i64;
            let (qx, qy, qr) = (q16(cx), q16(cy), q16(r));
            let (cx, cy, r) = (
                qx as f64 / 65536.0,
                qy as f64 / 65536.0,
                qr as f64 / 65536.0,
            );
            let mut display = MockDisplay::<BinaryColor>::new();
            let clip = display.bounding_box();
            draw_circle(&mut display, (qx, qy), qr, BinaryColor::On, &clip).unwrap();
            for y in 0..64 {
                for x in 0..64 {
                    let lit = display.get_pixel(Point::new(x, y)).is_some();
                    if lit != passes(cx, cy, r, x, y) {
                        // Only where the model sits on a knife edge.
                        let nudged = [(-1e-6, 0.0), (1e-6, 0.0), (0.0, -1e-6), (0.0, 1e-6)];
                        let grazing = [-1e-6, 1e-6].iter().any(|&dr| {
                            nudged
                                .iter()
                                .any(|&(dx, dy)| passes(cx + dx, cy + dy, r + dr, x, y) == lit)
                        });
                        assert!(grazing, "case {case}: ({x}, {y}) of {cx} {cy} r {r}: {lit}");
                    }
                }
            }
            // Tight: the outline reaches the pixels holding the circle's extremes.
            let area = display.affected_area();
            let hold = |v: f64| (v + 0.5).floor() as i32;
            assert_eq!(
                area.top_left,
                Point::new(hold(cx - r), hold(cy - r)),
                "case {case}"
            );
        }
    }

    /// Rows and runs outside the clip are not drawn; a radius beyond the largest draws
    /// nothing.
    #[test]
    fn clipped_and_bounded() {
        let mut display = MockDisplay::<BinaryColor>::new();
        let clip = Rectangle::new(Point::new(10, 10), Size::new(20, 20));
        draw_circle(
            &mut display,
            (20 << 16, 20 << 16),
            30 << 16,
            BinaryColor::On,
            &clip,
        )
        .unwrap();
        assert!(display.affected_area().is_zero_sized());
        draw_circle(
            &mut display,
            (20 << 16, 20 << 16),
            12 << 16,
            BinaryColor::On,
            &clip,
        )
        .unwrap();
        assert_eq!(display.affected_area(), clip);
        let mut untouched = MockDisplay::<BinaryColor>::new();
        let huge = (MAX_CIRCLE_RADIUS + 1) << 16;
        draw_circle(&mut untouched, (0, 0), huge, BinaryColor::On, &clip).unwrap();
        assert!(untouched.affected_area().is_zero_sized());
    }
}
