//! `tinyfractal render attractor` and `animate attractor`: strange attractors as points or
//! by density, 3D ones projected and turned.

use crate::clock::Instant;
use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::attractor::{Attractor, AttractorPicture, AttractorStats, Kind, Method};
use tinyfractal::render::{Gradient, Projection};
use tinyfractal::Real;

use crate::common::Common;
use crate::console::Failure;
use crate::noise_scene::parse_real;

/// Most points `--points-count` takes, and most steps `--skip` takes: a bound on a run's
/// time (a few seconds a hundred million on a host).
pub const MAX_POINTS: u64 = 1_000_000_000;

/// The colour of a point (points mode).
const POINT_COLOR: Rgb888 = Rgb888::new(0xFF, 0xB0, 0x40);

/// Density's colours, from none to the most hit: night blue through orange to white.
const DENSITY_KEYS: [Rgb888; 4] = [
    Rgb888::new(0x00, 0x00, 0x10),
    Rgb888::new(0x20, 0x30, 0x90),
    Rgb888::new(0xF0, 0x90, 0x20),
    Rgb888::new(0xFF, 0xFF, 0xE0),
];

/// What an attractor is and how it is drawn: `render attractor` and `animate attractor`
/// share these.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct AttractorOptions {
    /// Which attractor
    #[arg(long, value_name = "KIND", default_value = "henon", value_parser = parse_kind)]
    kind: Kind,
    /// Its parameters a,b[,c[,d]] (as many as the kind takes; default: Fractint's or the
    /// classical ones)
    #[arg(long, value_name = "A,B,C,D", allow_hyphen_values = true, value_parser = parse_list)]
    params: Option<Numbers>,
    /// The first point, X,Y (X,Y,Z for lorenz, rossler and pickover)
    #[arg(long, value_name = "X,Y[,Z]", allow_hyphen_values = true, value_parser = parse_list)]
    start: Option<Numbers>,
    /// A flow's time step (lorenz 0.01, rossler 0.04), above 0 and at most 1
    #[arg(long, value_name = "DT", value_parser = parse_real)]
    dt: Option<Real>,
    /// How a flow is integrated
    #[arg(long, value_name = "rk4|euler", value_parser = parse_method)]
    method: Option<Method>,
    /// Points plotted (after the skipped transient), at most 1000000000
    #[arg(long = "points-count", value_name = "N", default_value_t = 100_000,
          value_parser = clap::value_parser!(u64).range(0..=MAX_POINTS))]
    points_count: u64,
    /// Steps from the start before the first plotted point (0: the start is plotted), at
    /// most 1000000000
    #[arg(long, value_name = "N", default_value_t = tinyfractal::attractor::DEFAULT_SKIP,
          value_parser = clap::value_parser!(u64).range(0..=MAX_POINTS))]
    skip: u64,
    /// Colour each pixel by how many points hit it (log scale)
    #[arg(long)]
    density: bool,
    /// How a 3D attractor is seen (front, iso, perspective; z up); 2D ones in their plane
    #[arg(long, value_name = "VIEW", value_parser = crate::common::parse_projection)]
    projection: Option<Projection>,
}

/// `render attractor`'s options.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct RenderAttractorOptions {
    #[command(flatten)]
    attractor: AttractorOptions,
    /// Turn a 3D attractor about its vertical axis, in degrees
    #[arg(long, value_name = "DEG", default_value = "0", allow_hyphen_values = true,
          value_parser = parse_real)]
    turn: Real,
    /// Write every plotted point, `x y` (`x y z` in 3D) a line, in the attractor's units,
    /// in order from the first after the skip
    #[arg(long, value_name = "TXT")]
    points: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

fn parse_kind(text: &str) -> Result<Kind, String> {
    Kind::from_name(text).ok_or_else(|| {
        let names: Vec<&str> = Kind::ALL.iter().map(|kind| kind.name()).collect();
        format!(
            "unknown attractor `{text}`: give one of {}",
            names.join(", ")
        )
    })
}

fn parse_method(text: &str) -> Result<Method, String> {
    Method::from_name(text).ok_or_else(|| format!("unknown method `{text}`: give rk4 or euler"))
}

/// A comma-separated list of numbers (`--params`, `--start`): one value to clap.
#[derive(Debug, Clone, PartialEq)]
pub struct Numbers(Vec<Real>);

fn parse_list(text: &str) -> Result<Numbers, String> {
    text.split(',')
        .map(parse_real)
        .collect::<Result<_, _>>()
        .map(Numbers)
}

