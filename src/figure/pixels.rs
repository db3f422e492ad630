//! The figure walked in its pixels' fixed point: each part's map a Q2.30 matrix and a
//! Q16.16 translation, so that placing a part costs a table sine and eight 32×32→64
//! products, and a corner four, with no projection after (the `Real` walk's maps take
//! 128-bit products; docs/performance.md, The figure against the sketch).
//!
//! The fit's scale s (pixels a unit) is split as s = s′·2ᵏ with s′ in [½, 1): the matrices
//! hold s′ times a rotation (entries below 1, rotations keep them so), and a part's
//! lengths are read in units of 2⁻ᵏ (about pixels) as Q16.16 by a shift of their bits.
//! Every map is a rigid motion of the fitted plane, so a circle stays a circle of radius
//! r·s.

use super::part::{walk_parts, Part, Pose, Shape, CIRCLE, CIRCLE_SIDES};
use crate::error::{Error, MAX_PART_PIXELS};
use crate::math::real::round_half_away;
use crate::math::trig::BinaryAngle;
use crate::math::wide::mul_i32_wide;
use crate::math::Real;
use crate::render::circle::drawn_as_circle;

/// A point in Q16.16: pixels on the target (pixel (x, y) centred on (x, y)), or the fit's
/// provisional plane.
pub(crate) type Fixed = (i64, i64);

/// A part's outline where the walk put it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Outline<'a> {
    /// The points a line goes through, closed back to the first (a box, a circle too
    /// large for the circle rasteriser) or not (a line).
    Path {
        /// The points, in order.
        points: &'a [Fixed],
        /// Whether the outline closes.
        closed: bool,
    },
    /// A circle: its centre and radius.
    Circle {
        /// The centre.
        centre: Fixed,
        /// The radius (Q16.16, not negative).
        radius: i64,
    },
}

/// A part's outline and its colour index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Traced<'a> {
    /// Where the walk put it.
    pub(crate) outline: Outline<'a>,
    /// The part's colour index.
    pub(crate) color: u8,
}

impl Outline<'_> {
    /// The lines and circles it draws.
    pub(crate) fn drawn(&self) -> u64 {
        match *self {
            Self::Path { points, closed } => points.len() as u64 - u64::from(!closed),
            Self::Circle { .. } => 1,
        }
    }
}

/// One part's map: (X, Y) = (e, f) + M·(x, y), M in Q2.30 (s′ times a rotation, the y
/// axis flipped for the target), e and f Q16.16, the part's own (x, y) Q16.16 in units
/// of 2⁻ᵏ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct PixelMap {
    a: i32,
    b: i32,
    c: i32,
    d: i32,
    e: i64,
    f: i64,
}

/// Q2.30 × Q2.30 + Q2.30 × Q2.30, rounded to Q2.30.
#[inline(always)]
fn turned(p: i32, cos: i32, q: i32, sin: i32) -> i32 {
    let sum = mul_i32_wide(p, cos) + mul_i32_wide(q, sin);
    // |p|, |q| ≤ s′ < 1 and cos² + sin² = 1: the result stays below 2 in Q2.30.
    ((sum + (1 << 29)) >> 30) as i32
}

impl PixelMap {
    /// (X, Y) = origin + s′·(x, ±y): `flip` turns the y axis down, as a target's is.
    const fn scaled(scale_q30: i32, origin: Fixed, flip: bool) -> Self {
        Self {
            a: scale_q30,
            b: 0,
            c: 0,
            d: if flip { -scale_q30 } else { scale_q30 },
            e: origin.0,
            f: origin.1,
        }
    }

    /// The map's image of a part's point.
    #[inline(always)]
    fn apply(&self, (x, y): (i32, i32)) -> Fixed {
        let along = |p: i32, q: i32| (mul_i32_wide(p, x) + mul_i32_wide(q, y)) >> 30;
        (
            self.e + along(self.a, self.b),
            self.f + along(self.c, self.d),
        )
    }

