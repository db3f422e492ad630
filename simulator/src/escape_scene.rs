//! Rendering an escape-time view on the host: dwells into a buffer (for `--dwell`), then
//! coloured into a simulator display.

use std::io::{self, Write};
use std::path::PathBuf;
use std::time::Duration;

use crate::clock::Instant;

use clap::{Args, ValueEnum};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    escape::{Algorithm, Inside, Outside, RenderStats, Shading, Tier},
    math::{DeepCoord, DeepParseError},
    render::{Bands, Gradient, Palette, TwoColor},
    Coord, Error, Fractal, View,
};

use crate::common::Common;
use crate::console::Failure;
use crate::palette::PaletteName;

/// `render mandelbrot`'s options, and a Julia set's view.
#[derive(Debug, Args)]
pub struct EscapeOptions {
    /// Centre of the view, RE,IM [default: -0.75,0 for the Mandelbrot set, 0,0 for a Julia
    /// set]
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    pub(crate) centre: Option<(String, String)>,
    /// Width along the real axis [default: 3.5 for the Mandelbrot set, 3.2 for a Julia set]
    #[arg(long, value_name = "W", allow_hyphen_values = true)]
    pub(crate) width: Option<String>,
    /// Iteration cap, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    pub(crate) max_iterations: u32,
    /// How pixels are scheduled
    #[arg(long, value_enum, default_value = "fast")]
    pub(crate) algorithm: AlgorithmName,
    /// The fixed-point tier (auto chooses per view)
    #[arg(long, value_enum, default_value = "auto")]
    pub(crate) precision: Precision,
    /// The colours
    #[arg(long, value_enum, default_value = "classic")]
    pub(crate) palette: PaletteName,
    /// A Fractint .map colour map (lines `R G B`, anything after the numbers a comment):
    /// dwell d takes colour d mod the map's length, the set black (instead of --palette)
    #[arg(
        long = "palette-file",
        value_name = "FILE.map",
        conflicts_with = "palette"
    )]
    pub(crate) palette_file: Option<PathBuf>,
    /// Write `W H MAXITER`, then H lines of W dwells
    #[arg(long, value_name = "TXT")]
    pub(crate) dwell: Option<PathBuf>,
    /// Fractint's inside= mode: what a point that never escapes is worth (zmag: |z|² at
    /// the cap; period: its cycle's length)
    #[arg(long, value_enum, default_value = "maxiter")]
    pub(crate) inside: InsideName,
    /// Fractint's outside= mode: what an escaping point is worth (iter: its dwell; real,
    /// imag, mult, summ, atan: from its last point)
    #[arg(long, value_enum, default_value = "iter")]
    pub(crate) outside: OutsideName,
    /// Distance estimation: escaping pixels within W pixel widths of the set are drawn as
    /// the set, so thin strands stay connected (Fractint's default 0.71)
    #[arg(long, value_name = "W", value_parser = parse_distance)]
    pub(crate) distance: Option<u16>,
    #[command(flatten)]
    pub(crate) common: Common,
}

/// `render julia`'s options.
#[derive(Debug, Args)]
pub struct JuliaOptions {
    /// The Julia parameter k, RE,IM
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = crate::common::parse_pair)]
    pub(crate) c: (String, String),
    #[command(flatten)]
    pub(crate) view: EscapeOptions,
}

/// `--inside`: Fractint's inside= modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum InsideName {
    /// The set in the palette's inside colour
    Maxiter,
    /// |z|² at the cap, times max-iter/2, plus 1
    Zmag,
    /// The length of the cycle the orbit settled into
    Period,
}

/// `--outside`: Fractint's outside= modes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OutsideName {
    /// The dwell
    Iter,
    /// The dwell + the last point's real part + 7
    Real,
    /// The dwell + its imaginary part + 7
    Imag,
    /// The dwell × real/imaginary
    Mult,
    /// The dwell + real + imaginary
    Summ,
    /// The last point's angle, in 256 steps
    Atan,
}

