//! Reading a system from text: `.l` files, axioms and rules.

use core::fmt;

use super::location::Location;
use crate::math::AngleOutOfRange;

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
    /// The system has no axiom (`Axiom s` in a `.l` file). An empty one is valid: it draws
    /// nothing.
    MissingAxiom,
    /// The system has no angle (`Angle n` in a `.l` file).
    MissingAngle,
    /// The angle is not usable: divisions must be 1 to `max`.
    AngleOutOfRange {
        /// The value given.
        value: i64,
        /// The most divisions supported ([`MAX_ANGLE_DIVISIONS`](crate::math::MAX_ANGLE_DIVISIONS)).
        max: u16,
        /// Where it is.
        at: Location,
    },
    /// More rule lines than a grammar holds.
    TooManyRules {
        /// The capacity ([`Grammar::MAX_RULES`](crate::lsystem::Grammar::MAX_RULES)).
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
    /// A number is malformed or outside its allowed range.
    NumberOutOfRange {
        /// The command it belongs to.
        symbol: char,
        /// Where it is.
        at: Location,
    },
    /// The axiom and the rules hold more symbols than a grammar can.
    TooManySymbols {
        /// The capacity ([`Grammar::MAX_SYMBOLS`](crate::lsystem::Grammar::MAX_SYMBOLS)).
        max: usize,
        /// The first symbol that did not fit.
        at: Location,
    },
    /// More distinct numeric commands (`@0.5`, `\30`, `C12`, ...) than a grammar can hold.
    TooManyNumericCommands {
        /// The capacity ([`Grammar::MAX_NUMERIC_COMMANDS`](crate::lsystem::Grammar::MAX_NUMERIC_COMMANDS)).
        max: usize,
        /// The first one that did not fit.
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
    /// A `.l` entry reaches a line that opens another entry (`NAME {`) before its `}`.
    EntryRunsIntoNext {
        /// The line the entry starts on.
        entry: u32,
        /// The line of the next entry's `NAME {`.
        next: u32,
    },
    /// `Angle` is given a fraction; it counts divisions of a full turn.
    AngleNotWhole {
        /// Where the number is.
        at: Location,
    },
    /// A `.l` entry line is a row of numbers, as in a Fractint IFS file (`.ifs`).
    RowOfNumbers {
        /// The line.
        line: u32,
    },
    /// The file ends its lines with a lone carriage return (old Mac OS), so it reads as one
    /// line.
    OldMacLineEndings,
    /// A number (an `.lsys` angle) is malformed.
    NotANumber {
        /// Where it is.
        at: Location,
    },
    /// A colour of a `colors:` line is not `RRGGBB` in hexadecimal.
    NotAColor {
        /// Where it is.
        at: Location,
    },
    /// A `colors:` line lists more colours than the reader keeps.
    TooManyColors {
        /// The most colours it keeps.
        max: usize,
        /// Where the first colour too many is.
        at: Location,
    },
    /// A `tropism:` line is not `TX,TY,TZ E` (a direction and an elasticity).
    MalformedTropism {
        /// Where it is.
        at: Location,
    },
    /// An `.lsys` production's predecessor is not one symbol.
    NotOneSymbol {
        /// Where the predecessor is.
        at: Location,
    },
    /// A parameter expression is malformed.
    Expression {
        /// Where it goes wrong.
        at: Location,
    },
    /// An expression names something that is neither a parameter nor a constant.
    UnknownName {
        /// Where the name is.
        at: Location,
    },
    /// A module has more parameters than a grammar holds.
    TooManyParameters {
        /// The capacity ([`MAX_PARAMS`](crate::lsystem::MAX_PARAMS)).
        max: usize,
        /// Where the module is.
        at: Location,
    },
    /// A stochastic production's probability is below 2⁻¹⁵ or above 3.99.
    ProbabilityOutOfRange {
        /// Where the production is.
        at: Location,
    },
    /// A line of an `.ifs` entry has the wrong number of numbers.
    WrongColumnCount {
        /// 7 for a 2D entry, 13 for a 3D one.
        expected: usize,
        /// The numbers on the line.
        found: usize,
        /// Where the line's first number is.
        at: Location,
    },
    /// An IFS has more maps than it can hold.
    TooManyMaps {
        /// The capacity ([`Ifs::MAX_MAPS`](crate::ifs::Ifs::MAX_MAPS)).
        max: usize,
        /// Where the map that did not fit is.
        at: Location,
    },
    /// An `.ifs` entry has no maps.
    NoMaps {
        /// Where the entry is.
        at: Location,
    },
    /// A module has a number of parameters no production for its symbol takes.
    WrongArity {
        /// The module's symbol.
        symbol: char,
        /// Its parameters.
        found: u8,
        /// What a production for it takes.
        expected: u8,
        /// Where the module is.
        at: Location,
    },
    /// The probabilities of one left side's productions do not sum to 1.
    ProbabilitiesDoNotSum {
        /// What they sum to.
        sum: crate::math::Real,
        /// Where the first of them is.
        at: Location,
    },
    /// One symbol has both stochastic alternatives and plain (appending) productions.
    MixedProductions {
        /// The symbol.
        symbol: char,
        /// Where the production that does not fit is.
        at: Location,
    },
    /// An `.lsys` production uses notation the plain reader
    /// ([`LsysEntry::grammar`](crate::lsystem::LsysEntry::grammar)) does not take: read it with
    /// [`LsysEntry::parametric`](crate::lsystem::LsysEntry::parametric).
    Unsupported {
        /// What it uses.
        feature: Unsupported,
        /// Where.
        at: Location,
    },
}

/// Notation of `.lsys` productions that only the general reader
/// ([`LsysEntry::parametric`](crate::lsystem::LsysEntry::parametric)) takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Unsupported {
    /// `lc < pred > rc`.
    Context,
    /// `pred : condition -->`.
    Condition,
    /// Modules with parameters, `A(x)`.
    Parameters,
    /// A second production for the same predecessor (which needs conditions or
    /// probabilities to choose between them).
    SecondProduction,
    /// An open system (`env(k)`) with contexts: no reader takes them together.
    EnvironmentWithContext,
    /// A context in a homomorphism's production (`homomorphism:`): the homomorphism
    /// rewrites each module alone.
    ContextInHomomorphism,
}

