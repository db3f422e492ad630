//! `tinyfractal animate`: a picture that moves, as frames.
//!
//! A zoom that reuses its frames, colour cycling, an L-system growing by order, the walking
//! figure; written as numbered PNG frames, an animated GIF or an APNG, all or nothing, with a
//! progress bar on a terminal.

use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::time::Instant;

use crate::progress::ProgressBar;
use clap::{Args, Subcommand};
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame, RgbaImage};
use tinyfractal::{
    escape::{Algorithm, Tier, ZoomFrame, ZoomLine},
    lsystem::Wind,
    math::{DeepCoord, MAX_DECIMAL_PLACES},
    ParametricGrammar, Real, View,
};

use crate::attractor_scene::AttractorOptions;
use crate::console::Failure;
use crate::escape_scene::{self, Escape, Request};
use crate::noise_scene::TextureOptions;
use crate::palette::PaletteName;
use crate::particles_scene::ParticleOptions;
use crate::reaction_scene::ReactionOptions;
use crate::systems::{Purpose, Source};

/// `animate`'s options: what is animated, and its own options.
#[derive(Debug, Args)]
pub struct AnimateOptions {
    #[command(subcommand)]
    kind: Box<AnimationKind>,
}

impl AnimateOptions {
    /// `animate ...`: the frames are made on a thread of their own and written as they
    /// come (numbered PNGs, a GIF or an APNG), all or nothing.
    pub fn run(self) -> Result<(), Failure> {
        Ok(animate(&animation(*self.kind)?)?)
    }
}

#[derive(Debug, Args)]
struct FrameOptions {
    /// Frames to write [default: 100]
    #[arg(long, value_name = "N")]
    frames: Option<u32>,
    /// NAME.gif (animated GIF), NAME.png (APNG), or a folder for frame-0000.png, ...
    #[arg(long, value_name = "PATH", default_value = "animation.gif")]
    out: PathBuf,
    /// How long a frame shows in a GIF or APNG, in milliseconds
    #[arg(long = "delay", value_name = "MS", default_value_t = 40)]
    delay_ms: u32,
    /// Picture size in pixels, WxH
    #[arg(long = "size", value_name = "WxH", default_value = "320x240", value_parser = crate::common::parse_size)]
    size: (u32, u32),
    /// Print one line of statistics
    #[arg(long)]
    stats: bool,
}

#[derive(Debug, Subcommand)]
enum AnimationKind {
    /// A zoom into the Mandelbrot set (or a Julia set with --c), reusing each frame's
    /// columns and rows for the next
    Zoom(ZoomOptions),
    /// Colour cycling: one view, its gradient turned a step each frame
    Palette(PaletteOptions),
    /// XaoS's autopilot: from the whole set, zooming towards where the set meets the
    /// outside, backing out when stuck, reusing each frame's lines; seeded
    Autopilot(AutopilotOptions),
    /// An L-system growing: a plain one an order a frame; a parametric `.lsys` one
    /// continuously from order 0 (its new modules growing in between orders) over
    /// --frames [default: 8 an order, and one]
    Growth(GrowthOptions),
    /// A parametric `.lsys` plant swaying in a periodic wind (a tropism that changes with
    /// time), rooted where it stands: a loop of --frames [default: 24]
    Sway(SwayOptions),
    /// The lecture's figure walking (or waving), one cycle
    Figure(FigureAnimationOptions),
    /// Perlin noise moving: each frame a step deeper in its third dimension
    Noise(NoiseAnimationOptions),
    /// Reaction–diffusion unfolding: each frame --steps-per-frame steps later
    Reaction(ReactionAnimationOptions),
    /// A 3D attractor (lorenz, rossler, pickover) turning about its vertical axis, a full
    /// turn over the frames
    Attractor(AttractorAnimationOptions),
    /// A particle system from its start, a tick (1/30 s) a frame
    Particles(ParticleAnimationOptions),
}

#[derive(Debug, Args)]
struct ZoomOptions {
    /// The Julia parameter k, RE,IM (a Julia set instead of the Mandelbrot set)
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    c: Option<(String, String)>,
    /// The width of the last frame (default: --width shrunk by --factor a frame)
    #[arg(long = "end-width", value_name = "W", allow_hyphen_values = true)]
    end_width: Option<String>,
    /// How much each frame zooms in
    #[arg(long, value_name = "F", default_value_t = 1.05)]
    factor: f64,
    /// Reuse a line of the previous frame within this share of a pixel, in percent
    #[arg(long, value_name = "PERCENT", default_value_t = 100)]
    tolerance: u32,
    /// Compute every pixel of every frame
    #[arg(long)]
    exact: bool,
    #[command(flatten)]
    view: AnimatedView,
    #[command(flatten)]
    frames: FrameOptions,
}

