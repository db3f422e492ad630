//! Draws the Lorenz butterfly by density, seen in perspective and turned a little, and
//! prints where its orbit starts; saves `attractor.png`.
//!
//! `cargo run --example attractor`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::attractor::{Attractor, AttractorPicture, Kind};
use tinyfractal::render::{Gradient, Projection};
use tinyfractal::Real;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let lorenz = Attractor::new(Kind::Lorenz);
    // The orbit itself: the start, then a step of RK4 (Δt = 0.01) at a time.
    for point in lorenz.orbit(0, 3) {
        let [x, y, z] = point?;
        println!("{} {} {}", x.to_f64(), y.to_f64(), z.to_f64());
    }

    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
    let area = Rectangle::new(Point::zero(), display.size());
    let keys = [
        Rgb888::CSS_MIDNIGHT_BLUE,
        Rgb888::CSS_DARK_ORANGE,
        Rgb888::CSS_IVORY,
    ];
    let palette = Gradient::<Rgb888, 16>::new(&keys, Rgb888::BLACK).ok_or("colours")?;
    // Hit counts a pixel, in a buffer the caller owns (u8 would take half).
    let mut counts = vec![0u16; 320 * 240];
    let stats = AttractorPicture::new(lorenz, 500_000)
        .with_projection(Projection::Perspective {
            distance: Real::from_int(3),
        })
        .with_turn(Real::from_int(30))
        .fit_density(area, palette, &mut counts)?
        .draw(&mut display)?;
    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("attractor.png")?;
    println!("wrote attractor.png: {} points", stats.points);
    Ok(())
}
