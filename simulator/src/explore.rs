//! `tinyfractal explore`: the explorer's state and inputs, apart from SDL.
//!
//! An explorer of escape-time views and L-system files, as Fractint and XaoS users know it. The
//! state and its inputs live here, apart from SDL, so that they are tested headless: an
//! [`Input`] changes the view and cancels the stale render, and [`Explorer::tick`] renders
//! progressively (a coarse preview first, then the budgeted `Render::step`), so the window
//! stays responsive while a deep view computes. The `window` feature's loop only maps SDL
//! events to inputs and shows the display.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    escape::{Algorithm, Autopilot, Painter, Render},
    render::{DwellBuffer, DwellSink},
    Coord, View,
};

use tinyfractal_scenes::{Entry, Scene, GALLERY};

use crate::escape_scene::{self, HostPalette};

/// The palettes `p` steps through.
pub const PALETTES: [&str; 7] = [
    "classic",
    "fire",
    "gray",
    "smooth-classic",
    "smooth-fire",
    "bands",
    "histogram",
];

/// Where `h` goes: histogram colouring.
const HISTOGRAM: usize = 6;

/// Height of the status line at the bottom, in pixels.
pub const STATUS_HEIGHT: u32 = 12;

/// Iterations a tick computes at most before the window is updated.
pub const TICK_BUDGET: u64 = 2_000_000;

/// What the user did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// Zoom in twice, centred on a pixel (left click).
    ZoomIn(Point),
    /// Zoom out twice, centred on a pixel (right click).
    ZoomOut(Point),
    /// The wheel: up (positive) zooms in by 1.25 a notch about the pixel, down zooms out.
    Wheel(Point, i32),
    /// Move the view by pixels (drag, or arrow keys: a tenth of the picture).
    Pan(i32, i32),
    /// `+` / `-`: double or halve the iteration cap (escape time), or the order ± 1.
    More,
    /// Halves the iteration cap (or lowers the order).
    Fewer,
    /// `p`: the next palette.
    NextPalette,
    /// `h`: histogram colouring (each colour an equal share of the escaping pixels).
    Histogram,
    /// `c`: colour cycling on or off.
    ToggleCycling,
    /// `a`: XaoS's autopilot on or off: each finished picture, the view it steers to next.
    Autopilot,
    /// `j`: the Julia set of the point under the mouse (or back to the Mandelbrot set).
    JuliaAt(Point),
    /// `s`: save the picture as a PNG.
    Save,
    /// `r`: back to the start.
    Reset,
    /// Page down / page up: the next or previous system of an L-system file.
    NextSystem,
    /// The file's previous system, or the gallery's previous scene.
    PreviousSystem,
}

/// An escape-time view being explored.
#[derive(Debug, Clone, PartialEq)]
pub struct EscapeState {
    /// The Julia parameter, or `None` for the Mandelbrot set.
    pub julia: Option<(Coord, Coord)>,
    /// The centre.
    pub centre: (f64, f64),
    /// The width along the real axis.
    pub width: f64,
    /// The iteration cap.
    pub max_iterations: u32,
    /// The palette, an index into [`PALETTES`].
    pub palette: usize,
    /// Whether the colours cycle.
    pub cycling: bool,
    /// How far the colours have cycled.
    pub offset: u16,
}

impl Default for EscapeState {
    fn default() -> Self {
        Self {
            julia: None,
            centre: (-0.75, 0.0),
            width: 3.5,
            max_iterations: 256,
            palette: 0,
            cycling: false,
            offset: 0,
        }
    }
}

/// What is explored.
#[derive(Debug)]
pub enum Subject {
    /// An escape-time view.
    Escape(EscapeState),
    /// An L-system file's systems (text, names), the one shown and its order.
    LSystems {
        /// The file's text.
        text: String,
        /// An `.lsys` file (else Fractint's `.l`).
        lsys: bool,
        /// The names of its systems.
        names: Vec<String>,
        /// Which system is shown.
        index: usize,
        /// The order it is drawn at.
        order: u32,
    },
    /// The gallery's scenes: the one shown (at the explorer's size), with its parameter
    /// moved by `+`/`-`.
    Gallery {
        /// Which scene is shown.
        index: usize,
        /// The scene, with its own parameter as the user moved it.
        entry: Entry,
    },
}

