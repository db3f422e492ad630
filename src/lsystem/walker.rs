//! The derivation walker: an iterator over the symbols of the derived string, in order,
//! without ever building that string.
//!
//! The walker keeps one frame per expansion level: which rule line it is reading and where.
//! A symbol with a rule is expanded (a frame is pushed) while order remains; any other symbol
//! is handed out to be interpreted. Memory is `DEPTH` frames of 8 bytes, whatever the order.
//!
//! Stochastic productions are chosen by a hash of the expansion's place in the derivation
//! tree (the parent's key and the symbol's position in its body) and the grammar's seed, not
//! by a generator advanced in walk order: every walk of a derivation (the fit's and the
//! draw's), on every target, makes the same choices.

use heapless::Vec;

use super::alphabet::DerivedSymbol;
use super::choice::{child_key, kept, mix};
use super::grammar::{Grammar, Span};
use crate::error::{Error, WalkError};

/// Frames a walker holds by default: orders 0 to 16.
pub const DEFAULT_DEPTH: usize = 17;

/// Symbols a walk may read by default before it stops with [`WalkError::BudgetExhausted`].
pub const DEFAULT_BUDGET: u64 = 1 << 28;

/// Marks the axiom in `Frame::rule`.
const AXIOM: u8 = u8::MAX;

/// One expansion level: a rule line (or the axiom) and the read position in the grammar's
/// ops, up to the line's end: reading a symbol is one comparison and one load.
#[derive(Debug, Clone, Copy)]
struct Frame {
    position: u16,
    end: u16,
    rule: u8,
    /// This expansion's place in the derivation tree, hashed (16 bits keep a frame at 8
    /// bytes): stochastic choices below it are functions of it, so every walk of one
    /// derivation makes the same ones.
    key: u16,
}

impl Frame {
    fn at(rule: u8, span: Span, key: u16) -> Self {
        Self {
            position: span.start,
            end: span.end,
            rule,
            key,
        }
    }
}

/// Largest chunk of a budget counted in a machine word: 2³¹ symbols on a 32-bit core, all
/// of it on a 64-bit host (a few symbols in unit tests, so that they cross chunks).
const CHUNK: u64 = if cfg!(test) {
    7
} else if usize::BITS >= 64 {
    u64::MAX
} else {
    1 << 31
};

/// Symbols read against a budget, counted down in a machine word, in chunks of at most
/// [`CHUNK`] (one load, test and store a symbol on Cortex-M, where a 64-bit count and
/// comparison took nine).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Spent {
    /// Symbols read before the current chunk.
    read_before: u64,
    /// The current chunk's size, and what is left of it.
    chunk: usize,
    left: usize,
    budget: u64,
}

impl Spent {
    /// Nothing read yet, against `budget`.
    pub(crate) const fn new(budget: u64) -> Self {
        Self {
            read_before: 0,
            chunk: 0,
            left: 0,
            budget,
        }
    }

    /// Symbols read so far.
    pub(crate) const fn read(&self) -> u64 {
        self.read_before + (self.chunk - self.left) as u64
    }

    /// The budget.
    pub(crate) const fn budget(&self) -> u64 {
        self.budget
    }

    /// The same count against another budget.
    pub(crate) const fn with_budget(self, budget: u64) -> Self {
        Self {
            read_before: self.read(),
            ..Self::new(budget)
        }
    }

    /// Counts one symbol read; `false` if the budget is spent (nothing counted).
    #[inline(always)]
    pub(crate) fn one_more(&mut self) -> bool {
        if self.left == 0 && !self.next_chunk() {
            return false;
        }
        self.left -= 1;
        true
    }

    /// Starts the next chunk; `false` if the budget is spent.
    #[cold]
    fn next_chunk(&mut self) -> bool {
        self.read_before += self.chunk as u64;
        let left = self.budget.saturating_sub(self.read_before);
        // On a 64-bit host CHUNK is u64::MAX, and the minimum only matters on 32 bits.
        #[allow(clippy::unnecessary_min_or_max)]
        let chunk = left.min(CHUNK);
        self.chunk = usize::try_from(chunk).unwrap_or(0);
        self.left = self.chunk;
        left > 0
    }
}

/// The error for an `order` that needs more than `depth` levels (the axiom's, and one an
/// expansion).
pub(crate) fn order_too_high(order: u32, depth: usize) -> Error {
    Error::Walk(WalkError::OrderTooHigh {
        order,
        max: u32::try_from(depth.saturating_sub(1)).unwrap_or(u32::MAX),
    })
}

