//! Drawing a system's marks on a fitted target: lines one pixel wide or thick, polygons
//! filled by the nonzero rule, each at its depth (a depth buffer sorts them where one is
//! given) and, for surfaces in light, shaded by the polygon's normal.

use heapless::Vec;

use super::kept::{SeenMark, SeenMarks};
use super::surface::MAX_POLYGON_VERTICES;
use crate::error::DrawError;
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
fn normal(seen: &[Seen]) -> [i128; 3] {
    let coordinates = |s: &Seen| [s.x, s.y, s.depth].map(|v| i128::from(v.to_bits() >> 16));
    let mut n = [0i128; 3];
    for (i, a) in seen.iter().enumerate() {
        let b = seen.get(i + 1).or(seen.first()).unwrap_or(a);
        let ([ax, ay, az], [bx, by, bz]) = (coordinates(a), coordinates(b));
        n[0] += (ay - by) * (az + bz);
        n[1] += (az - bz) * (ax + bx);
        n[2] += (ax - bx) * (ay + by);
    }
    n
}

/// The mean depth of `seen`.
fn mean_depth(seen: &[Seen]) -> Real {
    let sum: i128 = seen.iter().map(|s| i128::from(s.depth.to_bits())).sum();
    let count = i128::try_from(seen.len().max(1)).unwrap_or(1);
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
