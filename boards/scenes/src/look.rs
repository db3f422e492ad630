//! Drawing a scene on a display: one [`Look`] per display says which colours to use.

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor, Rgb565, Rgb888},
    prelude::*,
    primitives::Rectangle,
};
use tinyfractal::error::FitError;
use tinyfractal::{
    error::DrawError,
    escape::{ReferencePoint, Shading, Tier, ZoomFrame, ZoomLine},
    ifs::IfsPicture,
    lsystem::{Cell, StoredMark, DEFAULT_DEPTH, DEFAULT_STACK},
    math::DeepCoord,
    noise::{Octaves, Texture},
    render::{Colors, Gradient, Orientation, Palette, Shade, DENSITY_LEVELS},
    Coord, Error, EscapeTime, Fractal, Ifs, IfsFile, LSystem, LsysFile, ParametricGrammar,
    ParametricLSystem, Real, View,
};

use crate::catalogue::{GeneralEntry, Scene, System};

/// Expansion-table cells an L-system scene is measured with (96 bytes each, on the stack while
/// it draws: 3.75 KiB).
///
/// The OLED plant's 40 (its 22.5° keeps a quarter of its 16 headings) and the snowflake's 24.
pub const LSYSTEM_CELLS: usize = 40;

/// The most pixels a board's density picture counts: the OLED's 128×64, a byte each
/// (8 KiB on the stack while it draws).
pub const MAX_BOARD_DENSITY_PIXELS: usize = 128 * 64;

/// The most pixels a full display's density picture counts: the real boards' 320×240 (and
/// the gallery's), a byte each.
pub(crate) const MAX_DISPLAY_DENSITY_PIXELS: usize = 320 * 240;

/// Most heights of a landscape drawn on a board (33², 4.3 KiB on the stack while it draws).
pub const MAX_BOARD_MAP_CELLS: usize = 33 * 33;

/// The colours a display draws the scenes in.
#[derive(Debug, Clone, Copy)]
pub struct Look<'a, C> {
    /// What the target is cleared to.
    pub background: C,
    /// The L-systems' line colour.
    pub ink: C,
    /// Escape-time gradient keys, spread over 16 colours.
    pub keys: &'a [Rgb888],
    /// Escape-time points that never escape.
    pub inside: C,
}

/// The SSD0323's 4-bit grey: white lines, a dark-light-dark gradient.
pub const GREY: Look<'static, Gray4> = Look {
    background: Gray4::BLACK,
    ink: Gray4::WHITE,
    keys: &[
        Rgb888::new(0x10, 0x10, 0x10),
        Rgb888::new(0x90, 0x90, 0x90),
        Rgb888::WHITE,
        Rgb888::new(0x50, 0x50, 0x50),
    ],
    inside: Gray4::BLACK,
};

/// RGB565 displays (ST7789, ILI9341): green plants on black, a blue-gold gradient.
pub const COLOUR: Look<'static, Rgb565> = Look {
    background: Rgb565::BLACK,
    ink: Rgb565::new(12, 58, 12),
    keys: &[
        Rgb888::new(0x00, 0x07, 0x64),
        Rgb888::new(0x20, 0x6B, 0xCB),
        Rgb888::new(0xED, 0xFF, 0xFF),
        Rgb888::new(0xFF, 0xAA, 0x00),
        Rgb888::new(0x00, 0x02, 0x00),
    ],
    inside: Rgb565::BLACK,
};

impl<C: PixelColor + From<Rgb888>> Look<'_, C> {
    /// The look's gradient of `N` entries over its keys (16 for dwells, 256 for smooth
    /// values and textures): what the scenes colour with.
    pub fn gradient<const N: usize>(&self) -> Result<Gradient<C, N>, Error> {
        Gradient::new(self.keys, self.inside).ok_or(Error::Fit(FitError::EmptyPalette))
    }
}

