//! An attractor on a target: its orbit placed through a projection, fitted from the
//! orbit's first points, drawn as points or by density.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::fixed::to_real;
use super::kind::Kind;
use super::orbit::{plane, Attractor, Orbit, Settled};
use super::place::Placer;
use super::step::State;
use crate::error::{only_target_errors, DrawError, Error, FitError};
use crate::math::trig::BinaryAngle;
use crate::math::Real;
use crate::render::density::{Density, HitCount};
use crate::render::fit::DEFAULT_MARGIN;
use crate::render::palette::Palette;
use crate::render::projection::Projection;
use crate::render::reach::Reach;
use crate::render::space::SpaceFit;

/// The transient skipped by default: the steps from the start before the first plotted
/// point (enough for the defaults' orbits to reach their attractors).
pub const DEFAULT_SKIP: u64 = 1000;

/// How many of the first points plotted (or all, if fewer) the picture is fitted to.
///
/// For an attractor that its orbit fills within its first points (all but those whose
/// orbits [spread](super::Kind::spreads)): one short pass instead of a second full orbit.
/// The rest of the orbit is drawn where it lands; a point outside the fitted box is
/// clipped and counted in [`AttractorStats::outside`]. A spreading orbit is fitted whole.
pub const FIT_POINTS: u64 = 1 << 12;

/// What a drawing did: points plotted, and how many of them fell outside the target.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AttractorStats {
    /// Points computed and placed (after the skipped transient).
    pub points: u64,
    /// Of those, how many landed outside the target (clipped).
    pub outside: u64,
}

/// An attractor to draw: how many points after which transient, and how space is seen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AttractorPicture {
    attractor: Attractor,
    skip: u64,
    points: u64,
    projection: Projection,
    turn: (i32, i32),
}

impl AttractorPicture {
    /// `points` points of `attractor` after [`DEFAULT_SKIP`] steps, seen from the front.
    ///
    /// A flow or Pickover's map is placed in space with its z up (picture y) and its y
    /// away from the viewer, so the Lorenz butterfly shows its wings from the front.
    pub fn new(attractor: Attractor, points: u64) -> Self {
        Self {
            attractor,
            skip: DEFAULT_SKIP,
            points,
            projection: Projection::Front,
            turn: (1 << 30, 0),
        }
    }

    /// Another transient: `skip` steps before the first point (0: the start is plotted).
    #[must_use]
    pub const fn with_skip(mut self, skip: u64) -> Self {
        self.skip = skip;
        self
    }

    /// How space is seen (a 2D attractor is drawn in its plane whatever this is).
    #[must_use]
    pub const fn with_projection(mut self, projection: Projection) -> Self {
        self.projection = projection;
        self
    }

    /// Turns a 3D attractor about its vertical axis by `degrees` before projecting it
    /// (what `animate attractor` steps through).
    #[must_use]
    pub fn with_turn(mut self, degrees: Real) -> Self {
        self.turn = BinaryAngle::from_degrees_bits(degrees.to_bits()).cos_sin();
        self
    }

    /// The attractor.
    pub fn attractor(&self) -> &Attractor {
        &self.attractor
    }

    /// The points it plots, in the attractor's units.
    pub fn orbit(&self) -> Orbit {
        self.attractor.orbit(self.skip, self.points)
    }

    /// The points it plots, from where the fit `settled` them.
    fn orbit_after(&self, settled: Settled) -> Orbit {
        self.attractor.orbit_from(settled, self.points)
    }

    /// A state as a point of picture space.
    #[inline]
    fn in_space(&self, state: State) -> [Real; 3] {
        let [x, y, z] = self.attractor.real(state);
        if self.attractor.kind().dimensions() == 2 {
            return [x, y, Real::ZERO];
        }
        // z up, y away; then the turn about the vertical axis.
        let (cos, sin) = self.turn;
        let depth = Real::from_bits(y.to_bits().saturating_neg());
        [
            x.mul_q30(cos).saturating_add(depth.mul_q30(sin)),
            z,
            depth.mul_q30(cos).saturating_sub(x.mul_q30(sin)),
        ]
    }

    fn projection(&self) -> Projection {
        if self.attractor.kind().dimensions() == 2 {
            Projection::Front
        } else {
            self.projection
        }
    }

    /// True where the picture is a plane of the state seen from the front (a 2D kind, or
    /// a 3D one from the front unturned): its points are placed in the orbit's own fixed
    /// point.
    fn planar(&self) -> bool {
        self.attractor.kind().dimensions() == 2
            || (self.projection == Projection::Front && self.turn == (1 << 30, 0))
    }

