//! Fractal sums of noise: fBm, turbulence and Musgrave's ridged multifractal, octave by
//! octave.

use super::perlin::Perlin;
use crate::error::{Error, ParameterError};
use crate::math::Real;

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
        (x, y, z): (Real, Real, Option<Real>),
    ) -> Result<Real, Error> {
        self.check()?;
        let overflow = Error::from(crate::math::Overflow);
        let (mut point, mut amplitude) = ((x, y, z), Real::ONE);
        let (mut total, mut weight) = (Real::ZERO, Real::ONE);
        for octave in 0..self.octaves {
            if octave > 0 {
                let scale = |value: Real| value.checked_mul(self.lacunarity).ok_or(overflow);
                point = (
                    scale(point.0)?,
                    scale(point.1)?,
                    point.2.map(scale).transpose()?,
                );
                amplitude = amplitude.checked_mul(self.persistence).ok_or(overflow)?;
            }
            let value = noise.sample(point).to_real();
            let term = match sum {
                Sum::Fbm => value,
                Sum::Turbulence => value.abs(),
                Sum::Ridged => {
                    let ridge = Real::ONE.saturating_sub(value.abs());
                    let signal = ridge.checked_mul(ridge).ok_or(overflow)?;
                    let weighted = signal.checked_mul(weight).ok_or(overflow)?;
                    let two = Real::from_int(2);
                    weight = signal
                        .checked_mul(two)
                        .ok_or(overflow)?
                        .clamp(Real::ZERO, Real::ONE);
                    weighted
                }
            };
            let scaled = term.checked_mul(amplitude).ok_or(overflow)?;
            total = total.checked_add(scaled).ok_or(overflow)?;
        }
        Ok(total)
    }
}
