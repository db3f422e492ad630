//! Bézier curves, the lecture's smooth counterpart to fractal and articulated shapes.
//!
//! Quadratic and cubic curves are flattened by de Casteljau subdivision in fixed point to
//! within a quarter of a pixel, and drawn through the run rasteriser.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::bezier::Bezier;
//!
//! let curve = Bezier::cubic([Point::new(1, 30), Point::new(10, 0), Point::new(50, 0), Point::new(60, 30)]);
//! let mut display = MockDisplay::<BinaryColor>::new();
//! let drawn = curve.into_stroked(BinaryColor::On).draw(&mut display)?;
//! // Its ends are its first and last control points, exactly.
//! assert_eq!(display.get_pixel(Point::new(1, 30)), Some(BinaryColor::On));
//! assert_eq!(display.get_pixel(Point::new(60, 30)), Some(BinaryColor::On));
//! assert!(drawn.pixels > 60);
//! # Ok::<(), core::convert::Infallible>(())
//! ```
//!
//! Memory: a curve is its four control points; flattening keeps a stack of at most
//! [`MAX_DEPTH`] halves (64 bytes each, about 1.2 KiB) while it draws.

mod curve;
mod drawing;

pub use curve::{Bezier, Flattened, MAX_DEPTH, TOLERANCE_SUBPIXELS};
pub use drawing::{vertex_to_f64, BezierStats, StrokedBezier};
