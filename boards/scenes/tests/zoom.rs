//! The boards' zoom: one frame of a byte a pixel moved in place from view to view, a call
//! between frames to pace it, and a last frame equal to the still render of the last view
//! (every pixel computed exactly at its own point, through the same gradient).

use embedded_graphics::pixelcolor::Gray4;
use tinyfractal::{
    escape::{Algorithm, Render},
    render::{DwellBuffer, Gradient, Palette},
    Coord, Fractal, View,
};
use tinyfractal_scenes::{Scene, Work, GREY, ZOOM_SCENES};

use tinyfractal_test_support::frame;

use frame::Frame;

#[test]
fn the_zoom_ends_on_the_exact_picture_of_its_last_view() {
    let entry = ZOOM_SCENES[0];
    let Scene::Zoom {
        centre,
        width,
        max_iterations,
        frames,
        shrink: (numerator, denominator),
        ..
    } = entry.scene
    else {
        panic!("{} is a zoom", entry.name)
    };
    let size = entry.size;
    let mut animated = Frame::filled(size, Gray4::new(7));
    let mut calls = 0;
    let work = entry
        .scene
        .draw_frames(&mut animated, &GREY, || calls += 1)
        .unwrap();
    assert_eq!((work, calls), (Work::Frames(u64::from(frames)), frames));
    assert_eq!(animated.outside, 0);

    // The last view: the first width shrunk by the ratio once a frame after the first.
    let mut last_width = i128::from(Coord::parse(width).unwrap().to_bits());
    for _ in 1..frames {
        last_width = last_width * i128::from(numerator) / i128::from(denominator);
    }
    let parse = |text: &str| Coord::parse(text).unwrap();
    let view = View::new(
        Fractal::Mandelbrot,
        (parse(centre.0), parse(centre.1)),
        Coord::from_bits(last_width as i64),
        size,
        max_iterations,
    )
    .unwrap();
    let shrunk = last_width as f64 / Coord::parse(width).unwrap().to_bits() as f64;
    assert!(
        (shrunk - 1.05f64.powi(1 - frames as i32)).abs() < 1e-9,
        "{shrunk}"
    );
    let mut dwells = vec![0u16; (size.width * size.height) as usize];
    let Ok(_) =
        Render::new(view, Algorithm::Exact).run(&mut DwellBuffer::new(&mut dwells, size.width));
    let gradient = Gradient::<Gray4, 16>::new(GREY.keys, GREY.inside).unwrap();
    let still: Vec<Gray4> = dwells
        .iter()
        .map(|&dwell| gradient.color(dwell, view.inside_value()))
        .collect();
    assert!(
        animated.pixels == still,
        "the last frame is not the still render"
    );
    let inside = still.iter().filter(|&&p| p == GREY.inside).count();
    assert!(
        inside > 0 && inside < still.len() / 2,
        "{inside} pixels inside"
    );
}
