//! A deterministic L-system as a careful fixed-point sketch draws it.

use embedded_graphics::primitives::{Line, PrimitiveStyle};
use embedded_graphics::{pixelcolor::Gray4, prelude::*};

use super::bounds::FixedBounds;
use super::shared::{expand, NAIVE_STRING, NAIVE_TURTLE_STACK};
use super::sine::{cos_q16, sin_q16, Turns};

/// The most headings the careful turtle keeps (a turn of 360/64 degrees).
pub const MAX_DIVISIONS: u32 = 64;

/// An L-system as a careful sketch draws it, Fractint's way: a Q16.16 turtle.
///
/// The string expanded as [`lsystem_f32`] expands it, then walked twice by a turtle whose
/// heading is one of `divisions` directions (a turn of 360/`divisions` degrees).
/// Each direction's unit step is found once from the sine table (Q16), so a step is two
/// additions and a turn an index's increment; the box and the fit are in Q16.16 with one
/// 64-bit division an axis. Returns the lines drawn, or 0 if the string outgrows
/// [`NAIVE_STRING`] or `divisions` is 0 or above [`MAX_DIVISIONS`].
///
/// [`lsystem_f32`]: super::lsystem_f32
pub fn lsystem_fixed<D: DrawTarget<Color = Gray4>>(
    (axiom, rules, draw_symbols): (&str, &[(char, &str)], &str),
    divisions: u32,
    order: u32,
    up: bool,
    target: &mut D,
) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    if !(1..=MAX_DIVISIONS).contains(&divisions) {
        return 0;
    }
    let mut buffer = [0u8; NAIVE_STRING];
    let Some(length) = expand(&mut buffer, axiom, rules, order) else {
        return 0;
    };
    let string = &buffer[..length];
    let start: Turns = if up { 1 << 30 } else { 0 };
    let mut steps = [(0i32, 0i32); MAX_DIVISIONS as usize];
    for (k, step) in steps.iter_mut().take(divisions as usize).enumerate() {
        let angle = start.wrapping_add(((k as u64) << 32).div_euclid(u64::from(divisions)) as u32);
        *step = (cos_q16(angle), sin_q16(angle));
    }
    let last = divisions as usize - 1;
    let draws = |s: u8| s == b'F' || draw_symbols.as_bytes().contains(&s);
    // Walks the string, calling `line` with each drawn line's ends in Q16.16 units.
    let walk = |line: &mut dyn FnMut((i32, i32), (i32, i32))| {
        let (mut x, mut y, mut heading) = (0i32, 0i32, 0usize);
        let mut stack = [(0i32, 0i32, 0usize); NAIVE_TURTLE_STACK];
        let mut depth = 0;
        for &symbol in string {
            match symbol {
                b'+' => heading = if heading == last { 0 } else { heading + 1 },
                b'-' => heading = if heading == 0 { last } else { heading - 1 },
                b'[' if depth < NAIVE_TURTLE_STACK => {
                    stack[depth] = (x, y, heading);
                    depth += 1;
                }
                b']' if depth > 0 => {
                    depth -= 1;
                    (x, y, heading) = stack[depth];
                }
                b'f' => {
                    x += steps[heading].0;
                    y += steps[heading].1;
                }
                s if draws(s) => {
                    let (nx, ny) = (x + steps[heading].0, y + steps[heading].1);
                    line((x, y), (nx, ny));
                    (x, y) = (nx, ny);
                }
                _ => {}
            }
        }
    };
    let mut bounds = FixedBounds::new();
    walk(&mut |a, b| bounds.add([a, b]));
    let (_, pixel) = bounds.fitted(target.bounding_box().size);
    let mut drawn = 0;
    walk(&mut |a, b| {
        let _ = Line::new(pixel(a), pixel(b))
            .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, 1))
            .draw(target);
        drawn += 1;
    });
    drawn
}

/// How many headings a turn of `angle` divides the circle into, if a whole number up to
/// [`MAX_DIVISIONS`]: the careful turtle's directions.
pub fn turn_divisions(angle: tinyfractal::Angle) -> Option<u32> {
    let divisions = match angle {
        tinyfractal::Angle::Divisions(n) => u32::from(n),
        tinyfractal::Angle::Degrees(d) => {
            let n = 360.0 / d.to_f64();
            let whole = n as u32;
            if f64::from(whole) != n {
                return None;
            }
            whole
        }
    };
    (1..=MAX_DIVISIONS)
        .contains(&divisions)
        .then_some(divisions)
}
