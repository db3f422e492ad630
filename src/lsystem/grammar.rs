//! A grammar compiled from text: axiom, single-symbol rules and the turn angle.
//!
//! Each body is read once, when it is given, into ops of one byte: an ASCII symbol (its
//! rule, if any, is found by a table lookup), or a reference to a numeric command whose
//! number is already converted (`@0.5`, `\\30`, `C12`). Brackets are checked balanced
//! within each body and every number in range, so the walk reads no text, parses nothing,
//! and its errors are only about size.

use heapless::Vec;

use super::alphabet::{Command, DerivedSymbol, Dialect, Plain};
use super::choice::pick;
use crate::error::{Error, Location, ReadError};
use crate::math::angle::Headings;
use crate::math::wide::shift_round;
use crate::math::{Angle, Real};

/// [`Grammar::MAX_RULES`], for the crate's own types and arrays.
pub(crate) const MAX_RULES: usize = 32;

/// [`Grammar::MAX_SYMBOLS`], for the crate's own types and arrays.
pub(crate) const MAX_SYMBOLS: usize = 512;

/// [`Grammar::MAX_NUMERIC_COMMANDS`], for the crate's own types and arrays.
pub(crate) const MAX_NUMERIC_COMMANDS: usize = 32;

const NO_RULE: u8 = u8::MAX;

/// Ops at or above this are numeric commands: `op - NUMERIC` indexes the grammar's table.
pub(crate) const NUMERIC: u8 = 0x80;

/// Where a compiled body is in the grammar's ops.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Span {
    pub(crate) start: u16,
    pub(crate) end: u16,
}

/// One rule line: its compiled body. Lines for the same symbol are chained.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Rule {
    pub(crate) body: Span,
    /// The index of the next line for the same symbol, or `NO_RULE`.
    pub(crate) next: u8,
    /// 0 for a line that appends to the ones before it (Fractint's repeated lines); else
    /// this production's weight among the alternatives for its symbol (stochastic), in
    /// units of 2⁻¹⁴ (16 bits keep a rule at 8 bytes).
    pub(crate) weight: u16,
}

/// An L-system: axiom, rules and angle, compiled from text and checked.
///
/// The compiled symbols: a whole array, so that reading one at a position a walk keeps in
/// range needs no bounds check (a position is masked to the array, a power of two long).
#[derive(Debug, Clone)]
struct Ops {
    bytes: [u8; MAX_SYMBOLS],
    len: usize,
}

impl Ops {
    const EMPTY: Self = Self {
        bytes: [0; MAX_SYMBOLS],
        len: 0,
    };

    const fn len(&self) -> usize {
        self.len
    }

    fn as_slice(&self) -> &[u8] {
        self.bytes.get(..self.len).unwrap_or_default()
    }

    /// The op at `index`, which the caller keeps below `len` (the walk's frames do: they
    /// hold spans of compiled bodies).
    #[inline(always)]
    fn at(&self, index: u16) -> u8 {
        const _: () = assert!(MAX_SYMBOLS.is_power_of_two());
        self.bytes
            .get(usize::from(index) % MAX_SYMBOLS)
            .copied()
            .unwrap_or(0)
    }

    fn push(&mut self, op: u8) -> Result<(), ()> {
        let slot = self.bytes.get_mut(self.len).ok_or(())?;
        *slot = op;
        self.len += 1;
        Ok(())
    }

    fn truncate(&mut self, len: usize) {
        self.len = self.len.min(len);
    }
}

/// A system's axiom and rules, compiled into symbols and tables.
///
/// Worst-case RAM: the ops ([`Grammar::MAX_SYMBOLS`] bytes), the numeric commands
/// ([`Grammar::MAX_NUMERIC_COMMANDS`] × 16 bytes), [`Grammar::MAX_RULES`] rule spans (5 bytes each), a
/// 128-byte rule lookup table, a 128-byte table of what each symbol does, and the
/// sine/cosine table for up to `MAX_ANGLE_DIVISIONS / 2 + 1` headings (264 bytes): about
/// 1.9 KiB. On a small MCU, build it in place
/// ([`add_rule`](Self::add_rule), [`add_draw_symbols`](Self::add_draw_symbols)): each move
/// of a grammar is a copy on the stack.
#[derive(Debug, Clone)]
pub struct Grammar<'a> {
    dialect: Dialect,
    axiom_text: &'a str,
    angle: Angle,
    ops: Ops,
    numeric: Vec<Command, MAX_NUMERIC_COMMANDS>,
    axiom: Span,
    rules: Vec<Rule, MAX_RULES>,
    /// First rule line for each ASCII symbol.
    first: [u8; 128],
    /// What each ASCII symbol does (for this dialect and extra drawing symbols).
    plain: [Plain; 128],
    headings: Headings,
    /// Seeds the choices among stochastic productions.
    seed: u32,
}