    /// The points the fit measures: the first [`FIT_POINTS`], or every point of an orbit
    /// that spreads.
    fn sample(&self) -> u64 {
        if self.attractor.kind().spreads() {
            self.points
        } else {
            self.points.min(FIT_POINTS)
        }
    }

    /// Where the orbit starts past its transient, and the fit, scaled and centred in
    /// `area` less a margin, with a planar picture's placement in the orbit's fixed point.
    fn settled_space(
        &self,
        area: &Rectangle,
    ) -> Result<(Settled, SpaceFit, Option<Placer>), Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        if self.planar() {
            if let Some(fitted) = self.planar_space(area)? {
                return Ok(fitted);
            }
        }
        let settled = self.attractor.settled(self.skip, self.points)?;
        let sample = self.sample();
        let space = SpaceFit::new(
            || {
                let mut orbit = self.attractor.orbit_from(settled, sample);
                core::iter::from_fn(move || orbit.next_state())
                    .map(|state| state.map(|state| [self.in_space(state)]))
            },
            self.projection(),
            false,
            area,
            DEFAULT_MARGIN,
        )?;
        Ok((settled, space, None))
    }

    /// A planar picture's fit from the sample's box, measured in state bits (no `Real`
    /// a point), with the first point it meets; `None` for a picture of no points.
    fn planar_space(
        &self,
        area: &Rectangle,
    ) -> Result<Option<(Settled, SpaceFit, Option<Placer>)>, Error> {
        let mut seen: Option<(State, [Reach; 2])> = None;
        self.attractor
            .orbit(self.skip, self.sample())
            .run(|[u, v], state| {
                let (_, [across, up]) = seen.get_or_insert((state, [Reach::of(u), Reach::of(v)]));
                across.widen(u);
                up.widen(v);
            })?;
        let Some((first, [across, up])) = seen else {
            return Ok(None);
        };
        let (low, high) = ([across.low, up.low], [across.high(), up.high()]);
        let bits = self.attractor.kind().fraction_bits();
        let real = |[u, v]: [i32; 2]| [to_real(u, bits), to_real(v, bits), Real::ZERO];
        let space = SpaceFit::front_box(real(low), real(high), area, DEFAULT_MARGIN)?;
        let placer = Placer::new(
            &space,
            (low, high),
            bits,
            (
                (area.top_left.x, area.top_left.y),
                (area.size.width, area.size.height),
            ),
        );
        let settled = Settled::new(first, self.skip);
        Ok(Some((settled, space, placer)))
    }

    /// Fitted into `area`, each point a pixel of `color`.
    pub fn fit<C: PixelColor>(
        &self,
        area: Rectangle,
        color: C,
    ) -> Result<AttractorDrawing<C>, Error> {
        let (settled, space, placer) = self.settled_space(&area)?;
        Ok(AttractorDrawing {
            picture: *self,
            settled,
            space,
            placer,
            area,
            color,
        })
    }

    /// Fitted into `area` and coloured by density: each pixel by how many points hit it,
    /// on a log scale through `palette` (as the IFS's density pictures). The counts go in
    /// `counts`, a cell a pixel of `area` (its only memory: `u16` or, in half the
    /// memory, `u8`); every pixel of `area` is written, a row at a time.
    pub fn fit_density<'b, P: Palette, T: HitCount>(
        &self,
        area: Rectangle,
        palette: P,
        counts: &'b mut [T],
    ) -> Result<AttractorDensity<'b, P, T>, Error> {
        let (settled, space, placer) = self.settled_space(&area)?;
        Ok(AttractorDensity {
            picture: *self,
            settled,
            space,
            placer,
            palette,
            density: Density::new(area, counts)?,
        })
    }
}

/// The picture plane's coordinates of a state seen from the front: x and y, or for a 3D
/// kind x and z (z up).
#[inline(always)]
fn planar(kind: Kind, state: State) -> [i32; 2] {
    if kind.dimensions() == 2 {
        plane::<false>(state)
    } else {
        plane::<true>(state)
    }
}

/// An attractor fitted to a target, a pixel a point: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct AttractorDrawing<C> {
    picture: AttractorPicture,
    /// Where the orbit starts past its transient (taken once, by the fit).
    settled: Settled,
    space: SpaceFit,
    placer: Option<Placer>,
    area: Rectangle,
    color: C,
}

