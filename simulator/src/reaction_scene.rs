//! `tinyfractal render reaction` and `animate reaction`: the Gray–Scott model on a grid,
//! stretched to the picture.

use std::path::PathBuf;
use std::time::Duration;

use crate::clock::Instant;

use clap::{Args, ValueEnum};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::reaction::{Cell, GrayScott, Preset, Reaction, ReactionDrawing, Start, ONE};
use tinyfractal::render::Gradient;
use tinyfractal::Real;
use tinyfractal_scenes::{Look, Scene};

use crate::common::Common;
use crate::console::Failure;
use crate::noise_scene::parse_real;

/// The grid's largest side on the host: a 4096×4096 grid is 64 MiB of cells.
const MAX_GRID_SIDE: u32 = Reaction::MAX_SIDE;

/// `--init`: where B starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum InitName {
    /// B = 1 in a centred square of side min(W, H)/8 (Sims's start)
    Square,
    /// B = 1 in seeded squares, one per 2048 cells (--seed)
    Spots,
}

/// What a reaction is: the model, the grid and the start. `render reaction` and `animate
/// reaction` share it.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct ReactionOptions {
    /// A named (f, k): coral (the default), mitosis (spots), worms, maze, holes, waves,
    /// solitons, u-skate, and Pearson's gamma, theta, mu
    #[arg(long, value_name = "NAME", value_parser = parse_preset,
          conflicts_with_all = ["feed", "kill"])]
    preset: Option<Preset>,
    /// The feed rate f (with --kill), 0 to 1
    #[arg(long, value_name = "F", requires = "kill", value_parser = parse_real)]
    feed: Option<Real>,
    /// The kill rate k (with --feed), 0 to 1
    #[arg(long, value_name = "K", requires = "feed", value_parser = parse_real)]
    kill: Option<Real>,
    /// A's diffusion rate D_A; D_A·Δt at most 1
    #[arg(long = "diffusion-a", value_name = "D", default_value = "1", value_parser = parse_real)]
    diffusion_a: Real,
    /// B's diffusion rate D_B; D_B·Δt at most 1
    #[arg(long = "diffusion-b", value_name = "D", default_value = "0.5", value_parser = parse_real)]
    diffusion_b: Real,
    /// The time step Δt, above 0 and at most 1
    #[arg(long, value_name = "DT", default_value = "1", value_parser = parse_real)]
    dt: Real,
    /// The grid in cells, WxH (3 to 4096 a side), stretched to --size
    #[arg(long, value_name = "WxH", default_value = "128x128", value_parser = parse_grid)]
    grid: (u32, u32),
    /// Where B starts
    #[arg(long, value_enum, default_value = "square")]
    init: InitName,
    /// The spots' seed (--init spots)
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u64,
}

/// A grid's cells and ring, owned for a run on the host.
#[derive(Debug)]
pub struct Grid {
    size: (u32, u32),
    cells: Vec<Cell>,
    ring: Vec<Cell>,
}

impl ReactionOptions {
    /// The model the options name.
    pub fn model(&self) -> GrayScott {
        let base = match (self.feed, self.kill) {
            (Some(feed), Some(kill)) => GrayScott::new(feed, kill),
            _ => self.preset.unwrap_or(Preset::Coral).model(),
        };
        GrayScott {
            diffusion_a: self.diffusion_a,
            diffusion_b: self.diffusion_b,
            dt: self.dt,
            ..base
        }
    }

    /// The start the options name.
    pub fn start(&self) -> Start {
        match self.init {
            InitName::Square => Start::Square,
            InitName::Spots => Start::Spots { seed: self.seed },
        }
    }

    /// Cells for the grid.
    pub fn grid(&self) -> Grid {
        let (w, h) = self.grid;
        Grid {
            size: self.grid,
            cells: vec![Cell::REST; w as usize * h as usize],
            ring: vec![Cell::REST; Reaction::ring_len(w)],
        }
    }
}

impl Grid {
    /// The reaction `options` ask for on this grid, started; the core's message otherwise.
    pub fn reaction(&mut self, options: &ReactionOptions) -> Result<Reaction<'_>, String> {
        let mut reaction =
            Reaction::new(&options.model(), self.size, &mut self.cells, &mut self.ring)
                .map_err(|e| format!("reaction: {e}"))?;
        reaction.start(options.start());
        Ok(reaction)
    }
}

/// The host's colours for B, 0 to 1: deep blue through teal to near white.
const KEYS: [Rgb888; 3] = [
    Rgb888::new(0x0C, 0x10, 0x30),
    Rgb888::new(0x20, 0x90, 0xA0),
    Rgb888::new(0xF4, 0xF0, 0xD8),
];

