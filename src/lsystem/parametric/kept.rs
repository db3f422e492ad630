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
pub struct StoredMark(Record);

impl StoredMark {
    /// An empty record, to fill a buffer with.
    pub const EMPTY: Self = Self(Record::Empty);

    /// The bytes a record takes.
    pub const BYTES: usize = size_of::<Self>();
}

impl Default for StoredMark {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// What a record holds.
#[derive(Debug, Clone, Copy)]
enum Record {
    Empty,
    Line {
        ends: [Seen; 2],
        width: Real,
        color: u8,
    },
    /// A polygon's first vertex, its count and colour; the rest follow two a record.
    Polygon {
        first: Seen,
        vertices: u8,
        color: u8,
    },
    Vertices([Seen; 2]),
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
        let origin = projection.project([Real::ZERO; 3], eye);
        Self {
            marks,
            projection,
            eye,
            ends: [origin; 2],
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
            match &self.records.next()?.0 {
                Record::Line { ends, width, color } => {
                    return Some(Ok(SeenMark::Line {
                        ends,
                        width: *width,
                        color: *color,
                    }))
                }
                &Record::Polygon {
                    first,
                    vertices,
                    color,
                } => {
                    self.vertices.clear();
                    let _ = self.vertices.push(first);
                    while self.vertices.len() < usize::from(vertices) {
                        let Some(&StoredMark(Record::Vertices(pair))) = self.records.next() else {
                            break;
                        };
                        for seen in pair {
                            if self.vertices.len() < usize::from(vertices) {
                                // Cannot fail: the count kept is at most the capacity.
                                let _ = self.vertices.push(seen);
                            }
                        }
                    }
                    return Some(Ok(SeenMark::Polygon {
                        vertices: &self.vertices,
                        color,
                    }));
                }
                // Only a polygon's records hold vertices, and it reads its own.
                Record::Vertices(_) | Record::Empty => {}
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
    /// Writes `record` next, or gives up keeping if the buffer is full. Inlined, so the
    /// record is built in its slot rather than copied there.
    #[inline(always)]
    fn write(&mut self, record: Record) {
        if let Some(written) = self.written {
            match self.records.get_mut(written) {
                Some(slot) => {
                    *slot = StoredMark(record);
                    self.written = Some(written + 1);
                }
                None => self.written = None,
            }
        }
    }

    #[inline(always)]
    fn keep(&mut self, mark: &SeenMark<'_>) {
        match *mark {
            SeenMark::Line { ends, width, color } => self.write(Record::Line {
                ends: *ends,
                width,
                color,
            }),
            SeenMark::Polygon { vertices, color } => {
                let Some((&first, rest)) = vertices.split_first() else {
                    return;
                };
                self.write(Record::Polygon {
                    first,
                    // Cannot saturate: at most MAX_POLYGON_VERTICES.
                    vertices: u8::try_from(vertices.len()).unwrap_or(u8::MAX),
                    color,
                });
                for pair in rest.chunks(2) {
                    let last = pair.last().copied().unwrap_or(first);
                    self.write(Record::Vertices([
                        pair.first().copied().unwrap_or(last),
                        last,
                    ]));
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
