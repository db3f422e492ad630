//! The chaos game: from the origin, apply a map chosen at random by its probability, over
//! and over; after the first [`SKIPPED`] points (still on their way to the attractor) every
//! point is on it, within the fixed-point rounding. The same seed plots the same points on
//! every target.
//!
//! A planar picture seen from the front whose maps contract (the lecture's fern, the
//! gasket, most of Fractint's) is fitted to a sample of its game and played in the pixels'
//! own fixed point ([`fast`](super::fast)); any other is fitted by playing the same game
//! (same seed) once to measure the points' extent, then again to draw, every plotted point
//! inside the fitted box, exactly. Both choose the same maps: one generator, one choice.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

#[cfg(doc)]
use super::fast::FIT_POINTS;
use super::fast::{pixel, repeat, sample_box, PixelGame, PixelMaps, FAST_MAPS, SKIPPED, SLOT_MASK};
use super::maps::Ifs;
use crate::error::{only_target_errors, DrawError, Error, FitError, WalkError};
use crate::math::random::Xorshift32;
use crate::math::Real;
use crate::render::density::{Density, HitCount};
use crate::render::fit::DEFAULT_MARGIN;
use crate::render::palette::{Colors, Palette};
use crate::render::projection::Projection;
use crate::render::space::SpaceFit;

/// A plotted point of a chaos game: where, and which map put it there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IfsPoint {
    /// The point (z is 0 for a 2D system).
    pub position: [Real; 3],
    /// The index of the map last applied.
    pub map: usize,
}

/// The points of a chaos game; yields `Err` once (a point beyond the fixed-point range)
/// and ends.
#[derive(Debug, Clone)]
pub struct ChaosGame<'i> {
    ifs: &'i Ifs,
    generator: Xorshift32,
    point: [Real; 3],
    left: u64,
    failed: bool,
}

impl<'i> ChaosGame<'i> {
    /// `points` points of `ifs`'s attractor, seeded with `seed`.
    pub fn new(ifs: &'i Ifs, seed: u64, points: u64) -> Self {
        let mut game = Self {
            ifs,
            generator: Xorshift32::new(seed),
            point: [Real::ZERO; 3],
            left: points,
            failed: false,
        };
        for _ in 0..SKIPPED {
            if game.advance().is_err() {
                game.failed = true;
                game.left = 0;
            }
        }
        game
    }

    fn advance(&mut self) -> Result<IfsPoint, Error> {
        let (map, affine) = self.ifs.choose(self.generator.next_u32());
        self.point = affine
            .apply(self.point)
            .ok_or(Error::Walk(WalkError::Overflow))?;
        Ok(IfsPoint {
            position: self.point,
            map,
        })
    }
}

impl Iterator for ChaosGame<'_> {
    type Item = Result<IfsPoint, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed && self.left == 0 {
            self.failed = false;
            return Some(Err(Error::Walk(WalkError::Overflow)));
        }
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let point = self.advance();
        if point.is_err() {
            self.left = 0;
        }
        Some(point)
    }
}

/// An IFS to draw: its maps, the seed, how many points, and how space is seen.
#[derive(Debug, Clone, Copy)]
pub struct IfsPicture<'i> {
    ifs: &'i Ifs,
    seed: u64,
    points: u64,
    projection: Option<Projection>,
}

impl<'i> IfsPicture<'i> {
    /// `points` points of `ifs`, seed 0; a 2D system seen from the front, a 3D one
    /// isometric.
    pub const fn new(ifs: &'i Ifs, points: u64) -> Self {
        Self {
            ifs,
            seed: 0,
            points,
            projection: None,
        }
    }

    /// Another game: the same seed plots the same points on every target.
    #[must_use]
    pub const fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// How space is seen.
    #[must_use]
    pub const fn with_projection(mut self, projection: Projection) -> Self {
        self.projection = Some(projection);
        self
    }

    /// The projection used.
    pub fn projection(&self) -> Projection {
        self.projection.unwrap_or(if self.ifs.is_3d() {
            Projection::Isometric
        } else {
            Projection::Front
        })
    }

