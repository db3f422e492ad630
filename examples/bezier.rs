//! Draws a heart of two cubic Bézier curves and a quadratic arch over it, and prints how
//! the first was flattened; saves `bezier.png`.
//!
//! `cargo run --example bezier`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::bezier::{vertex_to_f64, Bezier};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let left = Bezier::cubic([
        Point::new(160, 220),
        Point::new(20, 130),
        Point::new(80, 20),
        Point::new(160, 80),
    ]);
    let right = Bezier::cubic([
        Point::new(160, 80),
        Point::new(240, 20),
        Point::new(300, 130),
        Point::new(160, 220),
    ]);
    let arch = Bezier::quadratic([
        Point::new(20, 60),
        Point::new(160, -40),
        Point::new(300, 60),
    ]);
    // The pieces are within a quarter pixel of the curve; their ends are exact.
    let vertices: Vec<(f64, f64)> = left.flattened().map(vertex_to_f64).collect();
    println!(
        "{} pieces from {:?} to {:?}",
        vertices.len() - 1,
        vertices[0],
        vertices[vertices.len() - 1]
    );

    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
    let mut pixels = 0;
    for (curve, color) in [
        (left, Rgb888::CSS_CRIMSON),
        (right, Rgb888::CSS_CRIMSON),
        (arch, Rgb888::CSS_GOLD),
    ] {
        pixels += curve.into_stroked(color).draw(&mut display)?.pixels;
    }
    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("bezier.png")?;
    println!("wrote bezier.png: {pixels} pixels");
    Ok(())
}