/// Checks that `order` needs at most `depth` levels.
pub(crate) fn check_order(order: u32, depth: usize) -> Result<(), Error> {
    if usize::try_from(order).map_or(true, |order| order >= depth) {
        return Err(order_too_high(order, depth));
    }
    Ok(())
}

/// Iterates over the symbols of an L-system's derivation of a given order.
///
/// `DEPTH` is the number of expansion levels it can hold: the highest order is `DEPTH - 1`.
/// Yields `Err` once (budget exhausted) and then ends.
#[derive(Debug, Clone)]
pub struct Walker<'g, 'a, const DEPTH: usize = DEFAULT_DEPTH> {
    grammar: &'g Grammar<'a>,
    order: u32,
    frames: Vec<Frame, DEPTH>,
    spent: Spent,
    /// Symbols inside expansions the caller declined (measured, not read).
    declined: u64,
    max_depth: usize,
    /// Whether any rule has alternatives: only then are expansions' keys hashed.
    stochastic: bool,
}

/// What the walker hands out: a symbol to interpret, or an expansion the caller declined
/// (to account for it from the expansion table instead).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Next {
    /// An op to interpret.
    Op(u8),
    /// A symbol with a rule, not expanded: `left` expansions were due.
    Declined {
        /// The symbol.
        op: u8,
        /// Expansions left for it.
        left: u32,
    },
}

impl<'g, 'a> Walker<'g, 'a> {
    /// A walk of `grammar` at `order` with the default depth (orders up to 16).
    pub fn new(grammar: &'g Grammar<'a>, order: u32) -> Result<Self, Error> {
        Self::with_capacity(grammar, order)
    }
}

impl<'g, 'a, const DEPTH: usize> Walker<'g, 'a, DEPTH> {
    /// A walk of `grammar` at `order`; fails if the order needs more than `DEPTH` levels.
    pub fn with_capacity(grammar: &'g Grammar<'a>, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        let mut frames = Vec::new();
        frames
            .push(Frame::at(
                AXIOM,
                grammar.axiom_span(),
                kept(mix(grammar.seed())),
            ))
            .map_err(|_| order_too_high(order, DEPTH))?;
        Ok(Self {
            grammar,
            order,
            frames,
            spent: Spent::new(DEFAULT_BUDGET),
            declined: 0,
            max_depth: 1,
            stochastic: grammar.is_stochastic(),
        })
    }

    /// Stops the walk with [`WalkError::BudgetExhausted`] after `symbols` symbols are read
    /// (expanded or interpreted), so no order can hang a device.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.spent = self.spent.with_budget(symbols);
        self
    }

    /// Symbols read so far (with those of declined expansions, as accounted).
    pub const fn symbols_read(&self) -> u64 {
        self.spent.read().saturating_add(self.declined)
    }

    /// Accounts for a declined expansion: the symbols inside it and the frames it reaches.
    pub(crate) fn account(&mut self, symbols: u64, depth: u32) {
        self.declined = self.declined.saturating_add(symbols);
        let reached = self
            .frames
            .len()
            .saturating_add(usize::try_from(depth).unwrap_or(usize::MAX));
        self.max_depth = self.max_depth.max(reached);
    }

    /// The deepest expansion reached so far, in levels (the axiom is level 1).
    pub const fn max_depth(&self) -> usize {
        self.max_depth
    }

    /// The grammar being walked.
    pub const fn grammar(&self) -> &'g Grammar<'a> {
        self.grammar
    }

    /// The next op to interpret (see [`Grammar::command`]).
    #[inline]
    pub(crate) fn next_op(&mut self) -> Option<Result<u8, Error>> {
        self.next_with(|_, _| true).map(|next| {
            next.map(|next| match next {
                Next::Op(op) | Next::Declined { op, .. } => op,
            })
        })
    }

    /// The next op to interpret, asking `expand(symbol, left)` before each expansion.
    /// Always inlined: with `expand` constant (the plain walk) the question disappears.
    #[inline(always)]
    pub(crate) fn next_with(
        &mut self,
        mut expand: impl FnMut(u8, u32) -> bool,
    ) -> Option<Result<Next, Error>> {
        loop {
            let depth = self.frames.len();
            let top = self.frames.last_mut()?;
            if top.position >= top.end {
                // End of this line: go on with the next line for the same symbol, if any.
                match self.grammar.next_line(top.rule) {
                    Some(next) => *top = Frame::at(next, self.grammar.rule_span(next), top.key),
                    None => {
                        self.frames.pop();
                    }
                }
                continue;
            }
            if !self.spent.one_more() {
                self.frames.clear();
                return Some(Err(Error::Walk(WalkError::BudgetExhausted {
                    budget: self.spent.budget,
                })));
            }
            let at = top.position;
            let op = self.grammar.op(at);
            top.position += 1;
            let level = u32::try_from(depth - 1).unwrap_or(u32::MAX);
            // Numeric ops (128 and up) have no rule: `first_rule` says so.
            if level < self.order {
                if let Some(first) = self.grammar.first_rule(op) {
                    let left = self.order - level;
                    if !expand(op, left) {
                        return Some(Ok(Next::Declined { op, left }));
                    }
                    // Deterministic rules need no key: three multiplies an expansion saved.
                    let key = if self.stochastic {
                        child_key(top.key, at)
                    } else {
                        0
                    };
                    let rule = self.grammar.choose(first, key);
                    // Cannot fail: `new` checked that order + 1 <= DEPTH.
                    let frame = Frame::at(rule, self.grammar.rule_span(rule), kept(key));
                    if self.frames.push(frame).is_ok() {
                        self.max_depth = self.max_depth.max(depth + 1);
                        continue;
                    }
                }
            }
            return Some(Ok(Next::Op(op)));
        }
    }
}