impl<'a> Grammar<'a> {
    /// Most distinct numeric commands (`@0.5`, `\\30`, `C12`, ...) a grammar holds.
    pub const MAX_NUMERIC_COMMANDS: usize = MAX_NUMERIC_COMMANDS;

    /// Most symbols a grammar holds, the axiom and every rule body together (a numeric command
    /// with its number counts one). Fractint's own files need at most 412.
    pub const MAX_SYMBOLS: usize = MAX_SYMBOLS;

    /// Most rule lines a grammar holds (Fractint allowed 25); lines for one symbol append.
    pub const MAX_RULES: usize = MAX_RULES;

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
        // An empty axiom is valid (Fractint drew it as an empty screen): it draws nothing.
        let axiom = axiom.trim();
        let headings = Headings::new(angle).map_err(|out| ReadError::angle_at(out, at))?;
        let mut grammar = Self {
            dialect,
            axiom_text: axiom,
            angle,
            ops: Ops::EMPTY,
            numeric: Vec::new(),
            axiom: Span::default(),
            rules: Vec::new(),
            first: [NO_RULE; 128],
            plain: [Plain::Nothing; 128],
            headings,
            seed: 0,
        };
        grammar.decode_plain();
        grammar.axiom = grammar.compile(axiom.as_bytes(), at)?;
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

    /// Adds a stochastic production `symbol → body` chosen with `probability` among the
    /// alternatives for `symbol` (2⁻¹⁵ to 3.99; they need not sum to 1, only their ratios
    /// count, to 2⁻¹⁴; the choice is a pure function
    /// of the seed and the symbol's place in the derivation: see [`with_seed`](Self::with_seed)).
    pub fn add_alternative(
        &mut self,
        symbol: char,
        body: &'a str,
        probability: Real,
    ) -> Result<(), Error> {
        self.add_production(symbol, body, Some(probability), Location::column(1))
    }

    /// Seeds the choices among stochastic productions: the same seed derives the same string
    /// and draws the same picture on every walk and every target.
    #[must_use]
    pub const fn with_seed(mut self, seed: u32) -> Self {
        self.seed = seed;
        self
    }

    /// [`with_seed`](Self::with_seed) in place.
    pub fn set_seed(&mut self, seed: u32) {
        self.seed = seed;
    }

    /// The seed of the stochastic choices.
    pub const fn seed(&self) -> u32 {
        self.seed
    }

    /// Whether any symbol has stochastic productions.
    pub(crate) fn is_stochastic(&self) -> bool {
        self.rules.iter().any(|rule| rule.weight > 0)
    }

    /// Adds a rule; `at` is where the body starts (for error messages).
    pub(crate) fn add_rule_at(
        &mut self,
        symbol: char,
        body: &'a str,
        at: Location,
    ) -> Result<(), Error> {
        self.add_production(symbol, body, None, at)
    }

    /// Adds an appending line (`probability` `None`) or a stochastic alternative.
    pub(crate) fn add_production(
        &mut self,
        symbol: char,
        body: &'a str,
        probability: Option<Real>,
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
        let too_many = Error::Read(ReadError::TooManyRules {
            max: MAX_RULES,
            at: rule_at,
        });
        if self.rules.is_full() {
            return Err(too_many);
        }
        // Weights in units of 2⁻¹⁴: no floats; probabilities up to 3.99 (they need not sum
        // to 1, only their ratios count).
        let weight = match probability {
            None => 0,
            Some(p) => u16::try_from(shift_round(i128::from(p.to_bits()), 18))
                .ok()
                .filter(|&w| w > 0)
                .ok_or(Error::Read(ReadError::ProbabilityOutOfRange {
                    at: rule_at,
                }))?,
        };
        // One symbol's productions are all appending lines or all alternatives.
        if let Some(first) = self.first_rule(symbol).and_then(|index| self.rule(index)) {
            if (first.weight > 0) != (weight > 0) {
                return Err(Error::Read(ReadError::MixedProductions {
                    symbol: char::from(symbol),
                    at: rule_at,
                }));
            }
        }
        let compiled = self.compile(body.as_bytes(), at)?;
        let index = u8::try_from(self.rules.len()).unwrap_or(NO_RULE);
        self.rules
            .push(Rule {
                body: compiled,
                next: NO_RULE,
                weight,
            })
            .map_err(|_| too_many)?;
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
        self.add_draw_symbols(symbols)?;
        Ok(self)
    }

