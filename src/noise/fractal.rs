//! Fractal sums of noise: fBm, turbulence and Musgrave's ridged multifractal, octave by
//! octave.

use super::perlin::{Perlin, RowPart, Sample, SAMPLE_FRAC_BITS};
use crate::error::{Error, ParameterError};
use crate::math::wide::mul_i32_by_small;
use crate::math::Real;

/// The error of noise coordinates (or a sum of samples) past the fixed-point range.
pub(super) const OUT_OF_RANGE: Error = Error::Parameter(ParameterError::NoiseOutOfRange);

/// The most octaves a sum takes: the 16th octave's features are 2¹⁵ times finer than the
/// first's, below any display's pixel.
pub const MAX_OCTAVES: u32 = 16;

/// How the octaves of a fractal sum are taken: `octaves` samples, each at `lacunarity`
/// times the last one's frequency and `persistence` times its amplitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Octaves {
    /// Samples summed, 1 to [`MAX_OCTAVES`].
    pub octaves: u32,
    /// Each octave's amplitude over the last one's, 0 to 1 (the gain; ½ for fBm).
    pub persistence: Real,
    /// Each octave's frequency over the last one's, 1 to 4 (2 for fBm).
    pub lacunarity: Real,
}

impl Default for Octaves {
    /// Six octaves, persistence ½, lacunarity 2: the classic fBm.
    fn default() -> Self {
        Self {
            octaves: 6,
            persistence: Real::from_ratio(1, 2).unwrap_or(Real::ONE),
            lacunarity: Real::from_int(2),
        }
    }
}

/// Which sum of octaves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sum {
    /// Fractional Brownian motion: Σ aᵢ·noise(fᵢ·p).
    Fbm,
    /// Perlin's turbulence: Σ aᵢ·|noise(fᵢ·p)|.
    Turbulence,
    /// Musgrave's ridged multifractal (offset 1, gain 2): each octave's ridge
    /// (1 − |noise|)² weighted by the last one's, clamped to 0..1.
    Ridged,
}

impl Octaves {
    /// Checks the counts and ratios: octaves 1 to [`MAX_OCTAVES`], persistence in [0, 1],
    /// lacunarity in [1, 4] (past 4 the finest octave's coordinates would leave the range
    /// a sample takes).
    pub fn check(&self) -> Result<(), Error> {
        if self.octaves == 0 || self.octaves > MAX_OCTAVES {
            return Err(Error::Parameter(ParameterError::OctavesOutOfRange {
                octaves: self.octaves,
                max: MAX_OCTAVES,
            }));
        }
        if self.persistence < Real::ZERO || self.persistence > Real::ONE {
            return Err(Error::Parameter(ParameterError::PersistenceOutOfRange {
                persistence: self.persistence,
            }));
        }
        if self.lacunarity < Real::ONE || self.lacunarity > Real::from_int(4) {
            return Err(Error::Parameter(ParameterError::LacunarityOutOfRange {
                lacunarity: self.lacunarity,
            }));
        }
        Ok(())
    }

    /// The `sum` of the octaves of `noise` at (`x`, `y`, `z`), as a [`Real`]; 2D where `z` is
    /// `None`. Coordinates that leave `Real`'s range at a fine octave are an overflow error.
    pub fn sum(
        &self,
        noise: &Perlin,
        sum: Sum,
        point: (Real, Real, Option<Real>),
    ) -> Result<Real, Error> {
        self.ladder()?.sum(noise, sum, point)
    }

    /// The octaves checked and prepared for many points: each octave's amplitude, aⁱ, once
    /// (each the last one times the persistence, rounded to 2⁻³² as `Real` multiplies).
    pub(crate) fn ladder(&self) -> Result<Ladder, Error> {
        self.check()?;
        let mut amplitudes = [Real::ZERO; MAX_OCTAVES as usize];
        let mut amplitude = Real::ONE;
        for slot in amplitudes.iter_mut().take(self.octaves as usize) {
            *slot = amplitude;
            // At most 1 times a persistence of at most 1: no overflow.
            amplitude = amplitude
                .checked_mul(self.persistence)
                .unwrap_or(Real::ZERO);
        }
        Ok(Ladder {
            octaves: self.octaves,
            lacunarity: self.lacunarity,
            amplitudes,
            weights: amplitudes.map(Weight::of),
            narrow_from: narrow_from(amplitudes.get(..self.octaves as usize).unwrap_or(&[])),
        })
    }
}

