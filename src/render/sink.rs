//! Value sinks: where a family's raw values (dwells, hit counts) go before any colour, so
//! the same render can paint a display or fill a buffer of numbers.

use core::convert::Infallible;

use embedded_graphics::{prelude::*, primitives::Rectangle};

/// Where dwells go: the raw layer under the palette (a display, or a buffer of numbers).
pub trait DwellSink {
    /// The sink's error.
    type Error;

    /// Dwells for every pixel of `area`, row by row (as `fill_contiguous`).
    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Self::Error>;

    /// One dwell for every pixel of `area` (as `fill_solid`). Override it where a block
    /// costs less than its pixels, as on a display.
    fn uniform(&mut self, area: &Rectangle, dwell: u16) -> Result<(), Self::Error> {
        self.dwells(area, core::iter::repeat(dwell))
    }
}

/// Dwells in a caller's slice, row by row, `width` to a row.
///
/// The sink for tests, host output and anything that needs the numbers rather than colours. Pixels outside the
/// slice are dropped, as a `DrawTarget` drops pixels outside its bounds.
#[derive(Debug)]
pub struct DwellBuffer<'a> {
    values: &'a mut [u16],
    width: u32,
}

impl<'a> DwellBuffer<'a> {
    /// A sink over `values`, `width` dwells to a row (a zero width holds nothing).
    pub fn new(values: &'a mut [u16], width: u32) -> Self {
        Self { values, width }
    }

    /// The dwells, row by row.
    pub fn values(&self) -> &[u16] {
        self.values
    }

    /// Dwells to a row.
    pub const fn width(&self) -> u32 {
        self.width
    }

    fn index(&self, p: Point) -> Option<usize> {
        let (x, y) = (u32::try_from(p.x).ok()?, u32::try_from(p.y).ok()?);
        if x >= self.width {
            return None;
        }
        let index = usize::try_from(u64::from(y) * u64::from(self.width) + u64::from(x)).ok()?;
        (index < self.values.len()).then_some(index)
    }
}

impl DwellSink for DwellBuffer<'_> {
    type Error = Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Infallible> {
        for (p, dwell) in area.points().zip(dwells) {
            if let Some(cell) = self.index(p).and_then(|i| self.values.get_mut(i)) {
                *cell = dwell;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_rows_and_drops_what_lies_outside() {
        let mut values = [0u16; 12];
        let mut buffer = DwellBuffer::new(&mut values, 4);
        let Ok(()) = buffer.uniform(&Rectangle::new(Point::new(2, 1), Size::new(5, 5)), 7);
        let Ok(()) = buffer.dwells(
            &Rectangle::new(Point::new(-1, 0), Size::new(2, 1)),
            [1, 2].into_iter(),
        );
        assert_eq!(values, [2, 0, 0, 0, 0, 0, 7, 7, 0, 0, 7, 7]);
    }
}