/// What drawing a scene did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// Segments drawn.
    Segments(u64),
    /// Iterations computed.
    Iterations(u64),
    /// Points plotted (the chaos game).
    Points(u64),
    /// Cells drawn: squares (carpet), triangles (gasket), cubes, or terrain heights.
    Cells(u64),
    /// Frames drawn (a zoom).
    Frames(u64),
    /// Noise samples taken, one a pixel (a texture).
    Samples(u64),
    /// Cells stepped, once a step (reaction–diffusion).
    CellSteps(u64),
    /// Live particles moved, once a tick (a particle system).
    ParticleSteps(u64),
}

impl Work {
    /// The count, whatever it counts.
    pub const fn count(self) -> u64 {
        match self {
            Self::Segments(n)
            | Self::Iterations(n)
            | Self::Points(n)
            | Self::Cells(n)
            | Self::Frames(n)
            | Self::Samples(n)
            | Self::CellSteps(n)
            | Self::ParticleSteps(n) => n,
        }
    }

    /// What it counts, in the plural, for a board's log (`segments`, `iterations`, ...).
    pub const fn unit(self) -> &'static str {
        match self {
            Self::Segments(_) => "segments",
            Self::Iterations(_) => "iterations",
            Self::Points(_) => "points",
            Self::Cells(_) => "cells",
            Self::Frames(_) => "frames",
            Self::Samples(_) => "samples",
            Self::CellSteps(_) => "cell_steps",
            Self::ParticleSteps(_) => "particle_steps",
        }
    }
}

impl Scene {
    /// Draws the scene as [`Scene::draw`] does, calling `between_frames` after each frame
    /// of an animated scene (the walking figure, a zoom): a board waits there, so the
    /// animation runs at its pace rather than the display's.
    pub fn draw_frames<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
        between_frames: impl FnMut(),
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            Scene::Walk { .. } => self.draw_shape_frames(target, look, between_frames),
            Scene::Zoom { .. } => draw_zoom(target, look, self, between_frames),
            Scene::NoiseFlight { .. } => draw_flight(target, look, self, between_frames),
            Scene::Particles { .. } => self
                .draw_dynamics_frames(target, look, between_frames)
                .unwrap_or(Ok(Work::ParticleSteps(0))),
            _ => self.draw(target, look),
        }
    }

    /// Draws a scene for a panel of fewer colours (an escape-time view dithered onto one
    /// bit) as [`Scene::draw`] does, with the scenes' `panels` feature; `None` for any
    /// other scene or without the feature.
    ///
    /// Its drawing target is the dithering one: on a core's flash, a second copy of the
    /// escape-time engine, which is why it is a feature of its own.
    pub fn draw_panel<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        #[cfg(feature = "panels")]
        if let Scene::Zoom { pilot: Some(_), .. } = self {
            return Some(draw_zoom(target, look, self, || {}));
        }
        #[cfg(feature = "panels")]
        if let Scene::Escape(escape) = self {
            if let Some(dither) = escape.one_bit {
                return Some(
                    escape
                        .view(target.bounding_box().size)
                        .map_err(DrawError::Fractal)
                        .and_then(|view| draw_escape_one_bit(target, look, view, dither)),
                );
            }
        }
        let _ = (target, look);
        None
    }

    /// Draws a texture scene (Perlin noise, reaction–diffusion) as [`Scene::draw`] does,
    /// without reaching the other families' code; `None` for any other scene.
    ///
    /// A firmware that shows only textures calls this, so its flash holds only them.
    pub fn draw_texture<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            Scene::Noise {
                texture,
                octaves,
                scale,
                seed,
            } => Some(draw_noise(target, look, (texture, octaves), scale, seed)),
            Scene::Reaction {
                preset,
                grid,
                steps,
            } => Some(draw_reaction(target, look, preset, grid, steps)),
            Scene::NoiseTerrain {
                octaves,
                scale,
                seed,
                samples,
            } => Some(draw_noise_terrain(
                target,
                look,
                (octaves, scale, seed),
                samples,
            )),
            Scene::NoiseFlight { .. } => Some(draw_flight(target, look, self, || {})),
            _ => None,
        }
    }

    /// Draws the scene over the whole of `target`: an L-system clears it to
    /// `look.background` first; an escape-time view paints every pixel anyway, so clearing
    /// would only double the traffic to the display.
    pub fn draw<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            Scene::LSystem {
                system,
                order,
                orientation,
            } => {
                target.clear(look.background).map_err(DrawError::Target)?;
                draw_lsystem(target, look, system, order, orientation)
            }
            Scene::Ifs {
                source,
                system,
                points,
                seed,
                density: false,
            } => {
                target.clear(look.background).map_err(DrawError::Target)?;
                draw_ifs(target, look, (source, system), points, seed)
            }
            // Every pixel written: no clearing.
            Scene::Ifs {
                source,
                system,
                points,
                seed,
                density: true,
            } => draw_ifs_density(target, look, (source, system), points, seed),
            Scene::Subdivision { .. } => self.draw_shape_frames(target, look, || {}),
            Scene::Terrain { .. } => self
                .draw_terrain(target, look)
                .unwrap_or(Ok(Work::Cells(0))),
            Scene::Walk { .. } => self.draw_shape_frames(target, look, || {}),
            Scene::Zoom { .. } => draw_zoom(target, look, self, || {}),
            Scene::Noise { .. }
            | Scene::Reaction { .. }
            | Scene::NoiseTerrain { .. }
            | Scene::NoiseFlight { .. } => self
                .draw_texture(target, look)
                .unwrap_or(Ok(Work::Samples(0))),
            Scene::Attractor { .. } | Scene::Bezier { .. } | Scene::Particles { .. } => self
                .draw_dynamics(target, look)
                .unwrap_or(Ok(Work::Points(0))),
            Scene::Escape(escape) => {
                let view = escape.view(target.bounding_box().size)?;
                if escape.one_bit.is_some() {
                    return self.draw_panel(target, look).unwrap_or_else(|| {
                        target.clear(look.background).map_err(DrawError::Target)?;
                        Ok(Work::Iterations(0))
                    });
                }
                match (escape.shading, view.tier()) {
                    (_, Tier::Perturbation) => draw_perturbed(target, look, view),
                    (Shading::Dwell, _) => draw_escape::<D, 16>(target, look, view),
                    // 16 entries a dwell: the same colours at whole dwells; distances
                    // take 256 values.
                    (Shading::Smooth | Shading::Distance, _) => {
                        draw_escape::<D, 256>(target, look, view)
                    }
                }
            }
        }
    }
}