    /// [`with_draw_symbols`](Self::with_draw_symbols) in place, without moving the grammar.
    pub fn add_draw_symbols(&mut self, symbols: &str) -> Result<(), Error> {
        for (index, c) in symbols.char_indices() {
            let at = Location::column(u32::try_from(index + 1).unwrap_or(u32::MAX));
            let byte = u8::try_from(c)
                .ok()
                .filter(u8::is_ascii)
                .ok_or(Error::Read(ReadError::NonAsciiSymbol { at }))?;
            if let Some(plain) = self.plain.get_mut(usize::from(byte)) {
                *plain = self.dialect.extra_draw(*plain);
            }
        }
        Ok(())
    }

    /// Fills the table of what each symbol does: the dialect's commands, nothing else.
    fn decode_plain(&mut self) {
        for &(symbol, plain) in self.dialect.commands() {
            if let Some(entry) = self.plain.get_mut(usize::from(symbol)) {
                *entry = plain;
            }
        }
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
        self.axiom_text
    }

    /// Number of rule lines.
    pub fn rule_count(&self) -> usize {
        self.rules.len()
    }

    /// Symbols held, the axiom and all rule bodies together (at most [`Grammar::MAX_SYMBOLS`]).
    pub fn symbol_count(&self) -> usize {
        self.ops.len()
    }

    /// The ops of a compiled body.
    #[inline]
    pub(crate) fn ops(&self, span: Span) -> &[u8] {
        self.ops
            .as_slice()
            .get(usize::from(span.start)..usize::from(span.end))
            .unwrap_or_default()
    }

    /// The axiom's ops.
    #[inline]
    pub(crate) fn axiom_ops(&self) -> &[u8] {
        self.ops(self.axiom)
    }

    /// Where the axiom's ops are.
    pub(crate) const fn axiom_span(&self) -> Span {
        self.axiom
    }

    /// Where a rule line's ops are (empty for no such line).
    #[inline]
    pub(crate) fn rule_span(&self, index: u8) -> Span {
        self.rule(index).map_or(Span::default(), |rule| rule.body)
    }

    /// The op at `index` of all the ops (a walk's frames keep in-range positions).
    #[inline(always)]
    pub(crate) fn op(&self, index: u16) -> u8 {
        self.ops.at(index)
    }

    #[inline]
    pub(crate) fn rule(&self, index: u8) -> Option<&Rule> {
        self.rules.get(usize::from(index))
    }

    /// The rule line after `index` that continues it (Fractint's repeated lines; none for a
    /// stochastic alternative).
    #[inline]
    pub(crate) fn next_line(&self, index: u8) -> Option<u8> {
        self.rule(index)
            .filter(|rule| rule.weight == 0)
            .map(|rule| rule.next)
            .filter(|&next| next != NO_RULE)
    }

    /// The production to expand for a symbol whose first line is `first`: that line, or for
    /// stochastic alternatives the one `key` picks, each with its weight's share of the
    /// 2³² keys (a multiply and a shift: no division).
    #[inline]
    pub(crate) fn choose(&self, first: u8, key: u32) -> u8 {
        let Some(rule) = self.rule(first).filter(|rule| rule.weight > 0) else {
            return first;
        };
        let mut total: u64 = 0;
        let mut line = Some((first, rule));
        while let Some((_, rule)) = line {
            total += u64::from(rule.weight);
            line = self.rule(rule.next).map(|next| (rule.next, next));
        }
        let mut pick = pick(key, total);
        let mut line = Some((first, rule));
        while let Some((index, rule)) = line {
            let weight = u64::from(rule.weight);
            if pick < weight {
                return index;
            }
            pick -= weight;
            line = self.rule(rule.next).map(|next| (rule.next, next));
        }
        first
    }

