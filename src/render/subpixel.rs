//! Polylines with sub-pixel vertices to pixels, in runs: each segment takes, at every
//! pixel column (or row) it crosses, the pixel nearest the exact segment there, so a
//! drawn pixel is within half a pixel of the polyline; where segments meet, a pixel
//! already drawn by either of the last two is not drawn again, and the pixels stay
//! 8-connected.
//!
//! Coordinates are fixed point with [`SUBPIXEL_BITS`] fraction bits, pixel centres at
//! whole numbers.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::raster::PendingRun;

/// Fraction bits of a sub-pixel coordinate.
pub const SUBPIXEL_BITS: u32 = 16;

/// `value / 2^SUBPIXEL_BITS` rounded to the nearest whole pixel (halves up).
fn nearest(value: i64) -> i64 {
    (value + (1 << (SUBPIXEL_BITS - 1))) >> SUBPIXEL_BITS
}

/// Draws polylines through the run rasteriser: [`to`](Self::to) each vertex in turn,
/// [`finish`](Self::finish) at the end.
#[derive(Debug)]
pub(crate) struct Polyline<C> {
    run: PendingRun<C>,
    color: C,
    clip: Rectangle,
    last_vertex: Option<(i64, i64)>,
    /// The last two pixels drawn, the latest first.
    last_pixels: [Option<Point>; 2],
    /// Pixels drawn.
    pub(crate) pixels: u64,
}

impl<C: PixelColor> Polyline<C> {
    /// A polyline in `color`, clipped to `clip`.
    pub(crate) fn new(color: C, clip: Rectangle) -> Self {
        Self {
            run: PendingRun::default(),
            color,
            clip,
            last_vertex: None,
            last_pixels: [None; 2],
            pixels: 0,
        }
    }

