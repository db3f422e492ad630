//! The general L-system engine (ABOP 1.8–1.10): modules with fixed-point parameters,
//! productions with contexts, conditions and probabilities, successors whose parameters
//! are expressions of the bound ones, derived with bounded memory like every other system:
//! each frame of the walk keeps the parameters its production bound, and nothing else.
//!
//! ```text
//! axiom: B(2)A(4,4)
//! A(x,y) : y <= 3 --> A(x*2,x+y)
//! A(x,y) : y > 3  --> B(x)A(x/y,0)
//! B(x)   : x < 1  --> C
//! B(x)   : x >= 1 --> B(x-1)
//! b < a --> b                  # a context on either side, one module each
//! F(l) --> F(l*0.9) : 0.5      # stochastic: among the applicable ones, by probability
//! F(l) --> F(l*1.1) : 0.5
//! ```
//!
//! A module is rewritten by the first production for its symbol and number of parameters
//! whose contexts match and whose condition holds (when that one has a probability: one of
//! the applicable ones with probabilities, chosen by a hash of the module's place in the
//! derivation and the seed, so that every walk chooses alike); a module with none is kept.
//! A production binds its contexts' and its predecessor's parameters, in that order, at
//! most [`MAX_PARAMS`] together. Contexts are found without the string: see
//! [`context`](self::context).
//!
//! Capacities are named constants; a system beyond them is a typed error naming the limit.
//! Worst-case RAM (tested): the grammar 11.8 KiB (8 KiB of it the expression code, 16
//! bytes an instruction); a walk about 400 bytes a level of `DEPTH` (its frame of 56
//! bytes, and for contexts a left context and 4 remembered expansions) and 12.3 KiB for
//! the left contexts saved at open branches: 21 KiB for orders up to 16; context searches
//! use stack as [`context`](self::context) says.
//!
//! [`ParametricLSystem`](crate::ParametricLSystem) draws them: `F(l)`, `f(l)`, `+(a)`,
//! `-(a)` take their parameter as length and degrees.

pub(crate) mod action;
pub(crate) mod context;
pub(crate) mod draw;
pub(crate) mod environment;
pub(crate) mod expansion;
pub(crate) mod expr;
pub(crate) mod grammar;
pub(crate) mod kept;
pub(crate) mod marks;
pub(crate) mod matrix;
pub(crate) mod paint;
pub(crate) mod space;
pub(crate) mod surface;
pub(crate) mod tropism;
pub(crate) mod values;
pub(crate) mod walker;