/// The view options an animation shares with `render mandelbrot`.
#[derive(Debug, Args)]
struct AnimatedView {
    /// Centre of the view (the point zoomed into), RE,IM
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", default_value = "-0.743643887037151,0.131825904205330", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    centre: (String, String),
    /// Width along the real axis (of the first frame)
    #[arg(
        long,
        value_name = "W",
        default_value = "3",
        allow_hyphen_values = true
    )]
    width: String,
    /// Iteration cap, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    max_iterations: u32,
    /// The colours
    #[arg(long, value_enum, default_value = "classic")]
    palette: PaletteName,
}

#[derive(Debug, Args)]
struct PaletteOptions {
    /// The Julia parameter k, RE,IM (a Julia set instead of the Mandelbrot set)
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    c: Option<(String, String)>,
    /// Gradient entries the colours move a frame
    #[arg(long, value_name = "N", default_value_t = 4)]
    step: u16,
    #[command(flatten)]
    view: AnimatedView,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct AutopilotOptions {
    /// The seed of the autopilot's choices
    #[arg(long, value_name = "N", default_value_t = 1)]
    seed: u64,
    /// The Julia parameter k, RE,IM (a Julia set instead of the Mandelbrot set)
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    c: Option<(String, String)>,
    /// Reuse a line of the previous frame within this share of a pixel, in percent
    #[arg(long, value_name = "PERCENT", default_value_t = 100)]
    tolerance: u32,
    /// Iteration cap, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    max_iterations: u32,
    /// The colours
    #[arg(long, value_enum, default_value = "classic")]
    palette: PaletteName,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct GrowthOptions {
    #[command(flatten)]
    system: crate::systems::SystemOptions,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct SwayOptions {
    #[command(flatten)]
    system: crate::systems::SystemOptions,
    /// The wind's strength at the height of a gust: e·T of its push, T horizontal (+x)
    #[arg(long, value_name = "E", default_value = "0.05", value_parser = parse_wind, allow_hyphen_values = true)]
    wind: Real,
    /// Chooses the gusts' shape (the phase of their second harmonic)
    #[arg(long = "wind-seed", value_name = "N", default_value_t = 1)]
    wind_seed: u32,
    #[command(flatten)]
    frames: FrameOptions,
}

/// A wind strength: a decimal from −4 to 4.
fn parse_wind(text: &str) -> Result<Real, String> {
    Real::parse_signed(text)
        .filter(|e| e.abs() <= Real::from_int(4))
        .ok_or_else(|| {
            format!("{text:?} is not a wind strength: give a number from -4 to 4, e.g. 0.05")
        })
}

#[derive(Debug, Args)]
struct FigureAnimationOptions {
    /// The movement
    #[arg(long, value_enum, default_value = "walk")]
    pose: crate::figure_scene::PoseName,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct NoiseAnimationOptions {
    #[command(flatten)]
    texture: TextureOptions,
    /// The first frame's depth in 3D noise
    #[arg(long, value_name = "Z", default_value = "0", allow_hyphen_values = true,
          value_parser = crate::noise_scene::parse_real)]
    z: Real,
    /// How much deeper each frame is, in lattice cells
    #[arg(long = "z-step", value_name = "DZ", default_value = "0.05", allow_hyphen_values = true,
          value_parser = crate::noise_scene::parse_real)]
    z_step: Real,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct ReactionAnimationOptions {
    #[command(flatten)]
    reaction: ReactionOptions,
    /// Steps of the model between frames (the first frame is the start)
    #[arg(long = "steps-per-frame", value_name = "N", default_value_t = 50,
          value_parser = clap::value_parser!(u32).range(1..))]
    steps_per_frame: u32,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct AttractorAnimationOptions {
    #[command(flatten)]
    attractor: AttractorOptions,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct ParticleAnimationOptions {
    #[command(flatten)]
    particles: ParticleOptions,
    #[command(flatten)]
    frames: FrameOptions,
}

/// Frames an animation writes without `--frames`.
const DEFAULT_FRAMES: u32 = 100;

/// An animation as asked for: what moves, and its frames.
#[derive(Debug, Clone, PartialEq)]
struct AnimationPlan {
    /// What is animated.
    kind: Animation,
    /// Frames (for `growth`, orders 0 to `--order`, one frame each).
    frames: u32,
    /// `NAME.gif`, `NAME.png` (APNG), or a folder of numbered PNGs.
    out: PathBuf,
    /// Milliseconds a frame shows in a GIF or APNG.
    delay_ms: u32,
    /// Each frame's size (`--size`).
    size: (u32, u32),
    /// Whether to print a line of statistics (`--stats`).
    stats: bool,
}

/// What `animate` animates.
#[derive(Debug, Clone, PartialEq)]
enum Animation {
    /// A zoom from `view`'s width to `end_width` (or by `factor` a frame), reusing frames
    /// within `tolerance` % of a pixel unless `exact`.
    Zoom {
        /// The view zoomed into, and its first width.
        view: Escape,
        /// The last frame's width (`--end-width`), if given.
        end_width: Option<String>,
        /// How much each frame zooms in (`--factor`).
        factor: f64,
        /// How close a reused line must be, in percent of a pixel (`--tolerance`).
        tolerance: u32,
        /// Whether every pixel of every frame is computed (`--exact`).
        exact: bool,
    },
    /// XaoS's autopilot from `view` (the whole set), seeded.
    Autopilot {
        /// The first view.
        view: Escape,
        /// The seed (`--seed`).
        seed: u64,
        /// How close a reused line must be, in percent of a pixel (`--tolerance`).
        tolerance: u32,
    },
    /// One view, its gradient turned by `step` entries a frame.
    Palette {
        /// The view.
        view: Escape,
        /// Gradient entries the colours move a frame (`--step`).
        step: u16,
    },
    /// An L-system, one order a frame (plain), or growing continuously to `order`
    /// (parametric).
    Growth {
        /// The system.
        source: Source,
        /// The seed of stochastic productions (`--seed`), if given.
        seed: Option<u32>,
        /// The last order.
        order: u32,
    },
    /// A parametric plant at `order` swaying in `wind`.
    Sway {
        /// The system.
        source: Source,
        /// The seed of stochastic productions (`--seed`), if given.
        seed: Option<u32>,
        /// Its order.
        order: u32,
        /// The wind.
        wind: Wind,
    },
    /// The walking (or waving) figure.
    Figure {
        /// The movement (`--pose`).
        pose: crate::figure_scene::PoseName,
    },
    /// A texture at depths `z`, `z + step`, ... of 3D noise.
    Noise {
        /// What the texture is made of.
        texture: TextureOptions,
        /// The first frame's depth (`--z`).
        z: Real,
        /// Each frame's step deeper (`--z-step`).
        step: Real,
    },
    /// A reaction, `steps` steps a frame.
    Reaction {
        /// The model, grid and start.
        reaction: ReactionOptions,
        /// Steps between frames (`--steps-per-frame`).
        steps: u32,
    },
    /// A 3D attractor turning.
    Attractor {
        /// The attractor and how it is drawn.
        attractor: AttractorOptions,
    },
    /// A particle system, a tick a frame.
    Particles {
        /// The preset and seed.
        particles: ParticleOptions,
    },
}

/// The animation `kind` asks for; a usage error where its options do not fit together.
fn animation(kind: AnimationKind) -> Result<AnimationPlan, Failure> {
    let animated = |julia: Option<(String, String)>, view: AnimatedView| Escape {
        julia,
        centre: view.centre,
        width: view.width,
        max_iterations: view.max_iterations,
        algorithm: Algorithm::Exact,
        tier: None,
        palette: view.palette,
        palette_file: None,
        common: crate::common::Common {
            size: (0, 0),
            out: None,
            stats: false,
            window: false,
            dimension: false,
            colors: crate::common::Panel::Rgb888,
            dither: crate::common::DitherName::None,
        },
        dwell: None,
        modes: escape_scene::Modes::default(),
    };
    let (kind, frames) = match kind {
        AnimationKind::Zoom(options) => (
            Animation::Zoom {
                view: animated(options.c, options.view),
                end_width: options.end_width,
                factor: options.factor,
                tolerance: options.tolerance,
                exact: options.exact,
            },
            options.frames,
        ),
        AnimationKind::Autopilot(options) => {
            let (centre, width) = match options.c {
                None => (("-0.75", "0"), "3.5"),
                Some(_) => (("0", "0"), "3.2"),
            };
            let view = AnimatedView {
                centre: (centre.0.to_string(), centre.1.to_string()),
                width: width.to_string(),
                max_iterations: options.max_iterations,
                palette: options.palette,
            };
            (
                Animation::Autopilot {
                    view: animated(options.c, view),
                    seed: options.seed,
                    tolerance: options.tolerance,
                },
                options.frames,
            )
        }
        AnimationKind::Palette(options) => (
            Animation::Palette {
                view: animated(options.c, options.view),
                step: options.step,
            },
            options.frames,
        ),
        AnimationKind::Growth(options) => {
            let source = options.system.source(Purpose::Draw)?;
            let order = options.system.order;
            let mut text = String::new();
            let (loaded, _, _) = crate::systems::load(&source, &mut text)?;
            let parametric = matches!(loaded, crate::systems::Loaded::Parametric(..));
            let mut frames = options.frames;
            if !parametric && frames.frames.is_some() {
                return Err(Failure::Usage(
                    "--frames does not apply to the growth of a plain system: it writes one \
                     frame an order, 0 to --order (leave out --frames; a parametric .lsys \
                     system grows continuously over --frames)"
                        .to_string(),
                ));
            }
            // Plain: orders 0 to N, N + 1 frames; parametric: 8 an order, and the last.
            let per_order = if parametric { 8 } else { 1 };
            frames.frames = Some(
                frames
                    .frames
                    .unwrap_or(order.saturating_mul(per_order).saturating_add(1)),
            );
            let seed = options.system.seed;
            (
                Animation::Growth {
                    source,
                    seed,
                    order,
                },
                frames,
            )
        }
        AnimationKind::Sway(options) => {
            let mut frames = options.frames;
            frames.frames = Some(frames.frames.unwrap_or(24));
            (
                Animation::Sway {
                    source: options.system.source(Purpose::Draw)?,
                    seed: options.system.seed,
                    order: options.system.order,
                    wind: Wind {
                        push: [options.wind, Real::ZERO, Real::ZERO],
                        seed: options.wind_seed,
                    },
                },
                frames,
            )
        }
        AnimationKind::Figure(options) => {
            (Animation::Figure { pose: options.pose }, options.frames)
        }
        AnimationKind::Noise(options) => (
            Animation::Noise {
                texture: options.texture,
                z: options.z,
                step: options.z_step,
            },
            options.frames,
        ),
        AnimationKind::Reaction(options) => (
            Animation::Reaction {
                reaction: options.reaction,
                steps: options.steps_per_frame,
            },
            options.frames,
        ),
        AnimationKind::Attractor(options) => {
            if !options.attractor.is_3d() {
                return Err(Failure::Usage(format!(
                    "animate attractor turns a 3D attractor (lorenz, rossler, pickover): {} \
                     is drawn in its plane",
                    options.attractor.name()
                )));
            }
            options.attractor.attractor()?;
            if let Some(still) = options.attractor.standing_still()? {
                crate::console::warn(&still);
            }
            (
                Animation::Attractor {
                    attractor: options.attractor,
                },
                options.frames,
            )
        }
        AnimationKind::Particles(options) => (
            Animation::Particles {
                particles: options.particles,
            },
            options.frames,
        ),
    };
    let count = frames.frames.unwrap_or(DEFAULT_FRAMES);
    if count == 0 {
        return Err(Failure::Usage(
            "--frames 0: give at least one frame".to_string(),
        ));
    }
    Ok(AnimationPlan {
        kind,
        frames: count,
        out: frames.out,
        delay_ms: frames.delay_ms,
        size: frames.size,
        stats: frames.stats,
    })
}

/// A finished frame, handed from the animation to the encoder as it is made.
type Picture = SimulatorDisplay<Rgb888>;

/// What the animation sends the writer: each frame as it is made, then the `--stats`
/// detail.
enum Message {
    Frame(Picture),
    Done(String),
}

/// Where an animation sends its frames: on to the writer, at most one frame ahead of it,
/// so an animation's memory does not grow with its frames.
struct Emit<'s> {
    sender: SyncSender<Message>,
    bar: &'s ProgressBar,
}

