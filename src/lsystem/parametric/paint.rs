//! Drawing a system's marks on a fitted target: lines one pixel wide or thick, polygons
//! filled by the nonzero rule, each at its depth (a depth buffer sorts them where one is
//! given) and, for surfaces in light, shaded by the polygon's normal.

use heapless::Vec;

use super::kept::{SeenMark, SeenMarks};
use super::surface::MAX_POLYGON_VERTICES;
use crate::error::DrawError;
use crate::math::divide::div_i64_by_u32;
use crate::math::Real;
use crate::render::depth::Layered;
use crate::render::palette::Palette;
use crate::render::polygon::{fill_polygon, SubPixel, MAX_FILL_VERTICES};
use crate::render::projection::Seen;
use crate::render::raster::draw_line;
use crate::render::shade::{brightness, Shade};
use crate::render::space::{middle, SpaceFit};
use crate::render::thick::{fill_thick_line, THICK_FROM};

const _: () = assert!(MAX_POLYGON_VERTICES <= MAX_FILL_VERTICES);

/// How a surface's colour takes the light.
pub(crate) trait Lighting<C> {
    /// Whether it looks at the light at all (flat colours skip the normal).
    const LIT: bool;
    /// `color` at brightness `light` (255 full).
    fn lit(color: C, light: u8) -> C;
}

/// Surfaces in their palette colours, unlit.
pub(crate) struct Flat;

impl<C> Lighting<C> for Flat {
    const LIT: bool = false;
    #[inline]
    fn lit(color: C, _light: u8) -> C {
        color
    }
}

/// Surfaces shaded by their normal ([`brightness`]).
pub(crate) struct Lit;

impl<C: Shade> Lighting<C> for Lit {
    const LIT: bool = true;
    fn lit(color: C, light: u8) -> C {
        color.shade(light)
    }
}

/// The normal of a polygon seen in view space (Newell's method: any polygon, its length
/// twice the area), from coordinates in 2⁻¹⁶ units.
///
/// In 64 bits where every coordinate is below 2²⁸ (a picture's usual size): each term is
/// then below 2⁵⁸ and a polygon's at most 32 of them sum below 2⁶³, the same integers as
/// in 128 bits, whose products are several times dearer on a 32-bit core.
fn normal(seen: &[Seen]) -> [i128; 3] {
    let coordinates = |s: &Seen| [s.x, s.y, s.depth].map(|v| v.to_bits() >> 16);
    let narrow = seen.len() <= MAX_POLYGON_VERTICES
        && seen
            .iter()
            .all(|s| coordinates(s).iter().all(|c| c.unsigned_abs() < 1 << 28));
    if narrow {
        return newell(seen, coordinates).map(i128::from);
    }
    newell(seen, |s| coordinates(s).map(i128::from))
}

/// Newell's sums over `seen`'s edges in the integers `coordinates` gives.
#[inline(always)]
fn newell<T>(seen: &[Seen], coordinates: impl Fn(&Seen) -> [T; 3]) -> [T; 3]
where
    T: Copy
        + Default
        + core::ops::Add<Output = T>
        + core::ops::Sub<Output = T>
        + core::ops::Mul<Output = T>
        + core::ops::AddAssign,
{
    let mut n = [T::default(); 3];
    for (i, a) in seen.iter().enumerate() {
        let b = seen.get(i + 1).or(seen.first()).unwrap_or(a);
        let ([ax, ay, az], [bx, by, bz]) = (coordinates(a), coordinates(b));
        n[0] += (ay - by) * (az + bz);
        n[1] += (az - bz) * (ax + bx);
        n[2] += (ax - bx) * (ay + by);
    }
    n
}

/// The mean depth of `seen`, rounded towards zero: in 64 bits and a division by the
/// count's 32 bits where the sum fits (always, for depths below 2⁵⁸), else in 128.
fn mean_depth(seen: &[Seen]) -> Real {
    let count = seen.len().max(1);
    let narrow = seen
        .iter()
        .try_fold(0i64, |sum, s| sum.checked_add(s.depth.to_bits()));
    if let (Some(sum), Ok(divisor)) = (narrow, u32::try_from(count)) {
        return Real::from_bits(div_i64_by_u32(sum, divisor));
    }
    let sum: i128 = seen.iter().map(|s| i128::from(s.depth.to_bits())).sum();
    let count = i128::try_from(count).unwrap_or(1);
    Real::from_bits(i64::try_from(sum / count).unwrap_or(0))
}

