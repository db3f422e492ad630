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

/// One polygon being recorded.
#[derive(Debug, Clone)]
struct Polygon {
    vertices: Vec<[Real; 3], MAX_POLYGON_VERTICES>,
    /// Whether a `.` has recorded a vertex (then only `.`s do).
    dotted: bool,
}

/// The polygons open, and whether the last one has just closed.
#[derive(Debug, Clone, Default)]
pub(crate) struct Polygons {
    open: Vec<Polygon, MAX_OPEN_POLYGONS>,
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
    pub(crate) fn settle(&mut self) {
        if self.closed {
            self.open.pop();
            self.closed = false;
        }
    }

    /// Whether a polygon is open (moves inside one draw no lines).
    pub(crate) fn recording(&self) -> bool {
        !self.open.is_empty()
    }

    /// `{` at `position`.
    pub(crate) fn start(&mut self, position: [Real; 3]) -> Result<(), Error> {
        let mut vertices = Vec::new();
        // Cannot fail: the capacity is above 0.
        let _ = vertices.push(position);
        self.open
            .push(Polygon {
                vertices,
                dotted: false,
            })
            .map_err(|_| {
                Error::Walk(WalkError::PolygonsNestTooDeep {
                    capacity: MAX_OPEN_POLYGONS,
                })
            })
    }

    /// The turtle moved to `position` by `F` or `f`.
    pub(crate) fn moved(&mut self, position: [Real; 3]) -> Result<(), Error> {
        match self.open.last_mut() {
            Some(polygon) if !polygon.dotted => polygon
                .vertices
                .push(position)
                .map_err(|_| too_many_vertices()),
            _ => Ok(()),
        }
    }

    /// `.` at `position`.
    pub(crate) fn vertex(&mut self, position: [Real; 3]) -> Result<(), Error> {
        let Some(polygon) = self.open.last_mut() else {
            return Ok(());
        };
        if !polygon.dotted {
            polygon.vertices.clear();
            polygon.dotted = true;
        }
        polygon
            .vertices
            .push(position)
            .map_err(|_| too_many_vertices())
    }

    /// `}`: the polygon closes; [`closed`](Self::closed) has its vertices until the next
    /// module.
    pub(crate) fn end(&mut self) -> Result<(), Error> {
        if self.open.is_empty() {
            return Err(Error::Walk(WalkError::PolygonNotOpen));
        }
        self.closed = true;
        Ok(())
    }

    /// The vertices of the polygon the last module closed, in turtle units.
    pub(crate) fn closed(&self) -> &[[Real; 3]] {
        match self.open.last() {
            Some(polygon) if self.closed => &polygon.vertices,
            _ => &[],
        }
    }

    /// At the end of the walk: a polygon still open is an error (it would be lost).
    pub(crate) fn finish(&mut self) -> Result<(), Error> {
        self.settle();
        if self.open.is_empty() {
            Ok(())
        } else {
            Err(Error::Walk(WalkError::PolygonNotClosed))
        }
    }
}
