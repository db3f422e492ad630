//! Fractal theory: box-counting dimensions of rendered pictures against their theoretical
//! values (the table in docs/families.md), and the core's box counter against an independent one.

mod common;

use common::Bitmap;
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
use tinyfractal::{lsystem::Placement, Angle, BoxCounter, Dialect, Grammar, LSystem, Real};

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

/// The core's box counter over what `draw` paints into a `size` area (background black).
fn estimate(
    size: Size,
    draw: impl FnOnce(&mut BoxCounter<'_, BinaryColor>),
) -> (f64, f64, BoxCounter<'static, BinaryColor>) {
    let words = BoxCounter::<BinaryColor>::words_needed(size, 0);
    let bits: &'static mut [u32] = Box::leak(vec![0; words].into_boxed_slice());
    let mut counter = BoxCounter::new(size, 0, BinaryColor::Off, bits).unwrap();
    draw(&mut counter);
    let d = counter.dimension().unwrap();
    (d.value.to_f64(), d.residual.to_f64(), counter)
}

/// Theory, the core's estimate and the tolerance stated in docs/families.md's table.
const TOLERANCE: f64 = 0.05;

fn check(
    name: &str,
    theory: f64,
    (value, residual, _): (f64, f64, BoxCounter<'static, BinaryColor>),
) {
    println!("| {name} | {theory:.3} | {value:.3} | {residual:.3} |");
    assert!(
        (value - theory).abs() < TOLERANCE,
        "{name}: box-counting estimate {value:.4} (residual {residual:.4}), theory {theory:.4}"
    );
}

#[test]
fn box_counter_counts_as_the_independent_counter_does() {
    // The Koch curve above, counted both ways at every side from 1 to 64.
    let grammar = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap();
    let placement = Placement {
        origin: Point::new(5, 250),
        step: Real::ONE,
        turns: 0,
    };
    let drawing = LSystem::new(&grammar, 5)
        .place(placement, &[BinaryColor::On])
        .unwrap();
    let mut bitmap = Bitmap::new(260, 260);
    drawing.draw(&mut bitmap).unwrap();
    let (_, _, counter) = estimate(Size::new(260, 260), |c| {
        drawing.draw(c).unwrap();
    });
    for k in 0..=6 {
        assert_eq!(
            counter.occupied(k) as usize,
            occupied_boxes(&bitmap, 1 << k),
            "side {}",
            1 << k
        );
    }
}

#[test]
fn box_counting_estimates_match_theory() {
    use embedded_graphics::primitives::{Line, PrimitiveStyle, Rectangle};
    use tinyfractal::{Carpet, Gasket};
    let on = BinaryColor::On;
    // A filled square and a line: 2 and 1.
    check(
        "filled square",
        2.0,
        estimate(Size::new(512, 512), |c| {
            c.fill_solid(&Rectangle::new(Point::new(0, 0), Size::new(512, 512)), on)
                .unwrap();
        }),
    );
    check(
        "line",
        1.0,
        estimate(Size::new(512, 512), |c| {
            Line::new(Point::new(3, 7), Point::new(508, 300))
                .into_styled(PrimitiveStyle::with_stroke(on, 1))
                .draw(c)
                .unwrap();
        }),
    );
    // The Koch curve at order 6 (729 px), one pixel a step.
    let koch = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap();
    check(
        "Koch curve",
        4f64.ln() / 3f64.ln(),
        estimate(Size::new(740, 740), |c| {
            let placement = Placement {
                origin: Point::new(5, 600),
                step: Real::ONE,
                turns: 0,
            };
            LSystem::new(&koch, 6)
                .place(placement, &[on])
                .unwrap()
                .draw(c)
                .unwrap();
        }),
    );
    // The carpet at 3^6 pixels (its holes painted in the background: the counter clears
    // them again) and the gasket at 2^9 rows.
    check(
        "Sierpinski carpet",
        8f64.ln() / 3f64.ln(),
        estimate(Size::new(729, 729), |c| {
            let area = c.bounding_box();
            Carpet::new(6)
                .fit(area, on, BinaryColor::Off)
                .unwrap()
                .draw(c)
                .unwrap();
        }),
    );
    check(
        "Sierpinski gasket",
        3f64.ln() / 2f64.ln(),
        estimate(Size::new(740, 640), |c| {
            let area = c.bounding_box();
            Gasket::new(9)
                .fit(area, on, BinaryColor::Off)
                .unwrap()
                .draw(c)
                .unwrap();
        }),
    );
}
