//! A landscape of noise: fBm heights on a square grid, drawn as the shared relief.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::fractal::{Ladder, Octaves, Sum, MAX_OCTAVES, OUT_OF_RANGE};
use super::lattice::lattice_point;
use super::perlin::{Perlin, RowPart};
use super::plane::{ColumnBlock, RowSums, BLOCK_COLUMNS};
use crate::error::{Error, FitError, ParameterError};
use crate::math::Real;
use crate::render::Relief;

/// A landscape of `samples`² heights, each the fBm of 2D noise at its grid point: `scale`
/// lattice cells across, the point (i, j) at (scale·i/samples, scale·j/samples).
///
/// A height is the sum as [`Octaves::sum`] gives it, in Q16.16 (its `Real` shifted right
/// 16 bits, rounded down). Heights live in the caller's buffer, like a
/// [`TerrainMap`](crate::terrain::TerrainMap)'s, and draw as the same [`Relief`].
#[derive(Debug, Clone, Copy)]
pub struct NoiseTerrain<'a> {
    noise: &'a Perlin,
    octaves: Octaves,
    scale: Real,
    samples: u32,
}

impl<'a> NoiseTerrain<'a> {
    /// The largest side: 4097 heights, as a midpoint-displacement landscape's.
    pub const MAX_SAMPLES: u32 = 4097;

    /// `samples`² heights of `noise`, six octaves of fBm, four lattice cells across.
    pub fn new(noise: &'a Perlin, samples: u32) -> Self {
        Self {
            noise,
            octaves: Octaves::default(),
            scale: Real::from_int(4),
            samples,
        }
    }

    /// The same with these octaves.
    #[must_use]
    pub fn with_octaves(self, octaves: Octaves) -> Self {
        Self { octaves, ..self }
    }

    /// The same with `scale` lattice cells across.
    #[must_use]
    pub fn with_scale(self, scale: Real) -> Self {
        Self { scale, ..self }
    }

    /// Heights needed in the buffer: `samples`².
    pub const fn cells(&self) -> usize {
        self.samples as usize * self.samples as usize
    }

    /// Fills `heights` (row by row, Q16.16) with the landscape. Refuses a side outside 2 to
    /// [`MAX_SAMPLES`](Self::MAX_SAMPLES), octaves out of range, a scale that is not
    /// positive, a buffer too small, and a finest octave past `Real`'s range
    /// ([`NoiseOutOfRange`](crate::error::ParameterError::NoiseOutOfRange)). Where the
    /// octaves double (lacunarity 2), the heights are summed a block of 32 columns at a
    /// time, as a texture is drawn: 5 KiB of stack beside the caller's buffer.
    pub fn generate(&self, heights: &mut [i32]) -> Result<(), Error> {
        let ladder = self.octaves.ladder()?;
        if self.scale <= Real::ZERO {
            return Err(Error::Parameter(ParameterError::ScaleNotPositive {
                scale: self.scale,
            }));
        }
        if !(2..=Self::MAX_SAMPLES).contains(&self.samples) {
            return Err(Error::Parameter(ParameterError::GridOutOfRange {
                width: self.samples,
                height: self.samples,
                min: 2,
                max: Self::MAX_SAMPLES,
            }));
        }
        let given = heights.len();
        let heights =
            heights
                .get_mut(..self.cells())
                .ok_or(Error::Fit(FitError::BufferTooSmall {
                    needed: self.cells(),
                    given,
                }))?;
        let side = i64::from(self.samples);
        let at = |index: i64| -> Result<Real, Error> {
            let index = u32::try_from(index).map_err(|_| OUT_OF_RANGE)?;
            lattice_point(self.scale, index, self.samples).ok_or(OUT_OF_RANGE)
        };
        // Where the octaves double and the farthest point's finest octave is in range (so
        // every point's is), a block of columns at a time, the same sums; otherwise point
        // by point, which finds the point whose octave leaves the range.
        if ladder.doubles() && ladder.finest(at(side - 1)?).is_some() {
            return self.generate_in_blocks(&ladder, heights, at);
        }
        for (j, row) in (0_i64..).zip(heights.chunks_mut(self.samples as usize)) {
            let y = at(j)?;
            for (i, height) in (0_i64..).zip(row.iter_mut()) {
                let value = ladder.sum(self.noise, Sum::Fbm, (at(i)?, y, None))?;
                *height = (value.to_bits() >> 16) as i32;
            }
        }
        Ok(())
    }

    /// [`generate`](Self::generate)'s heights a block of columns at a time, each column's
    /// x half of every octave once for the whole height (`ladder`'s octaves double, and
    /// the point `at(index)` of every index keeps its finest octave in range).
    fn generate_in_blocks(
        &self,
        ladder: &Ladder,
        heights: &mut [i32],
        at: impl Fn(i64) -> Result<Real, Error>,
    ) -> Result<(), Error> {
        let samples = self.samples as usize;
        let mut block = ColumnBlock::EMPTY;
        block.set_noise(self.noise);
        let mut rows = [RowPart::default(); MAX_OCTAVES as usize];
        let mut sums = RowSums::ZERO;
        for first in (0..samples).step_by(BLOCK_COLUMNS) {
            let count = BLOCK_COLUMNS.min(samples - first);
            let mut xs = [Real::ZERO; BLOCK_COLUMNS];
            for (x, index) in xs.iter_mut().zip(first as i64..).take(count) {
                *x = at(index)?;
            }
            block.fill(ladder, xs.get(..count).unwrap_or(&[]));
            for (j, row) in (0_i64..).zip(heights.chunks_mut(samples)) {
                ladder.rows_into(at(j)?, &mut rows).ok_or(OUT_OF_RANGE)?;
                block.sums(self.noise, ladder, &rows, false, &mut sums);
                let cells = row.get_mut(first..first + count).unwrap_or(&mut []);
                for (height, sum) in cells.iter_mut().zip(sums.iter()) {
                    *height = (sum >> 16) as i32;
                }
            }
        }
        Ok(())
    }

    /// Generates the landscape into `heights` and fits it to `area` (stretched to fill it).
    pub fn fit<'h, C>(
        &self,
        area: Rectangle,
        heights: &'h mut [i32],
    ) -> Result<Relief<'h, C>, Error>
    where
        C: PixelColor + From<Rgb888>,
    {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        self.generate(heights)?;
        Relief::new(heights, self.samples, area)
    }
}
