//! Perlin's textures: noise and its sums turned into a level of a palette, over a picture.

use super::fractal::{Ladder, Octaves, Sum, OUT_OF_RANGE};
use super::lattice::lattice_point;
use super::level::{level_of, normalised_magnitude};
use super::perlin::Perlin;
use crate::error::Error;
use crate::math::trig::BinaryAngle;
use crate::math::wide::shift_round_i64;
use crate::math::Real;

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
        self.value_normalised(noise, &ladder, point, normaliser(&ladder)?)
    }

    /// What the texture is made of: a sum of octaves, or one sample where `None`.
    pub(super) fn source(self) -> Option<Sum> {
        match self {
            Self::Perlin | Self::Wood => None,
            Self::Fbm | Self::Clouds => Some(Sum::Fbm),
            Self::Turbulence | Self::Marble => Some(Sum::Turbulence),
            Self::Ridged => Some(Sum::Ridged),
        }
    }

    /// [`value`](Self::value) with the sums' normaliser given, so that a drawing computes
    /// it once rather than a division a pixel.
    pub(super) fn value_normalised(
        self,
        noise: &Perlin,
        ladder: &Ladder,
        point: (Real, Real, Option<Real>),
        normaliser: Real,
    ) -> Result<Real, Error> {
        let source = match self.source() {
            Some(sum) => ladder.sum(noise, sum, point)?,
            None => noise.sample(point).to_real(),
        };
        self.finish(source, point.0, normaliser)
    }

    /// How [`finish`](Self::finish) turns a sum of octaves into the value, where that is
    /// all it does: `Some(true)` normalised and centred (fBm, clouds), `Some(false)`
    /// normalised (turbulence, ridged); `None` for the textures that do more (or take one
    /// sample). [`sum_level`] takes the same steps.
    pub(super) fn sum_centring(self) -> Option<bool> {
        match self {
            Self::Fbm | Self::Clouds => Some(true),
            Self::Turbulence | Self::Ridged => Some(false),
            Self::Perlin | Self::Marble | Self::Wood => None,
        }
    }

    /// The value at a point whose x is `x` from its [`source`](Self::source): the sum of
    /// the octaves (not yet normalised) or the sample.
    #[inline(always)]
    pub(super) fn finish(self, source: Real, x: Real, normaliser: Real) -> Result<Real, Error> {
        let normalised = || normalise(source, normaliser).ok_or(OUT_OF_RANGE);
        let unit = |value: Real| value.clamp(Real::ZERO, Real::ONE);
        let centred = |value: Real| -> Result<Real, Error> {
            let shifted = value.checked_add(Real::ONE).ok_or(OUT_OF_RANGE)?;
            // Times ½ as `Real` multiplies (rounded half away from zero), by a shift.
            Ok(unit(Real::from_bits(shift_round_i64(shifted.to_bits(), 1))))
        };
        match self {
            Self::Perlin => centred(source),
            Self::Fbm | Self::Clouds => centred(normalised()?),
            Self::Turbulence | Self::Ridged => Ok(unit(normalised()?)),
            Self::Marble => {
                // Turns of the sine: its fraction is a binary angle. A quarter of the
                // turbulence bends the veins about as much as Perlin's radians do.
                let bend = Real::from_bits(source.to_bits() >> 2);
                let turns = x.checked_add(bend).ok_or(OUT_OF_RANGE)?;
                let angle = BinaryAngle(turns.to_bits() as u32);
                let (_, sin) = angle.cos_sin();
                // sin in 2⁻³⁰: (1 + sin) / 2 in 2⁻³¹, to 2⁻³².
                let level = ((1_i64 << 30) + i64::from(sin)) << 1;
                Ok(unit(Real::from_bits(level)))
            }
            Self::Wood => {
                let grain = source
                    .checked_add(Real::ONE)
                    .and_then(|value| value.checked_mul(Real::from_int(8)))
                    .ok_or(OUT_OF_RANGE)?;
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

/// `sum × normaliser` as `Real::checked_mul` gives it, rounded half away from zero to
/// 2⁻³², in two 32×32 → 64-bit products where the normaliser is below 1 (more than one
/// octave): |sum|·n = h·n·2³² + l·n for the magnitude's halves h and l, and only the
/// second part rounds. Every pixel of a sum's texture takes one.
#[inline]
fn normalise(sum: Real, normaliser: Real) -> Option<Real> {
    let magnitude = sum.to_bits().unsigned_abs();
    let (high, low) = ((magnitude >> 32) as u32, magnitude as u32);
    match u32::try_from(normaliser.to_bits()) {
        // h < 2³¹: see `normalised_magnitude`.
        Ok(n) if high >> 31 == 0 => {
            let rounded = normalised_magnitude((high, low), n);
            Some(Real::from_bits(if sum < Real::ZERO {
                -rounded
            } else {
                rounded
            }))
        }
        _ => sum.checked_mul(normaliser),
    }
}

/// 1/Σaⁱ over the octaves, rounded to 2⁻³²: what a sum is multiplied by to stay within
/// [−1, 1].
pub(super) fn normaliser(ladder: &Ladder) -> Result<Real, Error> {
    Real::ONE
        .checked_div(ladder.amplitude_total()?)
        .ok_or(OUT_OF_RANGE)
}

/// A texture over a picture: `scale` lattice cells across its width, at depth `z` (3D
/// noise) or in the plane.
#[derive(Debug, Clone)]
pub struct NoiseTexture<'a> {
    pub(super) noise: &'a Perlin,
    pub(super) texture: Texture,
    pub(super) octaves: Octaves,
    pub(super) scale: Real,
    pub(super) z: Option<Real>,
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
        // Past `Real`'s range (a picture far taller than wide at a vast scale) the point
        // saturates, and `fit` refuses it.
        let step = |pixels: u32| {
            lattice_point(self.scale, pixels, width).unwrap_or(Real::from_bits(i64::MAX))
        };
        (step(x), step(y), self.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::noise::level::sum_level;

    /// A sum's level by [`sum_level`] is the level of the value `finish` gives, for the
    /// textures that take it, over sums and normalisers of every size a texture has.
    #[test]
    fn sum_levels_are_the_finished_values_levels() {
        use proptest::prelude::*;
        use proptest::test_runner::TestRunner;
        let sums = prop_oneof![
            -(17_i64 << 32)..(17_i64 << 32),
            -(3_i64 << 31)..(3_i64 << 31),
            -4..4_i64,
            Just(1_i64 << 32),
            Just(-(1_i64 << 32)),
        ];
        let normalisers = prop_oneof![1..(1_i64 << 32), Just((1_i64 << 32) - 1), Just(1)];
        TestRunner::deterministic()
            .run(&(sums, normalisers), |(sum, normaliser)| {
                let n = Real::from_bits(normaliser);
                let x = Real::ZERO;
                let textures = [
                    Texture::Perlin,
                    Texture::Fbm,
                    Texture::Turbulence,
                    Texture::Ridged,
                    Texture::Clouds,
                    Texture::Marble,
                    Texture::Wood,
                ];
                for texture in textures {
                    let Some(centred) = texture.sum_centring() else {
                        continue;
                    };
                    let finished = texture.finish(Real::from_bits(sum), x, n).unwrap();
                    let fast = sum_level(sum, normaliser as u32, centred);
                    prop_assert_eq!(fast, level_of(finished), "{:?}", texture);
                }
                Ok(())
            })
            .unwrap();
    }

    /// Normalising a sum by halves gives `Real`'s product, over sums and normalisers of
    /// every size a texture has and past them.
    #[test]
    fn normalising_is_reals_product() {
        use proptest::prelude::*;
        use proptest::test_runner::TestRunner;
        let mut runner = TestRunner::deterministic();
        let sums = prop_oneof![any::<i64>(), -(17_i64 << 32)..(17_i64 << 32), -4..4_i64];
        let normalisers = prop_oneof![
            1..=(1_i64 << 32),
            Just(1 << 32),
            Just((1 << 32) - 1),
            any::<i64>()
        ];
        runner
            .run(&(sums, normalisers), |(sum, normaliser)| {
                let (sum, normaliser) = (Real::from_bits(sum), Real::from_bits(normaliser));
                prop_assert_eq!(normalise(sum, normaliser), sum.checked_mul(normaliser));
                Ok(())
            })
            .unwrap();
        // Halves round away from zero, as `Real` does.
        let half = Real::from_bits(1 << 31);
        for bits in [1, -1, 3, -3] {
            let sum = Real::from_bits(bits);
            assert_eq!(normalise(sum, half), sum.checked_mul(half));
        }
    }
}