impl AttractorOptions {
    /// The attractor the options describe; a usage error where they do not fit its kind.
    pub fn attractor(&self) -> Result<Attractor, Failure> {
        let kind = self.kind;
        let name = kind.name();
        let usage = |message: String| Failure::Usage(message);
        let failed = |e: tinyfractal::Error| format!("{name}: {e}");
        let mut attractor = Attractor::new(kind);
        if let Some(params) = &self.params {
            attractor = attractor.with_parameters(&params.0).map_err(failed)?;
        }
        if let Some(Numbers(start)) = &self.start {
            let dimensions = kind.dimensions();
            if start.len() != dimensions {
                let form = if dimensions == 3 { "X,Y,Z" } else { "X,Y" };
                return Err(usage(format!(
                    "--start: {name} is {dimensions}D: give {form} ({} numbers given)",
                    start.len()
                )));
            }
            let mut point = [Real::ZERO; 3];
            point[..dimensions].copy_from_slice(start);
            attractor = attractor.with_start(point).map_err(failed)?;
        }
        if !kind.is_flow() && (self.dt.is_some() || self.method.is_some()) {
            return Err(usage(format!(
                "--dt and --method are for the flows (lorenz, rossler): {name} is a map, \
                 iterated without a time step"
            )));
        }
        if let Some(dt) = self.dt {
            attractor = attractor.with_time_step(dt).map_err(failed)?;
        }
        if let Some(method) = self.method {
            attractor = attractor.with_method(method).map_err(failed)?;
        }
        Ok(attractor)
    }

    /// The picture: the attractor, its points, skip and projection, turned by `turn`°.
    pub fn picture(&self, turn: Real) -> Result<AttractorPicture, Failure> {
        let mut picture = AttractorPicture::new(self.attractor()?, self.points_count)
            .with_skip(self.skip)
            .with_turn(turn);
        if let Some(projection) = self.projection {
            picture = picture.with_projection(projection);
        }
        Ok(picture)
    }

    /// A warning where the orbit stands still (its first two plotted points are one, so
    /// every later point is too, and the picture is a single point), naming why it may.
    pub fn standing_still(&self) -> Result<Option<String>, Failure> {
        if self.points_count < 2 {
            return Ok(None);
        }
        let mut orbit = self.attractor()?.orbit(self.skip, 2);
        let (Some(Ok(first)), Some(Ok(second))) = (orbit.next(), orbit.next()) else {
            return Ok(None);
        };
        if first != second {
            return Ok(None);
        }
        let dimensions = self.kind.dimensions();
        let at: Vec<String> = first
            .iter()
            .take(dimensions)
            .map(|&v| coordinate(v))
            .collect();
        let why = if self.kind.is_flow() {
            format!(
                "an equilibrium of the flow, or a time step too small to move it in the \
                 fixed point's 2^-{} (raise --dt, or give another --start)",
                self.kind.fraction_bits()
            )
        } else {
            "a fixed point of the map (give another --start)".to_string()
        };
        Ok(Some(format!(
            "{}: the orbit stands still at ({}): each step leaves the point where it is, so \
             the picture is one point: {why}",
            self.name(),
            at.join(", ")
        )))
    }

    /// Whether the attractor is 3D.
    pub fn is_3d(&self) -> bool {
        self.kind.dimensions() == 3
    }

    /// The kind's name.
    pub fn name(&self) -> &'static str {
        self.kind.name()
    }

    /// Draws `picture` into `target` (points or density, as asked).
    pub fn draw(
        &self,
        picture: &AttractorPicture,
        target: &mut SimulatorDisplay<Rgb888>,
    ) -> Result<AttractorStats, String> {
        let name = self.name();
        let failed = |e: tinyfractal::Error| format!("{name}: {e}");
        let area = Rectangle::new(Point::zero(), target.size());
        let drawn = if self.density {
            let palette = Gradient::<Rgb888, 16>::new(&DENSITY_KEYS, Rgb888::BLACK)
                .ok_or("the density palette is empty")?;
            let mut counts = vec![0u16; area.size.width as usize * area.size.height as usize];
            picture
                .fit_density(area, palette, &mut counts)
                .map_err(failed)?
                .try_draw(target)
        } else {
            picture
                .fit(area, POINT_COLOR)
                .map_err(failed)?
                .try_draw(target)
        };
        drawn.map_err(crate::scene::engine_error).map_err(failed)
    }
}

/// Whether the picture is one colour but for at most one pixel (what an orbit that stands
/// still draws, by points or by density).
fn one_pixel_at_most(target: &SimulatorDisplay<Rgb888>) -> bool {
    let colors = || {
        let points = target.bounding_box().points();
        points.map(|p| target.get_pixel(p))
    };
    // The background: the first pixel's colour where the second has it too, else the
    // third's (one of the first two is then the odd one).
    let mut start = colors();
    let background = match (start.next(), start.next(), start.next()) {
        (Some(first), Some(second), _) if first == second => first,
        (_, _, Some(third)) => third,
        _ => return true,
    };
    colors().filter(|&c| c != background).nth(1).is_none()
}

