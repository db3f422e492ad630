//! What a figure is made of: the shapes of its parts, the parts with their joints and
//! children, and the joint angles of a pose.

use crate::math::Real;

/// [`Figure::MAX_DEPTH`], for the crate's own types and arrays.
pub(crate) const MAX_FIGURE_DEPTH: usize = 8;

/// [`Figure::MAX_JOINTS`], for the crate's own types and arrays.
pub(crate) const MAX_JOINTS: usize = 16;

/// What a part looks like, in its own units along +x from its joint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A line from the joint to (length, 0).
    Line {
        /// Its length.
        length: Real,
    },
    /// A box from (0, −width/2) to (length, width/2).
    Box {
        /// Along the part.
        length: Real,
        /// Across it.
        width: Real,
    },
    /// A circle of `radius` about (radius, 0): a head on a neck.
    Circle {
        /// Its radius.
        radius: Real,
    },
}

/// A part of a figure: a shape, the joint that turns it (an index into the pose's angles),
/// where on its parent it is attached, its rest angle, and its children.
#[derive(Debug, Clone, Copy)]
pub struct Part {
    /// Its name (for `--segments` and errors).
    pub name: &'static str,
    /// What it looks like.
    pub shape: Shape,
    /// Where it hangs on its parent, in the parent's units.
    pub attach: (Real, Real),
    /// Its angle to its parent at rest, degrees.
    pub rest: Real,
    /// The pose's angle added to the rest angle (`None`: rigid).
    pub joint: Option<usize>,
    /// Its colour index.
    pub color: u8,
    /// The parts attached to it.
    pub children: &'static [Part],
}

/// Joint angles in degrees, by joint index.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Pose {
    /// The angles.
    pub angles: [Real; MAX_JOINTS],
}
