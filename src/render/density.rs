//! Pictures coloured by how often points hit each pixel: the hit counts in the caller's
//! buffer, on a log scale through a palette, written a row at a time. The IFS and the
//! attractors draw their density pictures through this.

use core::cell::Cell;

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::palette::Palette;
use crate::error::{Error, FitError};

/// Density levels: a pixel hit `n` times takes level 1 + ⌊log₂ n⌋ (at most this − 1), one
/// never hit level 0; the palette is asked for values up to `DENSITY_LEVELS - 1` of
/// `DENSITY_LEVELS`.
pub const DENSITY_LEVELS: u16 = 16;

/// The shortest stretch of pixels never hit that is sent as a `fill_solid` of its own.
///
/// A shorter stretch goes with its row's lit pixels: on an SPI display a run's address
/// window costs about what a few pixels do.
pub const MIN_BLANK_RUN: usize = 8;

/// The density level of a hit count.
#[inline]
pub(crate) fn level(count: u16) -> u16 {
    if count == 0 {
        return 0;
    }
    let log2 = u16::try_from(count.ilog2()).unwrap_or(0);
    (1 + log2).min(DENSITY_LEVELS - 1)
}

/// A hit counter's cell: `u16` (counts to 65,535, every level) or `u8` (counts to 255,
/// levels up to 8, half the memory: what a board with little RAM gives).
pub trait HitCount: Copy + Default + core::fmt::Debug + sealed::Sealed {
    /// One more hit, saturating.
    fn bumped(self) -> Self;
    /// The count as a `u16`.
    fn count(self) -> u16;
}

/// `count` (below 2^`bits`) plus one, saturating at 2^`bits` − 1, as one more less its
/// carry out: one subtraction of a shifted value, cheaper in a density loop than a compare
/// and a conditional move (docs/performance.md, The attractors against the sketches).
#[inline(always)]
const fn saturating_bump(count: u32, bits: u32) -> u32 {
    let more = count + 1;
    more - (more >> bits)
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for u8 {}
    impl Sealed for u16 {}
}

impl HitCount for u8 {
    #[inline]
    fn bumped(self) -> Self {
        // At most 2^BITS − 1 again: the cast keeps it whole.
        saturating_bump(u32::from(self), Self::BITS) as Self
    }
    #[inline]
    fn count(self) -> u16 {
        u16::from(self)
    }
}

impl HitCount for u16 {
    #[inline]
    fn bumped(self) -> Self {
        // At most 2^BITS − 1 again: the cast keeps it whole.
        saturating_bump(u32::from(self), Self::BITS) as Self
    }
    #[inline]
    fn count(self) -> u16 {
        self
    }
}

/// Hit counts over an area, one cell a pixel in the caller's buffer (a count saturates).
pub(crate) struct Density<'b, T> {
    area: Rectangle,
    counts: &'b [Cell<T>],
}

impl<T> core::fmt::Debug for Density<'_, T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Density")
            .field("area", &self.area)
            .field("cells", &self.counts.len())
            .finish()
    }
}

impl<'b, T: HitCount> Density<'b, T> {
    /// Counts over `area` in the first width × height cells of `counts`, or
    /// [`FitError::BufferTooSmall`].
    pub(crate) fn new(area: Rectangle, counts: &'b mut [T]) -> Result<Self, Error> {
        let needed = usize::try_from(u64::from(area.size.width) * u64::from(area.size.height))
            .unwrap_or(usize::MAX);
        let given = counts.len();
        let counts = counts
            .get_mut(..needed)
            .ok_or(Error::Fit(FitError::BufferTooSmall { needed, given }))?;
        Ok(Self {
            area,
            counts: Cell::from_mut(counts).as_slice_of_cells(),
        })
    }

    /// Every count back to 0.
    pub(crate) fn clear(&self) {
        for cell in self.counts {
            cell.set(T::default());
        }
    }

