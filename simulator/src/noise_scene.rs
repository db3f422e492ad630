//! `tinyfractal noise`: Perlin noise at points, every digit of the engine's value; and
//! `render noise`, Perlin's textures as pictures.

use std::path::PathBuf;
use std::time::Duration;

use crate::clock::Instant;

use clap::{Args, ValueEnum};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::noise::{NoiseDrawing, NoiseTexture, Octaves, Perlin, Texture, MAX_OCTAVES};
use tinyfractal::render::Gradient;
use tinyfractal::Real;
use tinyfractal_scenes::{Look, Scene};

use crate::common::Common;
use crate::console::{self, Failure};

/// A point of `--at`: 2D without a z.
type NoisePoint = (Real, Real, Option<Real>);

/// `noise`'s options.
#[derive(Debug, Args)]
pub struct NoiseOptions {
    /// A point, X,Y (2D) or X,Y,Z (3D); repeat for more
    #[arg(long = "at", value_name = "X,Y[,Z]", required = true, allow_hyphen_values = true,
          value_parser = parse_point)]
    at: Vec<NoisePoint>,
    /// The permutation: 0 is Perlin's own, any other a seeded shuffle of it
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u32,
}

impl NoiseOptions {
    /// Prints the noise at each `--at` point, one a line, in the order given: the engine's
    /// value with every digit (a multiple of 2⁻²⁹, so at most 29 decimal places).
    pub fn run(&self) -> Result<(), Failure> {
        let noise = Perlin::seeded(self.seed);
        let mut text = String::new();
        for &point in &self.at {
            // Writing into a String cannot fail.
            let _ = noise.sample(point).write_exact(&mut text);
            text.push('\n');
        }
        Ok(console::print(&text)?)
    }
}

/// `--at`'s value: two or three decimal numbers separated by commas.
fn parse_point(text: &str) -> Result<NoisePoint, String> {
    let numbers: Vec<&str> = text.split(',').map(str::trim).collect();
    let number = |part: &str| parse_real(part).map_err(|e| format!("{e} (in `{text}`)"));
    match numbers.as_slice() {
        [x, y] => Ok((number(x)?, number(y)?, None)),
        [x, y, z] => Ok((number(x)?, number(y)?, Some(number(z)?))),
        _ => Err(format!(
            "`{text}` is not X,Y or X,Y,Z: two or three numbers, e.g. 3.14,42,7"
        )),
    }
}

/// `--texture`: what the noise becomes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextureName {
    /// One octave of noise, in greys
    Perlin,
    /// Fractional Brownian motion, in greys
    Fbm,
    /// Turbulence (the sum of |noise|), in greys
    Turbulence,
    /// Musgrave's ridged multifractal, in greys
    Ridged,
    /// fBm as a sky: blue to white
    Clouds,
    /// Perlin's marble: white veins bent by turbulence
    Marble,
    /// Perlin's wood: rings of grain in browns
    Wood,
}

impl TextureName {
    /// The core's texture.
    fn texture(self) -> Texture {
        match self {
            Self::Perlin => Texture::Perlin,
            Self::Fbm => Texture::Fbm,
            Self::Turbulence => Texture::Turbulence,
            Self::Ridged => Texture::Ridged,
            Self::Clouds => Texture::Clouds,
            Self::Marble => Texture::Marble,
            Self::Wood => Texture::Wood,
        }
    }
}

/// What a texture is made of: `render noise` and `animate noise` share it.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct TextureOptions {
    /// What the noise becomes
    #[arg(long, value_enum, default_value = "fbm")]
    texture: TextureName,
    /// Octaves the sums take, 1 to 16
    #[arg(long, value_name = "N", default_value_t = 6,
          value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_OCTAVES)))]
    octaves: u32,
    /// Each octave's amplitude over the last one's, 0 to 1
    #[arg(long, value_name = "P", default_value = "0.5", value_parser = parse_real)]
    persistence: Real,
    /// Each octave's frequency over the last one's, 1 to 4
    #[arg(long, value_name = "L", default_value = "2", value_parser = parse_real)]
    lacunarity: Real,
    /// Lattice cells across the picture's width
    #[arg(long, value_name = "S", default_value = "4", value_parser = parse_real)]
    scale: Real,
    /// The permutation: 0 is Perlin's own, any other a seeded shuffle of it
    #[arg(long, value_name = "N", default_value_t = 0)]
    seed: u32,
}

/// A texture as drawn on the host: its permutation and its colours.
type HostDrawing<'a> = NoiseDrawing<'a, Gradient<Rgb888, 256>>;

impl TextureOptions {
    /// The permutation the options name.
    pub fn noise(&self) -> Perlin {
        Perlin::seeded(self.seed)
    }