/// An L-system in `look.ink`, out of line: each family's frame is on the stack only while
/// it draws (one frame for all of them would hold the largest of each).
#[inline(never)]
fn draw_lsystem<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    system: &System,
    order: u32,
    orientation: Orientation,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
{
    // Borrowed where it was built: moving a grammar out of its `Result` would copy it.
    let built = system.grammar();
    let grammar = match &built {
        Ok(grammar) => grammar,
        Err(error) => return Err(DrawError::Fractal(*error)),
    };
    draw_grammar(target, look, grammar, order, orientation)
}

/// Fits and draws a built grammar, out of line: its walks' frames are not on the stack
/// while the grammar is being built. Measured from the expansion table where
/// [`LSYSTEM_CELLS`] hold one (the same fit as a sizing walk, drawn by walking at these
/// sizes: the same pixels in the same order), by a sizing walk otherwise.
#[inline(never)]
fn draw_grammar<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    grammar: &tinyfractal::Grammar<'_>,
    order: u32,
    orientation: Orientation,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
{
    let ink = [look.ink];
    let colors = Colors::new(&ink).ok_or(Error::Fit(FitError::EmptyPalette))?;
    let mut cells = [Cell::default(); LSYSTEM_CELLS];
    let drawing = LSystem::new(grammar, order)
        .with_orientation(orientation)
        .fit_in(target.bounding_box(), colors, &mut cells)?;
    let stats = drawing.draw(target).map_err(DrawError::Target)?;
    Ok(Work::Segments(stats.segments))
}

/// An escape-time view through the look's gradient of `N` entries, out of line.
#[inline(never)]
fn draw_escape<D, const N: usize>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    view: View,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let stats = EscapeTime::new(view, look.gradient::<N>()?)
        .draw(target)
        .map_err(DrawError::Target)?;
    Ok(Work::Iterations(stats.iterations))
}