/// Fractint's colourings and distance estimation, as `--inside`, `--outside` and
/// `--distance` ask.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Modes {
    /// `--inside`.
    pub inside: Inside,
    /// `--outside`.
    pub outside: Outside,
    /// `--distance` in 256ths of a pixel (0: off).
    pub distance: u16,
}

impl Modes {
    /// The modes of the options.
    fn of(options: &EscapeOptions) -> Self {
        Self {
            inside: match options.inside {
                InsideName::Maxiter => Inside::MaxIter,
                InsideName::Zmag => Inside::Zmag,
                InsideName::Period => Inside::Period,
            },
            outside: match options.outside {
                OutsideName::Iter => Outside::Iter,
                OutsideName::Real => Outside::Real,
                OutsideName::Imag => Outside::Imag,
                OutsideName::Mult => Outside::Mult,
                OutsideName::Summ => Outside::Summ,
                OutsideName::Atan => Outside::Atan,
            },
            distance: options.distance.unwrap_or(0),
        }
    }

    /// `view` with these modes.
    fn apply(self, view: View) -> Result<View, Error> {
        Ok(view
            .with_outside(self.outside)?
            .with_inside(self.inside)
            .with_distance(self.distance))
    }
}

/// `--distance W`: a width above 0 and at most 255 pixels, in 256ths of a pixel.
fn parse_distance(text: &str) -> Result<u16, String> {
    let width: f64 = text
        .parse()
        .map_err(|_| format!("`{text}` is not a number (write e.g. 0.71)"))?;
    let steps = (width * 256.0).round();
    if !(1.0..=f64::from(u16::MAX)).contains(&steps) {
        return Err(format!(
            "`{text}` is out of range: give a width from 1/256 to 255 pixel widths"
        ));
    }
    Ok(steps as u16)
}

/// `--algorithm`: how the pixels are scheduled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AlgorithmName {
    /// Every pixel computed
    Exact,
    /// Boundary tracing and subdivision: far fewer pixels computed
    Fast,
}

/// `--precision`: the fixed-point tier, or `auto`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// The tier the view needs (the calibrated rule)
    Auto,
    /// Q12 in 32 bits: fast and coarse, for Cortex-M0
    Narrow,
    /// Q28 keeping products' high 32 bits: shallow views
    Medium,
    /// Q28 with 64-bit products: the full views
    Standard,
    /// Q60 with 128-bit products: zooms to a spacing of 2^-54
    Deep,
    /// Q124 with 256-bit products: deep views with long orbits
    Wide,
    /// Differences from one reference orbit: the deepest zooms
    Perturbation,
}

impl Precision {
    /// The tier forced, `None` for automatic.
    pub fn tier(self) -> Option<Tier> {
        match self {
            Self::Auto => None,
            Self::Narrow => Some(Tier::Narrow),
            Self::Medium => Some(Tier::Medium),
            Self::Standard => Some(Tier::Standard),
            Self::Deep => Some(Tier::Deep),
            Self::Wide => Some(Tier::Wide),
            Self::Perturbation => Some(Tier::Perturbation),
        }
    }
}

/// An escape-time picture as asked for, its numbers as text checked by the core: what
/// `render mandelbrot|julia` and an animation's view resolve to.
#[derive(Debug, Clone, PartialEq)]
pub struct Escape {
    /// `None` for the Mandelbrot set, the parameter `(re, im)` for a Julia set.
    pub julia: Option<(String, String)>,
    /// The view's centre (`--center`), as text.
    pub centre: (String, String),
    /// The view's width (`--width`), as text.
    pub width: String,
    /// The iteration cap (`--max-iter`).
    pub max_iterations: u32,
    /// How the pixels are scheduled (`--algorithm`).
    pub algorithm: Algorithm,
    /// `None` for automatic.
    pub tier: Option<Tier>,
    /// The colours (`--palette`).
    pub palette: PaletteName,
    /// A colour map instead (`--palette-file`).
    pub palette_file: Option<PathBuf>,
    /// The options every render takes.
    pub common: Common,
    /// Where to write the dwells (`--dwell`), if anywhere.
    pub dwell: Option<PathBuf>,
    /// Fractint's colourings and distance estimation.
    pub modes: Modes,
}

