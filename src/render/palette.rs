//! From a value to a colour, for every family: an escape-time dwell, or an L-system's colour
//! index. Gradients work for any `PixelColor` that converts from `Rgb888` (every colour
//! type of embedded-graphics does: `Rgb565`, `Rgb888`, `Gray8`, `Gray4`, `BinaryColor`...).
//! Conversions happen when a palette is built, never per pixel.

use embedded_graphics::pixelcolor::{PixelColor, Rgb888, RgbColor};

/// Maps a value to a colour: an escape-time dwell, where `max` means "did not escape"
/// (inside), or an L-system colour index, drawn with `max` = `u16::MAX` (never inside).
pub trait Palette {
    /// The colour type.
    type Color: PixelColor;

    /// The colour of a pixel with this value.
    fn color(&self, value: u16, max: u16) -> Self::Color;
}

impl<P: Palette + ?Sized> Palette for &P {
    type Color = P::Color;

    fn color(&self, value: u16, max: u16) -> Self::Color {
        (**self).color(value, max)
    }
}

/// A list of colours taken in turn, as Fractint's colour indices are: value `v` takes
/// `colours[v % len]`; inside (an escape-time value at `max`) takes the first colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Colors<'a, C> {
    colors: &'a [C],
    first: C,
}

impl<'a, C: PixelColor> Colors<'a, C> {
    /// The colours in order; `None` if there are none.
    pub fn new(colors: &'a [C]) -> Option<Self> {
        let first = *colors.first()?;
        Some(Self { colors, first })
    }
}

impl<C: PixelColor> Palette for Colors<'_, C> {
    type Color = C;

    fn color(&self, value: u16, max: u16) -> C {
        if value >= max {
            return self.first;
        }
        // An index within the list needs no division (a library call on Cortex-M0, once a
        // segment for an L-system).
        let index = usize::from(value);
        match self.colors.get(index) {
            Some(&color) => color,
            None => self
                .colors
                .get(index % self.colors.len().max(1))
                .copied()
                .unwrap_or(self.first),
        }
    }
}

/// Inside one colour, outside another.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TwoColor<C> {
    /// The colour of points that did not escape.
    pub inside: C,
    /// The colour of every escaping point.
    pub outside: C,
}

impl<C: PixelColor> Palette for TwoColor<C> {
    type Color = C;

    fn color(&self, dwell: u16, max: u16) -> C {
        if dwell >= max {
            self.inside
        } else {
            self.outside
        }
    }
}

/// Ranges of dwell to colours: band `(up_to, colour)` covers dwells up to `up_to`; dwells
/// beyond the last band take its colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bands<'a, C> {
    bands: &'a [(u16, C)],
    inside: C,
}

impl<'a, C: PixelColor> Bands<'a, C> {
    /// Bands sorted by `up_to`, and the inside colour. `None` if `bands` is empty.
    pub fn new(bands: &'a [(u16, C)], inside: C) -> Option<Self> {
        (!bands.is_empty()).then_some(Self { bands, inside })
    }
}

impl<C: PixelColor> Palette for Bands<'_, C> {
    type Color = C;

    fn color(&self, dwell: u16, max: u16) -> C {
        if dwell >= max {
            return self.inside;
        }
        self.bands
            .iter()
            .find(|(up_to, _)| dwell <= *up_to)
            .or(self.bands.last())
            .map_or(self.inside, |&(_, color)| color)
    }
}

/// A smooth gradient through key colours, as a lookup table of `N` colours built once;
/// dwell `d` outside takes entry `(d + offset) % N`. Change the offset to cycle colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gradient<C, const N: usize> {
    /// Entries turned by `offset`: dwell `d` takes `table[d % N]`, one read a pixel.
    table: [C; N],
    inside: C,
    offset: u16,
}

impl<C: PixelColor + From<Rgb888>, const N: usize> Gradient<C, N> {
    /// Spreads `N` entries evenly through `keys` (a closed loop: the last key blends back
    /// into the first, so cycling has no seam). `None` if `keys` is empty or `N` is 0.
    pub fn new(keys: &[Rgb888], inside: C) -> Option<Self> {
        let first = *keys.first()?;
        if N == 0 {
            return None;
        }
        let mut table = [C::from(first); N];
        let segments = keys.len();
        for (index, entry) in table.iter_mut().enumerate() {
            // Position along the loop in 1/N steps, split into key and fraction (×256).
            let position = index * segments * 256 / N;
            let (key, fraction) = (position / 256, (position % 256) as u32);
            let from = keys.get(key).copied().unwrap_or(first);
            let to = keys.get((key + 1) % segments).copied().unwrap_or(first);
            let mix = |a: u8, b: u8| -> u8 {
                ((u32::from(a) * (256 - fraction) + u32::from(b) * fraction + 128) >> 8) as u8
            };
            *entry = C::from(Rgb888::new(
                mix(from.r(), to.r()),
                mix(from.g(), to.g()),
                mix(from.b(), to.b()),
            ));
        }
        Some(Self {
            table,
            inside,
            offset: 0,
        })
    }

    /// The same gradient shifted by `offset` entries (colour cycling). The table is turned
    /// here, once (N moves), so a pixel costs one read.
    #[must_use]
    pub fn with_offset(mut self, offset: u16) -> Self {
        if N > 0 {
            // From the current offset to the new one.
            let turn = (usize::from(offset) % N + N - usize::from(self.offset) % N) % N;
            self.table.rotate_left(turn);
        }
        self.offset = offset;
        self
    }
}

impl<C: PixelColor, const N: usize> Palette for Gradient<C, N> {
    type Color = C;

    fn color(&self, dwell: u16, max: u16) -> C {
        if dwell >= max {
            return self.inside;
        }
        let index = usize::from(dwell) % N.max(1);
        self.table.get(index).copied().unwrap_or(self.inside)
    }
}

#[cfg(test)]
mod tests {
    use embedded_graphics::pixelcolor::Rgb565;

    use super::*;

    #[test]
    fn colours_cycle_and_inside_takes_the_first() {
        let list = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE];
        let colors = Colors::new(&list).unwrap();
        let picked: [Rgb565; 5] = core::array::from_fn(|i| colors.color(i as u16, u16::MAX));
        assert_eq!(
            picked,
            [
                Rgb565::RED,
                Rgb565::GREEN,
                Rgb565::BLUE,
                Rgb565::RED,
                Rgb565::GREEN
            ]
        );
        assert_eq!(colors.color(7, 7), Rgb565::RED);
        assert_eq!(Colors::<Rgb565>::new(&[]), None);
    }
}
