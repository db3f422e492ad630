//! `render ifs` (the chaos game, from Fractint's `.ifs` files or inline maps) and
//! `render gingerbread` (the lecture's map).

use crate::clock::Instant;
use std::io::Write;
use std::path::PathBuf;

use crate::progress::ProgressBar;
use clap::Args;
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{ifs::IfsPicture, Gingerbread, IfsFile};

use crate::common::Common;

/// Greens for the maps of an IFS, one a map (the fern's four).
const GREENS: [Rgb888; 4] = [
    Rgb888::new(0x6B, 0x8E, 0x23),
    Rgb888::new(0x32, 0xCD, 0x32),
    Rgb888::new(0x22, 0x8B, 0x22),
    Rgb888::new(0x9A, 0xCD, 0x32),
];

/// Most points `--points-count` and `--iterations` take: a bound on a run's time (a few
/// minutes for the chaos game and its fit on a host), refused with it beyond.
pub const MAX_POINTS: u64 = 1_000_000_000;

/// From this many points a run shows its progress on a terminal (about a second's work).
const PROGRESS_FROM: u64 = 10_000_000;

/// A spinner for the fit's measuring pass (inside the engine, so its length is not seen)
/// of a run of at least [`PROGRESS_FROM`] points; `None` below.
fn measuring(points: u64) -> Option<ProgressBar> {
    (points >= PROGRESS_FROM)
        .then(|| crate::progress::spinner(&format!("measuring {points} points")))
}

/// Ends the spinner, and a bar over the draw's points where there was one.
fn drawing(measuring: Option<ProgressBar>, points: u64) -> ProgressBar {
    match measuring {
        Some(spinner) => {
            spinner.finish_and_clear();
            crate::progress::bar(points, "points")
        }
        None => ProgressBar::hidden(),
    }
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct IfsOptions {
    /// A Fractint .ifs file (with --name)
    #[arg(
        long,
        value_name = "PATH.ifs",
        requires = "name",
        conflicts_with = "map"
    )]
    file: Option<PathBuf>,
    /// The entry in the file (case-insensitive)
    #[arg(long, value_name = "NAME", requires = "file")]
    name: Option<String>,
    /// An inline map a,b,c,d,e,f,p: x' = a·x + b·y + e, y' = c·x + d·y + f, chosen with
    /// probability p (repeat for each map; the probabilities sum to 1)
    #[arg(
        long,
        value_name = "A,B,C,D,E,F,P",
        allow_hyphen_values = true,
        required_unless_present = "file"
    )]
    map: Vec<String>,
    /// Points plotted (after 100 skipped), at most 1000000000
    #[arg(long = "points-count", value_name = "N", default_value_t = 50_000,
          value_parser = clap::value_parser!(u64).range(0..=MAX_POINTS))]
    points_count: u64,
    /// Write every plotted point, `x y` (`x y z` in 3D) a line, in IFS coordinates
    #[arg(long, value_name = "TXT")]
    points: Option<PathBuf>,
    /// Colour each pixel by how many points hit it (log scale), not by map
    #[arg(long)]
    density: bool,
    /// The chaos game's seed
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u64,
    /// How a 3D IFS is seen (front, iso, perspective; 2D ones from the front)
    #[arg(long, value_name = "VIEW", value_parser = crate::common::parse_projection)]
    projection: Option<tinyfractal::render::Projection>,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct GingerbreadOptions {
    /// M in q.x = M(1 + 2L) − p.y + |p.x − L·M|
    #[arg(long, default_value_t = 40, allow_hyphen_values = true)]
    m: i64,
    /// L
    #[arg(long, default_value_t = 3, allow_hyphen_values = true)]
    l: i64,
    /// The first point X,Y
    #[arg(long, value_name = "X,Y", default_value = "115,121", value_parser = parse_point, allow_hyphen_values = true)]
    start: (i64, i64),
    /// Points plotted, at most 1000000000
    #[arg(long, value_name = "N", default_value_t = 10_000,
          value_parser = clap::value_parser!(u64).range(0..=MAX_POINTS))]
    iterations: u64,
    /// Write every point, `x y` a line, in map coordinates
    #[arg(long, value_name = "TXT")]
    points: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

fn parse_point(text: &str) -> Result<(i64, i64), String> {
    let bad = || format!("`{text}` is not X,Y in whole numbers, e.g. 115,121");
    let (x, y) = text.split_once(',').ok_or_else(bad)?;
    Ok((
        x.trim().parse().map_err(|_| bad())?,
        y.trim().parse().map_err(|_| bad())?,
    ))
}

