//! A Bézier curve drawn in a colour: its flattened pieces through the sub-pixel run
//! rasteriser, one pixel wide, 8-connected.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::curve::Bezier;
use crate::render::subpixel::{Polyline, SUBPIXEL_BITS};

/// What drawing a curve did: pieces of the flattened curve, and pixels drawn (inside the
/// target).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct BezierStats {
    /// Straight pieces the curve was flattened into.
    pub segments: u64,
    /// Pixels drawn.
    pub pixels: u64,
}

/// A curve with a one-pixel stroke: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StrokedBezier<C> {
    curve: Bezier,
    color: C,
}

impl Bezier {
    /// The curve stroked one pixel wide in `color`.
    pub const fn into_stroked<C>(self, color: C) -> StrokedBezier<C> {
        StrokedBezier { curve: self, color }
    }

    /// The box of the control points: the curve lies inside it.
    pub fn hull_box(&self) -> Rectangle {
        let points = self.control_points();
        let first = points.first().copied().unwrap_or_default();
        let (low, high) = points.iter().fold((first, first), |(low, high), p| {
            (
                Point::new(low.x.min(p.x), low.y.min(p.y)),
                Point::new(high.x.max(p.x), high.y.max(p.y)),
            )
        });
        // Sides in 64 bits: control points at the ends of i32 span more than 2³¹.
        let side =
            |a: i32, b: i32| u32::try_from(i64::from(b) - i64::from(a) + 1).unwrap_or(u32::MAX);
        Rectangle::new(low, Size::new(side(low.x, high.x), side(low.y, high.y)))
    }
}

impl<C: PixelColor> Dimensions for StrokedBezier<C> {
    fn bounding_box(&self) -> Rectangle {
        self.curve.hull_box()
    }
}

impl<C: PixelColor> Drawable for StrokedBezier<C> {
    type Color = C;
    type Output = BezierStats;

    /// Draws the curve; nothing where its control points' box misses the target.
    fn draw<D>(&self, target: &mut D) -> Result<BezierStats, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let clip = target.bounding_box();
        let hull = self.curve.hull_box();
        let apart = |low: i32, side: u32, clip_low: i32, clip_side: u32| {
            let (high, clip_high) = (
                i64::from(low) + i64::from(side),
                i64::from(clip_low) + i64::from(clip_side),
            );
            high <= i64::from(clip_low) || clip_high <= i64::from(low)
        };
        if apart(
            hull.top_left.x,
            hull.size.width,
            clip.top_left.x,
            clip.size.width,
        ) || apart(
            hull.top_left.y,
            hull.size.height,
            clip.top_left.y,
            clip.size.height,
        ) {
            return Ok(BezierStats::default());
        }
        let mut line = Polyline::new(self.color, clip);
        let mut vertices: u64 = 0;
        for vertex in self.curve.flattened() {
            line.to(target, vertex)?;
            vertices += 1;
        }
        line.finish(target)?;
        Ok(BezierStats {
            segments: vertices.saturating_sub(1),
            pixels: line.pixels,
        })
    }
}

/// A vertex of a flattened curve in pixels, as `f64` (exact: 16 fraction bits), for tests
/// and host output.
pub fn vertex_to_f64((x, y): (i64, i64)) -> (f64, f64) {
    let scale = f64::from(1u32 << SUBPIXEL_BITS);
    (x as f64 / scale, y as f64 / scale)
}
