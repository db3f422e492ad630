//! `tinyfractal render particles` and `animate particles`: the presets' particle systems,
//! stepped at thirty ticks a second.

use crate::clock::Instant;
use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::particles::{
    Frames, ParticleLook, ParticleSystem, Preset, PARTICLE_BITS, TICKS_PER_SECOND,
};
use tinyfractal::render::Gradient;

use crate::common::Common;
use crate::console::Failure;

/// Particles the host's pool holds.
pub const CAPACITY: usize = 4096;

/// The longest `--time`, in seconds: a bound on a run's time.
const MAX_SECONDS: f64 = 3600.0;

/// What `render particles` and `animate particles` share.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct ParticleOptions {
    /// The system: fountain, fire, fireworks, snow or explosion
    #[arg(long, value_name = "NAME", value_parser = parse_preset)]
    preset: Preset,
    /// The emitter's seed: the same seed, the same particles
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u64,
}

/// `render particles`' options.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct RenderParticleOptions {
    #[command(flatten)]
    system: ParticleOptions,
    /// The moment drawn, in seconds from the start (30 ticks a second), at most 3600
    #[arg(long, value_name = "T", default_value_t = 3.0, value_parser = parse_time)]
    time: f64,
    /// Write each live particle, `x y vx vy age` a line: position in pixels (y down),
    /// velocity in pixels a second, age in seconds
    #[arg(long, value_name = "TXT")]
    particles: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

fn parse_preset(text: &str) -> Result<Preset, String> {
    Preset::from_name(text).ok_or_else(|| {
        let names: Vec<&str> = Preset::ALL.iter().map(|p| p.name()).collect();
        format!("unknown preset `{text}`: give one of {}", names.join(", "))
    })
}

fn parse_time(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(t) if (0.0..=MAX_SECONDS).contains(&t) => Ok(t),
        _ => Err(format!(
            "`{text}` is not a time from 0 to {MAX_SECONDS} seconds"
        )),
    }
}

const FOUNTAIN: [Rgb888; 3] = [
    Rgb888::new(0xE0, 0xF4, 0xFF),
    Rgb888::new(0x40, 0x90, 0xFF),
    Rgb888::new(0x10, 0x30, 0x80),
];
const FIRE: [Rgb888; 4] = [
    Rgb888::new(0xFF, 0xF0, 0xA0),
    Rgb888::new(0xFF, 0x80, 0x10),
    Rgb888::new(0xA0, 0x10, 0x00),
    Rgb888::new(0x30, 0x08, 0x00),
];
const FIREWORKS: [Rgb888; 4] = [
    Rgb888::WHITE,
    Rgb888::new(0xFF, 0xD0, 0x40),
    Rgb888::new(0xFF, 0x30, 0x60),
    Rgb888::new(0x40, 0x10, 0x40),
];
const SNOW: [Rgb888; 2] = [Rgb888::WHITE, Rgb888::new(0xC0, 0xD8, 0xFF)];
const EXPLOSION: [Rgb888; 4] = [
    Rgb888::new(0xFF, 0xFF, 0xC0),
    Rgb888::new(0xFF, 0x90, 0x20),
    Rgb888::new(0x80, 0x80, 0x80),
    Rgb888::new(0x30, 0x30, 0x30),
];

/// A preset's colours, young to old.
fn keys(preset: Preset) -> &'static [Rgb888] {
    match preset {
        Preset::Fountain => &FOUNTAIN,
        Preset::Fire => &FIRE,
        Preset::Fireworks => &FIREWORKS,
        Preset::Snow => &SNOW,
        Preset::Explosion => &EXPLOSION,
    }
}

impl ParticleOptions {
    /// The system on a target of `size`.
    pub fn system(&self, size: Size) -> Box<ParticleSystem<CAPACITY>> {
        Box::new(self.preset.system(size, self.seed))
    }

    /// The preset's look on a target `height` pixels high.
    pub fn look(&self, height: u32) -> Result<ParticleLook<Gradient<Rgb888, 256>>, String> {
        let sizes = self.preset.sizes(height);
        Ok(ParticleLook {
            palette: Gradient::new(keys(self.preset), Rgb888::BLACK)
                .ok_or("the palette is empty")?,
            size_at_birth: sizes.birth,
            size_at_death: sizes.death,
        })
    }

    /// The preset's name.
    pub fn name(&self) -> &'static str {
        self.preset.name()
    }
}

/// Pixels a tick in Q16.16 to pixels a second.
fn per_second(v: i32) -> f64 {
    f64::from(v) * f64::from(TICKS_PER_SECOND) / f64::from(1u32 << PARTICLE_BITS)
}

impl RenderParticleOptions {
    /// `render particles`.
    pub fn run(&self) -> Result<(), Failure> {
        let common = &self.common;
        crate::delivery::window_available(common.window)?;
        let size = common.area().size;
        let options = &self.system;
        let look = options.look(size.height)?;
        let started = Instant::now();
        let mut system = options.system(size);
        let ticks = (self.time * f64::from(TICKS_PER_SECOND)).round() as u32;
        let steps = system.step(ticks);
        let mut display = SimulatorDisplay::new(size);
        let mut frames = Box::new(Frames::<CAPACITY>::new());
        let Ok(drawn) = frames.draw(&system, &look, Rgb888::BLACK, &mut display);
        let line = format!(
            "particles={} drawn={drawn} ticks={} replaced={} particle_steps={steps} elapsed_ms={:.3}",
            system.live().count(),
            system.ticks(),
            system.replaced(),
            started.elapsed().as_secs_f64() * 1e3
        );
        Ok(crate::delivery::deliver(
            common,
            options.name(),
            &display,
            |plan| {
                if let Some(path) = &self.particles {
                    plan.add("--particles", path, move |w: &mut dyn Write| {
                        let one = f64::from(1u32 << PARTICLE_BITS);
                        for p in system.live() {
                            writeln!(
                                w,
                                "{} {} {} {} {}",
                                f64::from(p.x) / one,
                                f64::from(p.y) / one,
                                per_second(p.vx),
                                per_second(p.vy),
                                f64::from(p.age) / f64::from(TICKS_PER_SECOND)
                            )?;
                        }
                        Ok(())
                    });
                }
            },
            &line,
        )?)
    }
}

/// `animate particles`' frames: a tick a frame from the start, each drawn over the last by
/// erasing its particles.
pub fn frames(
    options: &ParticleOptions,
    count: u32,
    size: Size,
    mut emit: impl FnMut(SimulatorDisplay<Rgb888>) -> Result<(), String>,
) -> Result<String, String> {
    let look = options.look(size.height)?;
    let mut system = options.system(size);
    let mut frames = Box::new(Frames::<CAPACITY>::new());
    let mut display = SimulatorDisplay::new(size);
    let mut steps = 0;
    for _ in 0..count {
        steps += system.step(1);
        let Ok(_) = frames.draw(&system, &look, Rgb888::BLACK, &mut display);
        emit(display.clone())?;
    }
    Ok(format!(
        " particle_steps={steps} replaced={}",
        system.replaced()
    ))
}
