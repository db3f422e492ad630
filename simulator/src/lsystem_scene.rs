//! `render lsystem`: a plain or parametric system drawn at an order, with `--segments`.

use std::path::PathBuf;

use clap::Args;
use embedded_graphics::pixelcolor::Rgb888;
use tinyfractal::ParametricGrammar;

use crate::common::{Common, View};
use crate::console::{self, Failure};
use crate::delivery::{deliver, window_available};
use crate::scene;
use crate::systems::{load, seed_applies, Loaded, Purpose, SystemOptions};

/// `render lsystem` of a parametric `.lsys` system. `--view` fits the whole picture to the
/// enlarged area and lets the target clip the rest (no expansion table here).
fn render_parametric(
    arguments: &LSystemOptions,
    grammar: &ParametricGrammar,
    entry_colors: &[Rgb888],
    name: &str,
) -> Result<(), String> {
    let common = &arguments.common;
    window_available(common.window)?;
    let order = arguments.system.order;
    let failed = |e: tinyfractal::Error| format!("{name} at order {order}: {e}");
    let colormap = arguments
        .colormap
        .as_deref()
        .map(crate::palette::read_map)
        .transpose()?;
    let look = scene::GeneralLook {
        projection: arguments.projection,
        depth_cue: arguments.depth_cue,
        environment: arguments.environment.as_ref(),
        colormap: colormap
            .as_deref()
            .or((!entry_colors.is_empty()).then_some(entry_colors)),
        ..scene::GeneralLook::default()
    };
    let rendered = scene::render_general(
        grammar,
        order,
        (common.width(), common.height()),
        arguments.view,
        &look,
    )
    .map_err(failed)?;
    let stats_line = format!(
        "segments={} polygons={} fit_ms={:.3} draw_ms={:.3} elapsed_ms={:.3}",
        rendered.stats.segments,
        rendered.stats.polygons,
        rendered.fit.as_secs_f64() * 1e3,
        rendered.draw.as_secs_f64() * 1e3,
        rendered.elapsed.as_secs_f64() * 1e3
    );
    let system = scene::general_system(grammar, order, &look);
    let display = rendered.display;
    deliver(
        common,
        &name.to_lowercase(),
        &display,
        |plan| {
            if let Some(path) = &arguments.segments {
                plan.add("--segments", path, move |w| match system.projection() {
                    Some(_) => scene::write_segments_3d(&system, w),
                    None => scene::write_parametric_segments(grammar, order, w),
                });
            }
            if let Some(path) = &arguments.polygons {
                plan.add("--polygons", path, move |w| {
                    scene::write_polygons(&system, grammar.is_3d(), w)
                });
            }
        },
        &stats_line,
    )
}

/// `render lsystem`'s options.
#[derive(Debug, Args)]
pub struct LSystemOptions {
    #[command(flatten)]
    pub system: SystemOptions,
    /// Write every drawn segment, `x0 y0 x1 y1` in turtle units
    #[arg(long, value_name = "TXT")]
    pub segments: Option<PathBuf>,
    /// Write every filled polygon (`{ }`), one a line: its vertices `x y` in turtle units
    /// (`x y z` for a system that turns in space), in drawing order
    #[arg(long, value_name = "TXT")]
    pub polygons: Option<PathBuf>,
    /// Draw only this window of the picture: fractions of the target the whole picture
    /// fills (0,0 top left, 1,1 bottom right), e.g. 0.4,0.4,0.6,0.6 to zoom 5 times
    #[arg(long, value_name = "X0,Y0,X1,Y1", value_parser = crate::common::parse_view, allow_hyphen_values = true)]
    pub view: Option<View>,
    /// Draw an .lsys system with the 3D turtle, seen from the front, isometric, or in
    /// perspective (systems using & ^ \ / $ are drawn in 3D anyway, isometric by default)
    #[arg(long, value_name = "VIEW", value_parser = crate::common::parse_projection)]
    pub projection: Option<tinyfractal::render::Projection>,
    /// In 3D, colour each line by its depth, nearer brighter
    #[arg(long = "depth-cue")]
    pub depth_cue: bool,
    /// The world an open system (env(k) in its productions) grows in: circle:R or heart:R,
    /// R in turtle units, the shape standing on the turtle's start; env(0) is 1 inside
    #[arg(long, value_name = "SHAPE:R", value_parser = crate::environment::Shape::parse)]
    pub environment: Option<crate::environment::Shape>,
    /// A Fractint .map colour map (lines `R G B`) for the colour modules to index; default:
    /// Fractint's 16 colours for .l systems, browns to greens for .lsys ones
    #[arg(long, value_name = "FILE.map")]
    pub colormap: Option<PathBuf>,
    #[command(flatten)]
    pub common: Common,
}

impl LSystemOptions {
    /// `render lsystem`: the system the options name, drawn at `--order`.
    pub fn run(&self) -> Result<(), Failure> {
        render_lsystem(self)
    }
}

fn render_lsystem(arguments: &LSystemOptions) -> Result<(), Failure> {
    let source = arguments.system.source(Purpose::Draw)?;
    let mut file_text = String::new();
    let (loaded, name, kind) = load(&source, &mut file_text)?;
    let three_d = [
        ("--projection", arguments.projection.is_some()),
        ("--depth-cue", arguments.depth_cue),
        ("--environment", arguments.environment.is_some()),
    ];
    if let (Loaded::Plain(_), Some((option, _))) =
        (&loaded, three_d.iter().find(|(_, given)| *given))
    {
        return Err(Failure::Usage(format!(
            "{option} does not apply to {name}: 3D views, depth cueing and environments are \
             the general engine's, for parametric `.lsys` systems, and {name} is drawn in the \
             plane (leave out {option})"
        )));
    }
    seed_applies(kind, arguments.system.seed, &name)?;
    let mut grammar = match loaded {
        Loaded::Plain(grammar) => *grammar,
        Loaded::Parametric(mut grammar, colors) => {
            if let Some(seed) = arguments.system.seed {
                grammar.set_seed(seed);
            }
            return Ok(render_parametric(arguments, &grammar, &colors, &name)?);
        }
    };
    if let Some(seed) = arguments.system.seed {
        grammar.set_seed(seed);
    }
    let common = &arguments.common;
    window_available(common.window)?;
    let failed = |e: tinyfractal::Error| format!("{name} at order {}: {e}", arguments.system.order);
    let colormap = arguments
        .colormap
        .as_deref()
        .map(crate::palette::read_map)
        .transpose()?;
    // Everything is computed and every output checked before anything is written.
    let rendered = scene::render_in(
        &grammar,
        arguments.system.order,
        (common.width(), common.height()),
        arguments.view,
        colormap.as_deref().unwrap_or(&crate::palette::VGA),
    )
    .map_err(failed)?;
    if rendered.stats.segments == 0 {
        console::complain(&format!(
            "tinyfractal: note: {name} draws nothing at order {}: the picture is empty\n",
            arguments.system.order
        ));
    }
    let (grammar, order) = (&grammar, arguments.system.order);
    Ok(deliver(
        common,
        &name.to_lowercase(),
        &rendered.display,
        |plan| {
            if let Some(path) = &arguments.segments {
                // The same walk as the fit's sizing pass, which succeeded: it cannot fail.
                plan.add("--segments", path, move |w| {
                    scene::write_segments(grammar, order, w)
                });
            }
        },
        &scene::stats_line(&rendered),
    )?)
}