    /// The points it plots.
    pub fn game(&self) -> ChaosGame<'i> {
        ChaosGame::new(self.ifs, self.seed, self.points)
    }

    /// Scales and centres the attractor into `area` (less a margin), each point coloured
    /// by the map that put it there.
    pub fn fit<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
    ) -> Result<IfsDrawing<'i, Colors<'p, C>>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let palette = Colors::new(palette).ok_or(Error::Fit(FitError::EmptyPalette))?;
        let (space, fast) = self.space(&area)?;
        Ok(IfsDrawing {
            picture: *self,
            space,
            palette,
            fast,
        })
    }

    /// The fit, and for a planar picture from the front whose maps (at most
    /// [`FAST_MAPS`]) contract, the game in pixel space: fitted to the box of the first
    /// [`FIT_POINTS`] points and the maps' fixed points. Any other picture
    /// is fitted to its whole game, played once to measure.
    fn space(&self, area: &Rectangle) -> Result<(SpaceFit, Option<PixelMaps>), Error> {
        if self.projection() == Projection::Front && !self.ifs.is_3d() {
            if let Some((low, high)) = sample_box(self.ifs, self.seed, self.points) {
                let space = SpaceFit::front_box(low, high, area, DEFAULT_MARGIN)?;
                let fast = space
                    .front_linear()
                    .and_then(|(scale, origin)| PixelMaps::new(self.ifs, scale, origin));
                if fast.is_some() {
                    return Ok((space, fast));
                }
            }
        }
        let space = SpaceFit::new(
            || self.game().map(|point| point.map(|p| [p.position])),
            self.projection(),
            false,
            area,
            DEFAULT_MARGIN,
        )?;
        Ok((space, None))
    }
}

impl<'i> IfsPicture<'i> {
    /// Like [`fit`](Self::fit), coloured by density: each pixel of `area` by how many
    /// points hit it, on a log scale ([`DENSITY_LEVELS`](crate::render::DENSITY_LEVELS)) through `palette` (value 0 for
    /// none, up to `DENSITY_LEVELS - 1`, of `DENSITY_LEVELS`). The hit counts go in
    /// `counts`, one cell a pixel of `area` (its only memory; `u16` cells count to 65,535,
    /// `u8` ones to 255 in half the memory);
    /// every pixel of `area` is written, a row at a time.
    pub fn fit_density<'b, P: Palette, T: HitCount>(
        &self,
        area: Rectangle,
        palette: P,
        counts: &'b mut [T],
    ) -> Result<DensityDrawing<'i, 'b, P, T>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let density = Density::new(area, counts)?;
        let (space, fast) = self.space(&area)?;
        Ok(DensityDrawing {
            picture: *self,
            space,
            palette,
            density,
            fast,
        })
    }
}

/// An IFS fitted and coloured by density: an embedded-graphics [`Drawable`].
#[derive(Debug)]
pub struct DensityDrawing<'i, 'b, P, T = u16> {
    picture: IfsPicture<'i>,
    space: SpaceFit,
    palette: P,
    density: Density<'b, T>,
    fast: Option<PixelMaps>,
}

impl<P: Palette, T: HitCount> DensityDrawing<'_, '_, P, T> {
    /// Counts the hits, then writes every pixel of the area a row at a time; returns the
    /// points played.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<u64, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        self.density.clear();
        let mut played = 0;
        if let Some(maps) = &self.fast {
            let area = self.density.area().top_left;
            let mut game = maps.game(self.picture.seed);
            repeat(self.picture.points, || {
                let (x, y) = pixel(game.next_point().1);
                // Outside the area: a column or row beyond its size, or wrapped negative.
                self.density
                    .hit_at(x.wrapping_sub(area.x) as u32, y.wrapping_sub(area.y) as u32);
            });
            played = self.picture.points;
        } else {
            for point in self.picture.game() {
                let (pixel, _) = self.space.place(point?.position);
                self.density.hit(pixel);
                played += 1;
            }
        }
        self.density
            .emit(&self.palette, target)
            .map_err(DrawError::Target)?;
        Ok(played)
    }
}

