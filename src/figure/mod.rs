//! Object hierarchies: the lecture's articulated body.
//!
//! Parts are drawn in their parent's coordinate system, each placed by a joint (a translation to the parent's attachment
//! point, then a rotation by the joint's angle), walked depth first with a bounded stack
//! of [`Affine2`](crate::math::Affine2) maps, as `glPushMatrix`/`glPopMatrix` do.
//!
//! A [`Part`] is a shape along its local +x axis (a limb from the joint to its end), its
//! children and their attachment points. The figure is drawn as lines and circles (a
//! rectangle as its outline; a circle as every pixel its curve passes through), fitted
//! to the target like an L-system, and walked in the target's pixels: Q16.16 with
//! 32×32→64 products (a `Real` walk draws a figure whose limbs are longer than 2¹⁵
//! pixels). [`Figure::for_each_line`] gives the lines in world units, a circle as its 16
//! sides.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::figure::{walk, BODY};
//! use tinyfractal::{Figure, Real};
//!
//! // The lecture's body a quarter of the way through its walk, fitted into 64×64.
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let pose = walk(Real::from_ratio(1, 4).unwrap());
//! let lines = Figure::new(&BODY, pose)
//!     .fit(display.bounding_box(), &[BinaryColor::On])?
//!     .draw(&mut display)?;
//! assert_eq!(lines, 22); // 19 lines and 3 circles
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod body;
pub(crate) mod hierarchy;
pub(crate) mod part;
mod pixels;

pub use body::{walk, wave, Joint, BODY};
pub use hierarchy::{Figure, FigureDrawing, FigureLine};
pub use part::{Part, Pose, Shape};
