//! The SSD0323's picture in RAM: 128×64 pixels of 4-bit grey, two to a byte with the left
//! pixel in the high nibble, rows top to bottom: exactly the bytes the controller takes.
//!
//! The controller cannot be read back and addresses two pixels per column, so a drawing
//! goes into this buffer and the whole buffer goes out at once (4 KiB over SPI).

use core::convert::Infallible;

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor},
    prelude::*,
    primitives::Rectangle,
};

/// Width in pixels.
pub const WIDTH: u32 = 128;
/// Height in pixels.
pub const HEIGHT: u32 = 64;
const ROW_BYTES: usize = WIDTH as usize / 2;

/// A 128×64 Gray4 framebuffer in the SSD0323's byte order.
#[derive(Debug, Clone)]
pub struct Framebuffer {
    bytes: [u8; ROW_BYTES * HEIGHT as usize],
}

impl Default for Framebuffer {
    fn default() -> Self {
        Self::new()
    }
}

impl Framebuffer {
    /// All black.
    pub const fn new() -> Self {
        Self {
            bytes: [0; ROW_BYTES * HEIGHT as usize],
        }
    }

    /// The bytes to send to the controller.
    pub const fn bytes(&self) -> &[u8] {
        &self.bytes
    }

    /// The grey level (0 to 15) of a pixel; 0 outside.
    pub fn level(&self, x: u32, y: u32) -> u8 {
        let Some(&byte) = self.bytes.get(y as usize * ROW_BYTES + x as usize / 2) else {
            return 0;
        };
        if x >= WIDTH {
            0
        } else if x.is_multiple_of(2) {
            byte >> 4
        } else {
            byte & 0x0F
        }
    }

    fn set(&mut self, x: u32, y: u32, level: u8) {
        if x >= WIDTH || y >= HEIGHT {
            return;
        }
        if let Some(byte) = self.bytes.get_mut(y as usize * ROW_BYTES + x as usize / 2) {
            *byte = if x.is_multiple_of(2) {
                (*byte & 0x0F) | (level << 4)
            } else {
                (*byte & 0xF0) | (level & 0x0F)
            };
        }
    }
}

impl OriginDimensions for Framebuffer {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl DrawTarget for Framebuffer {
    type Color = Gray4;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, color) in pixels {
            if let (Ok(x), Ok(y)) = (u32::try_from(p.x), u32::try_from(p.y)) {
                self.set(x, y, color.luma());
            }
        }
        Ok(())
    }

    /// Row by row, no `Pixel`s: the colours go straight to their nibbles.
    fn fill_contiguous<I: IntoIterator<Item = Gray4>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Infallible> {
        let mut colors = colors.into_iter();
        let (x0, y0) = (area.top_left.x, area.top_left.y);
        for y in y0..y0.saturating_add(area.size.height as i32) {
            for x in x0..x0.saturating_add(area.size.width as i32) {
                let Some(color) = colors.next() else {
                    return Ok(());
                };
                if let (Ok(x), Ok(y)) = (u32::try_from(x), u32::try_from(y)) {
                    self.set(x, y, color.luma());
                }
            }
        }
        Ok(())
    }

    /// Whole bytes where two pixels of a row share one, nibbles only at odd edges.
    fn fill_solid(&mut self, area: &Rectangle, color: Gray4) -> Result<(), Infallible> {
        let area = area.intersection(&self.bounding_box());
        let Some(bottom_right) = area.bottom_right() else {
            return Ok(());
        };
        let level = color.luma();
        let (left, right) = (area.top_left.x as u32, bottom_right.x as u32);
        for y in area.top_left.y as u32..=bottom_right.y as u32 {
            let mut x = left;
            if !x.is_multiple_of(2) {
                self.set(x, y, level);
                x += 1;
            }
            let pairs_end = (right + 1) & !1;
            if x < pairs_end {
                let row = y as usize * ROW_BYTES;
                if let Some(bytes) = self
                    .bytes
                    .get_mut(row + x as usize / 2..row + pairs_end as usize / 2)
                {
                    bytes.fill(level << 4 | level);
                }
                x = pairs_end;
            }
            if x <= right {
                self.set(x, y, level);
            }
        }
        Ok(())
    }
}
