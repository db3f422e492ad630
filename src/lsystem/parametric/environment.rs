//! Open L-systems (ABOP 1.8's topiary, growth towards light): productions whose conditions
//! or parameters ask the world the plant grows in, with `env(k)`, about the turtle where
//! the module is expanded.
//!
//! The walk is depth first, so when a module is expanded the turtle has drawn everything
//! before it in the final string: it stands where the module will be drawn. The fit's walk
//! and the draw's see the same states (both in turtle units), so they choose alike. Open
//! systems are drawn with the 3D turtle (from the front unless a projection is set), and
//! do not combine with contexts (a context search expands modules ahead of the turtle).

use core::fmt;

use crate::math::Real;

/// Where the turtle is when a module is expanded, in turtle units (x right, y up, z
/// towards the viewer; the turtle starts at the origin heading up).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TurtleState {
    /// Its position.
    pub position: [Real; 3],
    /// Its heading, a unit vector.
    pub heading: [Real; 3],
}

/// The world an open L-system grows in: `env(k)` in a condition or a parameter is
/// [`query`](Self::query)`(k, turtle)`.
///
/// ```
/// use tinyfractal::{LsysFile, Real, lsystem::{Environment, Segments3, TurtleState}};
///
/// /// 1 inside a circle of radius 10 about the origin, else 0.
/// struct Circle;
///
/// impl Environment for Circle {
///     fn query(&self, _query: Real, turtle: &TurtleState) -> Real {
///         let [x, y, _] = turtle.position.map(Real::to_f64);
///         if x * x + y * y <= 100.0 { Real::ONE } else { Real::ZERO }
///     }
/// }
///
/// // A shoot that grows a step wherever its apex is inside: at y = 0, 1, ..., 10.
/// let text = "shoot {\n axiom: A\n angle: 90\n A : env(0) > 0 --> FA\n A : env(0) == 0 -->\n}\n";
/// let grammar = LsysFile::new(text).entry("shoot")?.parametric()?;
/// let steps = Segments3::<17, 16>::new(&grammar, 16)?.with_environment(&Circle).count();
/// assert_eq!(steps, 11);
/// # Ok::<(), tinyfractal::Error>(())
/// ```
pub trait Environment {
    /// The answer to query `query` (the `k` of `env(k)`) about `turtle`.
    fn query(&self, query: Real, turtle: &TurtleState) -> Real;
}

/// An environment held by a drawing (shown, not printed, by `Debug`).
#[derive(Clone, Copy)]
pub(crate) struct Held<'e>(pub(crate) &'e dyn Environment);

impl fmt::Debug for Held<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Environment")
    }
}