impl EscapeOptions {
    /// `render mandelbrot`: the Mandelbrot set's view drawn, with `--dwell`.
    pub fn run(self) -> Result<(), Failure> {
        Ok(render_escape(&self.escape(None))?)
    }

    /// The picture these options ask for, of the Julia set of `julia` or else the
    /// Mandelbrot set; each set's whole picture by default.
    fn escape(self, julia: Option<(String, String)>) -> Escape {
        let options = self;
        let modes = Modes::of(&options);
        let (centre, width) = match julia {
            None => (("-0.75", "0"), "3.5"),
            Some(_) => (("0", "0"), "3.2"),
        };
        Escape {
            julia,
            centre: options
                .centre
                .unwrap_or_else(|| (centre.0.to_string(), centre.1.to_string())),
            width: options.width.unwrap_or_else(|| width.to_string()),
            max_iterations: options.max_iterations,
            algorithm: match options.algorithm {
                AlgorithmName::Exact => Algorithm::Exact,
                AlgorithmName::Fast => Algorithm::Fast,
            },
            tier: options.precision.tier(),
            palette: options.palette,
            palette_file: options.palette_file,
            common: options.common,
            dwell: options.dwell,
            modes,
        }
    }
}

impl JuliaOptions {
    /// `render julia`: the Julia set's view drawn, with `--dwell`.
    pub fn run(self) -> Result<(), Failure> {
        Ok(render_escape(&self.view.escape(Some(self.c)))?)
    }
}

/// A rendered view.
#[derive(Debug)]
pub struct Rendered {
    /// The view drawn.
    pub view: View,
    /// The pixels' values (dwells, or smooth values as the view's shading says), row by row.
    pub values: Vec<u16>,
    /// How its pixels were scheduled.
    pub algorithm: Algorithm,
    /// The picture.
    pub display: SimulatorDisplay<Rgb888>,
    /// What the render did.
    pub stats: RenderStats,
    /// The time it took.
    pub elapsed: Duration,
}

/// What to render, as the user wrote it.
#[derive(Debug)]
pub struct Request<'a> {
    /// The Julia parameter as text, or `None` for the Mandelbrot set.
    pub julia: Option<(&'a str, &'a str)>,
    /// The centre as text.
    pub centre: (&'a str, &'a str),
    /// The width as text.
    pub width: &'a str,
    /// The picture's size.
    pub size: Size,
    /// The iteration cap.
    pub max_iterations: u32,
    /// How the pixels are scheduled.
    pub algorithm: Algorithm,
    /// A forced tier, or `None` for the automatic one.
    pub tier: Option<Tier>,
    /// The palette's name.
    pub palette: &'a str,
    /// A colour map file instead, if any.
    pub palette_file: Option<&'a std::path::Path>,
    /// Fractint's colourings and distance estimation.
    pub modes: Modes,
}

/// What `render mandelbrot|julia` (or an animation's view) asked for, at `size`.
pub fn request(arguments: &Escape, size: Size) -> Request<'_> {
    Request {
        julia: arguments
            .julia
            .as_ref()
            .map(|(re, im)| (re.as_str(), im.as_str())),
        centre: (&arguments.centre.0, &arguments.centre.1),
        width: &arguments.width,
        size,
        max_iterations: arguments.max_iterations,
        algorithm: arguments.algorithm,
        tier: arguments.tier,
        palette: arguments.palette.name(),
        palette_file: arguments.palette_file.as_deref(),
        modes: arguments.modes,
    }
}

