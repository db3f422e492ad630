//! The lecture's body: hips → upper body (torso → neck → head; shoulders → upper arms →
//! forearms → hands) and lower body (thighs → shins → feet), facing +x, in units of about
//! a tenth of its height; and its poses: standing, a walk cycle, a wave.

use super::part::{Part, Pose, Shape};
use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// The joints a pose sets, in degrees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(usize)]
pub enum Joint {
    /// The torso's lean forward (negative) or back.
    Waist,
    /// The head's nod.
    Neck,
    /// Left shoulder: the arm forward (positive) or back.
    LeftShoulder,
    /// Left elbow.
    LeftElbow,
    /// Right shoulder.
    RightShoulder,
    /// Right elbow.
    RightElbow,
    /// Left hip: the leg forward (positive) or back.
    LeftHip,
    /// Left knee.
    LeftKnee,
    /// Right hip.
    RightHip,
    /// Right knee.
    RightKnee,
    /// Left ankle.
    LeftAnkle,
    /// Right ankle.
    RightAnkle,
}

const fn r(units: i64, hundredths: i64) -> Real {
    Real::from_bits((units << 32) + (hundredths << 32) / 100)
}

const fn degrees(d: i32) -> Real {
    Real::from_int(d)
}

const fn line(length: Real) -> Shape {
    Shape::Line { length }
}

const HAND: Part = Part {
    name: "hand",
    shape: Shape::Circle { radius: r(0, 20) },
    attach: (r(1, 30), Real::ZERO),
    rest: Real::ZERO,
    joint: None,
    color: 1,
    children: &[],
};

const fn forearm(joint: Joint, name: &'static str) -> Part {
    Part {
        name,
        shape: line(r(1, 30)),
        attach: (r(1, 50), Real::ZERO),
        rest: degrees(20),
        joint: Some(joint as usize),
        color: 1,
        children: &[HAND],
    }
}

const LEFT_FOREARM: [Part; 1] = [forearm(Joint::LeftElbow, "left forearm")];
const RIGHT_FOREARM: [Part; 1] = [forearm(Joint::RightElbow, "right forearm")];

const fn upper_arm(joint: Joint, name: &'static str, children: &'static [Part]) -> Part {
    Part {
        name,
        shape: line(r(1, 50)),
        attach: (r(2, 80), Real::ZERO),
        // Hanging down from the shoulder: the torso's x axis points up.
        rest: degrees(-175),
        joint: Some(joint as usize),
        color: 1,
        children,
    }
}

const HEAD: [Part; 1] = [Part {
    name: "head",
    shape: Shape::Circle { radius: r(0, 60) },
    attach: (r(0, 40), Real::ZERO),
    rest: Real::ZERO,
    joint: None,
    color: 2,
    children: &[],
}];

const UPPER_BODY: [Part; 3] = [
    Part {
        name: "neck",
        shape: line(r(0, 40)),
        attach: (r(3, 0), Real::ZERO),
        rest: Real::ZERO,
        joint: Some(Joint::Neck as usize),
        color: 0,
        children: &HEAD,
    },
    upper_arm(Joint::LeftShoulder, "left upper arm", &LEFT_FOREARM),
    upper_arm(Joint::RightShoulder, "right upper arm", &RIGHT_FOREARM),
];

const fn foot(joint: Joint, name: &'static str) -> Part {
    Part {
        name,
        shape: line(r(0, 60)),
        attach: (r(1, 80), Real::ZERO),
        // At a right angle to the shin, pointing forward (+x).
        rest: degrees(90),
        joint: Some(joint as usize),
        color: 3,
        children: &[],
    }
}

const LEFT_FOOT: [Part; 1] = [foot(Joint::LeftAnkle, "left foot")];
const RIGHT_FOOT: [Part; 1] = [foot(Joint::RightAnkle, "right foot")];

const fn shin(joint: Joint, name: &'static str, children: &'static [Part]) -> Part {
    Part {
        name,
        shape: line(r(1, 80)),
        attach: (r(1, 80), Real::ZERO),
        rest: Real::ZERO,
        joint: Some(joint as usize),
        color: 3,
        children,
    }
}

