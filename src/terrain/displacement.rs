//! Midpoint displacement itself: its parameters, the levels a number of samples needs,
//! and one displaced midpoint in Q16.16.

use crate::error::{Error, ParameterError};
use crate::math::Real;

/// [`Terrain::MAX_LEVELS`], for the crate's own types and arrays.
pub(crate) const MAX_TERRAIN_LEVELS: u32 = 16;

/// [`Displacement::MAX_SIGMA`], for the crate's own types and arrays.
pub(crate) const MAX_SIGMA: Real = Real::from_int(256);

/// [`Terrain::MAX_END`], for the crate's own types and arrays.
pub(crate) const MAX_END: Real = Real::from_int(4096);

/// The parameters every midpoint displacement shares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Displacement {
    /// σ is multiplied by this at each level, in (0, 1].
    pub roughness: Real,
    /// The first level's standard deviation, 0 to [`Displacement::MAX_SIGMA`].
    pub sigma: Real,
    /// The seed of the variates.
    pub seed: u64,
}

impl Displacement {
    /// The largest standard deviation.
    ///
    /// With the end heights below [`Terrain::MAX_END`](super::Terrain::MAX_END), every
    /// height stays within ±2¹⁵ units (6σ·(levels + 1) + an end), the range of the Q16.16
    /// heights.
    pub const MAX_SIGMA: Real = MAX_SIGMA;

    /// Checks the roughness and σ.
    pub fn check(&self) -> Result<(), Error> {
        if self.roughness <= Real::ZERO || self.roughness > Real::ONE {
            return Err(Error::Parameter(ParameterError::RoughnessOutOfRange {
                roughness: self.roughness,
            }));
        }
        if self.sigma < Real::ZERO || self.sigma > MAX_SIGMA {
            return Err(Error::Parameter(ParameterError::SigmaOutOfRange {
                sigma: self.sigma,
                max: MAX_SIGMA,
            }));
        }
        Ok(())
    }

    /// σ·rʲ for j = 0..=MAX_TERRAIN_LEVELS, as Q32. Out of line: its 128-bit products
    /// are long on Cortex-M0, and every generator of heights calls it once.
    #[inline(never)]
    pub(crate) fn sigmas(&self) -> [i64; MAX_TERRAIN_LEVELS as usize + 1] {
        let mut sigmas = [0; MAX_TERRAIN_LEVELS as usize + 1];
        let mut sigma = self.sigma.to_bits();
        for slot in sigmas.iter_mut() {
            *slot = sigma;
            sigma = ((i128::from(sigma) * i128::from(self.roughness.to_bits())) >> 32) as i64;
        }
        sigmas
    }
}

/// The number of levels k for `samples` = 2ᵏ + 1, checked against `max_levels`.
pub(crate) fn levels_of(samples: u32, max_levels: u32) -> Result<u32, Error> {
    let intervals = samples.saturating_sub(1);
    if samples < 2 || !intervals.is_power_of_two() {
        return Err(Error::Parameter(
            ParameterError::SamplesNotPowerOfTwoPlusOne { samples },
        ));
    }
    let levels = intervals.trailing_zeros();
    if levels > max_levels {
        return Err(Error::Parameter(ParameterError::TooManySamples {
            samples,
            max: (1 << max_levels) + 1,
        }));
    }
    Ok(levels)
}

/// The mean of `a` and `b` (Q16.16, rounded down) plus `sigma` (Q32) times `normal` (Q16).
#[inline]
pub(crate) fn displaced(mean: i64, sigma: i64, normal: i32) -> i32 {
    let height = mean + ((sigma * i64::from(normal)) >> 32);
    height.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// A Q16.16 height as a [`Real`].
pub(crate) const fn real_of(height: i32) -> Real {
    Real::from_bits((height as i64) << 16)
}
