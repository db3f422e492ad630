//! Ordered dithering: over every 8×8 block (4×4 for Bayer 4) the panel's levels average the
//! colour's to within a level's 1/64 (1/16), computed here from the levels themselves; a
//! picture drawn through the dithering target equals the picture drawn in 24-bit colour
//! and dithered pixel by pixel afterwards (so mirrored halves, tiles and runs change
//! nothing).

use embedded_graphics::pixelcolor::{
    BinaryColor, Gray2, Gray4, GrayColor, Rgb565, Rgb888, RgbColor,
};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::escape::Algorithm;
use tinyfractal::render::{Dither, Dithered, Gradient, Quantize};
use tinyfractal::{Coord, EscapeTime, Fractal, View};

/// The mean level of an n×n block of `grey` drawn through `dither` into a panel of
/// `levels` levels, as a fraction of the top level.
fn block_mean<C: Quantize + GrayColor + From<BinaryColor>>(
    grey: u8,
    dither: Dither,
    n: i32,
    levels: f64,
) -> f64 {
    let mut display = SimulatorDisplay::<C>::new(Size::new(16, 16));
    let area = Rectangle::new(Point::new(8, 8), Size::new(n as u32, n as u32));
    Dithered::new(&mut display, dither)
        .fill_solid(&area, Rgb888::new(grey, grey, grey))
        .unwrap();
    let sum: f64 = area
        .points()
        .map(|p| f64::from(display.get_pixel(p).luma()))
        .sum();
    sum / f64::from(n * n) / (levels - 1.0)
}

#[test]
fn blocks_average_the_grey_level() {
    for grey in 0..=255u8 {
        let wanted = f64::from(grey) / 255.0;
        for (dither, n, tolerance) in [
            (Dither::Bayer8, 8, 1.0 / 64.0),
            (Dither::Bayer4, 4, 1.0 / 16.0),
        ] {
            let one_bit = {
                let mut display = SimulatorDisplay::<BinaryColor>::new(Size::new(16, 16));
                let area = Rectangle::new(Point::new(8, 8), Size::new(n as u32, n as u32));
                Dithered::new(&mut display, dither)
                    .fill_solid(&area, Rgb888::new(grey, grey, grey))
                    .unwrap();
                area.points()
                    .filter(|&p| display.get_pixel(p) == BinaryColor::On)
                    .count() as f64
                    / f64::from(n * n)
            };
            assert!(
                (one_bit - wanted).abs() <= tolerance,
                "1 bit {grey} {dither:?}: {one_bit}"
            );
            let gray2 = block_mean::<Gray2>(grey, dither, n, 4.0);
            assert!(
                (gray2 - wanted).abs() <= tolerance / 3.0 + 1e-9,
                "gray2 {grey}: {gray2}"
            );
            let gray4 = block_mean::<Gray4>(grey, dither, n, 16.0);
            assert!(
                (gray4 - wanted).abs() <= tolerance / 15.0 + 1e-9,
                "gray4 {grey}: {gray4}"
            );
        }
        // Without dithering, the nearest level.
        let nearest = block_mean::<Gray2>(grey, Dither::None, 4, 4.0);
        assert!(
            (nearest * 3.0 - (wanted * 3.0).round()).abs() < 1e-9,
            "{grey}"
        );
    }
}

/// The escape-time picture of a symmetric view (its bottom half sent as the top half
/// mirrored, in tiles and runs) drawn through the dithering target is the 24-bit picture
/// dithered pixel by pixel; so are lines drawn in runs.
#[test]
fn dithering_is_a_function_of_the_pixel_alone() {
    let view = View::new(
        Fractal::Mandelbrot,
        (Coord::parse("-0.75").unwrap(), Coord::default()),
        Coord::parse("3.5").unwrap(),
        Size::new(96, 64),
        60,
    )
    .unwrap();
    let keys = [Rgb888::BLUE, Rgb888::WHITE, Rgb888::new(255, 160, 0)];
    let gradient = Gradient::<Rgb888, 16>::new(&keys, Rgb888::BLACK).unwrap();
    for algorithm in [Algorithm::Fast, Algorithm::Exact] {
        let mut full = SimulatorDisplay::<Rgb888>::new(view.size());
        EscapeTime::new(view, &gradient)
            .with_algorithm(algorithm)
            .draw(&mut full)
            .unwrap();
        for dither in [Dither::None, Dither::Bayer4, Dither::Bayer8] {
            let mut panel = SimulatorDisplay::<Rgb565>::new(view.size());
            EscapeTime::new(view, &gradient)
                .with_algorithm(algorithm)
                .draw(&mut Dithered::new(&mut panel, dither))
                .unwrap();
            for point in full.bounding_box().points() {
                let expected = Rgb565::quantize(full.get_pixel(point), dither.threshold(point));
                assert_eq!(
                    panel.get_pixel(point),
                    expected,
                    "{algorithm:?} {dither:?} {point}"
                );
            }
        }
    }
    // A thick diagonal line (a run a row) in a colour between two levels.
    let mut panel = SimulatorDisplay::<BinaryColor>::new(Size::new(40, 40));
    let grey = Rgb888::new(90, 90, 90);
    embedded_graphics::primitives::Line::new(Point::new(2, 3), Point::new(37, 30))
        .into_styled(PrimitiveStyle::with_stroke(grey, 5))
        .draw(&mut Dithered::new(&mut panel, Dither::Bayer8))
        .unwrap();
    let mut reference = SimulatorDisplay::<Rgb888>::new(Size::new(40, 40));
    embedded_graphics::primitives::Line::new(Point::new(2, 3), Point::new(37, 30))
        .into_styled(PrimitiveStyle::with_stroke(grey, 5))
        .draw(&mut reference)
        .unwrap();
    for point in reference.bounding_box().points() {
        let colour = reference.get_pixel(point);
        if colour != Rgb888::BLACK {
            let expected = BinaryColor::quantize(colour, Dither::Bayer8.threshold(point));
            assert_eq!(panel.get_pixel(point), expected, "{point}");
        }
    }
}

/// A run of one colour (`fill_solid`) is each pixel's colour quantized at its own
/// threshold, whether it leaves as a pattern or, one panel colour at every threshold, as a
/// run of that colour: every grey, on one-bit and 2-bit grey panels.
#[test]
fn a_run_of_one_colour_is_its_pixels() {
    fn check<C: Quantize + core::fmt::Debug + From<BinaryColor>>(grey: u8, dither: Dither) {
        let mut display = SimulatorDisplay::<C>::new(Size::new(24, 24));
        let area = Rectangle::new(Point::new(3, 5), Size::new(17, 11));
        let color = Rgb888::new(grey, grey, grey);
        Dithered::new(&mut display, dither)
            .fill_solid(&area, color)
            .unwrap();
        for point in area.points() {
            assert_eq!(
                display.get_pixel(point),
                C::quantize(color, dither.threshold(point)),
                "{grey} {dither:?} {point}"
            );
        }
    }
    for grey in 0..=255u8 {
        for dither in [Dither::None, Dither::Bayer4, Dither::Bayer8] {
            check::<BinaryColor>(grey, dither);
            check::<Gray2>(grey, dither);
        }
    }
}