const LEFT_SHIN: [Part; 1] = [shin(Joint::LeftKnee, "left shin", &LEFT_FOOT)];
const RIGHT_SHIN: [Part; 1] = [shin(Joint::RightKnee, "right shin", &RIGHT_FOOT)];

const fn thigh(joint: Joint, name: &'static str, side: Real, children: &'static [Part]) -> Part {
    Part {
        name,
        shape: line(r(1, 80)),
        attach: (Real::ZERO, side),
        rest: degrees(180),
        joint: Some(joint as usize),
        color: 3,
        children,
    }
}

const LOWER_AND_UPPER: [Part; 3] = [
    Part {
        name: "torso",
        shape: Shape::Box {
            length: r(3, 0),
            width: r(1, 0),
        },
        attach: (r(0, 30), Real::ZERO),
        rest: Real::ZERO,
        joint: Some(Joint::Waist as usize),
        color: 0,
        children: &UPPER_BODY,
    },
    thigh(Joint::LeftHip, "left thigh", r(0, 25), &LEFT_SHIN),
    thigh(
        Joint::RightHip,
        "right thigh",
        Real::from_bits(-(1 << 30)),
        &RIGHT_SHIN,
    ),
];

/// The body, standing on its feet, facing +x (y up).
pub static BODY: Part = Part {
    name: "hips",
    shape: Shape::Box {
        length: r(0, 30),
        width: r(0, 80),
    },
    attach: (Real::ZERO, Real::ZERO),
    rest: degrees(90),
    joint: None,
    color: 0,
    children: &LOWER_AND_UPPER,
};

/// `amplitude · sin(phase)` for a phase in turns.
fn swing(amplitude: i32, phase: Real) -> Real {
    let turns = phase.to_bits().rem_euclid(1 << 32);
    let (_, sin) = BinaryAngle(u32::try_from(turns).unwrap_or(0)).cos_sin();
    Real::from_bits(i64::from(amplitude) * (i64::from(sin) << 2))
}

fn set(pose: &mut Pose, joint: Joint, angle: Real) {
    if let Some(slot) = pose.angles.get_mut(joint as usize) {
        *slot = angle;
    }
}

/// The walk cycle at `time` (in cycles: 0 to 1 is one stride of each leg): legs swing
/// ±25° in opposition, knees bend on the way forward, arms swing against the legs.
pub fn walk(time: Real) -> Pose {
    let mut pose = Pose::default();
    let half = Real::from_bits(1 << 31);
    let other = time.saturating_add(half);
    set(&mut pose, Joint::LeftHip, swing(25, time));
    set(&mut pose, Joint::RightHip, swing(25, other));
    // A knee bends back (negative) while its leg comes forward.
    let quarter = Real::from_bits(1 << 30);
    let bend = |phase: Real| {
        let s = swing(35, phase.saturating_add(quarter));
        Real::ZERO.saturating_sub(s.max(Real::ZERO))
    };
    set(&mut pose, Joint::LeftKnee, bend(time));
    set(&mut pose, Joint::RightKnee, bend(other));
    set(&mut pose, Joint::LeftShoulder, swing(20, other));
    set(&mut pose, Joint::RightShoulder, swing(20, time));
    set(
        &mut pose,
        Joint::LeftElbow,
        swing(10, other).saturating_add(degrees(10)),
    );
    set(
        &mut pose,
        Joint::RightElbow,
        swing(10, time).saturating_add(degrees(10)),
    );
    set(&mut pose, Joint::Waist, degrees(-5));
    pose
}

/// A wave: the right arm raised, its forearm swinging ±30° with `time` (cycles).
pub fn wave(time: Real) -> Pose {
    let mut pose = Pose::default();
    set(&mut pose, Joint::RightShoulder, degrees(150));
    set(
        &mut pose,
        Joint::RightElbow,
        swing(30, time).saturating_add(degrees(20)),
    );
    pose
}
