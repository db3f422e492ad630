//! Perlin noise: Ken Perlin's improved noise (2002) in fixed point, and fractal sums of it.
//!
//! [`Perlin`] holds a permutation (his own for seed 0, a seeded shuffle otherwise) and
//! samples 2D and 3D noise bit for bit the same on every target; [`Octaves`] sums samples
//! into fBm, turbulence or a ridged multifractal; [`NoiseTexture`] draws Perlin's textures
//! and [`NoiseTerrain`] a landscape of fBm heights, shaded like midpoint displacement's. The values are his: exact where his f64
//! code computes without rounding, within 2⁻²⁰ of it elsewhere.
//!
//! ```
//! use tinyfractal::noise::{Octaves, Perlin, Sum};
//! use tinyfractal::Real;
//!
//! let noise = Perlin::reference();
//! let half = Real::from_ratio(1, 2).unwrap();
//! // Perlin's own value at the centre of a lattice cell.
//! assert_eq!(noise.noise3(half, half, half).to_f64(), -0.25);
//! // Six octaves of fBm at a point of the plane.
//! let fbm = Octaves::default().sum(&noise, Sum::Fbm, (half, Real::from_int(3), None))?;
//! assert!(fbm.to_f64().abs() < 2.0);
//! # Ok::<(), tinyfractal::Error>(())
//! ```
//!
//! Memory: a [`Perlin`] is its 256-byte permutation; sampling takes a few words of stack,
//! and drawing a texture about 6 KiB more ([`NoiseDrawing`]).

mod drawing;
mod fractal;
mod lattice;
mod level;
mod perlin;
mod plane;
mod terrain;
mod texture;

pub use drawing::NoiseDrawing;
pub use fractal::{Octaves, Sum, MAX_OCTAVES};
pub use level::LEVELS;
pub use perlin::{Perlin, Sample, SAMPLE_FRAC_BITS};
pub use terrain::NoiseTerrain;
pub use texture::{NoiseTexture, Texture};
