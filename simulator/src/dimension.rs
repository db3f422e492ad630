//! The box-counting dimension of a picture: the `--dimension` line of a render, and
//! `tinyfractal dimension FILE.png`.

use std::path::{Path, PathBuf};

use clap::Args;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::SimulatorDisplay;

use crate::console::{self, Failure};

/// `dimension`'s options.
#[derive(Debug, Args)]
pub struct DimensionOptions {
    /// The picture
    #[arg(value_name = "FILE.png")]
    pub file: PathBuf,
    /// The background colour, RRGGBB in hex
    #[arg(long, value_name = "RRGGBB", default_value = "000000", value_parser = parse_rgb)]
    pub background: u32,
}

impl DimensionOptions {
    /// `dimension FILE.png`: the box-counting dimension of the picture's pixels that are not
    /// the background.
    pub fn run(&self) -> Result<(), Failure> {
        Ok(dimension(&self.file, self.background)?)
    }
}

/// `--background`'s value.
fn parse_rgb(text: &str) -> Result<u32, String> {
    let hex = text.trim().trim_start_matches('#');
    match u32::from_str_radix(hex, 16) {
        Ok(value) if hex.len() == 6 => Ok(value),
        _ => Err(format!(
            "`{text}` is not a colour RRGGBB in hex, e.g. 000000 or ffffff"
        )),
    }
}

/// The box-counting dimension of `display`'s pixels other than `background`, as
/// `dimension=D.DDD residual=R.RRR boxes=S..L` (box sides in pixels).
pub fn dimension_line(
    display: &SimulatorDisplay<Rgb888>,
    background: Rgb888,
) -> Result<String, String> {
    use embedded_graphics::prelude::*;
    let size = display.size();
    let mut bits = vec![0u32; tinyfractal::BoxCounter::<Rgb888>::words_needed(size, 0)];
    let mut counter = tinyfractal::BoxCounter::new(size, 0, background, &mut bits)
        .map_err(|e| format!("dimension: {e}"))?;
    let pixels = display
        .bounding_box()
        .points()
        .map(|p| display.get_pixel(p));
    let Ok(()) = counter.fill_contiguous(&display.bounding_box(), pixels);
    let estimate = counter.dimension().map_err(|e| format!("dimension: {e}"))?;
    Ok(format!(
        "dimension={:.3} residual={:.3} boxes={}..{}",
        estimate.value.to_f64(),
        estimate.residual.to_f64(),
        1u32 << estimate.smallest,
        1u32 << estimate.largest
    ))
}

/// `tinyfractal dimension FILE.png`: the picture's box-counting dimension.
fn dimension(path: &Path, background: u32) -> Result<(), String> {
    use embedded_graphics::prelude::*;
    let picture = image::open(path)
        .map_err(|e| match e {
            // The reader's default limit (512 MiB decoded) keeps a small file that claims a
            // huge picture from taking the machine's memory.
            image::ImageError::Limits(_) => format!(
                "dimension {}: the picture is too large to read (more than 512 MiB decoded): \
                 give a smaller PNG",
                path.display()
            ),
            e => format!("dimension {}: {e}", path.display()),
        })?
        .to_rgb8();
    let (width, height) = picture.dimensions();
    let mut display = SimulatorDisplay::new(Size::new(width, height));
    for (x, y, pixel) in picture.enumerate_pixels() {
        let [r, g, b] = pixel.0;
        let _ = Pixel(Point::new(x as i32, y as i32), Rgb888::new(r, g, b)).draw(&mut display);
    }
    let [_, r, g, b] = background.to_be_bytes();
    console::print(&format!(
        "{}\n",
        dimension_line(&display, Rgb888::new(r, g, b))?
    ))
}