impl<P, T: HitCount> Dimensions for DensityDrawing<'_, '_, P, T> {
    fn bounding_box(&self) -> Rectangle {
        self.density.area()
    }
}

impl<P: Palette, T: HitCount> Drawable for DensityDrawing<'_, '_, P, T> {
    type Color = P::Color;
    type Output = u64;

    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}

/// A fitted IFS: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct IfsDrawing<'i, P> {
    picture: IfsPicture<'i>,
    space: SpaceFit,
    palette: P,
    fast: Option<PixelMaps>,
}

impl<P: Palette> IfsDrawing<'_, P> {
    /// Plots the points (one pixel each: the points are scattered, so there are no runs),
    /// reporting the game's errors too; returns how many were plotted.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<u64, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let clip = target.bounding_box();
        if let Some(maps) = &self.fast {
            return self.draw_fast(maps, target, &clip);
        }
        let mut plotted = 0;
        for point in self.picture.game() {
            let point = point?;
            let (pixel, depth) = self.space.place(point.position);
            let index = u16::try_from(point.map).unwrap_or(u16::MAX);
            let (value, max) = self.space.color_value(depth, index);
            if clip.contains(pixel) {
                target
                    .fill_solid(
                        &Rectangle::new(pixel, Size::new(1, 1)),
                        self.palette.color(value, max),
                    )
                    .map_err(DrawError::Target)?;
            }
            plotted += 1;
        }
        Ok(plotted)
    }
}

impl<P: Palette> IfsDrawing<'_, P> {
    /// The game in pixel space: each point a pixel in its map's colour through `draw_iter`
    /// (scattered points make no runs), clipped to `clip`.
    fn draw_fast<D>(
        &self,
        maps: &PixelMaps,
        target: &mut D,
        clip: &Rectangle,
    ) -> Result<u64, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let colors: [P::Color; FAST_MAPS] = core::array::from_fn(|map| {
            self.palette
                .color(u16::try_from(map).unwrap_or(u16::MAX), u16::MAX)
        });
        // The game's pixels go to the target as one iterator: a call a point would cost
        // more than the point.
        let pixels = FastPixels {
            game: maps.game(self.picture.seed),
            left: self.picture.points,
            clip: (clip.top_left, clip.size),
            colors,
        };
        target.draw_iter(pixels).map_err(DrawError::Target)?;
        Ok(self.picture.points)
    }
}

/// The pixels of a chunk of the game in pixel space, in their maps' colours, those
/// outside the clip skipped. Owns what it reads, so that the loop keeps it in registers.
struct FastPixels<'m, C> {
    game: PixelGame<'m>,
    /// Points still to play.
    left: u64,
    clip: (Point, Size),
    colors: [C; FAST_MAPS],
}

impl<C: PixelColor> Iterator for FastPixels<'_, C> {
    type Item = Pixel<C>;

    #[inline]
    fn next(&mut self) -> Option<Pixel<C>> {
        let (corner, size) = self.clip;
        while self.left > 0 {
            self.left -= 1;
            let (map, point) = self.game.next_point();
            let (x, y) = pixel(point);
            // Wrapped: a point left of or above the clip is a large column or row.
            let inside = (x.wrapping_sub(corner.x) as u32) < size.width
                && (y.wrapping_sub(corner.y) as u32) < size.height;
            if let (true, Some(&color)) = (inside, self.colors.get(map & SLOT_MASK)) {
                return Some(Pixel(Point::new(x, y), color));
            }
        }
        None
    }
}

impl<P> Dimensions for IfsDrawing<'_, P> {
    fn bounding_box(&self) -> Rectangle {
        self.space.bounding_box
    }
}

impl<P: Palette> Drawable for IfsDrawing<'_, P> {
    type Color = P::Color;
    type Output = u64;

    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}
