//! Draws the Mandelbrot set through a gradient into the simulator's display, and saves it
//! as `escape.png`.
//!
//! `cargo run --example escape`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::render::Gradient;
use tinyfractal::{Coord, EscapeTime, Fractal, View};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
    let number = |text: &str| Coord::parse(text).ok_or("not a number");
    let view = View::new(
        Fractal::Mandelbrot,
        (number("-0.75")?, number("0")?),
        number("3.5")?,
        display.size(),
        256,
    )?; // picks the precision tier
    let keys = [Rgb888::CSS_MIDNIGHT_BLUE, Rgb888::CSS_GOLD, Rgb888::WHITE];
    let palette = Gradient::<Rgb888, 64>::new(&keys, Rgb888::BLACK).ok_or("no keys")?;
    let Ok(stats) = EscapeTime::new(view, palette).draw(&mut display);
    println!(
        "{:?} tier: {} pixels computed of {}",
        view.tier(),
        stats.pixels,
        320 * 240
    );

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("escape.png")?;
    println!("wrote escape.png");
    Ok(())
}
