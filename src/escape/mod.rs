//! The escape-time engine, one stage per module:
//! view (and tier) → kernel → schedule → palette → drawable.
//!
//! ```
//! use embedded_graphics::prelude::*;
//! use tinyfractal::escape::{Algorithm, Render, Tier};
//! use tinyfractal::render::DwellBuffer;
//! use tinyfractal::{Coord, Fractal, View};
//!
//! // The dwells of the full Mandelbrot view at 64×48, into a slice, a budget at a time.
//! let view = View::new(
//!     Fractal::Mandelbrot,
//!     (Coord::parse("-0.75").unwrap(), Coord::default()),
//!     Coord::parse("3.5").unwrap(),
//!     Size::new(64, 48),
//!     100,
//! )?;
//! assert_eq!(view.tier(), Tier::Medium);
//! let mut dwells = [0u16; 64 * 48];
//! let mut sink = DwellBuffer::new(&mut dwells, 64);
//! let mut render = Render::new(view, Algorithm::Fast);
//! let Ok(mut progress) = render.step(&mut sink, 10_000);
//! while !progress.is_complete() {
//!     let Ok(next) = render.step(&mut sink, 10_000);
//!     progress = next;
//! }
//! // The middle of the main cardioid is inside: its dwell is the cap.
//! assert_eq!(dwells[24 * 64 + 40], 100);
//! # Ok::<(), tinyfractal::Error>(())
//! ```

pub(crate) mod arithmetic;
pub(crate) mod autopilot;
pub(crate) mod derivative;
pub(crate) mod distance;
pub(crate) mod drawing;
pub(crate) mod emit;
pub(crate) mod estimate;
pub(crate) mod kernel;
pub(crate) mod modes;
pub(crate) mod orbit;
pub(crate) mod perturbation;
pub(crate) mod render;
pub(crate) mod scaled;
pub(crate) mod schedule;
pub(crate) mod series;
pub(crate) mod subdivide;
pub(crate) mod tile;
pub(crate) mod trace;
pub(crate) mod view;
pub(crate) mod zoom;

pub use autopilot::{Autopilot, BACK_OUT, KEEP_RADIUS, NARROWING, STEER};
pub use drawing::{EscapeTime, Painter};
pub use kernel::MAX_FAST_TOLERANCE;
pub use modes::{Inside, Outside, PERIOD_SEARCH, PERIOD_TOLERANCE};
pub use perturbation::{ReferenceOrbit, REFERENCE_POINT_BYTES};
pub use render::{Algorithm, Progress, Render, RenderStats, TILE, TILE_CELLS, TILE_ROWS};
pub use scaled::ReferencePoint;
pub use view::{Fractal, Shading, Tier, View, DISTANCE_INSIDE, SMOOTH_FRACTION_BITS};
pub use zoom::{ReuseStats, ZoomFrame, ZoomLine, ZoomValue};