/// Checked octaves with their amplitudes computed: what a sum needs at every point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Ladder {
    octaves: u32,
    lacunarity: Real,
    amplitudes: [Real; MAX_OCTAVES as usize],
    /// The amplitudes as [`Weight`]s, once.
    weights: [Weight; MAX_OCTAVES as usize],
    /// The first octave of the finer ones whose terms sum in 32 bits.
    narrow_from: usize,
}

/// The first octave from which on the terms of 2D samples (each below 2 in magnitude) at
/// these `amplitudes` sum within ±2³¹ in 2⁻³²: a term is at most 2a·2³² + ½ (rounded), so
/// their bounds are summed from the last octave back while they stay below 2³¹.
fn narrow_from(amplitudes: &[Real]) -> usize {
    let mut bound: i64 = 0;
    let mut first = amplitudes.len();
    for (octave, amplitude) in amplitudes.iter().enumerate().rev() {
        bound += 2 * amplitude.to_bits() + 1;
        if bound >= 1 << 31 {
            break;
        }
        first = octave;
    }
    first
}

impl Ladder {
    /// Whether each octave doubles the last one's frequency (lacunarity 2), or there is one
    /// octave: then a plane's sum takes each octave's coordinates by doubling.
    pub(super) fn doubles(&self) -> bool {
        self.octaves == 1 || self.lacunarity == Real::from_int(2)
    }

    /// The amplitudes of the octaves summed, first to last.
    pub(super) fn amplitudes(&self) -> &[Real] {
        self.amplitudes
            .get(..self.octaves as usize)
            .unwrap_or(&self.amplitudes)
    }

    /// The first octave whose 2D terms a block sums in 32 bits: the terms of it and the
    /// octaves after it stay within ±2³¹ together.
    pub(super) fn narrow_from(&self) -> usize {
        self.narrow_from
    }

    /// Each octave's amplitude as a [`Weight`], first to last.
    pub(super) fn weights(&self) -> &[Weight] {
        self.weights
            .get(..self.octaves as usize)
            .unwrap_or(&self.weights)
    }

    /// `reach` (a coordinate's magnitude) at the finest octave: times the lacunarity once
    /// an octave after the first; `None` past `Real`'s range. Where a picture's farthest
    /// point stays in range, every point's every octave does.
    pub(super) fn finest(&self, reach: Real) -> Option<Real> {
        (1..self.octaves).try_fold(reach, |reach, _| reach.checked_mul(self.lacunarity))
    }

    /// Σaⁱ: what the sums of samples in [−1, 1] stay within.
    pub(crate) fn amplitude_total(&self) -> Result<Real, Error> {
        let mut total = Real::ZERO;
        for &amplitude in self.amplitudes() {
            total = total.checked_add(amplitude).ok_or(OUT_OF_RANGE)?;
        }
        Ok(total)
    }

    /// [`Octaves::sum`] with the amplitudes ready. Point by point, the general path: kept
    /// out of line where it is called (drawings take the blocks where they can), to spare
    /// the smallest boards' flash.
    #[inline(never)]
    pub(crate) fn sum(
        &self,
        noise: &Perlin,
        sum: Sum,
        (x, y, z): (Real, Real, Option<Real>),
    ) -> Result<Real, Error> {
        let overflow = OUT_OF_RANGE;
        if z.is_none() && self.lacunarity == Real::from_int(2) && sum != Sum::Ridged {
            return self
                .plane_sum(noise, sum == Sum::Turbulence, (x, y))
                .ok_or(overflow);
        }
        let mut point = (x, y, z);
        let (mut total, mut weight) = (Real::ZERO, Real::ONE);
        let amplitudes = self.amplitudes.iter().take(self.octaves as usize);
        for (octave, &amplitude) in amplitudes.enumerate() {
            if octave > 0 {
                let scale = |value: Real| self.scale(value).ok_or(overflow);
                point = (
                    scale(point.0)?,
                    scale(point.1)?,
                    point.2.map(scale).transpose()?,
                );
            }
            let value = noise.sample(point);
            let scaled = match sum {
                Sum::Fbm => times(value, amplitude),
                Sum::Turbulence => times(Sample(value.0.abs()), amplitude),
                Sum::Ridged => {
                    let ridge = Real::ONE.saturating_sub(value.to_real().abs());
                    let signal = ridge.checked_mul(ridge).ok_or(overflow)?;
                    let weighted = signal.checked_mul(weight).ok_or(overflow)?;
                    let two = Real::from_int(2);
                    weight = signal
                        .checked_mul(two)
                        .ok_or(overflow)?
                        .clamp(Real::ZERO, Real::ONE);
                    weighted.checked_mul(amplitude).ok_or(overflow)?
                }
            };
            total = total.checked_add(scaled).ok_or(overflow)?;
        }
        Ok(total)
    }

