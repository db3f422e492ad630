//! What the measuring firmware (`boards/qemu-measure`) runs, shared with the host test that
//! checks it.
//!
//! A target that folds every pixel into a checksum, and the two baselines a user would write
//! first, computed from the catalogue's own scenes.

use core::convert::Infallible;

use embedded_graphics::{pixelcolor::Gray4, prelude::*, primitives::Rectangle};

use tinyfractal::{escape::Shading, Coord};

use crate::catalogue::{EscapeScene, Scene};

/// A target with no memory (128×64 unless made larger).
///
/// Every pixel written (position and grey, in order) is folded into an FNV-1a checksum, so the
/// host can check the MCU drew the same thing. Like a display driver it takes runs
/// (`fill_contiguous`, `fill_solid`) without a `Pixel` and a bounds check each; the baselines
/// draw through `draw_iter`, pixel by pixel.
#[derive(Debug, Clone, Copy)]
pub struct Checksum {
    /// The checksum so far.
    pub value: u32,
    /// Pixels written.
    pub pixels: u32,
    size: Size,
}

impl Default for Checksum {
    fn default() -> Self {
        Self::new()
    }
}

impl Checksum {
    /// The empty checksum of a 128×64 target (the OLED's).
    pub const fn new() -> Self {
        Self::of_size(Size::new(128, 64))
    }

    /// The empty checksum of a target of `size` (at most 512×256: positions are folded
    /// in as 9 and 8 bits).
    pub const fn of_size(size: Size) -> Self {
        Self {
            value: 0x811C_9DC5,
            pixels: 0,
            size,
        }
    }

    /// One pixel written: its position (inside the target) and grey.
    fn record(&mut self, x: i32, y: i32, color: Gray4) {
        self.value = folded(self.value, x, y, color);
        self.pixels += 1;
    }
}

/// `value` with a pixel's position and grey folded in as one 21-bit word (FNV-1a's step on
/// words, not bytes): one multiply a pixel, about what a framebuffer write costs.
#[inline(always)]
fn folded(value: u32, x: i32, y: i32, color: Gray4) -> u32 {
    let word = (x as u32 & 0x1FF) | (y as u32 & 0xFF) << 9 | u32::from(color.into_storage()) << 17;
    (value ^ word).wrapping_mul(0x0100_0193)
}

impl OriginDimensions for Checksum {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Checksum {
    type Color = Gray4;
    type Error = Infallible;

    // Never inlined into a scene: it stands in for a display driver, which is a call
    // away from the engine, and a count should not follow how the optimiser merges the two.
    #[inline(never)]
    fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        let (width, height) = (self.size.width as i32, self.size.height as i32);
        for Pixel(p, color) in pixels {
            if (0..width).contains(&p.x) && (0..height).contains(&p.y) {
                self.record(p.x, p.y, color);
            }
        }
        Ok(())
    }

    /// Runs, as a display driver takes them: one bounds check per run, not per pixel (the
    /// checksum is the same as pixel by pixel).
    #[inline(never)]
    fn fill_contiguous<I: IntoIterator<Item = Gray4>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let Some(bottom_right) = area.bottom_right() else {
            return Ok(());
        };
        // Four comparisons, as a driver clips: the run inside the target or not.
        let (width, height) = (self.size.width as i32, self.size.height as i32);
        let inside = area.top_left.x >= 0
            && area.top_left.y >= 0
            && bottom_right.x < width
            && bottom_right.y < height;
        if !inside {
            let pixels = area.points().zip(colors).map(|(p, c)| Pixel(p, c));
            return self.draw_iter(pixels);
        }
        // In locals while the run lasts, as a driver keeps its bus state in registers.
        let (mut value, mut pixels) = (self.value, self.pixels);
        let mut colors = colors.into_iter();
        'rows: for y in area.top_left.y..bottom_right.y + 1 {
            for x in area.top_left.x..bottom_right.x + 1 {
                let Some(color) = colors.next() else {
                    break 'rows;
                };
                value = folded(value, x, y, color);
                pixels += 1;
            }
        }
        (self.value, self.pixels) = (value, pixels);
        Ok(())
    }

    #[inline(never)]
    fn fill_solid(&mut self, area: &Rectangle, color: Gray4) -> Result<(), Infallible> {
        self.fill_contiguous(area, core::iter::repeat(color))
    }
}

/// A view for the baselines: centre, width, and the Julia parameter if any.
#[derive(Debug, Clone, Copy)]
pub struct BaselineView {
    /// Centre (re, im).
    pub centre: (f32, f32),
    /// Width along the real axis.
    pub width: f32,
    /// The Julia parameter, or `None` for the Mandelbrot set.
    pub julia: Option<(f32, f32)>,
    /// Iteration cap.
    pub max_iterations: u32,
}

fn grey(dwell: u32, max: u32) -> Gray4 {
    if dwell >= max {
        Gray4::new(0)
    } else {
        Gray4::new((dwell % 15 + 1) as u8)
    }
}