    /// The map of a child attached at `attach` and turned by `angle`.
    fn child(&self, attach: (i32, i32), angle: BinaryAngle) -> Self {
        let (e, f) = self.apply(attach);
        let (cos, sin) = angle.cos_sin();
        Self {
            a: turned(self.a, cos, self.b, sin),
            b: turned(self.b, cos, self.a, -sin),
            c: turned(self.c, cos, self.d, sin),
            d: turned(self.d, cos, self.c, -sin),
            e,
            f,
        }
    }
}

/// The walk's arithmetic for one fit: the root map and how a part's lengths are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct PixelWalk {
    root: PixelMap,
    /// s′ in Q2.30: a circle's radius in the map's pixels is r·s′.
    scale_q30: i32,
    /// A length's `Real` bits shifted right by this (left if negative) are Q16.16 in the
    /// walk's units.
    shift: i32,
}

/// A `Real` read as Q16.16 after a shift right by `shift` (left if negative), rounded;
/// `None` if it does not fit 32 bits.
fn scaled_bits(value: Real, shift: i32) -> Option<i32> {
    let bits = value.to_bits();
    let q16 = if shift > 0 {
        let half = 1i64.checked_shl(shift as u32 - 1)?;
        bits.checked_add(half)? >> shift.min(63)
    } else {
        let up = shift.unsigned_abs();
        let moved = bits.checked_shl(up)?;
        (moved >> up == bits).then_some(moved)?
    };
    i32::try_from(q16).ok()
}

/// The top bit's index of a positive number's bits, 0 for 0.
fn top_bit(bits: u64) -> i32 {
    63 - bits.max(1).leading_zeros() as i32
}

impl PixelWalk {
    /// The walk for a fit of `scale` pixels a unit with the unit plane's origin at
    /// `origin` (pixels, y down); `None` if the scale is not positive or a length of
    /// `root`'s parts reaches [`MAX_PART_PIXELS`] on the target.
    pub(crate) fn fitted(root: &'static Part, scale: Real, origin: (Real, Real)) -> Option<Self> {
        let bits = u64::try_from(scale.to_bits()).ok().filter(|&b| b > 0)?;
        // s = S / 2³² with S's top bit at p; s′ = S / 2^(p+1) in [½, 1) and a unit is
        // 2^(p−31) of the walk's units: Q16.16 of those is the Real bits >> (47 − p).
        let p = top_bit(bits);
        let scale_q30 = i32::try_from(if p >= 29 {
            bits >> (p - 29)
        } else {
            bits << (29 - p)
        })
        .ok()?;
        let origin = (q16_of(origin.0), q16_of(origin.1));
        let walk = Self {
            root: PixelMap::scaled(scale_q30, origin, true),
            scale_q30,
            shift: 47 - p,
        };
        walk.reads(root).then_some(walk)
    }

    /// A walk for measuring: unflipped, with its origin at 0, its unit chosen so that the
    /// longest length of `root`'s parts is about 2¹⁰ (so a figure nested
    /// [`MAX_FIGURE_DEPTH`] deep stays within 2¹⁴), and the factor that takes its Q16.16
    /// coordinates back to `Real` bits (a shift left by it, right if negative).
    ///
    /// [`MAX_FIGURE_DEPTH`]: super::part::MAX_FIGURE_DEPTH
    pub(crate) fn measuring(root: &'static Part) -> (Self, i32) {
        let longest = longest_length(root);
        // The longest length's bits L have their top bit at q; L >> (q − 26) is about
        // 2²⁶, which is 2¹⁰ in Q16.16: shift = q − 26 = 47 − p for p = 73 − q.
        let shift = top_bit(longest) - 26;
        let scale_q30 = 1 << 29;
        let walk = Self {
            root: PixelMap::scaled(scale_q30, (0, 0), false),
            scale_q30,
            shift,
        };
        // A coordinate X (Q16.16) is s′·u′ for s′ = ½ and u′ (Q16.16) the Real bits
        // >> shift: the Real bits are X << (shift + 1).
        (walk, shift + 1)
    }

