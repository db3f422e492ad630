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

pub(crate) mod context;
pub(crate) mod draw;
pub(crate) mod environment;
pub(crate) mod expr;
pub(crate) mod matrix;
pub(crate) mod space;

use core::fmt;

use heapless::Vec;

use self::context::{expand_in_context, Branches, Expansions, Levels, MAX_CONTEXT_SLOTS};
use self::expr::{compile, evaluate, Code, EvalError, Instr, Names, Query, SyntaxError, MAX_CODE};
use super::alphabet::SymbolSet;
use super::walker::{check_order, child_key, kept, mix, order_too_high, pick};
use crate::error::{Arithmetic, Error, Location, ReadError, Unsupported, WalkError};
use crate::math::angle::Headings;
use crate::math::decimal::write_four_decimals;
use crate::math::wide::shift_round;
use crate::math::{Angle, Real};

/// Most parameters a module has.
pub const MAX_PARAMS: usize = 4;

/// Most modules of the axiom and all successors together.
pub const MAX_MODULES: usize = 256;

/// Most parameter expressions of all modules together.
pub const MAX_ARGUMENTS: usize = 256;

/// Most productions.
pub const MAX_PRODUCTIONS: usize = 32;

/// Most named constants (`define:`).
pub const MAX_CONSTANTS: usize = 16;

/// A module of the axiom or a successor: a symbol and its parameter expressions.
#[derive(Debug, Clone, Copy)]
struct Module {
    symbol: u8,
    first_argument: u16,
    arguments: u8,
    /// Where it is in its string's text (for errors).
    offset: u16,
}

/// A module of a production's left side: its symbol and number of parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Pattern {
    symbol: u8,
    params: u8,
}

impl Pattern {
    fn matches(self, module: &Neighbour) -> bool {
        self.symbol == module.symbol && self.params == module.values.count
    }
}

/// `lc < pred > rc : condition --> successor : probability`.
#[derive(Debug, Clone, Copy)]
struct Production {
    left: Option<Pattern>,
    predecessor: Pattern,
    right: Option<Pattern>,
    condition: Option<Code>,
    /// 0 for a deterministic production; else its weight among the applicable stochastic
    /// ones, in units of 2⁻¹⁴.
    weight: u16,
    /// Its modules, `start..end`.
    start: u16,
    end: u16,
    /// Where its successor's text is (for errors).
    successor_at: Place,
}

/// A module next to the one being rewritten, as a context sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Neighbour {
    pub(crate) symbol: u8,
    pub(crate) values: Values,
}

/// A parametric system, compiled from text.
#[derive(Debug, Clone)]
pub struct ParametricGrammar {
    /// The turn of `+` and `-` without a parameter (a quarter turn unless set).
    angle: Angle,
    /// Its directions for the 2D turtle.
    headings: Headings,
    code: Vec<Instr, MAX_CODE>,
    arguments: Vec<Code, MAX_ARGUMENTS>,
    modules: Vec<Module, MAX_MODULES>,
    productions: Vec<Production, MAX_PRODUCTIONS>,
    axiom: (u16, u16),
    axiom_at: Place,
    /// Symbols a context skips (`ignore:`).
    ignore: SymbolSet,
    /// Symbols with a production that has a context.
    contextual: SymbolSet,
    /// Seeds the choices among stochastic productions.
    seed: u32,
    /// Whether any module turns in space (`& ^ \\ / $`).
    three_d: bool,
}

/// What a text position is, for errors: `base` is where `text` starts.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Place {
    pub(crate) base: Location,
}

impl Place {
    /// The place of `part`, a slice of `whole`, whose place this is.
    pub(crate) fn within(self, whole: &str, part: &str) -> Self {
        let offset = (part.as_ptr() as usize).saturating_sub(whole.as_ptr() as usize);
        Self {
            base: self.at(offset),
        }
    }

    pub(crate) fn at(self, offset: usize) -> Location {
        Location {
            line: self.base.line,
            column: self
                .base
                .column
                .saturating_add(u32::try_from(offset).unwrap_or(u32::MAX)),
        }
    }
}

