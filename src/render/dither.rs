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

/// The thresholds of an n×n matrix spread over 8×8 (row by row), in 256ths:
/// (2k + 1)·128/n² for rank k.
// Evaluated when the crate compiles (the constants below): an index out of range would be
// a compile error, not a panic.
#[allow(clippy::indexing_slicing)]
const fn thresholds(n: usize) -> [u16; 64] {
    let mut table = [0u16; 64];
    let mut i = 0;
    while i < 64 {
        let (x, y) = (i % 8, i / 8);
        table[i] = if n == 8 {
            (2 * BAYER8[y][x] as u16 + 1) * 2
        } else if n == 4 {
            (2 * (BAYER8[y % 4][x % 4] / 4) as u16 + 1) * 8
        } else {
            128
        };
        i += 1;
    }
    table
}

const NEAREST: [u16; 64] = thresholds(1);
const BAYER4_THRESHOLDS: [u16; 64] = thresholds(4);
const BAYER8_THRESHOLDS: [u16; 64] = thresholds(8);
const NEAREST_RANGE: (u16, u16) = range(&NEAREST);
const BAYER4_RANGE: (u16, u16) = range(&BAYER4_THRESHOLDS);
const BAYER8_RANGE: (u16, u16) = range(&BAYER8_THRESHOLDS);

/// The lowest and highest of a table's thresholds.
// Evaluated when the crate compiles, as `thresholds` is.
#[allow(clippy::indexing_slicing)]
const fn range(table: &[u16; 64]) -> (u16, u16) {
    let (mut low, mut high) = (u16::MAX, 0);
    let mut i = 0;
    while i < 64 {
        if table[i] < low {
            low = table[i];
        }
        if table[i] > high {
            high = table[i];
        }
        i += 1;
    }
    (low, high)
}

/// The place of pixel (x, y) in an 8×8 block of thresholds, row by row.
#[inline(always)]
const fn cell(x: i32, y: i32) -> usize {
    ((y & 7) << 3 | (x & 7)) as usize
}

impl Dither {
    /// Its thresholds over an 8×8 block, row by row.
    #[inline]
    const fn table(self) -> &'static [u16; 64] {
        match self {
            Self::None => &NEAREST,
            Self::Bayer4 => &BAYER4_THRESHOLDS,
            Self::Bayer8 => &BAYER8_THRESHOLDS,
        }
    }

    /// Its lowest and highest thresholds (a colour alike at both is alike at every one:
    /// a panel's colour grows with the threshold).
    #[inline]
    const fn range(self) -> (u16, u16) {
        match self {
            Self::None => NEAREST_RANGE,
            Self::Bayer4 => BAYER4_RANGE,
            Self::Bayer8 => BAYER8_RANGE,
        }
    }

    /// The threshold at `point`, in 256ths: (2k + 1)·128/n², or 128 without dithering.
    #[inline]
    pub fn threshold(self, point: Point) -> u16 {
        self.table()
            .get(cell(point.x, point.y))
            .copied()
            .unwrap_or(128)
    }
}

/// The luma of a colour, 0–255.
#[inline]
fn luma(color: Rgb888) -> u8 {
    let sum = 77 * u32::from(color.r()) + 150 * u32::from(color.g()) + 29 * u32::from(color.b());
    u8::try_from(sum >> 8).unwrap_or(u8::MAX)
}

/// A panel's colour, made from 24-bit colour at a threshold.
///
/// A colour is prepared once ([`prepare`](Self::prepare): its luma or channels scaled to
/// the panel's levels) and then placed at each pixel's threshold ([`at`](Self::at)): a run
/// of one colour costs a comparison or a division by a constant a pixel.
pub trait Quantize: PixelColor {
    /// A colour ready to be placed at any threshold.
    type Prepared: Copy;

    /// `color` ready for [`at`](Self::at).
    fn prepare(color: Rgb888) -> Self::Prepared;

    /// The prepared colour at `threshold` (256ths; 128 rounds to nearest).
    fn at(prepared: Self::Prepared, threshold: u16) -> Self;

    /// `color` at `threshold`.
    fn quantize(color: Rgb888, threshold: u16) -> Self {
        Self::at(Self::prepare(color), threshold)
    }
}

impl Quantize for BinaryColor {
    /// The least threshold that lights it: v·256 + t·255 ≥ 255·256.
    type Prepared = u16;

    fn prepare(color: Rgb888) -> u16 {
        let short = 255 * 256 - 256 * u32::from(luma(color));
        u16::try_from(short.div_ceil(255)).unwrap_or(u16::MAX)
    }

