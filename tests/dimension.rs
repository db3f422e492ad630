//! Fractal theory: the box-counting dimension of a rendered Koch curve is log 4 / log 3.

mod common;

use common::Bitmap;
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
use tinyfractal::{Angle, Dialect, Grammar, LSystem, Placement, Real};

/// Boxes of side `side` pixels that hold at least one lit pixel.
fn occupied_boxes(bitmap: &Bitmap, side: i32) -> usize {
    let (w, h) = (bitmap.size.width as i32, bitmap.size.height as i32);
    let mut count = 0;
    for by in (0..h).step_by(side as usize) {
        for bx in (0..w).step_by(side as usize) {
            let hit = (by..(by + side).min(h))
                .any(|y| (bx..(bx + side).min(w)).any(|x| bitmap.get(x, y)));
            count += usize::from(hit);
        }
    }
    count
}

#[test]
fn koch_curve_box_counting_dimension_is_log4_over_log3() {
    let grammar = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap();
    // Order 7 with a 1-pixel step: 2187 pixels wide, the finest detail one pixel.
    let mut bitmap = Bitmap::new(2200, 660);
    let placement = Placement {
        origin: Point::new(5, 650),
        step: Real::ONE,
        turns: 0,
    };
    let drawing = LSystem::new(&grammar, 7)
        .place(placement, &[BinaryColor::On])
        .unwrap();
    drawing.draw(&mut bitmap).unwrap();
    assert!(bitmap
        .bounding_box()
        .contains(drawing.bounding_box().top_left));

    // Least-squares slope of log N(s) against log(1/s) over box sides 3, 9, 27, 81.
    let points: Vec<(f64, f64)> = [3, 9, 27, 81]
        .iter()
        .map(|&side| {
            (
                (1.0 / side as f64).ln(),
                (occupied_boxes(&bitmap, side) as f64).ln(),
            )
        })
        .collect();
    let n = points.len() as f64;
    let (mx, my) = (
        points.iter().map(|p| p.0).sum::<f64>() / n,
        points.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
        / points.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
    let theory = 4f64.ln() / 3f64.ln();
    // Box grids are not aligned with the curve's self-similar pieces, so a few per cent is
    // the method's own error; a wrong curve (a straight line: 1.0, a filled area: 2.0)
    // is far outside.
    println!("box-counting dimension {slope:.4}, theory {theory:.4}");
    assert!(
        (slope - theory).abs() < 0.04,
        "box-counting dimension {slope:.4}, theory {theory:.4}"
    );
}
