//! Open L-systems: productions ask an environment about the turtle where they expand.

use embedded_graphics::primitives::Rectangle;
use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
use tinyfractal::{
    error::{ReadError, Unsupported},
    lsystem::{Environment, Segments3, TurtleState},
    Error, LsysFile, ParametricGrammar, ParametricLSystem, Real,
};

fn grammar(text: &str) -> Result<ParametricGrammar, Error> {
    LsysFile::new(text).entries().next().unwrap()?.parametric()
}

/// 1 below the line y = `height`, else 0.
struct Below(f64);

impl Environment for Below {
    fn query(&self, _query: Real, turtle: &TurtleState) -> Real {
        if turtle.position[1].to_f64() < self.0 {
            Real::ONE
        } else {
            Real::ZERO
        }
    }
}

const SHOOT: &str =
    "s {\n  axiom: A\n  angle: 90\n  A : env(0) > 0 --> FA\n  A : env(0) == 0 -->\n}\n";

/// A shoot grows one step while the turtle, where its apex is expanded, is below the
/// line: from y = 0 it expands at 0, 1 and 2, and stops at 3, whatever the order.
#[test]
fn a_shoot_stops_at_the_line() {
    let grammar = grammar(SHOOT).unwrap();
    assert!(grammar.uses_environment());
    for order in [3, 10, 20] {
        let segments: Vec<_> = Segments3::<24, 16>::new(&grammar, order)
            .unwrap()
            .with_environment(&Below(3.0))
            .map(Result::unwrap)
            .collect();
        let ends: Vec<f64> = segments.iter().map(|s| s.end[1].to_f64()).collect();
        assert_eq!(ends, [1.0, 2.0, 3.0], "order {order}");
    }
    // Without an environment the walk says what is missing.
    let error = Segments3::<24, 16>::new(&grammar, 3)
        .unwrap()
        .find_map(Result::err)
        .unwrap();
    assert_eq!(
        error,
        Error::Walk(tinyfractal::error::WalkError::NoEnvironment { symbol: 'A' })
    );
}

/// The fit's walks and the draw's ask alike: the drawing lights exactly its bounding box's
/// extent, a 1-by-`3 steps` line standing on the start.
#[test]
fn fit_and_draw_agree() {
    let grammar = grammar(SHOOT).unwrap();
    let below = Below(3.0);
    let system = ParametricLSystem::<24, 16>::new(&grammar, 12).with_environment(&below);
    let drawing = system
        .fit(
            Rectangle::new(Point::zero(), Size::new(32, 32)),
            &[BinaryColor::On],
        )
        .unwrap();
    let mut display = MockDisplay::new();
    display.set_allow_overdraw(true);
    drawing.draw(&mut display).unwrap();
    let lit = display.affected_area();
    assert_eq!(lit, drawing.bounding_box());
    assert_eq!(lit.size.width, 1);
    assert!(lit.size.height > 20, "{lit:?}");
}

/// Environments and contexts do not mix: a typed error at the contextual production.
#[test]
fn environments_refuse_contexts() {
    let text = "s {\n  axiom: BA\n  angle: 90\n  B < A : env(0) > 0 --> FA\n}\n";
    assert!(matches!(
        grammar(text),
        Err(Error::Read(ReadError::Unsupported {
            feature: Unsupported::EnvironmentWithContext,
            ..
        }))
    ));
}
