//! L-systems, read from Fractint `.l` files, ABOP rules or `.lsys` files, and drawn.
//!
//! One stage per module: grammar (and the `.l` reader) → walker → turtle → raster → drawable, with the expansion
//! table beside the walker for measuring and drawing without visiting every segment.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::lsystem::Segments;
//! use tinyfractal::{Angle, Dialect, Grammar, LSystem, LsysFile};
//!
//! // The raw layer: the dragon's segments at order 3, in turtle units.
//! let dragon = Grammar::new(Dialect::Abop, "FX", Angle::Divisions(4))?
//!     .with_rule('X', "X+YF+")?
//!     .with_rule('Y', "-FX-Y")?;
//! assert_eq!(Segments::new(&dragon, 3)?.count(), 8);
//!
//! // A stochastic `.lsys` system: a seed draws the same plant on every target.
//! let file = LsysFile::new("bush {\n axiom: F\n angle: 25\n seed: 3\n\
//!                           F --> F[+F]F[-F]F : 0.5\n F --> F[+F]F : 0.5\n}\n");
//! let bush = file.entry("bush")?.grammar()?;
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let stats = LSystem::new(&bush, 3).fit(display.bounding_box(), &[BinaryColor::On])?.draw(&mut display)?;
//! assert!(stats.segments > 27);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod alphabet;
pub(crate) mod choice;
pub(crate) mod drawing;
pub(crate) mod fractint;
pub(crate) mod grammar;
pub(crate) mod lsys;
pub(crate) mod parametric;
pub(crate) mod pen;
pub(crate) mod segments;
pub(crate) mod sizing;
pub(crate) mod table;
pub(crate) mod turtle;
pub(crate) mod walker;

pub use alphabet::{DerivedSymbol, Dialect};
pub use drawing::{LSystem, LSystemDrawing, Placement};
pub use fractint::{Entries, Entry, LFile, Warnings};
pub use grammar::Grammar;
pub use lsys::{LsysEntries, LsysEntry, LsysFile};
pub use parametric::context::MAX_CONTEXT_SLOTS;
pub use parametric::draw::{ParametricDrawing, ParametricLSystem, ParametricSegments};
pub use parametric::environment::{Environment, TurtleState};
pub use parametric::grammar::ParametricGrammar;
pub use parametric::kept::StoredMark;
pub use parametric::marks::{Mark, Marks3, Segments3};
pub use parametric::space::Segment3;
pub use parametric::surface::{MAX_OPEN_POLYGONS, MAX_POLYGON_VERTICES};
pub use parametric::tropism::{Tropism, Wind};
pub use parametric::values::{DerivedModule, Values, MAX_PARAMS};
pub use parametric::walker::ParametricWalker;
pub use segments::{Segments, WalkStats};
pub use sizing::Bounds;
pub use table::{cells_needed, Cell, MAX_BODY_NESTING};
pub use turtle::{Segment, Start, TurtlePoint, DEFAULT_STACK};
pub use walker::{Walker, DEFAULT_BUDGET, DEFAULT_DEPTH};