impl Unsupported {
    const fn describe(self) -> &'static str {
        match self {
            Self::Context => "context-sensitive productions (`lc < pred > rc`)",
            Self::Condition => "conditions (`pred : cond --> ...`)",
            Self::Parameters => "modules with parameters (`A(x)`)",
            Self::SecondProduction => "a second production for one predecessor",
            Self::EnvironmentWithContext => {
                "an environment (`env(k)`) in a system with contexts (`lc < pred > rc`)"
            }
            Self::ContextInHomomorphism => "a context in a homomorphism",
        }
    }
}

/// Something a `.l` entry does that Fractint accepted but is most often a mistake.
///
/// It is drawn as Fractint drew it, with a warning: a missing `}`, for one (see
/// [`Entry::warnings`](crate::lsystem::Entry::warnings)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ReadWarning {
    /// A second `Axiom` line: the last one counts.
    RepeatedAxiom {
        /// The line of the first.
        first: u32,
        /// The line of this one.
        again: u32,
    },
    /// A second `Angle` line: the last one counts.
    RepeatedAngle {
        /// The line of the first.
        first: u32,
        /// The line of this one.
        again: u32,
    },
    /// A `U {` line: a rule rewriting `U` to `{` (which draws nothing).
    BraceRule {
        /// The symbol.
        symbol: char,
        /// The line.
        line: u32,
    },
    /// A lone `{` line: a rule for the symbol `{`, rewriting it to nothing.
    LoneBrace {
        /// The line.
        line: u32,
    },
}

impl fmt::Display for ReadWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::RepeatedAxiom { first, again } => write!(
                f,
                "line {again} is a second `Axiom` (the first is on line {first}): the last \
                 one counts, as in Fractint; is a `}}` missing before line {again}?"
            ),
            Self::RepeatedAngle { first, again } => write!(
                f,
                "line {again} is a second `Angle` (the first is on line {first}): the last \
                 one counts, as in Fractint; is a `}}` missing before line {again}?"
            ),
            Self::BraceRule { symbol, line } => write!(
                f,
                "line {line} reads as a rule rewriting `{symbol}` to `{{`, as in Fractint; \
                 is a `}}` missing before it?"
            ),
            Self::LoneBrace { line } => write!(
                f,
                "line {line}, a lone `{{`, reads as a rule for the symbol `{{`, as in \
                 Fractint; is a `}}` missing before it?"
            ),
        }
    }
}

