//! Light on surfaces: how bright a polygon is from its normal, and colours darkened to a
//! brightness, so that leaves in space read as surfaces.
//!
//! The light comes from the viewer's upper left, (−1, 1, 2)/√6 in view space (x right, y
//! up, z towards the viewer); a surface is lit from both sides (a leaf has two). Its
//! brightness is 35% (ambient) plus 65% of |n · l| for its unit normal n: 255 is full.

use crate::math::divide::isqrt_u128;
use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb555, Rgb565,
    Rgb666, Rgb888, RgbColor,
};
use embedded_graphics::prelude::*;

/// A colour that can be darkened: what surfaces in light need of a target's colour type.
pub trait Shade: PixelColor {
    /// This colour at `light` / 255 of its brightness.
    fn shade(self, light: u8) -> Self;
}

fn scaled(channel: u8, light: u8) -> u8 {
    // (channel · light + 127) / 255 ≤ channel: fits.
    u8::try_from((u16::from(channel) * u16::from(light) + 127) / 255).unwrap_or(channel)
}

macro_rules! shade_rgb {
    ($($color:ty),*) => {$(
        impl Shade for $color {
            fn shade(self, light: u8) -> Self {
                Self::new(
                    scaled(self.r(), light),
                    scaled(self.g(), light),
                    scaled(self.b(), light),
                )
            }
        }
    )*};
}

shade_rgb!(Rgb555, Rgb565, Rgb666, Rgb888, Bgr555, Bgr565, Bgr666, Bgr888);

macro_rules! shade_gray {
    ($($color:ty),*) => {$(
        impl Shade for $color {
            fn shade(self, light: u8) -> Self {
                Self::new(scaled(self.luma(), light))
            }
        }
    )*};
}

shade_gray!(Gray2, Gray4, Gray8);

impl Shade for BinaryColor {
    /// One bit has no shades: unchanged.
    fn shade(self, _light: u8) -> Self {
        self
    }
}

/// The light direction times √6: (−1, 1, 2).
const LIGHT: [i128; 3] = [-1, 1, 2];

/// The brightness (0–255) of a surface with normal `normal` in view space (any length; a
/// zero normal, a polygon with no area, is lit as one facing the viewer).
pub(crate) fn brightness(normal: [i128; 3]) -> u8 {
    // Only the direction counts: below 2^40 a component, the squares sum without overflow.
    let largest = normal.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    let shift = (128 - largest.leading_zeros()).saturating_sub(40);
    let n = normal.map(|c| c >> shift);
    let dot: i128 = n.iter().zip(&LIGHT).map(|(a, b)| a * b).sum();
    let squared: u128 = n.iter().map(|&a| a.unsigned_abs().pow(2)).sum();
    // |n|·√6, the dot's full scale: below 2⁴⁴ (squared·6 < 2⁸⁵), so the share below is
    // a 64-bit division where the library's would be a 128-bit one.
    let full = isqrt_u128(squared.saturating_mul(6));
    if full == 0 {
        return 255;
    }
    let share = |x: u128| match (u64::try_from(x * 166), u64::try_from(full)) {
        (Ok(x), Ok(full)) => u128::from(x / full),
        _ => x * 166 / full,
    };
    let facing = share(dot.unsigned_abs().min(full)); // 0..=166 (65%)
    u8::try_from(89 + facing).unwrap_or(255)
}