/// Highest order `+` reaches.
const MAX_ORDER: u32 = 16;

/// `value` one up (at most `high`) or one down (at least `low`).
fn stepped(value: u32, up: bool, low: u32, high: u32) -> u32 {
    if up {
        value.saturating_add(1).min(high)
    } else {
        value.saturating_sub(1).max(low)
    }
}

/// An iteration cap doubled or halved, within 16 and the smooth palettes' cap (so every
/// palette can show it).
fn stepped_cap(cap: u32, up: bool) -> u32 {
    if up {
        cap.saturating_mul(2).min(View::MAX_SMOOTH_ITERATIONS)
    } else {
        (cap / 2).max(16)
    }
}

/// The index after `index` (`next`) or before it, of `count`, wrapping round.
fn paged(index: usize, count: usize, next: bool) -> usize {
    let count = count.max(1);
    if next {
        (index + 1) % count
    } else {
        (index + count - 1) % count
    }
}

/// The gallery scene `index`, at `size`.
fn gallery_entry(index: usize, size: Size) -> Entry {
    let entry = GALLERY[index % GALLERY.len()];
    Entry { size, ..entry }
}

/// `entry` with its own parameter one step up or down: an order, the points of a chaos
/// game, a landscape's seed, an iteration cap.
fn adjusted(entry: Entry, up: bool) -> Entry {
    let scene = match entry.scene {
        Scene::LSystem {
            system,
            order,
            orientation,
        } => Scene::LSystem {
            system,
            order: stepped(order, up, 0, MAX_ORDER),
            orientation,
        },
        Scene::Subdivision { shape, order } => Scene::Subdivision {
            shape,
            order: stepped(order, up, 0, 7),
        },
        Scene::Ifs {
            source,
            system,
            points,
            seed,
            density,
        } => Scene::Ifs {
            source,
            system,
            points: if up {
                (points * 2).min(10_000_000)
            } else {
                (points / 2).max(1_000)
            },
            seed,
            density,
        },
        Scene::Attractor { kind, points } => Scene::Attractor {
            kind,
            points: if up {
                (points * 2).min(10_000_000)
            } else {
                (points / 2).max(1_000)
            },
        },
        Scene::Terrain {
            mut displacement,
            samples,
            map,
        } => {
            displacement.seed = if up {
                displacement.seed.wrapping_add(1)
            } else {
                displacement.seed.wrapping_sub(1)
            };
            Scene::Terrain {
                displacement,
                samples,
                map,
            }
        }
        Scene::Escape(escape) => {
            Scene::Escape(escape.with_max_iterations(stepped_cap(escape.max_iterations, up)))
        }
        Scene::NoiseFlight {
            texture,
            octaves,
            scale,
            seed,
            frames,
            z_step,
        } => Scene::NoiseFlight {
            texture,
            octaves,
            scale,
            seed: if up {
                seed.wrapping_add(1)
            } else {
                seed.wrapping_sub(1)
            },
            frames,
            z_step,
        },
        Scene::NoiseTerrain {
            octaves,
            scale,
            seed,
            samples,
        } => Scene::NoiseTerrain {
            octaves,
            scale,
            seed: if up {
                seed.wrapping_add(1)
            } else {
                seed.wrapping_sub(1)
            },
            samples,
        },
        Scene::Reaction {
            preset,
            grid,
            steps,
        } => Scene::Reaction {
            preset,
            grid,
            steps: if up {
                steps.saturating_mul(2).min(64_000)
            } else {
                (steps / 2).max(100)
            },
        },
        Scene::Noise {
            texture,
            octaves,
            scale,
            seed,
        } => Scene::Noise {
            texture,
            octaves,
            scale,
            seed: if up {
                seed.wrapping_add(1)
            } else {
                seed.wrapping_sub(1)
            },
        },
        Scene::Zoom {
            centre,
            width,
            max_iterations,
            frames,
            shrink,
            tolerance_percent,
            pilot,
        } => Scene::Zoom {
            centre,
            width,
            // A board keeps a byte a pixel.
            max_iterations: stepped_cap(max_iterations, up).min(255),
            frames,
            shrink,
            tolerance_percent,
            pilot,
        },
        // Nothing of its own to step: the figure and the curves stay as they are.
        unchanged @ (Scene::Walk { .. } | Scene::Bezier { .. } | Scene::Particles { .. }) => {
            unchanged
        }
    };
    Entry { scene, ..entry }
}

