//! The articulated figure: a rigid hierarchy (every limb keeps its length in every pose,
//! each child's joint on its parent's end), and the matrix stack's push/pop exact.

use std::collections::HashMap;

use embedded_graphics::primitives::Rectangle;
use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
use proptest::prelude::*;
use tinyfractal::{
    figure::{walk as walk_pose, Pose, Shape, BODY},
    Figure, Real,
};

/// A drawn line's ends.
type Line = ([f64; 2], [f64; 2]);

fn lines(pose: Pose) -> HashMap<&'static str, Vec<Line>> {
    let mut by_part: HashMap<&'static str, Vec<_>> = HashMap::new();
    Figure::new(&BODY, pose)
        .for_each_line(|line| {
            let s = line.segment;
            by_part.entry(line.part).or_default().push((
                [s.start[0].to_f64(), s.start[1].to_f64()],
                [s.end[0].to_f64(), s.end[1].to_f64()],
            ));
            Ok(())
        })
        .unwrap();
    by_part
}

/// Every `Line` part of the body and its length.
fn limbs() -> Vec<(&'static str, f64)> {
    fn visit(part: &tinyfractal::figure::Part, out: &mut Vec<(&'static str, f64)>) {
        if let Shape::Line { length } = part.shape {
            out.push((part.name, length.to_f64()));
        }
        for child in part.children {
            visit(child, out);
        }
    }
    let mut out = Vec::new();
    visit(&BODY, &mut out);
    out
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// In any pose, every limb keeps its length and each child's joint sits on its
    /// parent's end.
    #[test]
    fn the_body_is_rigid(angles in proptest::array::uniform12(-180i32..180)) {
        let mut pose = Pose::default();
        for (slot, &a) in pose.angles.iter_mut().zip(&angles) {
            *slot = Real::from_int(a);
        }
        let drawn = lines(pose);
        for (name, length) in limbs() {
            let (a, b) = drawn[name][0];
            prop_assert!((distance(a, b) - length).abs() < 1e-6, "{} is {}", name, distance(a, b));
        }
        for (parent, child) in [
            ("left upper arm", "left forearm"),
            ("right upper arm", "right forearm"),
            ("left thigh", "left shin"),
            ("right thigh", "right shin"),
            ("left shin", "left foot"),
            ("right shin", "right foot"),
        ] {
            let end = drawn[parent][0].1;
            let joint = drawn[child][0].0;
            prop_assert!(distance(end, joint) < 1e-6, "{} off {}", child, parent);
        }
    }
}

/// Standing, the figure is symmetric about its vertical axis in height: both feet on the
/// same level, the head above the hips. The walk moves the legs apart; and the figure
/// draws inside its box.
#[test]
fn poses_and_drawing() {
    let standing = lines(Pose::default());
    let y = |part: &str| standing[part][0].1[1];
    assert!((y("left foot") - y("right foot")).abs() < 1e-9);
    assert!(standing["head"][0].0[1] > standing["hips"][0].0[1] + 3.0);
    let step = lines(walk_pose(Real::from_ratio(1, 4).unwrap()));
    let (left, right) = (step["left foot"][0].0, step["right foot"][0].0);
    assert!((left[0] - right[0]).abs() > 1.0, "{left:?} {right:?}");
    assert_eq!(Figure::MAX_JOINTS, 16);
    let drawing = Figure::new(&BODY, walk_pose(Real::ZERO))
        .fit(
            Rectangle::new(Point::zero(), Size::new(48, 64)),
            &[BinaryColor::On],
        )
        .unwrap();
    let mut display = MockDisplay::new();
    display.set_allow_overdraw(true);
    let drawn = drawing.draw(&mut display).unwrap();
    // Two boxes (hips, torso) of four lines, ten limbs (two arms of two parts, two legs
    // of three), the neck, and three circles (head, hands).
    assert_eq!(drawn, 2 * 4 + (2 * 2 + 2 * 3) + 1 + 3, "lines and circles");
    assert_eq!(display.affected_area(), drawing.bounding_box());
}

/// An animation fitted over its frames: every frame of the walk cycle draws inside the
/// shared box, and together they fill it (the fit is tight over the cycle, not over one
/// frame, whose own fit would push other frames' feet outside).
#[test]
fn frames_of_a_cycle_share_one_fit() {
    let frames: Vec<Pose> = (0..16)
        .map(|k| walk_pose(Real::from_ratio(k, 16).unwrap()))
        .collect();
    let drawing = Figure::new(&BODY, frames[0])
        .fit_poses(
            Rectangle::new(Point::zero(), Size::new(48, 64)),
            &[BinaryColor::On],
            frames.iter().copied(),
        )
        .unwrap();
    let fitted = drawing.bounding_box();
    let mut union: Option<Rectangle> = None;
    for &pose in &frames {
        let mut display = MockDisplay::new();
        display.set_allow_overdraw(true);
        drawing.with_pose(pose).draw(&mut display).unwrap();
        let area = display.affected_area();
        assert_eq!(
            area.intersection(&fitted),
            area,
            "{pose:?} leaves {fitted:?}"
        );
        union = Some(union.map_or(area, |u| {
            Rectangle::with_corners(
                u.top_left.component_min(area.top_left),
                u.bottom_right()
                    .unwrap()
                    .component_max(area.bottom_right().unwrap()),
            )
        }));
    }
    assert_eq!(union, Some(fitted));
    // One frame's own fit is another fit: the cycle's box is wider than a frame's.
    let alone = Figure::new(&BODY, frames[0])
        .fit(
            Rectangle::new(Point::zero(), Size::new(48, 64)),
            &[BinaryColor::On],
        )
        .unwrap();
    assert_ne!(alone.bounding_box(), fitted);
}
