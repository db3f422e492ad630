//! `render lsystem`: a plain or parametric system drawn at an order, with `--segments`.

use tinyfractal::ParametricGrammar;

use crate::args::LSystemArgs;
use crate::console::{self, Failure};
use crate::delivery::{deliver, window_available};
use crate::scene;
use crate::systems::{load, seed_applies, Loaded};

/// `render lsystem` of a parametric `.lsys` system. `--view` fits the whole picture to the
/// enlarged area and lets the target clip the rest (no expansion table here).
fn render_parametric(
    arguments: &LSystemArgs,
    grammar: &ParametricGrammar,
    name: &str,
) -> Result<(), String> {
    let common = &arguments.common;
    window_available(common.window)?;
    let order = arguments.order;
    let failed = |e: tinyfractal::Error| format!("{name} at order {order}: {e}");
    let look = scene::GeneralLook {
        projection: arguments.projection,
        depth_cue: arguments.depth_cue,
        environment: arguments.environment.as_ref(),
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
        "segments={} fit_ms={:.3} draw_ms={:.3} elapsed_ms={:.3}",
        rendered.stats.segments,
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
        },
        &stats_line,
    )
}

/// `render lsystem`: the system a source names, drawn at `--order`.
pub fn render_lsystem(arguments: &LSystemArgs) -> Result<(), Failure> {
    let mut file_text = String::new();
    let (loaded, name, kind) = load(&arguments.source, &mut file_text)?;
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
    seed_applies(kind, arguments.seed, &name)?;
    let mut grammar = match loaded {
        Loaded::Plain(grammar) => *grammar,
        Loaded::Parametric(mut grammar) => {
            if let Some(seed) = arguments.seed {
                grammar.set_seed(seed);
            }
            return Ok(render_parametric(arguments, &grammar, &name)?);
        }
    };
    if let Some(seed) = arguments.seed {
        grammar.set_seed(seed);
    }
    let common = &arguments.common;
    window_available(common.window)?;
    let failed = |e: tinyfractal::Error| format!("{name} at order {}: {e}", arguments.order);
    // Everything is computed and every output checked before anything is written.
    let rendered = scene::render(
        &grammar,
        arguments.order,
        common.width(),
        common.height(),
        arguments.view,
    )
    .map_err(failed)?;
    if rendered.stats.segments == 0 {
        console::complain(&format!(
            "tinyfractal: note: {name} draws nothing at order {}: the picture is empty\n",
            arguments.order
        ));
    }
    let (grammar, order) = (&grammar, arguments.order);
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