#[cfg(feature = "panels")]
/// A one-bit panel (an SSD1306) over any target: on in the look's ink, off in its
/// background.
struct OneBit<'a, D: DrawTarget> {
    target: &'a mut D,
    on: D::Color,
    off: D::Color,
}

#[cfg(feature = "panels")]
impl<D: DrawTarget> OneBit<'_, D> {
    fn color(&self, bit: BinaryColor) -> D::Color {
        match bit {
            BinaryColor::On => self.on,
            BinaryColor::Off => self.off,
        }
    }
}

#[cfg(feature = "panels")]
impl<D: DrawTarget> Dimensions for OneBit<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

#[cfg(feature = "panels")]
impl<D: DrawTarget> DrawTarget for OneBit<'_, D> {
    type Color = BinaryColor;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), D::Error> {
        let (on, off) = (self.on, self.off);
        self.target.draw_iter(
            pixels
                .into_iter()
                .map(|Pixel(p, bit)| Pixel(p, if bit.is_on() { on } else { off })),
        )
    }

    fn fill_contiguous<I: IntoIterator<Item = BinaryColor>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), D::Error> {
        let (on, off) = (self.on, self.off);
        self.target.fill_contiguous(
            area,
            colors
                .into_iter()
                .map(|bit| if bit.is_on() { on } else { off }),
        )
    }

    fn fill_solid(&mut self, area: &Rectangle, bit: BinaryColor) -> Result<(), D::Error> {
        let color = self.color(bit);
        self.target.fill_solid(area, color)
    }
}

#[cfg(feature = "panels")]
use embedded_graphics::pixelcolor::BinaryColor;
#[cfg(feature = "panels")]
use tinyfractal::render::{Dither, Dithered};

#[cfg(feature = "panels")]
/// An escape-time view on a one-bit panel: its gradient in 24-bit colour, each pixel
/// dithered to one bit by its position, out of line.
#[inline(never)]
fn draw_escape_one_bit<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    view: View,
    dither: Dither,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
{
    let gradient = Gradient::<Rgb888, 16>::new(look.keys, Rgb888::BLACK)
        .ok_or(Error::Fit(FitError::EmptyPalette))?;
    let mut panel = OneBit {
        target,
        on: look.ink,
        off: look.background,
    };
    let stats = EscapeTime::new(view, &gradient)
        .draw(&mut Dithered::new(&mut panel, dither))
        .map_err(DrawError::Target)?;
    Ok(Work::Iterations(stats.iterations))
}

/// One of Perlin's textures over the whole of `target`, its 256 levels spread over the
/// look's gradient keys. Out of line: its 256-entry gradient is on the stack only while a
/// texture draws.
#[cfg(feature = "textures")]
#[inline(never)]
fn draw_noise<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    (texture, octaves): (Texture, Octaves),
    scale: Real,
    seed: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::noise::{NoiseTexture, Perlin};
    let noise = Perlin::seeded(seed);
    let area = target.bounding_box();
    NoiseTexture::new(&noise, texture)
        .with_octaves(octaves)
        .with_scale(scale)
        .fit(area, look.gradient::<256>()?)?
        .draw(target)
        .map_err(DrawError::Target)?;
    Ok(Work::Samples(
        u64::from(area.size.width) * u64::from(area.size.height),
    ))
}

/// A landscape of noise over the whole of `target`, its heights (at most
/// [`MAX_BOARD_MAP_CELLS`], 4.3 KiB) on the stack while it draws.
#[cfg(feature = "textures")]
#[inline(never)]
fn draw_noise_terrain<D>(
    target: &mut D,
    _: &Look<'_, D::Color>,
    (octaves, scale, seed): (Octaves, Real, u32),
    samples: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::noise::{NoiseTerrain, Perlin};
    let noise = Perlin::seeded(seed);
    let mut heights = [0i32; MAX_BOARD_MAP_CELLS];
    let heights = NoiseTerrain::new(&noise, samples)
        .with_octaves(octaves)
        .with_scale(scale)
        .fit(target.bounding_box(), &mut heights)?
        .draw(target)
        .map_err(DrawError::Target)?;
    Ok(Work::Cells(heights))
}

