//! A texture fitted to an area: drawn a block of columns at a time where its octaves
//! double, a row at a time otherwise.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::fractal::OUT_OF_RANGE;
use super::fractal::{Ladder, Octaves, Sum, MAX_OCTAVES};
use super::lattice::LatticeSteps;
use super::level::{level_of, SumLevels};
use super::perlin::RowPart;
use super::plane::{ColumnBlock, RowSums, BLOCK_COLUMNS};
use super::texture::{normaliser, NoiseTexture};
use crate::error::{Error, FitError, ParameterError};
use crate::math::Real;
use crate::render::palette::Palette;

impl<'a> NoiseTexture<'a> {
    /// The texture fitted to `area` with `palette`: level `l` is drawn as
    /// `palette.color(l, u16::MAX)`. Refuses octaves out of range, a scale that is not
    /// positive, and a picture whose finest octave would leave `Real`'s range (so that
    /// drawing cannot fail).
    pub fn fit<P: Palette>(
        &self,
        area: Rectangle,
        palette: P,
    ) -> Result<NoiseDrawing<'a, P>, Error> {
        let ladder = self.octaves.ladder()?;
        if self.scale <= Real::ZERO {
            return Err(Error::Parameter(ParameterError::ScaleNotPositive {
                scale: self.scale,
            }));
        }
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        // The farthest corner, times the finest octave's frequency, must stay in range.
        let size = area.size;
        let (x, y, z) = self.point((size.width, size.height), size.width);
        let reach = x.max(y).max(z.map_or(Real::ZERO, Real::abs));
        let finest = ladder.finest(reach).ok_or(OUT_OF_RANGE)?;
        // Marble adds the turbulence (at most Σaⁱ ≤ 16) to x.
        finest.checked_add(Real::from_int(16)).ok_or(OUT_OF_RANGE)?;
        let normaliser = normaliser(&ladder)?;
        Ok(NoiseDrawing::new(
            self.clone(),
            normaliser,
            ladder,
            area,
            palette,
        ))
    }
}

/// A texture fitted to an area with a palette: an embedded-graphics [`Drawable`].
///
/// Where its octaves double (fBm, clouds, turbulence and marble at lacunarity 2, and
/// Perlin's and wood's single sample), in the plane or at a depth, it is drawn a block of
/// 32 columns at a time, one `fill_contiguous` a block: each column's x half of every
/// octave is computed once for the block's height, which takes 5 KiB of stack while
/// drawing (16 octaves × 32 columns × 9 bytes, and a 512-byte table of the noise's
/// gradients). Otherwise (ridged, other lacunarities) it
/// is drawn a row at a time. Both give every pixel the value [`value_at`](Self::value_at)
/// gives.
#[derive(Debug, Clone)]
pub struct NoiseDrawing<'a, P> {
    texture: NoiseTexture<'a>,
    /// 1/Σaⁱ, once for every pixel.
    normaliser: Real,
    /// The octaves' amplitudes, once for every pixel.
    ladder: Ladder,
    area: Rectangle,
    palette: P,
}

impl<'a, P> NoiseDrawing<'a, P> {
    /// `texture` fitted to `area` (its checks done), with its octaves' `ladder` and
    /// `normaliser`.
    pub(super) fn new(
        texture: NoiseTexture<'a>,
        normaliser: Real,
        ladder: Ladder,
        area: Rectangle,
        palette: P,
    ) -> Self {
        Self {
            texture,
            normaliser,
            ladder,
            area,
            palette,
        }
    }

    /// The level of pixel (`x`, `y`) of the area, 0 to 255.
    pub fn level_at(&self, x: u32, y: u32) -> u8 {
        level_of(self.value_at(x, y))
    }

    /// The value of pixel (`x`, `y`) of the area, in [0, 1] (what its level rounds).
    pub fn value_at(&self, x: u32, y: u32) -> Real {
        let point = self.texture.point((x, y), self.area.size.width);
        let texture = &self.texture;
        // `fit` checked every point's range: a sample cannot fail here.
        texture
            .texture
            .value_normalised(texture.noise, &self.ladder, point, self.normaliser)
            .unwrap_or(Real::ZERO)
    }

    /// How this texture's octaves are summed a block of columns at a time (the octaves,
    /// and whether of |noise|), where they can be: octaves that double or a single sample,
    /// in the plane or at one depth, and not the ridged multifractal (whose octaves weight
    /// each other).
    fn blocks(&self) -> Option<(Ladder, bool)> {
        match self.texture.texture.source() {
            None => {
                let one = Octaves {
                    octaves: 1,
                    ..Octaves::default()
                };
                Some((one.ladder().ok()?, false))
            }
            Some(Sum::Ridged) => None,
            Some(sum) => self
                .ladder
                .doubles()
                .then_some((self.ladder, sum == Sum::Turbulence)),
        }
    }

