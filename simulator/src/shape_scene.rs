//! `render carpet`, `render gasket`, `render cube` (the Sierpiński family), `render terrain`
//! and `render terrain2d` (midpoint displacement, or noise), and the gallery's entries of
//! them.
//!
//! Drawn on black, the carpet and gasket in the palette's first colour (white).

use std::io::Write;
use std::path::PathBuf;
use std::time::Duration;

use crate::clock::Instant;

use clap::{Args, ValueEnum};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    noise::{NoiseTerrain, Octaves, Perlin},
    subdivision::{Camera, CubeVariant},
    terrain::Displacement,
    Carpet, Gasket, Real, SierpinskiCube, Terrain, TerrainMap,
};
use tinyfractal_scenes::{Look, Scene, Work, CUBE_COLOUR};

use crate::common::Common;

/// Ink for the carpet, the gasket and the terrain's profile: the palette's first colour.
const INK: Rgb888 = crate::palette::VGA[0];
/// The ground under a terrain profile.
const GROUND: Rgb888 = Rgb888::new(0x55, 0x6B, 0x2F);

/// The host's look for the catalogue's scenes of these families.
const HOST: Look<'static, Rgb888> = Look {
    background: Rgb888::BLACK,
    ink: INK,
    keys: &[Rgb888::BLACK, Rgb888::WHITE],
    inside: Rgb888::BLACK,
};

