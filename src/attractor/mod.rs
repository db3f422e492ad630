//! Strange attractors: maps iterated and flows integrated in 32-bit fixed point, drawn as
//! points or by density.
//!
//! [`Kind`] names the equations (Hénon, Clifford, de Jong, hopalong, Martin, Gumowski–Mira,
//! popcorn and Pickover's 3D map; the Lorenz and Rössler flows, by RK4 or Euler);
//! [`Attractor`] holds one with its parameters, start and time step, and iterates its
//! [`Orbit`]; [`AttractorPicture`] fits the orbit into a target and draws it. Sines come
//! from the engine's own table, so an orbit is bit-identical on every target: one golden
//! picture serves them all.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::attractor::{Attractor, AttractorPicture, Kind};
//!
//! // The Hénon map's strange attractor, 2,000 points fitted into 64×64.
//! let henon = Attractor::new(Kind::Henon);
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let stats = AttractorPicture::new(henon, 2_000)
//!     .fit(display.bounding_box(), BinaryColor::On)?
//!     .draw(&mut display)?;
//! assert_eq!((stats.points, stats.outside), (2_000, 0));
//!
//! // The orbit itself, in the attractor's units: the first point after the transient.
//! let first = henon.orbit(0, 2).nth(1).unwrap()?;
//! assert_eq!(first[0].to_f64(), 1.0); // (0, 0) → (1 − 1.4·0² + 0, 0.3·0)
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Numbers: each kind has its fixed point ([`Kind::fraction_bits`]: Hénon 2⁻²⁸ within ±8,
//! the flows 2⁻²⁴ within ±128); products are 32×32→64 bits and round down; a value that
//! leaves the range ends the orbit with [`WalkError::OrbitEscaped`](crate::error::WalkError)
//! instead of wrapping. Memory: an [`Attractor`] is under 100 bytes, an orbit a state more;
//! a density picture counts in the caller's buffer (2 bytes a pixel).

mod drawing;
mod fixed;
mod kind;
mod orbit;
mod place;
mod step;
mod value;

pub use drawing::{
    AttractorDensity, AttractorDrawing, AttractorPicture, AttractorStats, DEFAULT_SKIP, FIT_POINTS,
};
pub use kind::{Kind, Method};
pub use orbit::{Attractor, Orbit};