    /// The points of row `y`'s pixels, left to right: the same as
    /// [`NoiseTexture::point`] gives, ⌊scale·x/width⌋ in 2⁻³², stepped by quotient and
    /// remainder instead of dividing at every pixel.
    fn row_points(&self, y: u32) -> impl Iterator<Item = (Real, Real, Option<Real>)> + '_ {
        let width = self.area.size.width;
        let (_, row, z) = self.texture.point((0, y), width);
        let xs = LatticeSteps::new(self.texture.scale, width).take(width as usize);
        xs.map(move |x| (x, row, z))
    }
}

impl<P> Dimensions for NoiseDrawing<'_, P> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<P: Palette> Drawable for NoiseDrawing<'_, P> {
    type Color = P::Color;
    type Output = ();

    fn draw<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Self::Color>,
    {
        match self.blocks() {
            Some((ladder, turbulence)) => self.draw_blocks(target, &ladder, turbulence),
            None => self.draw_rows(target),
        }
    }
}

impl<P: Palette> NoiseDrawing<'_, P> {
    /// Draws a row at a time, each pixel's value from its point.
    fn draw_rows<D>(&self, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let width = self.area.size.width;
        for y in 0..self.area.size.height {
            // Wrapping, not counting on: a row past `i32::MAX` is off every target anyway.
            let top = self.area.top_left.y.wrapping_add_unsigned(y);
            let texture = &self.texture;
            let colors = self.row_points(y).map(|point| {
                // `fit` checked every point's range: a sample cannot fail here.
                let value = texture
                    .texture
                    .value_normalised(texture.noise, &self.ladder, point, self.normaliser)
                    .unwrap_or(Real::ZERO);
                self.palette.color(u16::from(level_of(value)), u16::MAX)
            });
            let line = Rectangle::new(Point::new(self.area.top_left.x, top), Size::new(width, 1));
            target.fill_contiguous(&line, colors)?;
        }
        Ok(())
    }

    /// Draws a block of [`BLOCK_COLUMNS`] columns at a time, as one `fill_contiguous` a
    /// block: the columns' x parts of every octave once a block, the rows' y parts once a
    /// row of it, the same values as [`draw_rows`](Self::draw_rows).
    fn draw_blocks<D>(
        &self,
        target: &mut D,
        ladder: &Ladder,
        turbulence: bool,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let Size { width, height } = self.area.size;
        // At a depth: each octave's part of it, once for the picture (`fit` checked its
        // range).
        let mut layers = [RowPart::default(); MAX_OCTAVES as usize];
        let layers = match self.texture.z {
            Some(z) => ladder.rows_into(z, &mut layers).map(|()| &layers),
            None => None,
        };
        // A sum's level by one product where the texture is its sum's value alone and the
        // normaliser is below 1 (otherwise through the texture's checked steps): its
        // factors once for the picture.
        let below_one = u32::try_from(self.normaliser.to_bits()).ok();
        let by_sum = match (self.texture.texture.sum_centring(), below_one) {
            (Some(centred), Some(normaliser)) => Some(SumLevels::new(normaliser, centred)),
            _ => None,
        };
        let mut xs = self.row_points(0).map(|(x, _, _)| x);
        let mut block = ColumnBlock::EMPTY;
        block.set_noise(self.texture.noise);
        let mut left = 0;
        while left < width {
            let mut columns = [Real::ZERO; BLOCK_COLUMNS];
            let mut count = 0;
            for (slot, x) in columns.iter_mut().zip(&mut xs) {
                *slot = x;
                count += 1;
            }
            let columns = columns.get(..count).unwrap_or(&[]);
            block.fill(ladder, columns);
            let colors = BlockColors {
                drawing: self,
                block: &block,
                ladder,
                turbulence,
                by_sum,
                layers,
                columns,
                rows: [RowPart::default(); MAX_OCTAVES as usize],
                sums: RowSums::ZERO,
                colors: [self.palette.color(0, u16::MAX); BLOCK_COLUMNS],
                row: 0,
                ys: LatticeSteps::new(self.texture.scale, width),
                column: columns.len(),
            };
            let top_left = self.area.top_left + Point::new(left as i32, 0);
            let size = Size::new(count as u32, height);
            target.fill_contiguous(&Rectangle::new(top_left, size), colors)?;
            left += count as u32;
        }
        Ok(())
    }
}