fn syntax(error: SyntaxError, place: Place, offset: usize) -> Error {
    Error::Read(match error {
        SyntaxError::Unexpected(at) => ReadError::Expression {
            at: place.at(offset + at),
        },
        SyntaxError::UnknownName(at) => ReadError::UnknownName {
            at: place.at(offset + at),
        },
        SyntaxError::TooLong(at) => ReadError::TooManySymbols {
            max: MAX_CODE,
            at: place.at(offset + at),
        },
    })
}

/// The value of a constant expression (a `define:`), evaluated once and not kept.
pub(crate) fn constant(
    text: &str,
    constants: &[(&str, Real)],
    place: Place,
) -> Result<Real, Error> {
    let names = Names {
        params: &[],
        constants,
    };
    let mut code: Vec<Instr, MAX_CODE> = Vec::new();
    compile(text, &names, &mut code).map_err(|e| syntax(e, place, 0))?;
    evaluate(&code, &[], None).map_err(|_| Error::Read(ReadError::Expression { at: place.at(0) }))
}

/// The index of the `)` that closes the `(` at `open`, if any.
fn closing(bytes: &[u8], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (index, &byte) in bytes.iter().enumerate().skip(open) {
        match byte {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(index);
                }
            }
            _ => {}
        }
    }
    None
}

impl ParametricGrammar {
    /// An empty system.
    pub fn new() -> Self {
        Self {
            angle: Angle::Divisions(4),
            headings: Headings::quarter_turns(),
            code: Vec::new(),
            arguments: Vec::new(),
            modules: Vec::new(),
            productions: Vec::new(),
            axiom: (0, 0),
            axiom_at: Place {
                base: Location::column(1),
            },
            ignore: SymbolSet::default(),
            contextual: SymbolSet::default(),
            seed: 0,
            three_d: false,
        }
    }

    /// Empties it, in place.
    pub(crate) fn clear(&mut self) {
        self.angle = Angle::Divisions(4);
        self.headings = Headings::quarter_turns();
        self.code.clear();
        self.arguments.clear();
        self.modules.clear();
        self.productions.clear();
        self.axiom = (0, 0);
        self.ignore = SymbolSet::default();
        self.contextual = SymbolSet::default();
        self.seed = 0;
        self.three_d = false;
    }

    /// Seeds the choices among stochastic productions (see
    /// [`Grammar::with_seed`](crate::Grammar::with_seed)).
    pub fn set_seed(&mut self, seed: u32) {
        self.seed = seed;
    }

    /// The seed of the stochastic choices.
    pub const fn seed(&self) -> u32 {
        self.seed
    }

    /// Sets the symbols contexts skip (`ignore: +-F`); spaces are not symbols.
    pub(crate) fn set_ignore(&mut self, symbols: &str) {
        for symbol in symbols.bytes().filter(|b| !b.is_ascii_whitespace()) {
            self.ignore.insert(symbol);
        }
    }

    /// Whether any module turns in space (`& ^ \\ / $`): the system is drawn in 3D.
    pub fn is_3d(&self) -> bool {
        self.three_d
    }

    /// Whether it is written in the lecture's matrix notation: a module `D`, `T`, `R(deg)`
    /// or `S(s)` that no production rewrites (a symbol with productions is the system's
    /// own, as `D` in the 3D Hilbert curve). Drawn by the matrix turtle.
    pub fn is_matrix(&self) -> bool {
        self.modules.iter().any(|module| {
            let command = matches!(module.symbol, b'D' | b'T')
                || (matches!(module.symbol, b'R' | b'S') && module.arguments > 0);
            command
                && !self
                    .productions
                    .iter()
                    .any(|p| p.predecessor.symbol == module.symbol)
        })
    }

    /// Whether any expression asks the environment (`env(k)`): an open system.
    pub fn uses_environment(&self) -> bool {
        self.code.contains(&Instr::Env)
    }

    /// Open systems do not combine with contexts: a context search expands modules ahead of
    /// the turtle, which an environment would have to answer about.
    pub(crate) fn check_open(&self) -> Result<(), Error> {
        let contextual = self
            .productions
            .iter()
            .find(|p| p.left.is_some() || p.right.is_some());
        match contextual {
            Some(production) if self.uses_environment() => {
                Err(Error::Read(ReadError::Unsupported {
                    feature: Unsupported::EnvironmentWithContext,
                    at: production.successor_at.at(0),
                }))
            }
            _ => Ok(()),
        }
    }

