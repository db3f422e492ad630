//! The fitted box without the measuring pass: where the turtle moves only by drawing
//! steps of one length, `fit` takes the pixel box from the sizing walk (the drawing pass
//! is that walk scaled, within half an ulp a step) instead of walking the drawing pass
//! once more. Each box here is checked against that pass, walked and measured in the test.

mod common;

use common::{shipped_file, SHIPPED_L_FILES};
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use tinyfractal::{
    error::WalkError, lsystem::Segments, render::Orientation, Angle, Dialect, Error, Grammar,
    LFile, LSystem, Real,
};

const ORIENTATIONS: [Orientation; 4] = [
    Orientation::Right,
    Orientation::Up,
    Orientation::Left,
    Orientation::Down,
];

/// Picture space (y up) to the screen pixel, as the orientation's quarter turn says.
fn screen(orientation: Orientation, p: tinyfractal::lsystem::TurtlePoint) -> Point {
    let neg = |v: Real| Real::from_bits(-v.to_bits());
    let (x, y) = match orientation {
        Orientation::Right => (p.x, neg(p.y)),
        Orientation::Up => (neg(p.y), neg(p.x)),
        Orientation::Left => (neg(p.x), p.y),
        Orientation::Down => (p.y, p.x),
    };
    Point::new(x.round_to_i32(), y.round_to_i32())
}

/// The box of the pixels the drawing pass's segment ends land on, by walking it; `None`
/// where `@` shrinks a step below what the public walk takes (2⁻²⁰ of a pixel: the
/// engine's own drawing pass takes any step).
fn walked_box(
    grammar: &Grammar<'_>,
    order: u32,
    orientation: Orientation,
    start: tinyfractal::lsystem::Start,
) -> Option<Rectangle> {
    let mut corners: Option<(Point, Point)> = None;
    let segments = match Segments::starting(grammar, order, start) {
        Err(Error::Walk(WalkError::StepUnderflow | WalkError::StepTooFine)) => return None,
        segments => segments.unwrap(),
    };
    for segment in segments {
        let segment = match segment {
            Err(Error::Walk(WalkError::StepUnderflow | WalkError::StepTooFine)) => return None,
            segment => segment.unwrap(),
        };
        for p in [segment.start, segment.end] {
            let p = screen(orientation, p);
            let (low, high) = corners.get_or_insert((p, p));
            *low = Point::new(low.x.min(p.x), low.y.min(p.y));
            *high = Point::new(high.x.max(p.x), high.y.max(p.y));
        }
    }
    Some(corners.map_or_else(
        || Rectangle::new(screen(orientation, start.position), Size::zero()),
        |(low, high)| Rectangle::with_corners(low, high),
    ))
}

fn check(grammar: &Grammar<'_>, order: u32, orientation: Orientation, size: Size) {
    let area = Rectangle::new(Point::new(3, -2), size);
    let system = LSystem::new(grammar, order)
        .with_orientation(orientation)
        .with_budget(200_000);
    let Ok(drawing) = system.fit(area, &[BinaryColor::On]) else {
        return;
    };
    let Some(expected) = walked_box(grammar, order, orientation, drawing.start()) else {
        return;
    };
    assert_eq!(
        drawing.bounding_box(),
        expected,
        "order {order}, {orientation:?}, {size:?}"
    );
}

#[test]
fn fitted_boxes_equal_the_walked_drawing_pass() {
    let sizes = [
        Size::new(128, 64),
        Size::new(320, 240),
        Size::new(97, 131),
        Size::new(5, 7),
        Size::new(2, 2),
    ];
    let mut systems = 0;
    for path in SHIPPED_L_FILES {
        let text = shipped_file(path);
        for entry in LFile::new(&text).entries() {
            let Ok(grammar) = entry.and_then(|entry| entry.grammar()) else {
                continue;
            };
            systems += 1;
            for order in 0..=4 {
                for orientation in ORIENTATIONS {
                    for size in sizes {
                        check(&grammar, order, orientation, size);
                    }
                }
            }
        }
    }
    assert!(systems >= 20, "{systems} systems");
}