/// The explorer: what is shown, the render under way, and the status line's facts.
#[derive(Debug)]
pub struct Explorer {
    /// What is shown.
    pub subject: Subject,
    start: EscapeState,
    size: Size,
    render: Option<(Render<'static>, View, HostPalette)>,
    /// The values computed so far (colour cycling repaints from them).
    values: Vec<u16>,
    started: Instant,
    /// How long the last complete picture took.
    pub elapsed: Duration,
    /// Where `s` saves, numbered.
    saves: u32,
    /// `s` was pressed: save once the picture is complete.
    save_pending: bool,
    /// The status line's last message (a save, an error).
    pub message: String,
    /// What a gallery scene's picture reports (its order, tier, ...).
    detail: String,
    /// `a`: the autopilot flying, and how many flights were started (each its own seed).
    autopilot: Option<Autopilot>,
    flights: u64,
}

impl Explorer {
    /// An explorer of escape-time views, its picture `size` (the status line below it).
    pub fn escape(start: EscapeState, size: Size) -> Self {
        Self::new(Subject::Escape(start.clone()), start, size)
    }

    /// An explorer of the systems in an L-system file.
    pub fn lsystems(text: String, names: Vec<String>, lsys: bool, size: Size) -> Self {
        let subject = Subject::LSystems {
            text,
            lsys,
            names,
            index: 0,
            order: 3,
        };
        Self::new(subject, EscapeState::default(), size)
    }

    /// An explorer of the gallery's scenes, starting at the one called `name`.
    pub fn gallery(name: &str, size: Size) -> Result<Self, String> {
        let index = GALLERY
            .iter()
            .position(|entry| entry.name == name)
            .ok_or_else(|| {
                let names: Vec<&str> = GALLERY.iter().map(|entry| entry.name).collect();
                format!(
                    "--scene: `{name}` is not a gallery scene ({})",
                    names.join(", ")
                )
            })?;
        let entry = gallery_entry(index, size);
        Ok(Self::new(
            Subject::Gallery { index, entry },
            EscapeState::default(),
            size,
        ))
    }

    fn new(subject: Subject, start: EscapeState, size: Size) -> Self {
        let mut explorer = Self {
            subject,
            start,
            size,
            render: None,
            values: vec![0; size.width as usize * size.height as usize],
            started: Instant::now(),
            elapsed: Duration::ZERO,
            saves: 0,
            save_pending: false,
            message: String::new(),
            detail: String::new(),
            autopilot: None,
            flights: 0,
        };
        explorer.restart();
        explorer
    }

    /// The picture's size (the window is `STATUS_HEIGHT` taller).
    pub fn picture_size(&self) -> Size {
        self.size
    }

    /// The complex point at pixel `p` of an escape-time view.
    fn point_at(state: &EscapeState, size: Size, p: Point) -> (f64, f64) {
        let spacing = state.width / f64::from(size.width);
        (
            state.centre.0 + (f64::from(p.x) + 0.5 - f64::from(size.width) / 2.0) * spacing,
            state.centre.1 - (f64::from(p.y) + 0.5 - f64::from(size.height) / 2.0) * spacing,
        )
    }

