//! ABOP's monopodial tree (figure 2.6) as a sketch grows and draws it, in `f32`: the
//! parametric string expanded in a byte buffer, then read twice by a float 3D turtle.
//!
//! A sketch hard-codes the three productions as code, keeps each module as its symbol's
//! byte followed by its parameters as `f32` (little-endian), and expands the string in
//! place, as [`lsystem_f32`](super::lsystem_f32) does: the current string moved to the
//! buffer's end, its expansion written from the start. The turtle keeps heading, left and
//! up as float vectors and turns them by `micromath`'s sine and cosine at each turn (ABOP
//! 1.5, the engine's axes: heading up the screen, left to −x, up towards the viewer), with
//! no renormalising; `$` rolls left to the horizontal with a square root. The picture is
//! the engine's default for a 3D system, the isometric view, fitted to the target less a
//! 2-pixel margin and centred; a line at least 1.5 pixels wide (its width times the scale)
//! is drawn that wide with embedded-graphics' `Line`, a narrower one a pixel wide.

use embedded_graphics::primitives::{Line, PrimitiveStyle};
use embedded_graphics::{pixelcolor::Gray4, prelude::*};
use micromath::F32Ext;

use super::bounds::Bounds;

/// The longest expanded string the sketch holds, in bytes (the tree at order 10 takes
/// 27,670: 7,162 modules and 5,127 parameters).
pub const NAIVE_TREE_STRING: usize = 28 * 1024;

/// The tree's constants (`define:` lines of `data/abop.lsys`).
const R1: f32 = 0.9;
const R2: f32 = 0.6;
const A0: f32 = 45.0;
const A2: f32 = 45.0;
const D: f32 = 137.5;
const WR: f32 = 0.707;

/// Deepest `[` nesting the turtle keeps (the tree at order 10 nests 10 deep).
const TREE_STACK: usize = 16;

/// Parameters a module of `symbol` carries.
pub(super) fn arity(symbol: u8) -> usize {
    match symbol {
        b'A' | b'B' | b'C' => 2,
        b'F' | b'!' | b'+' | b'-' | b'&' | b'^' | b'/' | b'\\' => 1,
        _ => 0,
    }
}

/// Bytes of the module `symbol` becomes (its production's, or itself).
fn grown(symbol: u8) -> usize {
    match symbol {
        b'A' => 40,
        b'B' | b'C' => 36,
        other => 1 + 4 * arity(other),
    }
}

/// Expands the string of `length` bytes at the buffer's start `order` times, in place, as
/// both tree sketches do; its new length, or `None` if it outgrows [`NAIVE_TREE_STRING`].
///
/// The string moves to the buffer's end and its expansion is written from the start: no
/// module shrinks, so the writer never passes the reader. `grow(buffer, read, write)`
/// writes the production of the `A`, `B` or `C` at `read` from `write` and returns where
/// the next module goes. Inlined into each sketch, so the `f32` one's code is what it was
/// when written out in it.
#[inline(always)]
pub(super) fn expand(
    buffer: &mut [u8; NAIVE_TREE_STRING],
    mut length: usize,
    order: u32,
    grow: impl Fn(&mut [u8], usize, usize) -> usize,
) -> Option<usize> {
    for _ in 0..order {
        let mut grown_length = 0;
        let mut at = 0;
        while at < length {
            grown_length += grown(buffer[at]);
            at += 1 + 4 * arity(buffer[at]);
        }
        if grown_length > NAIVE_TREE_STRING {
            return None;
        }
        buffer.copy_within(..length, NAIVE_TREE_STRING - length);
        let (mut read, mut write) = (NAIVE_TREE_STRING - length, 0);
        while read < NAIVE_TREE_STRING {
            let symbol = buffer[read];
            let size = 1 + 4 * arity(symbol);
            if matches!(symbol, b'A' | b'B' | b'C') {
                write = grow(buffer, read, write);
            } else {
                buffer.copy_within(read..read + size, write);
                write += size;
            }
            read += size;
        }
        length = grown_length;
    }
    Some(length)
}

/// Writes a module at `at`; returns where the next one goes.
fn put(buffer: &mut [u8], at: usize, symbol: u8, parameters: &[f32]) -> usize {
    buffer[at] = symbol;
    let mut at = at + 1;
    for p in parameters {
        buffer[at..at + 4].copy_from_slice(&p.to_le_bytes());
        at += 4;
    }
    at
}

/// The `f32` at `at`.
fn get(buffer: &[u8], at: usize) -> f32 {
    f32::from_le_bytes([buffer[at], buffer[at + 1], buffer[at + 2], buffer[at + 3]])
}