/// The colours of a block of columns' pixels, row by row: each row's sums at once (the
/// block's sums), then its pixels' colours one at a time.
struct BlockColors<'d, 'a, P: Palette> {
    drawing: &'d NoiseDrawing<'a, P>,
    block: &'d ColumnBlock,
    ladder: &'d Ladder,
    turbulence: bool,
    /// The levels by one product of each sum, where they are taken so.
    by_sum: Option<SumLevels>,
    /// Each octave's part of the depth, in 3D.
    layers: Option<&'d [RowPart; MAX_OCTAVES as usize]>,
    /// The block's columns' x.
    columns: &'d [Real],
    /// The current row's part of each octave.
    rows: [RowPart; MAX_OCTAVES as usize],
    /// The current row's sums of octaves, a column each (kept here: a row's sums are
    /// written in place, not built and moved).
    sums: RowSums,
    /// The current row's colours, a column each.
    colors: [P::Color; BLOCK_COLUMNS],
    /// The next row.
    row: u32,
    /// The rows' y, from the next row's on.
    ys: LatticeSteps,
    /// The next column of the current row.
    column: usize,
}

impl<P: Palette> Iterator for BlockColors<'_, '_, P> {
    type Item = P::Color;

    #[inline]
    fn next(&mut self) -> Option<P::Color> {
        if self.column >= self.columns.len() && !self.next_row() {
            return None;
        }
        // Below BLOCK_COLUMNS (the columns are at most that many): no bound to check.
        let color = self.colors.get(self.column % BLOCK_COLUMNS).copied();
        self.column += 1;
        color
    }
}

impl<P: Palette> BlockColors<'_, '_, P> {
    /// Sums the next row's columns and takes their colours; `false` past the last row.
    /// Once a row of the block, so out of line from the pixels' path.
    #[inline(never)]
    fn next_row(&mut self) -> bool {
        let drawing = self.drawing;
        let texture = &drawing.texture;
        if self.row >= drawing.area.size.height || self.columns.is_empty() {
            return false;
        }
        // `fit` checked every point's range: the rows cannot leave it.
        let y = self.ys.next().unwrap_or(Real::ZERO);
        if self.ladder.rows_into(y, &mut self.rows).is_none() {
            return false;
        }
        let (noise, turbulence) = (texture.noise, self.turbulence);
        let (block, ladder, rows) = (self.block, self.ladder, &self.rows);
        let sums = &mut self.sums;
        match self.layers {
            Some(layers) => block.sums_in_layer(noise, ladder, rows, layers, turbulence, sums),
            None => block.sums(noise, ladder, rows, turbulence, sums),
        }
        let (colors, columns, normaliser) = (&mut self.colors, self.columns, drawing.normaliser);
        let color = |level: u8| drawing.palette.color(u16::from(level), u16::MAX);
        match self.by_sum {
            Some(by_sum) => {
                for (slot, sum) in colors.iter_mut().zip(sums.iter()) {
                    *slot = color(by_sum.level(sum));
                }
            }
            None => {
                for ((slot, sum), &x) in colors.iter_mut().zip(sums.iter()).zip(columns) {
                    let value = texture
                        .texture
                        .finish(Real::from_bits(sum), x, normaliser)
                        .unwrap_or(Real::ZERO);
                    *slot = color(level_of(value));
                }
            }
        }
        self.row += 1;
        self.column = 0;
        true
    }
}

#[cfg(test)]
mod tests {
    use embedded_graphics::pixelcolor::Gray8;

    use super::*;
    use crate::noise::{Perlin, Texture};
    use crate::render::palette::TwoColor;

    /// Stepping along a row by quotient and remainder gives the points dividing gives.
    #[test]
    fn row_points_are_the_divided_points() {
        let noise = Perlin::reference();
        let palette = TwoColor {
            inside: Gray8::BLACK,
            outside: Gray8::WHITE,
        };
        for (width, scale) in [
            (1, "1"),
            (7, "3.3"),
            (128, "4"),
            (333, "0.001"),
            (97, "1000.77"),
        ] {
            let texture = NoiseTexture::new(&noise, Texture::Fbm)
                .with_scale(Real::parse_decimal(scale).unwrap());
            let area = Rectangle::new(Point::zero(), Size::new(width, 3));
            let drawing = texture.fit(area, palette).unwrap();
            for y in 0..3 {
                let mut count = 0;
                for (x, stepped) in (0..).zip(drawing.row_points(y)) {
                    assert_eq!(stepped, texture.point((x, y), width), "{width} {scale} {x}");
                    count += 1;
                }
                assert_eq!(count, width);
            }
        }
    }
}
