//! Parametric L-systems (ABOP 1.10): modules with fixed-point parameters, productions with
//! conditions, successors whose parameters are expressions of the predecessor's, derived
//! with bounded memory like every other system: each frame of the walk keeps the
//! parameters of the module it expands, and nothing else.
//!
//! ```text
//! axiom: B(2)A(4,4)
//! A(x,y) : y <= 3 --> A(x*2,x+y)
//! A(x,y) : y > 3  --> B(x)A(x/y,0)
//! B(x)   : x < 1  --> C
//! B(x)   : x >= 1 --> B(x-1)
//! ```
//!
//! A module is rewritten by the first production for its symbol and number of parameters
//! whose condition holds; a module with none is kept. Capacities are named constants; a
//! system beyond them is a typed error naming the limit. Worst-case RAM (tested): the
//! grammar 10.4 KiB (8 KiB of it the expression code, 16 bytes an instruction); a walk
//! `DEPTH` frames of 48 bytes (the bound parameter values), 856 bytes for orders up to 16.
//!
//! [`ParametricLSystem`](crate::ParametricLSystem) draws them: `F(l)`, `f(l)`, `+(a)`,
//! `-(a)` take their parameter as length and degrees.

pub(crate) mod draw;
pub(crate) mod expr;

use core::fmt;

use heapless::Vec;

use self::expr::{compile, evaluate, Code, EvalError, Instr, Names, SyntaxError, MAX_CODE};
use super::walker::{check_order, order_too_high};
use crate::error::{Arithmetic, Error, Location, ReadError, WalkError};
use crate::math::angle::Headings;
use crate::math::decimal::write_four_decimals;
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
}

/// `symbol(params) : condition --> successor`.
#[derive(Debug, Clone, Copy)]
struct Production {
    symbol: u8,
    params: u8,
    condition: Option<Code>,
    /// Its modules, `start..end`.
    start: u16,
    end: u16,
}

/// A parametric system, compiled from text.
#[derive(Debug, Clone)]
pub struct ParametricGrammar {
    /// The turtle's directions for `+` and `-` without a parameter (a quarter turn unless
    /// set).
    headings: Headings,
    code: Vec<Instr, MAX_CODE>,
    arguments: Vec<Code, MAX_ARGUMENTS>,
    modules: Vec<Module, MAX_MODULES>,
    productions: Vec<Production, MAX_PRODUCTIONS>,
    axiom: (u16, u16),
}

/// What a text position is, for errors: `base` is where `text` starts.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Place {
    pub(crate) base: Location,
}

impl Place {
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
    evaluate(&code, &[]).map_err(|_| Error::Read(ReadError::Expression { at: place.at(0) }))
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
            headings: Headings::quarter_turns(),
            code: Vec::new(),
            arguments: Vec::new(),
            modules: Vec::new(),
            productions: Vec::new(),
            axiom: (0, 0),
        }
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
        while let Some(&symbol) = bytes.get(at) {
            if symbol.is_ascii_whitespace() {
                at += 1;
                continue;
            }
            if !symbol.is_ascii() {
                return Err(Error::Read(ReadError::NonAsciiSymbol { at: place.at(at) }));
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
                })
                .map_err(|_| {
                    Error::Read(ReadError::TooManySymbols {
                        max: MAX_MODULES,
                        at: place.at(at),
                    })
                })?;
            at = next;
        }
        let position = |index: usize| u16::try_from(index).unwrap_or(u16::MAX);
        Ok((position(start), position(self.modules.len())))
    }

    /// Sets the angle of `+` and `-` without a parameter.
    pub(crate) fn set_angle(&mut self, angle: Angle, at: Location) -> Result<(), Error> {
        self.headings = Headings::new(angle, at)?;
        Ok(())
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
        Ok(())
    }

    /// Adds `predecessor : condition --> successor`; `predecessor` is `A` or `A(x,y)`.
    pub(crate) fn add_production(
        &mut self,
        predecessor: (&str, Place),
        condition: Option<(&str, Place)>,
        successor: (&str, Place),
        constants: &[(&str, Real)],
    ) -> Result<(), Error> {
        let (text, place) = predecessor;
        let text = text.trim();
        let bytes = text.as_bytes();
        let symbol = *bytes
            .first()
            .filter(|b| b.is_ascii() && !b.is_ascii_whitespace())
            .ok_or(Error::Read(ReadError::NotOneSymbol { at: place.at(0) }))?;
        let mut params: Vec<&str, MAX_PARAMS> = Vec::new();
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
                    params.push(name).map_err(|_| {
                        Error::Read(ReadError::TooManyParameters {
                            max: MAX_PARAMS,
                            at: place.at(0),
                        })
                    })?;
                }
            }
            Some(_) => return Err(Error::Read(ReadError::NotOneSymbol { at: place.at(0) })),
        }
        let condition = match condition {
            None => None,
            Some((text, place)) => {
                let names = Names {
                    params: &params,
                    constants,
                };
                Some(compile(text, &names, &mut self.code).map_err(|e| syntax(e, place, 0))?)
            }
        };
        let (text, place) = successor;
        let (start, end) = self.modules_of(text, &params, constants, place)?;
        self.productions
            .push(Production {
                symbol,
                params: u8::try_from(params.len()).unwrap_or(u8::MAX),
                condition,
                start,
                end,
            })
            .map_err(|_| {
                Error::Read(ReadError::TooManyRules {
                    max: MAX_PRODUCTIONS,
                    at: place.at(0),
                })
            })
    }

    fn code(&self, code: Code) -> &[Instr] {
        self.code
            .get(usize::from(code.start)..usize::from(code.end))
            .unwrap_or_default()
    }

    /// The values of a module's parameters, given its production's bound ones.
    fn values(&self, module: &Module, bound: &[Real]) -> Result<Values, EvalError> {
        let mut values = Values::default();
        for index in 0..usize::from(module.arguments) {
            let code = self
                .arguments
                .get(usize::from(module.first_argument) + index)
                .copied()
                .unwrap_or_default();
            let value = evaluate(self.code(code), bound)?;
            if let Some(slot) = values.values.get_mut(index) {
                *slot = value;
            }
        }
        values.count = module.arguments;
        Ok(values)
    }

    /// The first production that rewrites `symbol` with `values`.
    fn production_for(&self, symbol: u8, values: &Values) -> Result<Option<u8>, EvalError> {
        for (index, production) in self.productions.iter().enumerate() {
            if production.symbol != symbol || production.params != values.count {
                continue;
            }
            let holds = match production.condition {
                None => true,
                Some(code) => evaluate(self.code(code), values.as_slice())? != Real::ZERO,
            };
            if holds {
                return Ok(u8::try_from(index).ok());
            }
        }
        Ok(None)
    }
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