/// A texture's frames through 3D noise over the whole of `target`, frame k at depth
/// k·`z_step`, calling `between_frames` after each; the samples taken.
#[cfg(feature = "textures")]
#[inline(never)]
fn draw_flight<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    scene: &Scene,
    mut between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::noise::{NoiseTexture, Perlin};
    let Scene::NoiseFlight {
        texture,
        octaves,
        scale,
        seed,
        frames,
        z_step,
    } = *scene
    else {
        return Ok(Work::Samples(0));
    };
    let noise = Perlin::seeded(seed);
    let area = target.bounding_box();
    let palette = look.gradient::<256>()?;
    let mut depth = Real::ZERO;
    for _ in 0..frames {
        NoiseTexture::new(&noise, texture)
            .with_octaves(octaves)
            .with_scale(scale)
            .with_z(depth)
            .fit(area, &palette)?
            .draw(target)
            .map_err(DrawError::Target)?;
        between_frames();
        depth = depth
            .checked_add(z_step)
            .ok_or(DrawError::Fractal(Error::from(tinyfractal::math::Overflow)))?;
    }
    let pixels = u64::from(area.size.width) * u64::from(area.size.height);
    Ok(Work::Samples(pixels * u64::from(frames)))
}

/// Without the `textures` feature a texture's frames are the background.
#[cfg(not(feature = "textures"))]
fn draw_flight<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    _: &Scene,
    _: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    Ok(Work::Samples(0))
}

/// Without the `textures` feature a landscape of noise is the background.
#[cfg(not(feature = "textures"))]
fn draw_noise_terrain<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    _: (Octaves, Real, u32),
    _: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    Ok(Work::Cells(0))
}

/// Without the `textures` feature a texture is the background: no samples taken.
#[cfg(not(feature = "textures"))]
fn draw_noise<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    _: (Texture, Octaves),
    _: Real,
    _: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    Ok(Work::Samples(0))
}

/// The most cells a board's reaction grid has: 32×32, 4 KiB of cells and a 384-byte ring
/// on the stack while it runs.
pub const MAX_BOARD_REACTION_CELLS: usize = 32 * 32;

/// The most cells the host's catalogue reactions have (128×128, 64 KiB on the stack).
#[cfg(feature = "textures")]
const MAX_HOST_REACTION_CELLS: usize = 128 * 128;

/// A reaction over the whole of `target`: `preset` on a `grid` from Sims's square start,
/// `steps` steps, B's 256 levels spread over the look's gradient keys. The grid is on the
/// stack, in a buffer of [`MAX_BOARD_REACTION_CELLS`] when it fits (every board scene's:
/// 32 wide at most), of 128×128 otherwise (the host's).
#[cfg(feature = "textures")]
fn draw_reaction<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    preset: tinyfractal::reaction::Preset,
    grid: (u32, u32),
    steps: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let cells = grid.0 as usize * grid.1 as usize;
    // A board (a target without an OS) carries only its own buffer's code.
    if cells <= MAX_BOARD_REACTION_CELLS || cfg!(target_os = "none") {
        run_reaction::<D, MAX_BOARD_REACTION_CELLS, 96>(target, look, preset, grid, steps)
    } else {
        run_reaction::<D, MAX_HOST_REACTION_CELLS, 384>(target, look, preset, grid, steps)
    }
}

/// [`draw_reaction`] with a grid of `N` cells at most and a ring of `RING` (three rows).
/// Out of line, so its buffers are on the stack only while a reaction runs.
#[cfg(feature = "textures")]
#[inline(never)]
fn run_reaction<D, const N: usize, const RING: usize>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    preset: tinyfractal::reaction::Preset,
    grid: (u32, u32),
    steps: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::reaction::{Cell, Reaction, Start};
    let mut cells = [Cell::REST; N];
    let mut ring = [Cell::REST; RING];
    let mut reaction = Reaction::new(&preset.model(), grid, &mut cells, &mut ring)?;
    reaction.start(Start::Square);
    reaction.step(steps);
    reaction
        .fit(target.bounding_box(), look.gradient::<256>()?)?
        .draw(target)
        .map_err(DrawError::Target)?;
    Ok(Work::CellSteps(
        u64::from(steps) * u64::from(grid.0) * u64::from(grid.1),
    ))
}

