//! The L-system engine, one stage per module:
//! grammar (and the `.l` reader) → walker → turtle → raster → drawable.

pub(crate) mod alphabet;
pub(crate) mod drawing;
pub(crate) mod fractint;
pub(crate) mod grammar;
pub(crate) mod turtle;
pub(crate) mod walker;