/// A number the user wrote for `what` (`--center`, `--width`, `--c`), checked.
pub fn coordinate(what: &str, text: &str) -> Result<Coord, String> {
    Coord::parse(text).ok_or_else(|| not_a_number(what, text))
}

/// A `--center` or `--width` number with every digit kept (up to
/// [`MAX_DECIMAL_PLACES`](tinyfractal::math::MAX_DECIMAL_PLACES) after the point), checked.
///
/// Text that is no number, or not within ±8, gets [`coordinate`]'s message.
pub fn deep_coordinate(what: &str, text: &str) -> Result<DeepCoord, String> {
    DeepCoord::parse(text).map_err(|error| match error {
        DeepParseError::TooManyDigits { .. } => format!("{what}: `{text}`: {error}"),
        _ => not_a_number(what, text),
    })
}

/// The message for text that is not a coordinate.
fn not_a_number(what: &str, text: &str) -> String {
    format!("{what}: `{text}` is not a number between -8 and 8 (write e.g. -0.75, 1e-9 or 2.5E-3)")
}

/// The fractal of a request, checked.
fn fractal(request: &Request<'_>) -> Result<Fractal, String> {
    Ok(match request.julia {
        None => Fractal::Mandelbrot,
        Some((re, im)) => Fractal::Julia {
            re: coordinate("--c", re)?,
            im: coordinate("--c", im)?,
        },
    })
}

/// A request's view at `width` (text, as the user wrote it), and its palette.
pub fn view_at(request: &Request<'_>, width: &str) -> Result<(View, HostPalette), String> {
    let fractal = fractal(request)?;
    let centre = (
        deep_coordinate("--center", request.centre.0)?,
        deep_coordinate("--center", request.centre.1)?,
    );
    let width = deep_coordinate("--width", width)?;
    let (palette, shading) = match request.palette_file {
        Some(path) => (
            HostPalette::Map(crate::palette::read_map(path)?.into_boxed_slice()),
            Shading::Dwell,
        ),
        None => palette(request.palette)?,
    };
    let mut view = View::deep(fractal, centre, width, request.size, request.max_iterations)
        .and_then(|view| view.with_shading(shading))
        .and_then(|view| request.modes.apply(view))
        .map_err(|e: Error| e.to_string())?;
    if let Some(tier) = request.tier {
        view = view.with_tier(tier);
    }
    // Checked here, so that the size is known to fit before anything is computed.
    pixel_count(request.size)?;
    Ok((view, palette))
}

/// Checks and renders a request.
pub fn render(request: &Request<'_>) -> Result<Rendered, String> {
    let (view, palette) = view_at(request, request.width)?;
    let started = Instant::now();
    let (values, stats) = compute(view, request.algorithm)?;
    let elapsed = started.elapsed();
    let display = paint(&view, &values, &palette);
    Ok(Rendered {
        view,
        values,
        algorithm: request.algorithm,
        display,
        stats,
        elapsed,
    })
}

/// `values` (of `view`, row by row) through `palette`.
pub fn paint(view: &View, values: &[u16], palette: &HostPalette) -> SimulatorDisplay<Rgb888> {
    let mut display = SimulatorDisplay::new(view.size());
    paint_into(&mut display, view, values, palette);
    display
}

/// `values` (of `view`, row by row) through `palette` into `target`'s top-left corner.
pub fn paint_into<D>(target: &mut D, view: &View, values: &[u16], palette: &HostPalette)
where
    D: DrawTarget<Color = Rgb888, Error = core::convert::Infallible>,
{
    let inside = view.inside_value();
    let area = embedded_graphics::primitives::Rectangle::new(Point::zero(), view.size());
    if let HostPalette::Histogram(gradient) = palette {
        // The counts of every dwell, the set's included.
        let mut counts = vec![0u32; usize::from(inside) + 1];
        let equalised = tinyfractal::render::Histogram::new(
            &mut counts,
            values.iter().copied(),
            inside,
            256,
            gradient.as_ref(),
        );
        if let Ok(equalised) = equalised {
            let colours = values.iter().map(|&value| equalised.color(value, inside));
            let Ok(()) = target.fill_contiguous(&area, colours);
            return;
        }
    }
    let colours = values.iter().map(|&value| palette.color(value, inside));
    let Ok(()) = target.fill_contiguous(&area, colours);
}

