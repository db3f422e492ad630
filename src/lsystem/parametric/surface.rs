//! The polygons a turtle is recording (ABOP §1.9): `{` starts one, `.` records the turtle's
//! position as a vertex, `}` closes it to be filled.
//!
//! A polygon with no `.` (ABOP's own leaves, `{-f+f+f-|-f+f+f}`) is the turtle's path: its
//! vertices are where the turtle stood at `{` and after each `F` or `f` inside it. Once a
//! polygon has a `.`, only the `.`s are its vertices. Polygons outlive branches: a vertex
//! recorded inside `[ ]` belongs to the polygon open when it was recorded (ABOP's leaves
//! drawn from a midrib). A polygon may open inside another, [`MAX_OPEN_POLYGONS`] deep.

use heapless::Vec;

use crate::error::{Error, WalkError};
use crate::math::Real;

/// Most vertices of one polygon.
pub const MAX_POLYGON_VERTICES: usize = 32;

/// Most polygons open at once (a `{` inside a `{`).
pub const MAX_OPEN_POLYGONS: usize = 2;

/// The polygons open, and whether the last one has just closed. Kept in place, one slot a
/// nesting level: a polygon is 768 bytes, and moving one in or out at each `{` and after
/// each `}` was a copy of all of them.
#[derive(Debug, Clone, Default)]
pub(crate) struct Polygons {
    /// Each open polygon's vertices (slot i for the polygon opened at depth i).
    vertices: [Vec<[Real; 3], MAX_POLYGON_VERTICES>; MAX_OPEN_POLYGONS],
    /// Whether a `.` has recorded a vertex of the polygon (then only `.`s do).
    dotted: [bool; MAX_OPEN_POLYGONS],
    /// How many are open.
    open: usize,
    /// The last open polygon closed with the last module: dropped at the next one.
    closed: bool,
}

fn too_many_vertices() -> Error {
    Error::Walk(WalkError::PolygonTooLarge {
        capacity: MAX_POLYGON_VERTICES,
    })
}

impl Polygons {
    /// Forgets a polygon closed by the previous module.
    #[inline]
    pub(crate) fn settle(&mut self) {
        if self.closed {
            self.open = self.open.saturating_sub(1);
            self.closed = false;
        }
    }

    /// Whether a polygon is open (moves inside one draw no lines).
    pub(crate) fn recording(&self) -> bool {
        self.open > 0
    }

    /// `{` at `position`.
    pub(crate) fn start(&mut self, position: [Real; 3]) -> Result<(), Error> {
        let level = self.open;
        let (Some(vertices), Some(dotted)) =
            (self.vertices.get_mut(level), self.dotted.get_mut(level))
        else {
            return Err(Error::Walk(WalkError::PolygonsNestTooDeep {
                capacity: MAX_OPEN_POLYGONS,
            }));
        };
        vertices.clear();
        // Cannot fail: the capacity is above 0.
        let _ = vertices.push(position);
        *dotted = false;
        self.open = level + 1;
        Ok(())
    }

    /// The innermost open polygon's vertices and whether it is dotted.
    fn innermost(&mut self) -> Option<(&mut Vec<[Real; 3], MAX_POLYGON_VERTICES>, &mut bool)> {
        let level = self.open.checked_sub(1)?;
        Some((self.vertices.get_mut(level)?, self.dotted.get_mut(level)?))
    }

    /// A move (`F`, `f`) ended at `position`: a vertex of a polygon with no `.`.
    pub(crate) fn moved(&mut self, position: [Real; 3]) -> Result<(), Error> {
        match self.innermost() {
            Some((vertices, &mut false)) => {
                vertices.push(position).map_err(|_| too_many_vertices())
            }
            _ => Ok(()),
        }
    }

    /// `.` at `position`.
    pub(crate) fn vertex(&mut self, position: [Real; 3]) -> Result<(), Error> {
        let Some((vertices, dotted)) = self.innermost() else {
            return Ok(());
        };
        if !*dotted {
            vertices.clear();
            *dotted = true;
        }
        vertices.push(position).map_err(|_| too_many_vertices())
    }

    /// `}`: the polygon closes; [`closed`](Self::closed) has its vertices until the next
    /// module.
    pub(crate) fn end(&mut self) -> Result<(), Error> {
        if self.open == 0 {
            return Err(Error::Walk(WalkError::PolygonNotOpen));
        }
        self.closed = true;
        Ok(())
    }

    /// The vertices of the polygon the last module closed, in turtle units.
    pub(crate) fn closed(&self) -> &[[Real; 3]] {
        match self
            .open
            .checked_sub(1)
            .and_then(|level| self.vertices.get(level))
        {
            Some(vertices) if self.closed => vertices,
            _ => &[],
        }
    }

    /// At the end of the walk: a polygon still open is an error (it would be lost).
    pub(crate) fn finish(&mut self) -> Result<(), Error> {
        self.settle();
        if self.open == 0 {
            Ok(())
        } else {
            Err(Error::Walk(WalkError::PolygonNotClosed))
        }
    }
}