    /// Whether any production has a context.
    pub(crate) fn has_context(&self) -> bool {
        self.productions
            .iter()
            .any(|p| p.left.is_some() || p.right.is_some())
    }

    /// Whether `symbol` has a production with a context: its rewriting can change from one
    /// level to the next as its neighbours do.
    pub(crate) fn is_contextual(&self, symbol: u8) -> bool {
        self.contextual.contains(symbol)
    }

    /// Whether contexts skip `symbol`.
    pub(crate) fn is_ignored(&self, symbol: u8) -> bool {
        self.ignore.contains(symbol)
    }

    /// The module at `index` of all modules (frames keep in-range positions).
    fn module(&self, index: u16) -> Module {
        self.modules
            .get(usize::from(index))
            .copied()
            .unwrap_or(Module {
                symbol: 0,
                first_argument: 0,
                arguments: 0,
                offset: 0,
            })
    }

    /// The position after the `]` that closes the `[` at `open`, within `..end`.
    fn branch_end(&self, open: u16, end: u16) -> u16 {
        let mut depth = 0usize;
        for index in open..end {
            match self.module(index).symbol {
                b'[' => depth += 1,
                b']' => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return index + 1;
                    }
                }
                _ => {}
            }
        }
        end
    }

    /// Compiles a string of modules (`B(2)A(4,4)`, `F(l)[+(a)X(l*0.9)]`) whose parameter
    /// expressions may use `params` and `constants`; returns where its modules are.
    fn modules_of(
        &mut self,
        text: &str,
        params: &[&str],
        constants: &[(&str, Real)],
        place: Place,
    ) -> Result<(u16, u16), Error> {
        let start = self.modules.len();
        let bytes = text.as_bytes();
        let mut at = 0;
        // Branches balance within each string, so a context can skip one without leaving it.
        let (mut depth, mut outermost_open) = (0usize, 0);
        while let Some(&symbol) = bytes.get(at) {
            if symbol.is_ascii_whitespace() {
                at += 1;
                continue;
            }
            if !symbol.is_ascii() {
                return Err(Error::Read(ReadError::NonAsciiSymbol { at: place.at(at) }));
            }
            self.three_d |= b"&^\\/$".contains(&symbol);
            match symbol {
                b'[' => {
                    if depth == 0 {
                        outermost_open = at;
                    }
                    depth += 1;
                }
                b']' => {
                    depth =
                        depth
                            .checked_sub(1)
                            .ok_or(Error::Read(ReadError::UnbalancedBracket {
                                at: place.at(at),
                            }))?;
                }
                _ => {}
            }
            let first_argument = u16::try_from(self.arguments.len()).unwrap_or(u16::MAX);
            let mut arguments = 0u8;
            let mut next = at + 1;
            if bytes.get(next) == Some(&b'(') {
                let close = closing(bytes, next)
                    .ok_or(Error::Read(ReadError::Expression { at: place.at(next) }))?;
                let inner = text.get(next + 1..close).unwrap_or_default();
                let mut offset = next + 1;
                for argument in split_top_level(inner) {
                    let names = Names { params, constants };
                    let code = compile(argument, &names, &mut self.code)
                        .map_err(|e| syntax(e, place, offset))?;
                    self.arguments.push(code).map_err(|_| {
                        Error::Read(ReadError::TooManySymbols {
                            max: MAX_ARGUMENTS,
                            at: place.at(offset),
                        })
                    })?;
                    arguments += 1;
                    if usize::from(arguments) > MAX_PARAMS {
                        return Err(Error::Read(ReadError::TooManyParameters {
                            max: MAX_PARAMS,
                            at: place.at(at),
                        }));
                    }
                    offset += argument.len() + 1;
                }
                next = close + 1;
            }
            self.modules
                .push(Module {
                    symbol,
                    first_argument,
                    arguments,
                    offset: u16::try_from(at).unwrap_or(u16::MAX),
                })
                .map_err(|_| {
                    Error::Read(ReadError::TooManySymbols {
                        max: MAX_MODULES,
                        at: place.at(at),
                    })
                })?;
            at = next;
        }
        if depth > 0 {
            return Err(Error::Read(ReadError::UnclosedBracket {
                at: place.at(outermost_open),
            }));
        }
        let position = |index: usize| u16::try_from(index).unwrap_or(u16::MAX);
        Ok((position(start), position(self.modules.len())))
    }

    /// Sets the angle of `+` and `-` without a parameter.
    pub(crate) fn set_angle(&mut self, angle: Angle, at: Location) -> Result<(), Error> {
        self.headings = Headings::new(angle, at)?;
        self.angle = angle;
        Ok(())
    }

    /// The turn of `+` and `-` without a parameter.
    pub const fn angle(&self) -> Angle {
        self.angle
    }

    pub(crate) const fn headings(&self) -> &Headings {
        &self.headings
    }

    /// Sets the axiom, e.g. `B(2)A(4,4)`.
    pub(crate) fn set_axiom(
        &mut self,
        text: &str,
        constants: &[(&str, Real)],
        place: Place,
    ) -> Result<(), Error> {
        self.axiom = self.modules_of(text, &[], constants, place)?;
        self.axiom_at = place;
        Ok(())
    }

    /// Adds `lc < pred > rc : condition --> successor : probability`: `left_side` is
    /// `A`, `A(x,y)` or with contexts `B(z) < A(x) > C`; the parameters of the contexts and
    /// the predecessor together are at most [`MAX_PARAMS`].
    pub(crate) fn add_production<'t>(
        &mut self,
        left_side: (&'t str, Place),
        condition: Option<(&str, Place)>,
        successor: (&str, Place),
        probability: Option<(Real, Location)>,
        constants: &[(&str, Real)],
    ) -> Result<(), Error> {
        let (text, place) = left_side;
        let mut names: Vec<&'t str, MAX_PARAMS> = Vec::new();
        let (left, rest) = match text.split_once('<') {
            Some((left, rest)) => (Some(left), rest),
            None => (None, text),
        };
        let (predecessor, right) = match rest.split_once('>') {
            Some((predecessor, right)) => (predecessor, Some(right)),
            None => (rest, None),
        };
        let mut pattern_of = |part: &'t str| pattern(part, place.within(text, part), &mut names);
        let left = left.map(&mut pattern_of).transpose()?;
        let predecessor_place = place.within(text, predecessor.trim_start());
        let predecessor = pattern_of(predecessor)?;
        let right = right.map(&mut pattern_of).transpose()?;
        if matches!(predecessor.symbol, b'[' | b']') {
            return Err(Error::Read(ReadError::ReservedRule {
                symbol: char::from(predecessor.symbol),
                at: predecessor_place.at(0),
            }));
        }
        let condition = match condition {
            None => None,
            Some((text, place)) => {
                let names = Names {
                    params: &names,
                    constants,
                };
                Some(compile(text, &names, &mut self.code).map_err(|e| syntax(e, place, 0))?)
            }
        };
        // Weights in units of 2⁻¹⁴, as in the plain grammar.
        let weight = match probability {
            None => 0,
            Some((p, at)) => u16::try_from(shift_round(i128::from(p.to_bits()), 18))
                .ok()
                .filter(|&w| w > 0)
                .ok_or(Error::Read(ReadError::ProbabilityOutOfRange { at }))?,
        };
        let (text, successor_place) = successor;
        let (start, end) = self.modules_of(text, &names, constants, successor_place)?;
        if left.is_some() || right.is_some() {
            self.contextual.insert(predecessor.symbol);
        }
        self.productions
            .push(Production {
                left,
                predecessor,
                right,
                condition,
                weight,
                start,
                end,
                successor_at: successor_place,
            })
            .map_err(|_| {
                Error::Read(ReadError::TooManyRules {
                    max: MAX_PRODUCTIONS,
                    at: predecessor_place.at(0),
                })
            })
    }

    fn code(&self, code: Code) -> &[Instr] {
        self.code
            .get(usize::from(code.start)..usize::from(code.end))
            .unwrap_or_default()
    }

    /// The values of a module's parameters, given its production's bound ones.
    fn values(&self, module: &Module, bound: &[Real], query: Query) -> Result<Values, EvalError> {
        let mut values = Values::default();
        for index in 0..usize::from(module.arguments) {
            let code = self
                .arguments
                .get(usize::from(module.first_argument) + index)
                .copied()
                .unwrap_or_default();
            let value = evaluate(self.code(code), bound, query)?;
            if let Some(slot) = values.values.get_mut(index) {
                *slot = value;
            }
        }
        values.count = module.arguments;
        Ok(values)
    }

    /// Checks that every module whose symbol has productions has as many parameters as
    /// one of them takes: a module no production can ever rewrite is most often a typo.
    pub(crate) fn check_arities(&self) -> Result<(), Error> {
        let strings = core::iter::once((self.axiom, self.axiom_at)).chain(
            self.productions
                .iter()
                .map(|p| ((p.start, p.end), p.successor_at)),
        );
        for ((start, end), place) in strings {
            for index in start..end {
                let module = self.module(index);
                let mut arities = self
                    .productions
                    .iter()
                    .filter(|p| p.predecessor.symbol == module.symbol)
                    .map(|p| p.predecessor.params);
                let Some(expected) = arities.clone().next() else {
                    continue;
                };
                if !arities.any(|params| params == module.arguments) {
                    return Err(Error::Read(ReadError::WrongArity {
                        symbol: char::from(module.symbol),
                        found: module.arguments,
                        expected,
                        at: place.at(usize::from(module.offset)),
                    }));
                }
            }
        }
        Ok(())
    }

    /// The parameters a production binds (its contexts' and its predecessor's, in order)
    /// if it rewrites `module` between `left` and `right` and its condition holds.
    fn binding(
        &self,
        production: &Production,
        module: &Neighbour,
        left: Option<&Neighbour>,
        right: Option<&Neighbour>,
        query: Query,
    ) -> Result<Option<Values>, EvalError> {
        let mut bound = Values::default();
        let contexts = [(production.left, left), (production.right, right)];
        if !production.predecessor.matches(module) {
            return Ok(None);
        }
        for (pattern, neighbour) in contexts {
            match (pattern, neighbour) {
                (None, _) => {}
                (Some(pattern), Some(neighbour)) if pattern.matches(neighbour) => {}
                (Some(_), _) => return Ok(None),
            }
        }
        let parts = [
            production.left.and(left),
            Some(module),
            production.right.and(right),
        ];
        for part in parts.into_iter().flatten() {
            for &value in part.values.as_slice() {
                if let Some(slot) = bound.values.get_mut(usize::from(bound.count)) {
                    *slot = value;
                    bound.count += 1;
                }
            }
        }
        let holds = match production.condition {
            None => true,
            Some(code) => evaluate(self.code(code), bound.as_slice(), query)? != Real::ZERO,
        };
        Ok(holds.then_some(bound))
    }

    /// The production that rewrites `module` between `left` and `right` (contexts as
    /// found, skipping ignored symbols), and the parameters it binds: the first that
    /// applies, or when that one is stochastic, one of the applicable stochastic ones
    /// picked by `key` with its weight's share.
    fn production_for(
        &self,
        module: &Neighbour,
        left: Option<&Neighbour>,
        right: Option<&Neighbour>,
        key: u32,
        query: Query,
    ) -> Result<Option<(u8, Values)>, EvalError> {
        let mut total = 0u64;
        for (index, production) in self.productions.iter().enumerate() {
            let Some(bound) = self.binding(production, module, left, right, query)? else {
                continue;
            };
            if production.weight == 0 {
                if total == 0 {
                    return Ok(u8::try_from(index).ok().map(|index| (index, bound)));
                }
                continue;
            }
            total += u64::from(production.weight);
        }
        let mut pick = pick(key, total);
        for (index, production) in self.productions.iter().enumerate() {
            if production.weight == 0 {
                continue;
            }
            let Some(bound) = self.binding(production, module, left, right, query)? else {
                continue;
            };
            let weight = u64::from(production.weight);
            if pick < weight {
                return Ok(u8::try_from(index).ok().map(|index| (index, bound)));
            }
            pick -= weight;
        }
        Ok(None)
    }
}

