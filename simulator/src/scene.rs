//! Rendering an L-system into a simulator display, timed.

use std::io::{self, Write};
use std::time::Duration;

use crate::clock::Instant;

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    lsystem::{cells_needed, Cell, ParametricSegments, Segments, WalkStats},
    render::{Colors, Orientation},
    Error, Grammar, LSystem, ParametricGrammar,
};

use crate::common::View;
use crate::palette::VGA;

/// Expansion levels the CLI's walks hold: orders up to 256 (the core's default, for MCUs,
/// is 17 levels).
pub const DEPTH: usize = 257;

/// Saved turtles the CLI's walks hold (the core's default is 20).
pub const STACK: usize = 1024;

/// Most expansion-table cells the CLI allocates (about 100 bytes each); a system needing
/// more is walked.
pub const MAX_CELLS: usize = 1 << 20;

/// The CLI's L-system: desktop capacities.
pub type HostSystem<'g, 'a> = LSystem<'g, 'a, DEPTH, STACK>;

/// A rendered picture and what it took.
#[derive(Debug)]
pub struct Rendered {
    /// The picture.
    pub display: SimulatorDisplay<Rgb888>,
    /// What the walk did.
    pub stats: WalkStats,
    /// Fitting (measuring and checking) and drawing.
    pub fit: Duration,
    /// The time the drawing took.
    pub draw: Duration,
    /// The time everything took.
    pub elapsed: Duration,
}

/// Fits `grammar` at `order` into a `width`×`height` picture and draws it, heading right
/// for Fractint systems and up for ABOP ones; with a `view`, only that window of it.
pub fn render(
    grammar: &Grammar<'_>,
    order: u32,
    width: u32,
    height: u32,
    view: Option<View>,
) -> Result<Rendered, Error> {
    render_in(grammar, order, (width, height), view, &VGA)
}

/// [`render`] through the colour map `colors` (the colour modules index it).
pub fn render_in(
    grammar: &Grammar<'_>,
    order: u32,
    (width, height): (u32, u32),
    view: Option<View>,
    colors: &[Rgb888],
) -> Result<Rendered, Error> {
    let orientation = match grammar.dialect() {
        tinyfractal::Dialect::Fractint => Orientation::Right,
        tinyfractal::Dialect::Abop => Orientation::Up,
    };
    render_window(grammar, order, (width, height), orientation, view, colors)
}

/// The area the whole picture is fitted to so that `view` of it fills a `width`×`height`
/// target.
///
/// The target scaled by the window's inverse and moved by its corner. The drawing culls the
/// rest, so the cost follows what is visible.
pub fn fitted_area(width: u32, height: u32, view: Option<View>) -> Result<Rectangle, Error> {
    let target = Rectangle::new(Point::zero(), Size::new(width, height));
    let Some(view) = view else {
        return Ok(target);
    };
    let too_deep = Error::Walk(tinyfractal::error::WalkError::Overflow);
    let scaled = |pixels: u32, low: f64, high: f64| -> Result<(i32, u32), Error> {
        let size = (f64::from(pixels) / (high - low)).round();
        let corner = (-low * size).round();
        if size > f64::from(i32::MAX) || corner < f64::from(i32::MIN) {
            return Err(too_deep);
        }
        Ok((corner as i32, size as u32))
    };
    let (x, w) = scaled(width, view.x0, view.x1)?;
    let (y, h) = scaled(height, view.y0, view.y1)?;
    Ok(Rectangle::new(Point::new(x, y), Size::new(w, h)))
}

/// Like [`render`], with the first heading pointing `orientation` on screen.
pub fn render_oriented(
    grammar: &Grammar<'_>,
    order: u32,
    width: u32,
    height: u32,
    orientation: Orientation,
) -> Result<Rendered, Error> {
    render_window(grammar, order, (width, height), orientation, None, &VGA)
}

impl Rendered {
    /// A picture drawn from `started`, fitted after `fit`.
    fn timed(
        display: SimulatorDisplay<Rgb888>,
        stats: WalkStats,
        started: Instant,
        fit: Duration,
    ) -> Self {
        let elapsed = started.elapsed();
        Self {
            display,
            stats,
            fit,
            draw: elapsed - fit,
            elapsed,
        }
    }
}

