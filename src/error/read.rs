//! Reading a system from text: `.l` files, axioms and rules.

use core::fmt;

use super::Location;

/// The text of a system is malformed. Each variant carries the offending value and, where
/// the input is text, its [`Location`]; the message says how to fix it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ReadError {
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
    /// The axiom is empty or only white space.
    EmptyAxiom,
    /// The system has no angle (`Angle n` in a `.l` file).
    MissingAngle,
    /// The angle is not usable: divisions must be 1 to `max`.
    AngleOutOfRange {
        /// The value given.
        value: i64,
        /// The most divisions supported ([`MAX_ANGLE_DIVISIONS`](crate::MAX_ANGLE_DIVISIONS)).
        max: u16,
        /// Where it is.
        at: Location,
    },
    /// More rule lines than a grammar holds.
    TooManyRules {
        /// The capacity ([`MAX_RULES`](crate::MAX_RULES)).
        max: usize,
        /// Where the rule that did not fit starts.
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
    /// An axiom or rule is longer than the walker can index.
    BodyTooLong {
        /// The longest body, in bytes ([`MAX_BODY_LEN`](crate::MAX_BODY_LEN)).
        max: usize,
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
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::UnbalancedBracket { at } => {
                write!(
                    f,
                    "unbalanced `]` at {at}: remove it or add the matching `[` before it"
                )
            }
            Self::UnclosedBracket { at } => write!(
                f,
                "`[` at {at} is never closed: add a `]` in the same axiom or rule"
            ),
            Self::EmptyAxiom => write!(f, "the axiom is empty: give at least one symbol"),
            Self::MissingAngle => write!(f, "the system has no angle: add a line `Angle n`"),
            Self::AngleOutOfRange { value, max, at } => write!(
                f,
                "angle {value} at {at} is out of range: use 1 to {max} divisions of a full turn"
            ),
            Self::TooManyRules { max, at } => {
                write!(
                    f,
                    "too many rule lines (at most {max}): rule at {at} does not fit"
                )
            }
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
            Self::BodyTooLong { max, at } => {
                write!(
                    f,
                    "the text at {at} is longer than {max} bytes: split the rule"
                )
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
        }
    }
}