impl Emit<'_> {
    /// Sends `picture` on; an error once the writer has stopped (it says why).
    fn frame(&self, picture: Picture) -> Result<(), String> {
        self.bar.inc(1);
        self.sender
            .send(Message::Frame(picture))
            .map_err(|_| WRITER_STOPPED.to_string())
    }
}

/// The animation's error when the writer stopped first (the writer's own error is the one
/// reported).
const WRITER_STOPPED: &str = "the writer stopped";

/// Makes and writes `arguments`' frames (see [`AnimateOptions::run`]).
fn animate(arguments: &AnimationPlan) -> Result<(), String> {
    let started = Instant::now();
    let size = Size::new(arguments.size.0, arguments.size.1);
    let bar = crate::progress::bar(u64::from(arguments.frames), "frames");
    let (sender, receiver) = sync_channel(1);
    let result = std::thread::scope(|scope| {
        let stats = |detail: String| {
            let (frames, elapsed) = (arguments.frames, started.elapsed().as_secs_f64() * 1e3);
            match (arguments.stats, &arguments.kind) {
                (false, _) => String::new(),
                // Its line ends with `last_width=`, as its issue names it.
                (true, Animation::Autopilot { .. }) => {
                    format!("frames={frames} elapsed_ms={elapsed:.3}{detail}\n")
                }
                (true, _) => format!("frames={frames}{detail} elapsed_ms={elapsed:.3}\n"),
            }
        };
        // The writer on a thread of its own, the frames made on this one: in the pool that
        // `--threads` installed, so frames that can be made in parallel use its threads.
        let writer = scope.spawn(move || {
            let written = write(&receiver, arguments, stats);
            // The writer is done: a maker still sending stops at its next frame.
            drop(receiver);
            written
        });
        let emit = Emit { sender, bar: &bar };
        let made = make(arguments, size, &emit).and_then(|detail| {
            emit.sender
                .send(Message::Done(detail))
                .map_err(|_| WRITER_STOPPED.to_string())
        });
        // The maker is done: a writer still waiting sees the channel close.
        drop(emit);
        let written = writer
            .join()
            .unwrap_or_else(|_| Err("the animation's writer stopped unexpectedly".to_string()));
        match (made, written) {
            (Err(error), _) if error != WRITER_STOPPED => Err(error),
            (_, written) => written,
        }
    });
    bar.finish_and_clear();
    result
}