    /// Counts a hit on `pixel`; false where it is outside the area.
    #[inline]
    pub(crate) fn hit(&self, pixel: Point) -> bool {
        let offset = pixel - self.area.top_left;
        match (u32::try_from(offset.x), u32::try_from(offset.y)) {
            (Ok(column), Ok(row)) => self.hit_at(column, row),
            _ => false,
        }
    }

    /// Counts a hit on the pixel `column`, `row` of the area; false where it is outside.
    #[inline]
    pub(crate) fn hit_at(&self, column: u32, row: u32) -> bool {
        if column >= self.area.size.width || row >= self.area.size.height {
            return false;
        }
        self.hit_inside(column, row)
    }

    /// Counts a hit on the pixel `column`, `row`, known to be inside the area (where it
    /// is not, a cell beyond the counts is refused; another inside is counted instead).
    #[inline]
    pub(crate) fn hit_inside(&self, column: u32, row: u32) -> bool {
        self.hit_cell(row as usize * self.area.size.width as usize + column as usize)
    }

    /// Counts a hit on the cell `index`, row × width + column; false where it is beyond
    /// the counts (past the area's last row).
    #[inline]
    pub(crate) fn hit_cell(&self, index: usize) -> bool {
        match self.counts.get(index) {
            Some(cell) => {
                cell.set(cell.get().bumped());
                true
            }
            None => false,
        }
    }

    /// Writes every pixel of the area, a row at a time, left to right: a stretch of at
    /// least [`MIN_BLANK_RUN`] pixels never hit as one `fill_solid` of the unlit colour, the
    /// rest of the row in `fill_contiguous` runs between them (the same pixels in the same
    /// order as a row a call).
    pub(crate) fn emit<P: Palette, D>(&self, palette: &P, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let width = self.area.size.width;
        let width_cells = usize::try_from(width).unwrap_or(usize::MAX);
        // Each level's colour once, not a palette's interpolation a pixel.
        let shades: [P::Color; DENSITY_LEVELS as usize] =
            core::array::from_fn(|level| palette.color(level as u16, DENSITY_LEVELS));
        let [unlit, ..] = shades;
        // Every level is below DENSITY_LEVELS: the fallback is never taken.
        let shade = |count: u16| {
            shades
                .get(usize::from(level(count)))
                .copied()
                .unwrap_or(unlit)
        };
        let left = self.area.top_left.x;
        // A stretch of the row from `from`, `count` pixels: both below the width, a u32,
        // so the casts keep them whole; an area at the end of the i32 range wraps there
        // instead of overflowing (no panic in a debug build).
        let stretch = |y: i32, from: usize, count: usize| {
            Rectangle::new(
                Point::new(left.wrapping_add(from as i32), y),
                Size::new(count as u32, 1),
            )
        };
        for (row, cells) in self.counts.chunks(width_cells.max(1)).enumerate() {
            let y = self.area.top_left.y + i32::try_from(row).unwrap_or(i32::MAX);
            let blank = |x: usize| cells.get(x).is_some_and(|cell| cell.get().count() == 0);
            // The cells `from..to` of the row, in their colours.
            let colors = |from: usize, to: usize| {
                let part = cells.get(from..to).unwrap_or_default();
                part.iter().map(|cell| shade(cell.get().count()))
            };
            // Cells from `sent` on are not sent yet; `x` reads on.
            let (mut sent, mut x) = (0, 0);
            while x < cells.len() {
                if !blank(x) {
                    x += 1;
                    continue;
                }
                let start = x;
                while blank(x) {
                    x += 1;
                }
                if x - start < MIN_BLANK_RUN {
                    continue;
                }
                if start > sent {
                    target.fill_contiguous(&stretch(y, sent, start - sent), colors(sent, start))?;
                }
                target.fill_solid(&stretch(y, start, x - start), unlit)?;
                sent = x;
            }
            if sent < cells.len() {
                let end = cells.len();
                target.fill_contiguous(&stretch(y, sent, end - sent), colors(sent, end))?;
            }
        }
        Ok(())
    }

