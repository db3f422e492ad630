//! The escape-time engine, one stage per module:
//! view (and tier) → kernel → schedule → palette → drawable.

pub(crate) mod drawing;
pub(crate) mod kernel;
pub(crate) mod perturbation;
pub(crate) mod scaled;
pub(crate) mod schedule;
pub(crate) mod series;
pub(crate) mod view;
pub(crate) mod zoom;

pub use drawing::{EscapeTime, Painter};
pub use kernel::MAX_FAST_TOLERANCE;
pub use perturbation::{ReferenceOrbit, REFERENCE_POINT_BYTES};
pub use scaled::ReferencePoint;
pub use schedule::{Algorithm, Progress, Render, RenderStats, TILE, TILE_CELLS, TILE_ROWS};
pub use view::{
    Fractal, Shading, Tier, View, MAX_ITERATIONS, MAX_SMOOTH_ITERATIONS, SMOOTH_FRACTION_BITS,
};
pub use zoom::{ReuseStats, ZoomFrame, ZoomLine, ZoomValue};
