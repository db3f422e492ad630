//! Perlin's textures: noise and its sums turned into a level of a palette, and drawn.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::fractal::{Ladder, Octaves, RowSums, Sum};
use super::perlin::Perlin;
use crate::error::{Error, FitError, ParameterError};
use crate::math::trig::BinaryAngle;
use crate::math::{Overflow, Real};
use crate::render::palette::Palette;

/// Levels a texture takes, 0 to 255: a palette of 256 entries shows each one.
pub const LEVELS: u16 = 256;

/// How a texture turns noise into a value in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Texture {
    /// One octave: (noise + 1) / 2.
    Perlin,
    /// Fractional Brownian motion: (fBm / Σaⁱ + 1) / 2.
    Fbm,
    /// Turbulence: Σaⁱ·|noise| / Σaⁱ.
    Turbulence,
    /// Musgrave's ridged multifractal, over Σaⁱ.
    Ridged,
    /// fBm as the sky: the same values as [`Fbm`](Self::Fbm), for a sky palette.
    Clouds,
    /// Perlin's marble: (1 + sin 2π(x + turbulence / 4)) / 2, veins along y bent by
    /// turbulence.
    Marble,
    /// Perlin's wood: the fraction of 8·(noise + 1), rings of grain.
    Wood,
}

impl Texture {
    /// The texture's value at `point` (2D where z is `None`), in [0, 1]. A sum is
    /// normalised by 1/Σaⁱ rounded to 2⁻³², the same for every point.
    pub fn value(
        self,
        noise: &Perlin,
        octaves: &Octaves,
        point: (Real, Real, Option<Real>),
    ) -> Result<Real, Error> {
        let ladder = octaves.ladder()?;
        self.value_normalised(noise, &RowSums::any(&ladder), point, normaliser(&ladder)?)
    }

    /// [`value`](Self::value) with the sums' normaliser given, so that a drawing computes
    /// it once rather than a division a pixel.
    fn value_normalised(
        self,
        noise: &Perlin,
        octaves: &RowSums<'_>,
        point: (Real, Real, Option<Real>),
        normaliser: Real,
    ) -> Result<Real, Error> {
        let half = Real::from_bits(1 << (Real::FRAC_BITS - 1));
        let sample = || noise.sample(point);
        let sum = |sum: Sum| -> Result<Real, Error> {
            let total = octaves.sum(noise, sum, point)?;
            total.checked_mul(normaliser).ok_or(Error::from(Overflow))
        };
        let unit = |value: Real| value.clamp(Real::ZERO, Real::ONE);
        let centred = |value: Real| -> Result<Real, Error> {
            let shifted = value.checked_add(Real::ONE).ok_or(Overflow)?;
            Ok(unit(shifted.checked_mul(half).ok_or(Overflow)?))
        };
        match self {
            Self::Perlin => centred(sample().to_real()),
            Self::Fbm | Self::Clouds => centred(sum(Sum::Fbm)?),
            Self::Turbulence => Ok(unit(sum(Sum::Turbulence)?)),
            Self::Ridged => Ok(unit(sum(Sum::Ridged)?)),
            Self::Marble => {
                let turbulence = octaves.sum(noise, Sum::Turbulence, point)?;
                // Turns of the sine: its fraction is a binary angle. A quarter of the
                // turbulence bends the veins about as much as Perlin's radians do.
                let bend = Real::from_bits(turbulence.to_bits() >> 2);
                let turns = point.0.checked_add(bend).ok_or(Overflow)?;
                let angle = BinaryAngle(turns.to_bits() as u32);
                let (_, sin) = angle.cos_sin();
                // sin in 2⁻³⁰: (1 + sin) / 2 in 2⁻³¹, to 2⁻³².
                let level = ((1_i64 << 30) + i64::from(sin)) << 1;
                Ok(unit(Real::from_bits(level)))
            }
            Self::Wood => {
                let grain = sample()
                    .to_real()
                    .checked_add(Real::ONE)
                    .and_then(|value| value.checked_mul(Real::from_int(8)))
                    .ok_or(Overflow)?;
                Ok(Real::from_bits(
                    grain.to_bits() & ((1 << Real::FRAC_BITS) - 1),
                ))
            }
        }
    }

    /// The texture's level at `point`, 0 to 255: its value times 255, rounded.
    pub fn level(
        self,
        noise: &Perlin,
        octaves: &Octaves,
        point: (Real, Real, Option<Real>),
    ) -> Result<u8, Error> {
        let value = self.value(noise, octaves, point)?;
        Ok(level_of(value))
    }
}

/// A value in [0, 1] as a level 0 to 255, rounded to nearest (clamped first, so the
/// product fits 64 bits).
fn level_of(value: Real) -> u8 {
    let unit = value.clamp(Real::ZERO, Real::ONE).to_bits();
    let scaled = unit * i64::from(LEVELS - 1);
    ((scaled + (1 << (Real::FRAC_BITS - 1))) >> Real::FRAC_BITS) as u8
}

/// 1/Σaⁱ over the octaves, rounded to 2⁻³²: what a sum is multiplied by to stay within
/// [−1, 1].
fn normaliser(ladder: &Ladder) -> Result<Real, Error> {
    Real::ONE
        .checked_div(ladder.amplitude_total()?)
        .ok_or(Error::from(Overflow))
}