impl<const DEPTH: usize> Walker<'_, '_, DEPTH> {
    /// The next symbol of the derived string, with its number if it has one (for printing
    /// derivations; [`Iterator::next`] gives the bare symbols).
    pub fn next_symbol(&mut self) -> Option<Result<DerivedSymbol, Error>> {
        let grammar = self.grammar;
        self.next_op()
            .map(|op| op.map(|op| grammar.derived_symbol(op)))
    }
}

/// The symbols to interpret, in order, as `char`s (lower-cased in the Fractint dialect).
impl<const DEPTH: usize> Iterator for Walker<'_, '_, DEPTH> {
    type Item = Result<char, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_op()
            .map(|op| op.map(|op| char::from(self.grammar.symbol(op))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lsystem::alphabet::Dialect;
    use crate::math::angle::Angle;

    /// Over chunks of 7 (the unit tests' size): a budget of b stops the walk after exactly b
    /// symbols, with the count right at every step; a budget past the walk's length never
    /// stops it.
    #[test]
    fn budgets_hold_across_chunks() {
        let mut grammar = Grammar::new(Dialect::Fractint, "F-F", Angle::Divisions(4)).unwrap();
        grammar.add_rule('F', "F+F-F").unwrap();
        let length = Walker::new(&grammar, 3).unwrap().count() as u64;
        // Order 3 hands out 107 symbols (3, then 4 more for each of 2·3ⁿ F's a level) and
        // reads 133 (3 + 2·5 + 6·5 + 18·5: each F expanded reads its body).
        assert_eq!(length, 107);
        assert_eq!(total_symbols(&grammar), 133);
        for budget in 0..length + 10 {
            let mut walk = Walker::new(&grammar, 3).unwrap().with_budget(budget);
            let mut ok = 0;
            while let Some(next) = walk.next() {
                match next {
                    Ok(_) => {
                        ok += 1;
                        assert_eq!(walk.symbols_read(), ok_symbols(&grammar, ok));
                    }
                    Err(error) => {
                        assert_eq!(error, Error::Walk(WalkError::BudgetExhausted { budget }));
                        assert_eq!(walk.symbols_read(), budget);
                    }
                }
            }
            assert_eq!(walk.symbols_read(), budget.min(total_symbols(&grammar)));
        }
    }

    /// Symbols read (expanded and interpreted) by the time the `n`-th symbol is handed out.
    fn ok_symbols(grammar: &Grammar<'_>, n: u64) -> u64 {
        let mut walk = Walker::new(grammar, 3).unwrap().with_budget(u64::MAX);
        for _ in 0..n {
            walk.next();
        }
        walk.symbols_read()
    }

    fn total_symbols(grammar: &Grammar<'_>) -> u64 {
        let mut walk = Walker::new(grammar, 3).unwrap().with_budget(u64::MAX);
        while walk.next().is_some() {}
        walk.symbols_read()
    }
}
