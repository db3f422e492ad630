//! One host framebuffer for the tests and benches of every crate.
//!
//! Any colour, any size (MockDisplay stops at 64×64), pixels outside counted rather than
//! dropped silently, and `fill_solid` writing rows directly, as a real framebuffer does.

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};

/// A framebuffer of `C`, row by row.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame<C> {
    /// Its size.
    pub size: Size,
    /// Its pixels, row by row.
    pub pixels: Vec<C>,
    /// Pixels drawn outside the frame.
    pub outside: usize,
}

impl<C: PixelColor> Frame<C> {
    /// A frame of `size`, every pixel `background`.
    pub fn filled(size: Size, background: C) -> Self {
        Self {
            size,
            pixels: vec![background; (size.width * size.height) as usize],
            outside: 0,
        }
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
        (x < self.size.width && y < self.size.height).then(|| (y * self.size.width + x) as usize)
    }

    /// The pixel at (x, y), `None` outside.
    pub fn pixel(&self, x: i32, y: i32) -> Option<C> {
        self.index(x, y).map(|i| self.pixels[i])
    }
}

/// A 1-bit frame, all off.
pub type Bitmap = Frame<BinaryColor>;

impl Bitmap {
    /// A bitmap of `width`×`height`, all off.
    pub fn new(width: u32, height: u32) -> Self {
        Self::filled(Size::new(width, height), BinaryColor::Off)
    }

    /// Whether (x, y) is inside and on.
    pub fn get(&self, x: i32, y: i32) -> bool {
        self.pixel(x, y).is_some_and(|c| c.is_on())
    }

    /// How many pixels are on.
    pub fn lit(&self) -> usize {
        self.pixels.iter().filter(|c| c.is_on()).count()
    }
}

impl<C: PixelColor> OriginDimensions for Frame<C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor> DrawTarget for Frame<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            match self.index(p.x, p.y) {
                Some(i) => self.pixels[i] = c,
                None => self.outside += 1,
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        let inside = area.intersection(&self.bounding_box());
        self.outside +=
            (area.size.width * area.size.height - inside.size.width * inside.size.height) as usize;
        let Some(bottom_right) = inside.bottom_right() else {
            return Ok(());
        };
        let width = self.size.width as usize;
        for y in inside.top_left.y..=bottom_right.y {
            let row = y as usize * width;
            self.pixels[row + inside.top_left.x as usize..=row + bottom_right.x as usize]
                .fill(color);
        }
        Ok(())
    }
}
