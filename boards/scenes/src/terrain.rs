//! Midpoint-displacement terrain on a display, with the scenes' `terrain` feature; without
//! it a terrain scene draws the background and does no work.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use tinyfractal::error::DrawError;
#[cfg(feature = "terrain")]
use tinyfractal::{terrain::Displacement, Terrain, TerrainMap};

use crate::catalogue::Scene;
#[cfg(feature = "terrain")]
use crate::look::MAX_BOARD_MAP_CELLS;
use crate::look::{Look, Work};

impl Scene {
    /// Draws a terrain as [`Scene::draw`] does, without reaching the other families'
    /// code; `None` for any other scene.
    ///
    /// A firmware that measures only the terrains calls this, so its flash holds only them.
    pub fn draw_terrain<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Option<Result<Work, DrawError<D::Error>>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            #[cfg(feature = "terrain")]
            Scene::Terrain {
                displacement,
                samples,
                map,
            } => Some(draw_terrain(target, look, displacement, samples, map)),
            // Without the `terrain` feature: the background, no work.
            #[cfg(not(feature = "terrain"))]
            Scene::Terrain { .. } => Some(
                target
                    .clear(look.background)
                    .map_err(DrawError::Target)
                    .map(|()| Work::Cells(0)),
            ),
            _ => None,
        }
    }
}

/// Midpoint-displacement terrain over the whole target: a profile in `look.ink` under a
/// `look.background` sky, or a landscape in its height bands.
#[cfg(feature = "terrain")]
fn draw_terrain<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    displacement: Displacement,
    samples: u32,
    map: bool,
) -> Result<Work, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let heights = if map {
        draw_landscape(target, displacement, samples)?
    } else {
        draw_profile(target, look, displacement, samples)?
    };
    Ok(Work::Cells(heights))
}

/// A profile, out of line: its heights (at most [`MAX_BOARD_MAP_CELLS`], as many as a
/// landscape's) are on the stack only while it draws, generated once into them. A profile
/// of one sample a column of the OLED takes a buffer of its own size, as a sketch would
/// (the whole buffer is zeroed first).
#[cfg(feature = "terrain")]
#[inline(never)]
fn draw_profile<D>(
    target: &mut D,
    look: &Look<'_, D::Color>,
    displacement: Displacement,
    samples: u32,
) -> Result<u64, DrawError<D::Error>>
where
    D: DrawTarget,
{
    let terrain = Terrain::new(samples, displacement);
    let mut draw = |heights: &mut [i32]| {
        terrain
            .fit_with_heights(target.bounding_box(), look.ink, look.background, heights)?
            .draw(target)
            .map_err(DrawError::Target)
    };
    if samples as usize <= OLED_PROFILE_SAMPLES {
        draw(&mut [0; OLED_PROFILE_SAMPLES])
    } else {
        draw(&mut [0; MAX_BOARD_MAP_CELLS])
    }
}

/// A profile of one sample a column of a 128-pixel display.
#[cfg(feature = "terrain")]
const OLED_PROFILE_SAMPLES: usize = 129;

/// A landscape, out of line: its heights (at most [`MAX_BOARD_MAP_CELLS`], 4.3 KiB) are on
/// the stack only while it draws, not while a profile does.
#[cfg(feature = "terrain")]
#[inline(never)]
fn draw_landscape<D>(
    target: &mut D,
    displacement: Displacement,
    samples: u32,
) -> Result<u64, DrawError<D::Error>>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    let mut heights = [0i32; MAX_BOARD_MAP_CELLS];
    let drawing =
        TerrainMap::new(samples, displacement).fit(target.bounding_box(), &mut heights)?;
    drawing.draw(target).map_err(DrawError::Target)
}
