//! Fractal dimension by box counting, over whatever a [`Drawable`] draws.
//!
//! A [`BoxCounter`] is a `DrawTarget` that keeps one bit per box of the finest size (in a
//! buffer the caller gives), counts the occupied boxes of sides 2ᵏ from it, and fits the
//! slope of log₂ N against log₂ of the side by least squares: D = −slope, with the fit's
//! residual. Logarithms and the fit are fixed point, so the estimate is the same on every
//! target.
//!
//! A pixel counts when its colour is not the background. With the finest box a single
//! pixel, painting a pixel in the background colour clears it again, so drawings that
//! paint their background (the carpet's holes) count right; with larger finest boxes a
//! box only ever fills.
//!
//! [`Drawable`]: embedded_graphics::Drawable
//!
//! ```
//! use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::{PrimitiveStyle, Rectangle}};
//! use tinyfractal::BoxCounter;
//!
//! // A filled square has dimension 2.
//! let size = Size::new(256, 256);
//! let mut bits = vec![0u32; BoxCounter::<BinaryColor>::words_needed(size, 0)];
//! let mut counter = BoxCounter::new(size, 0, BinaryColor::Off, &mut bits)?;
//! let square = Rectangle::new(Point::zero(), size);
//! let Ok(()) = square.into_styled(PrimitiveStyle::with_fill(BinaryColor::On)).draw(&mut counter);
//! let estimate = counter.dimension()?;
//! assert!((estimate.value.to_f64() - 2.0).abs() < 0.01);
//! # Ok::<(), tinyfractal::Error>(())
//! ```

use core::convert::Infallible;

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError, ParameterError};
use crate::math::Real;

/// An estimated dimension: the slope's negative, and how far the counts stray from the
/// fitted line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Dimension {
    /// D = −slope of log₂ N(s) against log₂ s.
    pub value: Real,
    /// The root mean square of the counts' distance from the line, in log₂ units.
    pub residual: Real,
    /// log₂ of the smallest box side fitted.
    pub smallest: u32,
    /// log₂ of the largest box side fitted.
    pub largest: u32,
}

/// A draw target that records which boxes of side 2^`finest` pixels hold a pixel other
/// than the background, one bit each.
#[derive(Debug)]
pub struct BoxCounter<'a, C> {
    size: Size,
    finest: u32,
    background: C,
    bits: &'a mut [u32],
    columns: usize,
    rows: usize,
    row_words: usize,
}

impl<'a, C: PixelColor> BoxCounter<'a, C> {
    /// Finest boxes across and down an area of `size`, of side 2^`finest`.
    const fn grid(size: Size, finest: u32) -> (usize, usize) {
        let side = 1u32 << finest;
        (
            size.width.div_ceil(side) as usize,
            size.height.div_ceil(side) as usize,
        )
    }

    /// Words of buffer for an area of `size` with finest boxes of side 2^`finest`.
    pub const fn words_needed(size: Size, finest: u32) -> usize {
        let (columns, rows) = Self::grid(size, finest);
        columns.div_ceil(32) * rows
    }

    /// A counter over `size` pixels, counting pixels not equal to `background`, its
    /// finest boxes 2^`finest` pixels across, its bits in `bits` (cleared here).
    pub fn new(size: Size, finest: u32, background: C, bits: &'a mut [u32]) -> Result<Self, Error> {
        if size.width == 0 || size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let finest = finest.min(15);
        let needed = Self::words_needed(size, finest);
        let given = bits.len();
        let bits = bits
            .get_mut(..needed)
            .ok_or(Error::Fit(FitError::BufferTooSmall { needed, given }))?;
        bits.fill(0);
        let (columns, rows) = Self::grid(size, finest);
        Ok(Self {
            size,
            finest,
            background,
            bits,
            columns,
            rows,
            row_words: columns.div_ceil(32),
        })
    }

    /// Sets or clears the finest boxes from column `x0` to `x1` (exclusive) of row `y`.
    fn mark(&mut self, y: usize, x0: usize, x1: usize, on: bool) {
        let row = y * self.row_words;
        for x in x0..x1.min(self.columns) {
            if let Some(word) = self.bits.get_mut(row + x / 32) {
                let bit = 1 << (x % 32);
                if on {
                    *word |= bit;
                } else {
                    *word &= !bit;
                }
            }
        }
    }

    /// Whether any finest box from column `x0` to `x1` (exclusive) of row `y` is set.
    fn any(&self, y: usize, x0: usize, x1: usize) -> bool {
        let row = y * self.row_words;
        let mut x = x0;
        while x < x1 {
            let in_word = 32 - x % 32;
            let take = in_word.min(x1 - x);
            let mask = if take == 32 {
                u32::MAX
            } else {
                ((1u32 << take) - 1) << (x % 32)
            };
            if self.bits.get(row + x / 32).is_some_and(|w| w & mask != 0) {
                return true;
            }
            x += take;
        }
        false
    }

    /// Boxes of side 2^`side` pixels (at least the finest) that hold a counted pixel.
    pub fn occupied(&self, side: u32) -> u64 {
        let shift = side.saturating_sub(self.finest).min(31);
        let span = 1usize << shift;
        let mut count = 0;
        for by in (0..self.rows).step_by(span) {
            for bx in (0..self.columns).step_by(span) {
                let x1 = (bx + span).min(self.columns);
                if (by..(by + span).min(self.rows)).any(|y| self.any(y, bx, x1)) {
                    count += 1;
                }
            }
        }
        count
    }

