//! Drawing parametric systems: the derived modules read as turtle commands in ABOP's
//! notation, `F(l)` and `f(l)` a step of `l` units, `+(a)` and `-(a)` a turn of `a` degrees
//! (without a parameter: one step, the system's angle), `|`, `[`, `]`; fitted and drawn
//! like every L-system (a sizing walk, a checking walk in pixels, the draw).

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::action::command;
use super::context::MAX_CONTEXT_SLOTS;
use super::environment::{Environment, Held};
use super::grammar::ParametricGrammar;
use super::kept::{measure_keeping, Projected, Replay, StoredMark};
use super::marks::{MarkPoints, Marks3, Segments3, WalkOptions};
use super::paint::{paint, Flat, Lighting, Lit};
use super::tropism::{Tropism, Wind};
use super::walker::ParametricWalker;
use crate::error::{DrawError, Error, FitError};
use crate::lsystem::alphabet::Dialect;
use crate::lsystem::drawing::{colors, only_target_errors};
use crate::lsystem::pen::Pen;
use crate::lsystem::segments::{next_segment, WalkStats};
use crate::lsystem::sizing::{fitted_start, measure, pixel_box, Bounds};
use crate::lsystem::turtle::{Segment, Start, Turtle, DEFAULT_STACK};
use crate::lsystem::walker::{check_order, DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::math::Real;
use crate::render::depth::{DepthTested, Layered, Unsorted};
use crate::render::fit::{Orientation, DEFAULT_MARGIN};
use crate::render::palette::{Colors, Palette};
use crate::render::projection::Projection;
use crate::render::shade::Shade;
use crate::render::space::SpaceFit;
#[cfg(doc)]
use crate::render::space::DEPTH_LEVELS;

/// The segments a parametric system draws at an order, computed on the fly.
#[derive(Debug, Clone)]
pub struct ParametricSegments<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    walker: ParametricWalker<'g, DEPTH, SLOTS>,
    turtle: Turtle<'g, STACK>,
    segments: u64,
    failed: bool,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    ParametricSegments<'g, DEPTH, STACK, SLOTS>
{
    /// The segments of `grammar` at `order` from `start`.
    pub fn new(grammar: &'g ParametricGrammar, order: u32, start: Start) -> Result<Self, Error> {
        Ok(Self {
            walker: ParametricWalker::new(grammar, order)?.drawing(),
            turtle: Turtle::new(grammar.headings(), Dialect::Abop, start, false)?,
            segments: 0,
            failed: false,
        })
    }

    fn budget(mut self, symbols: u64) -> Self {
        self.walker = self.walker.with_budget(symbols);
        self
    }

    fn growing(mut self, growth: Option<Real>) -> Self {
        if let Some(fraction) = growth {
            self.walker = self.walker.growing(fraction);
        }
        self
    }

    /// Segments drawn so far.
    pub const fn segments(&self) -> u64 {
        self.segments
    }
}

impl<const DEPTH: usize, const STACK: usize, const SLOTS: usize> Iterator
    for ParametricSegments<'_, DEPTH, STACK, SLOTS>
{
    type Item = Result<Segment, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let (walker, turtle) = (&mut self.walker, &mut self.turtle);
        next_segment(&mut self.failed, &mut self.segments, || {
            Some(
                walker
                    .next()?
                    .and_then(|module| turtle.execute(command(&module))),
            )
        })
    }
}

