//! Fitting a picture in space to a target: its points projected (front, isometric,
//! perspective), their extent measured by a walk, scaled and centred like a 2D picture;
//! with depth cue, the depth range for colours. The 3D turtle and the 3D IFS share it.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::fit::{fit, Orientation};
use super::polygon::SubPixel;
use super::projection::{Eye, Projection, Seen};
use crate::error::{Error, WalkError};
use crate::math::Real;

/// One drawn line in space (x right, y up, z towards the viewer).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Segment3 {
    /// Where the line starts.
    pub start: [Real; 3],
    /// Where it ends.
    pub end: [Real; 3],
    /// The colour index, 0 unless set.
    pub color: u8,
}

/// Depth-cue levels: the palette's first `DEPTH_LEVELS` colours, farthest first.
pub const DEPTH_LEVELS: u16 = 16;

/// How a 3D picture lands on the target: its projection, the perspective eye, pixels per
/// picture unit and the screen position of the origin, and its depth range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct SpaceFit {
    projection: Projection,
    eye: Option<Eye>,
    scale: Real,
    origin: (Real, Real),
    depth: (Real, Real),
    depth_cue: bool,
    /// The pixel box of the drawn points.
    pub(crate) bounding_box: Rectangle,
}

/// The extent of a projected picture.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Extent {
    low: Seen,
    high: Seen,
}

impl Extent {
    /// Widens `extent` (`None`: nothing yet) to hold `seen`.
    #[inline]
    pub(crate) fn include(extent: &mut Option<Self>, seen: Seen) {
        let e = extent.get_or_insert(Self {
            low: seen,
            high: seen,
        });
        e.low.x = e.low.x.min(seen.x);
        e.low.y = e.low.y.min(seen.y);
        e.low.depth = e.low.depth.min(seen.depth);
        e.high.x = e.high.x.max(seen.x);
        e.high.y = e.high.y.max(seen.y);
        e.high.depth = e.high.depth.max(seen.depth);
    }
}

/// The projected extent of `points`, or `None` for a picture of nothing.
fn extent<const N: usize>(
    points: &mut impl Iterator<Item = Result<[[Real; 3]; N], Error>>,
    projection: Projection,
    eye: Option<Eye>,
) -> Result<Option<Extent>, Error> {
    let mut extent: Option<Extent> = None;
    for group in points {
        for p in group? {
            Extent::include(&mut extent, projection.project(p, eye));
        }
    }
    Ok(extent)
}

/// The projected extent of a fresh walk, out of line: one walk on the stack at a time.
#[inline(never)]
fn measured<I, const N: usize>(
    points: &impl Fn() -> I,
    projection: Projection,
    eye: Option<Eye>,
) -> Result<Option<Extent>, Error>
where
    I: Iterator<Item = Result<[[Real; 3]; N], Error>>,
{
    extent(&mut points(), projection, eye)
}

pub(crate) fn middle(a: Real, b: Real) -> Real {
    Real::from_bits(a.to_bits() / 2 + b.to_bits() / 2)
}

impl SpaceFit {
    /// Fits the picture whose points `points()` gives (in groups of `N`: a segment's two
    /// ends, a point) into `area` less `margin`: one walk to measure (two for a
    /// perspective, whose eye is placed from the first).
    pub(crate) fn new<I, const N: usize>(
        points: impl Fn() -> I,
        projection: Projection,
        depth_cue: bool,
        area: &Rectangle,
        margin: u32,
    ) -> Result<Self, Error>
    where
        I: Iterator<Item = Result<[[Real; 3]; N], Error>>,
    {
        // Each walk read through `&mut` (out of line, one at a time): a walk is a large
        // value, and moving it into a call would copy it (more stack on an MCU).
        let mut seen = measured(&points, projection, None)?;
        let mut eye = None;
        if let (Projection::Perspective { distance }, Some(e)) = (projection, seen) {
            // Half the box's three extents together bound its radius from above.
            let sum = e
                .high
                .x
                .saturating_sub(e.low.x)
                .saturating_add(e.high.y.saturating_sub(e.low.y))
                .saturating_add(e.high.depth.saturating_sub(e.low.depth));
            let radius = Real::from_bits(sum.to_bits() / 2).max(Real::ONE);
            let distance = distance.max(Real::from_ratio(11, 10).unwrap_or(Real::ONE));
            eye = Some(Eye {
                middle: Seen {
                    x: middle(e.low.x, e.high.x),
                    y: middle(e.low.y, e.high.y),
                    depth: middle(e.low.depth, e.high.depth),
                },
                distance: radius
                    .checked_mul(distance)
                    .ok_or(Error::Walk(WalkError::Overflow))?,
            });
            seen = measured(&points, projection, eye)?;
        }
        Self::from_extent(seen, projection, eye, depth_cue, area, margin)
    }

    /// Fits a picture seen from the front whose lines lie in the box from `low` to `high`
    /// (x, y; z is its depth range): no walk.
    pub(crate) fn front_box(
        low: [Real; 3],
        high: [Real; 3],
        area: &Rectangle,
        margin: u32,
    ) -> Result<Self, Error> {
        let seen = |[x, y, depth]: [Real; 3]| Seen { x, y, depth };
        let extent = Extent {
            low: seen(low),
            high: seen(high),
        };
        Self::from_extent(Some(extent), Projection::Front, None, false, area, margin)
    }

