//! Perlin's textures: noise and its sums turned into a level of a palette, over a picture.

use super::fractal::{Ladder, Octaves, Sum, OUT_OF_RANGE};
use super::perlin::Perlin;
use crate::error::Error;
use crate::math::trig::BinaryAngle;
use crate::math::wide::{mul_u32_wide, shift_round_i64};
use crate::math::Real;

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

/// |sum|·n in 2⁻³², rounded, from the magnitude's halves (h, l) and a normaliser n below
/// 1: h·n + (l·n + 2³¹)/2³², where only the second part rounds. h < 2³¹, so it is below
/// 2⁶³: no overflow.
#[inline(always)]
fn normalised_magnitude((high, low): (u32, u32), normaliser: u32) -> i64 {
    let rounded_low = (mul_u32_wide(low, normaliser) + (1 << 31)) >> 32;
    (mul_u32_wide(high, normaliser) + rounded_low) as i64
}

/// The coordinate ⌊scale·index/across⌋ (in 2⁻³²) of a grid of `across` points a
/// `scale` apart (`across` taken as at least 1, `scale` not negative); `None` past `Real`'s
/// range. In 64 bits where the product fits (scales below 2¹⁵ cells across a few thousand
/// points): a 128-bit division costs a Cortex-M tens of times more, for the same quotient.
#[inline(never)]
pub(super) fn lattice_point(scale: Real, index: u32, across: u32) -> Option<Real> {
    let (scale, across) = (scale.to_bits(), i64::from(across.max(1)));
    let bits = match scale.checked_mul(i64::from(index)) {
        Some(product) => product / across,
        None => i64::try_from(i128::from(scale) * i128::from(index) / i128::from(across)).ok()?,
    };
    Some(Real::from_bits(bits))
}

/// The coordinates [`lattice_point`] gives for the indices 0, 1, 2, … in turn, by
/// quotient and remainder instead of a 64-bit division each (`scale` taken as at least 0,
/// `across` as at least 1). Past `Real`'s range the coordinates wrap: a caller takes
/// only those its fit checked.
#[derive(Debug, Clone)]
pub(super) struct LatticeSteps {
    next: i64,
    carried: i64,
    quotient: i64,
    remainder: i64,
    across: i64,
}

impl LatticeSteps {
    /// From index 0, `scale` lattice units over `across` points.
    pub(super) fn new(scale: Real, across: u32) -> Self {
        let (scale, across) = (scale.to_bits().max(0), i64::from(across.max(1)));
        Self {
            next: 0,
            carried: 0,
            quotient: scale / across,
            remainder: scale % across,
            across,
        }
    }
}

impl Iterator for LatticeSteps {
    type Item = Real;

    #[inline]
    fn next(&mut self) -> Option<Real> {
        let point = Real::from_bits(self.next);
        self.next = self.next.wrapping_add(self.quotient);
        self.carried += self.remainder;
        if self.carried >= self.across {
            self.carried -= self.across;
            self.next = self.next.wrapping_add(1);
        }
        Some(point)
    }
}

/// The level of a sum's texture (fBm's, `centred`, or turbulence's and the ridged
/// multifractal's) from the sum of octaves `sum` (2⁻³²) and a normaliser below 1 (in
/// 2⁻³², so two or more octaves): [`level_of`] the value [`Texture::finish`] gives, the
/// same steps (normalise, centre, clamp, scale) in 32-bit parts and no checks, for a
/// drawing's every pixel. `sum` must be within ±2⁶² (a sum of 16 octaves is within ±17).
#[inline(always)]
pub(super) fn sum_level(sum: i64, normaliser: u32, centred: bool) -> u8 {
    let magnitude = sum.unsigned_abs();
    let rounded = normalised_magnitude(((magnitude >> 32) as u32, magnitude as u32), normaliser);
    let one = 1_i64 << Real::FRAC_BITS;
    let unit = if centred {
        // (value + 1) / 2, rounded half away from zero, as `finish` centres: a value
        // below −1 halves to at most 0, level 0.
        let shifted = if sum < 0 {
            one - rounded
        } else {
            one + rounded
        };
        if shifted < 0 {
            return 0;
        }
        (shifted + 1) >> 1
    } else if sum < 0 {
        return 0;
    } else {
        rounded
    };
    // As `level_of`, whose clamp below is spent here already (every path above is at
    // least 0): 1 and above is the last level.
    match u32::try_from(unit) {
        Ok(unit) => ((mul_u32_wide(unit, u32::from(LEVELS - 1)) + (1 << 31)) >> 32) as u8,
        Err(_) => (LEVELS - 1) as u8,
    }
}

/// A row of sums' levels by one product each: [`sum_level`]'s levels, for a drawing's
/// every pixel, where its rounding steps cost more than the sum's level needs.
///
/// The level is ⌊F⌋ clamped to 0 to 255, F being the level's real value before rounding
/// (128 + 127.5·n·s centred, ½ + 255·n·s otherwise, for the sum s and normaliser n),
/// which `sum_level`'s roundings move by under 2⁻²³. Here F is taken in 2⁻¹⁵ from the sum
/// in 2⁻²⁴ (rounded down) times the slope rounded to 2⁻²³, the product's high word: within
/// 2⁻¹⁴ of F for sums within ±17 (16 octaves). Where that lands within 2⁻¹³ of a whole
/// level (about one sum in 4,000), the level is `sum_level`'s own.
#[derive(Debug, Clone, Copy)]
pub(super) struct SumLevels {
    /// 127.5·n (centred) or 255·n, in 2⁻²³, rounded to an even number.
    slope: u32,
    /// F's start (128 or ½, in 2⁻¹⁵) less half the slope: the product is taken of the
    /// sum plus 2³¹ (unsigned, one `umull`), which adds exactly slope/2 to its high word.
    start: i32,
    normaliser: u32,
    centred: bool,
}