#[derive(Debug, Clone, PartialEq, Args)]
pub struct OrderOptions {
    /// Levels of subdivision
    #[arg(long, value_name = "N")]
    order: u32,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Variant {
    /// Remove the central subcube (26 kept)
    Centre,
    /// Remove the centre and the six face centres (20 kept: the Menger sponge)
    Axes,
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct CubeOptions {
    /// Levels of subdivision
    #[arg(long, value_name = "N")]
    order: u32,
    /// Which subcubes a step removes
    #[arg(long, value_enum, default_value = "axes")]
    variant: Variant,
    /// The camera's azimuth and elevation in degrees (orthographic; isometric by default)
    #[arg(long, value_name = "AZ,EL", default_value = "45,35.264", allow_hyphen_values = true, value_parser = parse_camera)]
    camera: Camera,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct DisplacementOptions {
    /// σ is multiplied by this at each level, in (0, 1]: 0.7071 is Brownian motion
    #[arg(long, value_name = "R", default_value = "0.7", allow_hyphen_values = true, value_parser = parse_real)]
    roughness: Real,
    /// The first level's standard deviation
    #[arg(long, value_name = "S", default_value = "20", allow_hyphen_values = true, value_parser = parse_real)]
    sigma: Real,
    /// The seed of the normal variates
    #[arg(long, value_name = "N", default_value_t = 1)]
    seed: u64,
}

impl DisplacementOptions {
    fn displacement(&self) -> Displacement {
        Displacement {
            roughness: self.roughness,
            sigma: self.sigma,
            seed: self.seed,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct TerrainOptions {
    #[command(flatten)]
    displacement: DisplacementOptions,
    /// Heights: 2^k + 1
    #[arg(long, value_name = "N", default_value_t = 1025)]
    samples: u32,
    /// The first and last heights, fixed
    #[arg(long, value_name = "A,B", default_value = "0,0", allow_hyphen_values = true, value_parser = parse_ends)]
    ends: (Real, Real),
    /// Write the heights, one a line
    #[arg(long, value_name = "TXT")]
    heights: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct Terrain2dOptions {
    /// How the heights are made
    #[arg(long, value_enum, default_value = "displacement")]
    method: TerrainMethod,
    #[command(flatten)]
    displacement: DisplacementOptions,
    /// With --method noise: octaves of fBm, 1 to 16 [default: 6]
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=16))]
    octaves: Option<u32>,
    /// With --method noise: each octave's amplitude over the last one's, 0 to 1 [default: 0.5]
    #[arg(long, value_name = "P", value_parser = parse_real)]
    persistence: Option<Real>,
    /// With --method noise: each octave's frequency over the last one's, 1 to 4 [default: 2]
    #[arg(long, value_name = "L", value_parser = parse_real)]
    lacunarity: Option<Real>,
    /// With --method noise: lattice cells across the landscape [default: 4]
    #[arg(long, value_name = "S", value_parser = parse_real)]
    scale: Option<Real>,
    /// Heights along a side: 2^k + 1
    #[arg(long, value_name = "N", default_value_t = 257)]
    samples: u32,
    /// Tile: opposite edges equal, the square step wrapping around
    #[arg(long)]
    wrap: bool,
    /// Write the heights, one row a line
    #[arg(long, value_name = "TXT")]
    heights: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

/// `render terrain2d --method`: where a landscape's heights come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TerrainMethod {
    /// Midpoint displacement (diamond-square), the lecture's
    Displacement,
    /// fBm of Perlin noise (--octaves, --persistence, --lacunarity, --scale, --seed)
    Noise,
}

fn parse_real(text: &str) -> Result<Real, String> {
    Real::parse_signed(text.trim())
        .ok_or_else(|| format!("`{text}` is not a number: write e.g. 0.7, 20 or 2.5e-1"))
}

fn parse_ends(text: &str) -> Result<(Real, Real), String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("`{text}` is not A,B: write e.g. 0,10"))?;
    Ok((parse_real(a)?, parse_real(b)?))
}

fn parse_camera(text: &str) -> Result<Camera, String> {
    let (azimuth, elevation) = text
        .split_once(',')
        .ok_or_else(|| format!("`{text}` is not AZ,EL in degrees: write e.g. 45,35.264"))?;
    Ok(Camera {
        azimuth: parse_real(azimuth)?,
        elevation: parse_real(elevation)?,
    })
}

fn milliseconds(elapsed: Duration) -> String {
    format!("elapsed_ms={:.3}", elapsed.as_secs_f64() * 1e3)
}

/// Fits (with the error prefixed by `name`), draws and times one picture into a display
/// of `--size`, then delivers it with its stats line: `counts` of what the draw returned,
/// then `elapsed_ms=`.
fn render_picture<T>(
    common: &Common,
    name: &str,
    fit: impl FnOnce(Rectangle) -> Result<T, tinyfractal::Error>,
    counts: impl FnOnce(T::Output) -> String,
) -> Result<(), String>
where
    T: Drawable<Color = Rgb888>,
{
    crate::delivery::window_available(common.window)?;
    let mut target = common.display();
    let started = Instant::now();
    let drawing = fit(common.area()).map_err(|e| format!("{name}: {e}"))?;
    let Ok(output) = drawing.draw(&mut target);
    let line = format!("{} {}", counts(output), milliseconds(started.elapsed()));
    crate::delivery::deliver(common, name, &target, |_| {}, &line)
}

/// `render carpet`.
pub fn render_carpet(options: &OrderOptions) -> Result<(), String> {
    render_picture(
        &options.common,
        "carpet",
        |area| Carpet::new(options.order).fit(area, INK, Rgb888::BLACK),
        |stats| format!("squares={} holes={}", stats.squares, stats.holes),
    )
}

/// `render gasket`.
pub fn render_gasket(options: &OrderOptions) -> Result<(), String> {
    render_picture(
        &options.common,
        "gasket",
        |area| Gasket::new(options.order).fit(area, INK, Rgb888::BLACK),
        |stats| format!("triangles={} runs={}", stats.triangles, stats.runs),
    )
}

/// `render cube`.
pub fn render_cube(options: &CubeOptions) -> Result<(), String> {
    let variant = match options.variant {
        Variant::Centre => CubeVariant::Centre,
        Variant::Axes => CubeVariant::Axes,
    };
    render_picture(
        &options.common,
        "cube",
        |area| {
            SierpinskiCube::new(options.order, variant)
                .with_camera(options.camera)
                .fit(area, CUBE_COLOUR, Rgb888::BLACK)
        },
        |stats| format!("cubes={} faces={}", stats.cubes, stats.faces),
    )
}

/// `render terrain`.
pub fn render_terrain(options: &TerrainOptions) -> Result<(), String> {
    crate::delivery::window_available(options.common.window)?;
    let failed = |e: tinyfractal::Error| format!("terrain: {e}");
    let terrain = Terrain::new(options.samples, options.displacement.displacement())
        .with_ends(options.ends.0, options.ends.1);
    let mut target = options.common.display();
    let started = Instant::now();
    // The heights kept, so they are generated once (a count past the most a profile has
    // is refused by the fit, before the buffer is used).
    let most = (1 << Terrain::MAX_LEVELS) + 1;
    let mut heights = vec![0; options.samples.min(most) as usize];
    let drawing = terrain
        .fit_with_heights(options.common.area(), GROUND, Rgb888::BLACK, &mut heights)
        .map_err(failed)?;
    let Ok(samples) = drawing.draw(&mut target);
    let (low, high) = drawing.range();
    let line = format!(
        "samples={samples} min={low} max={high} {}",
        milliseconds(started.elapsed())
    );
    crate::delivery::deliver(
        &options.common,
        "terrain",
        &target,
        |plan| {
            if let Some(path) = &options.heights {
                plan.add("--heights", path, move |w: &mut dyn Write| {
                    for height in terrain.heights().map_err(std::io::Error::other)? {
                        writeln!(w, "{height}")?;
                    }
                    Ok(())
                });
            }
        },
        &line,
    )
}

/// `render terrain2d`: a landscape by midpoint displacement or of noise.
pub fn render_terrain2d(options: &Terrain2dOptions) -> Result<(), String> {
    crate::delivery::window_available(options.common.window)?;
    let failed = |e: tinyfractal::Error| format!("terrain2d: {e}");
    let map =
        TerrainMap::new(options.samples, options.displacement.displacement()).wrapped(options.wrap);
    let noise = noise_of(options)?;
    // The buffer is the only limit: never more than the core's largest landscape, so a
    // size beyond it is refused by the core's own check, not by a failed allocation.
    let largest = (1usize << TerrainMap::MAX_LEVELS) + 1;
    let mut heights = vec![0i32; map.cells().min(largest * largest)];
    let mut target = options.common.display();
    let started = Instant::now();
    let area = options.common.area();
    let drawing = match &noise {
        None => map.fit::<Rgb888>(area, &mut heights),
        Some((noise, octaves, scale)) => NoiseTerrain::new(noise, options.samples)
            .with_octaves(*octaves)
            .with_scale(*scale)
            .fit::<Rgb888>(area, &mut heights),
    }
    .map_err(failed)?;
    let Ok(samples) = drawing.draw(&mut target);
    let (low, high) = drawing.range();
    let line = format!(
        "samples={samples} min={low} max={high} {}",
        milliseconds(started.elapsed())
    );
    let as_real = |v: i32| Real::from_bits(i64::from(v) << 16);
    let side = options.samples as usize;
    let heights = &heights;
    crate::delivery::deliver(
        &options.common,
        "terrain2d",
        &target,
        |plan| {
            if let Some(path) = &options.heights {
                plan.add("--heights", path, move |w: &mut dyn Write| {
                    for row in heights.chunks(side) {
                        let row: Vec<String> =
                            row.iter().map(|&v| as_real(v).to_string()).collect();
                        writeln!(w, "{}", row.join(" "))?;
                    }
                    Ok(())
                });
            }
        },
        &line,
    )
}

/// For `--method noise`, the permutation, octaves and scale the options name; `None` for
/// midpoint displacement. Options of the other method are refused, not ignored.
fn noise_of(options: &Terrain2dOptions) -> Result<Option<(Perlin, Octaves, Real)>, String> {
    let noise_options = [
        ("--octaves", options.octaves.is_some()),
        ("--persistence", options.persistence.is_some()),
        ("--lacunarity", options.lacunarity.is_some()),
        ("--scale", options.scale.is_some()),
    ];
    match options.method {
        TerrainMethod::Displacement => match noise_options.iter().find(|(_, given)| *given) {
            Some((name, _)) => Err(format!(
                "terrain2d: {name} applies to --method noise, not to midpoint displacement"
            )),
            None => Ok(None),
        },
        TerrainMethod::Noise => {
            let displacement = &options.displacement;
            let (roughness, sigma) = (Real::parse_decimal("0.7"), Real::parse_decimal("20"));
            if Some(displacement.roughness) != roughness
                || Some(displacement.sigma) != sigma
                || options.wrap
            {
                return Err(
                    "terrain2d: --roughness, --sigma and --wrap apply to midpoint \
                            displacement, not to --method noise"
                        .to_string(),
                );
            }
            let seed = u32::try_from(displacement.seed).map_err(|_| {
                "terrain2d: with --method noise, --seed is a permutation's, 0 to 4294967295"
                    .to_string()
            })?;
            let defaults = Octaves::default();
            let octaves = Octaves {
                octaves: options.octaves.unwrap_or(defaults.octaves),
                persistence: options.persistence.unwrap_or(defaults.persistence),
                lacunarity: options.lacunarity.unwrap_or(defaults.lacunarity),
            };
            let scale = options.scale.unwrap_or(Real::from_int(4));
            Ok(Some((Perlin::seeded(seed), octaves, scale)))
        }
    }
}

/// A catalogue scene of these families at `size`, for the gallery: the picture, its
/// detail and work columns, and the time it took.
pub fn render_entry(
    scene: &Scene,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, String, String, Duration), String> {
    let mut target = SimulatorDisplay::new(size);
    let started = Instant::now();
    let work = match *scene {
        // Landscapes larger than a board's: their buffers on the heap.
        Scene::Terrain {
            displacement,
            samples,
            map: true,
        } => {
            let map = TerrainMap::new(samples, displacement);
            let mut heights = vec![0i32; map.cells()];
            let drawing = map
                .fit::<Rgb888>(Rectangle::new(Point::zero(), size), &mut heights)
                .map_err(|e| e.to_string())?;
            let Ok(heights) = drawing.draw(&mut target);
            Work::Cells(heights)
        }
        Scene::NoiseTerrain {
            octaves,
            scale,
            seed,
            samples,
        } => {
            let noise = Perlin::seeded(seed);
            let terrain = NoiseTerrain::new(&noise, samples)
                .with_octaves(octaves)
                .with_scale(scale);
            let mut heights = vec![0i32; terrain.cells()];
            let drawing = terrain
                .fit::<Rgb888>(Rectangle::new(Point::zero(), size), &mut heights)
                .map_err(|e| e.to_string())?;
            let Ok(heights) = drawing.draw(&mut target);
            Work::Cells(heights)
        }
        _ => scene
            .draw(&mut target, &HOST)
            .map_err(crate::scene::engine_error)
            .map_err(|e| e.to_string())?,
    };
    let elapsed = started.elapsed();
    let detail = match *scene {
        Scene::Subdivision { order, .. } => format!("order {order}"),
        Scene::Terrain { samples, .. } => format!("{samples} samples"),
        Scene::NoiseTerrain { samples, seed, .. } => {
            format!("{samples} samples, noise seed {seed}")
        }
        Scene::Walk { frames } | Scene::Zoom { frames, .. } | Scene::Particles { frames, .. } => {
            format!("{frames} frames")
        }
        _ => String::new(),
    };
    let work = format!("{} {}s", work.count(), scene.work_unit());
    Ok((target, detail, work, elapsed))
}
