//! Draws Perlin's clouds and marble side by side, and prints his published value at
//! (½, ½, ½); saves `noise.png`.
//!
//! `cargo run --example noise`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::noise::{NoiseTexture, Perlin, Texture};
use tinyfractal::render::Gradient;
use tinyfractal::Real;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let noise = Perlin::reference();
    let half = Real::from_ratio(1, 2).ok_or("one half")?;
    // Every digit of the engine's value: Perlin's own -0.25.
    let mut value = String::new();
    noise.noise3(half, half, half).write_exact(&mut value)?;
    println!("noise(0.5, 0.5, 0.5) = {value}");

    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 160));
    // A texture's 256 levels through a gradient of 256 entries, one entry a level.
    let sky = [
        Rgb888::CSS_ROYAL_BLUE,
        Rgb888::CSS_LIGHT_SKY_BLUE,
        Rgb888::WHITE,
    ];
    let stone = [Rgb888::CSS_DIM_GRAY, Rgb888::CSS_SILVER, Rgb888::WHITE];
    let halves = [
        (Texture::Clouds, &sky, Point::zero()),
        (Texture::Marble, &stone, Point::new(160, 0)),
    ];
    for (texture, keys, corner) in halves {
        let palette = Gradient::<Rgb888, 256>::new(keys, Rgb888::BLACK).ok_or("colours")?;
        NoiseTexture::new(&noise, texture)
            .with_scale(Real::from_int(3))
            .fit(Rectangle::new(corner, Size::new(160, 160)), palette)?
            .draw(&mut display)?;
    }

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("noise.png")?;
    println!("wrote noise.png");
    Ok(())
}