/// A module pattern `A` or `A(x,y)` of a left side; its parameter names join `names`.
fn pattern<'a>(
    text: &'a str,
    place: Place,
    names: &mut Vec<&'a str, MAX_PARAMS>,
) -> Result<Pattern, Error> {
    let text = text.trim();
    let bytes = text.as_bytes();
    let symbol = *bytes
        .first()
        .filter(|b| b.is_ascii() && !b.is_ascii_whitespace())
        .ok_or(Error::Read(ReadError::NotOneSymbol { at: place.at(0) }))?;
    let mut params = 0u8;
    match bytes.get(1) {
        None => {}
        Some(b'(') if text.ends_with(')') => {
            for name in text.get(2..text.len() - 1).unwrap_or_default().split(',') {
                let name = name.trim();
                let valid = !name.is_empty()
                    && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
                if !valid {
                    return Err(Error::Read(ReadError::Expression { at: place.at(2) }));
                }
                names.push(name).map_err(|_| {
                    Error::Read(ReadError::TooManyParameters {
                        max: MAX_PARAMS,
                        at: place.at(0),
                    })
                })?;
                params += 1;
            }
        }
        Some(_) => return Err(Error::Read(ReadError::NotOneSymbol { at: place.at(0) })),
    }
    Ok(Pattern { symbol, params })
}