/// A parametric system at an order, ready to be fitted to a target.
#[derive(Debug, Clone, Copy)]
pub struct ParametricLSystem<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    grammar: &'g ParametricGrammar,
    order: u32,
    orientation: Orientation,
    budget: u64,
    /// How a 3D system is seen (`None`: isometric if it turns in space, else 2D).
    projection: Option<Projection>,
    depth_cue: bool,
    environment: Option<Held<'g>>,
    /// A tropism in place of the system's own (`Some(None)`: none).
    tropism: Option<Option<Tropism>>,
    growth: Option<Real>,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    ParametricLSystem<'g, DEPTH, STACK, SLOTS>
{
    /// `grammar` derived `order` times, heading up (ABOP's plants grow up).
    pub const fn new(grammar: &'g ParametricGrammar, order: u32) -> Self {
        Self {
            grammar,
            order,
            orientation: Orientation::Up,
            budget: DEFAULT_BUDGET,
            projection: None,
            depth_cue: false,
            environment: None,
            tropism: None,
            growth: None,
        }
    }

    /// Bends every step under `tropism` instead of the system's own `tropism:` (`None`:
    /// no tropism): wind sways a plant this way (see [`Wind`](crate::lsystem::Wind)).
    #[must_use]
    pub const fn with_tropism(mut self, tropism: Option<Tropism>) -> Self {
        self.tropism = Some(tropism);
        self
    }

    /// Draws the plant `fraction` (0 to 1) of the way grown from order n − 1 to this
    /// order n: the last order's new modules grow in (see
    /// [`ParametricWalker::growing`]). Fit the full-grown plant and draw the growing one
    /// with its placement for a plant that grows where it stands.
    #[must_use]
    pub const fn growing(mut self, fraction: Real) -> Self {
        self.growth = Some(fraction);
        self
    }

    /// The walk options of this drawing.
    const fn options(&self) -> WalkOptions<'g> {
        WalkOptions {
            budget: self.budget,
            environment: self.environment,
            tropism: self.tropism,
            growth: self.growth,
        }
    }

    /// Grows an open system in `environment` (`env(k)` asks it about the turtle); open
    /// systems are drawn with the 3D turtle, from the front unless a projection is set.
    #[must_use]
    pub const fn with_environment(mut self, environment: &'g dyn Environment) -> Self {
        self.environment = Some(Held(environment));
        self
    }

    /// Draws with the 3D turtle, seen through `projection` (systems whose modules turn in
    /// space, `& ^ \\ / $`, are drawn in 3D anyway, isometric unless set).
    #[must_use]
    pub const fn with_projection(mut self, projection: Projection) -> Self {
        self.projection = Some(projection);
        self
    }

    /// In 3D, colours each line by its depth instead of its colour index: the palette's
    /// first [`DEPTH_LEVELS`] colours, farthest first (give them dark to bright for nearer
    /// brighter).
    #[must_use]
    pub const fn with_depth_cue(mut self, depth_cue: bool) -> Self {
        self.depth_cue = depth_cue;
        self
    }

    /// The projection it is drawn with, if in 3D.
    pub fn projection(&self) -> Option<Projection> {
        match self.projection {
            Some(projection) => Some(projection),
            None if self.grammar.is_3d() => Some(Projection::default()),
            None if self.grammar.uses_environment()
                || self.grammar.is_matrix()
                || self.grammar.draws_surfaces()
                || matches!(self.tropism, Some(Some(_))) =>
            {
                Some(Projection::Front)
            }
            None => None,
        }
    }

    /// The 3D segments, in turtle units.
    pub fn segments_3d(&self) -> Result<Segments3<'g, DEPTH, STACK, SLOTS>, Error> {
        check_order(self.order, DEPTH)?;
        Ok(Segments3::from_marks(self.walk_3d()))
    }

    /// Everything it draws in 3D (lines with widths, polygons), in turtle units.
    pub fn marks(&self) -> Result<Marks3<'g, DEPTH, STACK, SLOTS>, Error> {
        check_order(self.order, DEPTH)?;
        Ok(self.walk_3d())
    }

    /// The 3D walk, built in one piece (an order too high is its first item).
    #[inline(always)]
    fn walk_3d(&self) -> Marks3<'g, DEPTH, STACK, SLOTS> {
        Marks3::starting(self.grammar, self.order, self.options())
    }

    /// [`fit`](Self::fit) in 3D, out of line: its walks do not share a frame with the
    /// 2D fit's.
    #[inline(never)]
    fn fit_3d<P>(
        &self,
        projection: Projection,
        area: &Rectangle,
        palette: P,
    ) -> Result<ParametricDrawing<'g, P, DEPTH, STACK, SLOTS>, Error> {
        let space = SpaceFit::new(
            || MarkPoints::new(self.walk_3d()),
            projection,
            self.depth_cue,
            area,
            DEFAULT_MARGIN,
        )?;
        Ok(self.placed(space, palette, None))
    }

    /// This system's drawing placed in space by `space`, replaying `kept` marks if any.
    fn placed<P>(
        &self,
        space: SpaceFit,
        palette: P,
        kept: Option<&'g [StoredMark]>,
    ) -> ParametricDrawing<'g, P, DEPTH, STACK, SLOTS> {
        ParametricDrawing {
            system: *self,
            start: Start::default(),
            palette,
            bounding_box: space.bounding_box,
            space: Some(space),
            kept,
        }
    }

    /// Fits the plant as it sways in `wind` over a loop of `frames` (the union of every
    /// frame's picture, so no frame leaves the area), seen through its projection (from
    /// the front unless it turns in space); draw frame k with
    /// [`ParametricDrawing::with_tropism`]`(Some(wind.tropism_at(own, k, frames)))`.
    pub fn fit_in_wind<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
        wind: &Wind,
        frames: u32,
    ) -> Result<ParametricDrawing<'g, Colors<'p, C>, DEPTH, STACK, SLOTS>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let palette = colors(palette)?;
        let own = self.tropism.unwrap_or(self.grammar.tropism());
        let swaying = |frame: u32| self.with_tropism(Some(wind.tropism_at(own, frame, frames)));
        let projection = self.projection().unwrap_or(Projection::Front);
        let space = SpaceFit::new(
            || (0..frames.max(1)).flat_map(move |frame| MarkPoints::new(swaying(frame).walk_3d())),
            projection,
            self.depth_cue,
            &area,
            DEFAULT_MARGIN,
        )?;
        Ok(swaying(0).placed(space, palette, None))
    }

    /// Which way the first heading points on screen.
    #[must_use]
    pub const fn with_orientation(mut self, orientation: Orientation) -> Self {
        self.orientation = orientation;
        self
    }

    /// Caps every walk at `symbols` modules.
    #[must_use]
    pub const fn with_budget(mut self, symbols: u64) -> Self {
        self.budget = symbols;
        self
    }

    fn segments(&self, start: Start) -> Result<ParametricSegments<'g, DEPTH, STACK, SLOTS>, Error> {
        Ok(ParametricSegments::new(self.grammar, self.order, start)?
            .budget(self.budget)
            .growing(self.growth))
    }

    /// Scales and centres the drawing into `area` (less a margin), colours from `palette`
    /// by the turtle's colour index.
    pub fn fit<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
    ) -> Result<ParametricDrawing<'g, Colors<'p, C>, DEPTH, STACK, SLOTS>, Error> {
        let palette = fit_palette(&area, palette)?;
        match self.projection() {
            Some(projection) => self.fit_3d(projection, &area, palette),
            None => self.fit_2d(&area, palette),
        }
    }

    /// [`fit`](Self::fit), keeping what the measuring walk draws in `marks` (a buffer of
    /// the caller's: one [`StoredMark`] a line, 1 + ⌊n / 2⌋ a polygon of n vertices), so
    /// that the drawing replays them instead of walking the derivation again: about half
    /// the work of a fit and a draw, for [`StoredMark::BYTES`] of RAM a record. The same
    /// pixels either way. Where the marks outgrow the buffer, or the system is drawn in
    /// 2D or in perspective (whose eye is placed from a first walk), the drawing walks as
    /// [`fit`](Self::fit)'s does.
    pub fn fit_with_marks<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
        marks: &'g mut [StoredMark],
    ) -> Result<ParametricDrawing<'g, Colors<'p, C>, DEPTH, STACK, SLOTS>, Error> {
        let palette = fit_palette(&area, palette)?;
        match self.projection() {
            Some(projection) if !matches!(projection, Projection::Perspective { .. }) => {
                let (extent, written) =
                    measure_keeping(&mut self.walk_3d(), projection, &mut *marks)?;
                let space = SpaceFit::from_extent(
                    extent,
                    projection,
                    None,
                    self.depth_cue,
                    &area,
                    DEFAULT_MARGIN,
                )?;
                let kept: &'g [StoredMark] = marks;
                Ok(self.placed(space, palette, written.and_then(|n| kept.get(..n))))
            }
            Some(projection) => self.fit_3d(projection, &area, palette),
            None => self.fit_2d(&area, palette),
        }
    }

    /// [`fit`](Self::fit) in 2D, out of line (its walks off the 3D path's stack).
    #[inline(never)]
    fn fit_2d<P>(
        &self,
        area: &Rectangle,
        palette: P,
    ) -> Result<ParametricDrawing<'g, P, DEPTH, STACK, SLOTS>, Error> {
        let area = *area;
        let bounds = measure(self.segments(Start::default())?)?;
        let start = fitted_start(bounds, 0, self.orientation, &area, DEFAULT_MARGIN)?;
        let pixels: Option<Bounds> = measure(self.segments(start)?)?;
        Ok(ParametricDrawing {
            system: *self,
            start,
            palette,
            bounding_box: pixel_box(self.orientation, pixels, start),
            space: None,
            kept: None,
        })
    }
}