    /// log₂ of the largest box side the area allows: its shorter side's.
    fn largest_side(&self) -> u32 {
        31 - self.size.width.min(self.size.height).leading_zeros()
    }

    /// The estimate over the default range of box sides: from 8 pixels (or the finest
    /// boxes, if larger) to a quarter of the shorter side, so the boxes are well above the
    /// pixels (below 8, the pixels' rendering of the finest detail bends the counts: a
    /// gasket drawn to single-pixel triangles measures 1.38 between sides 2 and 4) and
    /// at least four fit across the picture. Small areas start lower, down to 2 pixels.
    pub fn dimension(&self) -> Result<Dimension, Error> {
        let largest = self.largest_side().saturating_sub(2);
        let smallest = self.finest.max(largest.saturating_sub(2).clamp(1, 3));
        self.dimension_over(smallest, largest)
    }

    /// The estimate over box sides 2^`smallest` to 2^`largest` pixels.
    pub fn dimension_over(&self, smallest: u32, largest: u32) -> Result<Dimension, Error> {
        let max = self.largest_side();
        if smallest < self.finest || largest <= smallest || largest > max {
            return Err(Error::Parameter(ParameterError::BoxSizesOutOfRange {
                smallest,
                largest,
                max,
            }));
        }
        // Least squares of y = log2 N (Q16) against x = k.
        let (mut n, mut sx, mut sy, mut sxx, mut sxy) = (0i128, 0i128, 0i128, 0i128, 0i128);
        let mut points = [(0i128, 0i128); 32];
        for (slot, k) in points.iter_mut().zip(smallest..=largest) {
            let y = i128::from(log2_q16(self.occupied(k)));
            let x = i128::from(k);
            *slot = (x, y);
            n += 1;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        let denominator = n * sxx - sx * sx;
        if denominator == 0 {
            return Err(Error::Fit(FitError::EmptyDrawing));
        }
        // Slope and intercept in Q32 (y is Q16: shift 16 more).
        let slope = ((n * sxy - sx * sy) << 16) / denominator;
        let intercept = ((sy << 16) - slope * sx) / n;
        let mut squares = 0i128;
        for &(x, y) in points.iter().take(n as usize) {
            let error = (y << 16) - (intercept + slope * x);
            squares += (error >> 16) * (error >> 16);
        }
        // Root mean square, Q16 → Q32.
        let residual = isqrt((squares / n) as u128) << 16;
        Ok(Dimension {
            value: Real::from_bits(-(slope as i64)),
            residual: Real::from_bits(residual as i64),
            smallest,
            largest,
        })
    }
}

/// log₂ `n` in Q16 (0 for n ≤ 1): the integer part from the leading bit, the fraction by
/// repeated squaring of the mantissa.
pub(crate) fn log2_q16(n: u64) -> i64 {
    if n <= 1 {
        return 0;
    }
    let whole = 63 - n.leading_zeros();
    // Mantissa in [1, 2) as Q31.
    let mut x: u64 = if whole >= 31 {
        n >> (whole - 31)
    } else {
        n << (31 - whole)
    };
    let mut fraction = 0i64;
    for bit in (0..16).rev() {
        x = (x * x) >> 31;
        if x >= 1 << 32 {
            x >>= 1;
            fraction |= 1 << bit;
        }
    }
    (i64::from(whole) << 16) | fraction
}

/// ⌊√n⌋.
fn isqrt(n: u128) -> u128 {
    if n < 2 {
        return n;
    }
    let mut x = n;
    let mut y = x.div_ceil(2);
    while y < x {
        x = y;
        y = (x + n / x) / 2;
    }
    x
}

impl<C: PixelColor> OriginDimensions for BoxCounter<'_, C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor> DrawTarget for BoxCounter<'_, C> {
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(point, color) in pixels {
            let (Ok(x), Ok(y)) = (u32::try_from(point.x), u32::try_from(point.y)) else {
                continue;
            };
            if x >= self.size.width || y >= self.size.height {
                continue;
            }
            let on = color != self.background;
            if on || self.finest == 0 {
                let (bx, by) = ((x >> self.finest) as usize, (y >> self.finest) as usize);
                self.mark(by, bx, bx + 1, on);
            }
        }
        Ok(())
    }

    /// Whole rows of boxes at a time: a filled rectangle is common (carpets, terrain).
    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Infallible> {
        let area = area.intersection(&self.bounding_box());
        let Some(end) = area.bottom_right() else {
            return Ok(());
        };
        let on = color != self.background;
        if !on && self.finest != 0 {
            return Ok(());
        }
        let f = self.finest;
        let (x0, x1) = ((area.top_left.x as usize) >> f, ((end.x as usize) >> f) + 1);
        for y in ((area.top_left.y as usize) >> f)..=((end.y as usize) >> f) {
            self.mark(y, x0, x1, on);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log2_is_exact_on_powers_and_close_elsewhere() {
        assert_eq!(log2_q16(1), 0);
        assert_eq!(log2_q16(1024), 10 << 16);
        for n in [3u64, 5, 10, 1000, 123_456_789] {
            let expected = (n as f64).log2() * 65536.0;
            assert!((log2_q16(n) as f64 - expected).abs() <= 1.0, "{n}");
        }
    }
}