/// The engine's error of a draw into the simulator's display (whose own cannot happen).
pub fn engine_error(error: tinyfractal::error::DrawError<core::convert::Infallible>) -> Error {
    match error {
        tinyfractal::error::DrawError::Fractal(error) => error,
        tinyfractal::error::DrawError::Target(never) => match never {},
    }
}

/// A draw into the simulator's display, with the engine's errors.
fn drawn<T>(
    result: Result<T, tinyfractal::error::DrawError<core::convert::Infallible>>,
) -> Result<T, Error> {
    result.map_err(engine_error)
}

/// How a system of the general engine is drawn: its 3D view, depth cue, environment.
#[derive(Debug, Clone, Copy, Default)]
pub struct GeneralLook<'e> {
    /// How a 3D system is seen, if given.
    pub projection: Option<tinyfractal::render::Projection>,
    /// Whether 3D lines are coloured by depth.
    pub depth_cue: bool,
    /// The world an open system grows in, if any.
    pub environment: Option<&'e crate::environment::Shape>,
    /// The colour map the colour modules index (`--colormap`); the book's browns and
    /// greens without one.
    pub colormap: Option<&'e [Rgb888]>,
    /// A tropism in place of the system's own (the wind of `animate sway`).
    pub tropism: Option<Option<tinyfractal::lsystem::Tropism>>,
    /// How far the last order has grown in (`animate growth`), if growing.
    pub growth: Option<tinyfractal::Real>,
}

/// The system of the general engine (parametric, contextual, 3D, open) `look` describes.
pub fn general_system<'g>(
    grammar: &'g ParametricGrammar,
    order: u32,
    look: &GeneralLook<'g>,
) -> tinyfractal::ParametricLSystem<'g, DEPTH, STACK> {
    let mut system =
        tinyfractal::ParametricLSystem::new(grammar, order).with_depth_cue(look.depth_cue);
    if let Some(projection) = look.projection {
        system = system.with_projection(projection);
    }
    if let Some(shape) = look.environment {
        system = system.with_environment(shape);
    }
    if let Some(tropism) = look.tropism {
        system = system.with_tropism(tropism);
    }
    if let Some(fraction) = look.growth {
        system = system.growing(fraction);
    }
    system
}

/// The marks a fit of the general engine keeps for its drawing to replay (1 MiB): a
/// plant that draws more is walked twice, as a board with less RAM walks it.
const HOST_MARKS: usize = 16_384;

/// Fits and draws a system of the general engine into a `width`×`height` picture (with
/// a `view`, that window of it: the whole is fitted to the enlarged area and clipped).
pub fn render_general(
    grammar: &ParametricGrammar,
    order: u32,
    (width, height): (u32, u32),
    view: Option<View>,
    look: &GeneralLook<'_>,
) -> Result<Rendered, Error> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(width, height));
    let started = Instant::now();
    let system = general_system(grammar, order, look);
    let palette: &[Rgb888] = if system.projection().is_some() && look.depth_cue {
        &crate::palette::DEPTH_GREENS
    } else {
        look.colormap.unwrap_or(&crate::palette::BOOK)
    };
    let mut marks = vec![tinyfractal::lsystem::StoredMark::EMPTY; HOST_MARKS];
    let drawing = system.fit_with_marks(fitted_area(width, height, view)?, palette, &mut marks)?;
    let fit = started.elapsed();
    // The host always sorts surfaces by depth.
    let mut depth = vec![0u16; width as usize * height as usize];
    let stats = drawn(drawing.try_draw_lit(&mut display, Some(&mut depth)))?;
    Ok(Rendered::timed(display, stats, started, fit))
}

