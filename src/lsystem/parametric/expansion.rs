//! How one module expands one level down: the production chosen for it (contexts,
//! condition, probability), the values that production binds, and the walk's frame of it.

use super::expr::{evaluate, EvalError, Query};
use super::grammar::{Module, Neighbour, ParametricGrammar, Production, Rewrite};
use super::values::Values;
use crate::error::{Arithmetic, Error, WalkError};
use crate::lsystem::alphabet::SymbolSet;
use crate::lsystem::choice::{child_key, kept, pick};
use crate::lsystem::walker::Spent;
use crate::math::Real;

/// One expansion level: a production's modules (or the axiom's, or one module kept for a
/// level), the read position in them, and the values its predecessor bound.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    pub(super) position: u16,
    pub(super) end: u16,
    /// This expansion's place in the derivation tree, hashed: stochastic choices below it
    /// are functions of it (as in the plain walker).
    pub(super) key: u16,
    /// The same place hashed to 64 bits: which expansion a context search remembered.
    pub(super) path: u64,
    pub(super) bound: Values,
    /// Whether its modules are new in a growing walk (see
    /// [`ParametricWalker::growing`](super::walker::ParametricWalker::growing)).
    pub(super) growing: bool,
    /// Whether it is a homomorphism's successor: its modules are handed out as they are.
    pub(super) drawn: bool,
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

/// Symbols read by a walk and by its context searches, against a budget (counted down in
/// a machine word, as the plain walk counts).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Work {
    spent: Spent,
}

impl Work {
    /// Nothing read yet, against `budget`.
    pub(super) const fn new(budget: u64) -> Self {
        Self {
            spent: Spent::new(budget),
        }
    }

    /// Counts one symbol read, or the error of a spent budget.
    #[inline(always)]
    pub(super) fn tick(&mut self) -> Result<(), Error> {
        if self.spent.one_more() {
            Ok(())
        } else {
            Err(Error::Walk(WalkError::BudgetExhausted {
                budget: self.spent.budget(),
            }))
        }
    }

    /// Symbols read so far.
    pub(super) const fn read(&self) -> u64 {
        self.spent.read()
    }

    /// The same count against another budget.
    pub(super) const fn with_budget(self, budget: u64) -> Self {
        Self {
            spent: self.spent.with_budget(budget),
        }
    }
}

/// The typed error for an expression of `symbol`'s that cannot be evaluated.
pub(super) fn arithmetic(symbol: u8, problem: EvalError) -> Error {
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
    pub(super) fn read(&self, at: u16, bound: &Values, query: Query) -> Result<Neighbour, Error> {
        let mut values = Values::default();
        let symbol = self.read_into(at, bound, query, &mut values)?;
        Ok(Neighbour { symbol, values })
    }

    /// [`read`](Self::read), the values written into `values` (a walk's caller keeps
    /// them, instead of each module's passing up by value): the module's symbol.
    pub(super) fn read_into(
        &self,
        at: u16,
        bound: &Values,
        query: Query,
        values: &mut Values,
    ) -> Result<u8, Error> {
        let module = self.module(at);
        self.values_into(&module, bound.as_slice(), query, values)
            .map_err(|problem| arithmetic(module.symbol, problem))?;
        Ok(module.symbol)
    }

    /// How `module`, read at `at` in the frame `parent`, expands between `left` and
    /// `right`.
    pub(super) fn expand(
        &self,
        module: &Neighbour,
        at: u16,
        parent: &Frame,
        contexts: (Option<&Neighbour>, Option<&Neighbour>),
        query: Query,
    ) -> Result<Expansion, Error> {
        self.expand_by(Rewrite::Derivation, module, at, parent, contexts, query)
    }

    /// [`expand`](Self::expand) by the derivation's or the homomorphism's productions.
    pub(super) fn expand_by(
        &self,
        rewrite: Rewrite,
        module: &Neighbour,
        at: u16,
        parent: &Frame,
        contexts: (Option<&Neighbour>, Option<&Neighbour>),
        query: Query,
    ) -> Result<Expansion, Error> {
        let key = child_key(parent.key, at);
        let (left, right) = contexts;
        let choice = self
            .production_for(rewrite, module, left, right, key, query)
            .map_err(|problem| arithmetic(module.symbol, problem))?;
        let kept = kept(key);
        // Only a context search reads the path: a grammar without contexts keeps none.
        let path = if self.contextual == SymbolSet::default() {
            0
        } else {
            path_of(parent.path, at)
        };
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
                    growing: false,
                    drawn: false,
                })
            }
            None if self.is_contextual(module.symbol) => Expansion::Kept(Frame {
                position: at,
                end: at + 1,
                key: kept,
                path,
                bound: parent.bound,
                growing: parent.growing,
                drawn: false,
            }),
            None => Expansion::Final,
        })
    }
}

