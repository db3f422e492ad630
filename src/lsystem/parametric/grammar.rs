//! A parametric system compiled from text: its modules, productions (contexts, conditions,
//! probabilities) and their expressions' code, with the checks made while reading.

use heapless::Vec;

use super::expr::{compile, evaluate, Code, Instr, Names, SyntaxError, MAX_CODE};
use super::tropism::Tropism;
use super::values::{Values, MAX_PARAMS};
use crate::error::{Error, Location, ReadError, Unsupported};
use crate::lsystem::alphabet::SymbolSet;
use crate::math::angle::Headings;
use crate::math::wide::shift_round;
use crate::math::{Angle, Real};

/// [`ParametricGrammar::MAX_MODULES`], for the crate's own types and arrays.
pub(crate) const MAX_MODULES: usize = 256;

/// [`ParametricGrammar::MAX_ARGUMENTS`], for the crate's own types and arrays.
pub(crate) const MAX_ARGUMENTS: usize = 256;

/// [`ParametricGrammar::MAX_PRODUCTIONS`], for the crate's own types and arrays.
pub(crate) const MAX_PRODUCTIONS: usize = 32;

/// [`ParametricGrammar::MAX_CONSTANTS`], for the crate's own types and arrays.
pub(crate) const MAX_CONSTANTS: usize = 16;

/// A module of the axiom or a successor: a symbol and its parameter expressions.
#[derive(Debug, Clone, Copy)]
pub(super) struct Module {
    pub(super) symbol: u8,
    pub(super) first_argument: u16,
    pub(super) arguments: u8,
    /// Where it is in its string's text (for errors).
    pub(super) offset: u16,
}

/// A module of a production's left side: its symbol and number of parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Pattern {
    pub(super) symbol: u8,
    pub(super) params: u8,
}

impl Pattern {
    pub(super) fn matches(self, module: &Neighbour) -> bool {
        self.symbol == module.symbol && self.params == module.values.count
    }
}

/// `lc < pred > rc : condition --> successor : probability`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Production {
    pub(super) left: Option<Pattern>,
    pub(super) predecessor: Pattern,
    pub(super) right: Option<Pattern>,
    pub(super) condition: Option<Code>,
    /// 0 for a deterministic production; else its weight among the applicable stochastic
    /// ones, in units of 2⁻¹⁴.
    pub(super) weight: u16,
    /// Its modules, `start..end`.
    pub(super) start: u16,
    pub(super) end: u16,
    /// Where its successor's text is (for errors).
    pub(super) successor_at: Place,
}

/// Which productions rewrite a module: the derivation's, or the homomorphism's (applied
/// once, when drawing).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rewrite {
    Derivation,
    Homomorphism,
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
    pub(super) angle: Angle,
    /// Its directions for the 2D turtle.
    pub(super) headings: Headings,
    pub(super) code: Vec<Instr, MAX_CODE>,
    pub(super) arguments: Vec<Code, MAX_ARGUMENTS>,
    pub(super) modules: Vec<Module, MAX_MODULES>,
    pub(super) productions: Vec<Production, MAX_PRODUCTIONS>,
    pub(super) axiom: (u16, u16),
    pub(super) axiom_at: Place,
    /// Symbols a context skips (`ignore:`).
    pub(super) ignore: SymbolSet,
    /// Symbols with a production that has a context.
    pub(super) contextual: SymbolSet,
    /// Symbols a production of the derivation rewrites, and of the homomorphism: a
    /// module of any other symbol is kept without trying each production.
    pub(super) rewritten: (SymbolSet, SymbolSet),
    /// Seeds the choices among stochastic productions.
    pub(super) seed: u32,
    /// Whether any module turns in space (`& ^ \\ / $`).
    pub(super) three_d: bool,
    /// Whether any module draws a surface or a width (`{ } . ! _`), or a tropism bends it.
    pub(super) surfaces: bool,
    /// Where the homomorphism's productions start among `productions` (all of them are
    /// the derivation's when it is `productions.len()` or more).
    pub(super) homomorphism_from: u8,
    /// The tropism (`tropism:`), if any.
    pub(super) tropism: Option<Tropism>,
    /// The initial line width and the step of `!` and `_` (`width:`), in turtle units.
    pub(super) width: (Real, Real),
}

/// The step of `!` and `_` without a parameter when `width:` gives none: a tenth of a
/// unit step.
pub(crate) const DEFAULT_WIDTH_STEP: Real = Real::from_bits((1 << 32) / 10);

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

