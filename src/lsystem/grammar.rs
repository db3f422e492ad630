//! A grammar borrowed from text: axiom, single-symbol rules and the turn angle.
//!
//! Nothing is copied: the axiom and the rule bodies are slices of the caller's `&str`. Every
//! body is checked once here (brackets balanced within it, numbers well-formed and in
//! range), so the walker never meets malformed text and its errors are only about size.

use heapless::Vec;

use super::alphabet::{Dialect, SymbolSet, Token};
use crate::error::{Error, Location, ReadError};
use crate::math::angle::Headings;
use crate::math::Angle;

/// Most rule lines a grammar holds (Fractint allowed 25); lines for one symbol append.
pub const MAX_RULES: usize = 32;

/// Longest axiom or rule body, in bytes: the walker keeps positions in 16 bits.
pub const MAX_BODY_LEN: usize = u16::MAX as usize;

const NO_RULE: u8 = u8::MAX;

/// One rule line: a symbol and its replacement. Lines for the same symbol are chained.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rule<'a> {
    pub(crate) body: &'a [u8],
    /// The index of the next line for the same symbol, or `NO_RULE`.
    pub(crate) next: u8,
}

/// An L-system: axiom, rules and angle, borrowed from text and checked.
///
/// Worst-case RAM: `MAX_RULES` rule slices (two words and a byte each), a 128-byte lookup
/// table and the sine/cosine table for up to `MAX_ANGLE_DIVISIONS / 2 + 1` headings
/// (264 bytes): about 0.9 KiB on a 32-bit MCU.
#[derive(Debug, Clone)]
pub struct Grammar<'a> {
    dialect: Dialect,
    axiom: &'a [u8],
    angle: Angle,
    rules: Vec<Rule<'a>, MAX_RULES>,
    /// First rule line for each ASCII symbol.
    first: [u8; 128],
    extra_draw: SymbolSet,
    headings: Headings,
}

impl<'a> Grammar<'a> {
    /// A grammar with an axiom and an angle, and no rules yet.
    pub fn new(dialect: Dialect, axiom: &'a str, angle: Angle) -> Result<Self, Error> {
        Self::new_at(dialect, axiom, angle, Location::column(1))
    }

    /// Like [`new`](Self::new), with the axiom's place in a file for error messages.
    pub(crate) fn new_at(
        dialect: Dialect,
        axiom: &'a str,
        angle: Angle,
        at: Location,
    ) -> Result<Self, Error> {
        let axiom = axiom.trim();
        if axiom.is_empty() {
            return Err(Error::Read(ReadError::EmptyAxiom));
        }
        let headings = Headings::new(angle, at)?;
        let grammar = Self {
            dialect,
            axiom: axiom.as_bytes(),
            angle,
            rules: Vec::new(),
            first: [NO_RULE; 128],
            extra_draw: SymbolSet::default(),
            headings,
        };
        grammar.check_body(axiom.as_bytes(), at)?;
        Ok(grammar)
    }

    /// Adds a rule `symbol → body`. A second rule for the same symbol appends to the first,
    /// as repeated lines do in Fractint files.
    pub fn with_rule(mut self, symbol: char, body: &'a str) -> Result<Self, Error> {
        self.add_rule(symbol, body)?;
        Ok(self)
    }

    /// Adds a rule `symbol → body` in place: [`with_rule`](Self::with_rule) without moving
    /// the grammar (about 1 KiB) through every call, for tight MCU stacks.
    pub fn add_rule(&mut self, symbol: char, body: &'a str) -> Result<(), Error> {
        self.add_rule_at(symbol, body, Location::column(1))
    }

