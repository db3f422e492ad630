//! A square grid of heights drawn as a landscape seen from above: banded by height (water,
//! sand, grass, rock, snow) and hill-shaded, lit from the upper left. Midpoint
//! displacement's landscapes and noise's height fields are drawn the same way.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError};
use crate::math::Real;

/// Height bands, from the lowest level (of 256) each starts at: deep water, shallow
/// water, sand, grass, rock, snow.
const BANDS: [(u32, Rgb888); 6] = [
    (0, Rgb888::new(0x10, 0x30, 0x80)),
    (80, Rgb888::new(0x30, 0x70, 0xC0)),
    (100, Rgb888::new(0xD8, 0xC8, 0x88)),
    (110, Rgb888::new(0x40, 0x90, 0x38)),
    (180, Rgb888::new(0x80, 0x70, 0x60)),
    (225, Rgb888::new(0xF4, 0xF4, 0xF8)),
];
/// Levels below this are water: flat, not hill-shaded.
const SEA_LEVEL: u32 = 100;

/// A square grid of heights (Q16.16, row by row) stretched over an area: an
/// embedded-graphics [`Drawable`] sent as one `fill_contiguous`, row by row.
///
/// A pixel reads the grid bilinearly; its height, against the grid's lowest and highest,
/// picks a band; above the sea the slope towards the upper left lights it (up to 1.4) or
/// shades it (down to 0.5).
#[derive(Debug)]
pub struct Relief<'a, C> {
    heights: &'a [i32],
    n: usize,
    area: Rectangle,
    range: (i32, i32),
    color: core::marker::PhantomData<C>,
}

impl<'a, C> Relief<'a, C>
where
    C: PixelColor + From<Rgb888>,
{
    /// The first `side`² of `heights` over `area`. Refuses an empty area, a side below 2
    /// and a buffer shorter than `side`².
    pub fn new(heights: &'a [i32], side: u32, area: Rectangle) -> Result<Self, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let cells = side as usize * side as usize;
        let heights = match heights.get(..cells) {
            Some(heights) if side >= 2 => heights,
            _ => {
                return Err(Error::Fit(FitError::BufferTooSmall {
                    needed: cells.max(4),
                    given: heights.len(),
                }))
            }
        };
        let mut range = (i32::MAX, i32::MIN);
        for &h in heights {
            range = (range.0.min(h), range.1.max(h));
        }
        Ok(Self {
            heights,
            n: side as usize,
            area,
            range,
            color: core::marker::PhantomData,
        })
    }

    /// The lowest and highest heights.
    pub fn range(&self) -> (Real, Real) {
        let real = |h: i32| Real::from_bits(i64::from(h) << 16);
        (real(self.range.0), real(self.range.1))
    }

    /// The heights drawn (`side`²).
    pub fn cells(&self) -> usize {
        self.heights.len()
    }

    fn height(&self, x: usize, y: usize) -> i64 {
        let (x, y) = (x.min(self.n - 1), y.min(self.n - 1));
        i64::from(self.heights.get(y * self.n + x).copied().unwrap_or(0))
    }

    /// The colour of pixel (px, py) of the area: the grid read bilinearly, banded by
    /// height, lit by the slope towards the upper left. The rule, pixel by pixel, with its
    /// divisions: [`Rows`] draws the same colours by stepping.
    #[cfg(test)]
    fn color_at(&self, px: u32, py: u32) -> C {
        let last = (self.n - 1) as i64;
        let (w, h) = (
            i64::from(self.area.size.width.max(2) - 1),
            i64::from(self.area.size.height.max(2) - 1),
        );
        // Grid position in Q8.
        let gx = i64::from(px) * last * 256 / w;
        let gy = i64::from(py) * last * 256 / h;
        let (x, y, fx, fy) = ((gx >> 8) as usize, (gy >> 8) as usize, gx & 255, gy & 255);
        let top = self.height(x, y) * (256 - fx) + self.height(x + 1, y) * fx;
        let bottom = self.height(x, y + 1) * (256 - fx) + self.height(x + 1, y + 1) * fx;
        let height = (top * (256 - fy) + bottom * fy) >> 16;
        let (low, high) = (i64::from(self.range.0), i64::from(self.range.1));
        let spread = (high - low).max(1);
        let level = ((height - low) * 255 / spread).clamp(0, 255) as u32;
        let band = BANDS
            .iter()
            .rev()
            .find(|(start, _)| level >= *start)
            .map_or(Rgb888::BLACK, |(_, color)| *color);
        if level < SEA_LEVEL {
            return C::from(band);
        }
        // The slope down to the lower right, against the landscape's spread: a face to
        // the upper left is lit (up to 1.4), one away from it shaded (down to 0.5).
        let slope = (self.height(x.saturating_sub(1), y.saturating_sub(1))
            - self.height(x + 1, y + 1))
            * 256
            * last
            / spread;
        let light = (256 - slope / 8).clamp(128, 358);
        let lit = |c: u8| ((i64::from(c) * light) >> 8).clamp(0, 255) as u8;
        C::from(Rgb888::new(lit(band.r()), lit(band.g()), lit(band.b())))
    }
}