/// Writes the production of module `symbol`(`l`, `w`) at `at` (`A`, `B` or `C`); returns
/// where the next module goes.
fn produce(buffer: &mut [u8], at: usize, symbol: u8, l: f32, w: f32) -> usize {
    let mut at = put(buffer, at, b'!', &[w]);
    at = put(buffer, at, b'F', &[l]);
    at = put(buffer, at, b'[', &[]);
    match symbol {
        // A(l,w) --> !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
        b'A' => {
            at = put(buffer, at, b'&', &[A0]);
            at = put(buffer, at, b'B', &[l * R2, w * WR]);
            at = put(buffer, at, b']', &[]);
            at = put(buffer, at, b'/', &[D]);
            put(buffer, at, b'A', &[l * R1, w * WR])
        }
        // B(l,w) --> !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr), and C the mirror image.
        _ => {
            let (turn, next) = if symbol == b'B' {
                (b'-', b'C')
            } else {
                (b'+', b'B')
            };
            at = put(buffer, at, turn, &[A2]);
            at = put(buffer, at, b'$', &[]);
            at = put(buffer, at, next, &[l * R2, w * WR]);
            at = put(buffer, at, b']', &[]);
            put(buffer, at, next, &[l * R1, w * WR])
        }
    }
}

/// The turtle: position, heading, left, up, width.
#[derive(Clone, Copy)]
struct Turtle {
    p: [f32; 3],
    h: [f32; 3],
    l: [f32; 3],
    u: [f32; 3],
    width: f32,
}

/// `a` turned towards `b` by `degrees` in their plane: a′ = a·cos + b·sin, b′ = b·cos − a·sin.
fn rotate(a: &mut [f32; 3], b: &mut [f32; 3], degrees: f32) {
    let (sin, cos) = F32Ext::sin_cos(degrees.to_radians());
    for k in 0..3 {
        let (x, y) = (a[k], b[k]);
        a[k] = x * cos + y * sin;
        b[k] = y * cos - x * sin;
    }
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The isometric view of a point (y up the picture).
fn seen(p: [f32; 3]) -> (f32, f32) {
    (
        (p[0] - p[2]) * core::f32::consts::FRAC_1_SQRT_2,
        (2.0 * p[1] - p[0] - p[2]) * 0.408_248_3,
    )
}

/// Walks the string, calling `line` with each `F`'s ends (seen) and width.
fn walk(string: &[u8], line: &mut dyn FnMut((f32, f32), (f32, f32), f32)) {
    let mut turtle = Turtle {
        p: [0.0; 3],
        h: [0.0, 1.0, 0.0],
        l: [-1.0, 0.0, 0.0],
        u: [0.0, 0.0, 1.0],
        width: 1.0,
    };
    let mut stack = [turtle; TREE_STACK];
    let mut depth = 0;
    let mut at = 0;
    while at < string.len() {
        let symbol = string[at];
        let p = if arity(symbol) > 0 {
            get(string, at + 1)
        } else {
            0.0
        };
        at += 1 + 4 * arity(symbol);
        let t = &mut turtle;
        match symbol {
            b'F' => {
                let next = [
                    t.p[0] + p * t.h[0],
                    t.p[1] + p * t.h[1],
                    t.p[2] + p * t.h[2],
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
                let v = cross([0.0, 1.0, 0.0], t.h);
                let length = F32Ext::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                if length > 1e-6 {
                    t.l = [v[0] / length, v[1] / length, v[2] / length];
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

/// The monopodial tree from `A(1, 0.1)` at `order`, as a sketch grows and draws it.
///
/// White on black, as the module's notes say. Returns the lines drawn, or 0 if the string
/// outgrows [`NAIVE_TREE_STRING`].
pub fn monopodial_tree_f32<D: DrawTarget<Color = Gray4>>(order: u32, target: &mut D) -> u64 {
    let _ = target.clear(Gray4::BLACK);
    let mut buffer = [0u8; NAIVE_TREE_STRING];
    let length = put(&mut buffer, 0, b'A', &[1.0, 0.1]);
    let Some(length) = expand(&mut buffer, length, order, |buffer, read, write| {
        let (l, w) = (get(buffer, read + 1), get(buffer, read + 5));
        produce(buffer, write, buffer[read], l, w)
    }) else {
        return 0;
    };
    let string = &buffer[..length];
    let mut bounds = Bounds::new();
    walk(string, &mut |a, b, _| bounds.add([a, b]));
    let (scale, pixel) = bounds.fitted(target.bounding_box().size);
    let mut drawn = 0;
    walk(string, &mut |a, b, width| {
        let pixels = width * scale;
        let stroke = if pixels >= 1.5 {
            (pixels + 0.5) as u32
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