impl Default for ParametricGrammar {
    fn default() -> Self {
        Self::new()
    }
}

/// The arguments of a `(...)`, split at commas outside parentheses.
fn split_top_level(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    core::iter::from_fn(move || {
        let current = rest?;
        let mut depth = 0i32;
        for (index, byte) in current.bytes().enumerate() {
            match byte {
                b'(' => depth += 1,
                b')' => depth -= 1,
                b',' if depth == 0 => {
                    rest = current.get(index + 1..);
                    return current.get(..index);
                }
                _ => {}
            }
        }
        rest = None;
        Some(current)
    })
}

/// A module's parameter values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Values {
    values: [Real; MAX_PARAMS],
    count: u8,
}

impl Values {
    /// The first value, if any.
    pub fn first(&self) -> Option<Real> {
        self.as_slice().first().copied()
    }

    /// The values, in order.
    pub fn as_slice(&self) -> &[Real] {
        self.values
            .get(..usize::from(self.count))
            .unwrap_or_default()
    }
}

/// A module of a derived string: its symbol and parameter values. Displays as
/// `A(1.1429,0)`: values with at most 4 decimals, trailing zeros dropped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DerivedModule {
    /// The symbol.
    pub symbol: char,
    /// The parameter values.
    pub values: Values,
}

