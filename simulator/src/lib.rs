//! The host front end, as a library so that the `tinyfractal` binary, the tests and the
//! fuzz targets share it: the argument parser, each family's host renderer, the gallery and
//! the all-or-nothing output plan. `src/main.rs` only calls [`run`].

pub mod animate;
pub mod args;
pub mod common;
pub mod console;
pub mod environment;
pub mod escape_scene;
pub mod explore;
pub mod figure_scene;
pub mod files;
pub mod gallery;
pub mod ifs_scene;
pub mod output;
pub mod palette;
pub mod progress;
pub mod scene;
pub mod shape_scene;

use std::io::{self, Write};
use std::path::{Path, PathBuf};

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::SimulatorDisplay;
use std::process::ExitCode;

use args::{Command, DeriveArgs, EscapeArgs, LSystemArgs, Source};
use files::{entry_names, is_lsys, read_text, FileKind};
use tinyfractal::{
    Grammar, LFile, LsysFile, ParametricGrammar, ParametricWalker, Walker, DEFAULT_BUDGET,
};

/// The `tinyfractal` command: parses the process's arguments and runs them.
pub fn run() -> ExitCode {
    output::remove_temporaries_on_interrupt();
    let command = match args::parse(std::env::args_os().skip(1)) {
        Ok(command) => command,
        Err(error) if !error.use_stderr() => {
            // --help and --version.
            let _ = error.print();
            return ExitCode::SUCCESS;
        }
        Err(error) => {
            console::complain(&format!(
                "tinyfractal: {}(see `tinyfractal help`, or `tinyfractal help COMMAND`)\n",
                error.render()
            ));
            return ExitCode::from(2);
        }
    };
    let result = (|| -> Result<(), Failure> {
        match command {
            Command::Completions(shell) => args::completions(shell)?,
            Command::List(path) => list(&path)?,
            Command::Animate(arguments) => animate::animate(&arguments)?,
            Command::Explore(arguments) => explore_window(&arguments)?,
            Command::Derive(arguments) => derive(&arguments)?,
            Command::Gallery { out } => gallery::run(&out)?,
            Command::RenderLSystem(lsystem) => render_lsystem(&lsystem)?,
            Command::RenderEscape(escape) => render_escape(&escape)?,
            Command::RenderIfs(options) => ifs_scene::render_ifs(&options)?,
            Command::RenderGingerbread(options) => ifs_scene::render_gingerbread(&options)?,
            Command::RenderFigure(options) => figure_scene::render_figure(&options)?,
            Command::RenderCarpet(options) => shape_scene::render_carpet(&options)?,
            Command::RenderGasket(options) => shape_scene::render_gasket(&options)?,
            Command::RenderCube(options) => shape_scene::render_cube(&options)?,
            Command::RenderTerrain(options) => shape_scene::render_terrain(&options)?,
            Command::RenderTerrain2d(options) => shape_scene::render_terrain2d(&options)?,
            Command::Dimension { file, background } => dimension(&file, background)?,
        }
        Ok(())
    })();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // Standard output was closed (`| head`): a quiet stop.
        Err(Failure::Run(message)) if message == console::QUIET => ExitCode::FAILURE,
        Err(Failure::Run(message)) => {
            console::complain(&format!("tinyfractal: error: {message}\n"));
            ExitCode::FAILURE
        }
        Err(Failure::Usage(message)) => {
            console::complain(&format!(
                "tinyfractal: error: {message}\n(see `tinyfractal help`, or `tinyfractal help \
                 COMMAND`)\n"
            ));
            ExitCode::from(2)
        }
    }
}

/// Why a command failed, and so its exit status: a run's error (1), or a usage error
/// found only once the input was read (2), such as an option the file's system does not
/// take.
pub enum Failure {
    Run(String),
    Usage(String),
}

impl From<String> for Failure {
    fn from(message: String) -> Self {
        Self::Run(message)
    }
}

fn list(path: &Path) -> Result<(), String> {
    let text = read_text(path)?;
    let failed = |e: tinyfractal::Error| format!("{}: {e}", path.display());
    let names: Vec<&str> = entry_names(FileKind::of(path, &text), &text)
        .into_iter()
        .collect::<Result<_, _>>()
        .map_err(failed)?;
    let mut listed = String::new();
    for name in names {
        listed.push_str(name);
        listed.push('\n');
    }
    console::print(&listed)
}