/// Without the `textures` feature a reaction is the background: no steps taken.
#[cfg(not(feature = "textures"))]
fn draw_reaction<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    _: tinyfractal::reaction::Preset,
    _: (u32, u32),
    _: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    Ok(Work::CellSteps(0))
}

/// A zoom over the whole of `target`, one frame of storage on the stack, a byte a pixel:
/// 10,496 bytes up to the OLED's 128×64 (the micro:bit's 16 KiB hold it), 84,480 bytes up
/// to a display's 320×240 or 240×320.
fn draw_zoom<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    scene: &Scene,
    between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let size = target.bounding_box().size;
    if size.width <= 128 && size.height <= 64 {
        zoom_on_stack::<D, { 128 * 64 }, { 128 + 64 }>(target, look, scene, between_frames)
    } else {
        zoom_on_stack::<D, { 320 * 240 }, { 320 + 320 }>(target, look, scene, between_frames)
    }
}

/// A zoom in `PIXELS` bytes and `LINES` lines on the stack, out of line: each size's
/// storage exists only while its zoom draws.
#[inline(never)]
fn zoom_on_stack<D, const PIXELS: usize, const LINES: usize>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    scene: &Scene,
    between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let mut values = [0u8; PIXELS];
    let mut lines = [ZoomLine::default(); LINES];
    draw_zoom_in(target, look, scene, &mut values, &mut lines, between_frames)
}

/// A zoom in `values` and `lines` (the columns, then the rows), out of line:
/// `between_frames` after each frame. Counts frames.
#[inline(never)]
fn draw_zoom_in<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    scene: &Scene,
    values: &mut [u8],
    lines: &mut [ZoomLine],
    mut between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let Scene::Zoom {
        centre,
        width,
        max_iterations,
        frames,
        shrink: (numerator, denominator),
        tolerance_percent,
        pilot,
    } = *scene
    else {
        return Ok(Work::Frames(0));
    };
    // The autopilot is the `panels` feature's: without it its scene draws nothing.
    #[cfg(feature = "panels")]
    let mut pilot = pilot.map(tinyfractal::escape::Autopilot::new);
    #[cfg(not(feature = "panels"))]
    if pilot.is_some() {
        target.clear(look.background).map_err(DrawError::Target)?;
        return Ok(Work::Frames(0));
    }
    let size = target.bounding_box().size;
    // Every catalogue number parses: `zoom()` asserts it when the tables compile.
    let deep = |text: &str| DeepCoord::parse(text).unwrap_or_default();
    let centre = (deep(centre.0), deep(centre.1));
    let view_of = |width: i128| {
        let width = Coord::from_bits(i64::try_from(width).unwrap_or(0));
        let width = DeepCoord::from_coord(width);
        View::deep(Fractal::Mandelbrot, centre, width, size, max_iterations)
    };
    let mut width = i128::from(Coord::parse(width).unwrap_or_default().to_bits());
    let gradient = look.gradient::<16>()?;
    let (columns, rows) = lines.split_at_mut(lines.len().min(size.width as usize));
    let mut view = view_of(width)?;
    let mut frame = ZoomFrame::new(view, values, columns, rows)?;
    for index in 0..frames {
        // The autopilot steers from the second frame on; a zoom narrows by `shrink`.
        #[cfg(feature = "panels")]
        let steered = match &mut pilot {
            Some(pilot) if index > 0 => Some(pilot.next(&view, frame.values())?),
            _ => None,
        };
        #[cfg(not(feature = "panels"))]
        let steered: Option<View> = None;
        view = match steered {
            Some(next) => next,
            None => view_of(width)?,
        };
        // The last frame takes only lines at exactly its points: it is exact.
        let tolerance = if index + 1 == frames {
            0
        } else {
            tolerance_percent
        };
        frame.advance(view, Some(tolerance))?;
        frame.draw(target, &gradient).map_err(DrawError::Target)?;
        between_frames();
        width = width * i128::from(numerator) / i128::from(denominator.max(1));
    }
    Ok(Work::Frames(frames.into()))
}

