//! Rendering an L-system into a simulator display, timed.

use std::io::{self, Write};
use std::time::{Duration, Instant};

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{Error, Grammar, LSystem, Orientation, Segments, WalkStats};

use crate::palette::VGA;

/// A rendered picture and what it took.
pub struct Rendered {
    pub display: SimulatorDisplay<Rgb888>,
    pub stats: WalkStats,
    pub elapsed: Duration,
}

/// Fits `grammar` at `order` into a `width`×`height` picture and draws it, heading right
/// for Fractint systems and up for ABOP ones.
pub fn render(
    grammar: &Grammar<'_>,
    order: u32,
    width: u32,
    height: u32,
) -> Result<Rendered, Error> {
    let orientation = match grammar.dialect() {
        tinyfractal::Dialect::Fractint => Orientation::Right,
        tinyfractal::Dialect::Abop => Orientation::Up,
    };
    render_oriented(grammar, order, width, height, orientation)
}

/// Like [`render`], with the first heading pointing `orientation` on screen.
pub fn render_oriented(
    grammar: &Grammar<'_>,
    order: u32,
    width: u32,
    height: u32,
    orientation: Orientation,
) -> Result<Rendered, Error> {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(width, height));
    let started = Instant::now();
    let drawing = LSystem::new(grammar, order)
        .with_orientation(orientation)
        .fit(display.bounding_box(), &VGA)?;
    let stats = drawing
        .try_draw(&mut display)
        .map_err(|error| match error {
            tinyfractal::DrawError::Fractal(error) => error,
            tinyfractal::DrawError::Target(never) => match never {},
        })?;
    Ok(Rendered {
        display,
        stats,
        elapsed: started.elapsed(),
    })
}

/// Every drawn segment, `x0 y0 x1 y1` per line, in turtle units (start at the origin,
/// heading +x, step 1, y up): the engine's fixed-point values printed exactly. Streamed:
/// a derivation of billions of segments needs no more memory than one.
pub fn write_segments(grammar: &Grammar<'_>, order: u32, out: &mut dyn Write) -> io::Result<()> {
    for segment in Segments::new(grammar, order).map_err(io::Error::other)? {
        let s = segment.map_err(io::Error::other)?;
        writeln!(out, "{} {} {} {}", s.start.x, s.start.y, s.end.x, s.end.y)?;
    }
    Ok(())
}

/// The one-line `--stats` report.
pub fn stats_line(rendered: &Rendered) -> String {
    let s = rendered.stats;
    format!(
        "segments={} max_stack={} max_depth={} symbols={} elapsed_ms={:.3}",
        s.segments,
        s.max_stack,
        s.max_depth,
        s.symbols,
        rendered.elapsed.as_secs_f64() * 1e3
    )
}