fn pixel_count(size: Size) -> Result<usize, String> {
    usize::try_from(u64::from(size.width) * u64::from(size.height))
        .map_err(|_| "the picture is too large for this machine".to_string())
}

/// Every pixel's value, row by row; a perturbation view's reference orbit in a buffer
/// allocated here.
pub fn compute(view: View, algorithm: Algorithm) -> Result<(Vec<u16>, RenderStats), String> {
    let size = view.size();
    let mut values = vec![0; pixel_count(size)?];
    // Parts on every thread of the pool (see `parallel`).
    let stats = crate::parallel::render_parts(view, algorithm, &mut values)?;
    Ok((values, stats))
}

/// The `--dwell` text, streamed: `W H MAXITER`, then H lines of W dwells. Dwells, whatever
/// the palette and modes: a smooth, distance or mode picture's dwells are computed here.
pub fn write_dwells(rendered: &Rendered, out: &mut dyn Write) -> io::Result<()> {
    let size = rendered.view.size();
    let recomputed;
    let plain = rendered.view.dwells_only();
    let dwells = if plain == rendered.view {
        &rendered.values
    } else {
        recomputed = compute(plain, rendered.algorithm)
            .map_err(io::Error::other)?
            .0;
        &recomputed
    };
    writeln!(
        out,
        "{} {} {}",
        size.width,
        size.height,
        rendered.view.max_iterations()
    )?;
    for row in dwells.chunks(size.width as usize) {
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

/// The one-line `--stats` report; with ` warning=KIND` at the end (and the automatic
/// tier, where a forced one is the cause) when the picture is not exact by the tier rule:
/// see [`TierWarning`].
pub fn stats_line(rendered: &Rendered) -> String {
    let s = rendered.stats;
    let view = rendered.view;
    let warning = TierWarning::of(&view).map_or(String::new(), |warning| warning.stats(&view));
    // Perturbation also says how many iterations its series skipped and how many
    // times pixels rebased.
    let perturbed = if s.tier == Tier::Perturbation {
        format!(" skipped={} rebases={}", s.skipped, s.rebases)
    } else {
        String::new()
    };
    format!(
        "iterations={} pixels={} draw_calls={} tier={} elapsed_ms={:.3}{perturbed}{warning}",
        s.iterations,
        s.pixels,
        s.draw_calls,
        s.tier.name(),
        rendered.elapsed.as_secs_f64() * 1e3
    )
}

/// Why a view's picture is not exact by the tier rule (the render still runs: it is what
/// was asked for, and the warning says what it shows).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TierWarning {
    /// A forced tier's finest spacing is coarser than the pixels: flat or in blocks.
    CannotResolve,
    /// A forced tier where the rule picks `Wide` or perturbation for a long orbit: its
    /// bits lose dwells the automatic tier keeps.
    CannotCarry,
}

impl TierWarning {
    /// The warning for `view`, if any (the first that applies).
    pub fn of(view: &View) -> Option<Self> {
        let forced = view.tier() != view.automatic_tier();
        if !view.resolves_pixels() {
            Some(Self::CannotResolve)
        } else if forced
            && matches!(view.automatic_tier(), Tier::Wide | Tier::Perturbation)
            && view.tier() != Tier::Wide
        {
            Some(Self::CannotCarry)
        } else {
            None
        }
    }

    /// The `--stats` words: ` warning=KIND`, and the automatic tier where a forced one is
    /// the cause.
    pub fn stats(self, view: &View) -> String {
        let automatic = view.automatic_tier().name();
        match self {
            Self::CannotResolve => {
                format!(" warning=tier_cannot_resolve automatic_tier={automatic}")
            }
            Self::CannotCarry => format!(" warning=tier_cannot_carry automatic_tier={automatic}"),
        }
    }

    /// The message for stderr.
    pub fn message(self, view: &View) -> String {
        let tier = view.tier().name();
        let automatic = view.automatic_tier().name();
        let max = view.max_iterations();
        match self {
            Self::CannotResolve => format!(
                "--precision {tier} cannot tell this view's pixels apart (pixel spacing {} is \
                 below its finest, {}): the picture comes out flat or in blocks; the automatic \
                 tier for this view is {automatic} (leave out --precision)",
                view.spacing(),
                view.tier().finest_spacing()
            ),
            Self::CannotCarry => format!(
                "--precision {tier} cannot carry this view's rounding: at this pixel spacing \
                 ({}) and --max-iter {max} its bits lose dwells that {automatic} keeps, so \
                 some pixels differ from an exact orbit; the automatic tier for this view is \
                 {automatic} (leave out --precision)",
                view.spacing()
            ),
        }
    }
}

/// The palettes by name.
#[derive(Debug)]
pub enum HostPalette {
    /// A gradient over dwells or smooth values.
    Gradient(Box<Gradient<Rgb888, 256>>),
    /// A gradient over smooth values: 16 entries (sixteenths) for each of the dwell
    /// gradient's, so the same colours at whole dwells, and every shade between.
    Smooth(Box<Gradient<Rgb888, 4096>>),
    /// Alternating bands.
    Bands(Bands<'static, Rgb888>),
    /// Inside and outside, two colours.
    TwoColor(TwoColor<Rgb888>),
    /// A Fractint colour map: dwell d takes colour d mod its length, the set black.
    Map(Box<[Rgb888]>),
    /// A gradient's colours equalised over the picture's dwells when it is painted
    /// (histogram colouring); alone, the gradient.
    Histogram(Box<Gradient<Rgb888, 256>>),
}

impl HostPalette {
    /// The palette with its gradient turned by `offset` entries (colour cycling); `None`
    /// for palettes that are not gradients.
    pub fn turned(&self, offset: u16) -> Option<Self> {
        match self {
            Self::Gradient(p) => Some(Self::Gradient(Box::new(p.with_offset(offset)))),
            Self::Smooth(p) => Some(Self::Smooth(Box::new(p.with_offset(offset)))),
            Self::Bands(_) | Self::TwoColor(_) | Self::Map(_) | Self::Histogram(_) => None,
        }
    }
}

impl Palette for HostPalette {
    type Color = Rgb888;

    fn color(&self, dwell: u16, max: u16) -> Rgb888 {
        match self {
            Self::Gradient(p) => p.color(dwell, max),
            Self::Smooth(p) => p.color(dwell, max),
            Self::Bands(p) => p.color(dwell, max),
            Self::TwoColor(p) => p.color(dwell, max),
            Self::Map(colors) if dwell < max => colors
                .get(usize::from(dwell) % colors.len().max(1))
                .copied()
                .unwrap_or(Rgb888::BLACK),
            Self::Map(_) => Rgb888::BLACK,
            Self::Histogram(p) => p.color(dwell, max),
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

/// The palette called `name`, and the shading it reads: `smooth-NAME` is gradient NAME
/// over smooth values.
pub fn palette(name: &str) -> Result<(HostPalette, Shading), String> {
    let unknown = || {
        format!(
            "--palette: `{name}` is not classic, fire, gray, bands, two-color, smooth-classic, \
             smooth-fire, smooth-gray, histogram, distance-gray, distance-classic or \
             distance-fire"
        )
    };
    if let Some(gradient) = name.strip_prefix("distance-") {
        // Grey as a ramp (black at the set, grey at a pixel, white from 16 pixels on);
        // the others as their loops.
        const RAMP: [Rgb888; 4] = [
            Rgb888::new(0x00, 0x00, 0x00),
            Rgb888::new(0x80, 0x80, 0x80),
            Rgb888::WHITE,
            Rgb888::WHITE,
        ];
        let keys = match gradient {
            "gray" => &RAMP,
            other => gradient_keys(other).ok_or_else(unknown)?,
        };
        let palette = Gradient::new(keys, Rgb888::BLACK).ok_or("empty gradient")?;
        return Ok((HostPalette::Gradient(Box::new(palette)), Shading::Distance));
    }
    if let Some(gradient) = name.strip_prefix("smooth-") {
        let keys = gradient_keys(gradient).ok_or_else(unknown)?;
        let palette = Gradient::new(keys, Rgb888::BLACK).ok_or("empty gradient")?;
        return Ok((HostPalette::Smooth(Box::new(palette)), Shading::Smooth));
    }
    let palette = match name {
        "bands" => Bands::new(&BANDS, Rgb888::BLACK)
            .map(HostPalette::Bands)
            .ok_or("empty bands")?,
        "histogram" => {
            let keys = gradient_keys("classic").ok_or_else(unknown)?;
            let palette = Gradient::new(keys, Rgb888::BLACK).ok_or("empty gradient")?;
            HostPalette::Histogram(Box::new(palette))
        }
        "two-color" => HostPalette::TwoColor(TwoColor {
            inside: Rgb888::BLACK,
            outside: Rgb888::WHITE,
        }),
        gradient => {
            let keys = gradient_keys(gradient).ok_or_else(unknown)?;
            let palette = Gradient::new(keys, Rgb888::BLACK).ok_or("empty gradient")?;
            HostPalette::Gradient(Box::new(palette))
        }
    };
    Ok((palette, Shading::Dwell))
}

/// The key colours of the gradient palettes.
fn gradient_keys(name: &str) -> Option<&'static [Rgb888]> {
    const CLASSIC: [Rgb888; 5] = [
        Rgb888::new(0x00, 0x07, 0x64),
        Rgb888::new(0x20, 0x6B, 0xCB),
        Rgb888::new(0xED, 0xFF, 0xFF),
        Rgb888::new(0xFF, 0xAA, 0x00),
        Rgb888::new(0x00, 0x02, 0x00),
    ];
    const FIRE: [Rgb888; 4] = [
        Rgb888::new(0x20, 0x00, 0x00),
        Rgb888::new(0xC0, 0x20, 0x00),
        Rgb888::new(0xFF, 0xC0, 0x00),
        Rgb888::new(0xFF, 0xFF, 0xC0),
    ];
    const GRAY: [Rgb888; 2] = [Rgb888::new(0x20, 0x20, 0x20), Rgb888::WHITE];
    match name {
        "classic" => Some(&CLASSIC),
        "fire" => Some(&FIRE),
        "gray" => Some(&GRAY),
        _ => None,
    }
}

/// `render mandelbrot` and `render julia`: the view drawn, with `--dwell`.
fn render_escape(arguments: &Escape) -> Result<(), String> {
    let common = &arguments.common;
    let name = if arguments.julia.is_some() {
        "julia"
    } else {
        "mandelbrot"
    };
    let size = Size::new(common.width(), common.height());
    let request = request(arguments, size);
    crate::delivery::window_available(common.window)?;
    // Everything is computed and every output checked before anything is written.
    let rendered = render(&request).map_err(|e| format!("{name}: {e}"))?;
    if let Some(warning) = TierWarning::of(&rendered.view) {
        crate::console::warn(&warning.message(&rendered.view));
    }
    crate::delivery::deliver(
        common,
        name,
        &rendered.display,
        |plan| {
            if let Some(path) = &arguments.dwell {
                plan.add("--dwell", path, |w| write_dwells(&rendered, w));
            }
        },
        &stats_line(&rendered),
    )
}