/// A texture over a picture: `scale` lattice cells across its width, at depth `z` (3D
/// noise) or in the plane.
#[derive(Debug, Clone)]
pub struct NoiseTexture<'a> {
    noise: &'a Perlin,
    texture: Texture,
    octaves: Octaves,
    scale: Real,
    z: Option<Real>,
}

impl<'a> NoiseTexture<'a> {
    /// `texture` of `noise`, four lattice cells across, in the plane, six octaves.
    pub fn new(noise: &'a Perlin, texture: Texture) -> Self {
        Self {
            noise,
            texture,
            octaves: Octaves::default(),
            scale: Real::from_int(4),
            z: None,
        }
    }

    /// The same with these octaves (for the sums, marble's turbulence).
    #[must_use]
    pub fn with_octaves(self, octaves: Octaves) -> Self {
        Self { octaves, ..self }
    }

    /// The same with `scale` lattice cells across the picture's width.
    #[must_use]
    pub fn with_scale(self, scale: Real) -> Self {
        Self { scale, ..self }
    }

    /// The same at depth `z` of 3D noise (an animation moves it).
    #[must_use]
    pub fn with_z(self, z: Real) -> Self {
        Self { z: Some(z), ..self }
    }

    /// The point pixel (`x`, `y`) of a picture of `width` pixels samples: its top-left
    /// corner, `scale / width` lattice units a pixel, y down.
    pub fn point(&self, (x, y): (u32, u32), width: u32) -> (Real, Real, Option<Real>) {
        let width = width.max(1);
        let step = |pixels: u32| {
            let scale = self.scale.to_bits();
            // In 64 bits where the product fits (scales below 2¹⁵ cells): a 128-bit
            // division costs a Cortex-M tens of times more, for the same quotient.
            let bits = match scale.checked_mul(i64::from(pixels)) {
                Some(product) => product / i64::from(width),
                None => (i128::from(scale) * i128::from(pixels) / i128::from(width)) as i64,
            };
            Real::from_bits(bits)
        };
        (step(x), step(y), self.z)
    }

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
        let mut reach = x.max(y).max(z.map_or(Real::ZERO, Real::abs));
        for _ in 1..self.octaves.octaves {
            reach = reach.checked_mul(self.octaves.lacunarity).ok_or(Overflow)?;
        }
        // Marble adds the turbulence (at most Σaⁱ ≤ 16) to x.
        reach.checked_add(Real::from_int(16)).ok_or(Overflow)?;
        Ok(NoiseDrawing {
            texture: self.clone(),
            normaliser: normaliser(&ladder)?,
            ladder,
            area,
            palette,
        })
    }
}

/// A texture fitted to an area with a palette: an embedded-graphics [`Drawable`], sent as
/// one `fill_contiguous` a row.
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

impl<P> NoiseDrawing<'_, P> {
    /// The level of pixel (`x`, `y`) of the area, 0 to 255.
    pub fn level_at(&self, x: u32, y: u32) -> u8 {
        level_of(self.value_at(x, y))
    }

    /// The value of pixel (`x`, `y`) of the area, in [0, 1] (what its level rounds).
    pub fn value_at(&self, x: u32, y: u32) -> Real {
        let point = self.texture.point((x, y), self.area.size.width);
        self.value_of(&RowSums::any(&self.ladder), point)
    }

    /// The value at a point of the texture (one of this drawing's pixels), summed by `sums`.
    fn value_of(&self, sums: &RowSums<'_>, point: (Real, Real, Option<Real>)) -> Real {
        let texture = &self.texture;
        // `fit` checked every point's range: a sample cannot fail here.
        texture
            .texture
            .value_normalised(texture.noise, sums, point, self.normaliser)
            .unwrap_or(Real::ZERO)
    }

    /// The points of row `y`'s pixels, left to right: the same as
    /// [`NoiseTexture::point`] gives, ⌊scale·x/width⌋ in 2⁻³², stepped by quotient and
    /// remainder instead of dividing at every pixel.
    fn row_points(&self, y: u32) -> impl Iterator<Item = (Real, Real, Option<Real>)> + '_ {
        let width = self.area.size.width.max(1);
        let (_, row, z) = self.texture.point((0, y), width);
        // `fit` refused a scale that is not positive.
        let scale = self.texture.scale.to_bits().max(0);
        let (quotient, remainder) = (scale / i64::from(width), scale % i64::from(width));
        let (mut x, mut carried) = (0_i64, 0_i64);
        (0..self.area.size.width).map(move |_| {
            let point = (Real::from_bits(x), row, z);
            x += quotient;
            carried += remainder;
            if carried >= i64::from(width) {
                carried -= i64::from(width);
                x += 1;
            }
            point
        })
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
        // A row at a time: a row shares its y (each octave's part of it is computed
        // once), and its pixels leave as one run without an iterator of rows around it.
        let width = self.area.size.width;
        for y in 0..self.area.size.height {
            // Wrapping, not counting on: a row past `i32::MAX` is off every target anyway.
            let top = self.area.top_left.y.wrapping_add_unsigned(y);
            let (_, row, _) = self.texture.point((0, y), width.max(1));
            let sums = RowSums::row(&self.ladder, row);
            let colors = self.row_points(y).map(|point| {
                let level = level_of(self.value_of(&sums, point));
                self.palette.color(u16::from(level), u16::MAX)
            });
            let line = Rectangle::new(Point::new(self.area.top_left.x, top), Size::new(width, 1));
            target.fill_contiguous(&line, colors)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use embedded_graphics::pixelcolor::Gray8;

    use super::*;
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
