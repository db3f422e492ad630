//! Polygons filled by rows: one `fill_solid` per span of a row, with a half-open rule (a
//! pixel is inside when its centre is, on the left and top edges but not the right and
//! bottom ones), so polygons that share an edge neither overlap nor leave a gap between
//! them. Vertices are in Q16 pixels (1/65536 of a pixel; pixel (x, y) covers [x, x + 1) ×
//! [y, y + 1)).
//!
//! Convex polygons take a quicker path ([`fill_convex`]); any polygon, concave or crossing
//! itself, fills by the nonzero winding rule ([`fill_polygon`]): a pixel is inside when the
//! outline winds around its centre a nonzero number of times (a figure eight's two loops
//! are both filled, whichever way each turns).

use crate::math::divide::div_i64_by_u32;
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
    let (dx, dy) = (bottom.0 - top.0, bottom.1 - top.1);
    // A level edge, and an upright one (a cube's vertical edges, a thick line's ends),
    // whose crossing is its top's x without a division.
    if dy == 0 || dx == 0 {
        return top.0;
    }
    top.0 + divided((y - top.1) * dx, dy)
}

/// `n / d` as `/` has it (toward zero) for `d` > 0: by 32-bit divisions where `d` fits 32
/// bits (any edge of a picture's size), not a 64-bit library division; on cores without a
/// divide instruction, the library's one call.
fn divided(n: i64, d: i64) -> i64 {
    if cfg!(tinyfractal_no_hardware_divide) {
        return n / d;
    }
    match u32::try_from(d) {
        Ok(d) if d > 0 => div_i64_by_u32(n, d),
        _ => n / d,
    }
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

/// Most vertices [`fill_polygon`] fills (more are ignored, as if the outline closed at
/// the last one kept).
pub(crate) const MAX_FILL_VERTICES: usize = 64;

/// Fills the polygon with `vertices` (in order, either winding, concave or crossing itself)
/// in `color` by the nonzero rule, clipped to `clip`: one `fill_solid` per span of a row.
pub(crate) fn fill_polygon<D: DrawTarget>(
    target: &mut D,
    vertices: &[SubPixel],
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let vertices = vertices.get(..MAX_FILL_VERTICES).unwrap_or(vertices);
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
    let columns = (i64::from(clip.top_left.x), i64::from(clip_end.x) + 1);
    // Each edge crosses a row at most once: a crossing's x and its direction (+1 down).
    let mut crossings = [(0i64, 0i8); MAX_FILL_VERTICES];
    for row in rows {
        let centre = row * ONE + HALF;
        let mut count = 0;
        for (i, &a) in vertices.iter().enumerate() {
            let b = vertices
                .get(i + 1)
                .or(vertices.first())
                .copied()
                .unwrap_or(a);
            let (y0, y1, direction) = if a.1 <= b.1 {
                (a.1, b.1, 1)
            } else {
                (b.1, a.1, -1)
            };
            if y0 <= centre && centre < y1 {
                if let Some(slot) = crossings.get_mut(count) {
                    *slot = (crossing(a, b, centre), direction);
                    count += 1;
                }
            }
        }
        let row_crossings = crossings.get_mut(..count).unwrap_or_default();
        sort_by_x(row_crossings);
        let mut winding = 0i32;
        let mut span_start = 0i64;
        for &(x, direction) in row_crossings.iter() {
            let before = winding;
            winding += i32::from(direction);
            if before == 0 && winding != 0 {
                span_start = x;
            } else if before != 0 && winding == 0 {
                fill_span(target, (span_start, x), row, columns, color)?;
            }
        }
    }
    Ok(())
}

/// Sorts a row's handful of crossings by x: an insertion sort, in place (a few dozen
/// bytes of code where core's sort costs kilobytes of a board's flash).
fn sort_by_x(crossings: &mut [(i64, i8)]) {
    for i in 1..crossings.len() {
        let mut j = i;
        while j > 0 {
            match (crossings.get(j - 1).copied(), crossings.get(j).copied()) {
                (Some(a), Some(b)) if a.0 > b.0 => {
                    crossings.swap(j - 1, j);
                    j -= 1;
                }
                _ => break,
            }
        }
    }
}

/// Fills the pixels of `row` whose centres are in [`left`, `right`), within `columns`.
fn fill_span<D: DrawTarget>(
    target: &mut D,
    (left, right): (i64, i64),
    row: i64,
    columns: (i64, i64),
    color: D::Color,
) -> Result<(), D::Error> {
    let start = first_pixel(left).max(columns.0);
    let end = first_pixel(right).min(columns.1);
    if start >= end {
        return Ok(());
    }
    let (Ok(x), Ok(y), Ok(width)) = (
        i32::try_from(start),
        i32::try_from(row),
        u32::try_from(end - start),
    ) else {
        return Ok(());
    };
    target.fill_solid(
        &Rectangle::new(Point::new(x, y), Size::new(width, 1)),
        color,
    )
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec;
    use std::vec::Vec;

    /// The crossing's division is `/`: values of every size and sign, divisors of every
    /// positive size (32 bits and beyond), and the edges.
    #[test]
    fn crossings_divide_as_the_operator_does() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let n = (any::<i64>(), 0u32..64).prop_map(|(v, s)| v >> s);
        let d = (1i64.., 0u32..63).prop_map(|(v, s)| (v >> s).max(1));
        runner
            .run(&(n, d), |(n, d)| {
                prop_assert_eq!(divided(n, d), n / d);
                Ok(())
            })
            .unwrap();
        for n in [i64::MIN + 1, i64::MAX, -1, 0, 1] {
            for d in [1, 2, 3, i64::from(u32::MAX), 1 << 32, i64::MAX] {
                assert_eq!(divided(n, d), n / d, "{n} / {d}");
            }
        }
        assert_eq!(divided(i64::MIN, 1), i64::MIN);
    }

    /// A whole-pixel point in Q16.
    const fn subpixel(x: i64, y: i64) -> SubPixel {
        (x << SUBPIXEL_BITS, y << SUBPIXEL_BITS)
    }
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;

    /// The winding number of the closed outline `vertices` about `p` (f64).
    fn winding(vertices: &[(f64, f64)], p: (f64, f64)) -> i32 {
        let mut w = 0;
        for (i, &a) in vertices.iter().enumerate() {
            let b = vertices[(i + 1) % vertices.len()];
            let side = (b.0 - a.0) * (p.1 - a.1) - (p.0 - a.0) * (b.1 - a.1);
            if a.1 <= p.1 && b.1 > p.1 && side > 0.0 {
                w += 1;
            } else if a.1 > p.1 && b.1 <= p.1 && side < 0.0 {
                w -= 1;
            }
        }
        w
    }

    /// Concave and self-crossing outlines (a star, a figure eight, a comb) fill exactly
    /// the pixels whose centres an f64 winding number puts inside (nonzero), each once.
    #[test]
    fn any_polygon_fills_by_the_nonzero_rule() {
        let star: Vec<(f64, f64)> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * f64::from(k * 2 % 5) / 5.0 + 0.1;
                (31.3 + 27.1 * a.cos(), 30.7 + 27.9 * a.sin())
            })
            .collect();
        let eight = vec![(3.3, 4.1), (55.7, 58.2), (58.9, 3.7), (2.6, 57.4)];
        let comb = vec![
            (2.2, 2.4),
            (60.1, 2.9),
            (60.3, 50.6),
            (45.4, 50.2),
            (45.9, 12.3),
            (30.2, 12.8),
            (30.7, 50.9),
            (15.3, 50.1),
            (15.6, 12.6),
            (2.9, 12.2),
        ];
        for outline in [star, eight, comb] {
            let mut display = MockDisplay::<BinaryColor>::new();
            let q16: Vec<SubPixel> = outline
                .iter()
                .map(|&(x, y)| ((x * 65536.0) as i64, (y * 65536.0) as i64))
                .collect();
            let clip = display.bounding_box();
            fill_polygon(&mut display, &q16, BinaryColor::On, &clip).unwrap();
            let exact: Vec<(f64, f64)> = q16
                .iter()
                .map(|&(x, y)| (x as f64 / 65536.0, y as f64 / 65536.0))
                .collect();
            for y in 0..64 {
                for x in 0..64 {
                    let inside = winding(&exact, (f64::from(x) + 0.5, f64::from(y) + 0.5)) != 0;
                    let drawn = display.get_pixel(Point::new(x, y)).is_some();
                    assert_eq!(drawn, inside, "{outline:?} at ({x}, {y})");
                }
            }
        }
    }

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
