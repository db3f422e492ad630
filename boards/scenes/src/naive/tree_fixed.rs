//! ABOP's monopodial tree as a careful fixed-point sketch grows and draws it: the
//! parameters in Q16.16 in the string, a Q16 3D turtle.
//!
//! The string is the float sketch's, each parameter an `i32` in Q16.16 where that one
//! keeps an `f32`; the turtle's vectors are Q16 and turn by the sine table's values at
//! each turn (no renormalising, as the float sketch); `$` finds its root with an integer
//! square root. The picture is the float sketch's: isometric, fitted in Q16.16.

use embedded_graphics::primitives::{Line, PrimitiveStyle};
use embedded_graphics::{pixelcolor::Gray4, prelude::*};

use super::bounds::FixedBounds;
use super::shared::{mul_q16, q16};
use super::sine::{cos_q16, sin_q16, turns_of_degrees};
use super::tree::{arity, expand, NAIVE_TREE_STRING};

/// The tree's constants in Q16.16 (`define:` lines of `data/abop.lsys`).
const R1: i32 = q16(0.9);
const R2: i32 = q16(0.6);
const A0: i32 = q16(45.0);
const A2: i32 = q16(45.0);
const D: i32 = q16(137.5);
const WR: i32 = q16(0.707);

/// Deepest `[` nesting the turtle keeps.
const TREE_STACK: usize = 16;

/// Writes a module at `at`; returns where the next one goes.
fn put(buffer: &mut [u8], at: usize, symbol: u8, parameters: &[i32]) -> usize {
    buffer[at] = symbol;
    let mut at = at + 1;
    for p in parameters {
        buffer[at..at + 4].copy_from_slice(&p.to_le_bytes());
        at += 4;
    }
    at
}

/// The Q16.16 parameter at `at`.
fn get(buffer: &[u8], at: usize) -> i32 {
    i32::from_le_bytes([buffer[at], buffer[at + 1], buffer[at + 2], buffer[at + 3]])
}

/// Writes the production of `symbol`(`l`, `w`) at `at`, as the float sketch's
/// productions; returns where the next module goes.
fn produce(buffer: &mut [u8], at: usize, symbol: u8, l: i32, w: i32) -> usize {
    let mut at = put(buffer, at, b'!', &[w]);
    at = put(buffer, at, b'F', &[l]);
    at = put(buffer, at, b'[', &[]);
    let (short, long, narrow) = (mul_q16(l, R2), mul_q16(l, R1), mul_q16(w, WR));
    if symbol == b'A' {
        at = put(buffer, at, b'&', &[A0]);
        at = put(buffer, at, b'B', &[short, narrow]);
        at = put(buffer, at, b']', &[]);
        at = put(buffer, at, b'/', &[D]);
        put(buffer, at, b'A', &[long, narrow])
    } else {
        let (turn, next) = if symbol == b'B' {
            (b'-', b'C')
        } else {
            (b'+', b'B')
        };
        at = put(buffer, at, turn, &[A2]);
        at = put(buffer, at, b'$', &[]);
        at = put(buffer, at, next, &[short, narrow]);
        at = put(buffer, at, b']', &[]);
        put(buffer, at, next, &[long, narrow])
    }
}

/// The turtle: position, heading, left, up (Q16), width (Q16.16).
#[derive(Clone, Copy)]
struct Turtle {
    p: [i32; 3],
    h: [i32; 3],
    l: [i32; 3],
    u: [i32; 3],
    width: i32,
}

/// `a` turned towards `b` by `degrees` (Q16.16) in their plane.
fn rotate(a: &mut [i32; 3], b: &mut [i32; 3], degrees: i32) {
    let angle = turns_of_degrees(degrees);
    let (sin, cos) = (sin_q16(angle), cos_q16(angle));
    for k in 0..3 {
        let (x, y) = (a[k], b[k]);
        a[k] = mul_q16(x, cos) + mul_q16(y, sin);
        b[k] = mul_q16(y, cos) - mul_q16(x, sin);
    }
}

fn cross(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    let det = |p: i32, q: i32, r: i32, s: i32| {
        ((i64::from(p) * i64::from(q) - i64::from(r) * i64::from(s)) >> 16) as i32
    };
    [
        det(a[1], b[2], a[2], b[1]),
        det(a[2], b[0], a[0], b[2]),
        det(a[0], b[1], a[1], b[0]),
    ]
}

