//! Escape-time fractals as embedded-graphics drawables: dwells through a palette into any
//! `DrawTarget`, rows and tiles by `fill_contiguous`, uniform blocks by `fill_solid`.

use embedded_graphics::{prelude::*, primitives::Rectangle};

use super::render::{Algorithm, Render, RenderStats};
use super::scaled::ReferencePoint;
use super::view::View;
use crate::error::DrawError;
use crate::render::palette::Palette;
use crate::render::sink::DwellSink;

/// A [`DwellSink`] that paints into a display through a palette.
#[derive(Debug)]
pub struct Painter<'t, D, P> {
    target: &'t mut D,
    palette: P,
    max: u16,
}

impl<'t, D, P> Painter<'t, D, P>
where
    D: DrawTarget,
    P: Palette<Color = D::Color>,
{
    /// Paints `view`'s values into `target` with `palette` (dwells, or smooth values, as
    /// the view's [`Shading`](crate::escape::Shading) says).
    pub fn new(target: &'t mut D, palette: P, view: &View) -> Self {
        Self {
            target,
            palette,
            max: view.inside_value(),
        }
    }
}

impl<D, P> DwellSink for Painter<'_, D, P>
where
    D: DrawTarget,
    P: Palette<Color = D::Color> + Copy,
{
    type Error = D::Error;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), D::Error> {
        // A copy, not a reference to the field: the run's loop then reads the palette
        // itself, not a pointer to a pointer to it, for every pixel.
        let (palette, max) = (self.palette, self.max);
        self.target
            .fill_contiguous(area, dwells.map(move |dwell| palette.color(dwell, max)))
    }

    fn uniform(&mut self, area: &Rectangle, dwell: u16) -> Result<(), D::Error> {
        self.target
            .fill_solid(area, self.palette.color(dwell, self.max))
    }
}

/// A Mandelbrot or Julia picture with its palette: an embedded-graphics [`Drawable`] whose
/// top-left corner is the target's origin (use `translated` to move it).
#[derive(Debug, Clone, Copy)]
pub struct EscapeTime<P> {
    view: View,
    algorithm: Algorithm,
    palette: P,
}

impl<P: Palette> EscapeTime<P> {
    /// `view` drawn with `palette`, by the default (fast) algorithm.
    pub const fn new(view: View, palette: P) -> Self {
        Self {
            view,
            algorithm: Algorithm::Fast,
            palette,
        }
    }

    /// Chooses how pixels are scheduled.
    #[must_use]
    pub const fn with_algorithm(mut self, algorithm: Algorithm) -> Self {
        self.algorithm = algorithm;
        self
    }

    /// The view.
    pub const fn view(&self) -> &View {
        &self.view
    }

    /// A render to run in steps from a main loop (see [`Render::step`]).
    pub fn render(&self) -> Render<'static> {
        Render::new(self.view, self.algorithm)
    }

    /// Draws a Mandelbrot view by perturbation (what a [`Tier::Perturbation`] view
    /// needs), its reference orbit in `storage`: at least
    /// [`ReferenceOrbit::points_needed`](crate::escape::ReferenceOrbit::points_needed) points.
    ///
    /// [`Tier::Perturbation`]: crate::escape::Tier::Perturbation
    pub fn draw_perturbed<D>(
        &self,
        target: &mut D,
        storage: &mut [ReferencePoint],
    ) -> Result<RenderStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let mut render = Render::perturbed(self.view, self.algorithm, storage)?;
        let mut painter = Painter::new(target, &self.palette, &self.view);
        render.run(&mut painter).map_err(DrawError::Target)
    }
}

impl<P: Palette> Drawable for EscapeTime<P> {
    type Color = P::Color;
    type Output = RenderStats;

    fn draw<D>(&self, target: &mut D) -> Result<RenderStats, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let mut painter = Painter::new(target, &self.palette, &self.view);
        self.render().run(&mut painter)
    }
}

impl<P> Dimensions for EscapeTime<P> {
    fn bounding_box(&self) -> Rectangle {
        Rectangle::new(Point::zero(), self.view.size())
    }
}
