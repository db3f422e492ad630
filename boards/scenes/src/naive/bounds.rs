//! The box a sketch measures its turtle's points in, and its fit to the target.

use embedded_graphics::prelude::*;

/// The box of a turtle's points, as a sketch measures it before drawing.
pub(super) struct Bounds {
    low: (f32, f32),
    high: (f32, f32),
}

impl Bounds {
    pub(super) fn new() -> Self {
        Self {
            low: (f32::MAX, f32::MAX),
            high: (f32::MIN, f32::MIN),
        }
    }

    /// The box grown to hold `points`.
    pub(super) fn add(&mut self, points: [(f32, f32); 2]) {
        for (x, y) in points {
            self.low = (self.low.0.min(x), self.low.1.min(y));
            self.high = (self.high.0.max(x), self.high.1.max(y));
        }
    }

    /// The box fitted to a target of `size` less a 2-pixel margin and centred (y up): the
    /// scale in pixels a unit, and the pixel of a point.
    pub(super) fn fitted(&self, size: Size) -> (f32, impl Fn((f32, f32)) -> Point) {
        let (low, high) = (self.low, self.high);
        let (w, h) = (size.width as f32 - 4.0, size.height as f32 - 4.0);
        let scale = (w / (high.0 - low.0).max(1e-6)).min(h / (high.1 - low.1).max(1e-6));
        // Centred: the spare width (or height) split either side.
        let left = 2.0 + (w - (high.0 - low.0) * scale) / 2.0;
        let bottom = 2.0 + h - (h - (high.1 - low.1) * scale) / 2.0;
        let pixel = move |(x, y): (f32, f32)| {
            Point::new(
                (left + (x - low.0) * scale + 0.5) as i32,
                (bottom - (y - low.1) * scale + 0.5) as i32,
            )
        };
        (scale, pixel)
    }
}

/// The box of a fixed-point turtle's points in Q16.16, as a careful sketch measures it.
pub(super) struct FixedBounds {
    low: (i32, i32),
    high: (i32, i32),
}

impl FixedBounds {
    pub(super) fn new() -> Self {
        Self {
            low: (i32::MAX, i32::MAX),
            high: (i32::MIN, i32::MIN),
        }
    }

    /// The box grown to hold `points`.
    pub(super) fn add(&mut self, points: [(i32, i32); 2]) {
        for (x, y) in points {
            self.low = (self.low.0.min(x), self.low.1.min(y));
            self.high = (self.high.0.max(x), self.high.1.max(y));
        }
    }

    /// The box fitted as [`Bounds::fitted`] fits it, in Q16.16: the scale in pixels a
    /// unit (Q16), and the pixel of a point; one 64-bit division an axis, once.
    pub(super) fn fitted(&self, size: Size) -> (i64, impl Fn((i32, i32)) -> Point) {
        let (low, high) = (self.low, self.high);
        let (w, h) = (
            (i64::from(size.width) - 4) << 16,
            (i64::from(size.height) - 4) << 16,
        );
        let span = (
            (i64::from(high.0) - i64::from(low.0)).max(1),
            (i64::from(high.1) - i64::from(low.1)).max(1),
        );
        let scale = ((w << 16) / span.0).min((h << 16) / span.1);
        let left = (2 << 16) + (w - ((span.0 * scale) >> 16)) / 2;
        let bottom = (2 << 16) + h - (h - ((span.1 * scale) >> 16)) / 2;
        let pixel = move |(x, y): (i32, i32)| {
            let x = left + (((i64::from(x) - i64::from(low.0)) * scale) >> 16);
            let y = bottom - (((i64::from(y) - i64::from(low.1)) * scale) >> 16);
            Point::new(((x + 0x8000) >> 16) as i32, ((y + 0x8000) >> 16) as i32)
        };
        (scale, pixel)
    }
}
