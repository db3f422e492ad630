//! Drawing a scene on a display: one [`Look`] per display says which colours to use.

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor, Rgb565, Rgb888},
    prelude::*,
};
use tinyfractal::FitError;
use tinyfractal::{
    DrawError, Error, EscapeTime, Gradient, Ifs, IfsFile, IfsPicture, LSystem, LsysFile,
    Orientation, ParametricGrammar, ParametricLSystem, DEFAULT_DEPTH, DEFAULT_STACK,
};

use crate::catalogue::{escape_view, GeneralEntry, Scene, System};

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

/// What drawing a scene did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// Segments drawn.
    Segments(u64),
    /// Iterations computed.
    Iterations(u64),
    /// Points plotted (the chaos game).
    Points(u64),
}

impl Scene {
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
            } => {
                target.clear(look.background).map_err(DrawError::Target)?;
                draw_ifs(target, look, (source, system), points, seed)
            }
            Scene::Escape {
                julia,
                centre,
                width,
                max_iterations,
            } => draw_escape(target, look, julia, (centre, width), max_iterations),
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
/// while the grammar is being built.
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
    let drawing = LSystem::new(grammar, order)
        .with_orientation(orientation)
        .fit(target.bounding_box(), &ink)?;
    let stats = drawing.draw(target).map_err(DrawError::Target)?;
    Ok(Work::Segments(stats.segments))
}

/// An escape-time view through the look's gradient, out of line.
#[inline(never)]
fn draw_escape<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    julia: Option<(&str, &str)>,
    (centre, width): ((&str, &str), &str),
    max_iterations: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let size = target.bounding_box().size;
    let view = escape_view(julia, centre, width, max_iterations, size)?;
    let palette = Gradient::<D::Color, 16>::new(look.keys, look.inside)
        .ok_or(Error::Fit(FitError::EmptyPalette))?;
    let stats = EscapeTime::new(view, palette)
        .draw(target)
        .map_err(DrawError::Target)?;
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

impl GeneralEntry {
    /// Draws the system over the whole of `target`, cleared to `look.background` first,
    /// in `look.ink`. Its grammar (12 KiB) and a walk (about 8 KiB, with no room for
    /// contexts: the scenes have none) are on the stack while it draws: a scene for cores
    /// with the RAM for them.
    #[inline(never)]
    pub fn draw<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
    {
        target.clear(look.background).map_err(DrawError::Target)?;
        let mut grammar = ParametricGrammar::new();
        LsysFile::new(self.source)
            .entry(self.system)?
            .parametric_into(&mut grammar)?;
        let ink = [look.ink];
        let drawing =
            ParametricLSystem::<'_, DEFAULT_DEPTH, DEFAULT_STACK, 0>::new(&grammar, self.order)
                .fit(target.bounding_box(), &ink)?;
        let stats = drawing.try_draw(target)?;
        Ok(Work::Segments(stats.segments))
    }
}