/// A fitted parametric system: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct ParametricDrawing<
    'g,
    P,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    system: ParametricLSystem<'g, DEPTH, STACK, SLOTS>,
    start: Start,
    palette: P,
    bounding_box: Rectangle,
    space: Option<SpaceFit>,
    /// The marks the fit kept, to replay instead of walking (see
    /// [`ParametricLSystem::fit_with_marks`]).
    kept: Option<&'g [StoredMark]>,
}

impl<P, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    ParametricDrawing<'_, P, DEPTH, STACK, SLOTS>
{
    /// The same placement, the plant bent by `tropism` instead (a frame of a plant in the
    /// wind fitted by [`ParametricLSystem::fit_in_wind`]).
    #[must_use]
    pub const fn with_tropism(mut self, tropism: Option<Tropism>) -> Self {
        self.system = self.system.with_tropism(tropism);
        self.kept = None;
        self
    }

    /// How many records of the fit's buffer hold the marks this drawing replays (see
    /// [`ParametricLSystem::fit_with_marks`]); `None` where it walks the derivation instead.
    pub fn kept_marks(&self) -> Option<usize> {
        self.kept.map(<[StoredMark]>::len)
    }

    /// The same placement, the plant at `order` grown `fraction` of the way from the order
    /// below (a frame of a plant growing where it stands: fit the full-grown one).
    #[must_use]
    pub const fn growing(mut self, order: u32, fraction: Real) -> Self {
        self.system.order = order;
        self.system = self.system.growing(fraction);
        self.kept = None;
        self
    }
}

