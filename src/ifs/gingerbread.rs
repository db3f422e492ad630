//! The gingerbread man (the lecture's map): q.x = M(1 + 2L) − p.y + |p.x − L·M|,
//! q.y = p.x, on integers, so the orbit is exact on every target, and eventually
//! periodic: [`Gingerbread::cycle`] finds its tail and period with Brent's algorithm in
//! constant memory.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{only_target_errors, DrawError, Error, FitError, WalkError};

/// A point of the map (integer coordinates of the lecture's 640×480 area).
pub type MapPoint = (i64, i64);

/// The lecture's area: the orbit of the usual parameters lies in it.
pub const AREA: (i64, i64) = (640, 480);

/// The map and its start.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gingerbread {
    /// M (the lecture's 40).
    pub m: i64,
    /// L (the lecture's 3).
    pub l: i64,
    /// The first point (the lecture's (115, 121)).
    pub start: MapPoint,
    /// Points plotted.
    pub iterations: u64,
}

impl Default for Gingerbread {
    /// The lecture's parameters: M = 40, L = 3, start (115, 121), 10,000 points.
    fn default() -> Self {
        Self {
            m: 40,
            l: 3,
            start: (115, 121),
            iterations: 10_000,
        }
    }
}

/// Where an eventually periodic orbit repeats: `tail` points before the cycle, which is
/// `period` points long.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cycle {
    /// Points before the first that repeats.
    pub tail: u64,
    /// Length of the cycle.
    pub period: u64,
}

impl Gingerbread {
    /// The point after `p`, or [`WalkError::Overflow`] if it leaves the 64-bit range.
    pub fn step(&self, (x, y): MapPoint) -> Result<MapPoint, Error> {
        let overflow = Error::Walk(WalkError::Overflow);
        let reach = self.l.checked_mul(self.m).ok_or(overflow)?;
        let kink = x
            .checked_sub(reach)
            .ok_or(overflow)?
            .checked_abs()
            .ok_or(overflow)?;
        let base = self
            .l
            .checked_mul(2)
            .and_then(|l2| l2.checked_add(1))
            .and_then(|f| f.checked_mul(self.m))
            .ok_or(overflow)?;
        let qx = base
            .checked_sub(y)
            .and_then(|v| v.checked_add(kink))
            .ok_or(overflow)?;
        Ok((qx, x))
    }

    /// The orbit's first `iterations` points, from the start.
    pub fn points(&self) -> GingerbreadPoints {
        GingerbreadPoints {
            map: *self,
            next: Some(Ok(self.start)),
            left: self.iterations,
        }
    }

    /// The orbit's tail and period (Brent), searching at most `limit` steps; `None` if no
    /// repeat shows within them. Two points of memory.
    pub fn cycle(&self, limit: u64) -> Result<Option<Cycle>, Error> {
        // Brent: the hare runs ahead in powers of two until it meets the tortoise.
        let (mut power, mut period) = (1u64, 1u64);
        let mut tortoise = self.start;
        let mut hare = self.step(self.start)?;
        let mut steps = 1u64;
        while tortoise != hare {
            if steps >= limit {
                return Ok(None);
            }
            if power == period {
                tortoise = hare;
                power *= 2;
                period = 0;
            }
            hare = self.step(hare)?;
            period += 1;
            steps += 1;
        }
        // The tail: a pointer `period` ahead and one at the start meet where the cycle
        // begins.
        let (mut slow, mut fast) = (self.start, self.start);
        for _ in 0..period {
            fast = self.step(fast)?;
        }
        let mut tail = 0;
        while slow != fast {
            slow = self.step(slow)?;
            fast = self.step(fast)?;
            tail += 1;
        }
        Ok(Some(Cycle { tail, period }))
    }

    /// Fits the lecture's area (640×480, y down as in the lecture) into `area` and colours
    /// the points `color`.
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        color: C,
    ) -> Result<GingerbreadDrawing<C>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        Ok(GingerbreadDrawing {
            map: *self,
            area,
            color,
        })
    }
}

/// The points of an orbit; yields `Err` once (overflow) and ends.
#[derive(Debug, Clone)]
pub struct GingerbreadPoints {
    map: Gingerbread,
    next: Option<Result<MapPoint, Error>>,
    left: u64,
}

impl Iterator for GingerbreadPoints {
    type Item = Result<MapPoint, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let current = self.next.take()?;
        if let Ok(point) = current {
            self.next = Some(self.map.step(point));
        }
        Some(current)
    }
}

/// The gingerbread man fitted to an area: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct GingerbreadDrawing<C> {
    map: Gingerbread,
    area: Rectangle,
    color: C,
}

impl<C: PixelColor> GingerbreadDrawing<C> {
    /// The pixel of a map point: the 640×480 area scaled uniformly into the target area,
    /// centred (integer arithmetic).
    pub fn pixel(&self, (x, y): MapPoint) -> Point {
        let (w, h) = (
            i64::from(self.area.size.width),
            i64::from(self.area.size.height),
        );
        // The scale w/640 or h/480, the smaller, as a fraction num/den.
        let (num, den) = if w * AREA.1 <= h * AREA.0 {
            (w, AREA.0)
        } else {
            (h, AREA.1)
        };
        let offset_x = (w - AREA.0 * num / den) / 2;
        let offset_y = (h - AREA.1 * num / den) / 2;
        let to_i32 = |v: i64| i32::try_from(v).unwrap_or(if v < 0 { i32::MIN } else { i32::MAX });
        Point::new(
            self.area
                .top_left
                .x
                .saturating_add(to_i32(offset_x + x * num / den)),
            self.area
                .top_left
                .y
                .saturating_add(to_i32(offset_y + y * num / den)),
        )
    }

    /// Draws the points (one pixel each, clipped to the target), reporting overflow too;
    /// returns how many were plotted.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<u64, DrawError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        let clip = target.bounding_box();
        let mut plotted = 0;
        for point in self.map.points() {
            let pixel = self.pixel(point?);
            if clip.contains(pixel) {
                target
                    .fill_solid(&Rectangle::new(pixel, Size::new(1, 1)), self.color)
                    .map_err(DrawError::Target)?;
            }
            plotted += 1;
        }
        Ok(plotted)
    }
}

impl<C: PixelColor> Dimensions for GingerbreadDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> Drawable for GingerbreadDrawing<C> {
    type Color = C;
    type Output = u64;

    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        only_target_errors(self.try_draw(target))
    }
}
