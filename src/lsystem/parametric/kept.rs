//! The marks a fit keeps: what the measuring walk drew, already projected, so that the
//! drawing replays them instead of walking the derivation a second time. The walk is most
//! of a plant's cost (docs/performance.md, The general engine); a buffer of the caller's
//! halves it.

use heapless::Vec;

use super::marks::{Mark, Marks3};
use super::surface::MAX_POLYGON_VERTICES;
use crate::error::Error;
use crate::math::Real;
use crate::render::projection::{Eye, Projection, Seen};
use crate::render::space::Extent;

/// A record of the marks a fit keeps for its drawing to replay.
///
/// [`fit_with_marks`](crate::ParametricLSystem::fit_with_marks) writes them into a buffer
/// of the caller's: a line takes one, a polygon of n vertices 1 + ⌊n / 2⌋;
/// [`StoredMark::BYTES`] each.
#[derive(Debug, Clone, Copy)]
pub struct StoredMark {
    /// A line's ends; a polygon's first vertex (and nothing); two more of its vertices.
    points: [Seen; 2],
    /// A line's width.
    width: Real,
    kind: Kind,
    color: u8,
    /// A polygon's vertices.
    count: u8,
}

/// What a record holds. A plain struct with a kind, not an enum: each record is written
/// field by field into its slot (an enum's was built apart and copied in, byte by byte).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Empty,
    Line,
    /// A polygon's first vertex, its count and colour; the rest follow two a record.
    Polygon,
    Vertices,
}

impl StoredMark {
    /// An empty record, to fill a buffer with.
    pub const EMPTY: Self = Self {
        points: [ORIGIN; 2],
        width: Real::ZERO,
        kind: Kind::Empty,
        color: 0,
        count: 0,
    };

    /// The bytes a record takes.
    pub const BYTES: usize = size_of::<Self>();
}

/// The origin, seen from anywhere: an empty record's points.
const ORIGIN: Seen = Seen {
    x: Real::ZERO,
    y: Real::ZERO,
    depth: Real::ZERO,
};

impl Default for StoredMark {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// A mark as seen through the fit's projection: what the painter draws.
#[derive(Debug, Clone, Copy)]
pub(crate) enum SeenMark<'m> {
    /// A line's ends (borrowed: they are copied nowhere) and its width in turtle units
    /// (0: one pixel).
    Line {
        ends: &'m [Seen; 2],
        width: Real,
        color: u8,
    },
    /// A filled polygon's vertices.
    Polygon { vertices: &'m [Seen], color: u8 },
}

/// Marks handed out seen, one at a time (a lending iterator: a polygon's vertices are
/// borrowed until the next).
pub(crate) trait SeenMarks {
    /// The next mark, `None` at the end; an error ends the marks.
    fn next_seen(&mut self) -> Option<Result<SeenMark<'_>, Error>>;
}

/// A walk's marks projected as they come.
pub(crate) struct Projected<'w, 'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize> {
    marks: &'w mut Marks3<'g, DEPTH, STACK, SLOTS>,
    projection: Projection,
    eye: Option<Eye>,
    ends: [Seen; 2],
    vertices: Vec<Seen, MAX_POLYGON_VERTICES>,
}

impl<'w, 'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    Projected<'w, 'g, DEPTH, STACK, SLOTS>
{
    /// `marks` seen through `projection` (and `eye`, for a perspective).
    pub(crate) fn new(
        marks: &'w mut Marks3<'g, DEPTH, STACK, SLOTS>,
        (projection, eye): (Projection, Option<Eye>),
    ) -> Self {
        Self {
            marks,
            projection,
            eye,
            // Written before each line is handed out: any start will do.
            ends: [ORIGIN; 2],
            vertices: Vec::new(),
        }
    }
}

impl<const DEPTH: usize, const STACK: usize, const SLOTS: usize> SeenMarks
    for Projected<'_, '_, DEPTH, STACK, SLOTS>
{
    fn next_seen(&mut self) -> Option<Result<SeenMark<'_>, Error>> {
        let (projection, eye) = (self.projection, self.eye);
        let see = move |p: [Real; 3]| projection.project(p, eye);
        Some(match self.marks.next_mark()? {
            Ok(Mark::Line { segment, width }) => {
                self.ends = [see(segment.start), see(segment.end)];
                Ok(SeenMark::Line {
                    ends: &self.ends,
                    width,
                    color: segment.color,
                })
            }
            Ok(Mark::Polygon { vertices, color }) => {
                self.vertices.clear();
                for &vertex in vertices {
                    // Cannot fail: a polygon has at most MAX_POLYGON_VERTICES vertices.
                    let _ = self.vertices.push(see(vertex));
                }
                Ok(SeenMark::Polygon {
                    vertices: &self.vertices,
                    color,
                })
            }
            Err(error) => Err(error),
        })
    }
}

