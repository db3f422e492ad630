//! The dynamics' scenes (strange attractors) on a board: drawn by density with counts a
//! byte a pixel on the stack.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use tinyfractal::error::DrawError;

use crate::catalogue::Scene;
use crate::look::{Look, Work};

/// The most pixels a board's density picture counts: the OLED's 128×64, a byte each
/// (8 KiB on the stack while it draws).
pub const MAX_BOARD_DENSITY_PIXELS: usize = 128 * 64;

/// The most pixels the host's catalogue density pictures count (320×240).
#[cfg(feature = "dynamics")]
const MAX_HOST_DENSITY_PIXELS: usize = 320 * 240;

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
        match *self {
            Scene::Attractor { kind, points } => Some(draw_attractor(target, look, kind, points)),
            _ => None,
        }
    }
}

/// `kind`'s attractor by density over the whole of `target`, `points` points, the hit
/// counts' levels through the look's gradient.
#[cfg(feature = "dynamics")]
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
    // A board (a target without an OS) carries only its own buffer's code.
    if pixels <= MAX_BOARD_DENSITY_PIXELS || cfg!(target_os = "none") {
        count_attractor::<D, MAX_BOARD_DENSITY_PIXELS>(target, look, kind, points)
    } else {
        count_attractor::<D, MAX_HOST_DENSITY_PIXELS>(target, look, kind, points)
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

/// Without the `dynamics` feature an attractor is the background: no points computed.
#[cfg(not(feature = "dynamics"))]
fn draw_attractor<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    _: tinyfractal::attractor::Kind,
    _: u64,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    target.clear(look.background).map_err(DrawError::Target)?;
    Ok(Work::Points(0))
}