/// Makes the animation's frames into `emit`; the `--stats` detail.
fn make(arguments: &AnimationPlan, size: Size, emit: &Emit<'_>) -> Result<String, String> {
    match &arguments.kind {
        Animation::Zoom {
            view,
            end_width,
            factor,
            tolerance,
            exact,
        } => {
            let request = escape_scene::request(view, size);
            let tolerance = if *exact { None } else { Some(*tolerance) };
            zoom(
                &request,
                end_width.as_deref(),
                *factor,
                tolerance,
                arguments.frames,
                emit,
            )
        }
        Animation::Autopilot {
            view,
            seed,
            tolerance,
        } => autopilot(
            &escape_scene::request(view, size),
            *seed,
            *tolerance,
            arguments.frames,
            emit,
        ),
        Animation::Palette { view, step } => palette_cycle(
            &escape_scene::request(view, size),
            *step,
            arguments.frames,
            emit,
        ),
        Animation::Growth {
            source,
            seed,
            order,
        } => growth(source, *seed, (*order, arguments.frames), size, emit),
        Animation::Sway {
            source,
            seed,
            order,
            wind,
        } => {
            let mut text = String::new();
            let (grammar, colors, name) = parametric(source, *seed, &mut text, "sway")?;
            crate::plant_animation::sway(
                (&grammar, &colors),
                *order,
                wind,
                arguments.frames,
                size,
                |picture| emit.frame(picture),
            )
            .map_err(|e| format!("{name} {e}"))?;
            Ok(String::new())
        }
        Animation::Figure { pose } => {
            crate::figure_scene::cycle(*pose, arguments.frames, size, |frame| emit.frame(frame))?;
            Ok(String::new())
        }
        Animation::Noise { texture, z, step } => {
            noise_frames(texture, (*z, *step), arguments.frames, size, emit)
        }
        Animation::Reaction { reaction, steps } => {
            reaction_frames(reaction, *steps, arguments.frames, size, emit)
        }
        Animation::Attractor { attractor } => {
            crate::attractor_scene::frames(attractor, arguments.frames, size, |frame| {
                emit.frame(frame)
            })
        }
        Animation::Particles { particles } => {
            crate::particles_scene::frames(particles, arguments.frames, size, |frame| {
                emit.frame(frame)
            })
        }
    }
}

