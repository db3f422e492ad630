//! The walk of a parametric system's derivation: a stack of frames, one a level, and the
//! left contexts and remembered expansions a context-sensitive system needs.

use heapless::Vec;

use super::context::{expand_in_context, Branches, Expansions, Levels, MAX_CONTEXT_SLOTS};
use super::expansion::{Expansion, Frame, Work};
use super::expr::Query;
use super::grammar::{Neighbour, ParametricGrammar, Rewrite};
use super::values::{DerivedModule, Values};
use crate::error::Error;
use crate::lsystem::choice::{kept, mix};
use crate::lsystem::walker::{check_order, order_too_high};
use crate::math::Real;

/// The modules of a parametric system's derivation at an order, in order, without
/// building the string. Yields `Err` once (an arithmetic error, the budget, a capacity)
/// and ends.
///
/// For context-sensitive systems it also keeps, per level, the module a left context
/// sees, and finds right contexts by reading ahead from its frames (docs/lsystems.md's `.lsys`
/// section says how, and what it costs).
#[derive(Debug, Clone)]
pub struct ParametricWalker<
    'g,
    const DEPTH: usize = { crate::lsystem::walker::DEFAULT_DEPTH },
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
    /// Whether the homomorphism rewrites the derived modules (when drawing).
    interpret: bool,
    /// How far the last order's new modules have grown in (see
    /// [`growing`](Self::growing)).
    growth: Option<Real>,
    /// Whether the grammar has a production with a context (asked once, not a module).
    contextual: bool,
}

