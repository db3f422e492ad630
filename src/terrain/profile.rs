//! A mountain profile by 1D midpoint displacement, generated left to right with a stack of
//! one pending right end per level (k + 1 entries for 2ᵏ + 1 samples), so a profile of any
//! length needs no buffer; drawn as one column of ground and one of sky per pixel column.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::displacement::{
    displaced, levels_of, real_of, Displacement, MAX_END, MAX_TERRAIN_LEVELS,
};
use crate::error::{Error, FitError, ParameterError};
use crate::math::random::Seeded;
use crate::math::wide::div_narrow;
use crate::math::Real;

/// A profile of 2ᵏ + 1 heights by midpoint displacement.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Terrain {
    /// Roughness, σ and seed.
    pub displacement: Displacement,
    /// Heights: 2ᵏ + 1, up to 2¹⁶ + 1.
    pub samples: u32,
    /// The first and last heights (fixed), within ±[`Terrain::MAX_END`].
    pub ends: (Real, Real),
}

impl Terrain {
    /// The largest magnitude of a fixed end height.
    pub const MAX_END: Real = MAX_END;

    /// Most levels of midpoint displacement: 2¹⁶ + 1 samples in a profile.
    pub const MAX_LEVELS: u32 = MAX_TERRAIN_LEVELS;

    /// A profile of `samples` heights with ends at 0.
    pub const fn new(samples: u32, displacement: Displacement) -> Self {
        Self {
            displacement,
            samples,
            ends: (Real::ZERO, Real::ZERO),
        }
    }

    /// The same profile with its ends at `first` and `last`.
    #[must_use]
    pub const fn with_ends(mut self, first: Real, last: Real) -> Self {
        self.ends = (first, last);
        self
    }

    /// Checks every parameter; returns the number of levels.
    fn check(&self) -> Result<u32, Error> {
        self.displacement.check()?;
        for end in [self.ends.0, self.ends.1] {
            if end.abs() > MAX_END {
                return Err(Error::Parameter(ParameterError::EndOutOfRange {
                    end,
                    max: MAX_END,
                }));
            }
        }
        levels_of(self.samples, MAX_TERRAIN_LEVELS)
    }

    /// The heights, left to right.
    pub fn heights(&self) -> Result<Heights, Error> {
        let levels = self.check()?;
        let q16 = |end: Real| (end.to_bits() >> 16) as i32;
        let last = 1u32 << levels;
        let mut pending = [(0u32, 0i32); MAX_TERRAIN_LEVELS as usize + 2];
        if let Some(slot) = pending.first_mut() {
            *slot = (last, q16(self.ends.1));
        }
        Ok(Heights {
            seeded: Seeded::new(self.displacement.seed),
            sigmas: self.displacement.sigmas(),
            levels,
            left: None,
            first: Some(q16(self.ends.0)),
            pending,
            depth: 1,
        })
    }

    /// The profile fitted to `area`: its lowest and highest heights to the area's bottom
    /// and top rows, its samples spread over the columns; ground in `ground`, sky in `sky`.
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        ground: C,
        sky: C,
    ) -> Result<ProfileDrawing<C>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let mut range = (i32::MAX, i32::MIN);
        for height in self.heights()?.raw() {
            range = (range.0.min(height), range.1.max(height));
        }
        Ok(ProfileDrawing {
            terrain: *self,
            area,
            range,
            ground,
            sky,
        })
    }
}

/// A profile's heights, left to right: an iterator of [`Real`] (see [`Heights::raw`] for
/// the Q16.16 values).
#[derive(Debug, Clone)]
pub struct Heights {
    seeded: Seeded,
    sigmas: [i64; MAX_TERRAIN_LEVELS as usize + 1],
    levels: u32,
    /// The last sample given out: (index, height).
    left: Option<(u32, i32)>,
    /// The first sample, before it is given out.
    first: Option<i32>,
    /// Right ends still to give out, the nearest on top.
    pending: [(u32, i32); MAX_TERRAIN_LEVELS as usize + 2],
    depth: usize,
}

impl Heights {
    /// The heights as Q16.16 bits.
    pub fn raw(self) -> impl Iterator<Item = i32> {
        let mut heights = self;
        core::iter::from_fn(move || heights.next_raw())
    }

