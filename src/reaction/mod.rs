//! Reaction–diffusion: the Gray–Scott model in fixed point, stepped on the caller's grid.
//!
//! [`GrayScott`] holds the rates (feed, kill, the two diffusion rates and Δt) as Karl Sims
//! states the model; [`Reaction`] runs it on a grid of [`Cell`]s the caller owns, with a
//! ring of three rows instead of a second grid, one [`step`](Reaction::step) at a time from
//! a main loop; [`ReactionDrawing`] shows B through a palette. Every step is integer
//! arithmetic, so a run is bit-identical on every target.
//!
//! ```
//! use tinyfractal::reaction::{Cell, Preset, Reaction, Start};
//!
//! let mut cells = [Cell::REST; 32 * 32];
//! let mut ring = [Cell::REST; Reaction::ring_len(32)];
//! let mut reaction = Reaction::new(&Preset::Mitosis.model(), (32, 32), &mut cells, &mut ring)?;
//! reaction.start(Start::Square);
//! reaction.step(100);
//! assert_eq!(reaction.steps(), 100);
//! // B has spread beyond the 4×4 square it started in.
//! let seeded = reaction.cells().iter().filter(|cell| cell.b > 0).count();
//! assert!(seeded > 16);
//! # Ok::<(), tinyfractal::Error>(())
//! ```
//!
//! Memory: 4 bytes a cell (A and B in `u16`s) and 12 bytes a column for the ring; a
//! 128×128 grid takes 64 KiB + 1.5 KiB, the OLED's 64×32 8 KiB + 0.8 KiB.

mod drawing;
mod grid;
mod model;

pub use drawing::{level_of, ReactionDrawing, LEVELS};
pub use grid::{Cell, Reaction, Start};
pub use model::{GrayScott, Preset, CELL_FRAC_BITS, ONE};