impl<'g, const DEPTH: usize, const SLOTS: usize> ParametricWalker<'g, DEPTH, SLOTS> {
    /// A walk of `grammar` at `order`; fails if the order needs more than `DEPTH` levels.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        Ok(Self::starting(
            grammar,
            order,
            crate::lsystem::walker::DEFAULT_BUDGET,
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
                growing: false,
                drawn: false,
            });
        }
        Self {
            grammar,
            order,
            frames,
            pending,
            work: Work::new(budget),
            levels: Levels::new(),
            branches: Branches::new(),
            expansions: Expansions::new(),
            interpret: false,
            growth: None,
            contextual: grammar.has_context(),
        }
    }

    /// Hands out the modules as drawn: each derived module rewritten once by the system's
    /// homomorphism (`homomorphism:`) if one applies. The homomorphism is a level of the
    /// walk below the order: the order must be below `DEPTH - 1`.
    #[must_use]
    pub fn drawing(mut self) -> Self {
        if self.grammar.has_homomorphism() {
            self.interpret = true;
            if self.pending.is_none() {
                if let Err(error) = check_order(self.order + 1, DEPTH) {
                    self.pending = Some(error);
                    self.frames.clear();
                }
            }
        }
        self
    }

    /// Grows the last order's new modules in: at `fraction` t (0 to 1) of the way from
    /// order n − 1 to n (this walk's order), each module rewritten at the last step hands
    /// out its successor with every step `F`, `f`, `G` scaled by t, after itself (if a
    /// step) scaled by 1 − t. At t = 0 the picture is order n − 1's, at t = 1 order n's,
    /// and in between the new branches grow from nothing.
    #[must_use]
    pub fn growing(mut self, fraction: Real) -> Self {
        self.growth = Some(fraction.clamp(Real::ZERO, Real::ONE));
        self
    }

    /// Stops the walk with [`WalkError::BudgetExhausted`](crate::error::WalkError::BudgetExhausted) after `symbols` modules are read
    /// (context searches included).
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.work = self.work.with_budget(symbols);
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
        let mut module = DerivedModule::NONE;
        self.next_into(query, &mut module)
            .map(|outcome| outcome.map(|()| module))
    }

    /// [`next_queried`](Self::next_queried), the module written into `module` (a walk's
    /// caller keeps one, instead of each module passing up by value).
    pub(crate) fn next_into(
        &mut self,
        query: Query,
        module: &mut DerivedModule,
    ) -> Option<Result<(), Error>> {
        if let Some(error) = self.pending.take() {
            return Some(Err(error));
        }
        match self.step(query, module) {
            Ok(true) => Some(Ok(())),
            Ok(false) => None,
            Err(error) => {
                self.frames.clear();
                Some(Err(error))
            }
        }
    }

    /// Modules read so far, context searches included.
    pub const fn symbols_read(&self) -> u64 {
        self.work.read()
    }

    /// The next module written into `out`: false at the end.
    fn step(&mut self, query: Query, out: &mut DerivedModule) -> Result<bool, Error> {
        loop {
            match self.advance(query, out)? {
                Advanced::Module => return Ok(true),
                Advanced::End => return Ok(false),
                Advanced::Again => {}
            }
        }
    }

    /// One module read: handed out, or expanded (its successor's frame pushed).
    ///
    /// A system without contexts, not growing, takes the short way: each module read,
    /// expanded, its successor's frame pushed; contexts and growth go through
    /// [`expand_with_care`](Self::expand_with_care), out of line. One module a call, not
    /// a loop: most calls hand out the first module they read, and a loop here has the
    /// compiler set up, at every call, addresses that only its later rounds would use.
    #[inline(never)]
    fn advance(&mut self, query: Query, out: &mut DerivedModule) -> Result<Advanced, Error> {
        let grammar = self.grammar;
        let order = usize::try_from(self.order).unwrap_or(usize::MAX);
        let level = self.frames.len().wrapping_sub(1);
        let Some(top) = self.frames.last_mut() else {
            return Ok(Advanced::End);
        };
        if top.position >= top.end {
            self.frames.pop();
            return Ok(Advanced::Again);
        }
        self.work.tick()?;
        let at = top.position;
        top.position += 1;
        // The frame is copied only where an expansion needs it, not for every module.
        let (drawn, growing) = (top.drawn, top.growing);
        // Read straight into the caller's module: most are handed out as they are read,
        // and a module is a copy of 40 bytes each time it moves.
        let symbol = grammar.read_into(at, &top.bound, query, &mut out.values)?;
        if symbol == b'%' {
            self.cut();
            return Ok(Advanced::Again);
        }
        let read = |out: &DerivedModule| Neighbour {
            symbol,
            values: out.values,
        };
        if level >= order || drawn {
            if !drawn && self.interpret {
                if let Some(&parent) = self.frames.last() {
                    if self.interpreted(&read(out), at, &parent, query)? {
                        return Ok(Advanced::Again);
                    }
                }
            }
            out.symbol = char::from(symbol);
            if self.growth.is_some() {
                *out = self.grown(*out, growing);
            }
            return Ok(Advanced::Module);
        }
        let careful = self.contextual || self.growth.is_some();
        // Most modules of a production no production rewrites (`F`, `[`, the turns): they
        // are what they are at every level below, without a look at the productions (nor a
        // copy of the frame they are in).
        let rewritten = grammar.may_rewrite(Rewrite::Derivation, symbol);
        if !careful && !rewritten && !self.interpret {
            out.symbol = char::from(symbol);
            return Ok(Advanced::Module);
        }
        let Some(&parent) = self.frames.last() else {
            return Ok(Advanced::End);
        };
        if careful {
            let module = read(out);
            return Ok(
                match self.expand_with_care(&module, at, &parent, (level, order), query)? {
                    Some(module) => {
                        *out = module;
                        Advanced::Module
                    }
                    None => Advanced::Again,
                },
            );
        }
        if !rewritten {
            if self.interpret && self.interpreted(&read(out), at, &parent, query)? {
                return Ok(Advanced::Again);
            }
            out.symbol = char::from(symbol);
            return Ok(Advanced::Module);
        }
        let module = read(out);
        match grammar.expand(&module, at, &parent, (None, None), query)? {
            Expansion::Successor(frame) | Expansion::Kept(frame) => {
                // Cannot fail: `new` checked that order + 1 <= DEPTH.
                self.frames
                    .push(frame)
                    .map_err(|_| order_too_high(self.order, DEPTH))?;
                Ok(Advanced::Again)
            }
            Expansion::Final => {
                if self.interpreted(&module, at, &parent, query)? {
                    return Ok(Advanced::Again);
                }
                *out = derived(&module);
                Ok(Advanced::Module)
            }
        }
    }

    /// The expansion of `module` (read at `at` in `parent`, at `level` of `order`) in a
    /// system with contexts or growing: the module to hand out now, if any, with the
    /// successor's frame pushed where it has one.
    #[inline(never)]
    fn expand_with_care(
        &mut self,
        module: &Neighbour,
        at: u16,
        parent: &Frame,
        (level, order): (usize, usize),
        query: Query,
    ) -> Result<Option<DerivedModule>, Error> {
        let grammar = self.grammar;
        let contextual = self.contextual;
        let derived = derived(module);
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
                module,
                (at, true),
                &self.frames,
                &self.levels,
                &mut self.expansions,
                &mut self.work,
            )?
        } else {
            grammar.expand(module, at, parent, (None, None), query)?
        };
        if contextual {
            self.levels.visit(grammar, level, module);
        }
        let last_step = level + 1 == order;
        let frame = match (expansion, self.growth) {
            (Expansion::Successor(mut frame), Some(fraction)) if last_step => {
                frame.growing = true;
                // Cannot fail: `new` checked that order + 1 <= DEPTH.
                self.frames
                    .push(frame)
                    .map_err(|_| order_too_high(self.order, DEPTH))?;
                if is_step(derived.symbol) {
                    return Ok(Some(scaled(derived, Real::ONE.saturating_sub(fraction))));
                }
                return Ok(None);
            }
            (Expansion::Successor(frame) | Expansion::Kept(frame), _) => frame,
            (Expansion::Final, _) => {
                if contextual {
                    for below in level + 1..order {
                        self.levels.visit(grammar, below, module);
                    }
                }
                if self.interpreted(module, at, parent, query)? {
                    return Ok(None);
                }
                return Ok(Some(derived));
            }
        };
        // Cannot fail: `new` checked that order + 1 <= DEPTH.
        self.frames
            .push(frame)
            .map_err(|_| order_too_high(self.order, DEPTH))?;
        Ok(None)
    }
}