impl<C: PixelColor> AttractorDrawing<C> {
    /// Plots the points (one pixel each), reporting an orbit that leaves its range too.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<AttractorStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = C>,
    {
        let clip = target.bounding_box();
        let mut stats = AttractorStats::default();
        let mut orbit = self.picture.orbit_after(self.settled);
        let kind = self.picture.attractor.kind();
        while let Some(state) = orbit.next_state() {
            let state = state?;
            let pixel = match self.placer {
                Some(placer) => {
                    let [u, v] = planar(kind, state);
                    placer.place(u, v).map(|(column, row)| {
                        self.area.top_left + Point::new(column as i32, row as i32)
                    })
                }
                None => Some(self.space.place(self.picture.in_space(state)).0),
            };
            let pixel = pixel.filter(|pixel| clip.contains(*pixel));
            if let Some(pixel) = pixel {
                target
                    .fill_solid(&Rectangle::new(pixel, Size::new(1, 1)), self.color)
                    .map_err(DrawError::Target)?;
            } else {
                stats.outside += 1;
            }
            stats.points += 1;
        }
        Ok(stats)
    }
}

impl<C> Dimensions for AttractorDrawing<C> {
    fn bounding_box(&self) -> Rectangle {
        self.space.bounding_box
    }
}

impl<C: PixelColor> Drawable for AttractorDrawing<C> {
    type Color = C;
    type Output = AttractorStats;

    fn draw<D>(&self, target: &mut D) -> Result<AttractorStats, D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        only_target_errors(self.try_draw(target))
    }
}

/// An attractor fitted and coloured by density: an embedded-graphics [`Drawable`].
#[derive(Debug)]
pub struct AttractorDensity<'b, P, T = u16> {
    picture: AttractorPicture,
    /// Where the orbit starts past its transient (taken once, by the fit).
    settled: Settled,
    space: SpaceFit,
    placer: Option<Placer>,
    palette: P,
    density: Density<'b, T>,
}

impl<P: Palette, T: HitCount> AttractorDensity<'_, P, T> {
    /// Counts the hits, then writes every pixel of the area a row at a time.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<AttractorStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        self.density.clear();
        let mut stats = AttractorStats::default();
        let mut orbit = self.picture.orbit_after(self.settled);
        match self.placer {
            Some(placer) => {
                let count = orbit.remaining();
                orbit.run(|[u, v], _| {
                    let hit = match placer.cell(u, v) {
                        Some(cell) => self.density.hit_cell(cell as usize),
                        None => false,
                    };
                    if !hit {
                        stats.outside += 1;
                    }
                })?;
                stats.points = count;
            }
            None => {
                while let Some(state) = orbit.next_state() {
                    let (pixel, _) = self.space.place(self.picture.in_space(state?));
                    stats.outside += u64::from(!self.density.hit(pixel));
                    stats.points += 1;
                }
            }
        }
        self.density
            .emit(&self.palette, target)
            .map_err(DrawError::Target)?;
        Ok(stats)
    }
}

impl<P, T: HitCount> Dimensions for AttractorDensity<'_, P, T> {
    fn bounding_box(&self) -> Rectangle {
        self.density.area()
    }
}

impl<P: Palette, T: HitCount> Drawable for AttractorDensity<'_, P, T> {
    type Color = P::Color;
    type Output = AttractorStats;

    fn draw<D>(&self, target: &mut D) -> Result<AttractorStats, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::attractor::Attractor;
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;

    /// The pixels a drawing lights, by the orbit's own placement or by `Real`s through the
    /// projection.
    fn lit(drawing: &AttractorDrawing<BinaryColor>) -> MockDisplay<BinaryColor> {
        let mut display = MockDisplay::new();
        display.set_allow_overdraw(true);
        drawing.try_draw(&mut display).unwrap();
        display
    }

    /// Placing in the orbit's fixed point lights the pixels the projection does, for
    /// every kind seen from the front.
    #[test]
    fn fixed_point_placement_is_the_projections() {
        for kind in Kind::ALL {
            // More points than the fit measures: some land beyond its box, inside the area.
            let picture = AttractorPicture::new(Attractor::new(kind), 3 * FIT_POINTS);
            let fast = picture
                .fit(
                    Rectangle::new(Point::new(3, 5), Size::new(57, 41)),
                    BinaryColor::On,
                )
                .unwrap();
            assert!(fast.placer.is_some(), "{}", kind.name());
            let slow = AttractorDrawing {
                placer: None,
                ..fast
            };
            assert_eq!(lit(&fast), lit(&slow), "{}", kind.name());
        }
    }
}