/// Draws every mark of `marks` (seen through `space`'s projection), fitted by `space`,
/// into `target` in `palette`'s colours (by colour index, or by depth with depth cue);
/// surfaces lit by `L`. Returns the lines and the polygons drawn.
pub(crate) fn paint<T, P, L>(
    space: &SpaceFit,
    target: &mut T,
    marks: &mut impl SeenMarks,
    palette: &P,
) -> Result<(u64, u64), DrawError<T::Error>>
where
    T: Layered<Color = P::Color>,
    P: Palette,
    L: Lighting<P::Color>,
{
    let clip = target.bounding_box();
    let scale = space.scale();
    let (mut lines, mut polygons) = (0u64, 0u64);
    let mut last_end = None;
    while let Some(mark) = marks.next_seen() {
        match mark? {
            SeenMark::Line {
                ends: &[start, end],
                width,
                color,
            } => {
                lines += 1;
                let pixels = width.checked_mul(scale).map_or(0, |w| w.to_bits() >> 16);
                let (from, to) = (space.pixel(start), space.pixel(end));
                let depth = middle(start.depth, end.depth);
                let (value, max) = space.color_value(depth, u16::from(color));
                let color = palette.color(value, max);
                if T::KEEPS_DEPTH {
                    target.at_depth(space.buffer_depth(depth));
                }
                if pixels < THICK_FROM {
                    draw_line(target, from, to, last_end == Some(from), color, &clip)
                        .map_err(DrawError::Target)?;
                    last_end = Some(to);
                } else {
                    let (a, b) = (space.subpixel(start), space.subpixel(end));
                    fill_thick_line(target, (a, b), pixels, color, &clip)
                        .map_err(DrawError::Target)?;
                    last_end = None;
                }
            }
            SeenMark::Polygon { vertices, color } => {
                polygons += 1;
                let mut points: Vec<SubPixel, MAX_POLYGON_VERTICES> = Vec::new();
                for &vertex in vertices {
                    // Cannot fail: a polygon has at most MAX_POLYGON_VERTICES vertices.
                    let _ = points.push(space.subpixel(vertex));
                }
                let depth = mean_depth(vertices);
                let (value, max) = space.color_value(depth, u16::from(color));
                let light = if L::LIT {
                    brightness(normal(vertices))
                } else {
                    255
                };
                let color = L::lit(palette.color(value, max), light);
                if T::KEEPS_DEPTH {
                    target.at_depth(space.buffer_depth(depth));
                }
                fill_polygon(target, &points, color, &clip).map_err(DrawError::Target)?;
                last_end = None;
            }
        }
    }
    Ok((lines, polygons))
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use proptest::prelude::*;
    use std::vec::Vec as StdVec;

    /// Newell's normal and the mean depth in 128 bits throughout, where nothing can
    /// overflow: what the 64-bit paths must give.
    fn by_definition(seen: &[Seen]) -> ([i128; 3], Real) {
        let n = newell(seen, |s: &Seen| {
            [s.x, s.y, s.depth].map(|v| i128::from(v.to_bits() >> 16))
        });
        let sum: i128 = seen.iter().map(|s| i128::from(s.depth.to_bits())).sum();
        let count = i128::try_from(seen.len().max(1)).unwrap();
        (n, Real::from_bits(i64::try_from(sum / count).unwrap()))
    }

    /// Polygons of 1 to 32 vertices with coordinates of every size, the 64-bit paths'
    /// bounds on either side included.
    fn polygons() -> impl Strategy<Value = StdVec<Seen>> {
        let coordinate = (any::<i64>(), 0u32..64).prop_map(|(v, s)| Real::from_bits(v >> s));
        let vertex = (coordinate.clone(), coordinate.clone(), coordinate)
            .prop_map(|(x, y, depth)| Seen { x, y, depth });
        proptest::collection::vec(vertex, 1..=MAX_POLYGON_VERTICES)
    }

    #[test]
    fn normals_and_depths_are_their_definitions() {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(&polygons(), |seen| {
                let (n, depth) = by_definition(&seen);
                prop_assert_eq!(normal(&seen), n);
                prop_assert_eq!(mean_depth(&seen), depth);
                Ok(())
            })
            .unwrap();
        let extreme = |v: i64| Seen {
            x: Real::from_bits(v),
            y: Real::from_bits(v),
            depth: Real::from_bits(v),
        };
        for v in [i64::MIN, i64::MAX, (1 << 44) - 1, 1 << 44, -(1 << 44)] {
            let seen = [extreme(v), extreme(v / 3), extreme(v / -2)];
            assert_eq!(
                (normal(&seen), mean_depth(&seen)),
                by_definition(&seen),
                "{v}"
            );
            assert_eq!(mean_depth(&seen[..1]), by_definition(&seen[..1]).1, "{v}");
        }
    }
}
