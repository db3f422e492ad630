//! Draws a terrain profile above a diamond-square landscape, both by midpoint
//! displacement with one seed, and saves them as `terrain.png`.
//!
//! `cargo run --example terrain`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::terrain::Displacement;
use tinyfractal::{Real, Terrain, TerrainMap};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
    let displacement = Displacement {
        roughness: Real::from_ratio(7, 10).ok_or("roughness")?,
        sigma: Real::from_int(20),
        seed: 1,
    };

    let sky = Rectangle::new(Point::zero(), Size::new(320, 80));
    let drawn = Terrain::new(1025, displacement)
        .fit(sky, Rgb888::CSS_OLIVE_DRAB, Rgb888::CSS_SKY_BLUE)?
        .draw(&mut display)?;
    println!("profile: {drawn} columns");

    // The landscape's heights live in a buffer the caller gives: (2ᵏ + 1)² of them.
    let map = TerrainMap::new(129, displacement);
    let mut heights = vec![0; map.cells()];
    let land = Rectangle::new(Point::new(0, 80), Size::new(320, 160));
    map.fit::<Rgb888>(land, &mut heights)?.draw(&mut display)?;

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("terrain.png")?;
    println!("wrote terrain.png");
    Ok(())
}