/// A point as the `--points` file writes it: every digit of its fixed-point value.
fn coordinate(value: Real) -> String {
    format!("{}", value.to_f64())
}

impl RenderAttractorOptions {
    /// `render attractor`.
    pub fn run(&self) -> Result<(), Failure> {
        let common = &self.common;
        crate::delivery::window_available(common.window)?;
        let options = &self.attractor;
        if !options.is_3d() && self.turn != Real::ZERO {
            return Err(Failure::Usage(format!(
                "--turn turns a 3D attractor (lorenz, rossler, pickover): {} is drawn in its \
                 plane",
                options.name()
            )));
        }
        let picture = options.picture(self.turn)?;
        let mut target = common.display();
        let started = Instant::now();
        let stats = options.draw(&picture, &mut target)?;
        // A still orbit lights one pixel; only then is its start stepped again to see.
        if one_pixel_at_most(&target) {
            if let Some(still) = options.standing_still()? {
                crate::console::warn(&still);
            }
        }
        if stats.outside > 0 {
            crate::console::warn(&format!(
                "{}: {} of {} points fell outside the picture (it is fitted to the first {} \
                 points) and were left out",
                options.name(),
                stats.outside,
                stats.points,
                tinyfractal::attractor::FIT_POINTS
            ));
        }
        let line = format!(
            "points={} outside={} kind={} elapsed_ms={:.3}",
            stats.points,
            stats.outside,
            options.name(),
            started.elapsed().as_secs_f64() * 1e3
        );
        let three_d = options.is_3d();
        Ok(crate::delivery::deliver(
            common,
            options.name(),
            &target,
            |plan| {
                if let Some(path) = &self.points {
                    plan.add("--points", path, move |w: &mut dyn Write| {
                        for point in picture.orbit() {
                            let [x, y, z] = point.map_err(std::io::Error::other)?.map(coordinate);
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
            &line,
        )?)
    }
}

/// `animate attractor`'s frames: a 3D attractor turned about its vertical axis, a full
/// turn over the frames, each frame fitted afresh.
pub fn frames(
    options: &AttractorOptions,
    frames: u32,
    size: Size,
    mut emit: impl FnMut(SimulatorDisplay<Rgb888>) -> Result<(), String>,
) -> Result<String, String> {
    let mut points = 0;
    // Each frame its own turn: frames on every thread, in order.
    let make = |frame: u32| {
        let degrees = Real::from_ratio(360 * i64::from(frame), i64::from(frames.max(1)))
            .ok_or("the turn is out of range")?;
        let picture = options.picture(degrees).map_err(|e| e.to_string())?;
        let mut target = SimulatorDisplay::new(size);
        let drawn = options.draw(&picture, &mut target)?.points;
        Ok((target, drawn))
    };
    crate::parallel::frames_in_order(frames, make, |(target, drawn)| {
        points += drawn;
        emit(target)
    })?;
    Ok(format!(" points={points}"))
}

/// The gallery's attractor: `kind`'s defaults, `points` points by density into `size`.
pub fn render_entry(
    kind: Kind,
    points: u64,
    projection: Option<Projection>,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, u64, std::time::Duration), String> {
    let options = AttractorOptions {
        kind,
        params: None,
        start: None,
        dt: None,
        method: None,
        points_count: points,
        skip: tinyfractal::attractor::DEFAULT_SKIP,
        density: true,
        projection,
    };
    let picture = options.picture(Real::ZERO).map_err(|e| e.to_string())?;
    let mut target = SimulatorDisplay::new(size);
    let started = Instant::now();
    let stats = options.draw(&picture, &mut target)?;
    Ok((target, stats.points, started.elapsed()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One odd pixel anywhere, the first two included, is at most one; two are not; a
    /// uniform picture and one of a single pixel are.
    #[test]
    fn one_odd_pixel_is_at_most_one() {
        let (odd, background) = (Rgb888::WHITE, Rgb888::new(0, 0, 16));
        let picture = |size: Size, lit: &[Point]| {
            let mut target = SimulatorDisplay::new(size);
            target.clear(background).unwrap();
            for &p in lit {
                Pixel(p, odd).draw(&mut target).unwrap();
            }
            target
        };
        let size = Size::new(5, 4);
        assert!(one_pixel_at_most(&picture(size, &[])));
        for p in Rectangle::new(Point::zero(), size).points() {
            assert!(one_pixel_at_most(&picture(size, &[p])), "{p:?}");
        }
        for pair in [[0, 1], [1, 2], [0, 2], [0, 19], [7, 13]] {
            let lit = pair.map(|i| Point::new(i % 5, i / 5));
            assert!(!one_pixel_at_most(&picture(size, &lit)), "{lit:?}");
        }
        assert!(one_pixel_at_most(&picture(
            Size::new(1, 1),
            &[Point::zero()]
        )));
    }
}
