//! Walking a derivation: the walker's capacities and budget, and the turtle's range.

use core::fmt;

/// A walk stopped at one of its bounds. Nothing here is a bug in the input text: each
/// message says which bound to raise or which order to lower.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum WalkError {
    /// Branches nest deeper than the turtle stack can hold.
    StackTooDeep {
        /// The stack capacity (the `STACK` const generic).
        capacity: usize,
    },
    /// The order needs more expansion levels than the walker can hold.
    OrderTooHigh {
        /// The requested order.
        order: u32,
        /// The highest order this walker supports (its `DEPTH` const generic minus one).
        max: u32,
    },
    /// The derivation needed more symbols than the budget allows.
    BudgetExhausted {
        /// The budget, in symbols read.
        budget: u64,
    },
    /// A condition or parameter asks the environment (`env(k)`) and the walk has none: open
    /// systems are drawn with an [`Environment`](crate::lsystem::Environment).
    NoEnvironment {
        /// The module whose production or parameters ask.
        symbol: char,
    },
    /// Branches nest deeper than a context-sensitive walk can keep left contexts for.
    ContextsTooDeep {
        /// The walk's `SLOTS` ([`MAX_CONTEXT_SLOTS`](crate::lsystem::MAX_CONTEXT_SLOTS) unless
        /// set): one slot per level below each open branch.
        capacity: usize,
    },
    /// An attractor's orbit left the range of its kind's fixed point.
    OrbitEscaped {
        /// The step (from the start) whose point was out of range.
        step: u64,
        /// The range: the state stays strictly within ±this.
        range: u32,
    },
    /// A polygon (`{ ... }`) has more vertices than the turtle records.
    PolygonTooLarge {
        /// The most vertices of a polygon
        /// ([`MAX_POLYGON_VERTICES`](crate::lsystem::MAX_POLYGON_VERTICES)).
        capacity: usize,
    },
    /// Polygons open inside open polygons deeper than the turtle records.
    PolygonsNestTooDeep {
        /// The most polygons open at once
        /// ([`MAX_OPEN_POLYGONS`](crate::lsystem::MAX_OPEN_POLYGONS)).
        capacity: usize,
    },
    /// A `}` with no polygon open.
    PolygonNotOpen,
    /// The string ends inside a polygon: a `{` without its `}`.
    PolygonNotClosed,
    /// Turtle coordinates or the step left the fixed-point range.
    Overflow,
    /// The step shrank (through `@`) below what fixed point can represent with precision.
    StepUnderflow,
    /// The walk starts with a step below what fixed point represents with precision: the
    /// picture is more steps across than the target has pixels by a factor of 2²⁰ or more.
    StepTooFine,
    /// A parameter expression of a parametric system cannot be evaluated.
    Arithmetic {
        /// The module whose parameters (or whose production's condition) it is.
        symbol: char,
        /// What went wrong.
        problem: Arithmetic,
    },
}

/// What went wrong evaluating an expression.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Arithmetic {
    /// Division by zero.
    DivisionByZero,
    /// A result beyond the fixed-point range (±2³¹), a power that is not a whole number
    /// from -64 to 64, or the square root of a negative number.
    OutOfRange,
    /// An expression nested deeper than the evaluation stack.
    TooDeep,
}

impl fmt::Display for WalkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::StackTooDeep { capacity } => write!(
                f,
                "branches nest deeper than the turtle stack ({capacity} levels): lower the order or raise the STACK capacity"
            ),
            Self::OrderTooHigh { order, max } => write!(
                f,
                "order {order} is too high: this walker supports orders up to {max} (raise its DEPTH capacity)"
            ),
            Self::BudgetExhausted { budget } => write!(
                f,
                "the derivation needs more than {budget} symbols, the walk's budget: lower the \
                 order (a program using the crate can set a larger budget with `with_budget`)"
            ),
            Self::NoEnvironment { symbol } => write!(
                f,
                "the productions of `{symbol}` ask their environment (`env(k)`), and there is \
                 none: draw the system with an environment (the CLI's --environment)"
            ),
            Self::ContextsTooDeep { capacity } => write!(
                f,
                "branches nest too deep to keep the left contexts of a context-sensitive system \
                 ({capacity} slots, one per level below each open branch): lower the order or raise \
                 the walk's SLOTS"
            ),
            Self::OrbitEscaped { step, range } => write!(
                f,
                "the orbit left ±{range}, the range of this attractor's fixed point, at step \
                 {step}: with these parameters (or this start, or time step) it diverges; \
                 start from the kind's defaults and change one value at a time"
            ),
            Self::Overflow => write!(
                f,
                "turtle coordinates overflow the fixed-point range: lower the order or the step"
            ),
            Self::Arithmetic { symbol, problem } => {
                let what = match problem {
                    Arithmetic::DivisionByZero => "divides by zero",
                    Arithmetic::OutOfRange => {
                        "leaves the fixed-point range (±2^31), takes a fractional power or \
                         the root of a negative number"
                    }
                    Arithmetic::TooDeep => "nests deeper than the evaluation stack",
                };
                write!(f, "a parameter expression of module `{symbol}` {what}")
            }
            Self::StepUnderflow => write!(
                f,
                "the step shrank below fixed-point precision (too many `@` scalings): lower the order"
            ),
            Self::PolygonTooLarge { capacity } => {
                write!(f, "a polygon has over {capacity} vertices: record fewer")
            }
            Self::PolygonsNestTooDeep { capacity } => {
                write!(f, "polygons nest over {capacity} deep: close each `{{` sooner")
            }
            Self::PolygonNotOpen => write!(f, "a `}}` with no `{{` open"),
            Self::PolygonNotClosed => write!(f, "a `{{` with no `}}`"),
            Self::StepTooFine => write!(
                f,
                "the picture is too many steps across for the target: one step would be under \
                 2^-20 of a pixel, below fixed-point precision; lower the order or enlarge the \
                 target"
            ),
        }
    }
}
