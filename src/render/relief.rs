//! A square grid of heights drawn as a landscape seen from above: banded by height (water,
//! sand, grass, rock, snow) and hill-shaded, lit from the upper left. Midpoint
//! displacement's landscapes and noise's height fields are drawn the same way.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use crate::error::{Error, FitError};
use crate::math::wide::{mul_i32_by_small, mul_i64_by_small};
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

impl<C> Relief<'_, C> {
    /// The height at grid point (`x`, `y`), clamped to the grid.
    fn height(&self, x: usize, y: usize) -> i64 {
        i64::from(self.height32(x, y))
    }

    /// [`Relief::height`] as it is stored.
    fn height32(&self, x: usize, y: usize) -> i32 {
        let (x, y) = (x.min(self.n - 1), y.min(self.n - 1));
        self.heights.get(y * self.n + x).copied().unwrap_or(0)
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
/// no division a pixel.
///
/// The bilinear blend is regrouped exactly: for a cell of a row the grid's two columns are
/// blended down once, `L = a·(256 − fy) + c·fy` and `R = b·(256 − fy) + d·fy`, and a pixel's
/// height before the shift is `256·L + fx·(R − L)` (the same integer as the rule's). The
/// bands and the sea are compared there too, as thresholds on that numerator, so a pixel
/// is one product and a compare or two; the grid position steps by a whole and a
/// remainder, and the light (which depends on the cell only) is found once a cell,
/// without a division.
struct Rows<'r, 'a, C> {
    relief: &'r Relief<'a, C>,
    /// Pixels across and down.
    size: (u32, u32),
    /// The next pixel.
    px: u32,
    py: u32,
    /// Grid row above and the weight of the one below (Q8), for row `py`.
    y: usize,
    fy: i32,
    /// The grid column of pixel `px`, its fraction (Q8) and the remainder of the division
    /// that gives them.
    x: usize,
    fx: u32,
    remainder: u32,
    /// Each pixel's step of the grid position: whole columns, a fraction (Q8), and a
    /// remainder over `wm`.
    step: (usize, u32, u32),
    /// Pixels across less one (at least 1).
    wm: u32,
    /// The grid's last index.
    last: i64,
    /// Eight times the spread of heights, the light's divisor.
    divisor: CappedDivisor,
    /// The least blend numerator (height times 2¹⁶) of each band, and of the land above
    /// the sea.
    starts: [i64; BANDS.len()],
    sea: i64,
    /// The cell whose blend and light are known: its column (`usize::MAX` for none),
    /// `256·L`, `R − L`, and its light (Q8).
    column: usize,
    base: i64,
    rise: i64,
    light: i32,
    /// The cell's right column blended down (`R`): the next cell's left one.
    right: i64,
    /// The band of the last pixel (the next one is most likely in it too).
    band: usize,
    /// The last colour made, with its band and light.
    made: (usize, i32, C),
}

/// The least blend numerator `n` whose height `⌊n / 2¹⁶⌋` is at level `start` or above:
/// `(height − low)·255 ≥ start·spread ⟺ height ≥ low + ⌈start·spread / 255⌉`.
fn least_numerator(low: i64, spread: i64, start: u32) -> i64 {
    let above = (i64::from(start) * spread + 254) / 255;
    (low + above) << 16
}

/// The most a light divides out: 128 steps of 1/256 (the light's clamp needs no more).
const LIGHT_STEPS: u32 = 128;

/// Division by one divisor, many times, capped at [`LIGHT_STEPS`]: by a multiply with its
/// reciprocal and one correction, as compilers divide by a constant.
#[derive(Debug, Clone, Copy)]
struct CappedDivisor {
    divisor: u64,
    /// ⌊2⁵⁶ / divisor⌋ + 1 (at least 2⁵⁶ / divisor, short of it by less than 1), or 0 for
    /// a divisor of 2⁴⁸ or more (divided the slow way).
    inverse: u64,
}

impl CappedDivisor {
    /// Division by `divisor` (0 is taken as 1).
    fn new(divisor: u64) -> Self {
        let divisor = divisor.max(1);
        let inverse = if divisor < 1 << 48 {
            (1 << 56) / divisor + 1
        } else {
            0
        };
        Self { divisor, inverse }
    }

    /// ⌊`n` / divisor⌋, or [`LIGHT_STEPS`] where it is that or more.
    ///
    /// Below the cap `n` < 128·divisor, so `n`·inverse < 2⁶³ + 2⁵⁵ stays in 64 bits and
    /// exceeds `n`·2⁵⁶ / divisor by less than 128·divisor / 2⁵⁶ ≤ ½: the estimate is the
    /// quotient or one more.
    fn capped(&self, n: u64) -> u32 {
        let d = self.divisor;
        if self.inverse == 0 {
            return (n / d).min(u64::from(LIGHT_STEPS)) as u32;
        }
        if n >= d * u64::from(LIGHT_STEPS) {
            return LIGHT_STEPS;
        }
        let estimate = (n * self.inverse) >> 56;
        (estimate - u64::from(estimate * d > n)) as u32
    }
}

/// A band's colour in `light` (Q8).
fn lit_band<C: From<Rgb888>>(band: usize, light: i32) -> C {
    let color = BANDS.get(band).map_or(Rgb888::BLACK, |(_, color)| *color);
    let lit = |c: u8| ((i32::from(c) * light) >> 8).clamp(0, 255) as u8;
    C::from(Rgb888::new(lit(color.r()), lit(color.g()), lit(color.b())))
}

impl<'r, 'a, C: From<Rgb888>> Rows<'r, 'a, C> {
    fn new(relief: &'r Relief<'a, C>) -> Self {
        let (w, h) = (relief.area.size.width, relief.area.size.height);
        let last = (relief.n - 1) as i64;
        let wm = w.max(2) - 1;
        let low = i64::from(relief.range.0);
        let spread = (i64::from(relief.range.1) - low).max(1);
        let step = last * 256 / i64::from(wm);
        let mut rows = Self {
            relief,
            size: (w, h),
            px: 0,
            py: 0,
            y: 0,
            fy: 0,
            x: 0,
            fx: 0,
            remainder: 0,
            step: (
                (step >> 8) as usize,
                (step & 255) as u32,
                (last * 256 % i64::from(wm)) as u32,
            ),
            wm,
            last,
            divisor: CappedDivisor::new(8 * spread.unsigned_abs()),
            starts: BANDS.map(|(start, _)| least_numerator(low, spread, start)),
            sea: least_numerator(low, spread, SEA_LEVEL),
            column: usize::MAX,
            base: 0,
            rise: 0,
            light: 256,
            right: 0,
            band: 0,
            made: (0, 256, lit_band(0, 256)),
        };
        rows.start_row();
        rows
    }

    /// Sets up row `py`: its grid rows, and the column position back to 0.
    fn start_row(&mut self) {
        let hm = i64::from(self.size.1.max(2) - 1);
        let gy = i64::from(self.py) * self.last * 256 / hm;
        (self.y, self.fy) = ((gy >> 8) as usize, (gy & 255) as i32);
        (self.x, self.fx, self.remainder) = (0, 0, 0);
        self.column = usize::MAX;
    }

    /// Sets up the cell of column `x` in the current row: its blend and its light.
    #[inline(never)]
    fn enter_cell(&mut self, x: usize) {
        let relief = self.relief;
        let (y, fy) = (self.y, self.fy);
        // The column on the left is the last cell's right one where the pixels moved on
        // by one cell.
        // A height times a weight of at most 256: 32-bit factors, from halves on ARMv6-M.
        let blend = |above: i32, below: i32| {
            mul_i32_by_small(above, 256 - fy) + mul_i32_by_small(below, fy)
        };
        let left = if self.column != usize::MAX && self.column + 1 == x {
            self.right
        } else {
            blend(relief.height32(x, y), relief.height32(x, y + 1))
        };
        let d = relief.height(x + 1, y + 1);
        let right = blend(relief.height32(x + 1, y), d as i32);
        self.right = right;
        // The light, used above the sea: 256 − slope/8 within 128..=358, where the slope
        // is ⌊(corner above left − d)·256·last / spread⌋ towards zero; the two divisions
        // towards zero are one by 8·spread, and the clamp needs at most 128 of it.
        let rise = (relief.height(x.saturating_sub(1), y.saturating_sub(1)) - d) * 256 * self.last;
        let steps = self.divisor.capped(rise.unsigned_abs()) as i32;
        self.light = if rise < 0 {
            (256 + steps).min(358)
        } else {
            (256 - steps).max(128)
        };
        (self.column, self.base, self.rise) = (x, left << 8, right - left);
    }

    /// The band of blend numerator `n`: the last whose least numerator it reaches (the
    /// first band takes every height), looked for from the last pixel's.
    #[inline]
    fn band_of(&mut self, n: i64) -> usize {
        let band = self.band;
        let reached = |band: usize| self.starts.get(band).is_some_and(|&start| n >= start);
        if (band == 0 || reached(band)) && !reached(band + 1) {
            return band;
        }
        let band = self
            .starts
            .iter()
            .rposition(|&start| n >= start)
            .unwrap_or(0);
        self.band = band;
        band
    }
}

impl<C> Iterator for Rows<'_, '_, C>
where
    C: PixelColor + From<Rgb888>,
{
    type Item = C;

    #[inline(always)]
    fn next(&mut self) -> Option<C> {
        if self.py >= self.size.1 || self.size.0 == 0 {
            return None;
        }
        if self.column != self.x {
            self.enter_cell(self.x);
        }
        // The rise of two blends (each within ±2³⁹) is within ±2⁴⁰, fx below 256.
        let numerator = self.base + mul_i64_by_small(self.rise, self.fx);
        let band = self.band_of(numerator);
        let light = if numerator < self.sea {
            256
        } else {
            self.light
        };
        let (made_band, made_light, made) = self.made;
        let color = if made_band == band && made_light == light {
            made
        } else {
            let color = lit_band(band, light);
            self.made = (band, light, color);
            color
        };
        // On to the next pixel: the grid position by its step, exactly
        // ⌊px·last·256 / wm⌋ (whole columns, fraction).
        self.px += 1;
        let (whole, fraction, remainder) = self.step;
        self.remainder += remainder;
        let mut fx = self.fx + fraction;
        if self.remainder >= self.wm {
            self.remainder -= self.wm;
            fx += 1;
        }
        self.x += whole + (fx >> 8) as usize;
        self.fx = fx & 255;
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

    /// The capped quotient is the division's, capped, for divisors of every size and
    /// numerators at and beside whole multiples.
    #[test]
    fn capped_quotients_are_divisions() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..100_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let d = (state >> (state % 64)).max(1);
            let divisor = CappedDivisor::new(d);
            for n in [
                (state.rotate_left(23) >> (state % 13)) % d.saturating_mul(200),
                d.saturating_mul(state % 130),
                d.saturating_mul(state % 130).saturating_sub(1),
            ] {
                assert_eq!(divisor.capped(n), (n / d).min(128) as u32, "{n} {d}");
            }
        }
        for d in [1, 7, (1 << 48) - 1, 1 << 48] {
            let n = d * 128 - 1;
            assert_eq!(CappedDivisor::new(d).capped(n), 127, "{d}");
        }
    }

    /// Stepping draws the rule's colours, pixel by pixel, on grids of every shape of
    /// height (flat, a ramp, a peak, noise, and noise over the whole of i32, where the
    /// blends reach 2³⁹) at sizes wider, narrower and equal to the grid.
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
            let grids: [&dyn Fn(usize, usize) -> i32; 5] = [
                &|_, _| 7 << 16,
                &|x, y| ((x + 2 * y) as i32) << 14,
                &|x, y| -(((x as i32 - 4).pow(2) + (y as i32 - 4).pow(2)) << 12),
                &|_, _| 0,
                &|_, _| 0,
            ];
            for (g, grid) in grids.iter().enumerate() {
                let mut heights = [0i32; 33 * 33];
                for y in 0..side {
                    for x in 0..side {
                        heights[y * side + x] = match g {
                            3 => (random() >> 4) as i32 - (1 << 27),
                            4 => random() as i32,
                            _ => grid(x, y),
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
