//! Runs Sims's mitosis on a 96×96 grid from his start, stepping from a loop as a firmware's
//! main loop would, and draws B; saves `reaction.png`.
//!
//! `cargo run --example reaction`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::reaction::{Cell, Preset, Reaction, Start};
use tinyfractal::render::Gradient;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The caller owns the grid and the ring of three rows: nothing is allocated inside.
    let mut cells = vec![Cell::REST; 96 * 96];
    let mut ring = vec![Cell::REST; Reaction::ring_len(96)];
    let mut reaction = Reaction::new(&Preset::Mitosis.model(), (96, 96), &mut cells, &mut ring)?;
    reaction.start(Start::Square);
    // A main loop: 100 steps at a time, so a display or a button can be served between.
    while reaction.steps() < 6000 {
        reaction.step(100);
    }

    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(288, 288));
    let keys = [
        Rgb888::CSS_MIDNIGHT_BLUE,
        Rgb888::CSS_TEAL,
        Rgb888::CSS_IVORY,
    ];
    let palette = Gradient::<Rgb888, 256>::new(&keys, Rgb888::BLACK).ok_or("colours")?;
    reaction
        .fit(Rectangle::new(Point::zero(), display.size()), palette)?
        .draw(&mut display)?;
    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("reaction.png")?;
    println!("wrote reaction.png after {} steps", reaction.steps());
    Ok(())
}
