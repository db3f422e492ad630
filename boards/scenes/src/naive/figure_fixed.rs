//! The walking figure as a careful fixed-point sketch draws it: a Q16.16 matrix stack.

use embedded_graphics::primitives::{Circle, Line, PrimitiveStyle};
use embedded_graphics::{pixelcolor::Gray4, prelude::*};

use super::shared::{mul_q16, q16};
use super::sine::{cos_q16, sin_q16, turns_of_degrees, Turns};

/// A 2D affine map in Q16.16, as [`figure_f32`]'s `Matrix` in fixed point: the linear
/// part in pixels a unit, the translation in pixels.
///
/// [`figure_f32`]: super::figure_f32
#[derive(Clone, Copy)]
struct Matrix([i32; 6]);

impl Matrix {
    /// This map after a move by `(x, y)` and a turn by `degrees` (all Q16.16).
    fn then(self, (x, y): (i32, i32), degrees: i32) -> Self {
        let [a, b, c, d, tx, ty] = self.0;
        let angle = turns_of_degrees(degrees);
        let (sin, cos) = (sin_q16(angle), cos_q16(angle));
        Self([
            mul_q16(a, cos) + mul_q16(b, sin),
            mul_q16(b, cos) - mul_q16(a, sin),
            mul_q16(c, cos) + mul_q16(d, sin),
            mul_q16(d, cos) - mul_q16(c, sin),
            mul_q16(a, x) + mul_q16(b, y) + tx,
            mul_q16(c, x) + mul_q16(d, y) + ty,
        ])
    }

    /// A point of the part's frame in pixels.
    fn pixel(&self, (x, y): (i32, i32)) -> Point {
        let [a, b, c, d, tx, ty] = self.0;
        Point::new(
            (mul_q16(a, x) + mul_q16(b, y) + tx) >> 16,
            (mul_q16(c, x) + mul_q16(d, y) + ty) >> 16,
        )
    }
}

/// The joints' angles at the cycle's `phase`, in Q16 degrees, as the float sketch's walk
/// has them.
fn walk_angles(phase: Turns) -> [i32; 8] {
    let swing = |amplitude: f32, phase: Turns| mul_q16(q16(amplitude), sin_q16(phase));
    let bend = |phase: Turns| -swing(35.0, phase.wrapping_add(1 << 30)).max(0);
    let other = phase.wrapping_add(1 << 31);
    [
        swing(25.0, phase),
        swing(25.0, other),
        bend(phase),
        bend(other),
        swing(20.0, other),
        swing(20.0, phase),
        swing(10.0, other) + q16(10.0),
        swing(10.0, phase) + q16(10.0),
    ]
}

/// A line from `from` to `to` in the part's frame (a sketch's `drawLine`).
fn bone<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    ends: [(i32, i32); 2],
    color: Gray4,
) -> u64 {
    let _ = Line::new(m.pixel(ends[0]), m.pixel(ends[1]))
        .into_styled(PrimitiveStyle::with_stroke(color, 1))
        .draw(target);
    1
}

/// A box `length` along and `width` across the part's x axis: four bones.
fn boxed<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    (length, width): (i32, i32),
    color: Gray4,
) -> u64 {
    let w = width / 2;
    let corners = [(0, -w), (length, -w), (length, w), (0, w)];
    (0..4)
        .map(|k| bone(target, m, [corners[k], corners[(k + 1) % 4]], color))
        .sum()
}

/// A circle of `radius` whose leftmost point is the part's origin (a sketch's
/// `drawCircle`).
fn round<D: DrawTarget<Color = Gray4>>(
    target: &mut D,
    m: &Matrix,
    radius: i32,
    scale: i32,
    color: Gray4,
) -> u64 {
    let diameter = (mul_q16(2 * radius, scale) >> 16) as u32;
    let _ = Circle::with_center(m.pixel((radius, 0)), diameter.max(1))
        .into_styled(PrimitiveStyle::with_stroke(color, 1))
        .draw(target);
    1
}

/// One pose of the figure by the Q16.16 matrix stack, every part in `color`. Returns the
/// lines and circles drawn.
fn pose<D: DrawTarget<Color = Gray4>>(target: &mut D, phase: Turns, color: Gray4) -> u64 {
    let [left_hip, right_hip, left_knee, right_knee, left_shoulder, right_shoulder, left_elbow, right_elbow] =
        walk_angles(phase);
    let size = target.bounding_box().size;
    let scale = ((size.height as i32) << 16) / 10;
    let root = Matrix([
        scale,
        0,
        0,
        -scale,
        (size.width as i32) << 15,
        mul_q16((size.height as i32) << 16, q16(0.45)),
    ]);
    let hips = root.then((0, 0), q16(90.0));
    let mut drawn = boxed(target, &hips, (q16(0.3), q16(0.8)), color);
    let torso = hips.then((q16(0.3), 0), q16(-5.0));
    drawn += boxed(target, &torso, (q16(3.0), q16(1.0)), color);
    let neck = torso.then((q16(3.0), 0), 0);
    drawn += bone(target, &neck, [(0, 0), (q16(0.4), 0)], color);
    drawn += round(target, &neck.then((q16(0.4), 0), 0), q16(0.6), scale, color);
    for (shoulder, elbow) in [(left_shoulder, left_elbow), (right_shoulder, right_elbow)] {
        let upper = torso.then((q16(2.8), 0), q16(-175.0) + shoulder);
        drawn += bone(target, &upper, [(0, 0), (q16(1.5), 0)], color);
        let fore = upper.then((q16(1.5), 0), q16(20.0) + elbow);
        drawn += bone(target, &fore, [(0, 0), (q16(1.3), 0)], color);
        drawn += round(target, &fore.then((q16(1.3), 0), 0), q16(0.2), scale, color);
    }
    for (side, hip, knee) in [
        (q16(0.25), left_hip, left_knee),
        (q16(-0.25), right_hip, right_knee),
    ] {
        let thigh = hips.then((0, side), q16(180.0) + hip);
        drawn += bone(target, &thigh, [(0, 0), (q16(1.8), 0)], color);
        let shin = thigh.then((q16(1.8), 0), knee);
        drawn += bone(target, &shin, [(0, 0), (q16(1.8), 0)], color);
        let foot = shin.then((q16(1.8), 0), q16(90.0));
        drawn += bone(target, &foot, [(0, 0), (q16(0.6), 0)], color);
    }
    drawn
}

/// The walking figure as a careful sketch draws it: [`figure_f32`]'s parts and walk by a
/// Q16.16 matrix stack, its angles binary angles read from the sine table.
///
/// `frames` frames of one walk cycle, each erasing the last by drawing it again in black.
/// Returns the lines and circles drawn (erasing not counted).
///
/// [`figure_f32`]: super::figure_f32
pub fn figure_fixed<D: DrawTarget<Color = Gray4>>(frames: u32, target: &mut D) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let mut drawn = 0;
    let mut last = None;
    for frame in 0..frames {
        // The cycle's share in binary angle: frame/frames of a turn.
        let phase = ((u64::from(frame) << 32) / u64::from(frames.max(1))) as Turns;
        if let Some(last) = last {
            pose(target, last, Gray4::BLACK);
        }
        drawn += pose(target, phase, Gray4::WHITE);
        last = Some(phase);
    }
    drawn
}