    /// The fit of a measured extent (`None`: a picture of nothing). Not generic: one copy
    /// whatever the walks that measured it.
    pub(crate) fn from_extent(
        seen: Option<Extent>,
        projection: Projection,
        eye: Option<Eye>,
        depth_cue: bool,
        area: &Rectangle,
        margin: u32,
    ) -> Result<Self, Error> {
        let zero = Seen {
            x: Real::ZERO,
            y: Real::ZERO,
            depth: Real::ZERO,
        };
        let e = seen.unwrap_or(Extent {
            low: zero,
            high: zero,
        });
        let fitted = fit(
            (e.low.x, e.low.y),
            (e.high.x, e.high.y),
            Orientation::Right,
            area,
            margin,
        )?;
        let mut space = Self {
            projection,
            eye,
            scale: fitted.scale,
            origin: fitted.origin,
            depth: (e.low.depth, e.high.depth),
            depth_cue,
            bounding_box: Rectangle::zero(),
        };
        let (a, b) = (space.pixel(e.low), space.pixel(e.high));
        space.bounding_box = if seen.is_some() {
            Rectangle::with_corners(a, b)
        } else {
            Rectangle::new(a, Size::zero())
        };
        Ok(space)
    }

    /// The pixel a seen point lands on.
    pub(crate) fn pixel(&self, seen: Seen) -> Point {
        let scaled = |v: Real| v.checked_mul(self.scale).unwrap_or(Real::ZERO);
        Point::new(
            self.origin.0.saturating_add(scaled(seen.x)).round_to_i32(),
            self.origin.1.saturating_sub(scaled(seen.y)).round_to_i32(),
        )
    }

    /// A front view's scale (pixels a unit) and the screen position of the origin, so a
    /// family can place its points in its own arithmetic: pixel = round(origin + (x, −y) ·
    /// scale). `None` for any other projection.
    pub(crate) fn front_linear(&self) -> Option<(Real, (Real, Real))> {
        (self.projection == Projection::Front).then_some((self.scale, self.origin))
    }

    /// The depth-cue level of a depth: 0 farthest to `DEPTH_LEVELS - 1` nearest.
    pub(crate) fn level(&self, depth: Real) -> u16 {
        let (low, high) = self.depth;
        let span = high.to_bits().saturating_sub(low.to_bits());
        if span <= 0 {
            return DEPTH_LEVELS - 1;
        }
        let into = i128::from(depth.to_bits().saturating_sub(low.to_bits()));
        let level = into * i128::from(DEPTH_LEVELS - 1) / i128::from(span);
        u16::try_from(level.clamp(0, i128::from(DEPTH_LEVELS - 1))).unwrap_or(0)
    }

    /// Where a seen point lands in Q16 pixels on the fill rule's grid (pixel (x, y) covers
    /// [x, x + 1) × [y, y + 1), so a point [`place`](Self::place) puts on a pixel lands on
    /// its centre).
    pub(crate) fn subpixel(&self, seen: Seen) -> SubPixel {
        let scaled = |v: Real| v.checked_mul(self.scale).unwrap_or(Real::ZERO);
        let q16 = |v: Real| (v.to_bits() + (1 << 31)) >> 16;
        let x = self.origin.0.saturating_add(scaled(seen.x));
        let y = self.origin.1.saturating_sub(scaled(seen.y));
        (q16(x), q16(y))
    }

    /// The projection and, for a perspective, the eye it is seen with.
    pub(crate) const fn view(&self) -> (Projection, Option<Eye>) {
        (self.projection, self.eye)
    }

    /// Pixels a picture unit (across the screen; a perspective's at its middle depth).
    pub(crate) const fn scale(&self) -> Real {
        self.scale
    }

    /// A depth as a depth buffer's `u16`: 0 the farthest the picture reaches, 65535 the
    /// nearest.
    pub(crate) fn buffer_depth(&self, depth: Real) -> u16 {
        let (low, high) = self.depth;
        let span = high.to_bits().saturating_sub(low.to_bits());
        if span <= 0 {
            return 0;
        }
        let into = depth.to_bits().saturating_sub(low.to_bits());
        if into <= 0 {
            return 0;
        }
        if into >= span {
            return 65_535;
        }
        // In 64 bits where the product fits (a 128-bit division is a long call on a
        // 32-bit core); the same quotient either way.
        let quotient = match into.checked_mul(65_535) {
            Some(product) => product / span,
            None => (i128::from(into) * 65_535 / i128::from(span)) as i64,
        };
        u16::try_from(quotient).unwrap_or(65_535)
    }

    /// Where a point of space lands: its pixel and its projected depth.
    pub(crate) fn place(&self, p: [Real; 3]) -> (Point, Real) {
        let seen = self.projection.project(p, self.eye);
        (self.pixel(seen), seen.depth)
    }

    /// The colour index of a point at `depth` (with depth cue, its level; else `index`)
    /// and the palette's `max` for it.
    pub(crate) fn color_value(&self, depth: Real, index: u16) -> (u16, u16) {
        if self.depth_cue {
            (self.level(depth), DEPTH_LEVELS - 1)
        } else {
            (index, u16::MAX)
        }
    }
}
