//! Random fractals by midpoint displacement, as the lecture gives them.
//!
//! A midpoint is the
//! mean of its ends plus a normal variate N(0, σ), and σ is multiplied by the roughness r
//! at each level (r = 1/√2 is Brownian motion). A profile ([`Terrain`]) in 1D and a
//! landscape ([`TerrainMap`], diamond-square) in 2D.
//!
//! Heights are fixed point, Q16.16 in an `i32` (1/65536 of a unit); the variates come from
//! a counter-based hash of (seed, sample index) (see `math::random`), so each sample is
//! computed on its own and every target gets the same bits. σ at level j is σ·rʲ, computed
//! by repeated fixed-point products (Q32), the same on every target.
//!
//! ```
//! use tinyfractal::terrain::Displacement;
//! use tinyfractal::{Real, Terrain};
//!
//! // 65 samples of a profile with roughness 1/2 and σ = 8: the same seed, the same heights.
//! let displacement = Displacement {
//!     roughness: Real::from_ratio(1, 2).unwrap(),
//!     sigma: Real::from_int(8),
//!     seed: 7,
//! };
//! let heights = |seed| -> Result<Vec<Real>, tinyfractal::Error> {
//!     Ok(Terrain::new(65, Displacement { seed, ..displacement }).heights()?.collect())
//! };
//! let profile = heights(7)?;
//! assert_eq!(profile.len(), 65);
//! assert_eq!(profile, heights(7)?);
//! assert_ne!(profile, heights(8)?);
//! # Ok::<(), tinyfractal::Error>(())
//! ```

pub(crate) mod displacement;
pub(crate) mod map;
pub(crate) mod profile;

pub use displacement::Displacement;
pub use map::{MapDrawing, TerrainMap};
pub use profile::{Heights, ProfileDrawing, Terrain};
