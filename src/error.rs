//! One `Copy` error type for the whole crate, with messages that say how to fix the input.

use core::fmt;

/// Where in the source text a problem was found (1-based; `line` is 0 for text that did not
/// come from a file, such as a rule passed on the command line).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Location {
    /// 1-based line in the file, or 0 when the text was not read from a file.
    pub line: u32,
    /// 1-based column (in bytes) within the line or the inline text.
    pub column: u32,
}

impl Location {
    /// A location inside inline text (no file line).
    pub const fn column(column: u32) -> Self {
        Self { line: 0, column }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "column {}", self.column)
        } else {
            write!(f, "line {}, column {}", self.line, self.column)
        }
    }
}

/// Everything that can go wrong in tinyfractal, from reading a system to drawing it.
///
/// Each variant carries the offending value and, where the input is text, its [`Location`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Error {
    /// A `]` closes a branch that was never opened with `[`.
    UnbalancedBracket {
        /// Where the `]` is.
        at: Location,
    },
    /// A `[` is never closed by `]` in the same axiom or rule.
    UnclosedBracket {
        /// Where the `[` is.
        at: Location,
    },
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
    /// The axiom is empty or only white space.
    EmptyAxiom,
    /// The system has no angle (`Angle n` in a `.l` file).
    MissingAngle,
    /// The angle is not usable: divisions must be 1 to [`MAX_ANGLE_DIVISIONS`](crate::MAX_ANGLE_DIVISIONS).
    AngleOutOfRange {
        /// The value given.
        value: i64,
        /// Where it is.
        at: Location,
    },
    /// More rule lines than [`MAX_RULES`](crate::MAX_RULES).
    TooManyRules {
        /// The capacity.
        max: usize,
        /// Where the rule that did not fit starts.
        at: Location,
    },
    /// A rule line does not have the form `c=body` with one character `c`.
    InvalidRule {
        /// Where the rule is.
        at: Location,
    },
    /// The symbol is a command that cannot be rewritten (brackets; in Fractint files also
    /// `+ - / \ @ | ! C < >`).
    ReservedRule {
        /// The symbol.
        symbol: char,
        /// Where the rule is.
        at: Location,
    },
    /// Text follows a complete `.l` line (Fractint splits lines on spaces, tabs and `=`).
    ExtraText {
        /// Where the extra text starts.
        at: Location,
    },
    /// Only ASCII symbols are supported.
    NonAsciiSymbol {
        /// Where the character is.
        at: Location,
    },
    /// A command that takes a number (`\ / @ C < >`) has none.
    MissingNumber {
        /// The command.
        symbol: char,
        /// Where it is.
        at: Location,
    },
    /// A number is malformed or outside its allowed range.
    NumberOutOfRange {
        /// The command it belongs to.
        symbol: char,
        /// Where it is.
        at: Location,
    },
    /// An axiom or rule is longer than the walker can index (65,535 bytes).
    BodyTooLong {
        /// Where it starts.
        at: Location,
    },
    /// A `.l` entry is opened with `{` but never closed with `}`.
    UnterminatedEntry {
        /// Where the entry starts.
        at: Location,
    },
    /// A `.l` entry line is neither `Angle`, `Axiom` nor a rule.
    UnknownLine {
        /// Where it is.
        at: Location,
    },
    /// No system of that name is in the file.
    UnknownSystem,
    /// Turtle coordinates or the step left the fixed-point range.
    Overflow,
    /// The step shrank (through `@`) below what fixed point can represent with precision.
    StepUnderflow,
    /// Nothing is drawn at this order, so there is nothing to fit.
    EmptyDrawing,
    /// The target has no pixels to draw into.
    ZeroSizeTarget,
    /// The palette has no colours.
    EmptyPalette,
    /// The iteration cap is 0 or above [`MAX_ITERATIONS`](crate::MAX_ITERATIONS).
    IterationsOutOfRange {
        /// The value given.
        value: u32,
    },
    /// The view has no positive width, reaches beyond ±3.5, or a Julia parameter has |k| > 2.
    ViewOutOfRange,
    /// The pixel spacing is finer than the deepest tier resolves (2⁻⁵⁴).
    ZoomTooDeep,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::UnbalancedBracket { at } => {
                write!(f, "unbalanced `]` at {at}: remove it or add the matching `[` before it")
            }
            Self::UnclosedBracket { at } => write!(
                f,
                "`[` at {at} is never closed: add a `]` in the same axiom or rule"
            ),
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
            Self::EmptyAxiom => write!(f, "the axiom is empty: give at least one symbol"),
            Self::MissingAngle => write!(f, "the system has no angle: add a line `Angle n`"),
            Self::AngleOutOfRange { value, at } => write!(
                f,
                "angle {value} at {at} is out of range: use 1 to {} divisions of a full turn",
                crate::MAX_ANGLE_DIVISIONS
            ),
            Self::TooManyRules { max, at } => {
                write!(f, "too many rule lines (at most {max}): rule at {at} does not fit")
            }
            Self::InvalidRule { at } => write!(
                f,
                "invalid rule at {at}: write one symbol, `=`, then its replacement (`F=F+F`)"
            ),
            Self::ReservedRule { symbol, at } => write!(
                f,
                "rule at {at} rewrites `{symbol}`, a reserved command: rename the symbol"
            ),
            Self::ExtraText { at } => write!(
                f,
                "extra text at {at}: one axiom, angle or rule body per line, without spaces"
            ),
            Self::NonAsciiSymbol { at } => {
                write!(f, "non-ASCII character at {at}: symbols must be ASCII")
            }
            Self::MissingNumber { symbol, at } => {
                write!(f, "`{symbol}` at {at} needs a number after it")
            }
            Self::NumberOutOfRange { symbol, at } => write!(
                f,
                "the number after `{symbol}` at {at} is malformed or out of range"
            ),
            Self::BodyTooLong { at } => {
                write!(f, "the text at {at} is longer than 65535 bytes: split the rule")
            }
            Self::UnterminatedEntry { at } => {
                write!(f, "the entry at {at} has no closing `}}`")
            }
            Self::UnknownLine { at } => write!(
                f,
                "line {} is not `Angle n`, `Axiom s` or a rule `c=s`",
                at.line
            ),
            Self::UnknownSystem => write!(f, "no system of that name in the file"),
            Self::Overflow => write!(
                f,
                "turtle coordinates overflow the fixed-point range: lower the order or the step"
            ),
            Self::StepUnderflow => write!(
                f,
                "the step shrank below fixed-point precision (too many `@` scalings): lower the order"
            ),
            Self::EmptyDrawing => write!(f, "the system draws nothing at this order"),
            Self::ZeroSizeTarget => write!(f, "the draw target has zero width or height"),
            Self::EmptyPalette => write!(f, "the palette is empty: give at least one colour"),
            Self::IterationsOutOfRange { value } => write!(
                f,
                "max-iter {value} is out of range: use 1 to {}",
                crate::MAX_ITERATIONS
            ),
            Self::ViewOutOfRange => write!(
                f,
                "the view is out of range: the width must be positive, every point within \
                 ±3.5, and a Julia parameter at most 2 from 0"
            ),
            Self::ZoomTooDeep => write!(
                f,
                "the zoom is too deep: pixel spacing below 2^-54 is finer than the deepest tier"
            ),
        }
    }
}

impl core::error::Error for Error {}

/// An error while drawing: either the engine's own [`Error`] or the display's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawError<E> {
    /// The system could not be drawn.
    Fractal(Error),
    /// The draw target reported an error.
    Target(E),
}

impl<E> From<Error> for DrawError<E> {
    fn from(error: Error) -> Self {
        Self::Fractal(error)
    }
}

impl<E: fmt::Debug> fmt::Display for DrawError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Fractal(error) => error.fmt(f),
            Self::Target(error) => write!(f, "the draw target failed: {error:?}"),
        }
    }
}

impl<E: fmt::Debug> core::error::Error for DrawError<E> {}
