//! `tinyfractal explore`: the explorer a command starts, in an SDL window (with the
//! `window` feature; without it the arguments are checked and the run refused).

#[cfg(feature = "window")]
use embedded_graphics::pixelcolor::Rgb888;
#[cfg(feature = "window")]
use embedded_graphics_simulator::SimulatorDisplay;

use std::path::PathBuf;

use clap::Args;

use crate::console::Failure;
#[cfg(not(feature = "window"))]
use crate::delivery::window_available;
use crate::escape_scene;
use crate::explore;
use crate::files::{entry_names, read_text, FileKind};

/// `explore`'s options.
#[derive(Debug, Args)]
pub struct ExploreOptions {
    /// Page through the systems of this .l or .lsys file instead
    #[arg(long, value_name = "PATH", conflicts_with = "scene")]
    pub file: Option<PathBuf>,
    /// Page through the gallery's scenes instead, starting at this one (+/- its order,
    /// points, seed or iteration cap)
    #[arg(long, value_name = "NAME")]
    pub scene: Option<String>,
    /// Start with the Julia set of k = RE,IM
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    pub c: Option<(String, String)>,
    /// Centre of the first view, RE,IM
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", default_value = "-0.75,0", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    pub centre: (String, String),
    /// Width of the first view
    #[arg(
        long,
        value_name = "W",
        default_value = "3.5",
        allow_hyphen_values = true
    )]
    pub width: String,
    /// Iteration cap of the first view, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    pub max_iterations: u32,
    /// Picture size in pixels, WxH (a status line goes below it)
    #[arg(long = "size", value_name = "WxH", default_value = "320x240", value_parser = crate::common::parse_size)]
    pub size: (u32, u32),
}

impl ExploreOptions {
    /// `explore`: the explorer in a window (with the `window` feature; without it the
    /// options are checked and the run refused).
    pub fn run(&self) -> Result<(), Failure> {
        Ok(explore_window(self)?)
    }
}

/// The explorer a command starts.
fn explorer(arguments: &ExploreOptions) -> Result<explore::Explorer, String> {
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
    let julia = match &arguments.c {
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
fn explore_window(arguments: &ExploreOptions) -> Result<(), String> {
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
                        Keycode::H => Some(Input::Histogram),
                        Keycode::A => Some(Input::Autopilot),
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
fn explore_window(arguments: &ExploreOptions) -> Result<(), String> {
    // The arguments are still checked, so a mistake is reported as such.
    explorer(arguments)?;
    window_available(true)
}
