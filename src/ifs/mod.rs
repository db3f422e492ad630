//! Iterated function systems by the chaos game (the Barnsley fern, Fractint's `.ifs`
//! files), and the gingerbread man: reader → maps → chaos game → drawing.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::ifs::{Cycle, IfsPicture};
//! use tinyfractal::{Gingerbread, IfsFile};
//!
//! // The lecture's fern, 2,000 points of the chaos game fitted into 64×64.
//! let file = IfsFile::new("fern {\n 0 0 0 .16 0 0 .01\n .85 .04 -.04 .85 0 1.6 .85\n\
//!                          .2 -.26 .23 .22 0 1.6 .07\n -.15 .28 .26 .24 0 .44 .07\n}\n");
//! let fern = file.entry("fern")?.ifs()?;
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let plotted = IfsPicture::new(&fern, 2_000)
//!     .fit(display.bounding_box(), &[BinaryColor::On])?
//!     .draw(&mut display)?;
//! assert_eq!(plotted, 2_000);
//!
//! // The gingerbread man: the lecture's orbit is periodic from its start.
//! let cycle = Gingerbread::default().cycle(1_000_000)?;
//! assert_eq!(cycle, Some(Cycle { tail: 0, period: 3810 }));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod chaos;
pub(crate) mod fast;
pub(crate) mod file;
pub(crate) mod gingerbread;
pub(crate) mod maps;

/// The density levels (shared by every density picture: see [`crate::render`]).
pub use crate::render::DENSITY_LEVELS;
pub use chaos::{ChaosGame, DensityDrawing, IfsDrawing, IfsPicture, IfsPoint};
pub use fast::{FAST_MAPS, FIT_POINTS, SKIPPED};
pub use file::{IfsEntry, IfsFile};
pub use gingerbread::{Cycle, Gingerbread, GingerbreadDrawing, GingerbreadPoints, MapPoint};
pub use maps::{AffineMap, Ifs};