    /// Whether every length of `root`'s parts reads in 32 bits and is shorter than
    /// [`MAX_PART_PIXELS`] on the target.
    fn reads(&self, root: &'static Part) -> bool {
        let mut fits = true;
        let most = i64::from(MAX_PART_PIXELS) << 16;
        for_each_part(root, |part| {
            fits &= lengths(part.shape, part.attach).iter().all(|&v| {
                scaled_bits(v, self.shift).is_some_and(|q16| {
                    (i64::from(q16).abs() * i64::from(self.scale_q30)) >> 30 < most
                })
            });
        });
        fits
    }

    /// Reads a length of the figure it was made for (every one checked to fit by
    /// [`reads`](Self::reads)), rounded.
    #[inline(always)]
    fn read(&self, value: Real) -> i32 {
        let bits = value.to_bits();
        // `shift` is 47 − p for p in [0, 62]: a shift right by at most 47, or left by at most
        // 15 of a value the check found to fit.
        if self.shift > 0 {
            (((bits >> (self.shift - 1)) + 1) >> 1) as i32
        } else {
            (bits << self.shift.unsigned_abs()) as i32
        }
    }

    /// Every part of `root` in `pose`, depth first, as `visit` sees its outline with the
    /// part's colour. The walk holds a map a level: deeper than [`MAX_FIGURE_DEPTH`] is
    /// [`WalkError::StackTooDeep`].
    ///
    /// [`MAX_FIGURE_DEPTH`]: super::part::MAX_FIGURE_DEPTH
    /// [`WalkError::StackTooDeep`]: crate::error::WalkError::StackTooDeep
    pub(crate) fn walk(
        &self,
        root: &'static Part,
        pose: &Pose,
        mut visit: impl FnMut(Traced<'_>),
    ) -> Result<(), Error> {
        let mut points = [(0, 0); CIRCLE_SIDES];
        walk_parts(
            root,
            &self.root,
            |part, parent| Ok(self.place(part, parent, pose)),
            |part, map| {
                visit(self.trace(part, map, &mut points));
                Ok(())
            },
        )
    }

    /// The map of `part` on `parent` in `pose`. Out of line: one copy for every walk.
    #[inline(never)]
    fn place(&self, part: &Part, parent: &PixelMap, pose: &Pose) -> PixelMap {
        let attach = (self.read(part.attach.0), self.read(part.attach.1));
        parent.child(attach, joint_angle(part, pose))
    }

    /// A part's outline under `map`, its points written into `points`: a circle as a
    /// circle, or as its 16 corners if too large for the circle rasteriser. Out of line:
    /// one copy for every walk.
    #[inline(never)]
    fn trace<'p>(
        &self,
        part: &Part,
        map: &PixelMap,
        points: &'p mut [Fixed; CIRCLE_SIDES],
    ) -> Traced<'p> {
        let (count, closed) = match part.shape {
            Shape::Line { length } => {
                points[0] = map.apply((0, 0));
                points[1] = map.apply((self.read(length), 0));
                (2, false)
            }
            Shape::Box { length, width } => {
                let (length, half) = (self.read(length), self.read(width) / 2);
                points[0] = map.apply((0, -half));
                points[1] = map.apply((length, -half));
                points[2] = map.apply((length, half));
                points[3] = map.apply((0, half));
                (4, true)
            }
            Shape::Circle { radius } => {
                // Corner k is the centre plus cos_k times the map's image of (r, 0) and
                // sin_k times its image of (0, r), in Q16.16 pixels.
                let radius = self.read(radius);
                let (cx, cy) = map.apply((radius, 0));
                let scaled = (mul_i32_wide(radius, self.scale_q30) >> 30).abs();
                if drawn_as_circle(scaled) {
                    return Traced {
                        outline: Outline::Circle {
                            centre: (cx, cy),
                            radius: scaled,
                        },
                        color: part.color,
                    };
                }
                let image = |p: i32| (mul_i32_wide(p, radius) >> 30) as i32;
                let (ux, uy, vx, vy) = (image(map.a), image(map.c), image(map.b), image(map.d));
                for (point, &(cos, sin)) in points.iter_mut().zip(CIRCLE.iter()) {
                    let along =
                        |u: i32, v: i32| (mul_i32_wide(cos, u) + mul_i32_wide(sin, v)) >> 30;
                    *point = (cx + along(ux, vx), cy + along(uy, vy));
                }
                (CIRCLE_SIDES, true)
            }
        };
        Traced {
            outline: Outline::Path {
                points: points.get(..count).unwrap_or(&[]),
                closed,
            },
            color: part.color,
        }
    }
}

