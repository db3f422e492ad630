//! The Sierpiński gasket: a triangle split into four by its edges' midpoints, the middle
//! one removed, and the same in the three others, to the order asked.
//!
//! Drawn by rows with index arithmetic, no stack: at order N the triangle is 2ᴺ rows of
//! small triangles, and small triangle c of row r is kept exactly when the binomial
//! coefficient C(r, c) is odd (Lucas: `c & !r == 0`), which is the subdivision's rule
//! unrolled. A pixel row crosses one row of small triangles; each kept one covers an
//! interval of it, computed exactly in integers, and the row goes out as alternating
//! background and ink runs, one `fill_solid` each.
//!
//! The triangle has its apex up, its height 887/1024 (≈ √3/2, 0.02 % off) of its base, and
//! is as large as fits the target, centred.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::order::{check_order, power};
use crate::error::{Error, FitError};
use crate::math::divide::{div_u64_narrow, Divisor};

/// The triangle's height over its base, as a ratio (≈ √3/2).
const HEIGHT_PER_BASE: (u64, u64) = (887, 1024);

/// The Sierpiński gasket at an order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gasket {
    /// Levels of subdivision (0: a filled triangle).
    pub order: u32,
}

/// What drawing a gasket did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GasketStats {
    /// Kept triangles of the last level: 3ᴺ.
    pub triangles: u64,
    /// Ink runs drawn (`fill_solid` calls in the ink colour).
    pub runs: u64,
}

impl Gasket {
    /// The gasket at `order`.
    pub const fn new(order: u32) -> Self {
        Self { order }
    }

    /// Kept triangles at this order: 3ᴺ.
    pub const fn triangles(&self) -> u64 {
        power(3, self.order)
    }

    /// The gasket as large as fits `area`, centred, in `ink` on `background`. Fails when a
    /// triangle of the last level would be under a pixel tall.
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        ink: C,
        background: C,
    ) -> Result<GasketDrawing<C>, Error> {
        let (w, h) = (u64::from(area.size.width), u64::from(area.size.height));
        let height = h.min(w * HEIGHT_PER_BASE.0 / HEIGHT_PER_BASE.1);
        let base = (height * HEIGHT_PER_BASE.1 / HEIGHT_PER_BASE.0).min(w);
        if height == 0 || base == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        check_order(self.order, 2, height)?;
        let offset = Point::new(((w - base) / 2) as i32, ((h - height) / 2) as i32);
        Ok(GasketDrawing {
            order: self.order,
            frame: Rectangle::new(
                area.top_left + offset,
                Size::new(base as u32, height as u32),
            ),
            ink,
            background,
        })
    }
}

/// A gasket fitted to a box: an embedded-graphics [`Drawable`] that paints every pixel of
/// the box once, row by row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GasketDrawing<C> {
    order: u32,
    frame: Rectangle,
    ink: C,
    background: C,
}

impl<C: PixelColor> GasketDrawing<C> {
    /// The divisor that finds a column ([`row_runs`](Self::row_runs)'s 2q, the same at every
    /// row), where it fits 32 bits: found once a drawing, so that on ARMv6-M each column is
    /// a multiply rather than a library division.
    fn column_divisor(&self) -> Option<Divisor> {
        let q = 4 * u64::from(self.frame.size.height) * power(2, self.order);
        u32::try_from(2 * q).ok().and_then(Divisor::new)
    }

    /// The ink intervals of pixel row `y` (0 at the apex), as pixel columns from the box's
    /// left, in increasing order, merged where they touch; `emit` gets each, and its first
    /// error ends the row. `columns` is [`column_divisor`](Self::column_divisor)'s.
    fn row_runs<E>(
        &self,
        y: u64,
        columns: Option<Divisor>,
        mut emit: impl FnMut(u64, u64) -> Result<(), E>,
    ) -> Result<(), E> {
        let (base, height) = (
            u64::from(self.frame.size.width),
            u64::from(self.frame.size.height),
        );
        let rows = power(2, self.order);
        // The row's centre is (2y + 1)/(2·height) of the way down, in row r of triangles at
        // `within`/(2·height) of the way down that row.
        let depth = (2 * y + 1) * rows;
        let r = div_u64_narrow(depth, 2 * height);
        let within = depth - r * 2 * height;
        // In units of 1/q pixels: triangle c's apex is at base·(rows + 2c − r)/(2·rows),
        // and it is base·within/(2·height·2·rows) wide on each side at this row.
        let q = 2 * height * 2 * rows;
        let half = base * within;
        // The first pixel whose centre is at or right of `edge`: ⌈edge/q − 1/2⌉, at least 0.
        let first = |edge: u64| {
            let twice = 2 * edge;
            let numerator = twice + q - 1;
            match (columns, u32::try_from(numerator)) {
                _ if twice <= q => 0,
                (Some(columns), Ok(numerator)) => u64::from(columns.divide(numerator)),
                _ => div_u64_narrow(numerator, 2 * q),
            }
        };
        let mut run: Option<(u64, u64)> = None;
        let mut c = 0u64;
        loop {
            let apex = base * (rows + 2 * c - r) * 2 * height;
            let (start, end) = (first(apex - half), first(apex + half));
            if start < end {
                run = match run {
                    Some((s, e)) if start <= e => Some((s, e.max(end))),
                    Some(done) => {
                        emit(done.0, done.1)?;
                        Some((start, end))
                    }
                    None => Some((start, end)),
                };
            }
            if c == r {
                break;
            }
            // The next c with c & !r == 0, in increasing order.
            c = ((c | !r).wrapping_add(1)) & r;
        }
        match run {
            Some(done) => emit(done.0, done.1),
            None => Ok(()),
        }
    }
}

impl<C: PixelColor> Dimensions for GasketDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.frame
    }
}

impl<C: PixelColor> Drawable for GasketDrawing<C> {
    type Color = C;
    type Output = GasketStats;

    fn draw<D>(&self, target: &mut D) -> Result<GasketStats, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut stats = GasketStats {
            triangles: power(3, self.order),
            runs: 0,
        };
        let width = u64::from(self.frame.size.width);
        let origin = self.frame.top_left;
        let paint = |target: &mut D, row: i32, from: u64, to: u64, color: C| {
            if to <= from {
                return Ok(());
            }
            let run = Rectangle::new(
                Point::new(origin.x + from as i32, row),
                Size::new((to - from) as u32, 1),
            );
            target.fill_solid(&run, color)
        };
        let columns = self.column_divisor();
        for y in 0..u64::from(self.frame.size.height) {
            let row = origin.y + y as i32;
            let mut painted = 0u64;
            self.row_runs(y, columns, |start, end| {
                let end = end.min(width);
                paint(target, row, painted, start, self.background)?;
                paint(target, row, start, end, self.ink)?;
                stats.runs += 1;
                painted = end;
                Ok(())
            })?;
            paint(target, row, painted, width, self.background)?;
        }
        Ok(stats)
    }
}