    fn next_raw(&mut self) -> Option<i32> {
        if let Some(first) = self.first.take() {
            self.left = Some((0, first));
            return Some(first);
        }
        let (left_index, left_height) = self.left?;
        loop {
            let top = self.depth.checked_sub(1)?;
            let &(right_index, right_height) = self.pending.get(top)?;
            if right_index - left_index == 1 {
                self.depth = top;
                self.left = Some((right_index, right_height));
                return Some(right_height);
            }
            // Split [left, right]: its midpoint is of level levels − log2(span) + 1.
            let span = right_index - left_index;
            let level = (self.levels - span.trailing_zeros()) as usize;
            let middle = left_index + span / 2;
            let mean = (i64::from(left_height) + i64::from(right_height)) >> 1;
            let sigma = self.sigmas.get(level).copied().unwrap_or(0);
            let height = displaced(mean, sigma, self.seeded.normal_q16(middle));
            *self.pending.get_mut(self.depth)? = (middle, height);
            self.depth += 1;
        }
    }
}

impl Iterator for Heights {
    type Item = Real;

    fn next(&mut self) -> Option<Real> {
        self.next_raw().map(real_of)
    }
}

/// A profile fitted to an area: an embedded-graphics [`Drawable`] that paints every pixel
/// of the area once, two `fill_solid` columns (sky above, ground below) per pixel column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ProfileDrawing<C> {
    terrain: Terrain,
    area: Rectangle,
    /// The lowest and highest heights (Q16.16).
    range: (i32, i32),
    ground: C,
    sky: C,
}

impl<C: PixelColor> ProfileDrawing<C> {
    /// The lowest and highest heights.
    pub fn range(&self) -> (Real, Real) {
        (real_of(self.range.0), real_of(self.range.1))
    }

    /// The row (from the area's top) of the ground's surface at `height`.
    fn row(&self, height: i64) -> u32 {
        let (low, high) = (i64::from(self.range.0), i64::from(self.range.1));
        let rows = i64::from(self.area.size.height) - 1;
        if high == low {
            return (rows / 2) as u32;
        }
        div_narrow((high - height) * rows + (high - low) / 2, high - low) as u32
    }
}

impl<C: PixelColor> Dimensions for ProfileDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> Drawable for ProfileDrawing<C> {
    type Color = C;
    type Output = u64;

    /// Column c covers the profile from c·(n−1)/W to (c+1)·(n−1)/W samples (n samples, W
    /// columns); its ground reaches the highest point of the piecewise-linear profile
    /// there, so no peak is lost when there are more samples than columns. Returns the
    /// samples generated.
    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let Ok(heights) = self.terrain.heights() else {
            return Ok(0);
        };
        let mut heights = heights.raw();
        let width = i64::from(self.area.size.width);
        let intervals = i64::from(self.terrain.samples) - 1;
        // The segment [a, b] of the profile in use: (index, height) of its ends.
        let mut a = (0i64, i64::from(heights.next().unwrap_or(0)));
        let mut b = (1i64, i64::from(heights.next().unwrap_or(0)));
        // The profile at position p/width samples, within segment [a, b] (b one sample
        // on): at its ends, the ends' heights, with no product or division.
        let at = |a: (i64, i64), b: (i64, i64), p: i64| {
            let along = p - a.0 * width;
            if along == 0 {
                a.1
            } else if along == width {
                b.1
            } else {
                a.1 + div_narrow((b.1 - a.1) * along, width)
            }
        };
        for column in 0..width {
            let (from, to) = (column * intervals, (column + 1) * intervals);
            let mut highest = at(a, b, from);
            // Samples inside the column, moving the segment along.
            while b.0 * width <= to && b.0 < intervals {
                highest = highest.max(b.1);
                a = b;
                b = (b.0 + 1, i64::from(heights.next().unwrap_or(0)));
            }
            highest = highest.max(at(a, b, to.min(b.0 * width)));
            let row = self.row(highest);
            let x = self.area.top_left.x + column as i32;
            let top = self.area.top_left.y;
            target.fill_solid(
                &Rectangle::new(Point::new(x, top), Size::new(1, row)),
                self.sky,
            )?;
            target.fill_solid(
                &Rectangle::new(
                    Point::new(x, top + row as i32),
                    Size::new(1, self.area.size.height - row),
                ),
                self.ground,
            )?;
        }
        Ok(u64::from(self.terrain.samples))
    }
}