impl<C> Dimensions for Relief<'_, C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C> Drawable for Relief<'_, C>
where
    C: PixelColor + From<Rgb888>,
{
    type Color = C;
    type Output = u64;

    /// Returns the heights drawn.
    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        target.fill_contiguous(&self.area, Rows::new(self))?;
        Ok(self.heights.len() as u64)
    }
}

/// The colours of a relief's pixels, row by row, as [`Relief::color_at`] gives them, with
/// no division a pixel: the grid column stepped by a whole and a remainder, the bands
/// compared as heights scaled by 255 against each band's start times the spread, and the
/// light (which depends on the grid cell only) computed once a cell.
struct Rows<'r, 'a, C> {
    relief: &'r Relief<'a, C>,
    /// Pixels across and down.
    size: (u32, u32),
    /// The next pixel.
    px: u32,
    py: u32,
    /// Grid rows above and below, and the weight of the one below (Q8), for row `py`.
    row: (usize, i64),
    /// The grid column position (Q8) of pixel `px`, and the remainder of its division.
    gx: (i64, i64),
    /// Each pixel's step of the grid column position: a whole and a remainder over `wm`.
    step: (i64, i64),
    /// Pixels across less one (at least 1), the grid's last index.
    wm: i64,
    last: i64,
    /// The spread of heights (at least 1).
    spread: i64,
    /// Each band's start times the spread, and the sea level's: what a height less the
    /// lowest, times 255, is compared with.
    starts: [i64; BANDS.len()],
    sea: i64,
    /// The cell whose corners and light are known: its column, its corners (top left, top
    /// right, bottom left, bottom right) and its light (Q8).
    cell: Option<(usize, [i64; 4], i64)>,
    /// The last colour made, with its band and light.
    made: Option<(usize, i64, C)>,
}

impl<'r, 'a, C> Rows<'r, 'a, C> {
    fn new(relief: &'r Relief<'a, C>) -> Self {
        let (w, h) = (relief.area.size.width, relief.area.size.height);
        let last = (relief.n - 1) as i64;
        let wm = i64::from(w.max(2) - 1);
        let spread = (i64::from(relief.range.1) - i64::from(relief.range.0)).max(1);
        let mut rows = Self {
            relief,
            size: (w, h),
            px: 0,
            py: 0,
            row: (0, 0),
            gx: (0, 0),
            step: (last * 256 / wm, last * 256 % wm),
            wm,
            last,
            spread,
            starts: BANDS.map(|(start, _)| i64::from(start) * spread),
            sea: i64::from(SEA_LEVEL) * spread,
            cell: None,
            made: None,
        };
        rows.start_row();
        rows
    }

    /// Sets up row `py`: its grid rows, and the column position back to 0.
    fn start_row(&mut self) {
        let hm = i64::from(self.size.1.max(2) - 1);
        let gy = i64::from(self.py) * self.last * 256 / hm;
        self.row = ((gy >> 8) as usize, gy & 255);
        self.gx = (0, 0);
        self.cell = None;
    }
}