/// Every pixel in order: its dwell from `dwell(i, j)`, drawn alone with `draw_iter`, as the
/// classic display sketches do. Returns the total iterations.
fn pixel_by_pixel<D: DrawTarget<Color = Gray4>>(
    view: BaselineView,
    target: &mut D,
    mut dwell: impl FnMut(u32, u32) -> u32,
) -> u64 {
    let size = target.bounding_box().size;
    let mut total = 0u64;
    for j in 0..size.height {
        for i in 0..size.width {
            let n = dwell(i, j);
            total += u64::from(n);
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(i as i32, j as i32),
                grey(n, view.max_iterations),
            )));
        }
    }
    total
}

/// The naive f32 loop, drawn pixel by pixel: what a first sketch does.
pub fn baseline_f32<D: DrawTarget<Color = Gray4>>(view: BaselineView, target: &mut D) -> u64 {
    let size = target.bounding_box().size;
    let d = view.width / size.width as f32;
    pixel_by_pixel(view, target, |i, j| {
        let re = view.centre.0 + (i as f32 + 0.5 - size.width as f32 / 2.0) * d;
        let im = view.centre.1 - (j as f32 + 0.5 - size.height as f32 / 2.0) * d;
        let ((mut x, mut y), (cr, ci)) = match view.julia {
            None => ((0.0f32, 0.0f32), (re, im)),
            Some(k) => ((re, im), k),
        };
        let mut n = 0;
        while n < view.max_iterations {
            n += 1;
            let xt = x * x - y * y + cr;
            y = 2.0 * x * y + ci;
            x = xt;
            if x * x + y * y > 4.0 {
                break;
            }
        }
        n
    })
}

/// The naive fixed-point loop of the classic Arduino display example: i64 with 20
/// fractional bits, drawn pixel by pixel.
pub fn baseline_fixed20<D: DrawTarget<Color = Gray4>>(view: BaselineView, target: &mut D) -> u64 {
    const ONE: f32 = (1 << 20) as f32;
    let fix = |v: f32| (v * ONE) as i64;
    let size = target.bounding_box().size;
    let d = fix(view.width / size.width as f32);
    let (left, top) = (
        fix(view.centre.0) - d * i64::from(size.width) / 2 + d / 2,
        fix(view.centre.1) + d * i64::from(size.height) / 2 - d / 2,
    );
    let four = 4i64 << 20;
    pixel_by_pixel(view, target, |i, j| {
        let re = left + d * i64::from(i);
        let im = top - d * i64::from(j);
        let ((mut x, mut y), (cr, ci)) = match view.julia {
            None => ((0i64, 0i64), (re, im)),
            Some((kr, ki)) => ((re, im), (fix(kr), fix(ki))),
        };
        let mut n = 0;
        while n < view.max_iterations {
            n += 1;
            let (x2, y2) = ((x * x) >> 20, (y * y) >> 20);
            let xy = (x * y) >> 19;
            x = x2 - y2 + cr;
            y = xy + ci;
            if ((x * x) >> 20) + ((y * y) >> 20) > four {
                break;
            }
        }
        n
    })
}

impl BaselineView {
    /// The baselines' view of a catalogue scene, where a baseline applies: escape-time
    /// views that `f32` resolves (width at least 2⁻¹⁰, so a 128-pixel row's spacing is
    /// about 60 times f32's resolution near 1). L-systems have none, and f32 cannot tell
    /// the deep zoom's pixels apart. The numbers are the scene's own text, each rounded to
    /// the nearest f32 as a literal would be (through `Coord`: a test checks it against
    /// `str::parse`, which would cost the firmware 20 KB of flash and a larger stack).
    #[inline(never)]
    pub fn of(scene: &Scene) -> Option<Self> {
        // A naive loop computes dwells: it is no baseline for smooth values.
        let Scene::Escape(EscapeScene {
            julia,
            centre,
            width,
            max_iterations,
            shading: Shading::Dwell,
            ..
        }) = *scene
        else {
            return None;
        };
        let number = |text: &str| Coord::parse(text).map(|value| value.to_f64() as f32);
        let width = number(width).filter(|&w| w >= 1.0 / 1024.0)?;
        let julia = match julia {
            None => None,
            Some((re, im)) => Some((number(re)?, number(im)?)),
        };
        Some(Self {
            centre: (number(centre.0)?, number(centre.1)?),
            width,
            julia,
            max_iterations,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{GALLERY, SCENES};

    /// Through `Coord` and `f64`, every number of a catalogue view with a baseline becomes
    /// the f32 that `str::parse` (the nearest one) gives: no double rounding bites.
    #[test]
    fn baseline_numbers_are_the_nearest_f32() {
        let with_baseline = SCENES.iter().chain(&GALLERY);
        for entry in with_baseline.filter(|entry| BaselineView::of(&entry.scene).is_some()) {
            let Scene::Escape(EscapeScene {
                julia,
                centre,
                width,
                ..
            }) = entry.scene
            else {
                continue;
            };
            let (k_re, k_im) = julia.unwrap_or(("0", "0"));
            for text in [centre.0, centre.1, width, k_re, k_im] {
                let via_coord = Coord::parse(text).map(|value| value.to_f64() as f32);
                assert_eq!(
                    via_coord,
                    text.parse::<f32>().ok(),
                    "{}: {text}",
                    entry.name
                );
            }
        }
    }
}