    /// Applies an input; a change of view cancels the render under way and starts anew.
    pub fn input(&mut self, input: Input) {
        let size = self.size;
        let mut redraw = true;
        match (&mut self.subject, input) {
            (_, Input::Save) => {
                // The finished picture is saved, not a preview of it.
                self.save_pending = true;
                redraw = false;
            }
            (Subject::Escape(state), input) => {
                let zoom_about = |state: &mut EscapeState, p: Point, factor: f64| {
                    let point = Self::point_at(state, size, p);
                    // The point under the mouse stays where it is.
                    state.centre = (
                        point.0 + (state.centre.0 - point.0) / factor,
                        point.1 + (state.centre.1 - point.1) / factor,
                    );
                    state.width /= factor;
                };
                match input {
                    Input::ZoomIn(p) => zoom_about(state, p, 2.0),
                    Input::ZoomOut(p) => zoom_about(state, p, 0.5),
                    Input::Wheel(p, notches) => zoom_about(state, p, 1.25f64.powi(notches)),
                    Input::Pan(dx, dy) => {
                        let spacing = state.width / f64::from(size.width);
                        state.centre.0 -= f64::from(dx) * spacing;
                        state.centre.1 += f64::from(dy) * spacing;
                    }
                    Input::More | Input::Fewer => {
                        state.max_iterations =
                            stepped_cap(state.max_iterations, input == Input::More);
                    }
                    Input::NextPalette => state.palette = (state.palette + 1) % PALETTES.len(),
                    Input::Histogram => state.palette = HISTOGRAM,
                    Input::ToggleCycling => {
                        state.cycling = !state.cycling;
                        redraw = false;
                    }
                    Input::Autopilot => {
                        self.autopilot = match self.autopilot {
                            Some(_) => None,
                            None => {
                                self.flights += 1;
                                Some(Autopilot::new(self.flights))
                            }
                        };
                        redraw = false;
                    }
                    Input::JuliaAt(p) => match state.julia {
                        Some(_) => {
                            state.julia = None;
                            (state.centre, state.width) = (self.start.centre, self.start.width);
                        }
                        None => {
                            let (re, im) = Self::point_at(state, size, p);
                            state.julia = Coord::from_f64(re).zip(Coord::from_f64(im));
                            (state.centre, state.width) = ((0.0, 0.0), 3.2);
                        }
                    },
                    Input::Reset => *state = self.start.clone(),
                    Input::NextSystem | Input::PreviousSystem | Input::Save => redraw = false,
                }
            }
            (
                Subject::LSystems {
                    names,
                    index,
                    order,
                    ..
                },
                input,
            ) => match input {
                Input::More | Input::Fewer => {
                    *order = stepped(*order, input == Input::More, 0, MAX_ORDER);
                }
                Input::NextSystem | Input::PreviousSystem => {
                    *index = paged(*index, names.len(), input == Input::NextSystem);
                }
                Input::Reset => *order = 3,
                _ => redraw = false,
            },
            (Subject::Gallery { index, entry }, input) => match input {
                Input::More => *entry = adjusted(*entry, true),
                Input::Fewer => *entry = adjusted(*entry, false),
                Input::NextSystem | Input::PreviousSystem | Input::Reset => {
                    if input != Input::Reset {
                        *index = paged(*index, GALLERY.len(), input == Input::NextSystem);
                    }
                    *entry = gallery_entry(*index, size);
                }
                _ => redraw = false,
            },
        }
        if redraw {
            self.restart();
        }
    }

    /// Starts the picture anew (a stale render is dropped).
    fn restart(&mut self) {
        self.render = None;
        self.started = Instant::now();
        self.elapsed = Duration::ZERO;
        self.message.clear();
        if let Subject::Escape(state) = &self.subject {
            match self.view(state) {
                Ok((view, palette)) => {
                    let render = Render::new(view, Algorithm::Fast).with_preview(8);
                    self.render = Some((render, view, palette));
                }
                Err(error) => self.message = error,
            }
        }
    }

