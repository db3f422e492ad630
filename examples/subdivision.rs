//! Draws the Sierpiński carpet, gasket and the Menger sponge side by side, and saves them
//! as `subdivision.png`.
//!
//! `cargo run --example subdivision`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::subdivision::CubeVariant;
use tinyfractal::{Carpet, Gasket, SierpinskiCube};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(480, 160));
    let third = |i: i32| Rectangle::new(Point::new(160 * i, 0), Size::new(160, 160));

    let carpet = Carpet::new(4)
        .fit(third(0), Rgb888::WHITE, Rgb888::BLACK)?
        .draw(&mut display)?;
    let gasket = Gasket::new(6)
        .fit(third(1), Rgb888::WHITE, Rgb888::BLACK)?
        .draw(&mut display)?;
    let sponge = SierpinskiCube::new(3, CubeVariant::Axes)
        .fit(third(2), Rgb888::CSS_SANDY_BROWN, Rgb888::BLACK)?
        .draw(&mut display)?;
    println!(
        "{} squares, {} triangles, {} cubes",
        carpet.squares, gasket.triangles, sponge.cubes
    );

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("subdivision.png")?;
    println!("wrote subdivision.png");
    Ok(())
}