/// A system as a source names it: plain (Fractint, ABOP, stochastic) or parametric.
pub(crate) enum Loaded<'a> {
    Plain(Box<Grammar<'a>>),
    Parametric(Box<ParametricGrammar>),
}

/// The system a source names, the name to report it by, and the kind of its file (`None`
/// inline); warnings go to stderr. The file is read once, here.
pub(crate) fn load<'a>(
    source: &'a Source,
    file_text: &'a mut String,
) -> Result<(Loaded<'a>, String, Option<FileKind>), String> {
    load_for(source, file_text, Purpose::Draw)
}

/// What a system is loaded for: a drawing needs its angle, a derivation does not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Purpose {
    Draw,
    Derive,
}

/// [`load`] for `purpose`.
pub(crate) fn load_for<'a>(
    source: &'a Source,
    file_text: &'a mut String,
    purpose: Purpose,
) -> Result<(Loaded<'a>, String, Option<FileKind>), String> {
    Ok(match source {
        Source::File { path, name } => {
            *file_text = read_text(path)?;
            let file_text: &'a String = file_text;
            let failed = |e: tinyfractal::Error| format!("{name} in {}: {e}", path.display());
            if is_lsys(path, file_text)? {
                let entry = LsysFile::new(file_text).entry(name).map_err(failed)?;
                let loaded = if entry.is_parametric() {
                    Loaded::Parametric(Box::new(entry.parametric().map_err(failed)?))
                } else if purpose == Purpose::Derive {
                    Loaded::Plain(Box::new(entry.grammar_to_derive().map_err(failed)?))
                } else {
                    Loaded::Plain(Box::new(entry.grammar().map_err(failed)?))
                };
                return Ok((loaded, name.clone(), Some(FileKind::Lsys)));
            }
            let entry = LFile::new(file_text).entry(name).map_err(failed)?;
            let grammar = match purpose {
                Purpose::Derive => entry.grammar_to_derive(),
                Purpose::Draw => entry.grammar(),
            }
            .map_err(failed)?;
            for warning in entry.warnings() {
                warn(&format!("{name} in {}: {warning}", path.display()));
            }
            (
                Loaded::Plain(Box::new(grammar)),
                name.clone(),
                Some(FileKind::Fractint),
            )
        }
        Source::Inline {
            axiom,
            rules,
            angle,
            draw_symbols,
            dialect,
        } => {
            let label = "inline system";
            let with = |e: tinyfractal::Error| format!("{label}: {e}");
            let mut grammar = Grammar::new(*dialect, axiom, *angle)
                .map_err(with)?
                .with_draw_symbols(draw_symbols)
                .map_err(with)?;
            for (symbol, body) in rules {
                grammar = grammar
                    .with_rule(*symbol, body)
                    .map_err(|e| format!("{label}: rule {symbol}={body}: {e}"))?;
            }
            (
                Loaded::Plain(Box::new(grammar)),
                "lsystem".to_string(),
                None,
            )
        }
    })
}

/// `derive`: the string at the order, on one line, if it is at most `--max-length` symbols
/// (measured first, so nothing is printed past the limit).
fn derive(arguments: &DeriveArgs) -> Result<(), Failure> {
    let mut file_text = String::new();
    let (loaded, name, kind) = load_for(&arguments.source, &mut file_text, Purpose::Derive)?;
    seed_applies(kind, arguments.seed, &name)?;
    let budget = derive_budget(arguments);
    let mut grammar = match loaded {
        Loaded::Plain(grammar) => *grammar,
        Loaded::Parametric(mut grammar) => {
            if let Some(seed) = arguments.seed {
                grammar.set_seed(seed);
            }
            let walk = || {
                ParametricWalker::<'_, { scene::DEPTH }>::new(&grammar, arguments.order)
                    .map(|walker| walker.with_budget(budget))
            };
            return Ok(print_derivation(walk, arguments, &name)?);
        }
    };
    if let Some(seed) = arguments.seed {
        grammar.set_seed(seed);
    }
    let walk = || {
        Walker::<'_, '_, { scene::DEPTH }>::with_capacity(&grammar, arguments.order).map(|walker| {
            let mut walker = walker.with_budget(budget);
            core::iter::from_fn(move || walker.next_symbol())
        })
    };
    Ok(print_derivation(walk, arguments, &name)?)
}

