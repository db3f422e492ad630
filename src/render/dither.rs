//! Ordered dithering: any picture in 24-bit colour shown on the panel a board has (one-bit,
//! 2-, 4- or 8-bit grey, RGB565), each pixel's threshold from a Bayer matrix at its
//! position, so smooth palettes keep their gradients on few levels.
//!
//! A channel of value v (0–255) on a panel of N levels takes level ⌊v·(N − 1)/255 + t⌋,
//! where t is the Bayer threshold (2k + 1)/(2n²) of the pixel's place in the n×n matrix
//! (k its rank), or ½ without dithering (round to nearest). Over any n×n block the levels
//! average v·(N − 1)/255 to within 1/(n²) of a level (tested), and as the threshold depends
//! on the position only, tiles, runs and mirrored halves need nothing of each other.
//! Grey panels take the luma (77·R + 150·G + 29·B) / 256.

use embedded_graphics::pixelcolor::{BinaryColor, Gray2, Gray4, Gray8, Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// How a picture's colours are brought to the panel's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum Dither {
    /// Each channel rounded to the nearest level.
    #[default]
    None,
    /// Bayer's 4×4 ordered dither.
    Bayer4,
    /// Bayer's 8×8 ordered dither.
    Bayer8,
}

/// Bayer's 8×8 matrix: the rank of each place (its top-left 4×4 quarter, halved, is the
/// 4×4 one).
const BAYER8: [[u8; 8]; 8] = [
    [0, 32, 8, 40, 2, 34, 10, 42],
    [48, 16, 56, 24, 50, 18, 58, 26],
    [12, 44, 4, 36, 14, 46, 6, 38],
    [60, 28, 52, 20, 62, 30, 54, 22],
    [3, 35, 11, 43, 1, 33, 9, 41],
    [51, 19, 59, 27, 49, 17, 57, 25],
    [15, 47, 7, 39, 13, 45, 5, 37],
    [63, 31, 55, 23, 61, 29, 53, 21],
];

impl Dither {
    /// The threshold at `point`, in 256ths: (2k + 1)·128/n², or 128 without dithering.
    #[inline]
    pub fn threshold(self, point: Point) -> u16 {
        let (x, y) = ((point.x & 7) as usize, (point.y & 7) as usize);
        match self {
            Self::None => 128,
            Self::Bayer8 => {
                let rank = BAYER8
                    .get(y)
                    .and_then(|row| row.get(x))
                    .copied()
                    .unwrap_or(0);
                (2 * u16::from(rank) + 1) * 2
            }
            Self::Bayer4 => {
                let rank = BAYER8
                    .get(y & 3)
                    .and_then(|row| row.get(x & 3))
                    .copied()
                    .unwrap_or(0)
                    / 4;
                (2 * u16::from(rank) + 1) * 8
            }
        }
    }
}

/// The level (0 to `levels` − 1) of channel value `value` (0–255) at `threshold` (256ths).
#[inline]
fn level(value: u8, levels: u32, threshold: u16) -> u32 {
    (u32::from(value) * (levels - 1) * 256 + u32::from(threshold) * 255) / (255 * 256)
}

/// The luma of a colour, 0–255.
#[inline]
fn luma(color: Rgb888) -> u8 {
    let sum = 77 * u32::from(color.r()) + 150 * u32::from(color.g()) + 29 * u32::from(color.b());
    u8::try_from(sum >> 8).unwrap_or(u8::MAX)
}

/// A panel's colour, made from 24-bit colour at a threshold.
pub trait Quantize: PixelColor {
    /// `color` at `threshold` (256ths; 128 rounds to nearest).
    fn quantize(color: Rgb888, threshold: u16) -> Self;
}

impl Quantize for BinaryColor {
    fn quantize(color: Rgb888, threshold: u16) -> Self {
        if level(luma(color), 2, threshold) > 0 {
            Self::On
        } else {
            Self::Off
        }
    }
}

macro_rules! quantize_gray {
    ($($color:ty: $levels:expr),*) => {$(
        impl Quantize for $color {
            fn quantize(color: Rgb888, threshold: u16) -> Self {
                let level = level(luma(color), $levels, threshold);
                Self::new(u8::try_from(level).unwrap_or(u8::MAX))
            }
        }
    )*};
}

quantize_gray!(Gray2: 4, Gray4: 16, Gray8: 256);

impl Quantize for Rgb565 {
    fn quantize(color: Rgb888, threshold: u16) -> Self {
        let channel =
            |value: u8, levels: u32| u8::try_from(level(value, levels, threshold)).unwrap_or(0);
        Self::new(
            channel(color.r(), 32),
            channel(color.g(), 64),
            channel(color.b(), 32),
        )
    }
}

impl Quantize for Rgb888 {
    fn quantize(color: Rgb888, _threshold: u16) -> Self {
        color
    }
}

/// A panel of fewer colours seen as a 24-bit target.
///
/// Every pixel drawn into it is brought to the panel's colours by [`Dither`] at its
/// position. Runs stay runs: a `fill_solid` of one colour leaves as a `fill_contiguous` of
/// its dithered pattern (or a `fill_solid` without dithering).
#[derive(Debug)]
pub struct Dithered<'a, D> {
    target: &'a mut D,
    dither: Dither,
}

impl<'a, D> Dithered<'a, D> {
    /// `target` seen as a 24-bit target, its colours made by `dither`.
    pub fn new(target: &'a mut D, dither: Dither) -> Self {
        Self { target, dither }
    }
}

impl<D: DrawTarget> Dimensions for Dithered<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D> DrawTarget for Dithered<'_, D>
where
    D: DrawTarget,
    D::Color: Quantize,
{
    type Color = Rgb888;
    type Error = D::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Rgb888>>,
    {
        let dither = self.dither;
        self.target
            .draw_iter(pixels.into_iter().map(|Pixel(point, color)| {
                Pixel(point, D::Color::quantize(color, dither.threshold(point)))
            }))
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Rgb888>,
    {
        let dither = self.dither;
        let colors = area
            .points()
            .zip(colors)
            .map(|(point, color)| D::Color::quantize(color, dither.threshold(point)));
        self.target.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb888) -> Result<(), Self::Error> {
        if self.dither == Dither::None {
            return self.target.fill_solid(
                area,
                D::Color::quantize(color, Dither::None.threshold(Point::zero())),
            );
        }
        let dither = self.dither;
        let colors = area
            .points()
            .map(|point| D::Color::quantize(color, dither.threshold(point)));
        self.target.fill_contiguous(area, colors)
    }
}
