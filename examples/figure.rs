//! Draws the lecture's articulated body at four phases of its walk, side by side, and
//! saves them as `figure.png`.
//!
//! `cargo run --example figure`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::figure::{walk, BODY};
use tinyfractal::{Figure, Real};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 120));
    for quarter in 0..4 {
        let phase = Real::from_ratio(quarter, 4).ok_or("phase")?;
        let area = Rectangle::new(Point::new(80 * quarter as i32, 0), Size::new(80, 120));
        let lines = Figure::new(&BODY, walk(phase))
            .fit(area, &[Rgb888::WHITE])?
            .draw(&mut display)?;
        println!("phase {quarter}/4: {lines} lines");
    }

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("figure.png")?;
    println!("wrote figure.png");
    Ok(())
}
