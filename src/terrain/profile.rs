//! A mountain profile by 1D midpoint displacement, generated left to right with a stack of
//! one pending right end per level (k + 1 entries for 2ᵏ + 1 samples), so a profile of any
//! length needs no buffer; drawn as one column of ground and one of sky per pixel column.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::displacement::{
    displaced, levels_of, real_of, Displacement, MAX_END, MAX_TERRAIN_LEVELS,
};
use crate::error::{Error, FitError, ParameterError};
use crate::math::divide::div_narrow;
use crate::math::random::Seeded;
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

    /// Checks every parameter; returns the number of levels. Out of line: both ways of
    /// generating the heights call it.
    #[inline(never)]
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
    /// Needs no buffer: the heights are generated once to fit and again to draw (see
    /// [`fit_with_heights`](Self::fit_with_heights) to generate them once).
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        ground: C,
        sky: C,
    ) -> Result<ProfileDrawing<'static, C>, Error> {
        check_area(area)?;
        let range = range_of(self.heights()?.raw());
        Ok(ProfileDrawing {
            terrain: *self,
            area,
            range,
            ground,
            sky,
            stored: None,
        })
    }

    /// Like [`fit`](Self::fit), with the heights kept in the caller's `heights` (at least
    /// [`samples`](Self::samples) long, 4 bytes a sample): generated once, not once to fit
    /// and again to draw. The same picture.
    pub fn fit_with_heights<'a, C: PixelColor>(
        &self,
        area: Rectangle,
        ground: C,
        sky: C,
        heights: &'a mut [i32],
    ) -> Result<ProfileDrawing<'a, C>, Error> {
        check_area(area)?;
        let stored = self.generate(heights)?;
        Ok(ProfileDrawing {
            terrain: *self,
            area,
            range: range_of(stored.iter().copied()),
            ground,
            sky,
            stored: Some(stored),
        })
    }

    /// The heights (Q16.16, left to right) written into the first `samples` of `heights`,
    /// a level at a time, coarsest first. Each midpoint's deviate is keyed by its index,
    /// so the values are [`heights`](Self::heights)'s, which generates them depth first.
    fn generate<'a>(&self, heights: &'a mut [i32]) -> Result<&'a [i32], Error> {
        let levels = self.check()?;
        let (needed, given) = (self.samples as usize, heights.len());
        let heights = heights
            .get_mut(..needed)
            .ok_or(Error::Fit(FitError::BufferTooSmall { needed, given }))?;
        let q16 = |end: Real| (end.to_bits() >> 16) as i32;
        if let Some(first) = heights.first_mut() {
            *first = q16(self.ends.0);
        }
        if let Some(last) = heights.last_mut() {
            *last = q16(self.ends.1);
        }
        let (seeded, sigmas) = (
            Seeded::new(self.displacement.seed),
            self.displacement.sigmas(),
        );
        // A span of 2^k samples splits at level `levels` − k.
        for (level, &sigma) in (0..levels).zip(sigmas.iter()) {
            let span = 1usize << (levels - level);
            let half = span / 2;
            let mut left = 0;
            while let (Some(&l), Some(&r)) = (heights.get(left), heights.get(left + span)) {
                let mean = (i64::from(l) + i64::from(r)) >> 1;
                let middle = left + half;
                if let Some(slot) = heights.get_mut(middle) {
                    *slot = displaced(mean, sigma, seeded.normal_q16(middle as u32));
                }
                left += span;
            }
        }
        Ok(heights)
    }
}

/// An area with no pixels is refused.
fn check_area(area: Rectangle) -> Result<(), Error> {
    if area.size.width == 0 || area.size.height == 0 {
        return Err(Error::Fit(FitError::ZeroSizeTarget));
    }
    Ok(())
}

/// The lowest and highest of `heights`.
fn range_of(heights: impl Iterator<Item = i32>) -> (i32, i32) {
    heights.fold((i32::MAX, i32::MIN), |(low, high), height| {
        (low.min(height), high.max(height))
    })
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
pub struct ProfileDrawing<'a, C> {
    terrain: Terrain,
    area: Rectangle,
    /// The lowest and highest heights (Q16.16).
    range: (i32, i32),
    ground: C,
    sky: C,
    /// The heights, where the caller keeps them ([`Terrain::fit_with_heights`]); else
    /// they are generated again as the columns are drawn.
    stored: Option<&'a [i32]>,
}

