//! Systems whose `@` factors shrink or grow the step by many orders of magnitude (spirals,
//! shells, horns) fit and draw as a float turtle draws them: checked against the f64
//! model of the turtle language in `common`, which knows nothing of the engine's units.

mod common;

use common::{Bitmap, ModelSystem};
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use tinyfractal::{error::WalkError, Error, LFile, LSystem};

/// Fractint systems past a 64-bit fixed-point turtle's 2⁶³ of range: a shell shrinking
/// by 0.8 a step (0.8²⁵⁶ ≈ 2⁻⁸²), a horn growing by 1.5 (1.5²⁵⁶ ≈ 2¹⁵⁰), and a square
/// spiral whose step shrinks to 2⁻⁶⁰ before its segments are drawn, growing back (each
/// `@I.5` undoes an `@.5`: the last segment is as long as the first step).
const SYSTEMS: &str = "\
shell {
  angle 24
  axiom x
  x=f+@.8x
}
horn {
  angle 24
  axiom x
  x=f+@1.5x
}
regrow {
  angle 4
  axiom a
  a=@.5a@i.5+f
}
";

const ORDERS: [(&str, u32); 3] = [("shell", 256), ("horn", 256), ("regrow", 60)];

/// The area and the fit's margin.
const SIZE: (u32, u32) = (200, 150);
const MARGIN: f64 = 2.0;

fn model(name: &str, order: u32) -> Vec<[f64; 4]> {
    let start = SYSTEMS.find(&format!("{name} {{")).unwrap();
    let body = &SYSTEMS[start..];
    let body = &body[body.find('{').unwrap() + 1..body.find('}').unwrap()];
    let system = ModelSystem::from_fractint_body(body);
    system.segments(&system.derive(order, 1 << 20).unwrap())
}

#[test]
fn steps_scaled_by_many_orders_of_magnitude_draw_as_a_float_turtle_draws_them() {
    let file = LFile::new(SYSTEMS);
    for (name, order) in ORDERS {
        let grammar = file.find(name).unwrap();
        let system = LSystem::<'_, '_, 300, 20>::with_capacity(&grammar, order);
        // In turtle units (a first step of 1), a fixed-point walk cannot hold it.
        assert!(
            matches!(
                system.bounds(),
                Err(Error::Walk(WalkError::StepUnderflow | WalkError::Overflow))
            ),
            "{name}: {:?}",
            system.bounds()
        );
        let area = Rectangle::new(Point::zero(), Size::new(SIZE.0, SIZE.1));
        let drawing = system
            .fit(area, &[BinaryColor::On])
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut frame = Bitmap::new(SIZE.0, SIZE.1);
        let stats = drawing.draw(&mut frame).unwrap();
        assert_eq!(frame.outside, 0, "{name}");

        // The model's box, fitted as the fit documents it: the tighter axis spans the area
        // less the margins.
        let segments = model(name, order);
        assert_eq!(stats.segments, segments.len() as u64, "{name}");
        let (mut low, mut high) = ((0.0f64, 0.0f64), (0.0f64, 0.0f64));
        for s in &segments {
            for (x, y) in [(s[0], s[1]), (s[2], s[3])] {
                low = (low.0.min(x), low.1.min(y));
                high = (high.0.max(x), high.1.max(y));
            }
        }
        let span = |size: u32| f64::from(size - 1) - 2.0 * MARGIN;
        let scale = (span(SIZE.0) / (high.0 - low.0)).min(span(SIZE.1) / (high.1 - low.1));
        let start = drawing.start();
        let step = start.step.to_f64() * 2f64.powi(-(start.step_shift as i32));
        assert!(
            (step / scale - 1.0).abs() < 1e-4,
            "{name}: step {step:e} px, the model's {scale:e}"
        );

        // Every end of a segment at least two pixels long lies on a lit pixel (or next to
        // one): the shape is the model's, not only its box.
        let (x0, y0) = (start.position.x.to_f64(), start.position.y.to_f64());
        let mut checked = 0;
        for s in &segments {
            let length = step * (s[2] - s[0]).hypot(s[3] - s[1]);
            if length < 2.0 {
                continue;
            }
            for (x, y) in [(s[0], s[1]), (s[2], s[3])] {
                // Orientation right: the row is −y.
                let (px, py) = (
                    (x0 + step * x).round() as i32,
                    (-(y0 + step * y)).round() as i32,
                );
                let lit = (-1..=1).any(|dx| (-1..=1).any(|dy| frame.get(px + dx, py + dy)));
                assert!(lit, "{name}: no ink near ({px}, {py})");
                checked += 1;
            }
        }
        assert!(checked >= 4, "{name}: {checked} ends checked");
    }
}
