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
    /// Turtle coordinates or the step left the fixed-point range.
    Overflow,
    /// The step shrank (through `@`) below what fixed point can represent with precision.
    StepUnderflow,
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
                "the derivation needs more than {budget} symbols: lower the order or raise the budget"
            ),
            Self::Overflow => write!(
                f,
                "turtle coordinates overflow the fixed-point range: lower the order or the step"
            ),
            Self::StepUnderflow => write!(
                f,
                "the step shrank below fixed-point precision (too many `@` scalings): lower the order"
            ),
        }
    }
}