    /// Every op of the axiom and the rules.
    pub(crate) fn all_ops(&self) -> &[u8] {
        self.ops.as_slice()
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

    /// Compiles one body into ops, checking it: ASCII, balanced brackets, every number in
    /// range, and room left.
    fn compile(&mut self, body: &[u8], at: Location) -> Result<Span, Error> {
        let located = |offset: usize| Location {
            line: at.line,
            column: at
                .column
                .saturating_add(u32::try_from(offset).unwrap_or(u32::MAX)),
        };
        let start = self.ops.len();
        let result = self.compile_into_ops(body, located);
        if result.is_err() {
            // A failed body leaves nothing behind.
            self.ops.truncate(start);
        }
        result?;
        let position = |index: usize| u16::try_from(index).unwrap_or(u16::MAX);
        Ok(Span {
            start: position(start),
            end: position(self.ops.len()),
        })
    }

    fn compile_into_ops(
        &mut self,
        body: &[u8],
        located: impl Fn(usize) -> Location,
    ) -> Result<(), Error> {
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
            if token.symbol.is_ascii_whitespace() {
                // Spaces between symbols (`.lsys` successors) are layout, not symbols.
                position = next;
                continue;
            }
            let command = self.dialect.decode(token, here)?;
            let op = if self.dialect.takes_number(token.symbol) {
                self.numeric_op(command, here)?
            } else {
                token.symbol
            };
            self.ops.push(op).map_err(|_| {
                Error::Read(ReadError::TooManySymbols {
                    max: MAX_SYMBOLS,
                    at: here,
                })
            })?;
            position = next;
        }
        if depth > 0 {
            return Err(Error::Read(ReadError::UnclosedBracket {
                at: located(outermost_open),
            }));
        }
        Ok(())
    }

    /// The op of a numeric command: its index in the table, added if new.
    fn numeric_op(&mut self, command: Command, at: Location) -> Result<u8, Error> {
        let index = match self.numeric.iter().position(|&known| known == command) {
            Some(index) => index,
            None => {
                self.numeric.push(command).map_err(|_| {
                    Error::Read(ReadError::TooManyNumericCommands {
                        max: MAX_NUMERIC_COMMANDS,
                        at,
                    })
                })?;
                self.numeric.len() - 1
            }
        };
        // Below MAX_NUMERIC_COMMANDS = 64, so within 0x80..0xC0.
        Ok(NUMERIC + u8::try_from(index).unwrap_or(0))
    }

    /// What the turtle does for an op. Always inlined: it is on every symbol's path, and
    /// with more callers (the table) LLVM would not inline it.
    #[inline(always)]
    pub(crate) fn command(&self, op: u8) -> Command {
        if op >= NUMERIC {
            self.numeric
                .get(usize::from(op - NUMERIC))
                .copied()
                .unwrap_or(Command::Nothing)
        } else {
            self.plain
                .get(usize::from(op))
                .copied()
                .unwrap_or_default()
                .command()
        }
    }

    /// An op as a derived string prints it: its symbol and, for a numeric command, its
    /// number (degrees for `\\` and `/`).
    pub(crate) fn derived_symbol(&self, op: u8) -> DerivedSymbol {
        let number = match self.command(op) {
            Command::FreeLeft(turn) | Command::FreeRight(turn) => {
                // A binary angle times 360 is its degrees in Q32 bits.
                Some(Real::from_bits(i64::from(turn.0) * 360))
            }
            Command::Scale(factor) => Some(factor),
            Command::SetColor(c) | Command::RaiseColor(c) | Command::LowerColor(c) => {
                Some(Real::from_int(i32::from(c)))
            }
            _ => None,
        };
        DerivedSymbol {
            symbol: char::from(self.symbol(op)),
            number: number.filter(|_| op >= NUMERIC),
        }
    }

    /// The symbol an op was written as (lower-cased in the Fractint dialect).
    pub(crate) fn symbol(&self, op: u8) -> u8 {
        if op < NUMERIC {
            return op;
        }
        match self.command(op) {
            Command::FreeLeft(_) => b'\\',
            Command::FreeRight(_) => b'/',
            Command::Scale(_) => b'@',
            Command::SetColor(_) => b'c',
            Command::RaiseColor(_) => b'<',
            Command::LowerColor(_) => b'>',
            _ => b'?',
        }
    }
}
