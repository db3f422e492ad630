//! The traits and vocabulary types most programs use, to import at once.
//!
//! As `embedded_graphics::prelude` does for geometry and drawing, `use tinyfractal::prelude::*;`
//! brings the two traits a target or a palette implements and the numbers and error every
//! family speaks; the families' own types stay in their modules.
//!
//! ```
//! use tinyfractal::prelude::*;
//!
//! let step: Real = Real::from_ratio(1, 2).ok_or(Error::Walk(tinyfractal::error::WalkError::Overflow))?;
//! assert_eq!(step.to_f64(), 0.5);
//! assert_eq!(Angle::parse_degrees("22.5"), Some(Angle::Degrees(Real::from_ratio(45, 2).unwrap())));
//! # Ok::<(), Error>(())
//! ```

pub use crate::error::Error;
pub use crate::math::{Angle, Coord, Real};
pub use crate::render::{DwellSink, Palette};