    /// The area counted.
    pub(crate) fn area(&self) -> Rectangle {
        self.area
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::math::Generator;
    use crate::render::palette::Colors;
    use embedded_graphics::pixelcolor::Gray8;

    /// Every pixel sent in order, and the `fill_solid` calls.
    #[derive(Default)]
    struct Sent {
        pixels: Vec<(Point, Gray8)>,
        solid: Vec<Rectangle>,
    }

    impl OriginDimensions for Sent {
        fn size(&self) -> Size {
            Size::new(1 << 12, 1 << 12)
        }
    }

    impl DrawTarget for Sent {
        type Color = Gray8;
        type Error = core::convert::Infallible;

        fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(
            &mut self,
            pixels: I,
        ) -> Result<(), Self::Error> {
            self.pixels
                .extend(pixels.into_iter().map(|Pixel(p, c)| (p, c)));
            Ok(())
        }

        fn fill_solid(&mut self, area: &Rectangle, color: Gray8) -> Result<(), Self::Error> {
            self.solid.push(*area);
            self.pixels.extend(area.points().map(|p| (p, color)));
            Ok(())
        }
    }

    /// Rows with blanks of every length from none to a whole row: every pixel is sent
    /// once, left to right and row by row, in its level's colour; each blank of at least
    /// `MIN_BLANK_RUN` pixels is one `fill_solid` and no shorter one is.
    #[test]
    fn rows_go_in_order_with_long_blanks_alone() {
        let mut random = Generator::new(5);
        let greys: [Gray8; DENSITY_LEVELS as usize] =
            core::array::from_fn(|level| Gray8::new(level as u8 * 16 + 3));
        let palette = Colors::new(&greys).unwrap();
        for width in [1u32, 7, 8, 9, 40] {
            let height = 5;
            let mut counts = std::vec![0u16; (width * height) as usize];
            for cell in counts.iter_mut() {
                // Mostly blank, in stretches of random length.
                if random.next_u32().is_multiple_of(6) {
                    *cell = (random.next_u32() % 300) as u16;
                }
            }
            // A whole blank row and a whole lit one.
            counts[..width as usize].fill(0);
            counts[width as usize..2 * width as usize].fill(3);
            let expected_counts = counts.clone();
            let area = Rectangle::new(Point::new(-3, 11), Size::new(width, height));
            let density = Density::new(area, &mut counts).unwrap();
            let mut sent = Sent::default();
            density.emit(&palette, &mut sent).unwrap();
            let expected: Vec<(Point, Gray8)> = area
                .points()
                .zip(&expected_counts)
                .map(|(p, &count)| (p, palette.color(level(count), DENSITY_LEVELS)))
                .collect();
            assert_eq!(sent.pixels, expected, "width {width}");
            // The blanks of at least MIN_BLANK_RUN, from the counts.
            let mut blanks = Vec::new();
            for (row, cells) in expected_counts.chunks(width as usize).enumerate() {
                let mut x = 0;
                while x < cells.len() {
                    let start = x;
                    while x < cells.len() && cells[x] == 0 {
                        x += 1;
                    }
                    if x - start >= MIN_BLANK_RUN {
                        blanks.push(Rectangle::new(
                            area.top_left + Point::new(start as i32, row as i32),
                            Size::new((x - start) as u32, 1),
                        ));
                    }
                    x = x.max(start + 1);
                }
            }
            assert_eq!(sent.solid, blanks, "width {width}");
        }
    }

    /// A count bumped is one more, saturating, for every count of either width.
    #[test]
    fn bumped_counts_saturate() {
        for count in 0..=u8::MAX {
            assert_eq!(count.bumped(), count.saturating_add(1), "{count}");
        }
        for count in 0..=u16::MAX {
            assert_eq!(count.bumped(), count.saturating_add(1), "{count}");
        }
    }
}
