//! What the symbols mean: scanning one token (a symbol and its number, if any) from a body,
//! and decoding a token into a turtle [`Command`] for each [`Dialect`].
//!
//! As in Fractint, a numeric command written without digits (`\`, `/`, `C`, `<`, `>`,
//! `@`) takes the number 0: no turn, colour 0, no change, and for `@` a step of 0 (what
//! follows draws points).

use core::fmt;

use crate::error::{Error, Location, ReadError};
use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// Which rules of notation a system follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Dialect {
    /// Fractint's `.l` notation: case-insensitive; `F`/`D` draw, `G`/`M` move, and the
    /// commands `| ! \nn /nn @nn Cnn <nn >nn`.
    #[default]
    Fractint,
    /// *The Algorithmic Beauty of Plants*: case-sensitive; `F` (and any extra drawing
    /// symbols) draw, `f` moves; `+ - | [ ]`.
    Abop,
}

/// One symbol of a body, with its numeric argument (empty when it takes none).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Token<'a> {
    /// The symbol, lower-cased in the Fractint dialect.
    pub(crate) symbol: u8,
    /// The digits after a numeric command (and `I`/`Q` prefixes after `@`).
    pub(crate) argument: &'a [u8],
}

/// What the turtle does for one token.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Command {
    /// Step along the main heading, drawing.
    Draw,
    /// Step along the main heading without drawing.
    Move,
    /// Step along the free (degree) heading, drawing (Fractint `D`).
    DrawFree,
    /// Step along the free heading without drawing (Fractint `M`).
    MoveFree,
    /// Turn counter-clockwise by the system's angle (clockwise when reversed).
    Left,
    /// Turn clockwise by the system's angle (counter-clockwise when reversed).
    Right,
    /// Turn clockwise by half a turn (Angle div 2 steps).
    Around,
    /// Swap the meanings of `+`/`-` and `\`/`/`.
    Reverse,
    /// Turn the free heading counter-clockwise by the given angle.
    FreeLeft(BinaryAngle),
    /// Turn the free heading clockwise by the given angle.
    FreeRight(BinaryAngle),
    /// Multiply the step.
    Scale(Real),
    /// Set the colour index.
    SetColor(u8),
    /// Raise the colour index.
    RaiseColor(u8),
    /// Lower the colour index.
    LowerColor(u8),
    /// Step `length` steps along the main heading, drawing (a parametric `F(l)`).
    DrawBy(Real),
    /// Step `length` steps along the main heading without drawing (`f(l)`).
    MoveBy(Real),
    /// Save the turtle.
    Push,
    /// Restore the turtle.
    Pop,
    /// Nothing (a symbol that only drives the derivation).
    Nothing,
}

impl Dialect {
    /// The symbol as rules and commands see it.
    #[inline]
    pub(crate) const fn normalize(self, byte: u8) -> u8 {
        match self {
            Self::Fractint => byte.to_ascii_lowercase(),
            Self::Abop => byte,
        }
    }

    /// Symbols that cannot have rules.
    pub(crate) fn is_reserved(self, symbol: u8) -> bool {
        match self {
            Self::Fractint => b"+-/\\@|!c<>[]".contains(&symbol),
            Self::Abop => matches!(symbol, b'[' | b']'),
        }
    }

    #[inline]
    pub(crate) fn takes_number(self, symbol: u8) -> bool {
        self == Self::Fractint && matches!(symbol, b'\\' | b'/' | b'@' | b'c' | b'<' | b'>')
    }