/// `--seed` is for the stochastic productions only `.lsys` files have: given for a `.l`
/// file's or an inline system, it is a usage error, not ignored.
fn seed_applies(kind: Option<FileKind>, seed: Option<u32>, name: &str) -> Result<(), Failure> {
    if seed.is_some() && kind != Some(FileKind::Lsys) {
        return Err(Failure::Usage(format!(
            "--seed does not apply to {name}: only `.lsys` systems have stochastic \
             productions (leave out --seed)"
        )));
    }
    Ok(())
}

/// Reads a walk may take: expansions that print nothing still take reads, so they are
/// bounded too.
fn derive_budget(arguments: &DeriveArgs) -> u64 {
    arguments.max_length.saturating_mul(64).max(DEFAULT_BUDGET)
}

/// Longest `--max-length` that is checked before anything is printed: counting this many
/// symbols takes well under a second.
const COUNTED_FIRST: u64 = 10_000_000;

/// Prints a derivation on one line if it has at most `--max-length` symbols. Up to
/// [`COUNTED_FIRST`], `walk` is walked once to count them, then again to print, so nothing
/// is printed past the limit and nothing is kept in memory; past it the string streams as
/// it is derived (`derive ... | head` ends at once) and the run stops with the error at
/// the limit.
fn print_derivation<W, I, T>(walk: W, arguments: &DeriveArgs, name: &str) -> Result<(), String>
where
    W: Fn() -> Result<I, tinyfractal::Error>,
    I: Iterator<Item = Result<T, tinyfractal::Error>>,
    T: std::fmt::Display,
{
    let order = arguments.order;
    let failed = |e: tinyfractal::Error| format!("{name} at order {order}: {e}");
    let too_long = || {
        format!(
            "{name} at order {order}: the derived string is longer than {} symbols: \
             lower the order or raise --max-length",
            arguments.max_length
        )
    };
    let counted_first = arguments.max_length <= COUNTED_FIRST;
    if counted_first {
        let mut length = 0u64;
        for symbol in walk().map_err(failed)? {
            symbol.map_err(failed)?;
            length += 1;
            if length > arguments.max_length {
                return Err(too_long());
            }
        }
    }
    /// Why printing stopped.
    enum Stop {
        Walk(tinyfractal::Error),
        TooLong,
        Output(io::Error),
    }
    let mut out = io::BufWriter::new(io::stdout().lock());
    let written = (|| -> Result<(), Stop> {
        let mut length = 0u64;
        for symbol in walk().map_err(Stop::Walk)? {
            length += 1;
            if length > arguments.max_length {
                return Err(Stop::TooLong);
            }
            write!(out, "{}", symbol.map_err(Stop::Walk)?).map_err(Stop::Output)?;
        }
        writeln!(out)
            .and_then(|()| out.flush())
            .map_err(Stop::Output)
    })();
    match written {
        Ok(()) => Ok(()),
        Err(Stop::Walk(e)) => Err(failed(e)),
        Err(Stop::TooLong) => {
            // What was printed ends its line, so the message is not glued to it.
            let _ = writeln!(out).and_then(|()| out.flush());
            Err(too_long())
        }
        Err(Stop::Output(e)) => Err(console::failed(&e)),
    }
}

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