impl fmt::Display for DerivedModule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        f.write_char(self.symbol)?;
        if self.values.count == 0 {
            return Ok(());
        }
        f.write_char('(')?;
        for (index, value) in self.values.as_slice().iter().enumerate() {
            if index > 0 {
                f.write_char(',')?;
            }
            write_four_decimals(f, *value)?;
        }
        f.write_char(')')
    }
}

/// One expansion level: a production's modules (or the axiom's, or one module kept for a
/// level), the read position in them, and the values its predecessor bound.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    position: u16,
    end: u16,
    /// This expansion's place in the derivation tree, hashed: stochastic choices below it
    /// are functions of it (as in the plain walker).
    key: u16,
    /// The same place hashed to 64 bits: which expansion a context search remembered.
    path: u64,
    bound: Values,
}

/// The place of the expansion of the module at `at` inside the expansion `parent` (the
/// SplitMix64 finaliser over both).
pub(crate) const fn path_of(parent: u64, at: u16) -> u64 {
    let mut z = parent
        .wrapping_add(0x9E37_79B9_7F4A_7C15)
        .wrapping_add((at as u64) << 40);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Symbols read by a walk and by its context searches, against a budget.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Work {
    read: u64,
    budget: u64,
}

impl Work {
    fn tick(&mut self) -> Result<(), Error> {
        if self.read >= self.budget {
            return Err(Error::Walk(WalkError::BudgetExhausted {
                budget: self.budget,
            }));
        }
        self.read += 1;
        Ok(())
    }
}

/// The typed error for an expression of `symbol`'s that cannot be evaluated.
fn arithmetic(symbol: u8, problem: EvalError) -> Error {
    Error::Walk(WalkError::Arithmetic {
        symbol: char::from(symbol),
        problem: match problem {
            EvalError::DivisionByZero => Arithmetic::DivisionByZero,
            EvalError::OutOfRange => Arithmetic::OutOfRange,
            EvalError::TooDeep => Arithmetic::TooDeep,
            EvalError::NoEnvironment => {
                return Error::Walk(WalkError::NoEnvironment {
                    symbol: char::from(symbol),
                })
            }
        },
    })
}

/// What a read module becomes one level down.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Expansion {
    /// Its production's successor, with the parameters it bound.
    Successor(Frame),
    /// Itself, to be looked at again one level down (its neighbours may change there).
    Kept(Frame),
    /// Itself at every level down (no production can ever rewrite it).
    Final,
}