    /// Reads the token at `position` of `body`; returns it and the position after it, or
    /// `None` at the end. The argument is scanned, not checked: [`Dialect::decode`] checks it.
    #[inline]
    pub(crate) fn scan<'a>(self, body: &'a [u8], position: usize) -> Option<(Token<'a>, usize)> {
        let symbol = self.normalize(*body.get(position)?);
        let start = position + 1;
        let mut end = start;
        if self.takes_number(symbol) {
            if symbol == b'@' {
                while body
                    .get(end)
                    .is_some_and(|b| matches!(b.to_ascii_lowercase(), b'i' | b'q'))
                {
                    end += 1;
                }
            }
            while body
                .get(end)
                .is_some_and(|b| b.is_ascii_digit() || *b == b'.')
            {
                end += 1;
            }
        }
        let argument = body.get(start..end).unwrap_or_default();
        Some((Token { symbol, argument }, end))
    }

    /// What a token makes the turtle do, extra drawing symbols aside (a grammar's table of
    /// what each symbol does has those). Errors carry the column of the token within its
    /// body (`at`).
    pub(crate) fn decode(self, token: Token<'_>, at: Location) -> Result<Command, Error> {
        if !self.takes_number(token.symbol) {
            return Ok(self.plain(token.symbol).command());
        }
        Ok(match token.symbol {
            b'\\' => Command::FreeLeft(degrees(token, at)?),
            b'/' => Command::FreeRight(degrees(token, at)?),
            b'@' => Command::Scale(scale(token, at)?),
            b'c' => Command::SetColor(color(token, at)?),
            b'<' => Command::RaiseColor(color(token, at)?),
            _ => Command::LowerColor(color(token, at)?),
        })
    }

    /// What a symbol that takes no number makes the turtle do, unless it is an extra
    /// drawing symbol (see [`extra_draw`](Self::extra_draw)).
    pub(crate) fn plain(self, symbol: u8) -> Plain {
        self.commands()
            .iter()
            .find(|&&(s, _)| s == symbol)
            .map_or(Plain::Nothing, |&(_, plain)| plain)
    }

    /// What a symbol doing `plain` does once made an extra drawing symbol: ABOP's draw,
    /// unless they are commands; Fractint ignores them (`F` and `D` draw there).
    pub(crate) fn extra_draw(self, plain: Plain) -> Plain {
        if self == Self::Abop && plain == Plain::Nothing {
            Plain::Draw
        } else {
            plain
        }
    }

    /// The symbols that take no number and do something, and what they do (any other
    /// symbol does nothing, but for ABOP's extra drawing symbols).
    pub(crate) const fn commands(self) -> &'static [(u8, Plain)] {
        match self {
            Self::Fractint => &[
                (b'f', Plain::Draw),
                (b'g', Plain::Move),
                (b'd', Plain::DrawFree),
                (b'm', Plain::MoveFree),
                (b'+', Plain::Left),
                (b'-', Plain::Right),
                (b'|', Plain::Around),
                (b'!', Plain::Reverse),
                (b'[', Plain::Push),
                (b']', Plain::Pop),
            ],
            Self::Abop => &[
                (b'F', Plain::Draw),
                (b'f', Plain::Move),
                (b'+', Plain::Left),
                (b'-', Plain::Right),
                (b'|', Plain::Around),
                (b'[', Plain::Push),
                (b']', Plain::Pop),
            ],
        }
    }
}

/// A command that takes no number, in a byte: the grammar keeps one for every symbol, so
/// reading what a symbol does is one load, whatever the dialect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) enum Plain {
    #[default]
    Nothing,
    Draw,
    Move,
    DrawFree,
    MoveFree,
    Left,
    Right,
    Around,
    Reverse,
    Push,
    Pop,
}

impl Plain {
    /// The command.
    #[inline(always)]
    pub(crate) const fn command(self) -> Command {
        match self {
            Self::Nothing => Command::Nothing,
            Self::Draw => Command::Draw,
            Self::Move => Command::Move,
            Self::DrawFree => Command::DrawFree,
            Self::MoveFree => Command::MoveFree,
            Self::Left => Command::Left,
            Self::Right => Command::Right,
            Self::Around => Command::Around,
            Self::Reverse => Command::Reverse,
            Self::Push => Command::Push,
            Self::Pop => Command::Pop,
        }
    }
}

fn out_of_range(token: Token<'_>, at: Location) -> Error {
    Error::Read(ReadError::NumberOutOfRange {
        symbol: char::from(token.symbol),
        at,
    })
}

/// The number of a numeric command: 0 when it has no digits, as in Fractint.
fn number(token: Token<'_>, digits: &[u8], at: Location) -> Result<Real, Error> {
    if digits.is_empty() {
        return Ok(Real::ZERO);
    }
    core::str::from_utf8(digits)
        .ok()
        .and_then(Real::parse_decimal)
        .ok_or(out_of_range(token, at))
}

/// The turn of `\` and `/`, from degrees.
fn degrees(token: Token<'_>, at: Location) -> Result<BinaryAngle, Error> {
    Ok(BinaryAngle::from_degrees_bits(
        number(token, token.argument, at)?.to_bits(),
    ))
}

/// The factor of `@`: `[I][Q]number` in either order, inverse and square root.
fn scale(token: Token<'_>, at: Location) -> Result<Real, Error> {
    let prefix = token
        .argument
        .iter()
        .take_while(|b| matches!(b.to_ascii_lowercase(), b'i' | b'q'))
        .count();
    let (flags, digits) = token.argument.split_at(prefix);
    let inverse = flags
        .iter()
        .filter(|b| b.eq_ignore_ascii_case(&b'i'))
        .count();
    let root = flags
        .iter()
        .filter(|b| b.eq_ignore_ascii_case(&b'q'))
        .count();
    if inverse > 1 || root > 1 {
        return Err(out_of_range(token, at));
    }
    let mut factor = number(token, digits, at)?;
    if digits.is_empty() && inverse == 0 {
        // Fractint's `@` without a number: a step of 0.
        return Ok(Real::ZERO);
    }
    if root == 1 {
        factor = factor.checked_sqrt().ok_or(out_of_range(token, at))?;
    }
    if inverse == 1 {
        factor = Real::ONE
            .checked_div(factor)
            .ok_or(out_of_range(token, at))?;
    }
    // A factor of 0 would collapse the turtle; beyond 2^16 either way is surely a typo.
    let limit = Real::from_int(1 << 16);
    let floor = Real::from_bits(1 << 16);
    if factor < floor || factor > limit {
        return Err(out_of_range(token, at));
    }
    Ok(factor)
}