    /// The view and palette of an escape-time state.
    fn view(&self, state: &EscapeState) -> Result<(View, HostPalette), String> {
        let text = |v: f64| format!("{v:e}");
        let julia = state.julia.map(|(re, im)| (re.to_string(), im.to_string()));
        let centre = (text(state.centre.0), text(state.centre.1));
        let width = text(state.width);
        let request = escape_scene::Request {
            julia: julia.as_ref().map(|(re, im)| (re.as_str(), im.as_str())),
            centre: (&centre.0, &centre.1),
            width: &width,
            size: self.size,
            max_iterations: state.max_iterations,
            algorithm: Algorithm::Fast,
            tier: None,
            palette: PALETTES[state.palette % PALETTES.len()],
            palette_file: None,
            modes: escape_scene::Modes::default(),
        };
        let (view, palette) = escape_scene::view_at(&request, &width)?;
        // Its centre is an f64: past Deep's spacing it has no more digits to zoom into.
        if view.tier() == tinyfractal::escape::Tier::Perturbation {
            return Err(format!(
                "the explorer zooms to a pixel spacing of 2^-54; for deeper views use \
                 `tinyfractal render mandelbrot --center RE,IM --width {width}` with all the \
                 centre's digits"
            ));
        }
        Ok((view, palette))
    }

    /// Whether the picture is complete.
    pub fn is_complete(&self) -> bool {
        match &self.render {
            Some((render, _, _)) => render.progress().is_complete(),
            None => true,
        }
    }

    /// Works on the picture for at most `budget` iterations (escape time; an L-system is
    /// drawn whole), and draws the status line.
    pub fn tick(&mut self, display: &mut SimulatorDisplay<Rgb888>, budget: u64) {
        let size = self.size;
        let mut picture = display.cropped(&Rectangle::new(Point::zero(), size));
        let mut drawn = None;
        let mut steer = false;
        match &mut self.subject {
            Subject::Escape(state) => {
                if let Some((render, view, palette)) = &mut self.render {
                    if state.cycling {
                        state.offset = state.offset.wrapping_add(4);
                    }
                    let turned = palette.turned(state.offset);
                    let palette = turned.as_ref().unwrap_or(palette);
                    if !render.progress().is_complete() {
                        let mut sink = Recording {
                            painter: Painter::new(&mut picture, palette, view),
                            values: DwellBuffer::new(&mut self.values, size.width),
                        };
                        let Ok(_) = render.step(&mut sink, budget);
                        self.elapsed = self.started.elapsed();
                    } else if let Some(pilot) = &mut self.autopilot {
                        // A finished picture: the next view the autopilot steers to.
                        match pilot.next(view, &self.values) {
                            Ok(next) => {
                                let spacing = next.spacing().to_f64();
                                state.centre = (next.centre().0.to_f64(), next.centre().1.to_f64());
                                state.width = spacing * f64::from(size.width);
                                steer = true;
                            }
                            Err(error) => self.message = error.to_string(),
                        }
                    } else if state.cycling {
                        // Cycling repaints the finished picture from its values.
                        escape_scene::paint_into(&mut picture, view, &self.values, palette);
                    }
                }
            }
            // An L-system or a gallery scene is drawn whole, once.
            Subject::LSystems {
                text,
                lsys,
                names,
                index,
                order,
            } if self.elapsed.is_zero() => {
                let name = names.get(*index).cloned().unwrap_or_default();
                let grammar = if *lsys {
                    tinyfractal::LsysFile::new(text).find(&name)
                } else {
                    tinyfractal::LFile::new(text).find(&name)
                };
                drawn = Some(
                    grammar
                        .map_err(|e| format!("{name}: {e}"))
                        .and_then(|grammar| {
                            crate::scene::render(&grammar, *order, size.width, size.height, None)
                                .map_err(|e| e.to_string())
                        })
                        .map(|rendered| (rendered.display, String::new())),
                );
            }
            Subject::Gallery { entry, .. } if self.elapsed.is_zero() => {
                drawn = Some(
                    crate::gallery::picture(entry).map(|(display, detail, _, _)| (display, detail)),
                );
            }
            Subject::LSystems { .. } | Subject::Gallery { .. } => {}
        }
        if let Some(drawn) = drawn {
            let Ok(()) = picture.clear(Rgb888::BLACK);
            match drawn {
                Ok((drawn, detail)) => {
                    copy(&drawn, drawn.bounding_box(), &mut picture);
                    self.detail = detail;
                }
                Err(error) => self.message = error,
            }
            self.elapsed = self.started.elapsed().max(Duration::from_nanos(1));
        }
        if steer {
            self.restart();
        }
        if self.save_pending && self.is_complete() {
            self.save_pending = false;
            self.save(display);
        }
        self.draw_status(display);
    }