/// Fractint's Koch2 (Angle 12) at order 1 puts box edges exactly half a pixel from a
/// rounding boundary at many sizes: the drawing pass's last ulps decide them, so the
/// margin must send these to the walk (without it, 65×64 and 72×65 among others are off
/// by a pixel).
#[test]
fn an_edge_on_a_rounding_boundary_is_measured_by_walking() {
    let grammar = Grammar::new(Dialect::Fractint, "F---F---F---F", Angle::Divisions(12))
        .and_then(|g| g.with_rule('F', "-F+++F---F+"))
        .unwrap();
    for width in (2..400).step_by(7) {
        for height in [64, 65, 240, 241] {
            check(&grammar, 1, Orientation::Right, Size::new(width, height));
        }
    }
}

/// Systems whose `@` makes the drawing pass drift from the scaled sizing walk by more than
/// half an ulp a step (found by a search over 27,349 random fits, where margins without
/// the `@` term got these boxes a pixel wrong): the margin counts each `@` too.
#[test]
fn a_scaled_step_widens_the_margin() {
    let cases = [
        ("-X@.7F@.5", Angle::Divisions(16), 2, Size::new(35, 98)),
        (
            "+[@.3@.9@.5X@.3F]",
            Angle::Divisions(16),
            2,
            Size::new(183, 154),
        ),
        ("++@.3+XF", Angle::Divisions(8), 3, Size::new(206, 133)),
        ("-X@.5F", Angle::Divisions(16), 2, Size::new(297, 194)),
    ];
    for (rule, angle, order, size) in cases {
        let grammar = Grammar::new(Dialect::Fractint, "X", angle)
            .and_then(|g| g.with_rule('X', rule))
            .and_then(|g| g.with_rule('F', "F@.7F"))
            .unwrap();
        check(&grammar, order, Orientation::Right, size);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Random bracketed systems over `F G M + - [ ] | ! @`, `Angle n` or a free angle, any
    /// size (`G` and `M` move without drawing; `@` scales the step, by 0.1 to 1.5).
    #[test]
    fn random_systems_fit_the_box_their_drawing_pass_measures(
        axiom in "[F+\\-XG]{1,5}",
        rule_f in "[F+\\-]{0,4}(\\[[F+\\-XG]{0,4}\\])?[F+\\-|!M]{0,3}",
        rule_x in "([F+\\-XG]|@\\.[1-9]|@1\\.5){0,6}",
        divisions in 3u16..24,
        free in proptest::option::of(1i64..90),
        order in 0u32..5,
        width in 2u32..260,
        height in 2u32..200,
        turn in 0usize..4,
    ) {
        let angle = match free {
            Some(degrees) => Angle::Degrees(Real::from_ratio(degrees * 7, 10).unwrap()),
            None => Angle::Divisions(divisions),
        };
        let Ok(grammar) = Grammar::new(Dialect::Fractint, &axiom, angle)
            .and_then(|g| g.with_rule('F', &rule_f))
            .and_then(|g| g.with_rule('X', &rule_x))
        else {
            return Ok(());
        };
        check(&grammar, order, ORIENTATIONS[turn], Size::new(width, height));
    }
}

/// Every system of Fractint's own files (shared/corpus), at orders 1 to 5, several sizes,
/// heading right and up. Built as ignored where the corpus is missing, except under
/// `CI=true`.
#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn fitted_boxes_equal_the_walked_pass_for_fractints_corpus() {
    let folder = std::path::PathBuf::from(env!("TINYFRACTAL_CORPUS_DIR")).join("fractint");
    let sizes = [
        Size::new(128, 64),
        Size::new(65, 64),
        Size::new(72, 65),
        Size::new(320, 240),
        Size::new(241, 199),
    ];
    let mut systems = 0;
    for file in ["fractint.l", "penrose.l", "tiling.l"] {
        let path = folder.join(file);
        let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let text: String = bytes.iter().map(|&b| char::from(b)).collect();
        for entry in LFile::new(&text).entries() {
            let Ok(grammar) = entry.and_then(|entry| entry.grammar()) else {
                continue;
            };
            systems += 1;
            for order in 1..=5 {
                for orientation in [Orientation::Right, Orientation::Up] {
                    for size in sizes {
                        check(&grammar, order, orientation, size);
                    }
                }
            }
        }
    }
    assert_eq!(systems, 90);
}