impl ParametricGrammar {
    /// The module at `at` of a frame whose predecessor bound `bound`, with its values.
    fn read(&self, at: u16, bound: &Values, query: Query) -> Result<Neighbour, Error> {
        let module = self.module(at);
        let values = self
            .values(&module, bound.as_slice(), query)
            .map_err(|problem| arithmetic(module.symbol, problem))?;
        Ok(Neighbour {
            symbol: module.symbol,
            values,
        })
    }

    /// How `module`, read at `at` in the frame `parent`, expands between `left` and
    /// `right`.
    fn expand(
        &self,
        module: &Neighbour,
        at: u16,
        parent: &Frame,
        contexts: (Option<&Neighbour>, Option<&Neighbour>),
        query: Query,
    ) -> Result<Expansion, Error> {
        let key = child_key(parent.key, at);
        let (left, right) = contexts;
        let choice = self
            .production_for(module, left, right, key, query)
            .map_err(|problem| arithmetic(module.symbol, problem))?;
        let kept = kept(key);
        let path = path_of(parent.path, at);
        Ok(match choice {
            Some((index, bound)) => {
                let production = self.productions.get(usize::from(index));
                let (position, end) = production.map_or((0, 0), |p| (p.start, p.end));
                Expansion::Successor(Frame {
                    position,
                    end,
                    key: kept,
                    path,
                    bound,
                })
            }
            None if self.is_contextual(module.symbol) => Expansion::Kept(Frame {
                position: at,
                end: at + 1,
                key: kept,
                path,
                bound: parent.bound,
            }),
            None => Expansion::Final,
        })
    }
}

/// The modules of a parametric system's derivation at an order, in order, without
/// building the string. Yields `Err` once (an arithmetic error, the budget, a capacity)
/// and ends.
///
/// For context-sensitive systems it also keeps, per level, the module a left context
/// sees, and finds right contexts by reading ahead from its frames (the README's `.lsys`
/// section says how, and what it costs).
#[derive(Debug, Clone)]
pub struct ParametricWalker<
    'g,
    const DEPTH: usize = { super::walker::DEFAULT_DEPTH },
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    grammar: &'g ParametricGrammar,
    order: u32,
    frames: Vec<Frame, DEPTH>,
    /// An error to hand out first (an order beyond `DEPTH`).
    pending: Option<Error>,
    work: Work,
    levels: Levels<DEPTH>,
    branches: Branches<SLOTS>,
    expansions: Expansions<DEPTH>,
}

