//! A square grid of heights drawn as a landscape seen from above: banded by height (water,
//! sand, grass, rock, snow) and hill-shaded, lit from the upper left. Midpoint
//! displacement's landscapes and noise's height fields are drawn the same way.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError};
use crate::math::Real;

/// Height bands, from the lowest level (of 256) each starts at: deep water, shallow
/// water, sand, grass, rock, snow.
const BANDS: [(u32, Rgb888); 6] = [
    (0, Rgb888::new(0x10, 0x30, 0x80)),
    (80, Rgb888::new(0x30, 0x70, 0xC0)),
    (100, Rgb888::new(0xD8, 0xC8, 0x88)),
    (110, Rgb888::new(0x40, 0x90, 0x38)),
    (180, Rgb888::new(0x80, 0x70, 0x60)),
    (225, Rgb888::new(0xF4, 0xF4, 0xF8)),
];
/// Levels below this are water: flat, not hill-shaded.
const SEA_LEVEL: u32 = 100;

/// A square grid of heights (Q16.16, row by row) stretched over an area: an
/// embedded-graphics [`Drawable`] sent as one `fill_contiguous`, row by row.
///
/// A pixel reads the grid bilinearly; its height, against the grid's lowest and highest,
/// picks a band; above the sea the slope towards the upper left lights it (up to 1.4) or
/// shades it (down to 0.5).
#[derive(Debug)]
pub struct Relief<'a, C> {
    heights: &'a [i32],
    n: usize,
    area: Rectangle,
    range: (i32, i32),
    color: core::marker::PhantomData<C>,
}

impl<'a, C> Relief<'a, C>
where
    C: PixelColor + From<Rgb888>,
{
    /// The first `side`² of `heights` over `area`. Refuses an empty area, a side below 2
    /// and a buffer shorter than `side`².
    pub fn new(heights: &'a [i32], side: u32, area: Rectangle) -> Result<Self, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let cells = side as usize * side as usize;
        let heights = match heights.get(..cells) {
            Some(heights) if side >= 2 => heights,
            _ => {
                return Err(Error::Fit(FitError::BufferTooSmall {
                    needed: cells.max(4),
                    given: heights.len(),
                }))
            }
        };
        let mut range = (i32::MAX, i32::MIN);
        for &h in heights {
            range = (range.0.min(h), range.1.max(h));
        }
        Ok(Self {
            heights,
            n: side as usize,
            area,
            range,
            color: core::marker::PhantomData,
        })
    }

    /// The lowest and highest heights.
    pub fn range(&self) -> (Real, Real) {
        let real = |h: i32| Real::from_bits(i64::from(h) << 16);
        (real(self.range.0), real(self.range.1))
    }

    /// The heights drawn (`side`²).
    pub fn cells(&self) -> usize {
        self.heights.len()
    }

    fn height(&self, x: usize, y: usize) -> i64 {
        let (x, y) = (x.min(self.n - 1), y.min(self.n - 1));
        i64::from(self.heights.get(y * self.n + x).copied().unwrap_or(0))
    }

    /// The colour of pixel (px, py) of the area: the grid read bilinearly, banded by
    /// height, lit by the slope towards the upper left.
    fn color_at(&self, px: u32, py: u32) -> C {
        let last = (self.n - 1) as i64;
        let (w, h) = (
            i64::from(self.area.size.width.max(2) - 1),
            i64::from(self.area.size.height.max(2) - 1),
        );
        // Grid position in Q8.
        let gx = i64::from(px) * last * 256 / w;
        let gy = i64::from(py) * last * 256 / h;
        let (x, y, fx, fy) = ((gx >> 8) as usize, (gy >> 8) as usize, gx & 255, gy & 255);
        let top = self.height(x, y) * (256 - fx) + self.height(x + 1, y) * fx;
        let bottom = self.height(x, y + 1) * (256 - fx) + self.height(x + 1, y + 1) * fx;
        let height = (top * (256 - fy) + bottom * fy) >> 16;
        let (low, high) = (i64::from(self.range.0), i64::from(self.range.1));
        let spread = (high - low).max(1);
        let level = ((height - low) * 255 / spread).clamp(0, 255) as u32;
        let band = BANDS
            .iter()
            .rev()
            .find(|(start, _)| level >= *start)
            .map_or(Rgb888::BLACK, |(_, color)| *color);
        if level < SEA_LEVEL {
            return C::from(band);
        }
        // The slope down to the lower right, against the landscape's spread: a face to
        // the upper left is lit (up to 1.4), one away from it shaded (down to 0.5).
        let slope = (self.height(x.saturating_sub(1), y.saturating_sub(1))
            - self.height(x + 1, y + 1))
            * 256
            * last
            / spread;
        let light = (256 - slope / 8).clamp(128, 358);
        let lit = |c: u8| ((i64::from(c) * light) >> 8).clamp(0, 255) as u8;
        C::from(Rgb888::new(lit(band.r()), lit(band.g()), lit(band.b())))
    }
}

impl<C> Dimensions for Relief<'_, C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C> Drawable for Relief<'_, C>
where
    C: PixelColor + From<Rgb888>,
{
    type Color = C;
    type Output = u64;

    /// Returns the heights drawn.
    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let (w, h) = (self.area.size.width, self.area.size.height);
        let colors = (0..h).flat_map(|y| (0..w).map(move |x| self.color_at(x, y)));
        target.fill_contiguous(&self.area, colors)?;
        Ok(self.heights.len() as u64)
    }
}