/// ⌊√n⌋, a bit at a time.
fn isqrt(n: u64) -> u64 {
    let (mut root, mut rest, mut bit) = (0u64, n, 1u64 << 62);
    while bit > n {
        bit >>= 2;
    }
    while bit != 0 {
        if rest >= root + bit {
            rest -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    root
}

/// The isometric view of a point (y up the picture), Q16.16.
fn seen(p: [i32; 3]) -> (i32, i32) {
    (
        mul_q16(p[0] - p[2], q16(core::f32::consts::FRAC_1_SQRT_2)),
        mul_q16(2 * p[1] - p[0] - p[2], q16(0.408_248_3)),
    )
}

/// Walks the string, calling `line` with each `F`'s ends (seen) and width.
fn walk(string: &[u8], line: &mut dyn FnMut((i32, i32), (i32, i32), i32)) {
    const ONE: i32 = 1 << 16;
    let mut turtle = Turtle {
        p: [0; 3],
        h: [0, ONE, 0],
        l: [-ONE, 0, 0],
        u: [0, 0, ONE],
        width: ONE,
    };
    let mut stack = [turtle; TREE_STACK];
    let mut depth = 0;
    let mut at = 0;
    while at < string.len() {
        let symbol = string[at];
        let p = if arity(symbol) > 0 {
            get(string, at + 1)
        } else {
            0
        };
        at += 1 + 4 * arity(symbol);
        let t = &mut turtle;
        match symbol {
            b'F' => {
                let next = [
                    t.p[0] + mul_q16(p, t.h[0]),
                    t.p[1] + mul_q16(p, t.h[1]),
                    t.p[2] + mul_q16(p, t.h[2]),
                ];
                line(seen(t.p), seen(next), t.width);
                t.p = next;
            }
            b'!' => t.width = p,
            b'+' => rotate(&mut t.h, &mut t.l, p),
            b'-' => rotate(&mut t.h, &mut t.l, -p),
            b'&' => rotate(&mut t.h, &mut t.u, -p),
            b'^' => rotate(&mut t.h, &mut t.u, p),
            b'\\' => rotate(&mut t.l, &mut t.u, p),
            b'/' => rotate(&mut t.l, &mut t.u, -p),
            b'$' => {
                // Left = up-the-world × heading, normalised: (h.z, 0, −h.x)/|…|.
                let v = [t.h[2], 0, -t.h[0]];
                let squares = i64::from(v[0]).pow(2) + i64::from(v[2]).pow(2);
                let length = isqrt(squares as u64) as i64;
                if length > 0 {
                    let unit = |c: i32| ((i64::from(c) << 16) / length) as i32;
                    t.l = [unit(v[0]), 0, unit(v[2])];
                    t.u = cross(t.h, t.l);
                }
            }
            b'[' if depth < TREE_STACK => {
                stack[depth] = *t;
                depth += 1;
            }
            b']' if depth > 0 => {
                depth -= 1;
                *t = stack[depth];
            }
            _ => {}
        }
    }
}

/// The monopodial tree from `A(1, 0.1)` at `order`, as a careful sketch grows and draws
/// it: [`monopodial_tree_f32`]'s string and turtle in Q16.16.
///
/// White on black. Returns the lines drawn, or 0 if the string outgrows
/// [`NAIVE_TREE_STRING`].
///
/// [`monopodial_tree_f32`]: super::monopodial_tree_f32
pub fn monopodial_tree_fixed<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let mut buffer = [0u8; NAIVE_TREE_STRING];
    let length = put(&mut buffer, 0, b'A', &[1 << 16, q16(0.1)]);
    let Some(length) = expand(&mut buffer, length, order, |buffer, read, write| {
        let (l, w) = (get(buffer, read + 1), get(buffer, read + 5));
        produce(buffer, write, buffer[read], l, w)
    }) else {
        return 0;
    };
    let string = &buffer[..length];
    let mut bounds = FixedBounds::new();
    walk(string, &mut |a, b, _| bounds.add([a, b]));
    let (scale, pixel) = bounds.fitted(target.bounding_box().size);
    let mut drawn = 0;
    walk(string, &mut |a, b, width| {
        let pixels = (i64::from(width) * scale) >> 16;
        let stroke = if pixels >= 3 << 15 {
            ((pixels + (1 << 15)) >> 16) as u32
        } else {
            1
        };
        let _ = Line::new(pixel(a), pixel(b))
            .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, stroke))
            .draw(target);
        drawn += 1;
    });
    drawn
}