impl<C> Iterator for Rows<'_, '_, C>
where
    C: PixelColor + From<Rgb888>,
{
    type Item = C;

    fn next(&mut self) -> Option<C> {
        if self.py >= self.size.1 || self.size.0 == 0 {
            return None;
        }
        let relief = self.relief;
        let (x, fx) = ((self.gx.0 >> 8) as usize, self.gx.0 & 255);
        let (y, fy) = self.row;
        let (corners, light) = match self.cell {
            Some((column, corners, light)) if column == x => (corners, light),
            _ => {
                let corners = [
                    relief.height(x, y),
                    relief.height(x + 1, y),
                    relief.height(x, y + 1),
                    relief.height(x + 1, y + 1),
                ];
                // The light depends on the cell only (used above the sea).
                let slope = (relief.height(x.saturating_sub(1), y.saturating_sub(1)) - corners[3])
                    * 256
                    * self.last
                    / self.spread;
                let light = (256 - slope / 8).clamp(128, 358);
                self.cell = Some((x, corners, light));
                (corners, light)
            }
        };
        let [a, b, c, d] = corners;
        let top = a * (256 - fx) + b * fx;
        let bottom = c * (256 - fx) + d * fx;
        let height = (top * (256 - fy) + bottom * fy) >> 16;
        // level ≥ start ⟺ ⌊(height − low)·255 / spread⌋ ≥ start ⟺ (height − low)·255 ≥
        // start·spread; the first band takes every level (clamped at 0).
        let scaled = (height - i64::from(relief.range.0)) * 255;
        let band = self
            .starts
            .iter()
            .rposition(|&start| scaled >= start)
            .unwrap_or(0);
        let light = if scaled < self.sea { 256 } else { light };
        let color = match self.made {
            Some((made_band, made_light, color)) if made_band == band && made_light == light => {
                color
            }
            _ => {
                let color = BANDS.get(band).map_or(Rgb888::BLACK, |(_, color)| *color);
                let lit = |c: u8| ((i64::from(c) * light) >> 8).clamp(0, 255) as u8;
                let color = C::from(Rgb888::new(lit(color.r()), lit(color.g()), lit(color.b())));
                self.made = Some((band, light, color));
                color
            }
        };
        // On to the next pixel: the column position by its step, exactly
        // ⌊px·last·256 / wm⌋.
        self.px += 1;
        self.gx = (self.gx.0 + self.step.0, self.gx.1 + self.step.1);
        if self.gx.1 >= self.wm {
            self.gx = (self.gx.0 + 1, self.gx.1 - self.wm);
        }
        if self.px == self.size.0 {
            self.px = 0;
            self.py += 1;
            self.start_row();
        }
        Some(color)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::Rgb888;

    /// Stepping draws the rule's colours, pixel by pixel, on grids of every shape of
    /// height (flat, a ramp, a peak, noise) at sizes wider, narrower and equal to the grid.
    #[test]
    fn rows_are_the_rules_colours() {
        let mut state = 0x1234_5678u32;
        let mut random = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state
        };
        for side in [2usize, 3, 5, 9, 17, 33] {
            let grids: [&dyn Fn(usize, usize) -> i32; 4] = [
                &|_, _| 7 << 16,
                &|x, y| ((x + 2 * y) as i32) << 14,
                &|x, y| -(((x as i32 - 4).pow(2) + (y as i32 - 4).pow(2)) << 12),
                &|_, _| 0,
            ];
            for (g, grid) in grids.iter().enumerate() {
                let mut heights = [0i32; 33 * 33];
                for y in 0..side {
                    for x in 0..side {
                        heights[y * side + x] = if g == 3 {
                            (random() >> 4) as i32 - (1 << 27)
                        } else {
                            grid(x, y)
                        };
                    }
                }
                for (w, h) in [
                    (1, 1),
                    (2, 2),
                    (7, 5),
                    (33, 33),
                    (64, 48),
                    (128, 64),
                    (13, 97),
                ] {
                    let area = Rectangle::new(Point::new(3, 1), Size::new(w, h));
                    let relief = Relief::<Rgb888>::new(&heights, side as u32, area).unwrap();
                    let rule = (0..h).flat_map(|y| (0..w).map(move |x| (x, y)));
                    let mut rows = Rows::new(&relief);
                    for (x, y) in rule {
                        assert_eq!(
                            rows.next(),
                            Some(relief.color_at(x, y)),
                            "{side} {g} {w}x{h} ({x}, {y})"
                        );
                    }
                    assert_eq!(rows.next(), None);
                }
            }
        }
    }
}