/// A reaction's `frames` frames: the start, then `steps` steps later each frame.
fn reaction_frames(
    options: &ReactionOptions,
    steps: u32,
    frames: u32,
    size: Size,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let mut grid = options.grid();
    let mut reaction = grid.reaction(options)?;
    let area = embedded_graphics::primitives::Rectangle::new(Point::zero(), size);
    for frame in 0..frames {
        if frame > 0 {
            reaction.step(steps);
        }
        let mut picture = Picture::new(size);
        let Ok(()) = crate::reaction_scene::drawing(&reaction, area)?.draw(&mut picture);
        emit.frame(picture)?;
    }
    let (w, h) = reaction.size();
    Ok(format!(
        " steps={} cell_steps={}",
        reaction.steps(),
        reaction.steps() * u64::from(w) * u64::from(h)
    ))
}

/// A texture at `frames` depths of 3D noise, `z` then a `step` deeper each frame.
fn noise_frames(
    texture: &TextureOptions,
    (z, step): (Real, Real),
    frames: u32,
    size: Size,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let noise = texture.noise();
    let area = embedded_graphics::primitives::Rectangle::new(Point::zero(), size);
    // Each frame its own depth: frames on every thread, in order.
    let make = |frame: u32| {
        let depth = step
            .checked_mul(Real::from_int(i32::try_from(frame).unwrap_or(i32::MAX)))
            .and_then(|offset| z.checked_add(offset))
            .ok_or_else(|| format!("noise: frame {frame}'s depth is past the noise's range"))?;
        let drawing = texture.drawing(&noise, Some(depth), area)?;
        let mut picture = Picture::new(size);
        let Ok(()) = drawing.draw(&mut picture);
        Ok(picture)
    };
    crate::parallel::frames_in_order(frames, make, |picture| emit.frame(picture))?;
    Ok(String::new())
}

