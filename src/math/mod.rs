//! The numbers every family shares.
//!
//! Fixed-point `Real` (the turtle's) and `Coord` (the complex plane's), their exact decimal
//! parser, wide products and rounding, divisions and roots without the library's long
//! routines, integer sines, and turn angles with their direction tables. This is also
//! where affine maps, the matrix stack and the seeded generator belong.

pub(crate) mod affine;
pub(crate) mod angle;
pub(crate) mod big;
pub(crate) mod bits;
pub(crate) mod coord;
pub(crate) mod decimal;
pub(crate) mod divide;
pub(crate) mod frame3;
pub(crate) mod log;
pub(crate) mod random;
pub(crate) mod real;
pub(crate) mod trig;
pub(crate) mod wide;

pub use affine::{Affine2, Affine3, Overflow};
pub use angle::{Angle, AngleOutOfRange, MAX_ANGLE_DIVISIONS};
pub use big::{DeepCoord, DeepParseError, DEEP_LIMBS, MAX_DECIMAL_PLACES};
pub use coord::Coord;
pub use random::{Generator, Xorshift32};
pub use real::Real;