/// One expansion level: the read position in a production's modules (or the axiom's), and
/// the values its predecessor's parameters are bound to.
#[derive(Debug, Clone, Copy)]
struct Frame {
    position: u16,
    end: u16,
    bound: Values,
}

/// The modules of a parametric system's derivation at an order, in order, without
/// building the string. Yields `Err` once (an arithmetic error, the budget) and ends.
#[derive(Debug, Clone)]
pub struct ParametricWalker<'g, const DEPTH: usize = { super::walker::DEFAULT_DEPTH }> {
    grammar: &'g ParametricGrammar,
    order: u32,
    frames: Vec<Frame, DEPTH>,
    read: u64,
    budget: u64,
}

impl<'g, const DEPTH: usize> ParametricWalker<'g, DEPTH> {
    /// A walk of `grammar` at `order`; fails if the order needs more than `DEPTH` levels.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        let mut frames = Vec::new();
        let (position, end) = grammar.axiom;
        frames
            .push(Frame {
                position,
                end,
                bound: Values::default(),
            })
            .map_err(|_| order_too_high(order, DEPTH))?;
        Ok(Self {
            grammar,
            order,
            frames,
            read: 0,
            budget: super::walker::DEFAULT_BUDGET,
        })
    }

    /// Stops the walk with [`WalkError::BudgetExhausted`] after `symbols` modules are read.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.budget = symbols;
        self
    }
}

impl<const DEPTH: usize> Iterator for ParametricWalker<'_, DEPTH> {
    type Item = Result<DerivedModule, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let grammar = self.grammar;
        loop {
            let depth = self.frames.len();
            let top = self.frames.last_mut()?;
            if top.position >= top.end {
                self.frames.pop();
                continue;
            }
            if self.read >= self.budget {
                self.frames.clear();
                return Some(Err(Error::Walk(WalkError::BudgetExhausted {
                    budget: self.budget,
                })));
            }
            self.read += 1;
            let module = grammar
                .modules
                .get(usize::from(top.position))
                .copied()
                .unwrap_or(Module {
                    symbol: 0,
                    first_argument: 0,
                    arguments: 0,
                });
            top.position += 1;
            let bound = top.bound;
            let failed = |problem: EvalError, frames: &mut Vec<Frame, DEPTH>| {
                frames.clear();
                Some(Err(Error::Walk(WalkError::Arithmetic {
                    symbol: char::from(module.symbol),
                    problem: match problem {
                        EvalError::DivisionByZero => Arithmetic::DivisionByZero,
                        EvalError::OutOfRange => Arithmetic::OutOfRange,
                        EvalError::TooDeep => Arithmetic::TooDeep,
                    },
                })))
            };
            let values = match grammar.values(&module, bound.as_slice()) {
                Ok(values) => values,
                Err(problem) => return failed(problem, &mut self.frames),
            };
            let level = u32::try_from(depth - 1).unwrap_or(u32::MAX);
            if level < self.order {
                match grammar.production_for(module.symbol, &values) {
                    Err(problem) => return failed(problem, &mut self.frames),
                    Ok(Some(index)) => {
                        let production = grammar.productions.get(usize::from(index));
                        if let Some(production) = production {
                            let frame = Frame {
                                position: production.start,
                                end: production.end,
                                bound: values,
                            };
                            // Cannot fail: `new` checked that order + 1 <= DEPTH.
                            if self.frames.push(frame).is_ok() {
                                continue;
                            }
                        }
                    }
                    Ok(None) => {}
                }
            }
            return Some(Ok(DerivedModule {
                symbol: char::from(module.symbol),
                values,
            }));
        }
    }
}