/// The widths of a zoom's frames, as text: the first is `--width`, the last `end_width`
/// when given (both exactly as written), the rest shrink by one factor a frame.
fn widths(start: &str, end: Option<&str>, factor: f64, frames: u32) -> Result<Vec<String>, String> {
    let number = |option: &str, text: &str| {
        DeepCoord::parse(text)
            .map(DeepCoord::to_f64)
            .ok()
            .filter(|&w| w > 0.0)
            .ok_or_else(|| {
                format!("{option}: `{text}` is not a width between 0 and 8 (e.g. 3 or 1e-5)")
            })
    };
    let first = number("--width", start)?;
    let factor = match end {
        Some(end) if frames > 1 => {
            (first / number("--end-width", end)?).powf(1.0 / f64::from(frames - 1))
        }
        _ => factor,
    };
    if !(factor.is_finite() && factor > 0.0) {
        return Err(format!(
            "--factor {factor}: give a factor above 0 (e.g. 1.05)"
        ));
    }
    (0..frames)
        .map(|k| match (k, end) {
            (0, _) => Ok(start.to_string()),
            (k, Some(end)) if k + 1 == frames => Ok(end.to_string()),
            (k, _) => frame_width(first / factor.powi(k as i32)).ok_or_else(|| {
                format!(
                    "--factor {factor} over {frames} frames: frame {k} would be {:e} wide, past \
                     the deepest zoom (about 10^-42 across 320 pixels) and the widest view; \
                     use fewer --frames or a factor nearer 1",
                    first / factor.powi(k as i32)
                )
            }),
        })
        .collect()
}

/// A frame's width as decimal text a view reads: 15 significant digits, fewer where that
/// would pass the 56 decimal places a coordinate holds; `None` past that or past 8.
fn frame_width(width: f64) -> Option<String> {
    if !(width.is_normal() && width < 8.0) {
        return None;
    }
    let exponent = width.log10().floor() as i32;
    let digits = 14.min(MAX_DECIMAL_PLACES as i32 + exponent);
    (digits >= 0).then(|| format!("{width:.*e}", digits as usize))
}

/// A zoom: each frame reuses the last within `tolerance` % of a pixel (`None`: every
/// frame computed in full); the first and last frames are exact.
fn zoom(
    request: &Request<'_>,
    end_width: Option<&str>,
    factor: f64,
    tolerance: Option<u32>,
    frames: u32,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let widths = widths(request.width, end_width, factor, frames)?;
    // Every frame has the same palette: one is kept.
    let mut palette = None;
    let views = widths
        .iter()
        .enumerate()
        .map(|(index, width)| {
            escape_scene::view_at(request, width)
                .map(|(view, frame_palette)| {
                    palette.get_or_insert(frame_palette);
                    view
                })
                .map_err(|e| match index {
                    0 => e,
                    _ => format!("frame {index} of the zoom, {width} wide: {e}"),
                })
        })
        .collect::<Result<Vec<View>, String>>()?;
    let Some(palette) = palette else {
        return Ok(String::new());
    };
    // A frame that is not exact by the tier rule says so, once, before any is computed.
    if let Some((index, warning)) = views
        .iter()
        .enumerate()
        .find_map(|(index, view)| escape_scene::TierWarning::of(view).map(|w| (index, w)))
    {
        crate::console::warn(&format!(
            "the frame at width {} and those like it: {}",
            widths[index],
            warning.message(&views[index])
        ));
    }
    let pixels = (request.size.width * request.size.height) as usize;
    let mut values = vec![0u16; pixels];
    let mut columns = vec![ZoomLine::default(); request.size.width as usize];
    let mut rows = vec![ZoomLine::default(); request.size.height as usize];
    let (mut computed, mut total) = (0u64, 0u64);
    // One frame, moved in place from view to view. A frame computes in a fixed tier, so a
    // view whose tier is perturbation (past `Deep`'s spacing, or deep with a long orbit)
    // is rendered whole by perturbation, as `render` renders it; the frame's storage is
    // checked against a fixed tier's view of the same size.
    let fixed = |view: &View| match view.tier() {
        Tier::Perturbation => view.with_tier(Tier::Deep),
        _ => *view,
    };
    let mut frame = ZoomFrame::new(fixed(&views[0]), &mut values, &mut columns, &mut rows)
        .map_err(|e| e.to_string())?;
    for (index, view) in views.iter().enumerate() {
        let last = index + 1 == views.len();
        if view.tier() == Tier::Perturbation {
            let (perturbed, _) = escape_scene::compute(*view, Algorithm::Exact)?;
            computed += pixels as u64;
            total += pixels as u64;
            emit.frame(escape_scene::paint(view, &perturbed, &palette))?;
            continue;
        }
        // The last frame takes only lines at exactly its own points: it is exact.
        let tolerance = tolerance.map(|percent| if last { 0 } else { percent });
        let stats = frame.advance(*view, tolerance).map_err(|e| e.to_string())?;
        computed += u64::from(stats.computed);
        total += u64::from(stats.computed + stats.reused);
        emit.frame(escape_scene::paint(view, frame.values(), &palette))?;
    }
    let share = computed as f64 / total.max(1) as f64;
    Ok(format!(
        " computed_share={share:.4} last_width={}",
        widths.last().map_or("", String::as_str)
    ))
}

