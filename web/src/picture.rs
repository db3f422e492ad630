//! A picture as the page's canvas takes it, which a whole render and a view drawn in
//! steps both answer with.

use embedded_graphics::prelude::*;
use embedded_graphics::{pixelcolor::Rgb888, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;

/// A picture as the page's canvas takes it: RGBA bytes, row by row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picture {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Four bytes a pixel (alpha 255), rows top to bottom.
    pub rgba: Vec<u8>,
}

impl Picture {
    /// The pixels of a simulator display (the gallery's pictures).
    pub fn of(display: &SimulatorDisplay<Rgb888>) -> Self {
        let Rectangle { size, .. } = display.bounding_box();
        let mut rgba = Vec::with_capacity((size.width * size.height * 4) as usize);
        for y in 0..size.height as i32 {
            for x in 0..size.width as i32 {
                let colour = display.get_pixel(Point::new(x, y));
                rgba.extend_from_slice(&[colour.r(), colour.g(), colour.b(), 255]);
            }
        }
        Self {
            width: size.width,
            height: size.height,
            rgba,
        }
    }
}