    /// Goes on to the vertex (`x`, `y`) (sub-pixel units), drawing the segment from the
    /// last one (the first vertex draws its own pixel).
    pub(crate) fn to<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        (x, y): (i64, i64),
    ) -> Result<(), D::Error> {
        match self.last_vertex.replace((x, y)) {
            Some(from) => self.segment(target, from, (x, y)),
            None => self.plot(target, (nearest(x), nearest(y))),
        }
    }

    /// Draws the segment `from`–`to` but its first pixel where the last segment drew it.
    fn segment<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        (x0, y0): (i64, i64),
        (x, y): (i64, i64),
    ) -> Result<(), D::Error> {
        let (dx, dy) = (x - x0, y - y0);
        let x_major = dx.abs() >= dy.abs();
        // Along the major axis from the pixel of the start to the pixel of the end; at
        // each, the minor coordinate of the exact segment, rounded.
        let (major0, major1, minor0, d_major, d_minor, m0) = if x_major {
            (nearest(x0), nearest(x), y0, dx, dy, x0)
        } else {
            (nearest(y0), nearest(y), x0, dy, dx, y0)
        };
        let step: i64 = if major1 >= major0 { 1 } else { -1 };
        // Only the part of the major range inside the clip is walked: a segment far
        // off-screen costs its set-up alone.
        let (clip_start, clip_size) = if x_major {
            (self.clip.top_left.x, self.clip.size.width)
        } else {
            (self.clip.top_left.y, self.clip.size.height)
        };
        let (clip_low, clip_high) = (
            i64::from(clip_start),
            i64::from(clip_start) + i64::from(clip_size) - 1,
        );
        let (low, high) = (major0.min(major1), major0.max(major1));
        if high < clip_low || low > clip_high {
            // Nothing of it shows; the next segment starts afresh.
            self.last_pixels = [None; 2];
            return Ok(());
        }
        let (major0, major1) = if step > 0 {
            (major0.max(clip_low), major1.min(clip_high))
        } else {
            (major0.min(clip_high), major1.max(clip_low))
        };
        let sign = if d_major < 0 { -1 } else { 1 };
        let (span, slope) = (d_major.abs(), d_minor * sign);
        // A segment longer than 2²⁸ pixels: its visible part, cut at the clip (exactly, to
        // the sub-pixel), is drawn instead, so the carried remainder fits 64 bits.
        if span >= 1 << 44 {
            let at = |major: i64| {
                let along = (i128::from(major) << SUBPIXEL_BITS) - i128::from(m0);
                let minor =
                    i128::from(minor0) + (along * i128::from(slope)).div_euclid(i128::from(span));
                let minor = i64::try_from(minor).unwrap_or(0);
                if x_major {
                    (major << SUBPIXEL_BITS, minor)
                } else {
                    (minor, major << SUBPIXEL_BITS)
                }
            };
            // At most 2²⁷ pixels of it at a time: the cut piece is short enough.
            let end = if step > 0 {
                major1.min(major0 + (1 << 27))
            } else {
                major1.max(major0 - (1 << 27))
            };
            self.segment(target, at(major0), at(end))?;
            if end != major1 {
                self.segment(target, at(end), at(major1))?;
            }
            return Ok(());
        }
        // The minor pixel at major pixel M is base + ⌊(2N + D) / 2D⌋ with
        // N = rel·|d_major| + (M·2^bits − m0)·d_minor·sign(d_major), rel the start's minor
        // coordinate from its own pixel `base`, and D = |d_major|·2^bits: one division for
        // the first, then the remainder carried (|d_minor| ≤ |d_major|: at most one carry a
        // step). In 64 bits while the numbers allow (a segment under 2^24 pixels starting
        // within a pixel of its first drawn one: every flattened curve's).
        let base = nearest(minor0);
        let rel = minor0 - (base << SUBPIXEL_BITS);
        let along = (major0 << SUBPIXEL_BITS) - m0;
        let twice_d = span << (SUBPIXEL_BITS + 1);
        let (offset, mut remainder) = if span == 0 {
            (0, 0)
        } else if span < 1 << 40 && along.abs() <= 1 << 17 {
            let t = 2 * (rel * span + along * slope) + (span << SUBPIXEL_BITS);
            (t.div_euclid(twice_d), t.rem_euclid(twice_d))
        } else {
            let t = 2
                * (i128::from(rel) * i128::from(span) + i128::from(along) * i128::from(slope))
                + (i128::from(span) << SUBPIXEL_BITS);
            let twice = i128::from(twice_d);
            (
                i64::try_from(t.div_euclid(twice)).unwrap_or(0),
                i64::try_from(t.rem_euclid(twice)).unwrap_or(0),
            )
        };
        let mut quotient = base + offset;
        let delta = 2 * (slope << SUBPIXEL_BITS) * step;
        let mut major = major0;
        loop {
            let pixel = if x_major {
                (major, quotient)
            } else {
                (quotient, major)
            };
            self.plot(target, pixel)?;
            if major == major1 {
                break;
            }
            major += step;
            if span > 0 {
                remainder += delta;
                if remainder >= twice_d {
                    remainder -= twice_d;
                    quotient += 1;
                } else if remainder < 0 {
                    remainder += twice_d;
                    quotient -= 1;
                }
            }
        }
        Ok(())
    }

    /// Draws the pixel, unless it is one of the last two drawn (where a bend turns from
    /// one axis to the other, the next segment's first pixels can step back onto its
    /// neighbour's last); clipped.
    fn plot<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        (x, y): (i64, i64),
    ) -> Result<(), D::Error> {
        let (Ok(x), Ok(y)) = (i32::try_from(x), i32::try_from(y)) else {
            return Ok(());
        };
        let pixel = Point::new(x, y);
        if self.last_pixels.contains(&Some(pixel)) {
            return Ok(());
        }
        self.last_pixels = [Some(pixel), self.last_pixels[0]];
        if self.clip.contains(pixel) {
            self.pixels += 1;
            self.run.add(target, pixel, self.color)?;
        }
        Ok(())
    }

    /// Sends what is pending.
    pub(crate) fn finish<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
    ) -> Result<(), D::Error> {
        self.run.send(target)
    }
}