impl ReadError {
    /// The number layer's [`AngleOutOfRange`] at the place the angle was read.
    pub(crate) fn angle_at(out: AngleOutOfRange, at: Location) -> Self {
        Self::AngleOutOfRange {
            value: i64::from(out.divisions),
            max: crate::math::MAX_ANGLE_DIVISIONS,
            at,
        }
    }
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
            Self::MissingAxiom => write!(f, "the system has no axiom: add a line `Axiom s`"),
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
            Self::NumberOutOfRange { symbol, at } => write!(
                f,
                "the number after `{symbol}` at {at} is malformed or out of range"
            ),
            Self::TooManySymbols { max, at } => write!(
                f,
                "the system holds more than {max} symbols (axiom and rules together): the \
                 symbol at {at} does not fit"
            ),
            Self::TooManyNumericCommands { max, at } => write!(
                f,
                "the system uses more than {max} different numeric commands (`@0.5`, `C12`, \
                 ...): the one at {at} does not fit"
            ),
            Self::UnterminatedEntry { at } => {
                write!(f, "the entry at {at} has no closing `}}`")
            }
            Self::UnknownLine { at } => write!(
                f,
                "line {} is not `Angle n`, `Axiom s` or a rule `c=s`",
                at.line
            ),
            Self::UnknownSystem => write!(f, "no system of that name in the file"),
            Self::EntryRunsIntoNext { entry, next } => write!(
                f,
                "the entry on line {entry} runs into another entry's `NAME {{` on line \
                 {next}: is a `}}` missing before line {next}?"
            ),
            Self::AngleNotWhole { at } => write!(
                f,
                "the angle at {at} is not a whole number: `Angle n` counts divisions of a \
                 full turn (`Angle 6` turns by 60°)"
            ),
            Self::RowOfNumbers { line } => write!(
                f,
                "line {line} is a row of numbers, as in a Fractint IFS file (`.ifs`), not an \
                 L-system file (`.l`)"
            ),
            Self::Expression { at } => write!(
                f,
                "the expression at {at} is malformed: write e.g. x*2, (x+y)/2 or t>1 && x!=0"
            ),
            Self::UnknownName { at } => write!(
                f,
                "the name at {at} is neither a parameter of the predecessor nor a `define:`d \
                 constant"
            ),
            Self::TooManyParameters { max, at } => {
                write!(f, "the module at {at} has more than {max} parameters")
            }
            Self::ProbabilityOutOfRange { at } => write!(
                f,
                "the probability of the production at {at} is out of range: give 0.0001 to 3.99, \
                 e.g. 0.33"
            ),
            Self::MixedProductions { symbol, at } => write!(
                f,
                "the production for `{symbol}` at {at} mixes with the others for `{symbol}`: \
                 give every one a probability, or give one production"
            ),
            Self::NotANumber { at } => write!(
                f,
                "the number at {at} is malformed: write e.g. 22.5, -90 or 1e-3"
            ),
            Self::NotAColor { at } => write!(f, "the colour at {at} is not RRGGBB (hex digits)"),
            Self::TooManyColors { max, at } => {
                write!(f, "the colour at {at} is one over the {max} kept")
            }
            Self::MalformedTropism { at } => {
                write!(
                    f,
                    "the tropism at {at} is not `TX,TY,TZ E` (e.g. 0,-1,0 0.22)"
                )
            }
            Self::NotOneSymbol { at } => write!(
                f,
                "the predecessor at {at} is not one symbol: write `X --> ...`"
            ),
            Self::WrongColumnCount {
                expected,
                found,
                at,
            } => write!(
                f,
                "the map at {at} has {found} numbers; a map has {expected} (`a b c d e f p` in \
                 2D; the matrix, the translation and p in 3D)"
            ),
            Self::TooManyMaps { max, at } => {
                write!(
                    f,
                    "the map at {at} is one too many: an IFS holds at most {max}"
                )
            }
            Self::NoMaps { at } => write!(f, "the entry at {at} has no maps"),
            Self::WrongArity {
                symbol,
                found,
                expected,
                at,
            } => write!(
                f,
                "the module `{symbol}` at {at} has {found} parameters, but the productions for \
                 `{symbol}` take {expected}: no production can rewrite it"
            ),
            Self::ProbabilitiesDoNotSum { sum, at } => {
                write!(f, "the probabilities of the productions from {at} sum to ")?;
                sum.write_four_decimals(f)?;
                write!(
                    f,
                    ", not 1: make them add up to 1, e.g. 0.33, 0.33 and 0.34"
                )
            }
            Self::Unsupported {
                feature: Unsupported::EnvironmentWithContext,
                at,
            } => write!(
                f,
                "{} at {at}: context searches expand modules ahead of the turtle, where no \
                 environment can be asked; use one or the other",
                Unsupported::EnvironmentWithContext.describe()
            ),
            Self::Unsupported { feature, at } => write!(
                f,
                "{} at {at}: the plain reader does not take them; read the system with \
                 `LsysEntry::parametric` (the CLI does; see docs/lsystems.md)",
                feature.describe()
            ),
            Self::OldMacLineEndings => write!(
                f,
                "the file ends its lines with a carriage return alone (old Mac OS), so it \
                 reads as one line: convert it to LF or CRLF line endings"
            ),
        }
    }
}
