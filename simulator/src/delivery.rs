//! The end of every render: the picture and the outputs a command adds, written all or
//! none, then the `--stats` line and the window.

use std::path::PathBuf;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::SimulatorDisplay;

use crate::common::Common;
use crate::dimension::dimension_line;
use crate::output;

/// The end of every render: the picture to `--out` (default `NAME.png`) and the outputs
/// `more` adds, all or none; then the `--stats` line and the window.
pub fn deliver<'a>(
    common: &Common,
    name: &str,
    display: &'a SimulatorDisplay<Rgb888>,
    more: impl FnOnce(&mut output::Plan<'a>),
    stats: &str,
) -> Result<(), String> {
    // What the panel shows (`--colors`, `--dither`): made once, kept for the plan's
    // writers, which borrow the picture for as long as the command runs.
    let display: &'a SimulatorDisplay<Rgb888> =
        match crate::common::as_panel(display, common.colors, common.dither) {
            Some(shown) => Box::leak(Box::new(shown)),
            None => display,
        };
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

/// `--window` in a build without the window: refused before anything is computed.
pub fn window_available(asked: bool) -> Result<(), String> {
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

#[cfg(not(feature = "window"))]
fn show(_: &SimulatorDisplay<Rgb888>) -> Result<(), String> {
    Err("built without a window: run with `cargo run --release --features window -- ...` (needs SDL2)".into())
}
