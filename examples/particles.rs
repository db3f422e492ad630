//! Runs the fireworks preset for two seconds from a main loop, a frame a tick, erasing the
//! last frame's particles instead of clearing; saves the last frame as `particles.png`.
//!
//! `cargo run --example particles`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::particles::{Frames, ParticleLook, Preset, TICKS_PER_SECOND};
use tinyfractal::render::Gradient;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let size = Size::new(320, 240);
    // A pool of 512 particles, on the stack: nothing is allocated inside.
    let mut fireworks = Preset::Fireworks.system::<512>(size, 42);
    let keys = [Rgb888::WHITE, Rgb888::CSS_GOLD, Rgb888::CSS_CRIMSON];
    let look = ParticleLook {
        palette: Gradient::<Rgb888, 64>::new(&keys, Rgb888::BLACK).ok_or("colours")?,
        size_at_birth: 2,
        size_at_death: 1,
    };
    let mut display = SimulatorDisplay::<Rgb888>::new(size);
    let mut frames = Frames::new();
    for _ in 0..2 * TICKS_PER_SECOND {
        fireworks.step(1);
        frames.draw(&fireworks, &look, Rgb888::BLACK, &mut display)?;
    }
    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("particles.png")?;
    println!(
        "wrote particles.png: {} live particles after {} ticks",
        fireworks.live().count(),
        fireworks.ticks()
    );
    Ok(())
}
