//! What a figure is made of: the shapes of its parts, the parts with their joints and
//! children, and the joint angles of a pose.

use heapless::Vec;

use crate::error::{Error, WalkError};
use crate::math::Real;

/// [`Figure::MAX_DEPTH`](super::Figure::MAX_DEPTH), for the crate's own types and arrays.
pub(crate) const MAX_FIGURE_DEPTH: usize = 8;

/// [`Figure::MAX_JOINTS`](super::Figure::MAX_JOINTS), for the crate's own types and arrays.
pub(crate) const MAX_JOINTS: usize = 16;

/// Corners a circle's outline goes through where it is drawn as lines.
pub(crate) const CIRCLE_SIDES: usize = 16;

/// [`CIRCLE_SIDES`] points about a unit circle (cos, sin) in Q30: one table for both walks.
// Indexing runs at compile time only: an out-of-range index would fail the build.
#[allow(clippy::indexing_slicing)]
pub(crate) const CIRCLE: [(i32, i32); CIRCLE_SIDES] = {
    let mut points = [(0, 0); CIRCLE_SIDES];
    let mut i = 0;
    while i < CIRCLE_SIDES {
        points[i] = crate::math::trig::sin_cos(i as u32, CIRCLE_SIDES as u32);
        i += 1;
    }
    points
};

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

/// Walks `root` and everything attached to it depth first, each part with a state made
/// from its parent's by `place` (the root's from `start`: a map, for the walks that draw).
///
/// `visit` sees each part with its state as it is reached. The walk holds a state a level:
/// deeper than [`MAX_FIGURE_DEPTH`] is [`WalkError::StackTooDeep`].
#[inline(always)]
pub(crate) fn walk_parts<S: Copy>(
    root: &'static Part,
    start: &S,
    mut place: impl FnMut(&'static Part, &S) -> Result<S, Error>,
    mut visit: impl FnMut(&'static Part, &S) -> Result<(), Error>,
) -> Result<(), Error> {
    // Each entry: a part, its state, and the next child to visit.
    let mut stack: Vec<(&'static Part, S, usize), MAX_FIGURE_DEPTH> = Vec::new();
    let full = Error::Walk(WalkError::StackTooDeep {
        capacity: MAX_FIGURE_DEPTH,
    });
    let state = place(root, start)?;
    visit(root, &state)?;
    stack.push((root, state, 0)).map_err(|_| full)?;
    while let Some(top) = stack.last_mut() {
        let (part, state, next) = *top;
        let Some(child) = part.children.get(next) else {
            stack.pop();
            continue;
        };
        top.2 += 1;
        let child_state = place(child, &state)?;
        visit(child, &child_state)?;
        stack.push((child, child_state, 0)).map_err(|_| full)?;
    }
    Ok(())
}