/// A part's angle to its parent: its rest angle plus its joint's, as a binary angle. An
/// angle under 2¹⁵ degrees (any pose's) is read in Q16.16 and turned by one product;
/// larger ones go through the exact division.
#[inline(always)]
fn joint_angle(part: &Part, pose: &Pose) -> BinaryAngle {
    // 2³² / 360, rounded: a degree in binary-angle units.
    const UNITS_PER_DEGREE: i64 = 11_930_465;
    let turn = part
        .joint
        .and_then(|j| pose.angles.get(j).copied())
        .unwrap_or(Real::ZERO);
    let degrees = part.rest.saturating_add(turn).to_bits();
    // Under 2¹⁵ degrees either way: Q16.16 (rounded) in 32 bits.
    let q16 = (degrees >> 47 == degrees >> 63).then(|| (((degrees >> 15) + 1) >> 1) as i32);
    match q16 {
        // Q16.16 degrees × 2³²/360 is Q16 binary-angle units; wrapping to u32 reduces
        // modulo a turn.
        Some(q16) => BinaryAngle(((i64::from(q16) * UNITS_PER_DEGREE) >> 16) as u32),
        None => BinaryAngle::from_degrees_bits(degrees),
    }
}

/// The lengths a part's shape and attachment are made of.
fn lengths(shape: Shape, attach: (Real, Real)) -> [Real; 4] {
    let (first, second) = match shape {
        Shape::Line { length } => (length, Real::ZERO),
        Shape::Box { length, width } => (length, width),
        Shape::Circle { radius } => (radius, Real::ZERO),
    };
    [first, second, attach.0, attach.1]
}

/// The largest magnitude of any length of `root`'s parts, as `Real` bits.
fn longest_length(root: &'static Part) -> u64 {
    let mut longest = 0;
    for_each_part(root, |part| {
        for v in lengths(part.shape, part.attach) {
            longest = longest.max(v.to_bits().unsigned_abs());
        }
    });
    longest
}

/// Every part of `root`, depth first, at most [`MAX_FIGURE_DEPTH`] deep (deeper parts are
/// left out: the walks themselves report them).
///
/// [`MAX_FIGURE_DEPTH`]: super::part::MAX_FIGURE_DEPTH
fn for_each_part(root: &'static Part, mut visit: impl FnMut(&'static Part)) {
    let _ = walk_parts(
        root,
        &(),
        |_, _| Ok(()),
        |part, _| {
            visit(part);
            Ok(())
        },
    );
}

/// A Q16.16 coordinate rounded to a pixel, halves away from zero (as `Real` rounds).
#[inline(always)]
pub(crate) fn pixel(v: i64) -> i32 {
    round_half_away(v, 16)
}

/// A `Real` as Q16.16, rounded (half up).
pub(crate) fn q16_of(v: Real) -> i64 {
    (v.to_bits() >> 15).wrapping_add(1) >> 1
}