/// The reaction's B over `area`, in the host's colours.
pub fn drawing<'r>(
    reaction: &'r Reaction<'_>,
    area: Rectangle,
) -> Result<ReactionDrawing<'r, Gradient<Rgb888, 256>>, String> {
    let palette = Gradient::<Rgb888, 256>::new(&KEYS, Rgb888::BLACK)
        .ok_or_else(|| "reaction: no colours".to_string())?;
    reaction
        .fit(area, palette)
        .map_err(|e| format!("reaction: {e}"))
}

/// `render reaction`'s options.
#[derive(Debug, Args)]
pub struct RenderReactionOptions {
    #[command(flatten)]
    reaction: ReactionOptions,
    /// Steps of the model before the picture
    #[arg(long, value_name = "N", default_value_t = 5000)]
    steps: u32,
    /// Write `W H` (the grid), then the B field's H rows of W values in [0, 1]
    #[arg(long, value_name = "TXT")]
    values: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

impl RenderReactionOptions {
    /// `render reaction`: the grid after `--steps` steps, with `--values`.
    pub fn run(&self) -> Result<(), Failure> {
        let common = &self.common;
        crate::delivery::window_available(common.window)?;
        let mut grid = self.reaction.grid();
        let mut reaction = grid.reaction(&self.reaction)?;
        let started = Instant::now();
        let bar = crate::progress::bar(u64::from(self.steps), "steps");
        let mut done = 0;
        while done < self.steps {
            let chunk = (self.steps - done).min(100);
            reaction.step(chunk);
            done += chunk;
            bar.inc(u64::from(chunk));
        }
        bar.finish_and_clear();
        let elapsed = started.elapsed();
        let drawing = drawing(&reaction, common.area())?;
        let mut display = common.display();
        let Ok(()) = drawing.draw(&mut display);
        let (w, h) = reaction.size();
        let cells = u64::from(w) * u64::from(h);
        let line = format!(
            "cells={cells} steps={} cell_steps={} elapsed_ms={:.3}",
            self.steps,
            cells * u64::from(self.steps),
            elapsed.as_secs_f64() * 1e3
        );
        let reaction = &reaction;
        Ok(crate::delivery::deliver(
            common,
            "reaction",
            &display,
            |plan| {
                if let Some(path) = &self.values {
                    plan.add("--values", path, move |out| {
                        writeln!(out, "{w} {h}")?;
                        for row in reaction.cells().chunks(w as usize) {
                            let values: Vec<String> =
                                row.iter().map(|cell| concentration(cell.b)).collect();
                            writeln!(out, "{}", values.join(" "))?;
                        }
                        Ok(())
                    });
                }
            },
            &line,
        )?)
    }
}

/// A cell's concentration as a decimal: exactly its value, a multiple of 2⁻¹⁵.
fn concentration(value: u16) -> String {
    (f64::from(value) / f64::from(ONE)).to_string()
}

/// `--preset`'s value: a preset's name.
fn parse_preset(text: &str) -> Result<Preset, String> {
    Preset::ALL
        .into_iter()
        .find(|preset| preset.name() == text)
        .ok_or_else(|| {
            let names: Vec<&str> = Preset::ALL.iter().map(|p| p.name()).collect();
            format!("unknown preset `{text}`: give one of {}", names.join(", "))
        })
}

/// `--grid`'s value: WxH, each side 3 to 4096.
fn parse_grid(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = crate::common::parse_size(text)?;
    let side = Reaction::MIN_SIDE..=MAX_GRID_SIDE;
    if !side.contains(&w) || !side.contains(&h) {
        return Err(format!(
            "the grid {w}x{h} is out of range: each side must be {} to {MAX_GRID_SIDE} cells",
            Reaction::MIN_SIDE
        ));
    }
    Ok((w, h))
}

/// A catalogue reaction at `size`, for the gallery, in the host's colours: the picture,
/// its detail and work columns, and the time it took.
pub fn render_entry(
    scene: &Scene,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, String, String, Duration), String> {
    let Scene::Reaction { preset, steps, .. } = *scene else {
        return Err("not a reaction scene".to_string());
    };
    let look = Look {
        background: Rgb888::BLACK,
        ink: Rgb888::WHITE,
        keys: &KEYS,
        inside: Rgb888::BLACK,
    };
    let mut display = SimulatorDisplay::new(size);
    let started = Instant::now();
    let work = scene
        .draw(&mut display, &look)
        .map_err(crate::scene::engine_error)
        .map_err(|e| e.to_string())?;
    let detail = format!("{}, {steps} steps", preset.name());
    let work = format!("{} {}s", work.count(), scene.work_unit());
    Ok((display, detail, work, started.elapsed()))
}