/// XaoS's autopilot (`escape::Autopilot`) from the request's view: each frame the next
/// view from the last picture, the frame moved in place and its lines reused within
/// `tolerance` % of a pixel.
fn autopilot(
    request: &Request<'_>,
    seed: u64,
    tolerance: u32,
    frames: u32,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let (mut view, palette) = escape_scene::view_at(request, request.width)?;
    let pixels = (request.size.width * request.size.height) as usize;
    let mut values = vec![0u16; pixels];
    let mut columns = vec![ZoomLine::default(); request.size.width as usize];
    let mut rows = vec![ZoomLine::default(); request.size.height as usize];
    let mut frame =
        ZoomFrame::new(view, &mut values, &mut columns, &mut rows).map_err(|e| e.to_string())?;
    let mut pilot = tinyfractal::escape::Autopilot::new(seed);
    let (mut computed, mut total) = (0u64, 0u64);
    for index in 0..frames {
        if index > 0 {
            view = pilot
                .next(&view, frame.values())
                .map_err(|e| e.to_string())?;
        }
        let stats = frame
            .advance(view, Some(tolerance))
            .map_err(|e| e.to_string())?;
        computed += u64::from(stats.computed);
        total += u64::from(stats.computed + stats.reused);
        emit.frame(escape_scene::paint(&view, frame.values(), &palette))?;
    }
    let share = computed as f64 / total.max(1) as f64;
    let width = view.spacing().to_f64() * f64::from(request.size.width);
    Ok(format!(
        " computed_share={share:.4} backed_out={} last_width={width:e}",
        pilot.backed_out()
    ))
}

/// One view, its gradient turned `step` entries a frame.
fn palette_cycle(
    request: &Request<'_>,
    step: u16,
    frames: u32,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let (view, palette) = escape_scene::view_at(request, request.width)?;
    let (values, _) = escape_scene::compute(view, Algorithm::Exact)?;
    for k in 0..frames {
        let offset = (u64::from(k) * u64::from(step) % 65_536) as u16;
        let turned = palette.turned(offset).ok_or_else(|| {
            format!(
                "--palette {}: colour cycling needs a gradient (classic, fire, gray or smooth-*)",
                request.palette
            )
        })?;
        emit.frame(escape_scene::paint(&view, &values, &turned))?;
    }
    Ok(String::new())
}

/// The parametric system `source` names, its entry's colours and its name; an error
/// naming `animation` for a plain one.
fn parametric(
    source: &Source,
    seed: Option<u32>,
    text: &mut String,
    animation: &str,
) -> Result<(ParametricGrammar, Vec<Rgb888>, String), String> {
    let (loaded, name, _) = crate::systems::load(source, text)?;
    let crate::systems::Loaded::Parametric(mut grammar, colors) = loaded else {
        return Err(format!(
            "{name}: {animation} animates the general engine's systems (parametric .lsys \
             ones: F(l), 3D turns, polygons, widths, tropism); this one is plain"
        ));
    };
    if let Some(seed) = seed {
        grammar.set_seed(seed);
    }
    Ok((*grammar, colors, name))
}

/// A plain L-system at orders 0 to `frames` − 1, each fitted to the picture; a parametric
/// one growing continuously to `order` over `frames`.
fn growth(
    source: &Source,
    seed: Option<u32>,
    (order, frames): (u32, u32),
    size: Size,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let mut text = String::new();
    let (loaded, name, _) = crate::systems::load(source, &mut text)?;
    let grammar = match loaded {
        crate::systems::Loaded::Plain(grammar) => grammar,
        crate::systems::Loaded::Parametric(mut grammar, colors) => {
            if let Some(seed) = seed {
                grammar.set_seed(seed);
            }
            crate::plant_animation::grow((&grammar, &colors), order, frames, size, |picture| {
                emit.frame(picture)
            })
            .map_err(|e| format!("{name} {e}"))?;
            return Ok(String::new());
        }
    };
    let mut grammar = *grammar;
    if let Some(seed) = seed {
        grammar.set_seed(seed);
    }
    for order in 0..frames {
        let rendered = crate::scene::render(&grammar, order, size.width, size.height, None)
            .map_err(|e| format!("{name} at order {order}: {e}"))?;
        emit.frame(rendered.display)?;
    }
    Ok(String::new())
}

