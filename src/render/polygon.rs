//! Convex polygons filled by rows: one `fill_solid` per row of a polygon, with a
//! half-open rule (a pixel is inside when its centre is, on the left and top edges but not
//! the right and bottom ones), so polygons that share an edge neither overlap nor leave a
//! gap between them. Vertices are in Q16 pixels (1/65536 of a pixel).

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// Fractional bits of a vertex coordinate.
pub(crate) const SUBPIXEL_BITS: u32 = 16;
const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;

/// A point in Q16 pixels.
pub(crate) type SubPixel = (i64, i64);

/// The x where the edge from `a` to `b` crosses height `y` (Q16), computed from the
/// endpoints in a fixed order (the upper first), so two polygons sharing an edge get the
/// same crossing to the bit.
fn crossing(a: SubPixel, b: SubPixel, y: i64) -> i64 {
    let (top, bottom) = if (a.1, a.0) <= (b.1, b.0) {
        (a, b)
    } else {
        (b, a)
    };
    let dy = bottom.1 - top.1;
    if dy == 0 {
        return top.0;
    }
    top.0 + (y - top.1) * (bottom.0 - top.0) / dy
}

/// The first pixel whose centre is at or after `edge` (Q16).
fn first_pixel(edge: i64) -> i64 {
    // ceil((edge - 1/2) / 1)
    (edge - HALF + ONE - 1).div_euclid(ONE)
}

/// Fills the convex polygon with `vertices` (in order, either winding) in `color`, clipped
/// to `clip`: one `fill_solid` per row it covers.
pub(crate) fn fill_convex<D: DrawTarget>(
    target: &mut D,
    vertices: &[SubPixel],
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let (Some(low), Some(high)) = (
        vertices.iter().map(|v| v.1).min(),
        vertices.iter().map(|v| v.1).max(),
    ) else {
        return Ok(());
    };
    let Some(clip_end) = clip.bottom_right() else {
        return Ok(());
    };
    let rows = first_pixel(low).max(i64::from(clip.top_left.y))
        ..first_pixel(high).min(i64::from(clip_end.y) + 1);
    for row in rows {
        let centre = row * ONE + HALF;
        let (mut left, mut right) = (i64::MAX, i64::MIN);
        for (i, &a) in vertices.iter().enumerate() {
            let b = vertices
                .get(i + 1)
                .or(vertices.first())
                .copied()
                .unwrap_or(a);
            let (y0, y1) = if a.1 <= b.1 { (a.1, b.1) } else { (b.1, a.1) };
            // Half-open in y: an edge covers the rows whose centre is in [y0, y1).
            if y0 <= centre && centre < y1 {
                let x = crossing(a, b, centre);
                left = left.min(x);
                right = right.max(x);
            }
        }
        if left >= right {
            continue;
        }
        let start = first_pixel(left).max(i64::from(clip.top_left.x));
        let end = first_pixel(right).min(i64::from(clip_end.x) + 1);
        if start < end {
            let (Ok(x), Ok(y), Ok(width)) = (
                i32::try_from(start),
                i32::try_from(row),
                u32::try_from(end - start),
            ) else {
                continue;
            };
            target.fill_solid(
                &Rectangle::new(Point::new(x, y), Size::new(width, 1)),
                color,
            )?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A whole-pixel point in Q16.
    const fn subpixel(x: i64, y: i64) -> SubPixel {
        (x << SUBPIXEL_BITS, y << SUBPIXEL_BITS)
    }
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;

    #[test]
    fn a_square_on_pixel_edges_covers_its_pixels_exactly() {
        let mut display = MockDisplay::<BinaryColor>::new();
        let square = [
            subpixel(1, 1),
            subpixel(4, 1),
            subpixel(4, 3),
            subpixel(1, 3),
        ];
        let clip = display.bounding_box();
        fill_convex(&mut display, &square, BinaryColor::On, &clip).unwrap();
        display.assert_pattern(&[
            "     ", //
            " ### ", //
            " ### ", //
        ]);
    }

    #[test]
    fn triangles_sharing_an_edge_neither_overlap_nor_leave_gaps() {
        // Two triangles splitting a 6x5 rectangle along a slanted diagonal: every pixel of
        // the rectangle exactly once (MockDisplay panics on overdraw).
        let mut display = MockDisplay::<BinaryColor>::new();
        let (a, b, c, d) = (
            (ONE / 3, ONE / 5),
            (6 * ONE + ONE / 3, ONE / 5),
            (6 * ONE + ONE / 3, 5 * ONE + ONE / 5),
            (ONE / 3, 5 * ONE + ONE / 5),
        );
        let clip = display.bounding_box();
        fill_convex(&mut display, &[a, b, c], BinaryColor::On, &clip).unwrap();
        fill_convex(&mut display, &[a, c, d], BinaryColor::Off, &clip).unwrap();
        let covered = display.affected_area();
        assert_eq!(covered, Rectangle::new(Point::new(0, 0), Size::new(6, 5)));
        let count = covered
            .points()
            .filter(|&p| display.get_pixel(p).is_some())
            .count();
        assert_eq!(count, 30);
    }
}