    /// fBm (or turbulence, the sum of |noise|) of 2D noise at lacunarity 2, the usual sum,
    /// in 64-bit integers: the same value as the general path, at a fraction of its cost on
    /// a 32-bit core. `None` where a coordinate leaves `Real`'s range.
    fn plane_sum(&self, noise: &Perlin, turbulence: bool, (x, y): (Real, Real)) -> Option<Real> {
        let rows = self.rows(y)?;
        self.plane_sum_in_row(noise, turbulence, x, &rows)
    }

    /// Each octave's y part of a row at `y` (lacunarity 2: y doubled an octave); `None`
    /// where it leaves `Real`'s range.
    pub(super) fn rows(&self, y: Real) -> Option<[RowPart; MAX_OCTAVES as usize]> {
        let mut rows = [RowPart::default(); MAX_OCTAVES as usize];
        self.rows_into(y, &mut rows)?;
        Some(rows)
    }

    /// [`rows`](Self::rows) written into `rows`, a row's parts kept in place.
    pub(super) fn rows_into(
        &self,
        y: Real,
        rows: &mut [RowPart; MAX_OCTAVES as usize],
    ) -> Option<()> {
        let mut y = y.to_bits();
        for (octave, row) in rows.iter_mut().take(self.octaves as usize).enumerate() {
            if octave > 0 {
                y = y.checked_mul(2)?;
            }
            *row = RowPart::of(Real::from_bits(y));
        }
        Some(())
    }

    /// [`plane_sum`](Self::plane_sum) at `x` in a row whose y parts are ready.
    fn plane_sum_in_row(
        &self,
        noise: &Perlin,
        turbulence: bool,
        x: Real,
        rows: &[RowPart; MAX_OCTAVES as usize],
    ) -> Option<Real> {
        let mut x = x.to_bits();
        // Each term is at most 1.04 in magnitude, 16 of them: no overflow.
        let mut total: i64 = 0;
        let octaves = self.amplitudes.iter().zip(rows).take(self.octaves as usize);
        for (octave, (&amplitude, &row)) in octaves.enumerate() {
            if octave > 0 {
                x = x.checked_mul(2)?;
            }
            let mut value = noise.noise2_in_row(Real::from_bits(x), row);
            if turbulence {
                value = Sample(value.0.abs());
            }
            total += times(value, amplitude).to_bits();
        }
        Some(Real::from_bits(total))
    }

    /// A coordinate at the next octave: times the lacunarity, rounded to 2⁻³²; a doubling
    /// (the usual lacunarity) exactly, in 64 bits.
    fn scale(&self, value: Real) -> Option<Real> {
        if self.lacunarity == Real::from_int(2) {
            value.to_bits().checked_mul(2).map(Real::from_bits)
        } else {
            value.checked_mul(self.lacunarity)
        }
    }
}

/// `sample × amplitude` as `Real::checked_mul` gives it (rounded half away from zero to
/// 2⁻³²), in 64 bits: |sample| < 2³¹ in Q29 and the amplitude at most 2³² in Q32, so the
/// product in Q61 fits. Rounded without a branch: a negative product's half away from zero
/// is ⌊(p + half − 1) / 2²⁹⌋.
#[inline(always)]
pub(super) fn times(sample: Sample, amplitude: Real) -> Real {
    let product = i64::from(sample.0) * amplitude.to_bits();
    let half = 1 << (SAMPLE_FRAC_BITS - 1);
    Real::from_bits((product + half + (product >> 63)) >> SAMPLE_FRAC_BITS)
}

/// An octave's amplitude as its samples' terms are cheapest taken: [`times`] without its
/// 64-bit product and rounding where the amplitude is a multiple of 2⁻³ (fBm's first four
/// octaves) or a power of two (its later ones), the same terms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Weight {
    /// m·2⁻³ (m at most 8): the product m·sample in 2⁻³² is exact, nothing rounds.
    Eighths(i32),
    /// 2⁻ᵏ for k from 4 to 32: the sample (in 2⁻²⁹) shifted right by k − 3, rounded half
    /// away from zero, in 32 bits.
    Halving(u32),
    /// Any other amplitude: [`times`].
    Any(Real),
}