    #[inline]
    fn at(least: u16, threshold: u16) -> Self {
        if threshold >= least {
            Self::On
        } else {
            Self::Off
        }
    }
}

macro_rules! quantize_gray {
    ($($color:ty: $levels:expr),*) => {$(
        impl Quantize for $color {
            /// The luma scaled: v·(N − 1)·256.
            type Prepared = u32;

            fn prepare(color: Rgb888) -> u32 {
                u32::from(luma(color)) * ($levels - 1) * 256
            }

            #[inline]
            fn at(scaled: u32, threshold: u16) -> Self {
                let level = (scaled + u32::from(threshold) * 255) / (255 * 256);
                Self::new(u8::try_from(level).unwrap_or(u8::MAX))
            }
        }
    )*};
}

quantize_gray!(Gray2: 4, Gray4: 16, Gray8: 256);

impl Quantize for Rgb565 {
    /// The channels scaled: v·(N − 1)·256 for 32, 64 and 32 levels.
    type Prepared = [u32; 3];

    fn prepare(color: Rgb888) -> [u32; 3] {
        [
            u32::from(color.r()) * 31 * 256,
            u32::from(color.g()) * 63 * 256,
            u32::from(color.b()) * 31 * 256,
        ]
    }

    #[inline]
    fn at([r, g, b]: [u32; 3], threshold: u16) -> Self {
        let level = |scaled: u32| {
            u8::try_from((scaled + u32::from(threshold) * 255) / (255 * 256)).unwrap_or(0)
        };
        Self::new(level(r), level(g), level(b))
    }
}

impl Quantize for Rgb888 {
    type Prepared = Rgb888;

    fn prepare(color: Rgb888) -> Rgb888 {
        color
    }

    fn at(color: Rgb888, _threshold: u16) -> Self {
        color
    }
}

/// A panel of fewer colours seen as a 24-bit target.
///
/// Every pixel drawn into it is brought to the panel's colours by [`Dither`] at its
/// position. Runs stay runs: a `fill_solid` of one colour leaves as a `fill_contiguous` of
/// its dithered pattern, or as a `fill_solid` where every threshold gives one panel colour
/// (always without dithering).
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
        let table = self.dither.table();
        self.target
            .draw_iter(pixels.into_iter().map(|Pixel(point, color)| {
                let threshold = table.get(cell(point.x, point.y)).copied().unwrap_or(128);
                Pixel(point, D::Color::quantize(color, threshold))
            }))
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Rgb888>,
    {
        let table = self.dither.table();
        let (left, width) = (area.top_left.x, area.size.width.max(1));
        let mut x = 0;
        let mut row = area.top_left.y;
        // Runs of one colour are the rule: the last colour is prepared once.
        let mut last: Option<(Rgb888, <D::Color as Quantize>::Prepared)> = None;
        let colors = colors.into_iter().map(move |color| {
            let prepared = match last {
                Some((seen, prepared)) if seen == color => prepared,
                _ => {
                    let prepared = D::Color::prepare(color);
                    last = Some((color, prepared));
                    prepared
                }
            };
            let column = left.wrapping_add_unsigned(x);
            let index = cell(column, row);
            x += 1;
            if x == width {
                x = 0;
                row += 1;
            }
            D::Color::at(prepared, table.get(index).copied().unwrap_or(128))
        });
        self.target.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb888) -> Result<(), Self::Error> {
        let prepared = D::Color::prepare(color);
        // One colour at every threshold (always without dithering; with it, a colour at or
        // beyond the panel's ends, or between two of its levels' thresholds' reach) is a
        // run of that colour.
        let (low, high) = self.dither.range();
        let lowest = D::Color::at(prepared, low);
        if lowest == D::Color::at(prepared, high) {
            return self.target.fill_solid(area, lowest);
        }
        // Each row's pattern of eight, repeated.
        let table = self.dither.table();
        let (left, width) = (area.top_left.x, area.size.width.max(1));
        let mut pattern = [D::Color::at(prepared, 128); 8];
        let mut row = area.top_left.y;
        let mut x = width;
        let colors = core::iter::from_fn(move || {
            if x == width {
                x = 0;
                for (column, slot) in pattern.iter_mut().enumerate() {
                    let index = cell(left.wrapping_add(column as i32), row);
                    *slot = D::Color::at(prepared, table.get(index).copied().unwrap_or(128));
                }
                row += 1;
            }
            let color = pattern.get((x & 7) as usize).copied();
            x += 1;
            color
        });
        self.target.fill_contiguous(area, colors)
    }
}
