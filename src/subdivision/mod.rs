//! Subdivision fractals: the lecture's Sierpiński family.
//!
//! The carpet (a square split 3×3
//! with its centre removed, recursively), the gasket (a triangle split in four with its
//! middle removed) and the cube (27 subcubes with the centre, or the centre and the six
//! face centres, removed), each drawn by index arithmetic or a bounded explicit stack,
//! never a list of cells.
//!
//! Each drawing paints every pixel of its box once (the kept cells in the ink colour, the
//! removed ones in the background colour), except the cube, which clears its box and then
//! paints faces back to front.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::Carpet;
//!
//! // The carpet at order 3 in 27×27 pixels: 8³ squares kept, (8³ − 1)/7 holes.
//! let mut display = MockDisplay::<BinaryColor>::new();
//! let area = display.bounding_box().resized(Size::new(27, 27), embedded_graphics::geometry::AnchorPoint::TopLeft);
//! let stats = Carpet::new(3)
//!     .fit(area, BinaryColor::On, BinaryColor::Off)?
//!     .draw(&mut display)?;
//! assert_eq!((stats.squares, stats.holes), (512, 73));
//! // The centre pixel lies in the largest hole.
//! assert_eq!(display.get_pixel(Point::new(13, 13)), Some(BinaryColor::Off));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod carpet;
pub(crate) mod cube;
pub(crate) mod gasket;
pub(crate) mod order;

pub use carpet::{Carpet, CarpetDrawing, CarpetStats};
pub use cube::{Camera, CubeDrawing, CubeStats, CubeVariant, SierpinskiCube};
pub use gasket::{Gasket, GasketDrawing, GasketStats};
pub use order::MAX_SUBDIVISION_ORDER;
