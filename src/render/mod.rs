//! From numbers to pixels, for every family.
//!
//! The run rasteriser for lines, value sinks
//! (the raw layer under colour), palettes, density pictures, and fitting a picture into a target. This is
//! also where 3D projection belongs, and the relief drawing every height field shares.

pub(crate) mod circle;
pub(crate) mod density;
pub(crate) mod depth;
pub(crate) mod dither;
pub(crate) mod fit;
pub(crate) mod histogram;
pub(crate) mod last_frame;
pub(crate) mod palette;
pub(crate) mod polygon;
pub(crate) mod projection;
pub(crate) mod raster;
pub(crate) mod reach;
pub(crate) mod relief;
pub(crate) mod shade;
pub(crate) mod sink;
pub(crate) mod space;
pub(crate) mod subpixel;
pub(crate) mod thick;

pub use density::{HitCount, DENSITY_LEVELS, MIN_BLANK_RUN};
pub use dither::{Dither, Dithered, Quantize};
pub use fit::{Orientation, DEFAULT_MARGIN};
pub use histogram::Histogram;
pub use last_frame::{LastFrame, Recording};
pub use palette::{Bands, Colors, Gradient, Palette, TwoColor};
pub use projection::Projection;
pub use relief::Relief;
pub use shade::Shade;
pub use sink::{DwellBuffer, DwellSink};
pub use space::DEPTH_LEVELS;
pub use subpixel::SUBPIXEL_BITS;
