//! The articulated figure as a hierarchy of parts: shapes, parts and poses, and the
//! depth-first walk with a stack of maps that draws them.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use heapless::Vec;

use crate::error::{only_target_errors, DrawError, Error, FitError, WalkError};
use crate::math::affine::Affine2;
use crate::math::Real;
use crate::render::fit::DEFAULT_MARGIN;
use crate::render::palette::{Colors, Palette};
use crate::render::raster::draw_line;
use crate::render::space::{Segment3, SpaceFit};

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

/// One drawn line of a figure, with the part it belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FigureLine {
    /// The line in world units (z = 0).
    pub segment: Segment3,
    /// The part's name.
    pub part: &'static str,
}

/// 16 points about a unit circle (cos, sin) in Q32, for circles.
// Indexing runs at compile time only: an out-of-range index would fail the build.
#[allow(clippy::indexing_slicing)]
const CIRCLE: [(i64, i64); 16] = {
    let mut points = [(0, 0); 16];
    let mut i = 0;
    while i < 16 {
        let (c, s) = crate::math::trig::sin_cos(i as u32, 16);
        points[i] = ((c as i64) << 2, (s as i64) << 2);
        i += 1;
    }
    points
};

/// The outline of a shape in its own units: the lines to draw.
fn outline(shape: Shape) -> Vec<((Real, Real), (Real, Real)), 16> {
    let mut lines = Vec::new();
    let zero = Real::ZERO;
    match shape {
        Shape::Line { length } => {
            let _ = lines.push(((zero, zero), (length, zero)));
        }
        Shape::Box { length, width } => {
            let half = Real::from_bits(width.to_bits() / 2);
            let low = Real::ZERO.saturating_sub(half);
            let corners = [(zero, low), (length, low), (length, half), (zero, half)];
            for (index, &from) in corners.iter().enumerate() {
                let to = corners.get((index + 1) % 4).copied().unwrap_or(from);
                let _ = lines.push((from, to));
            }
        }
        Shape::Circle { radius } => {
            let point = |(c, s): (i64, i64)| {
                let scaled = |v: i64| radius.checked_mul(Real::from_bits(v)).unwrap_or(zero);
                (radius.saturating_add(scaled(c)), scaled(s))
            };
            for (index, &from) in CIRCLE.iter().enumerate() {
                let to = CIRCLE.get((index + 1) % 16).copied().unwrap_or(from);
                let _ = lines.push((point(from), point(to)));
            }
        }
    }
    lines
}

/// A figure in a pose.
#[derive(Debug, Clone, Copy)]
pub struct Figure {
    root: &'static Part,
    pose: Pose,
}

impl Figure {
    /// Deepest hierarchy a figure walk holds (the body is 5 deep).
    pub const MAX_DEPTH: usize = MAX_FIGURE_DEPTH;

    /// Most joints a pose names.
    pub const MAX_JOINTS: usize = MAX_JOINTS;

    /// `root` and everything attached to it, in `pose`.
    pub const fn new(root: &'static Part, pose: Pose) -> Self {
        Self { root, pose }
    }

