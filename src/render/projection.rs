//! Projections of space (x right, y up, z towards the viewer) onto the picture plane (x
//! right, y up), with a depth (larger is nearer) for depth-cued colour.

use crate::math::Real;

/// How a 3D picture is seen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Projection {
    /// From the front, along −z, without perspective: a system turned only by `+` and `-`
    /// looks as the 2D turtle draws it.
    Front,
    /// Isometric: from the direction (1, 1, 1), the three axes 120° apart on the picture.
    #[default]
    Isometric,
    /// The isometric view seen from a point at `distance` times the picture's radius from
    /// its middle, so nearer parts are larger (1.5 is strong, 10 mild).
    Perspective {
        /// The eye's distance from the picture's middle, in radii (at least 1.1).
        distance: Real,
    },
}

/// 1/√2 in Q30.
const INV_SQRT2: i32 = 759_250_125;
/// 1/√6 in Q30.
const INV_SQRT6: i32 = 438_353_264;
/// 1/√3 in Q30.
const INV_SQRT3: i32 = 619_925_131;

/// A point seen through a projection: picture coordinates and depth.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Seen {
    pub(crate) x: Real,
    pub(crate) y: Real,
    pub(crate) depth: Real,
}

fn add(a: Real, b: Real) -> Real {
    a.saturating_add(b)
}

/// The isometric picture coordinates and depth of `p`.
fn isometric([x, y, z]: [Real; 3]) -> Seen {
    let twice_y = add(y, y);
    Seen {
        x: x.saturating_sub(z).mul_q30(INV_SQRT2),
        y: twice_y.saturating_sub(add(x, z)).mul_q30(INV_SQRT6),
        depth: add(add(x, y), z).mul_q30(INV_SQRT3),
    }
}

/// Where the eye is, for a perspective view: the middle of the picture's isometric box and
/// the eye's distance from it, in picture units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Eye {
    pub(crate) middle: Seen,
    pub(crate) distance: Real,
}

impl Projection {
    /// `p` projected; `eye` is needed for [`Projection::Perspective`] (else isometric).
    pub(crate) fn project(self, p: [Real; 3], eye: Option<Eye>) -> Seen {
        match (self, eye) {
            (Self::Front, _) => Seen {
                x: p[0],
                y: p[1],
                depth: p[2],
            },
            (Self::Isometric, _) | (Self::Perspective { .. }, None) => isometric(p),
            (Self::Perspective { .. }, Some(eye)) => {
                let seen = isometric(p);
                // Scale about the middle by distance / (distance − nearness).
                let nearer = seen.depth.saturating_sub(eye.middle.depth);
                let away = eye
                    .distance
                    .saturating_sub(nearer)
                    .max(Real::from_bits(1 << 16));
                let factor = eye.distance.checked_div(away).unwrap_or(Real::ONE);
                let scaled = |value: Real, middle: Real| {
                    add(
                        middle,
                        value
                            .saturating_sub(middle)
                            .checked_mul(factor)
                            .unwrap_or(Real::ZERO),
                    )
                };
                Seen {
                    x: scaled(seen.x, eye.middle.x),
                    y: scaled(seen.y, eye.middle.y),
                    depth: seen.depth,
                }
            }
        }
    }
}