fn render_lsystem(arguments: &LSystemArgs) -> Result<(), Failure> {
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

fn render_escape(arguments: &EscapeArgs) -> Result<(), String> {
    let common = &arguments.common;
    let name = if arguments.julia.is_some() {
        "julia"
    } else {
        "mandelbrot"
    };
    let size = embedded_graphics::geometry::Size::new(common.width(), common.height());
    let request = escape_scene::request(arguments, size);
    window_available(common.window)?;
    // Everything is computed and every output checked before anything is written.
    let rendered = escape_scene::render(&request).map_err(|e| format!("{name}: {e}"))?;
    if let Some(warning) = escape_scene::TierWarning::of(&rendered.view) {
        warn(&warning.message(&rendered.view));
    }
    deliver(
        common,
        name,
        &rendered.display,
        |plan| {
            if let Some(path) = &arguments.dwell {
                plan.add("--dwell", path, |w| {
                    escape_scene::write_dwells(&rendered, w)
                });
            }
        },
        &escape_scene::stats_line(&rendered),
    )
}

/// Says something the user should know on stderr; the run goes on.
fn warn(message: &str) {
    console::complain(&format!("tinyfractal: warning: {message}\n"));
}

/// The end of every render: the picture to `--out` (default `NAME.png`) and the outputs
/// `more` adds, all or none; then the `--stats` line and the window.
fn deliver<'a>(
    common: &args::Common,
    name: &str,
    display: &'a SimulatorDisplay<Rgb888>,
    more: impl FnOnce(&mut output::Plan<'a>),
    stats: &str,
) -> Result<(), String> {
    let out = common
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{name}.png")));
    let mut plan = output::Plan::new();
    plan.add("--out", &out, |w| output::png(display, w));
    more(&mut plan);
    // The lines for standard output are made first and printed before any file is put
    // in place: a `--dimension` that fails, or an output that cannot be printed, leaves
    // the folder as it was.
    let mut printed = String::new();
    if common.stats {
        printed.push_str(stats);
        printed.push('\n');
    }
    if common.dimension {
        printed.push_str(&dimension_line(display, Rgb888::new(0, 0, 0))?);
        printed.push('\n');
    }
    plan.print(printed);
    plan.write()?;
    if common.window {
        show(display)?;
    }
    Ok(())
}

/// The box-counting dimension of `display`'s pixels other than `background`, as
/// `dimension=D.DDD residual=R.RRR boxes=S..L` (box sides in pixels).
fn dimension_line(
    display: &SimulatorDisplay<Rgb888>,
    background: Rgb888,
) -> Result<String, String> {
    use embedded_graphics::prelude::*;
    let size = display.size();
    let mut bits = vec![0u32; tinyfractal::BoxCounter::<Rgb888>::words_needed(size, 0)];
    let mut counter = tinyfractal::BoxCounter::new(size, 0, background, &mut bits)
        .map_err(|e| format!("dimension: {e}"))?;
    let pixels = display
        .bounding_box()
        .points()
        .map(|p| display.get_pixel(p));
    let Ok(()) = counter.fill_contiguous(&display.bounding_box(), pixels);
    let estimate = counter.dimension().map_err(|e| format!("dimension: {e}"))?;
    Ok(format!(
        "dimension={:.3} residual={:.3} boxes={}..{}",
        estimate.value.to_f64(),
        estimate.residual.to_f64(),
        1u32 << estimate.smallest,
        1u32 << estimate.largest
    ))
}

/// `tinyfractal dimension FILE.png`: the picture's box-counting dimension.
fn dimension(path: &Path, background: u32) -> Result<(), String> {
    use embedded_graphics::prelude::*;
    let picture = image::open(path)
        .map_err(|e| format!("dimension {}: {e}", path.display()))?
        .to_rgb8();
    let (width, height) = picture.dimensions();
    let mut display = SimulatorDisplay::new(embedded_graphics::prelude::Size::new(width, height));
    for (x, y, pixel) in picture.enumerate_pixels() {
        let [r, g, b] = pixel.0;
        let _ = Pixel(Point::new(x as i32, y as i32), Rgb888::new(r, g, b)).draw(&mut display);
    }
    let [_, r, g, b] = background.to_be_bytes();
    console::print(&format!(
        "{}\n",
        dimension_line(&display, Rgb888::new(r, g, b))?
    ))
}

/// `--window` in a build without the window: refused before anything is computed.
fn window_available(asked: bool) -> Result<(), String> {
    if asked && cfg!(not(feature = "window")) {
        return Err("--window: built without a window: run with `cargo run --release --features window -- ...` (needs SDL2)".into());
    }
    Ok(())
}

#[cfg(feature = "window")]
fn show(display: &SimulatorDisplay<Rgb888>) -> Result<(), String> {
    use embedded_graphics_simulator::{OutputSettingsBuilder, Window};
    Window::new(
        "tinyfractal",
        &OutputSettingsBuilder::new().scale(2).build(),
    )
    .show_static(display);
    Ok(())
}

/// The explorer a command starts.
fn explorer(arguments: &args::ExploreArgs) -> Result<explore::Explorer, String> {
    let size = embedded_graphics::geometry::Size::new(arguments.size.0, arguments.size.1);
    if let Some(name) = &arguments.scene {
        return explore::Explorer::gallery(name, size);
    }
    if let Some(path) = &arguments.file {
        let text = read_text(path)?;
        let kind = FileKind::of(path, &text).lsystems(path)?;
        let names: Vec<String> = entry_names(kind, &text)
            .into_iter()
            .filter_map(|name| name.ok().map(str::to_string))
            .collect();
        if names.is_empty() {
            return Err(format!("{}: no systems to explore", path.display()));
        }
        let lsys = kind == FileKind::Lsys;
        return Ok(explore::Explorer::lsystems(text, names, lsys, size));
    }
    let number = |option: &str, text: &str| {
        escape_scene::coordinate(option, text).map(tinyfractal::Coord::to_f64)
    };
    let julia = match &arguments.julia {
        Some((re, im)) => Some((
            escape_scene::coordinate("--c", re)?,
            escape_scene::coordinate("--c", im)?,
        )),
        None => None,
    };
    let start = explore::EscapeState {
        julia,
        centre: (
            number("--center", &arguments.centre.0)?,
            number("--center", &arguments.centre.1)?,
        ),
        width: number("--width", &arguments.width)?,
        max_iterations: arguments.max_iterations,
        ..explore::EscapeState::default()
    };
    Ok(explore::Explorer::escape(start, size))
}

#[cfg(feature = "window")]
fn explore_window(arguments: &args::ExploreArgs) -> Result<(), String> {
    use embedded_graphics_simulator::sdl2::{Keycode, MouseButton};
    use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorEvent, Window};
    use explore::Input;
    let mut explorer = explorer(arguments)?;
    let size = explorer.picture_size();
    let mut display = SimulatorDisplay::<Rgb888>::new(embedded_graphics::geometry::Size::new(
        size.width,
        size.height + explore::STATUS_HEIGHT,
    ));
    let mut window = Window::new("tinyfractal explore", &OutputSettingsBuilder::new().build());
    let (mut mouse, mut pressed) = (embedded_graphics::prelude::Point::zero(), None);
    loop {
        explorer.tick(&mut display, explore::TICK_BUDGET);
        window.update(&display);
        let events: Vec<SimulatorEvent> = window.events().collect();
        for event in events {
            let input = match event {
                SimulatorEvent::Quit => return Ok(()),
                SimulatorEvent::MouseMove { point } => {
                    mouse = point;
                    None
                }
                SimulatorEvent::MouseButtonDown { point, .. } => {
                    pressed = Some(point);
                    None
                }
                SimulatorEvent::MouseButtonUp { mouse_btn, point } => {
                    let from = pressed.take().unwrap_or(point);
                    let moved = point - from;
                    if moved.x.abs() + moved.y.abs() > 3 {
                        Some(Input::Pan(moved.x, moved.y))
                    } else if mouse_btn == MouseButton::Right {
                        Some(Input::ZoomOut(point))
                    } else {
                        Some(Input::ZoomIn(point))
                    }
                }
                SimulatorEvent::MouseWheel { scroll_delta, .. } => {
                    Some(Input::Wheel(mouse, scroll_delta.y))
                }
                SimulatorEvent::KeyDown { keycode, .. } => {
                    let step = (size.width / 10) as i32;
                    match keycode {
                        Keycode::Left => Some(Input::Pan(step, 0)),
                        Keycode::Right => Some(Input::Pan(-step, 0)),
                        Keycode::Up => Some(Input::Pan(0, step)),
                        Keycode::Down => Some(Input::Pan(0, -step)),
                        Keycode::Plus | Keycode::Equals | Keycode::KpPlus => Some(Input::More),
                        Keycode::Minus | Keycode::KpMinus => Some(Input::Fewer),
                        Keycode::P => Some(Input::NextPalette),
                        Keycode::C => Some(Input::ToggleCycling),
                        Keycode::J => Some(Input::JuliaAt(mouse)),
                        Keycode::S => Some(Input::Save),
                        Keycode::R => Some(Input::Reset),
                        Keycode::PageDown => Some(Input::NextSystem),
                        Keycode::PageUp => Some(Input::PreviousSystem),
                        Keycode::Escape | Keycode::Q => return Ok(()),
                        _ => None,
                    }
                }
                _ => None,
            };
            if let Some(input) = input {
                explorer.input(input);
            }
        }
    }
}

#[cfg(not(feature = "window"))]
fn explore_window(arguments: &args::ExploreArgs) -> Result<(), String> {
    // The arguments are still checked, so a mistake is reported as such.
    explorer(arguments)?;
    window_available(true)
}

#[cfg(not(feature = "window"))]
fn show(_: &SimulatorDisplay<Rgb888>) -> Result<(), String> {
    Err("built without a window: run with `cargo run --release --features window -- ...` (needs SDL2)".into())
}