impl<'g, const DEPTH: usize, const SLOTS: usize> ParametricWalker<'g, DEPTH, SLOTS> {
    /// A walk of `grammar` at `order`; fails if the order needs more than `DEPTH` levels.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        Ok(Self::starting(
            grammar,
            order,
            super::walker::DEFAULT_BUDGET,
        ))
    }

    /// A walk of `grammar` at `order` capped at `budget` modules, built in one piece (a
    /// walk is kilobytes: every `Result` or builder step around it is a copy on an MCU's
    /// stack). An order beyond `DEPTH` is its first item, an error.
    #[inline(always)]
    pub(crate) fn starting(grammar: &'g ParametricGrammar, order: u32, budget: u64) -> Self {
        let mut frames = Vec::new();
        let pending = check_order(order, DEPTH).err();
        if pending.is_none() {
            let (position, end) = grammar.axiom;
            // Cannot fail: DEPTH > order >= 0.
            let _ = frames.push(Frame {
                position,
                end,
                key: kept(mix(grammar.seed)),
                path: 0,
                bound: Values::default(),
            });
        }
        Self {
            grammar,
            order,
            frames,
            pending,
            work: Work { read: 0, budget },
            levels: Levels::new(),
            branches: Branches::new(),
            expansions: Expansions::new(),
        }
    }

    /// Stops the walk with [`WalkError::BudgetExhausted`] after `symbols` modules are read
    /// (context searches included).
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.work.budget = symbols;
        self
    }

    /// `%` (cpfg, L-Py): drops the rest of the branch it is in, up to the `]` that closes
    /// the branch (left to be read), or to the end of the string. The rest of the branch
    /// may go on beyond the frame `%` is in: it is then the rest of the frame above, and so
    /// up, skipped unexpanded.
    fn cut(&mut self) {
        let grammar = self.grammar;
        let mut depth = 0usize;
        while let Some(top) = self.frames.last_mut() {
            while top.position < top.end {
                match grammar.module(top.position).symbol {
                    b'[' => depth += 1,
                    b']' if depth == 0 => return,
                    b']' => depth -= 1,
                    _ => {}
                }
                top.position += 1;
            }
            self.frames.pop();
        }
    }

    /// The next module; `query` answers `env(k)` (the environment, about the turtle where
    /// the walk is).
    pub(crate) fn next_queried(&mut self, query: Query) -> Option<Result<DerivedModule, Error>> {
        if let Some(error) = self.pending.take() {
            return Some(Err(error));
        }
        match self.step(query) {
            Ok(module) => module.map(Ok),
            Err(error) => {
                self.frames.clear();
                Some(Err(error))
            }
        }
    }

    /// Modules read so far, context searches included.
    pub const fn symbols_read(&self) -> u64 {
        self.work.read
    }

    /// The next module, or `None` at the end.
    fn step(&mut self, query: Query) -> Result<Option<DerivedModule>, Error> {
        let grammar = self.grammar;
        let contextual = grammar.has_context();
        let order = usize::try_from(self.order).unwrap_or(usize::MAX);
        loop {
            let level = self.frames.len().wrapping_sub(1);
            let Some(top) = self.frames.last_mut() else {
                return Ok(None);
            };
            if top.position >= top.end {
                self.frames.pop();
                continue;
            }
            self.work.tick()?;
            let at = top.position;
            top.position += 1;
            let parent = *top;
            let module = grammar.read(at, &parent.bound, query)?;
            if module.symbol == b'%' {
                self.cut();
                continue;
            }
            let derived = DerivedModule {
                symbol: char::from(module.symbol),
                values: module.values,
            };
            if level >= order {
                return Ok(Some(derived));
            }
            if contextual {
                match module.symbol {
                    b'[' => {
                        self.branches.open(&self.levels, level, order)?;
                        return Ok(Some(derived));
                    }
                    b']' => {
                        self.branches.close(&mut self.levels, level, order);
                        return Ok(Some(derived));
                    }
                    _ => {}
                }
            }
            let expansion = if grammar.is_contextual(module.symbol) {
                expand_in_context(
                    grammar,
                    &module,
                    (at, true),
                    &self.frames,
                    &self.levels,
                    &mut self.expansions,
                    &mut self.work,
                )?
            } else {
                grammar.expand(&module, at, &parent, (None, None), query)?
            };
            if contextual {
                self.levels.visit(grammar, level, &module);
            }
            let frame = match expansion {
                Expansion::Successor(frame) | Expansion::Kept(frame) => frame,
                Expansion::Final => {
                    if contextual {
                        for below in level + 1..order {
                            self.levels.visit(grammar, below, &module);
                        }
                    }
                    return Ok(Some(derived));
                }
            };
            // Cannot fail: `new` checked that order + 1 <= DEPTH.
            self.frames
                .push(frame)
                .map_err(|_| order_too_high(self.order, DEPTH))?;
        }
    }
}

impl<const DEPTH: usize, const SLOTS: usize> Iterator for ParametricWalker<'_, DEPTH, SLOTS> {
    type Item = Result<DerivedModule, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_queried(None)
    }
}