    /// Adds a rule; `at` is where the body starts (for error messages).
    pub(crate) fn add_rule_at(
        &mut self,
        symbol: char,
        body: &'a str,
        at: Location,
    ) -> Result<(), Error> {
        let rule_at = Location {
            line: at.line,
            column: at.column.saturating_sub(2).max(1),
        };
        let symbol = u8::try_from(symbol)
            .ok()
            .filter(u8::is_ascii)
            .ok_or(Error::Read(ReadError::NonAsciiSymbol { at: rule_at }))?;
        let symbol = self.dialect.normalize(symbol);
        if self.dialect.is_reserved(symbol) {
            return Err(Error::Read(ReadError::ReservedRule {
                symbol: char::from(symbol),
                at: rule_at,
            }));
        }
        self.check_body(body.as_bytes(), at)?;
        let index = u8::try_from(self.rules.len()).unwrap_or(NO_RULE);
        self.rules
            .push(Rule {
                body: body.as_bytes(),
                next: NO_RULE,
            })
            .map_err(|_| {
                Error::Read(ReadError::TooManyRules {
                    max: MAX_RULES,
                    at: rule_at,
                })
            })?;
        // Chain it after the last line for the same symbol.
        match self.first_rule(symbol) {
            None => {
                if let Some(first) = self.first.get_mut(usize::from(symbol)) {
                    *first = index;
                }
            }
            Some(mut last) => {
                while let Some(next) = self.rule(last).map(|rule| rule.next) {
                    if next == NO_RULE {
                        break;
                    }
                    last = next;
                }
                if let Some(rule) = self.rules.get_mut(usize::from(last)) {
                    rule.next = index;
                }
            }
        }
        Ok(())
    }

    /// Makes more symbols draw (ABOP edge-rewriting systems, e.g. `A` and `B` in the Gosper
    /// curve). Ignored by the Fractint dialect, where `F` and `D` draw.
    pub fn with_draw_symbols(mut self, symbols: &str) -> Result<Self, Error> {
        for (index, c) in symbols.char_indices() {
            let at = Location::column(u32::try_from(index + 1).unwrap_or(u32::MAX));
            let byte = u8::try_from(c)
                .ok()
                .filter(u8::is_ascii)
                .ok_or(Error::Read(ReadError::NonAsciiSymbol { at }))?;
            self.extra_draw.insert(byte);
        }
        Ok(self)
    }

    /// The notation this grammar follows.
    pub const fn dialect(&self) -> Dialect {
        self.dialect
    }

    /// The turn angle.
    pub const fn angle(&self) -> Angle {
        self.angle
    }

    /// The axiom as written.
    pub fn axiom(&self) -> &'a str {
        core::str::from_utf8(self.axiom).unwrap_or_default()
    }

    /// Number of rule lines.
    pub fn rule_count(&self) -> usize {
        self.rules.len()
    }

    #[inline]
    pub(crate) fn axiom_bytes(&self) -> &'a [u8] {
        self.axiom
    }

    #[inline]
    pub(crate) fn rule(&self, index: u8) -> Option<&Rule<'a>> {
        self.rules.get(usize::from(index))
    }

    /// The first rule line for a (normalized) symbol.
    #[inline]
    pub(crate) fn first_rule(&self, symbol: u8) -> Option<u8> {
        self.first
            .get(usize::from(symbol))
            .copied()
            .filter(|&index| index != NO_RULE)
    }

    #[inline]
    pub(crate) const fn headings(&self) -> &Headings {
        &self.headings
    }

    /// Checks one body: ASCII, balanced brackets, every number decodes.
    fn check_body(&self, body: &[u8], at: Location) -> Result<(), Error> {
        let located = |offset: usize| Location {
            line: at.line,
            column: at
                .column
                .saturating_add(u32::try_from(offset).unwrap_or(u32::MAX)),
        };
        if body.len() > MAX_BODY_LEN {
            return Err(Error::Read(ReadError::BodyTooLong {
                max: MAX_BODY_LEN,
                at,
            }));
        }
        // Where the outermost open `[` is, for the message if it is never closed.
        let mut outermost_open = 0;
        let mut depth = 0usize;
        let mut position = 0;
        while let Some((token, next)) = self.dialect.scan(body, position) {
            let here = located(position);
            if !token.symbol.is_ascii() {
                return Err(Error::Read(ReadError::NonAsciiSymbol { at: here }));
            }
            match token.symbol {
                b'[' => {
                    if depth == 0 {
                        outermost_open = position;
                    }
                    depth += 1;
                }
                b']' => {
                    depth = depth
                        .checked_sub(1)
                        .ok_or(Error::Read(ReadError::UnbalancedBracket { at: here }))?;
                }
                _ => {}
            }
            self.dialect.decode(token, self.extra_draw, here)?;
            position = next;
        }
        if depth > 0 {
            return Err(Error::Read(ReadError::UnclosedBracket {
                at: located(outermost_open),
            }));
        }
        Ok(())
    }

    /// Decodes a token of a body already checked by `check_body`.
    #[inline]
    pub(crate) fn decode(&self, token: Token<'_>) -> Result<super::alphabet::Command, Error> {
        self.dialect
            .decode(token, self.extra_draw, Location::default())
    }
}