/// A colour index or increment, 0 to 255 (0 without digits).
fn color(token: Token<'_>, at: Location) -> Result<u8, Error> {
    let mut value: u32 = 0;
    for &digit in token.argument {
        if !digit.is_ascii_digit() || value > 255 {
            return Err(out_of_range(token, at));
        }
        value = value * 10 + u32::from(digit - b'0');
    }
    u8::try_from(value).map_err(|_| out_of_range(token, at))
}

/// A set of ASCII symbols.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct SymbolSet(u128);

impl SymbolSet {
    pub(crate) fn insert(&mut self, symbol: u8) {
        if symbol < 128 {
            self.0 |= 1 << symbol;
        }
    }

    #[inline]
    pub(crate) fn contains(self, symbol: u8) -> bool {
        symbol < 128 && self.0 & (1 << symbol) != 0
    }
}

/// One symbol of a derived string, as it prints.
///
/// The symbol (lower-cased in the Fractint dialect) and, for a numeric command, its number (`@` the factor, `\` and `/` degrees,
/// `C`, `<`, `>` the colour), shown with at most 4 decimals, trailing zeros dropped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DerivedSymbol {
    /// The symbol.
    pub symbol: char,
    /// The number of a numeric command.
    pub number: Option<Real>,
}

impl fmt::Display for DerivedSymbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        f.write_char(self.symbol)?;
        let Some(number) = self.number else {
            return Ok(());
        };
        number.write_four_decimals(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(dialect: Dialect, text: &str) -> Result<Command, Error> {
        let (token, _) = dialect
            .scan(text.as_bytes(), 0)
            .ok_or(Error::Read(ReadError::MissingAxiom))?;
        dialect.decode(token, Location::column(1))
    }

    #[test]
    fn fractint_commands_are_case_insensitive() {
        assert_eq!(decode(Dialect::Fractint, "f"), Ok(Command::Draw));
        assert_eq!(decode(Dialect::Fractint, "F"), Ok(Command::Draw));
        assert_eq!(decode(Dialect::Fractint, "C12"), Ok(Command::SetColor(12)));
        assert_eq!(decode(Dialect::Fractint, "<1"), Ok(Command::RaiseColor(1)));
        assert_eq!(
            decode(Dialect::Fractint, "\\22.5"),
            Ok(Command::FreeLeft(BinaryAngle::from_degrees_bits(
                22 << 32 | 1 << 31
            )))
        );
    }

    #[test]
    fn scale_prefixes_in_either_order() {
        let expected = 1.0 / 3f64.sqrt();
        for text in ["@IQ3", "@QI3", "@iq3", "@qi3"] {
            match decode(Dialect::Fractint, text) {
                Ok(Command::Scale(f)) => assert!((f.to_f64() - expected).abs() < 1e-9, "{text}"),
                other => panic!("{text}: {other:?}"),
            }
        }
    }

    #[test]
    fn numbers_are_checked() {
        let at = Location::column(1);
        assert_eq!(
            decode(Dialect::Fractint, "C256"),
            Err(Error::Read(ReadError::NumberOutOfRange { symbol: 'c', at }))
        );
        // Without digits, as in Fractint: 0.
        assert_eq!(
            decode(Dialect::Fractint, "@"),
            Ok(Command::Scale(Real::ZERO))
        );
        assert_eq!(decode(Dialect::Fractint, "C"), Ok(Command::SetColor(0)));
        assert_eq!(
            decode(Dialect::Fractint, "\\"),
            Ok(Command::FreeLeft(BinaryAngle::default()))
        );
        assert_eq!(
            decode(Dialect::Fractint, "@0"),
            Err(Error::Read(ReadError::NumberOutOfRange { symbol: '@', at }))
        );
        assert_eq!(
            decode(Dialect::Fractint, "@1.2.3"),
            Err(Error::Read(ReadError::NumberOutOfRange { symbol: '@', at }))
        );
    }

    #[test]
    fn abop_is_case_sensitive() {
        assert_eq!(decode(Dialect::Abop, "F"), Ok(Command::Draw));
        assert_eq!(decode(Dialect::Abop, "f"), Ok(Command::Move));
        assert_eq!(decode(Dialect::Abop, "C12"), Ok(Command::Nothing));
    }
}
