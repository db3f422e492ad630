//! The general engine's plants moving: swaying in a periodic wind (`animate sway`) and
//! growing continuously from a sapling (`animate growth` of a parametric system), each
//! frame drawn with one placement, so the plant stays rooted where it stands.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::lsystem::Wind;
use tinyfractal::{ParametricGrammar, Real};

use crate::scene::{self, DEPTH, STACK};

/// The colours the colour modules index: the entry's own, else the book's.
fn colors(entry: &[Rgb888]) -> &[Rgb888] {
    if entry.is_empty() {
        &crate::palette::BOOK
    } else {
        entry
    }
}

/// Draws one frame of `drawing` lit, with a depth buffer, onto a fresh picture.
fn frame(
    drawing: &tinyfractal::lsystem::ParametricDrawing<
        '_,
        tinyfractal::render::Colors<'_, Rgb888>,
        DEPTH,
        STACK,
    >,
    size: Size,
) -> Result<SimulatorDisplay<Rgb888>, tinyfractal::Error> {
    let mut display = SimulatorDisplay::<Rgb888>::new(size);
    let mut depth = vec![0u16; size.width as usize * size.height as usize];
    drawing
        .try_draw_lit(&mut display, Some(&mut depth))
        .map_err(scene::engine_error)?;
    Ok(display)
}

/// `frames` frames of `grammar` at `order` swaying in `wind`, a loop: fitted to the union
/// of every frame, each frame drawn in its wind.
pub(crate) fn sway(
    (grammar, entry_colors): (&ParametricGrammar, &[Rgb888]),
    order: u32,
    wind: &Wind,
    frames: u32,
    size: Size,
    mut emit: impl FnMut(SimulatorDisplay<Rgb888>) -> Result<(), String>,
) -> Result<(), String> {
    let failed = |e: tinyfractal::Error| format!("at order {order}: {e}");
    let system = tinyfractal::ParametricLSystem::<DEPTH, STACK>::new(grammar, order);
    let area = Rectangle::new(Point::zero(), size);
    let fitted = system
        .fit_in_wind(area, colors(entry_colors), wind, frames)
        .map_err(failed)?;
    for k in 0..frames {
        let tropism = wind.tropism_at(grammar.tropism(), k, frames);
        emit(frame(&fitted.with_tropism(Some(tropism)), size).map_err(failed)?)?;
    }
    Ok(())
}

/// `frames` frames of `grammar` growing from order 0 to `order`, evenly: frame k is
/// k·order/(frames − 1) orders grown, its last order's new modules that far grown in;
/// fitted to the full-grown plant.
pub(crate) fn grow(
    (grammar, entry_colors): (&ParametricGrammar, &[Rgb888]),
    order: u32,
    frames: u32,
    size: Size,
    mut emit: impl FnMut(SimulatorDisplay<Rgb888>) -> Result<(), String>,
) -> Result<(), String> {
    let failed = |e: tinyfractal::Error| format!("at order {order}: {e}");
    let system = tinyfractal::ParametricLSystem::<DEPTH, STACK>::new(grammar, order);
    let area = Rectangle::new(Point::zero(), size);
    let fitted = system.fit(area, colors(entry_colors)).map_err(failed)?;
    let last = u64::from(frames.saturating_sub(1).max(1));
    for k in 0..frames {
        // Grown k·order/last orders: order n, n − 1 + t.
        let scaled = u64::from(k) * u64::from(order);
        let (whole, part) = (scaled / last, scaled % last);
        let (n, t) = if part == 0 {
            (whole, Real::ONE)
        } else {
            (
                whole + 1,
                Real::from_ratio(part as i64, last as i64).unwrap_or(Real::ONE),
            )
        };
        let drawing = match u32::try_from(n) {
            Ok(0) | Err(_) => fitted.growing(0, Real::ONE),
            Ok(n) => fitted.growing(n, t),
        };
        emit(frame(&drawing, size).map_err(|e| format!("frame {k}: {e}"))?)?;
    }
    Ok(())
}
