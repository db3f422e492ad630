//! Sierpiński's shapes and the walking figure on a display, with the scenes' `shapes`
//! feature; without it each draws the background and does no work.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
#[cfg(feature = "shapes")]
use embedded_graphics::primitives::Rectangle;
use tinyfractal::error::DrawError;
#[cfg(feature = "shapes")]
use tinyfractal::{
    error::FitError,
    figure::{walk as walk_pose, BODY},
    render::{Colors, LastFrame},
    Carpet, Error, Figure, Gasket, Real, SierpinskiCube,
};

use crate::catalogue::Scene;
#[cfg(feature = "shapes")]
use crate::catalogue::{Shape, CUBE_COLOUR};
use crate::look::{Look, Work};

impl Scene {
    /// Draws one of Sierpiński's shapes or the walking figure as [`Scene::draw`] does,
    /// without reaching the other families' code; `None` for any other scene.
    ///
    /// A firmware that measures only the shapes calls this, so its flash holds only them.
    pub fn draw_shape<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            Scene::Subdivision { .. } | Scene::Walk { .. } => {
                Some(self.draw_shape_frames(target, look, || {}))
            }
            _ => None,
        }
    }

    /// A shape as [`draw_shape`](Self::draw_shape) draws it, calling `between_frames`
    /// after each of the figure's frames; the background and no work for any other scene.
    pub(crate) fn draw_shape_frames<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
        between_frames: impl FnMut(),
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            #[cfg(feature = "shapes")]
            Scene::Subdivision { shape, order } => draw_subdivision(target, look, shape, order),
            #[cfg(feature = "shapes")]
            Scene::Walk { frames } => draw_walk(target, look, frames, between_frames),
            // Any other scene, or a shape without the `shapes` feature: the background, no
            // work.
            _ => {
                let _ = between_frames;
                target.clear(look.background).map_err(DrawError::Target)?;
                Ok(match self {
                    Scene::Walk { .. } => Work::Segments(0),
                    _ => Work::Cells(0),
                })
            }
        }
    }
}

#[cfg(feature = "shapes")]
/// A Sierpiński carpet, gasket or cube over the whole target, out of line. The carpet and
/// gasket paint their box (ink and background) and the cube its target; what is left of
/// the target around the carpet's square or the gasket's box is cleared first.
#[inline(never)]
fn draw_subdivision<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    shape: Shape,
    order: u32,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let area = target.bounding_box();
    let cells = match shape {
        Shape::Carpet => {
            let drawing = Carpet::new(order).fit(area, look.ink, look.background)?;
            clear_around(target, area, drawing.bounding_box(), look.background)?;
            drawing.draw(target).map_err(DrawError::Target)?.squares
        }
        Shape::Gasket => {
            let drawing = Gasket::new(order).fit(area, look.ink, look.background)?;
            clear_around(target, area, drawing.bounding_box(), look.background)?;
            drawing.draw(target).map_err(DrawError::Target)?.triangles
        }
        Shape::Cube(variant) => {
            SierpinskiCube::new(order, variant)
                .fit(area, CUBE_COLOUR, look.background)?
                .draw(target)
                .map_err(DrawError::Target)?
                .cubes
        }
    };
    Ok(Work::Cells(cells))
}

#[cfg(feature = "shapes")]
/// Clears the parts of `area` outside `inner` (the bands beside or above and below it).
fn clear_around<D: DrawTarget>(
    target: &mut D,
    area: Rectangle,
    inner: Rectangle,
    background: D::Color,
) -> Result<(), DrawError<D::Error>> {
    let (Some(outer_end), Some(inner_end)) = (area.bottom_right(), inner.bottom_right()) else {
        return Ok(());
    };
    let bands = [
        Rectangle::with_corners(area.top_left, Point::new(outer_end.x, inner.top_left.y - 1)),
        Rectangle::with_corners(Point::new(area.top_left.x, inner_end.y + 1), outer_end),
        Rectangle::with_corners(
            Point::new(area.top_left.x, inner.top_left.y),
            Point::new(inner.top_left.x - 1, inner_end.y),
        ),
        Rectangle::with_corners(
            Point::new(inner_end.x + 1, inner.top_left.y),
            Point::new(outer_end.x, inner_end.y),
        ),
    ];
    for band in bands {
        // `with_corners` swaps corners given in the wrong order: an empty band comes out
        // reversed, so keep only bands really outside `inner`.
        if band.size.width > 0 && band.size.height > 0 && band.intersection(&inner).is_zero_sized()
        {
            target
                .fill_solid(&band, background)
                .map_err(DrawError::Target)?;
        }
    }
    Ok(())
}

/// The runs of the walking figure's frame kept to erase it (8 bytes each): every frame
/// on the OLED; a larger display's frames are erased by drawing them again.
#[cfg(feature = "shapes")]
const WALK_RUNS: usize = 256;

/// The walk cycle in `look.ink`, out of line: `frames` frames fitted once over all of
/// them, each frame erasing the last one before drawing its own (the runs it sent filled
/// again in the background, or where they were too many for [`WALK_RUNS`], its lines drawn
/// again in the background), so the display is cleared once, not every frame. What stays
/// on the target is the last frame alone.
#[inline(never)]
#[cfg(feature = "shapes")]
fn draw_walk<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    frames: u32,
    mut between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    // Frame k of n at k/n of a stride (none for n = 0).
    let pose = |frame: u32| Real::from_ratio(i64::from(frame), i64::from(frames)).map(walk_pose);
    let Some(first) = pose(0) else {
        return Ok(Work::Segments(0));
    };
    let (ink, paper) = ([look.ink], [look.background]);
    let drawing = Figure::new(&BODY, first).fit_poses(
        target.bounding_box(),
        &ink,
        (1..frames).filter_map(pose),
    )?;
    let eraser =
        drawing.with_palette(Colors::new(&paper).ok_or(Error::Fit(FitError::EmptyPalette))?);
    let mut lines = 0;
    let mut last = None;
    // The last frame's runs, erased by filling them again in the background; a frame of
    // more runs than this holds is erased by drawing it again.
    let mut last_frame = LastFrame::<WALK_RUNS>::new();
    for frame in (0..frames).filter_map(pose) {
        if let Some(last) = last {
            let erased = last_frame
                .erase(target, look.background)
                .map_err(DrawError::Target)?;
            if !erased {
                eraser.with_pose(last).try_draw(target)?;
            }
        }
        lines += drawing
            .with_pose(frame)
            .try_draw(&mut last_frame.recording(target))?;
        last = Some(frame);
        between_frames();
    }
    Ok(Work::Segments(lines))
}
