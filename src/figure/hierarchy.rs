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
use crate::render::raster::{draw_line_on, PendingRun};
use crate::render::space::{Segment3, SpaceFit};

use super::part::{walk_parts, Part, Pose, Shape, CIRCLE, CIRCLE_SIDES};
use super::part::{MAX_FIGURE_DEPTH, MAX_JOINTS};
use super::pixels::{pixel, Fixed, Outline, PixelWalk, Traced};
use crate::render::circle::draw_circle;

/// One drawn line of a figure, with the part it belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FigureLine {
    /// The line in world units (z = 0).
    pub segment: Segment3,
    /// The part's name.
    pub part: &'static str,
}

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
            // The Q30 table in Q32.
            let point = |(c, s): (i32, i32)| {
                let scaled = |v: i32| {
                    let v = Real::from_bits(i64::from(v) << 2);
                    radius.checked_mul(v).unwrap_or(zero)
                };
                (radius.saturating_add(scaled(c)), scaled(s))
            };
            for (index, &from) in CIRCLE.iter().enumerate() {
                let to = CIRCLE
                    .get((index + 1) % CIRCLE_SIDES)
                    .copied()
                    .unwrap_or(from);
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
        self.for_each_placed(|part, map| draw_part(part, map, &mut visit))
    }

    /// Every part with its map (parts' units to world units), depth first.
    fn for_each_placed(
        &self,
        visit: impl FnMut(&'static Part, &Affine2) -> Result<(), Error>,
    ) -> Result<(), Error> {
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
        walk_parts(self.root, &Affine2::IDENTITY, place, visit)
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
        // Measured in the pixel walk's arithmetic on a provisional plane (one 64-bit walk
        // a pose, not a `Real` one), then read back into units.
        let (measuring, back) = PixelWalk::measuring(self.root);
        let mut corners: Option<[Fixed; 2]> = None;
        for pose in core::iter::once(self.pose).chain(poses) {
            measuring.walk(self.root, &pose, |traced| {
                let mut widen = |(x, y): Fixed| {
                    let [low, high] = corners.get_or_insert([(x, y); 2]);
                    *low = (low.0.min(x), low.1.min(y));
                    *high = (high.0.max(x), high.1.max(y));
                };
                match traced.outline {
                    Outline::Path { points, .. } => points.iter().copied().for_each(widen),
                    Outline::Circle { centre, radius } => {
                        widen((centre.0 - radius, centre.1 - radius));
                        widen((centre.0 + radius, centre.1 + radius));
                    }
                }
            })?;
        }
        let [low, high] = corners.unwrap_or([(0, 0); 2]);
        let unit = |v: i64| -> Result<Real, Error> {
            let bits = if back >= 0 {
                v.checked_mul(1i64.checked_shl(back.unsigned_abs()).unwrap_or(0))
                    .filter(|_| back < 63)
            } else {
                Some(v >> back.unsigned_abs().min(63))
            };
            bits.map(Real::from_bits)
                .ok_or(Error::Walk(WalkError::Overflow))
        };
        let space = SpaceFit::front_box(
            [unit(low.0)?, unit(low.1)?, Real::ZERO],
            [unit(high.0)?, unit(high.1)?, Real::ZERO],
            &area,
            DEFAULT_MARGIN,
        )?;
        let walk = space
            .front_linear()
            .and_then(|(scale, origin)| PixelWalk::fitted(self.root, scale, origin))
            .ok_or(Error::Fit(FitError::PartTooLong))?;
        Ok(FigureDrawing {
            figure: *self,
            space,
            walk,
            palette,
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
    /// The walk in the fit's pixels.
    walk: PixelWalk,
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
            walk: self.walk,
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
        let mut run = PendingRun::default();
        let draw = |traced: Traced<'_>| {
            let color = self.palette.color(u16::from(traced.color), u16::MAX);
            let result = draw_outline(target, &mut run, traced, color, &clip);
            if let Err(error) = result {
                failed.get_or_insert(error);
            }
            drawn += traced.outline.drawn();
        };
        self.walk.walk(self.figure.root, &self.figure.pose, draw)?;
        run.send(target).map_err(DrawError::Target)?;
        match failed {
            Some(error) => Err(DrawError::Target(error)),
            None => Ok(drawn),
        }
    }
}

/// Draws an outline: a path's lines each from the last one's end (its first pixel
/// already drawn), short steps joined into runs; a circle by the circle rasteriser.
fn draw_outline<D: DrawTarget>(
    target: &mut D,
    run: &mut PendingRun<D::Color>,
    traced: Traced<'_>,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let (points, closed) = match traced.outline {
        Outline::Path { points, closed } => (points, closed),
        Outline::Circle { centre, radius } => {
            run.send(target)?;
            return draw_circle(target, centre, radius, color, clip);
        }
    };
    let at = |(x, y): Fixed| Point::new(pixel(x), pixel(y));
    let Some(&first) = points.first() else {
        return Ok(());
    };
    let closing = closed.then_some(first);
    let mut last = at(first);
    for (index, &point) in points.iter().skip(1).chain(closing.iter()).enumerate() {
        let next = at(point);
        draw_line_on(target, run, last, next, index > 0, color, clip)?;
        last = next;
    }
    Ok(())
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::FitError;
    use crate::figure::pixels::q16_of;
    use crate::figure::{walk, BODY};
    use crate::render::circle::drawn_as_circle;
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;

    /// The pixels a drawing lights, and how many lines and circles it counts.
    fn lit<P: Palette<Color = BinaryColor>>(
        drawing: &FigureDrawing<P>,
    ) -> (MockDisplay<BinaryColor>, u64) {
        let mut display = MockDisplay::new();
        display.set_allow_overdraw(true);
        let lines = drawing.try_draw(&mut display).unwrap();
        (display, lines)
    }

    /// The model: the figure drawn by the `Real` walk of [`Figure::for_each_placed`] (maps
    /// of Q32.32 with 128-bit products), each point placed by the fit's scale and origin in
    /// `Real`, through the same rasterisers.
    fn by_real_walk(
        drawing: &FigureDrawing<Colors<'_, BinaryColor>>,
    ) -> (MockDisplay<BinaryColor>, u64) {
        let mut target = MockDisplay::new();
        target.set_allow_overdraw(true);
        let clip = target.bounding_box();
        let (mut run, mut drawn) = (PendingRun::default(), 0);
        let (scale, origin) = drawing.space.front_linear().unwrap();
        let on_target = |[x, y, _]: [Real; 3]| -> Fixed {
            let scaled = |v: Real| v.checked_mul(scale).unwrap();
            (
                q16_of(origin.0.saturating_add(scaled(x))),
                q16_of(origin.1.saturating_sub(scaled(y))),
            )
        };
        let mut draw = |traced: Traced<'_>| {
            draw_outline(&mut target, &mut run, traced, BinaryColor::On, &clip).unwrap();
            drawn += traced.outline.drawn();
        };
        drawing
            .figure
            .for_each_placed(|part, map| {
                if let Shape::Circle { radius } = part.shape {
                    let centre = on_target(map.apply(radius, Real::ZERO)?);
                    let scaled = radius.checked_mul(scale).unwrap().abs();
                    let radius = q16_of(scaled);
                    assert!(drawn_as_circle(radius));
                    draw(Traced {
                        outline: Outline::Circle { centre, radius },
                        color: part.color,
                    });
                    return Ok(());
                }
                let mut points: Vec<Fixed, 16> = Vec::new();
                let outline = outline(part.shape);
                let closed = outline.len() > 1;
                for (index, &(from, to)) in outline.iter().enumerate() {
                    if index == 0 {
                        points.push(on_target(map.apply(from.0, from.1)?)).unwrap();
                    }
                    if !closed || index + 1 < outline.len() {
                        points.push(on_target(map.apply(to.0, to.1)?)).unwrap();
                    }
                }
                draw(Traced {
                    outline: Outline::Path {
                        points: &points,
                        closed,
                    },
                    color: part.color,
                });
                Ok(())
            })
            .unwrap();
        run.send(&mut target).unwrap();
        (target, drawn)
    }

    /// The walk in the fit's pixels lights the pixels the `Real` walk's placed points do,
    /// in every pose of the walk cycle and of a wild one, at several sizes and offsets.
    #[test]
    fn the_pixel_walk_draws_the_real_walks_picture() {
        let areas = [
            Rectangle::new(Point::zero(), Size::new(64, 64)),
            Rectangle::new(Point::new(3, 5), Size::new(57, 41)),
            Rectangle::new(Point::new(1, 0), Size::new(20, 63)),
            Rectangle::new(Point::zero(), Size::new(9, 7)),
        ];
        let mut wild = Pose::default();
        for (k, angle) in wild.angles.iter_mut().enumerate() {
            *angle = Real::from_ratio(7919 * k as i64 % 720 - 360, 1).unwrap();
        }
        let poses = (0..24)
            .map(|k| walk(Real::from_ratio(k, 24).unwrap()))
            .chain([wild, Pose::default()]);
        for area in areas {
            for pose in poses.clone() {
                let drawing = Figure::new(&BODY, pose)
                    .fit(area, &[BinaryColor::On])
                    .unwrap();
                let ((pixels, lines), (model, model_lines)) =
                    (lit(&drawing), by_real_walk(&drawing));
                assert_eq!(lines, model_lines);
                pixels.assert_eq(&model);
            }
        }
    }

    /// A figure fitted to 400,000 pixels has limbs too long for the pixel walk's 32 bits:
    /// a typed error, not a wrong picture.
    #[test]
    fn a_figure_beyond_the_pixel_walk_is_refused() {
        let area = Rectangle::new(Point::zero(), Size::new(400_000, 400_000));
        let fitted = Figure::new(&BODY, Pose::default()).fit(area, &[BinaryColor::On]);
        assert_eq!(fitted.err(), Some(Error::Fit(FitError::PartTooLong)));
        let area = Rectangle::new(Point::zero(), Size::new(20_000, 20_000));
        assert!(Figure::new(&BODY, Pose::default())
            .fit(area, &[BinaryColor::On])
            .is_ok());
    }
}
