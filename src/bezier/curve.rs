//! A quadratic or cubic Bézier curve and its flattening: de Casteljau's halving until each
//! piece lies within a quarter of a pixel of its chord.

use embedded_graphics::prelude::*;

use crate::math::wide::{mul_i64_by_small, square_i32_wide};
use crate::render::subpixel::SUBPIXEL_BITS;

/// How far a flattened piece may stray from its chord: a quarter of a pixel, in
/// sub-pixel units (2⁻¹⁶ of a pixel).
pub const TOLERANCE_SUBPIXELS: i64 = 1 << (SUBPIXEL_BITS - 2);

/// The deepest halving: a curve whose control points are anywhere within `i32` is flat
/// to the tolerance by then (its control polygon's bend shrinks four times a halving).
pub const MAX_DEPTH: usize = 20;

/// A control point in sub-pixel units.
type Sub = [i64; 2];

/// A Bézier curve: three control points (quadratic) or four (cubic), in the target's pixel
/// coordinates. The curve starts at the first and ends at the last.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bezier {
    points: [Point; 4],
    cubic: bool,
}

impl Bezier {
    /// The quadratic curve of `points`.
    pub const fn quadratic(points: [Point; 3]) -> Self {
        Self {
            points: [points[0], points[1], points[2], points[2]],
            cubic: false,
        }
    }

    /// The cubic curve of `points`.
    pub const fn cubic(points: [Point; 4]) -> Self {
        Self {
            points,
            cubic: true,
        }
    }

    /// The control points (three or four).
    pub fn control_points(&self) -> &[Point] {
        let count = if self.cubic { 4 } else { 3 };
        self.points.get(..count).unwrap_or(&self.points)
    }

    /// True for a cubic curve.
    pub const fn is_cubic(&self) -> bool {
        self.cubic
    }

    /// The vertices of the flattened curve, in sub-pixel units (2^[`SUBPIXEL_BITS`] a
    /// pixel): the first control point, then the end of each piece, the last being the
    /// last control point exactly.
    ///
    /// [`SUBPIXEL_BITS`]: crate::render::SUBPIXEL_BITS
    pub fn flattened(&self) -> Flattened {
        let sub = |p: Point| {
            [
                i64::from(p.x) << SUBPIXEL_BITS,
                i64::from(p.y) << SUBPIXEL_BITS,
            ]
        };
        let piece = Piece {
            points: self.points.map(sub),
            depth: 0,
        };
        Flattened {
            stack: [piece; MAX_DEPTH + 1],
            len: 1,
            cubic: self.cubic,
            started: false,
        }
    }
}

/// A piece of a curve waiting to be flattened, and how many halvings made it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Piece {
    points: [Sub; 4],
    depth: usize,
}

/// The vertices of a flattened curve ([`Bezier::flattened`]), in order.
#[derive(Debug, Clone)]
pub struct Flattened {
    stack: [Piece; MAX_DEPTH + 1],
    len: usize,
    cubic: bool,
    started: bool,
}

/// True where every component of `values` is within ±2^limit.
fn small(values: &[i64], limit: u32) -> bool {
    values.iter().all(|v| v.unsigned_abs() < 1 << limit)
}

/// The flatness test: the curve stays within the tolerance of its chord. For a cubic, the
/// bound max(|u|², |v|²) over both axes / 16 with u = 3P₁ − 2P₀ − P₃ and
/// v = 3P₂ − P₀ − 2P₃ (Willcocks); for a quadratic |P₀ − 2P₁ + P₂|² / 16.
fn flat(points: &[Sub; 4], cubic: bool) -> bool {
    let limit = 16 * TOLERANCE_SUBPIXELS * TOLERANCE_SUBPIXELS;
    let [p0, p1, p2, p3] = *points;
    if cubic {
        let axis = |i: usize| -> (i64, i64) {
            let c = |p: Sub| p.get(i).copied().unwrap_or(0);
            // Three times a control point (a pixel coordinate's sub-pixels, within ±2⁴⁷):
            // on ARMv6-M three 32-bit products, where `3 *` an i64 is a library call.
            let thrice = |p: Sub| mul_i64_by_small(c(p), 3);
            (
                thrice(p1) - 2 * c(p0) - c(p3),
                thrice(p2) - c(p0) - 2 * c(p3),
            )
        };
        let ((ux, vx), (uy, vy)) = (axis(0), axis(1));
        // Beyond 2^24 sub-pixels a term alone exceeds the limit (and its square i64).
        small(&[ux, vx, uy, vy], 24)
            && square(ux).max(square(vx)) + square(uy).max(square(vy)) <= limit
    } else {
        let d = |i: usize| {
            let c = |p: Sub| p.get(i).copied().unwrap_or(0);
            c(p0) - 2 * c(p1) + c(p2)
        };
        let (dx, dy) = (d(0), d(1));
        small(&[dx, dy], 24) && square(dx) + square(dy) <= limit
    }
}

/// The square of a term within ±2²⁴ (so its `i32` is exact) by a 32-bit square: on
/// ARMv6-M from 16-bit halves, where an `i64` product is a library call.
fn square(term: i64) -> i64 {
    square_i32_wide(term as i32)
}

/// The midpoint of two points, rounded down.
fn mid(a: Sub, b: Sub) -> Sub {
    [(a[0] + b[0]) >> 1, (a[1] + b[1]) >> 1]
}

/// The two halves of a piece, at t = ½ (de Casteljau).
fn halves(points: &[Sub; 4], cubic: bool) -> ([Sub; 4], [Sub; 4]) {
    let [p0, p1, p2, p3] = *points;
    if cubic {
        let (m01, m12, m23) = (mid(p0, p1), mid(p1, p2), mid(p2, p3));
        let (m012, m123) = (mid(m01, m12), mid(m12, m23));
        let m = mid(m012, m123);
        ([p0, m01, m012, m], [m, m123, m23, p3])
    } else {
        let (m01, m12) = (mid(p0, p1), mid(p1, p2));
        let m = mid(m01, m12);
        ([p0, m01, m, m], [m, m12, p2, p2])
    }
}

impl Iterator for Flattened {
    type Item = (i64, i64);

    fn next(&mut self) -> Option<(i64, i64)> {
        if !self.started {
            self.started = true;
            let [x, y] = self.stack.first()?.points[0];
            return Some((x, y));
        }
        loop {
            self.len = self.len.checked_sub(1)?;
            let piece = *self.stack.get(self.len)?;
            if piece.depth >= MAX_DEPTH || flat(&piece.points, self.cubic) {
                // A piece ends at its last control point (a quadratic's third).
                let end = if self.cubic {
                    piece.points[3]
                } else {
                    piece.points[2]
                };
                return Some((end[0], end[1]));
            }
            let (left, right) = halves(&piece.points, self.cubic);
            let depth = piece.depth + 1;
            // The right half waits beneath the left: pieces come out in order.
            for half in [right, left] {
                if let Some(slot) = self.stack.get_mut(self.len) {
                    *slot = Piece {
                        points: half,
                        depth,
                    };
                    self.len += 1;
                }
            }
        }
    }
}