fn render_window(
    grammar: &Grammar<'_>,
    order: u32,
    (width, height): (u32, u32),
    orientation: Orientation,
    view: Option<View>,
    colors: &[Rgb888],
) -> Result<Rendered, Error> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(width, height));
    let started = Instant::now();
    let system = HostSystem::with_capacity(grammar, order).with_orientation(orientation);
    let palette =
        Colors::new(colors).ok_or(Error::Fit(tinyfractal::error::FitError::EmptyPalette))?;
    let mut cells = cells_needed(grammar, order)
        .filter(|&needed| needed <= MAX_CELLS)
        .map_or_else(Vec::new, |needed| vec![Cell::default(); needed]);
    let area = fitted_area(width, height, view)?;
    let drawing = system.fit_in(area, palette, &mut cells)?;
    let fit = started.elapsed();
    let stats = drawn(drawing.try_draw(&mut display))?;
    Ok(Rendered::timed(display, stats, started, fit))
}

/// Every drawn segment, `x0 y0 x1 y1` per line, in turtle units (start at the origin, heading
/// +x, step 1, y up).
///
/// The engine's fixed-point values printed exactly. Streamed: a derivation of billions of
/// segments needs no more memory than one.
pub fn write_segments(grammar: &Grammar<'_>, order: u32, out: &mut dyn Write) -> io::Result<()> {
    let walk = Segments::<'_, '_, DEPTH, STACK>::with_capacity(grammar, order, Default::default())
        .map_err(io::Error::other)?;
    write_all_segments(walk, out)
}

/// [`write_segments`] for a parametric system.
pub fn write_parametric_segments(
    grammar: &ParametricGrammar,
    order: u32,
    out: &mut dyn Write,
) -> io::Result<()> {
    let walk = ParametricSegments::<'_, DEPTH, STACK>::new(grammar, order, Default::default())
        .map_err(io::Error::other)?;
    write_all_segments(walk, out)
}

/// `--segments` of a system drawn in 3D: `x0 y0 z0 x1 y1 z1` a line, in turtle units.
pub fn write_segments_3d(
    system: &tinyfractal::ParametricLSystem<'_, DEPTH, STACK>,
    out: &mut dyn Write,
) -> io::Result<()> {
    for segment in system.segments_3d().map_err(io::Error::other)? {
        let s = segment.map_err(io::Error::other)?;
        let ([x0, y0, z0], [x1, y1, z1]) = (s.start, s.end);
        writeln!(out, "{x0} {y0} {z0} {x1} {y1} {z1}")?;
    }
    Ok(())
}

/// `--polygons`: each filled polygon a line, its vertices `x y` (`x y z` if `space`) in
/// turtle units.
pub fn write_polygons(
    system: &tinyfractal::ParametricLSystem<'_, DEPTH, STACK>,
    space: bool,
    out: &mut dyn Write,
) -> io::Result<()> {
    let mut marks = system.marks().map_err(io::Error::other)?;
    while let Some(mark) = marks.next_mark() {
        if let tinyfractal::lsystem::Mark::Polygon { vertices, .. } =
            mark.map_err(io::Error::other)?
        {
            let mut line = String::new();
            for [x, y, z] in vertices {
                if !line.is_empty() {
                    line.push(' ');
                }
                line.push_str(&if space {
                    format!("{x} {y} {z}")
                } else {
                    format!("{x} {y}")
                });
            }
            writeln!(out, "{line}")?;
        }
    }
    Ok(())
}

fn write_all_segments(
    walk: impl Iterator<Item = Result<tinyfractal::lsystem::Segment, Error>>,
    out: &mut dyn Write,
) -> io::Result<()> {
    for segment in walk {
        let s = segment.map_err(io::Error::other)?;
        writeln!(out, "{} {} {} {}", s.start.x, s.start.y, s.end.x, s.end.y)?;
    }
    Ok(())
}

/// The one-line `--stats` report.
pub fn stats_line(rendered: &Rendered) -> String {
    let s = rendered.stats;
    format!(
        "segments={} max_stack={} max_depth={} symbols={} fit_ms={:.3} draw_ms={:.3} elapsed_ms={:.3}",
        s.segments,
        s.max_stack,
        s.max_depth,
        s.symbols,
        rendered.fit.as_secs_f64() * 1e3,
        rendered.draw.as_secs_f64() * 1e3,
        rendered.elapsed.as_secs_f64() * 1e3
    )
}