/// `render ifs`.
pub fn render_ifs(options: &IfsOptions) -> Result<(), String> {
    crate::delivery::window_available(options.common.window)?;
    let (text, name) = match (&options.file, &options.name) {
        (Some(path), Some(name)) => (crate::files::read_text(path)?, name.clone()),
        _ => {
            let rows: Vec<String> = options.map.iter().map(|m| m.replace(',', " ")).collect();
            (
                format!("inline {{\n{}\n}}\n", rows.join("\n")),
                "inline".to_string(),
            )
        }
    };
    let failed = |e: tinyfractal::Error| format!("{name}: {e}");
    let ifs = IfsFile::new(&text)
        .entry(&name)
        .and_then(|entry| entry.ifs())
        .map_err(failed)?;
    if ifs.never_chosen() > 0 {
        crate::console::warn(&format!(
            "{name}: {} of its maps have a probability of 0 or less, or are passed by the \
             sums before them: drawn as Fractint draws them, never chosen (the last map takes \
             what the others leave)",
            ifs.never_chosen()
        ));
    }
    let mut picture = IfsPicture::new(&ifs, options.points_count).with_seed(options.seed);
    if let Some(projection) = options.projection {
        picture = picture.with_projection(projection);
    }
    let mut target = options.common.display();
    let started = Instant::now();
    let spinner = measuring(options.points_count);
    let drawn = if options.density {
        let palette = density_palette()?;
        let pixels = options.common.width() as usize * options.common.height() as usize;
        let mut counts = vec![0u16; pixels];
        // Counted in memory, then written a row at a time: the spinner runs throughout.
        let drawn = picture
            .fit_density(options.common.area(), palette, &mut counts)
            .map_err(failed)?
            .try_draw(&mut target);
        if let Some(spinner) = spinner {
            spinner.finish_and_clear();
        }
        drawn
    } else {
        let fitted = picture
            .fit(options.common.area(), &GREENS)
            .map_err(failed)?;
        let bar = drawing(spinner, options.points_count);
        let drawn = fitted.try_draw(&mut crate::progress::Ticking::new(&mut target, &bar));
        bar.finish_and_clear();
        drawn
    };
    let plotted = drawn.map_err(crate::scene::engine_error).map_err(failed)?;
    let stats = format!(
        "points={plotted} maps={} elapsed_ms={:.3}",
        ifs.len(),
        started.elapsed().as_secs_f64() * 1e3
    );
    let three_d = ifs.is_3d();
    crate::delivery::deliver(
        &options.common,
        &name.to_lowercase(),
        &target,
        |plan| {
            if let Some(path) = &options.points {
                plan.add("--points", path, move |w: &mut dyn Write| {
                    for point in picture.game() {
                        let [x, y, z] = point.map_err(std::io::Error::other)?.position;
                        if three_d {
                            writeln!(w, "{x} {y} {z}")?;
                        } else {
                            writeln!(w, "{x} {y}")?;
                        }
                    }
                    Ok(())
                });
            }
        },
        &stats,
    )
}

/// The gallery's IFS: `name` of `source`, `points` points, into `size`.
pub fn render_entry(
    source: &str,
    name: &str,
    points: u64,
    density: bool,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, u64, std::time::Duration), String> {
    let failed = |e: tinyfractal::Error| e.to_string();
    let ifs = IfsFile::new(source)
        .entry(name)
        .and_then(|entry| entry.ifs())
        .map_err(failed)?;
    let mut target = SimulatorDisplay::new(size);
    let started = Instant::now();
    let picture = IfsPicture::new(&ifs, points);
    let area = Rectangle::new(Point::zero(), size);
    let drawn = if density {
        let mut counts = vec![0u16; size.width as usize * size.height as usize];
        picture
            .fit_density(area, density_palette()?, &mut counts)
            .map_err(failed)?
            .try_draw(&mut target)
    } else {
        picture
            .fit(area, &GREENS)
            .map_err(failed)?
            .try_draw(&mut target)
    };
    let plotted = drawn.map_err(crate::scene::engine_error).map_err(failed)?;
    Ok((target, plotted, started.elapsed()))
}

/// The density pictures' greens, from dark to pale.
fn density_palette() -> Result<tinyfractal::render::Gradient<Rgb888, 16>, String> {
    let keys = [
        Rgb888::new(0x00, 0x10, 0x00),
        Rgb888::new(0x20, 0xA0, 0x20),
        Rgb888::new(0xF0, 0xFF, 0xC0),
    ];
    tinyfractal::render::Gradient::new(&keys, Rgb888::BLACK)
        .ok_or_else(|| "the density palette is empty".to_string())
}

/// `render gingerbread`.
pub fn render_gingerbread(options: &GingerbreadOptions) -> Result<(), String> {
    crate::delivery::window_available(options.common.window)?;
    let map = Gingerbread {
        m: options.m,
        l: options.l,
        start: options.start,
        iterations: options.iterations,
    };
    let failed = |e: tinyfractal::Error| format!("gingerbread: {e}");
    let mut target = options.common.display();
    let started = Instant::now();
    let spinner = measuring(options.iterations);
    let fitted = map
        .fit(options.common.area(), Rgb888::new(0xD2, 0x69, 0x1E))
        .map_err(failed)?;
    let bar = drawing(spinner, options.iterations);
    let drawn = fitted.try_draw(&mut crate::progress::Ticking::new(&mut target, &bar));
    bar.finish_and_clear();
    let plotted = drawn.map_err(crate::scene::engine_error).map_err(failed)?;
    let elapsed = started.elapsed();
    // The cycle, searched over at most 2^24 steps (two points of memory).
    let cycle = match map.cycle(1 << 24).map_err(failed)? {
        Some(cycle) => format!("period={} tail={}", cycle.period, cycle.tail),
        None => "period=none tail=none".to_string(),
    };
    let stats = format!(
        "points={plotted} {cycle} elapsed_ms={:.3}",
        elapsed.as_secs_f64() * 1e3
    );
    crate::delivery::deliver(
        &options.common,
        "gingerbread",
        &target,
        |plan| {
            if let Some(path) = &options.points {
                plan.add("--points", path, move |w: &mut dyn Write| {
                    for point in map.points() {
                        let (x, y) = point.map_err(std::io::Error::other)?;
                        writeln!(w, "{x} {y}")?;
                    }
                    Ok(())
                });
            }
        },
        &stats,
    )
}