/// What one module read came to.
enum Advanced {
    /// A module to hand out (written where the caller asked).
    Module,
    /// Nothing yet: read on.
    Again,
    /// The end of the walk.
    End,
}

/// A read module as handed out.
fn derived(module: &Neighbour) -> DerivedModule {
    DerivedModule {
        symbol: char::from(module.symbol),
        values: module.values,
    }
}

impl<const DEPTH: usize, const SLOTS: usize> ParametricWalker<'_, DEPTH, SLOTS> {
    /// When drawing, rewrites `module` (read at `at` in `parent`) by the homomorphism:
    /// whether a production applied (its successor is then the next frame, handed out as
    /// it is).
    fn interpreted(
        &mut self,
        module: &Neighbour,
        at: u16,
        parent: &Frame,
        query: Query,
    ) -> Result<bool, Error> {
        if !self.interpret {
            return Ok(false);
        }
        let expansion = self.grammar.expand_by(
            Rewrite::Homomorphism,
            module,
            at,
            parent,
            (None, None),
            query,
        )?;
        let Expansion::Successor(mut frame) = expansion else {
            return Ok(false);
        };
        frame.growing = parent.growing;
        frame.drawn = true;
        self.frames
            .push(frame)
            .map_err(|_| order_too_high(self.order + 1, DEPTH))?;
        Ok(true)
    }

    /// `module` as handed out: its step scaled by the growth if it is new.
    fn grown(&self, module: DerivedModule, growing: bool) -> DerivedModule {
        match self.growth {
            Some(fraction) if growing && is_step(module.symbol) => scaled(module, fraction),
            _ => module,
        }
    }
}

/// Whether `symbol` is a step (`F`, `f`, `G`), whose length growth scales.
fn is_step(symbol: char) -> bool {
    matches!(symbol, 'F' | 'f' | 'G')
}

/// The step `module` (`F`, `f`, `G`, a length of one unless given) scaled by `factor`.
fn scaled(mut module: DerivedModule, factor: Real) -> DerivedModule {
    let values = &mut module.values;
    if let Some(first) = values.values.first_mut() {
        if values.count == 0 {
            *first = factor;
            values.count = 1;
        } else {
            *first = first.checked_mul(factor).unwrap_or(*first);
        }
    }
    module
}

impl<const DEPTH: usize, const SLOTS: usize> Iterator for ParametricWalker<'_, DEPTH, SLOTS> {
    type Item = Result<DerivedModule, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_queried(None)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::error::WalkError;
    use crate::lsystem::LsysFile;

    /// Over the unit tests' chunks of 7: a budget of b stops a parametric walk after
    /// exactly b modules read, with the count right when it stops; a budget past the walk's
    /// length never stops it.
    #[test]
    fn budgets_hold_across_chunks() {
        let text = "Grow {\n  axiom: A(1)\n  angle: 30\n  A(x) --> F(x)[+A(x*0.5)]-A(x*0.7)\n}\n";
        let mut grammar = ParametricGrammar::new();
        LsysFile::new(text)
            .entry("Grow")
            .unwrap()
            .parametric_into(&mut grammar)
            .unwrap();
        let mut whole = ParametricWalker::<'_, 8>::new(&grammar, 4).unwrap();
        let handed = whole.by_ref().map(Result::unwrap).count() as u64;
        let total = whole.symbols_read();
        assert!(
            total > handed && total > 20,
            "{total} read, {handed} handed out"
        );
        for budget in 0..total + 10 {
            let mut walk = ParametricWalker::<'_, 8>::new(&grammar, 4)
                .unwrap()
                .with_budget(budget);
            let errors: std::vec::Vec<Error> = walk.by_ref().filter_map(Result::err).collect();
            if budget < total {
                let exhausted = Error::Walk(WalkError::BudgetExhausted { budget });
                assert_eq!(errors, [exhausted], "budget {budget}");
                assert_eq!(walk.symbols_read(), budget);
            } else {
                assert!(errors.is_empty(), "budget {budget}");
                assert_eq!(walk.symbols_read(), total);
            }
        }
    }
}
