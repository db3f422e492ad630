//! Draws the Koch snowflake and an ABOP plant from `data/classics.l` into the simulator's
//! display, and saves it as `lsystem.png`.
//!
//! `cargo run --example lsystem`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::render::Orientation;
use tinyfractal::{Angle, Dialect, Grammar, LFile, LSystem};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 160));
    let (left, right) = (
        Rectangle::new(Point::zero(), Size::new(160, 160)),
        Rectangle::new(Point::new(160, 0), Size::new(160, 160)),
    );

    // Inline, in ABOP's notation.
    let snowflake =
        Grammar::new(Dialect::Abop, "F--F--F", Angle::Divisions(6))?.with_rule('F', "F+F--F+F")?;
    let stats = LSystem::new(&snowflake, 4)
        .fit(left, &[Rgb888::CSS_LIGHT_SKY_BLUE])?
        .draw(&mut display)?;
    println!("snowflake: {} segments", stats.segments);

    // From a Fractint file, by name; ABOP's plants grow up.
    let file = LFile::new(include_str!("../data/classics.l"));
    let plant = file.find("PlantF")?;
    LSystem::new(&plant, 4)
        .with_orientation(Orientation::Up)
        .fit(right, &[Rgb888::CSS_LIME_GREEN])?
        .draw(&mut display)?;

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("lsystem.png")?;
    println!("wrote lsystem.png");
    Ok(())
}