impl ParametricGrammar {
    /// The values of a module's parameters, given its production's bound ones, written
    /// into `values`.
    fn values_into(
        &self,
        module: &Module,
        bound: &[Real],
        query: Query,
        values: &mut Values,
    ) -> Result<(), EvalError> {
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
        Ok(())
    }

    /// The parameters a production binds (its contexts' and its predecessor's, in order)
    /// if it rewrites `module` between `left` and `right` and its condition holds. For a
    /// production whose predecessor matches `module` ([`production_for`] passes over the
    /// others before calling this).
    ///
    /// [`production_for`]: Self::production_for
    pub(super) fn binding(
        &self,
        production: &Production,
        module: &Neighbour,
        left: Option<&Neighbour>,
        right: Option<&Neighbour>,
        query: Query,
    ) -> Result<Option<Values>, EvalError> {
        debug_assert!(production.predecessor.matches(module));
        let bound = if production.left.is_none() && production.right.is_none() {
            // No contexts: the predecessor's values are the binding, as they are.
            module.values
        } else {
            match bind_in_context(production, module, left, right) {
                Some(bound) => bound,
                None => return Ok(None),
            }
        };
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
    pub(super) fn production_for(
        &self,
        rewrite: Rewrite,
        module: &Neighbour,
        left: Option<&Neighbour>,
        right: Option<&Neighbour>,
        key: u32,
        query: Query,
    ) -> Result<Option<(u8, Values)>, EvalError> {
        if !self.may_rewrite(rewrite, module.symbol) {
            return Ok(None);
        }
        let (first, productions) = self.rewriting(rewrite);
        let index_of = |index: usize| u8::try_from(first + index).ok();
        let mut total = 0u64;
        for (index, production) in productions.iter().enumerate() {
            // Another symbol's production, passed over here without a call to `binding`.
            if !production.predecessor.matches(module) {
                continue;
            }
            let Some(bound) = self.binding(production, module, left, right, query)? else {
                continue;
            };
            if production.weight == 0 {
                if total == 0 {
                    return Ok(index_of(index).map(|index| (index, bound)));
                }
                continue;
            }
            total += u64::from(production.weight);
        }
        let mut pick = pick(key, total);
        for (index, production) in productions.iter().enumerate() {
            if production.weight == 0 || !production.predecessor.matches(module) {
                continue;
            }
            let Some(bound) = self.binding(production, module, left, right, query)? else {
                continue;
            };
            let weight = u64::from(production.weight);
            if pick < weight {
                return Ok(index_of(index).map(|index| (index, bound)));
            }
            pick -= weight;
        }
        Ok(None)
    }
}

/// The parameters a production with a context binds: its left context's, its
/// predecessor's and its right context's, in order; `None` where a context does not match.
fn bind_in_context(
    production: &Production,
    module: &Neighbour,
    left: Option<&Neighbour>,
    right: Option<&Neighbour>,
) -> Option<Values> {
    let mut bound = Values::default();
    let contexts = [(production.left, left), (production.right, right)];
    for (pattern, neighbour) in contexts {
        match (pattern, neighbour) {
            (None, _) => {}
            (Some(pattern), Some(neighbour)) if pattern.matches(neighbour) => {}
            (Some(_), _) => return None,
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
    Some(bound)
}