/// Writes the frames `receiver` brings to `--out` (a GIF, an APNG or a folder of numbered
/// PNGs, made if missing) as they come, and the `--stats` line once the last is in,
/// all or nothing; in a folder, numbered frames past these (an earlier, longer run's)
/// are removed once these are in place.
fn write(
    receiver: &Receiver<Message>,
    arguments: &AnimationPlan,
    stats: impl FnOnce(String) -> String,
) -> Result<(), String> {
    let (out, delay_ms, count) = (&arguments.out, arguments.delay_ms, arguments.frames);
    // The next frame, or why there is none (the maker's error is reported instead).
    let next = || match receiver.recv() {
        Ok(Message::Frame(picture)) => Ok(picture),
        _ => Err(io::Error::other("the animation stopped")),
    };
    let mut plan = crate::output::Plan::new();
    let extension = out
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let paths: Vec<_>;
    let folder = !matches!(extension.as_deref(), Some("gif" | "png"));
    let made_folder = folder && !out.exists();
    match extension.as_deref() {
        Some("gif") => plan.add("--out", out, move |w| gif(count, next, delay_ms, w)),
        Some("png") => plan.add("--out", out, move |w| apng(count, next, delay_ms, w)),
        _ => {
            std::fs::create_dir_all(out).map_err(|e| format!("--out {}: {e}", out.display()))?;
            paths = (0..count)
                .map(|k| out.join(format!("frame-{k:04}.png")))
                .collect();
            for path in &paths {
                plan.add("--out", path, move |w| crate::output::png(&next()?, w));
            }
        }
    }
    plan.print_after(move || match receiver.recv() {
        Ok(Message::Done(detail)) => Ok(stats(detail)),
        _ => Err("the animation stopped".to_string()),
    });
    let written = plan.write();
    if written.is_err() && made_folder {
        // Only if empty: nothing of anyone else's is removed.
        let _ = std::fs::remove_dir(out);
    }
    written?;
    if folder {
        remove_stale_frames(out, count as usize)?;
    }
    Ok(())
}

/// Removes `frame-NNNN.png` files numbered `count` and on from `folder`: what an earlier
/// run with more frames left there.
fn remove_stale_frames(folder: &Path, count: usize) -> Result<(), String> {
    let entries =
        std::fs::read_dir(folder).map_err(|e| format!("--out {}: {e}", folder.display()))?;
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(number) = name
            .to_str()
            .and_then(|name| name.strip_prefix("frame-"))
            .and_then(|rest| rest.strip_suffix(".png"))
            .filter(|digits| digits.len() >= 4 && digits.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|digits| digits.parse::<usize>().ok())
        else {
            continue;
        };
        if number >= count && entry.file_type().is_ok_and(|kind| kind.is_file()) {
            std::fs::remove_file(entry.path())
                .map_err(|e| format!("--out {}: {e}", entry.path().display()))?;
        }
    }
    Ok(())
}

/// RGB bytes of a frame, row by row.
fn rgb(frame: &SimulatorDisplay<Rgb888>) -> Vec<u8> {
    frame
        .to_rgb_output_image(&OutputSettingsBuilder::new().build())
        .as_image_buffer()
        .as_raw()
        .to_vec()
}

fn gif(
    count: u32,
    next: impl Fn() -> io::Result<Picture>,
    delay_ms: u32,
    out: &mut dyn Write,
) -> io::Result<()> {
    let mut encoder = GifEncoder::new_with_speed(out, 10);
    encoder
        .set_repeat(Repeat::Infinite)
        .map_err(io::Error::other)?;
    let delay = Delay::from_numer_denom_ms(delay_ms, 1);
    for _ in 0..count {
        let frame = next()?;
        let size = frame.size();
        let rgba = rgb(&frame)
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let image = RgbaImage::from_raw(size.width, size.height, rgba)
            .ok_or_else(|| io::Error::other("a frame of the wrong size"))?;
        encoder
            .encode_frame(Frame::from_parts(image, 0, 0, delay))
            .map_err(io::Error::other)?;
    }
    Ok(())
}

fn apng(
    count: u32,
    next: impl Fn() -> io::Result<Picture>,
    delay_ms: u32,
    out: &mut dyn Write,
) -> io::Result<()> {
    if count == 0 {
        return Ok(());
    }
    let first = next()?;
    let size = first.size();
    let mut encoder = png::Encoder::new(out, size.width, size.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_animated(count, 0).map_err(io::Error::other)?;
    let delay = u16::try_from(delay_ms).unwrap_or(u16::MAX);
    encoder
        .set_frame_delay(delay, 1000)
        .map_err(io::Error::other)?;
    let mut writer = encoder.write_header().map_err(io::Error::other)?;
    writer
        .write_image_data(&rgb(&first))
        .map_err(io::Error::other)?;
    for _ in 1..count {
        writer
            .write_image_data(&rgb(&next()?))
            .map_err(io::Error::other)?;
    }
    writer.finish().map_err(io::Error::other)
}