pub(super) fn syntax(error: SyntaxError, place: Place, offset: usize) -> Error {
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
pub(super) fn closing(bytes: &[u8], open: usize) -> Option<usize> {
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
    /// Most named constants (`define:`).
    pub const MAX_CONSTANTS: usize = MAX_CONSTANTS;

    /// Most productions.
    pub const MAX_PRODUCTIONS: usize = MAX_PRODUCTIONS;

    /// Most parameter expressions of all modules together.
    pub const MAX_ARGUMENTS: usize = MAX_ARGUMENTS;

    /// Most modules of the axiom and all successors together.
    pub const MAX_MODULES: usize = MAX_MODULES;

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
            rewritten: (SymbolSet::default(), SymbolSet::default()),
            seed: 0,
            three_d: false,
            surfaces: false,
            homomorphism_from: u8::MAX,
            tropism: None,
            width: (Real::ZERO, DEFAULT_WIDTH_STEP),
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
        self.rewritten = (SymbolSet::default(), SymbolSet::default());
        self.seed = 0;
        self.three_d = false;
        self.surfaces = false;
        self.homomorphism_from = u8::MAX;
        self.tropism = None;
        self.width = (Real::ZERO, DEFAULT_WIDTH_STEP);
    }

    /// The productions of a rewriting, and the index of the first among all.
    pub(super) fn rewriting(&self, rewrite: Rewrite) -> (usize, &[Production]) {
        let from = usize::from(self.homomorphism_from).min(self.productions.len());
        match rewrite {
            Rewrite::Derivation => (0, self.productions.get(..from).unwrap_or_default()),
            Rewrite::Homomorphism => (from, self.productions.get(from..).unwrap_or_default()),
        }
    }

    /// Whether a production of `rewrite` may rewrite `symbol` (symbols beyond ASCII are
    /// not kept in the sets: they may).
    pub(super) fn may_rewrite(&self, rewrite: Rewrite, symbol: u8) -> bool {
        let set = match rewrite {
            Rewrite::Derivation => self.rewritten.0,
            Rewrite::Homomorphism => self.rewritten.1,
        };
        symbol >= 128 || set.contains(symbol)
    }

    /// Whether it has a homomorphism: productions applied once, when drawing.
    pub fn has_homomorphism(&self) -> bool {
        usize::from(self.homomorphism_from) < self.productions.len()
    }

    /// Starts the homomorphism: productions added from now on apply when drawing only.
    pub(crate) fn start_homomorphism(&mut self) {
        self.homomorphism_from = u8::try_from(self.productions.len()).unwrap_or(u8::MAX);
    }

    /// Whether it draws surfaces or widths (`{ } . ! _`) or bends under a tropism: it is
    /// drawn by the 3D turtle, from the front unless it turns in space.
    pub fn draws_surfaces(&self) -> bool {
        self.surfaces || self.tropism.is_some()
    }

    /// Its tropism (`tropism:`), if any.
    pub const fn tropism(&self) -> Option<Tropism> {
        self.tropism
    }

    /// Sets its tropism.
    pub fn set_tropism(&mut self, tropism: Option<Tropism>) {
        self.tropism = tropism;
    }

    /// Its initial line width and the step of `!` and `_`, in turtle units (a step `F`
    /// is one).
    pub const fn width(&self) -> (Real, Real) {
        self.width
    }

    /// Sets the initial line width and the step of `!` and `_`.
    pub(crate) fn set_width(&mut self, width: Real, step: Real) {
        self.width = (width, step);
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
    pub(super) fn module(&self, index: u16) -> Module {
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
    pub(super) fn branch_end(&self, open: u16, end: u16) -> u16 {
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
    pub(super) fn modules_of(
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
            self.surfaces |= b"{}.!_".contains(&symbol);
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
        self.headings = Headings::new(angle).map_err(|out| ReadError::angle_at(out, at))?;
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
            if self.has_homomorphism_started() {
                return Err(Error::Read(ReadError::Unsupported {
                    feature: Unsupported::ContextInHomomorphism,
                    at: predecessor_place.at(0),
                }));
            }
            self.contextual.insert(predecessor.symbol);
        }
        if self.has_homomorphism_started() {
            self.rewritten.1.insert(predecessor.symbol);
        } else {
            self.rewritten.0.insert(predecessor.symbol);
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

    /// Whether `homomorphism:` has been read: productions go to the homomorphism.
    fn has_homomorphism_started(&self) -> bool {
        usize::from(self.homomorphism_from) <= self.productions.len()
    }

    /// The instructions of one expression.
    pub(super) fn code(&self, code: Code) -> &[Instr] {
        self.code
            .get(usize::from(code.start)..usize::from(code.end))
            .unwrap_or_default()
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
}

/// A module pattern `A` or `A(x,y)` of a left side; its parameter names join `names`.
pub(super) fn pattern<'a>(
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
pub(super) fn split_top_level(text: &str) -> impl Iterator<Item = &str> {
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