    /// The texture of `noise` over `area` at depth `z` (the plane if `None`), in its host
    /// colours; a message naming the bad parameter otherwise.
    pub fn drawing<'a>(
        &self,
        noise: &'a Perlin,
        z: Option<Real>,
        area: Rectangle,
    ) -> Result<HostDrawing<'a>, String> {
        let octaves = Octaves {
            octaves: self.octaves,
            persistence: self.persistence,
            lacunarity: self.lacunarity,
        };
        let mut texture = NoiseTexture::new(noise, self.texture.texture())
            .with_octaves(octaves)
            .with_scale(self.scale);
        if let Some(z) = z {
            texture = texture.with_z(z);
        }
        let palette = Gradient::<Rgb888, 256>::new(keys(self.texture.texture()), Rgb888::BLACK)
            .ok_or_else(|| "noise: the texture has no colours".to_string())?;
        texture
            .fit(area, palette)
            .map_err(|e| format!("noise: {e}"))
    }
}

/// `render noise`'s options.
#[derive(Debug, Args)]
pub struct RenderNoiseOptions {
    #[command(flatten)]
    texture: TextureOptions,
    /// Depth in 3D noise (default: the plane, 2D noise)
    #[arg(long, value_name = "Z", allow_hyphen_values = true, value_parser = parse_real)]
    z: Option<Real>,
    /// Write `W H`, then H lines of W values in [0, 1] (each pixel's, before the palette)
    #[arg(long, value_name = "TXT")]
    values: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

impl RenderNoiseOptions {
    /// `render noise`: the texture over the picture, with `--values`.
    pub fn run(&self) -> Result<(), Failure> {
        let common = &self.common;
        crate::delivery::window_available(common.window)?;
        let noise = self.texture.noise();
        let started = Instant::now();
        let drawing = self.texture.drawing(&noise, self.z, common.area())?;
        let mut display = common.display();
        let Ok(()) = drawing.draw(&mut display);
        let (width, height) = (common.width(), common.height());
        let line = format!(
            "samples={} elapsed_ms={:.3}",
            u64::from(width) * u64::from(height),
            started.elapsed().as_secs_f64() * 1e3
        );
        let drawing = &drawing;
        Ok(crate::delivery::deliver(
            common,
            "noise",
            &display,
            |plan| {
                if let Some(path) = &self.values {
                    plan.add("--values", path, move |w| {
                        writeln!(w, "{width} {height}")?;
                        for y in 0..height {
                            let row: Vec<String> = (0..width)
                                .map(|x| drawing.value_at(x, y).to_string())
                                .collect();
                            writeln!(w, "{}", row.join(" "))?;
                        }
                        Ok(())
                    });
                }
            },
            &line,
        )?)
    }
}

/// A decimal number option (`--persistence`, `--scale`, ...).
pub(crate) fn parse_real(text: &str) -> Result<Real, String> {
    Real::parse_signed(text.trim()).ok_or_else(|| {
        format!("`{text}` is not a decimal number within ±2147483647, e.g. 0.5 or -4.2")
    })
}

/// The key colours a texture's levels run through on the host, 0 to 255.
fn keys(texture: Texture) -> &'static [Rgb888] {
    const GREYS: [Rgb888; 2] = [Rgb888::BLACK, Rgb888::WHITE];
    const SKY: [Rgb888; 3] = [
        Rgb888::new(0x1E, 0x50, 0xB4),
        Rgb888::new(0x6E, 0xA0, 0xE6),
        Rgb888::WHITE,
    ];
    const MARBLE: [Rgb888; 3] = [
        Rgb888::new(0x30, 0x30, 0x38),
        Rgb888::new(0xB0, 0xB0, 0xB8),
        Rgb888::WHITE,
    ];
    const WOOD: [Rgb888; 3] = [
        Rgb888::new(0x5A, 0x32, 0x14),
        Rgb888::new(0xA0, 0x64, 0x28),
        Rgb888::new(0xD2, 0x96, 0x50),
    ];
    match texture {
        Texture::Perlin | Texture::Fbm | Texture::Turbulence | Texture::Ridged => &GREYS,
        Texture::Clouds => &SKY,
        Texture::Marble => &MARBLE,
        Texture::Wood => &WOOD,
    }
}

/// A catalogue texture at `size`, for the gallery, in its host colours: the picture, its
/// detail and work columns, and the time it took.
pub fn render_entry(
    scene: &Scene,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, String, String, Duration), String> {
    let Scene::Noise {
        texture,
        octaves,
        seed,
        ..
    } = *scene
    else {
        return Err("not a noise scene".to_string());
    };
    let look = Look {
        background: Rgb888::BLACK,
        ink: Rgb888::WHITE,
        keys: keys(texture),
        inside: Rgb888::BLACK,
    };
    let mut display = SimulatorDisplay::new(size);
    let started = Instant::now();
    let work = scene
        .draw(&mut display, &look)
        .map_err(crate::scene::engine_error)
        .map_err(|e| e.to_string())?;
    let detail = format!("{} octaves, seed {seed}", octaves.octaves);
    let work = format!("{} {}s", work.count(), scene.work_unit());
    Ok((display, detail, work, started.elapsed()))
}