    /// The status line: scene, view, tier, time (or the last message).
    pub fn status(&self) -> String {
        if !self.message.is_empty() {
            return self.message.clone();
        }
        let ms = self.elapsed.as_secs_f64() * 1e3;
        match &self.subject {
            Subject::Escape(state) => {
                let name = if state.julia.is_some() {
                    "julia"
                } else {
                    "mandelbrot"
                };
                let tier = self
                    .render
                    .as_ref()
                    .map_or("-", |(_, view, _)| view.tier().name());
                let done = if self.is_complete() { "" } else { " ..." };
                format!(
                    "{name} {:.6},{:.6} w={:.3e} it={} {tier} {}{done} {ms:.0}ms",
                    state.centre.0,
                    state.centre.1,
                    state.width,
                    state.max_iterations,
                    PALETTES[state.palette % PALETTES.len()]
                )
            }
            Subject::LSystems {
                names,
                index,
                order,
                ..
            } => {
                let name = names.get(*index).map_or("", String::as_str);
                format!(
                    "{name} order {order} ({}/{}) {ms:.0}ms",
                    index + 1,
                    names.len()
                )
            }
            Subject::Gallery { entry, .. } => format!("{} {} {ms:.0}ms", entry.name, self.detail),
        }
    }

    fn draw_status(&self, display: &mut SimulatorDisplay<Rgb888>) {
        let area = Rectangle::new(
            Point::new(0, self.size.height as i32),
            Size::new(self.size.width, STATUS_HEIGHT),
        );
        let Ok(()) = area
            .into_styled(PrimitiveStyle::with_fill(Rgb888::new(0x20, 0x20, 0x20)))
            .draw(display);
        let style = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
        let Ok(_) = Text::with_baseline(
            &self.status(),
            area.top_left + Point::new(2, 1),
            style,
            Baseline::Top,
        )
        .draw(display);
    }

    /// Saves the picture (without the status line) as `explore-NNN.png`.
    fn save(&mut self, display: &SimulatorDisplay<Rgb888>) {
        let mut picture = SimulatorDisplay::new(self.size);
        copy(display, picture.bounding_box(), &mut picture);
        let path = PathBuf::from(format!("explore-{:03}.png", self.saves));
        self.saves += 1;
        self.message = match crate::output::save_png(&picture, "explore", &path) {
            Ok(()) => format!("saved {}", path.display()),
            Err(error) => error,
        };
    }
}

/// Copies `area` of `from` into `to`.
fn copy<D>(from: &SimulatorDisplay<Rgb888>, area: Rectangle, to: &mut D)
where
    D: DrawTarget<Color = Rgb888, Error = core::convert::Infallible>,
{
    let Ok(()) = to.draw_iter(area.points().map(|p| Pixel(p, from.get_pixel(p))));
}

/// Paints values and keeps them: the sink of the explorer's renders.
struct Recording<'a, P> {
    painter: P,
    values: DwellBuffer<'a>,
}

impl<P: DwellSink<Error = core::convert::Infallible>> DwellSink for Recording<'_, P> {
    type Error = core::convert::Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Self::Error> {
        let values: Vec<u16> = dwells.collect();
        self.values.dwells(area, values.iter().copied())?;
        self.painter.dwells(area, values.into_iter())
    }

    fn uniform(&mut self, area: &Rectangle, dwell: u16) -> Result<(), Self::Error> {
        self.values.uniform(area, dwell)?;
        self.painter.uniform(area, dwell)
    }
}
