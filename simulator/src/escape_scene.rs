//! Rendering an escape-time view on the host: dwells into a buffer (for `--dwell`), then
//! coloured into a simulator display.

use std::io::{self, Write};
use std::time::{Duration, Instant};

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    Algorithm, Bands, Coord, DwellBuffer, Error, Fractal, Gradient, Palette, Render, RenderStats,
    Tier, TwoColor, View,
};

/// A rendered view.
pub struct Rendered {
    pub view: View,
    /// Dwells, row by row.
    pub dwells: Vec<u16>,
    pub display: SimulatorDisplay<Rgb888>,
    pub stats: RenderStats,
    pub elapsed: Duration,
}

/// What to render, as the user wrote it.
pub struct Request<'a> {
    pub julia: Option<(&'a str, &'a str)>,
    pub centre: (&'a str, &'a str),
    pub width: &'a str,
    pub size: Size,
    pub max_iterations: u32,
    pub algorithm: Algorithm,
    pub tier: Option<Tier>,
    pub palette: &'a str,
}

fn coordinate(what: &str, text: &str) -> Result<Coord, String> {
    Coord::parse(text).ok_or_else(|| {
        format!(
            "{what}: `{text}` is not a number between -8 and 8 (write e.g. -0.75, 1e-9 or 2.5E-3)"
        )
    })
}

/// Checks and renders a request.
pub fn render(request: &Request<'_>) -> Result<Rendered, String> {
    let fractal = match request.julia {
        None => Fractal::Mandelbrot,
        Some((re, im)) => Fractal::Julia {
            re: coordinate("--c", re)?,
            im: coordinate("--c", im)?,
        },
    };
    let centre = (
        coordinate("--center", request.centre.0)?,
        coordinate("--center", request.centre.1)?,
    );
    let width = coordinate("--width", request.width)?;
    let palette = palette(request.palette)?;
    let failed = |e: Error| e.to_string();
    let mut view =
        View::new(fractal, centre, width, request.size, request.max_iterations).map_err(failed)?;
    if let Some(tier) = request.tier {
        view = view.with_tier(tier);
    }
    let cells = usize::try_from(u64::from(request.size.width) * u64::from(request.size.height))
        .map_err(|_| "the picture is too large for this machine".to_string())?;
    let mut dwells = vec![0; cells];
    let started = Instant::now();
    let Ok(stats) = Render::new(view, request.algorithm)
        .run(&mut DwellBuffer::new(&mut dwells, request.size.width));
    let elapsed = started.elapsed();
    let mut display = SimulatorDisplay::new(request.size);
    let max = u16::try_from(request.max_iterations).unwrap_or(u16::MAX);
    let colours = dwells.iter().map(|&d| palette.color(d, max));
    let Ok(()) = display.fill_contiguous(&display.bounding_box(), colours);
    Ok(Rendered {
        view,
        dwells,
        display,
        stats,
        elapsed,
    })
}

/// The `--dwell` text, streamed: `W H MAXITER`, then H lines of W dwells.
pub fn write_dwells(rendered: &Rendered, out: &mut dyn Write) -> io::Result<()> {
    let size = rendered.view.size();
    writeln!(
        out,
        "{} {} {}",
        size.width,
        size.height,
        rendered.view.max_iterations()
    )?;
    for row in rendered.dwells.chunks(size.width as usize) {
        let mut values = row.iter();
        if let Some(first) = values.next() {
            write!(out, "{first}")?;
        }
        for value in values {
            write!(out, " {value}")?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// The one-line `--stats` report; with `warning=tier_cannot_resolve automatic_tier=NAME`
/// at the end when a forced tier cannot tell the pixels apart.
pub fn stats_line(rendered: &Rendered) -> String {
    let s = rendered.stats;
    let view = rendered.view;
    let warning = if view.resolves_pixels() {
        String::new()
    } else {
        format!(
            " warning=tier_cannot_resolve automatic_tier={}",
            view.automatic_tier().name()
        )
    };
    format!(
        "iterations={} pixels={} draw_calls={} tier={} elapsed_ms={:.3}{warning}",
        s.iterations,
        s.pixels,
        s.draw_calls,
        s.tier.name(),
        rendered.elapsed.as_secs_f64() * 1e3
    )
}

/// The warning for a forced tier whose unit is larger than the pixel spacing (the render
/// still runs: it is what was asked for, and shows why it is flat).
pub fn tier_warning(view: &View) -> Option<String> {
    if view.resolves_pixels() {
        return None;
    }
    let tier = view.tier();
    let unit = Coord::from_bits(1 << (Coord::FRAC_BITS - tier.precision_bits()));
    Some(format!(
        "--precision {} cannot tell this view's pixels apart (pixel spacing {} is below its \
         unit {unit}): the picture comes out flat or in blocks; the automatic tier for this \
         view is {} (leave out --precision)",
        tier.name(),
        view.spacing(),
        view.automatic_tier().name()
    ))
}

/// The palettes by name.
pub enum HostPalette {
    Gradient(Box<Gradient<Rgb888, 256>>),
    Bands(Bands<'static, Rgb888>),
    TwoColor(TwoColor<Rgb888>),
}

impl Palette for HostPalette {
    type Color = Rgb888;

    fn color(&self, dwell: u16, max: u16) -> Rgb888 {
        match self {
            Self::Gradient(p) => p.color(dwell, max),
            Self::Bands(p) => p.color(dwell, max),
            Self::TwoColor(p) => p.color(dwell, max),
        }
    }
}

const BANDS: [(u16, Rgb888); 5] = [
    (4, Rgb888::new(0x10, 0x10, 0x40)),
    (8, Rgb888::new(0x20, 0x40, 0xA0)),
    (16, Rgb888::new(0x40, 0xA0, 0xE0)),
    (32, Rgb888::new(0xF0, 0xF0, 0x80)),
    (64, Rgb888::new(0xF0, 0x80, 0x20)),
];

pub fn palette(name: &str) -> Result<HostPalette, String> {
    let gradient = |keys: &[Rgb888]| {
        Gradient::new(keys, Rgb888::BLACK)
            .map(|g| HostPalette::Gradient(Box::new(g)))
            .ok_or_else(|| "empty gradient".to_string())
    };
    match name {
        "classic" => gradient(&[
            Rgb888::new(0x00, 0x07, 0x64),
            Rgb888::new(0x20, 0x6B, 0xCB),
            Rgb888::new(0xED, 0xFF, 0xFF),
            Rgb888::new(0xFF, 0xAA, 0x00),
            Rgb888::new(0x00, 0x02, 0x00),
        ]),
        "fire" => gradient(&[
            Rgb888::new(0x20, 0x00, 0x00),
            Rgb888::new(0xC0, 0x20, 0x00),
            Rgb888::new(0xFF, 0xC0, 0x00),
            Rgb888::new(0xFF, 0xFF, 0xC0),
        ]),
        "gray" => gradient(&[Rgb888::new(0x20, 0x20, 0x20), Rgb888::WHITE]),
        "bands" => Bands::new(&BANDS, Rgb888::BLACK)
            .map(HostPalette::Bands)
            .ok_or_else(|| "empty bands".to_string()),
        "two-color" => Ok(HostPalette::TwoColor(TwoColor {
            inside: Rgb888::BLACK,
            outside: Rgb888::WHITE,
        })),
        other => Err(format!(
            "--palette: `{other}` is not classic, fire, gray, bands or two-color"
        )),
    }
}
