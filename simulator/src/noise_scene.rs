//! `tinyfractal noise`: Perlin noise at points, every digit of the engine's value.

use std::fmt::Write as _;

use clap::Args;
use tinyfractal::noise::Perlin;
use tinyfractal::Real;

use crate::console::{self, Failure};

/// A point of `--at`: 2D without a z.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NoisePoint {
    x: Real,
    y: Real,
    z: Option<Real>,
}

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
        for point in &self.at {
            let sample = match point.z {
                Some(z) => noise.noise3(point.x, point.y, z),
                None => noise.noise2(point.x, point.y),
            };
            // Writing into a String cannot fail.
            let _ = sample.write_exact(&mut text);
            text.push('\n');
        }
        Ok(console::print(&text)?)
    }
}

/// `--at`'s value: two or three decimal numbers separated by commas.
fn parse_point(text: &str) -> Result<NoisePoint, String> {
    let numbers: Vec<&str> = text.split(',').map(str::trim).collect();
    let number = |part: &str| {
        Real::parse_signed(part).ok_or_else(|| {
            let mut message = String::new();
            let _ = write!(
                message,
                "`{part}` in `{text}` is not a decimal number within ±2147483647 (e.g. -4.2)"
            );
            message
        })
    };
    match numbers.as_slice() {
        [x, y] => Ok(NoisePoint {
            x: number(x)?,
            y: number(y)?,
            z: None,
        }),
        [x, y, z] => Ok(NoisePoint {
            x: number(x)?,
            y: number(y)?,
            z: Some(number(z)?),
        }),
        _ => Err(format!(
            "`{text}` is not X,Y or X,Y,Z: two or three numbers, e.g. 3.14,42,7"
        )),
    }
}
