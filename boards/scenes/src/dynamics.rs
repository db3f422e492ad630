//! The dynamics' scenes on a board: strange attractors by density with counts a byte a
//! pixel on the stack, and curves in Bézier's smooth strokes.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use tinyfractal::error::DrawError;

use crate::catalogue::Scene;
use crate::look::{Look, Work};
#[cfg(feature = "dynamics")]
use crate::look::{MAX_BOARD_DENSITY_PIXELS, MAX_DISPLAY_DENSITY_PIXELS};

impl Scene {
    /// Draws a dynamics scene (a strange attractor) as [`Scene::draw`] does, without
    /// reaching the other families' code; `None` for any other scene.
    pub fn draw_dynamics<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        self.draw_dynamics_frames(target, look, || {})
    }

    /// [`draw_dynamics`](Self::draw_dynamics), calling `between_frames` after each frame of
    /// an animated scene (the particles).
    pub fn draw_dynamics_frames<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
        between_frames: impl FnMut(),
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        #[cfg(feature = "dynamics")]
        return match *self {
            Scene::Attractor { kind, points } => Some(draw_attractor(target, look, kind, points)),
            Scene::Bezier { curves } => Some(draw_bezier(target, look, curves)),
            Scene::Particles { preset, frames } => Some(draw_particles(
                target,
                look,
                (preset, frames),
                between_frames,
            )),
            _ => None,
        };
        // Without the `dynamics` feature a dynamics scene is the background: no work done.
        #[cfg(not(feature = "dynamics"))]
        {
            let _ = between_frames;
            let nothing = match *self {
                Scene::Attractor { .. } => Work::Points(0),
                Scene::Bezier { .. } => Work::Segments(0),
                Scene::Particles { .. } => Work::ParticleSteps(0),
                _ => return None,
            };
            Some(
                target
                    .clear(look.background)
                    .map(|()| nothing)
                    .map_err(DrawError::Target),
            )
        }
    }
}

/// The most particles a board's pool holds: 128 (2.5 KiB, and as much again for the last
/// frame's squares).
pub const MAX_BOARD_PARTICLES: usize = 128;

/// `preset`'s system on the whole of `target` from its start, `frames` ticks, a frame each:
/// the target cleared once, then each frame erasing the last one's particles; their age
/// through the look's gradient. The work is the particle-steps.
#[cfg(feature = "dynamics")]
#[inline(never)]
fn draw_particles<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    (preset, frames): (tinyfractal::particles::Preset, u32),
    mut between_frames: impl FnMut(),
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::particles::{Frames, ParticleLook};
    let size = target.bounding_box().size;
    let sizes = preset.sizes(size.height);
    let particle_look = ParticleLook {
        palette: look.gradient::<16>()?,
        size_at_birth: sizes.birth,
        size_at_death: sizes.death,
    };
    let mut system = preset.system::<MAX_BOARD_PARTICLES>(size, 1);
    let mut drawn = Frames::<MAX_BOARD_PARTICLES>::new();
    target.clear(look.background).map_err(DrawError::Target)?;
    let mut steps = 0;
    for _ in 0..frames {
        steps += system.step(1);
        drawn
            .draw(&system, &particle_look, look.background, target)
            .map_err(DrawError::Target)?;
        between_frames();
    }
    Ok(Work::ParticleSteps(steps))
}

/// `kind`'s attractor by density over the whole of `target`, `points` points, the hit
/// counts' levels through the look's gradient.
#[cfg(feature = "dynamics")]
#[inline(never)]
fn draw_attractor<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    kind: tinyfractal::attractor::Kind,
    points: u64,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let area = target.bounding_box();
    let pixels = area.size.width as usize * area.size.height as usize;
    // The OLED's buffer where it is enough, a full display's (the Pico's and the DISCO's
    // 320×240, 75 KiB on their stacks) otherwise.
    if pixels <= MAX_BOARD_DENSITY_PIXELS {
        count_attractor::<D, MAX_BOARD_DENSITY_PIXELS>(target, look, kind, points)
    } else {
        count_attractor::<D, MAX_DISPLAY_DENSITY_PIXELS>(target, look, kind, points)
    }
}

/// [`draw_attractor`] with `N` counts at most, out of line: its buffer is on the stack
/// only while it draws.
#[cfg(feature = "dynamics")]
#[inline(never)]
fn count_attractor<D, const N: usize>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    kind: tinyfractal::attractor::Kind,
    points: u64,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::attractor::{Attractor, AttractorPicture};
    let mut counts = [0u8; N];
    let stats = AttractorPicture::new(Attractor::new(kind), points)
        .fit_density(target.bounding_box(), look.gradient::<16>()?, &mut counts)?
        .try_draw(target)?;
    Ok(Work::Points(stats.points))
}

/// The design's size: curves are given in a 320×240 picture.
const DESIGN: (i32, i32) = (320, 240);

/// Where a point of a 320×240 curve design lands in `area`: scaled by the tighter of
/// width/320 and height/240, centred.
pub fn design_placement(area: Rectangle) -> impl Fn((i16, i16)) -> Point {
    let (width, height) = (area.size.width as i32, area.size.height as i32);
    // The scale num/den: the tighter of width/320 and height/240.
    let (num, den) = if width * DESIGN.1 <= height * DESIGN.0 {
        (width, DESIGN.0)
    } else {
        (height, DESIGN.1)
    };
    let offset = Point::new(
        (width - DESIGN.0 * num / den) / 2,
        (height - DESIGN.1 * num / den) / 2,
    );
    move |(x, y): (i16, i16)| {
        area.top_left + offset + Point::new(i32::from(x) * num / den, i32::from(y) * num / den)
    }
}

/// `curves` (a 320×240 design) scaled uniformly and centred on `target`, over the look's
/// background in its ink; the work is the curves' straight pieces. Out of line: the
/// flattening's stack of halves (1.5 KiB) is on the stack only while it draws.
#[cfg(feature = "dynamics")]
#[inline(never)]
fn draw_bezier<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    curves: &[[(i16, i16); 4]],
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    use tinyfractal::bezier::Bezier;
    let area = target.bounding_box();
    target.clear(look.background).map_err(DrawError::Target)?;
    let place = design_placement(area);
    let mut segments = 0;
    for &[a, b, c, d] in curves {
        let curve = Bezier::cubic([place(a), place(b), place(c), place(d)]);
        segments += curve
            .into_stroked(look.ink)
            .draw(target)
            .map_err(DrawError::Target)?
            .segments;
    }
    Ok(Work::Segments(segments))
}