/// Most points of a reference orbit a board keeps (on the stack, only while a deep view
/// draws): 24 bytes each, 24 KiB for a cap of 1000 iterations.
pub const MAX_BOARD_REFERENCE_POINTS: usize = 1001;

/// A view past `Deep`'s spacing by perturbation, its reference orbit on the stack, out of
/// line: dwell shading (a smooth deep scene would need the smooth gradient here too).
#[inline(never)]
fn draw_perturbed<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    view: View,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let mut storage = [ReferencePoint::default(); MAX_BOARD_REFERENCE_POINTS];
    let stats =
        EscapeTime::new(view, look.gradient::<16>()?).draw_perturbed(target, &mut storage)?;
    Ok(Work::Iterations(stats.iterations))
}

/// An IFS in `look.ink`, out of line: its maps are on the stack only while it draws.
#[inline(never)]
fn draw_ifs<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    (source, system): (&str, &str),
    points: u64,
    seed: u64,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
{
    let mut ifs = Ifs::new();
    IfsFile::new(source).entry(system)?.ifs_into(&mut ifs)?;
    let ink = [look.ink];
    let drawing = IfsPicture::new(&ifs, points)
        .with_seed(seed)
        .fit(target.bounding_box(), &ink)?;
    Ok(Work::Points(drawing.try_draw(target)?))
}

/// An IFS by density, the hit counts' levels through the look's gradient, a byte a pixel.
///
/// On a display whose shorter side is at most 64 pixels (the OLED) the counts cover the
/// largest square centred in it (4 KiB), either side the colour of a pixel never hit: the
/// whole OLED's 8 KiB beside the IFS's 32 maps and its fit are more than the micro:bit's
/// 16 KiB of RAM, and the fern, taller than wide, fits its height either way. On a larger
/// display they cover all of it (up to 320×240; a larger one is refused as the fit
/// refuses counts too few for its area).
fn draw_ifs_density<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    (source, system): (&str, &str),
    points: u64,
    seed: u64,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let area = target.bounding_box();
    let side = area.size.width.min(area.size.height);
    let (ifs, gradient) = ((source, system), look.gradient::<16>()?);
    if (side as usize).pow(2) > MAX_BOARD_IFS_DENSITY_PIXELS {
        return count_ifs::<D, { MAX_DISPLAY_DENSITY_PIXELS }>(
            target,
            (area, gradient),
            ifs,
            (points, seed),
        );
    }
    let (spare_x, spare_y) = (area.size.width - side, area.size.height - side);
    let square = Rectangle::new(
        area.top_left + Point::new((spare_x / 2) as i32, (spare_y / 2) as i32),
        Size::new(side, side),
    );
    // Either side of the square: left and right, or above and below.
    let (before, after) = if spare_x > 0 {
        let width = spare_x / 2;
        (
            Rectangle::new(area.top_left, Size::new(width, side)),
            Rectangle::new(
                area.top_left + Point::new((width + side) as i32, 0),
                Size::new(spare_x - width, side),
            ),
        )
    } else {
        let height = spare_y / 2;
        (
            Rectangle::new(area.top_left, Size::new(side, height)),
            Rectangle::new(
                area.top_left + Point::new(0, (height + side) as i32),
                Size::new(side, spare_y - height),
            ),
        )
    };
    // In the colour of a pixel never hit, so that the square does not show.
    let unlit = gradient.color(0, DENSITY_LEVELS);
    for strip in [before, after] {
        target
            .fill_solid(&strip, unlit)
            .map_err(DrawError::Target)?;
    }
    count_ifs::<D, MAX_BOARD_IFS_DENSITY_PIXELS>(target, (square, gradient), ifs, (points, seed))
}

/// The most pixels a board's IFS density counts: the OLED's height squared, a byte each.
const MAX_BOARD_IFS_DENSITY_PIXELS: usize = 64 * 64;