impl<P: Palette, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    ParametricDrawing<'_, P, DEPTH, STACK, SLOTS>
{
    /// Draws, reporting the engine's errors too.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<WalkStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        match self.space {
            Some(space) => self.draw_3d::<_, Flat>(&space, &mut Unsorted(target)),
            None => self.draw_2d(target),
        }
    }

    /// The 2D draw, out of line (its walk off the 3D path's stack).
    #[inline(never)]
    fn draw_2d<D>(&self, target: &mut D) -> Result<WalkStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let clip = target.bounding_box();
        let mut segments = self.system.segments(self.start)?;
        let mut pen = Pen::default();
        for segment in segments.by_ref() {
            let segment = segment?;
            let color = self.palette.color(u16::from(segment.color), u16::MAX);
            pen.draw(target, self.system.orientation, segment, color, &clip)
                .map_err(DrawError::Target)?;
        }
        pen.finish(target).map_err(DrawError::Target)?;
        Ok(WalkStats {
            segments: segments.segments(),
            ..WalkStats::default()
        })
    }
}

impl<P: Palette, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    ParametricDrawing<'_, P, DEPTH, STACK, SLOTS>
{
    /// The 3D draw, out of line: its walk does not share a frame with the 2D draw's.
    #[inline(never)]
    fn draw_3d<T, L>(
        &self,
        space: &SpaceFit,
        target: &mut T,
    ) -> Result<WalkStats, DrawError<T::Error>>
    where
        T: Layered<Color = P::Color>,
        L: Lighting<P::Color>,
    {
        let (lines, polygons) = match self.kept {
            Some(records) => {
                paint::<_, _, L>(space, target, &mut Replay::new(records), &self.palette)?
            }
            None => {
                let mut marks = self.system.walk_3d();
                let mut seen = Projected::new(&mut marks, space.view());
                paint::<_, _, L>(space, target, &mut seen, &self.palette)?
            }
        };
        Ok(WalkStats {
            segments: lines,
            polygons,
            ..WalkStats::default()
        })
    }

    /// Draws with surfaces in light (each polygon shaded by its normal) and, given a
    /// `depth` buffer (one `u16` a pixel of the target's bounding box, emptied here),
    /// nearer surfaces and lines hiding farther ones; without one, in walk order.
    pub fn try_draw_lit<D>(
        &self,
        target: &mut D,
        depth: Option<&mut [u16]>,
    ) -> Result<WalkStats, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
        P::Color: Shade,
    {
        let Some(space) = self.space else {
            return self.draw_2d(target);
        };
        match depth {
            Some(buffer) => {
                let mut tested = DepthTested::new(target, buffer)?;
                self.draw_3d::<_, Lit>(&space, &mut tested)
            }
            None => self.draw_3d::<_, Lit>(&space, &mut Unsorted(target)),
        }
    }
}

impl<P: Palette, const DEPTH: usize, const STACK: usize, const SLOTS: usize> Drawable
    for ParametricDrawing<'_, P, DEPTH, STACK, SLOTS>
{
    type Color = P::Color;
    type Output = WalkStats;

    fn draw<D>(&self, target: &mut D) -> Result<WalkStats, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}

impl<P, const DEPTH: usize, const STACK: usize, const SLOTS: usize> Dimensions
    for ParametricDrawing<'_, P, DEPTH, STACK, SLOTS>
{
    fn bounding_box(&self) -> Rectangle {
        self.bounding_box
    }
}

/// A fit's palette, once its target is known to have an area: what [`fit`] and
/// [`fit_with_marks`] check first.
///
/// [`fit`]: ParametricLSystem::fit
/// [`fit_with_marks`]: ParametricLSystem::fit_with_marks
fn fit_palette<'p, C: PixelColor>(
    area: &Rectangle,
    palette: &'p [C],
) -> Result<Colors<'p, C>, Error> {
    if area.size.width == 0 || area.size.height == 0 {
        return Err(Error::Fit(FitError::ZeroSizeTarget));
    }
    colors(palette)
}