/// Kept marks handed out again, in the order they were kept.
pub(crate) struct Replay<'k> {
    records: core::slice::Iter<'k, StoredMark>,
    vertices: Vec<Seen, MAX_POLYGON_VERTICES>,
}

impl<'k> Replay<'k> {
    pub(crate) fn new(records: &'k [StoredMark]) -> Self {
        Self {
            records: records.iter(),
            vertices: Vec::new(),
        }
    }
}

impl SeenMarks for Replay<'_> {
    fn next_seen(&mut self) -> Option<Result<SeenMark<'_>, Error>> {
        loop {
            // Read in place: a record is too large to copy out whole at every mark.
            let record = self.records.next()?;
            match record.kind {
                Kind::Line => {
                    return Some(Ok(SeenMark::Line {
                        ends: &record.points,
                        width: record.width,
                        color: record.color,
                    }))
                }
                Kind::Polygon => {
                    let count = usize::from(record.count);
                    self.vertices.clear();
                    let _ = self.vertices.push(record.points[0]);
                    while self.vertices.len() < count {
                        let Some(pair) = self.records.next().filter(|r| r.kind == Kind::Vertices)
                        else {
                            break;
                        };
                        for &seen in &pair.points {
                            if self.vertices.len() < count {
                                // Cannot fail: the count kept is at most the capacity.
                                let _ = self.vertices.push(seen);
                            }
                        }
                    }
                    return Some(Ok(SeenMark::Polygon {
                        vertices: &self.vertices,
                        color: record.color,
                    }));
                }
                // Only a polygon's records hold vertices, and it reads its own.
                Kind::Vertices | Kind::Empty => {}
            }
        }
    }
}

/// Where a walk's marks are written as they are measured.
struct Keeper<'k> {
    records: &'k mut [StoredMark],
    /// Records written; `None` once the marks outgrew the buffer.
    written: Option<usize>,
}

impl Keeper<'_> {
    /// The next record to write, or `None` (and no keeping from then on) if the buffer
    /// is full.
    #[inline(always)]
    fn next(&mut self) -> Option<&mut StoredMark> {
        let written = self.written?;
        self.written = Some(written + 1).filter(|&n| n <= self.records.len());
        self.records.get_mut(written)
    }

    #[inline(always)]
    fn keep(&mut self, mark: &SeenMark<'_>) {
        match *mark {
            SeenMark::Line { ends, width, color } => {
                if let Some(record) = self.next() {
                    record.points = *ends;
                    record.width = width;
                    record.kind = Kind::Line;
                    record.color = color;
                }
            }
            SeenMark::Polygon { vertices, color } => {
                let Some((&first, rest)) = vertices.split_first() else {
                    return;
                };
                if let Some(record) = self.next() {
                    record.points[0] = first;
                    record.kind = Kind::Polygon;
                    record.color = color;
                    // Cannot saturate: at most MAX_POLYGON_VERTICES.
                    record.count = u8::try_from(vertices.len()).unwrap_or(u8::MAX);
                }
                for pair in rest.chunks(2) {
                    if let (Some(&a), Some(&b), Some(record)) =
                        (pair.first(), pair.last(), self.next())
                    {
                        record.points = [a, b];
                        record.kind = Kind::Vertices;
                    }
                }
            }
        }
    }
}

const _: () = assert!(MAX_POLYGON_VERTICES <= u8::MAX as usize);

/// Walks `marks` once, seen through `projection` (not a perspective, whose eye needs the
/// extent first): the extent of everything drawn, as [`SpaceFit`](crate::render::space)
/// measures it, and how many of `records` hold every mark, in order (`None`: they did
/// not fit, and are not to be replayed).
#[inline(never)]
pub(crate) fn measure_keeping<const DEPTH: usize, const STACK: usize, const SLOTS: usize>(
    marks: &mut Marks3<'_, DEPTH, STACK, SLOTS>,
    projection: Projection,
    records: &mut [StoredMark],
) -> Result<(Option<Extent>, Option<usize>), Error> {
    let mut projected = Projected::new(marks, (projection, None));
    let mut keeper = Keeper {
        records,
        written: Some(0),
    };
    let mut extent = None;
    while let Some(mark) = projected.next_seen() {
        let mark = mark?;
        match mark {
            SeenMark::Line { ends, .. } => {
                for &seen in ends {
                    Extent::include(&mut extent, seen);
                }
            }
            SeenMark::Polygon { vertices, .. } => {
                for &seen in vertices {
                    Extent::include(&mut extent, seen);
                }
            }
        }
        keeper.keep(&mark);
    }
    Ok((extent, keeper.written))
}
