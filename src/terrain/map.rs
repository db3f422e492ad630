//! A landscape by diamond-square: the lecture's midpoint displacement in 2D. Heights live
//! in a buffer the caller gives, (2ᵏ + 1)² of them, so its size is the only limit: a
//! square step's value depends on the whole coarser grid around it, so computing a tile
//! from a hash of its position alone would repeat the coarser levels for every tile. The
//! buffer is also what a firmware would keep to redraw a landscape without recomputing it.
//!
//! At level j (σⱼ = σ·rʲ) the diamond step sets each square's centre to the mean of its 4
//! corners plus σⱼ·N(0, 1), and the square step each edge's midpoint to the mean of its
//! neighbours (4 inside; on the border the 3 there are, or, wrapped for tiling, the 4 of
//! the periodic grid) plus σⱼ·N(0, 1). Corners start at σ·N(0, 1) (one shared value when
//! wrapped). Drawn as a [`Relief`]: shaded by height (water, sand, grass, rock, snow)
//! with hill shading lit from the upper left.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::displacement::{displaced, levels_of, Displacement};
use crate::error::{Error, FitError};
use crate::math::random::Seeded;
use crate::render::Relief;

/// A landscape fitted to an area: the shared [`Relief`] drawing of its heights.
pub type MapDrawing<'a, C> = Relief<'a, C>;

/// [`TerrainMap::MAX_LEVELS`], for the crate's own types and arrays.
pub(crate) const MAX_MAP_LEVELS: u32 = 12;

/// A landscape of (2ᵏ + 1)² heights by diamond-square.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TerrainMap {
    /// Roughness, σ and seed.
    pub displacement: Displacement,
    /// Heights along a side: 2ᵏ + 1.
    pub samples: u32,
    /// Whether the landscape tiles (opposite edges equal, the square step wrapping).
    pub wrap: bool,
}

impl TerrainMap {
    /// Most levels of a landscape: (2¹² + 1)² heights (64 MiB of buffer; the buffer limits
    /// it first).
    pub const MAX_LEVELS: u32 = MAX_MAP_LEVELS;

    /// A landscape of `samples`² heights, not wrapped.
    pub const fn new(samples: u32, displacement: Displacement) -> Self {
        Self {
            displacement,
            samples,
            wrap: false,
        }
    }

    /// The same landscape, tiling when `wrap`.
    #[must_use]
    pub const fn wrapped(mut self, wrap: bool) -> Self {
        self.wrap = wrap;
        self
    }

    /// Heights needed in the buffer: `samples`².
    pub const fn cells(&self) -> usize {
        self.samples as usize * self.samples as usize
    }

    /// Fills `heights` (row by row, Q16.16) with the landscape.
    pub fn generate(&self, heights: &mut [i32]) -> Result<(), Error> {
        self.displacement.check()?;
        let levels = levels_of(self.samples, MAX_MAP_LEVELS)?;
        let given = heights.len();
        let heights =
            heights
                .get_mut(..self.cells())
                .ok_or(Error::Fit(FitError::BufferTooSmall {
                    needed: self.cells(),
                    given,
                }))?;
        let n = self.samples as usize;
        let last = n - 1;
        let sigmas = self.displacement.sigmas();
        let seeded = Seeded::new(self.displacement.seed);
        let key = |x: usize, y: usize| (y * n + x) as u32;
        let mut grid = Grid { heights, n };
        let first_sigma = sigmas.first().copied().unwrap_or(0);
        let corner = |x, y| displaced(0, first_sigma, seeded.normal_q16(key(x, y)));
        if self.wrap {
            let shared = corner(0, 0);
            for (x, y) in [(0, 0), (last, 0), (0, last), (last, last)] {
                grid.set(x, y, shared);
            }
        } else {
            for (x, y) in [(0, 0), (last, 0), (0, last), (last, last)] {
                grid.set(x, y, corner(x, y));
            }
        }
        let mut step = last;
        for level in 0..levels as usize {
            let half = step / 2;
            let sigma = sigmas.get(level).copied().unwrap_or(0);
            // Diamond: the centres of the squares.
            for y in (half..last).step_by(step) {
                for x in (half..last).step_by(step) {
                    let sum = grid.get(x - half, y - half)
                        + grid.get(x + half, y - half)
                        + grid.get(x - half, y + half)
                        + grid.get(x + half, y + half);
                    grid.set(
                        x,
                        y,
                        displaced(sum >> 2, sigma, seeded.normal_q16(key(x, y))),
                    );
                }
            }
            // Square: the midpoints of the edges, from their 3 or 4 neighbours.
            for y in (0..=last).step_by(half) {
                let start = if (y / half).is_multiple_of(2) {
                    half
                } else {
                    0
                };
                for x in (start..=last).step_by(step) {
                    if self.wrap && (x == last || y == last) {
                        continue; // copies of row and column 0, set below
                    }
                    let mut sum = 0i64;
                    let mut count = 0i64;
                    let neighbours = [
                        (x as isize - half as isize, y as isize),
                        (x as isize + half as isize, y as isize),
                        (x as isize, y as isize - half as isize),
                        (x as isize, y as isize + half as isize),
                    ];
                    for (nx, ny) in neighbours {
                        let inside = |c: isize| (0..=last as isize).contains(&c);
                        let at = if self.wrap {
                            Some((nx.rem_euclid(last as isize), ny.rem_euclid(last as isize)))
                        } else if inside(nx) && inside(ny) {
                            Some((nx, ny))
                        } else {
                            None
                        };
                        if let Some((nx, ny)) = at {
                            sum += grid.get(nx as usize, ny as usize);
                            count += 1;
                        }
                    }
                    let mean = sum.div_euclid(count.max(1));
                    grid.set(x, y, displaced(mean, sigma, seeded.normal_q16(key(x, y))));
                }
            }
            if self.wrap {
                for i in 0..=last {
                    let (row, column) = (grid.get(i, 0), grid.get(0, i));
                    grid.set(i, last, row as i32);
                    grid.set(last, i, column as i32);
                }
            }
            step = half;
        }
        Ok(())
    }

    /// Generates the landscape into `heights` and fits it to `area` (stretched to fill it).
    pub fn fit<'a, C>(
        &self,
        area: Rectangle,
        heights: &'a mut [i32],
    ) -> Result<MapDrawing<'a, C>, Error>
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

/// The buffer as a square grid.
struct Grid<'a> {
    heights: &'a mut [i32],
    n: usize,
}

impl Grid<'_> {
    fn get(&self, x: usize, y: usize) -> i64 {
        i64::from(self.heights.get(y * self.n + x).copied().unwrap_or(0))
    }

    fn set(&mut self, x: usize, y: usize, value: i32) {
        if let Some(slot) = self.heights.get_mut(y * self.n + x) {
            *slot = value;
        }
    }
}
