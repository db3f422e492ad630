//! The box-counting dimension of a picture: the `--dimension` line of a render, and
//! `tinyfractal dimension FILE.png`.

use std::path::Path;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::SimulatorDisplay;

use crate::console;

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
pub fn dimension(path: &Path, background: u32) -> Result<(), String> {
    use embedded_graphics::prelude::*;
    let picture = image::open(path)
        .map_err(|e| format!("dimension {}: {e}", path.display()))?
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