impl Weight {
    /// The weight of `amplitude` (0 to 1).
    pub(super) fn of(amplitude: Real) -> Self {
        let bits = amplitude.to_bits();
        let eighth = 1 << SAMPLE_FRAC_BITS;
        if bits % eighth == 0 && (0..=8 * eighth).contains(&bits) {
            Self::Eighths((bits / eighth) as i32)
        } else if bits > 0 && bits.count_ones() == 1 {
            // Below 2⁻³ here: the shift is 4 to 32.
            Self::Halving(SAMPLE_FRAC_BITS - bits.trailing_zeros())
        } else {
            Self::Any(amplitude)
        }
    }

    /// `sample`'s term at this weight, in 2⁻³²: `times(sample, amplitude)`.
    #[inline(always)]
    pub(super) fn term(self, sample: Sample) -> i64 {
        match self {
            Self::Eighths(m) => mul_i32_by_small(sample.0, m),
            Self::Halving(shift) => {
                // |sample| < 2³⁰·¹ and the half at most 2²⁸: no overflow. A negative
                // sample's half away from zero is ⌊(s + half − 1) / 2ᵏ⌋, as in `times`.
                let value = sample.0;
                let half = 1 << (shift.saturating_sub(1) & 31);
                i64::from((value + half + (value >> 31)) >> (shift & 31))
            }
            Self::Any(amplitude) => times(sample, amplitude).to_bits(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// The octaves summed in 32 bits are the last ones whose terms' bounds stay below
    /// 2³¹ together: fBm's from ⅛ on (⅛ + ¹⁄₁₆ + ¹⁄₃₂ < ¼), none at persistence 1.
    #[test]
    fn narrow_octaves_are_the_fine_ones_that_fit() {
        let ladder = |octaves, persistence| {
            Octaves {
                octaves,
                persistence,
                lacunarity: Real::from_int(2),
            }
            .ladder()
            .unwrap()
        };
        let half = Real::from_ratio(1, 2).unwrap();
        assert_eq!(ladder(6, half).narrow_from(), 3);
        assert_eq!(ladder(16, half).narrow_from(), 3);
        assert_eq!(ladder(2, half).narrow_from(), 2);
        assert_eq!(ladder(4, Real::ONE).narrow_from(), 4);
        assert_eq!(ladder(3, Real::ZERO).narrow_from(), 1);
        // The bound itself: 2·Σaᵢ·2³² plus a half for each term stays below 2³¹.
        for (octaves, persistence) in [(6, half), (16, half), (9, Real::from_ratio(1, 3).unwrap())]
        {
            let ladder = ladder(octaves, persistence);
            let narrow = &ladder.amplitudes()[ladder.narrow_from()..];
            let bound: i64 = narrow.iter().map(|a| 2 * a.to_bits() + 1).sum();
            assert!(bound < 1 << 31, "{octaves} {persistence:?}");
        }
    }

    /// Every kind of weight gives the term `times` gives, at amplitudes of each kind.
    #[test]
    fn weights_give_the_products_terms() {
        let eighths = (0..=8_i64).prop_map(|m| m << SAMPLE_FRAC_BITS);
        let powers = (0..=32_u32).prop_map(|k| 1_i64 << k);
        let amplitudes = prop_oneof![eighths, powers, 0..=(1_i64 << 32)];
        // Samples within the noise's range, ±1.04 in 2⁻²⁹, and at its ends.
        let bound = (1_i32 << SAMPLE_FRAC_BITS) + (1 << (SAMPLE_FRAC_BITS - 4));
        let samples = prop_oneof![-bound..=bound, Just(-bound), Just(bound), -64..64];
        TestRunner::deterministic()
            .run(&(amplitudes, samples), |(amplitude, sample)| {
                let amplitude = Real::from_bits(amplitude);
                let weight = Weight::of(amplitude);
                let sample = Sample(sample);
                prop_assert_eq!(weight.term(sample), times(sample, amplitude).to_bits());
                Ok(())
            })
            .unwrap();
        // Each kind is reached (so the test is not of one path only).
        for (kind, amplitude) in [(0, 1_i64 << 31), (1, 1 << 20), (2, 3 << 20)] {
            let weight = Weight::of(Real::from_bits(amplitude));
            let index = match weight {
                Weight::Eighths(_) => 0,
                Weight::Halving(_) => 1,
                Weight::Any(_) => 2,
            };
            assert_eq!(index, kind, "{weight:?}");
        }
    }
}
