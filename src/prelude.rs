//! The traits and vocabulary types most programs use, to import at once.
//!
//! As `embedded_graphics::prelude` does for geometry and drawing, `use tinyfractal::prelude::*;`
//! brings the two traits a target or a palette implements and the numbers and error every
//! family speaks; the families' own types stay in their modules.
//!
//! ```
//! use tinyfractal::prelude::*;
//!
//! let degrees = Real::from_ratio(45, 2).unwrap();
//! assert_eq!(Angle::parse_degrees("22.5"), Some(Angle::Degrees(degrees)));
//! let centre: Coord = Coord::parse("-0.75").unwrap();
//! assert_eq!(centre.to_f64(), -0.75);
//! ```

pub use crate::error::Error;
pub use crate::math::{Angle, Coord, Real};
pub use crate::render::{DwellSink, Palette};