impl<C: PixelColor> ProfileDrawing<'_, C> {
    /// The lowest and highest heights.
    pub fn range(&self) -> (Real, Real) {
        (real_of(self.range.0), real_of(self.range.1))
    }

    /// The columns from `heights`, left to right (one copy of the loop for either
    /// source of heights).
    ///
    /// Column c covers the profile from c·(n−1)/W to (c+1)·(n−1)/W samples (n samples, W
    /// columns); its ground reaches the highest point of the piecewise-linear profile
    /// there, so no peak is lost when there are more samples than columns. Positions are
    /// in W-ths of a sample, stepped by additions.
    #[inline(never)]
    fn draw_columns<D>(
        &self,
        heights: &mut dyn Iterator<Item = i32>,
        target: &mut D,
    ) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let width = i64::from(self.area.size.width);
        let intervals = i64::from(self.terrain.samples) - 1;
        // The segment [a, b] of the profile in use: the position and height of its ends,
        // and b's index.
        let mut a = (0i64, heights.next().unwrap_or(0));
        let mut b = (width, heights.next().unwrap_or(0));
        let mut b_index = 1;
        // The profile at position p, within segment [a, b]: at its ends, the ends'
        // heights, with no product or division; between them, between their heights.
        let at = |a: (i64, i32), b: (i64, i32), p: i64| {
            let along = p - a.0;
            if along == 0 {
                a.1
            } else if along == width {
                b.1
            } else {
                let (low, high) = (i64::from(a.1), i64::from(b.1));
                (low + div_narrow((high - low) * along, width)) as i32
            }
        };
        let row_of = RowOf::new(self.range, self.area.size.height);
        let (x, top) = (self.area.top_left.x, self.area.top_left.y);
        let mut paint = |column: u32, highest: i32| {
            let row = row_of.row(highest);
            let x = x.wrapping_add(column as i32);
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
            )
        };
        if intervals == width {
            // One sample a column: column c spans samples c and c + 1 exactly, and its
            // highest point is the higher of theirs (what the general loop finds).
            let mut left = a.1;
            let mut right = b.1;
            for column in 0..self.area.size.width {
                paint(column, left.max(right))?;
                left = right;
                right = heights.next().unwrap_or(0);
            }
            return Ok(u64::from(self.terrain.samples));
        }
        let mut from = 0;
        for column in 0..self.area.size.width {
            let to = from + intervals;
            let mut highest = at(a, b, from);
            // Samples inside the column, moving the segment along.
            while b.0 <= to && b_index < intervals {
                highest = highest.max(b.1);
                a = b;
                b = (b.0 + width, heights.next().unwrap_or(0));
                b_index += 1;
            }
            highest = highest.max(at(a, b, to.min(b.0)));
            from = to;
            paint(column, highest)?;
        }
        Ok(u64::from(self.terrain.samples))
    }
}

/// The row (from the area's top) of the ground's surface at a height:
/// ⌊((high − height)·last_row + ⌊(high − low)/2⌋) / (high − low)⌋, the middle row where
/// the profile is flat.
#[derive(Debug, Clone, Copy)]
struct RowOf {
    range: (i32, i32),
    /// The area's last row: its height less one.
    last_row: i64,
    /// Every numerator fits 32 bits (one 32-bit product and division a column).
    narrow: bool,
}

impl RowOf {
    fn new(range: (i32, i32), height: u32) -> Self {
        let last_row = i64::from(height) - 1;
        let span = i64::from(range.1) - i64::from(range.0);
        Self {
            range,
            last_row,
            narrow: span
                .checked_mul(last_row)
                .and_then(|product| product.checked_add(span / 2))
                .is_some_and(|numerator| i32::try_from(numerator).is_ok())
                && i32::try_from(span).is_ok(),
        }
    }

    #[inline(always)]
    fn row(&self, height: i32) -> u32 {
        let (low, high) = self.range;
        if high == low {
            return (self.last_row / 2) as u32;
        }
        if self.narrow {
            // high − height is within the span, so each term fits as the whole does.
            let span = high.wrapping_sub(low);
            let numerator = high.wrapping_sub(height) * self.last_row as i32 + span / 2;
            return (numerator / span) as u32;
        }
        let (low, high) = (i64::from(low), i64::from(high));
        div_narrow(
            (high - i64::from(height)) * self.last_row + (high - low) / 2,
            high - low,
        ) as u32
    }
}

impl<C: PixelColor> Dimensions for ProfileDrawing<'_, C> {
    fn bounding_box(&self) -> Rectangle {
        self.area
    }
}

impl<C: PixelColor> Drawable for ProfileDrawing<'_, C> {
    type Color = C;
    type Output = u64;

    /// Draws the columns (see [`Terrain::fit`]). Returns the samples used.
    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        match self.stored {
            Some(stored) => self.draw_columns(&mut stored.iter().copied(), target),
            None => {
                let Ok(heights) = self.terrain.heights() else {
                    return Ok(0);
                };
                self.draw_columns(&mut heights.raw(), target)
            }
        }
    }
}
