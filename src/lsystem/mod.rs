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