    /// Every line, in world units, depth first; `visit` sees each with its part's name.
    /// The walk holds one map a level ([`Figure::MAX_DEPTH`]): deeper is
    /// [`WalkError::StackTooDeep`].
    pub fn for_each_line(
        &self,
        mut visit: impl FnMut(FigureLine) -> Result<(), Error>,
    ) -> Result<(), Error> {
        // Each entry: a part, the map of its parent, and the next child to visit.
        let mut stack: Vec<(&'static Part, Affine2, usize), MAX_FIGURE_DEPTH> = Vec::new();
        let full = Error::Walk(WalkError::StackTooDeep {
            capacity: MAX_FIGURE_DEPTH,
        });
        let place = |part: &Part, parent: &Affine2| -> Result<Affine2, Error> {
            let mut map = *parent;
            map.translate(part.attach.0, part.attach.1)?;
            let angle = part
                .joint
                .and_then(|j| self.pose.angles.get(j).copied())
                .unwrap_or(Real::ZERO);
            let total = part
                .rest
                .checked_add(angle)
                .ok_or(Error::Walk(WalkError::Overflow))?;
            map.rotate_degrees(total)?;
            Ok(map)
        };
        let map = place(self.root, &Affine2::IDENTITY)?;
        draw_part(self.root, &map, &mut visit)?;
        stack.push((self.root, map, 0)).map_err(|_| full)?;
        while let Some(top) = stack.last_mut() {
            let (part, map, next) = *top;
            let Some(child) = part.children.get(next) else {
                stack.pop();
                continue;
            };
            top.2 += 1;
            let child_map = place(child, &map)?;
            draw_part(child, &child_map, &mut visit)?;
            stack.push((child, child_map, 0)).map_err(|_| full)?;
        }
        Ok(())
    }

    /// Scales and centres the figure into `area` (less a margin), each part in its colour.
    pub fn fit<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
    ) -> Result<FigureDrawing<Colors<'p, C>>, Error> {
        self.fit_poses(area, palette, core::iter::empty())
    }

    /// Like [`Figure::fit`], but so that the figure fits in each of `poses` too: the frames
    /// of an animation share one scale and origin (swap poses with
    /// [`FigureDrawing::with_pose`]), so the figure does not jump between frames.
    pub fn fit_poses<'p, C: PixelColor>(
        &self,
        area: Rectangle,
        palette: &'p [C],
        poses: impl IntoIterator<Item = Pose>,
    ) -> Result<FigureDrawing<Colors<'p, C>>, Error> {
        if area.size.width == 0 || area.size.height == 0 {
            return Err(Error::Fit(FitError::ZeroSizeTarget));
        }
        let palette = Colors::new(palette).ok_or(Error::Fit(FitError::EmptyPalette))?;
        let mut corners = None;
        self.widen(&mut corners)?;
        for pose in poses {
            Self::new(self.root, pose).widen(&mut corners)?;
        }
        let [low, high] = corners.unwrap_or([[Real::ZERO; 3]; 2]);
        let space = SpaceFit::front_box(low, high, &area, DEFAULT_MARGIN)?;
        Ok(FigureDrawing {
            figure: *self,
            space,
            palette,
        })
    }

    /// Widens `corners` (the lowest and highest x and y, z = 0) to the ends of every line:
    /// one walk, no list of lines.
    fn widen(&self, corners: &mut Option<[[Real; 3]; 2]>) -> Result<(), Error> {
        self.for_each_line(|line| {
            for p in [line.segment.start, line.segment.end] {
                let [low, high] = corners.get_or_insert([p, p]);
                low[0] = low[0].min(p[0]);
                low[1] = low[1].min(p[1]);
                high[0] = high[0].max(p[0]);
                high[1] = high[1].max(p[1]);
            }
            Ok(())
        })
    }
}

fn draw_part(
    part: &'static Part,
    map: &Affine2,
    visit: &mut impl FnMut(FigureLine) -> Result<(), Error>,
) -> Result<(), Error> {
    for (from, to) in outline(part.shape) {
        let segment = Segment3 {
            start: map.apply(from.0, from.1)?,
            end: map.apply(to.0, to.1)?,
            color: part.color,
        };
        visit(FigureLine {
            segment,
            part: part.name,
        })?;
    }
    Ok(())
}

/// A fitted figure: an embedded-graphics [`Drawable`].
#[derive(Debug, Clone, Copy)]
pub struct FigureDrawing<P> {
    figure: Figure,
    space: SpaceFit,
    palette: P,
}

impl<P> FigureDrawing<P> {
    /// The same fit (scale and origin) with the figure in `pose`: a frame of an animation
    /// fitted by [`Figure::fit_poses`].
    #[must_use]
    pub fn with_pose(mut self, pose: Pose) -> Self {
        self.figure.pose = pose;
        self
    }

    /// The same fit drawn through `palette`: with a palette of the background colour, the
    /// eraser of a frame (an animation redraws the last frame's lines in the background
    /// instead of clearing the display).
    #[must_use]
    pub fn with_palette<Q>(self, palette: Q) -> FigureDrawing<Q> {
        FigureDrawing {
            figure: self.figure,
            space: self.space,
            palette,
        }
    }
}

impl<P: Palette> FigureDrawing<P> {
    /// Draws the lines, reporting the walk's errors too; returns how many were drawn.
    pub fn try_draw<D>(&self, target: &mut D) -> Result<u64, DrawError<D::Error>>
    where
        D: DrawTarget<Color = P::Color>,
    {
        let clip = target.bounding_box();
        let mut drawn = 0u64;
        let mut failed = None;
        self.figure.for_each_line(|line| {
            let ((from, _), (to, _)) = (
                self.space.place(line.segment.start),
                self.space.place(line.segment.end),
            );
            let color = self.palette.color(u16::from(line.segment.color), u16::MAX);
            if let Err(error) = draw_line(target, from, to, false, color, &clip) {
                failed.get_or_insert(error);
            }
            drawn += 1;
            Ok(())
        })?;
        match failed {
            Some(error) => Err(DrawError::Target(error)),
            None => Ok(drawn),
        }
    }
}

impl<P> Dimensions for FigureDrawing<P> {
    fn bounding_box(&self) -> Rectangle {
        self.space.bounding_box
    }
}

impl<P: Palette> Drawable for FigureDrawing<P> {
    type Color = P::Color;
    type Output = u64;

    fn draw<D>(&self, target: &mut D) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
    {
        only_target_errors(self.try_draw(target))
    }
}