impl SumLevels {
    /// F in 2⁻¹⁵ beside the level's bits (a level is F's bits from 15 up).
    const FRACTION_BITS: u32 = 15;
    /// How far (in 2⁻¹⁵) the product may land from F: at most 2, twice that for margin.
    const MARGIN: i32 = 4;

    /// The levels of sums normalised by `normaliser` (below 1, in 2⁻³²), centred (fBm's)
    /// or not (turbulence's and the ridged multifractal's), as [`sum_level`] takes them.
    pub(super) fn new(normaliser: u32, centred: bool) -> Self {
        // 255·n·2²² (or half of it), rounded, doubled: below 255·2²³ < 2³².
        let shift = if centred { 11 } else { 10 };
        let half = (u64::from(normaliser) * u64::from(LEVELS - 1) + (1 << (shift - 1))) >> shift;
        let slope = (half as u32) << 1;
        // 128, or ½.
        let offset: i32 = if centred {
            128 << Self::FRACTION_BITS
        } else {
            1 << (Self::FRACTION_BITS - 1)
        };
        Self {
            slope,
            start: offset - half as i32,
            normaliser,
            centred,
        }
    }

    /// The level of `sum` (in 2⁻³², within ±17): the same as [`sum_level`]'s.
    #[inline(always)]
    pub(super) fn level(&self, sum: i64) -> u8 {
        // The sum in 2⁻²⁴ (within ±17·2²⁴, so it fits), plus 2³¹.
        let coarse = (sum >> 8) as u32 ^ (1 << 31);
        let fine = (mul_u32_wide(coarse, self.slope) >> 32) as i32 + self.start;
        let edge =
            (fine.wrapping_add(Self::MARGIN) & ((1 << Self::FRACTION_BITS) - 1)) < 2 * Self::MARGIN;
        if edge {
            return self.exact(sum);
        }
        (fine >> Self::FRACTION_BITS).clamp(0, i32::from(LEVELS - 1)) as u8
    }

    /// [`sum_level`], for the sums whose product lands near a level's edge.
    #[cold]
    #[inline(never)]
    fn exact(&self, sum: i64) -> u8 {
        sum_level(sum, self.normaliser, self.centred)
    }
}

/// A value in [0, 1] as a level 0 to 255, rounded to nearest (clamped first): the
/// value's 2⁻³² units times 255, in one 32×32 → 64-bit product below 1.
#[inline]
pub(super) fn level_of(value: Real) -> u8 {
    let unit = value.clamp(Real::ZERO, Real::ONE).to_bits();
    match u32::try_from(unit) {
        Ok(unit) => ((mul_u32_wide(unit, u32::from(LEVELS - 1)) + (1 << 31)) >> 32) as u8,
        // 1 itself.
        Err(_) => (LEVELS - 1) as u8,
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

    /// A sum's level by [`SumLevels`] is [`sum_level`]'s: over random sums, and at every
    /// level's edge (the sums about where F, found in f64, is a whole level), where the
    /// product alone would round either way.
    #[test]
    fn sum_levels_by_one_product_are_sum_levels() {
        use proptest::prelude::*;
        use proptest::test_runner::TestRunner;
        let bound = 17_i64 << 32;
        let cases = (1..(1_i64 << 32), any::<bool>(), -bound..bound);
        TestRunner::deterministic()
            .run(&cases, |(normaliser, centred, sum)| {
                let normaliser = normaliser as u32;
                let levels = SumLevels::new(normaliser, centred);
                prop_assert_eq!(levels.level(sum), sum_level(sum, normaliser, centred));
                // Every edge: F = L at s = (L − 128)/(127.5·n) centred, (L − ½)/(255·n) not.
                let n = f64::from(normaliser) / 2f64.powi(32);
                for edge in 0..=256 {
                    let s = if centred {
                        (f64::from(edge) - 128.0) / (127.5 * n)
                    } else {
                        (f64::from(edge) - 0.5) / (255.0 * n)
                    };
                    let at = (s * 2f64.powi(32)) as i64;
                    if !(-bound..bound).contains(&at) {
                        continue;
                    }
                    for sum in (at - 600..at + 600).step_by(7).chain([at - 1, at, at + 1]) {
                        prop_assert_eq!(
                            levels.level(sum),
                            sum_level(sum, normaliser, centred),
                            "sum {} normaliser {} centred {}",
                            sum,
                            normaliser,
                            centred
                        );
                    }
                }
                Ok(())
            })
            .unwrap();
    }

    /// Stepping gives [`lattice_point`]'s coordinates, at scales whose products need 128
    /// bits too.
    #[test]
    fn lattice_steps_are_the_divided_points() {
        let scales = [
            1,
            3,
            1 << 32,
            4_294_967_297,
            17_179_869_184_007,
            i64::MAX / 5,
        ];
        for (scale, across) in scales
            .into_iter()
            .flat_map(|s| [1, 7, 128, 333].map(|a| (s, a)))
        {
            let scale = Real::from_bits(scale);
            let steps = LatticeSteps::new(scale, across);
            for (index, stepped) in (0..1000).zip(steps) {
                let Some(divided) = lattice_point(scale, index, across) else {
                    break;
                };
                assert_eq!(stepped, divided, "{scale:?} {across} {index}");
            }
        }
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
