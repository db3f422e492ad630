//! The L-system engine, one stage per module:
//! grammar (and the `.l` reader) → walker → turtle → raster → drawable, with the expansion
//! table beside the walker for measuring and drawing without visiting every segment.

pub(crate) mod alphabet;
pub(crate) mod choice;
pub(crate) mod drawing;
pub(crate) mod fractint;
pub(crate) mod grammar;
pub(crate) mod lsys;
pub(crate) mod parametric;
pub(crate) mod table;
pub(crate) mod turtle;
pub(crate) mod walker;

pub use alphabet::{DerivedSymbol, Dialect};
pub use drawing::{Bounds, LSystem, LSystemDrawing, Placement};
pub use fractint::{Entries, Entry, LFile, Warnings};
pub use grammar::{Grammar, MAX_NUMERIC_COMMANDS, MAX_RULES, MAX_SYMBOLS};
pub use lsys::{LsysEntries, LsysEntry, LsysFile};
pub use parametric::context::MAX_CONTEXT_SLOTS;
pub use parametric::draw::{ParametricDrawing, ParametricLSystem, ParametricSegments};
pub use parametric::environment::{Environment, TurtleState};
pub use parametric::grammar::{
    ParametricGrammar, MAX_ARGUMENTS, MAX_CONSTANTS, MAX_MODULES, MAX_PRODUCTIONS,
};
pub use parametric::space::{Segment3, Segments3};
pub use parametric::values::{DerivedModule, Values, MAX_PARAMS};
pub use parametric::walker::ParametricWalker;
pub use table::{cells_needed, Cell, MAX_BODY_NESTING};
pub use turtle::{Segment, Segments, Start, TurtlePoint, WalkStats, DEFAULT_STACK};
pub use walker::{Walker, DEFAULT_BUDGET, DEFAULT_DEPTH};