/// [`draw_ifs_density`] with `N` counts at most, in `area` through `gradient`, out of
/// line: its buffer is on the stack only while it draws.
#[inline(never)]
fn count_ifs<D, const N: usize>(
    target: &mut D,
    (area, gradient): (Rectangle, Gradient<D::Color, 16>),
    (source, system): (&str, &str),
    (points, seed): (u64, u64),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let mut ifs = Ifs::new();
    IfsFile::new(source).entry(system)?.ifs_into(&mut ifs)?;
    let mut counts = [0u8; N];
    let played = IfsPicture::new(&ifs, points)
        .with_seed(seed)
        .fit_density(area, gradient, &mut counts)?
        .try_draw(target)?;
    Ok(Work::Points(played))
}

/// Most colours of an entry's `colors:` line a board keeps.
const MAX_PLANT_COLORS: usize = 16;

/// Draws a still plant fitted to the whole of `target`, its fit's marks kept for the
/// drawing to replay: out of line, so that only a still plant's frame holds them.
#[inline(never)]
fn draw_still<D>(
    target: &mut D,
    system: &ParametricLSystem<'_, DEFAULT_DEPTH, DEFAULT_STACK, 0>,
    palette: &[D::Color],
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: Shade,
{
    let mut marks = [StoredMark::EMPTY; PLANT_MARKS];
    let drawing = system.fit_with_marks(target.bounding_box(), palette, &mut marks)?;
    let stats = drawing.try_draw_lit(target, None)?;
    Ok(Work::Segments(stats.segments))
}

/// The marks a still plant's fit keeps for its drawing to replay, instead of walking its
/// derivation twice: the monopodial tree's 1,023 lines and the leafy bush's 420 lines and
/// 135 leaves (540 records) fit ([`StoredMark::BYTES`] each, on the stack).
const PLANT_MARKS: usize = 1_100;

impl GeneralEntry {
    /// Draws the system over the whole of `target`, cleared to `look.background` first,
    /// in its colours (its `colors:` line, else the catalogue's `BOOK`) with its surfaces
    /// lit, in walk order (no depth buffer); a swaying entry's frames one after another.
    /// Its grammar (12 KiB), a walk (about 8 KiB, with no room for contexts: the scenes
    /// have none) and, for a still plant, the marks its fit keeps (70 KiB) are on the stack
    /// while it draws: a scene for cores with the RAM for them.
    pub fn draw<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888> + Shade,
    {
        self.draw_frames(target, look, || {})
    }

    /// [`draw`](Self::draw), calling `between` between frames.
    #[inline(never)]
    pub fn draw_frames<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
        mut between: impl FnMut(),
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888> + Shade,
    {
        let entry = LsysFile::new(self.source).entry(self.system)?;
        let mut grammar = ParametricGrammar::new();
        entry.parametric_into(&mut grammar)?;
        let own = entry.colors::<MAX_PLANT_COLORS>()?;
        let colors: &[Rgb888] = if own.is_empty() {
            &crate::catalogue::BOOK
        } else {
            &own
        };
        let all: [D::Color; MAX_PLANT_COLORS] = core::array::from_fn(|i| {
            D::Color::from(colors.get(i).copied().unwrap_or(Rgb888::BLACK))
        });
        let palette = all.get(..colors.len()).unwrap_or(&all);
        let system =
            ParametricLSystem::<'_, DEFAULT_DEPTH, DEFAULT_STACK, 0>::new(&grammar, self.order);
        let area = target.bounding_box();
        if self.frames == 0 {
            target.clear(look.background).map_err(DrawError::Target)?;
            return draw_still(target, &system, palette);
        }
        let fitted = system.fit_in_wind(area, palette, &crate::catalogue::WIND, self.frames)?;
        let mut segments = 0;
        for frame in 0..self.frames {
            if frame > 0 {
                between();
            }
            target.clear(look.background).map_err(DrawError::Target)?;
            let tropism = crate::catalogue::WIND.tropism_at(grammar.tropism(), frame, self.frames);
            segments += fitted
                .with_tropism(Some(tropism))
                .try_draw_lit(target, None)?
                .segments;
        }
        Ok(Work::Segments(segments))
    }
}
