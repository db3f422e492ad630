//! Plays the chaos game with the lecture's fern from `data/lecture.ifs`, beside the
//! gingerbread man, and saves them as `ifs.png`.
//!
//! `cargo run --example ifs`

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};
use tinyfractal::ifs::IfsPicture;
use tinyfractal::{Gingerbread, IfsFile};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
    let (left, right) = (
        Rectangle::new(Point::zero(), Size::new(160, 240)),
        Rectangle::new(Point::new(160, 60), Size::new(160, 120)),
    );

    let file = IfsFile::new(include_str!("../data/lecture.ifs"));
    let fern = file.entry("fern")?.ifs()?;
    let points = IfsPicture::new(&fern, 100_000)
        .fit(left, &[Rgb888::CSS_FOREST_GREEN, Rgb888::CSS_LIME_GREEN])?
        .draw(&mut display)?;
    println!("fern: {points} points");

    let man = Gingerbread::default();
    if let Some(cycle) = man.cycle(1_000_000)? {
        println!(
            "gingerbread man: period {}, tail {}",
            cycle.period, cycle.tail
        );
    }
    man.fit(right, Rgb888::CSS_SANDY_BROWN)?
        .draw(&mut display)?;

    display
        .to_rgb_output_image(&OutputSettings::default())
        .save_png("ifs.png")?;
    println!("wrote ifs.png");
    Ok(())
}
