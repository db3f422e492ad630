//! Contexts (ABOP 1.8) in a walk that never builds the string.
//!
//! A context is the nearest module on one side at the same level, skipping the symbols of
//! `ignore:` and, as ABOP defines them, whole branches: a left context skips back over
//! `[...]`, and the first module of a branch sees the one before its `[`; a right context
//! skips forward over `[...]` and ends at the `]` that closes its own branch.
//!
//! - Left: the walk reads every level's modules in order, so it keeps, per level, the last
//!   module a left context sees ([`LeftContexts`]), saved at each `[` and restored at its
//!   `]`: `DEPTH` entries and at most [`MAX_CONTEXT_SLOTS`] saved ones, whatever the order.
//! - Right: not read yet, so found by reading ahead from a copy of the walk's frames,
//!   expanding only what lies between (a branch met on the way is skipped at the level it
//!   is met, without expanding it); a module met there that needs its own right context
//!   to be expanded starts a search one level up. Searches nest at most the order deep:
//!   each holds a copy of the frames and left contexts, `DEPTH` × 104 bytes, so a
//!   context-sensitive walk of order `n` may use `n` × `DEPTH` × 104 bytes of stack.
//!   The expansions they compute are remembered ([`Expansions`]) for the walk and the next
//!   searches; their reading counts against the walk's budget, so no system can hang one.
//!
//! A module whose symbol has a production with a context, and whose productions do not
//! apply, is kept for the next level (its neighbours may have changed there) rather than
//! handed out at once.

use heapless::Vec;

use super::expansion::{path_of, Expansion, Frame, Work};
use super::grammar::{Neighbour, ParametricGrammar};
use crate::error::{Error, WalkError};

/// Left contexts a walk saves at once by default (its `SLOTS`).
///
/// One per level below each open branch, over all the branches open at a place of the walk (ABOP figure 1.31 (b)
/// at order 30 needs 144). 48 bytes each; a walk of a system without contexts needs none
/// (`SLOTS = 0` saves 12 KiB on an MCU).
pub const MAX_CONTEXT_SLOTS: usize = 256;

/// How many expansions computed while reading ahead a walk remembers per level.
pub const REMEMBERED: usize = 4;

/// Per level, the module a left context sees at a place of the walk (or of a read-ahead).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Levels<const DEPTH: usize> {
    lasts: [Option<Neighbour>; DEPTH],
}

impl<const DEPTH: usize> Levels<DEPTH> {
    /// The start of a walk.
    pub(crate) const fn new() -> Self {
        Self {
            lasts: [None; DEPTH],
        }
    }

    /// The left context of the next module at `level`.
    pub(crate) fn left(&self, level: usize) -> Option<Neighbour> {
        self.lasts.get(level).copied().flatten()
    }

    /// `module` was read at `level`: unless ignored, it is the next one's left context.
    pub(crate) fn visit(&mut self, grammar: &ParametricGrammar, level: usize, module: &Neighbour) {
        if grammar.is_ignored(module.symbol) {
            return;
        }
        if let Some(last) = self.lasts.get_mut(level) {
            *last = Some(*module);
        }
    }
}

/// The walk's left contexts saved at each open branch, restored at its end.
#[derive(Debug, Clone)]
pub(crate) struct Branches<const SLOTS: usize> {
    saved: Vec<Option<Neighbour>, SLOTS>,
    /// The level of each open branch.
    levels: Vec<u8, SLOTS>,
}

impl<const SLOTS: usize> Branches<SLOTS> {
    pub(crate) const fn new() -> Self {
        Self {
            saved: Vec::new(),
            levels: Vec::new(),
        }
    }

    /// A `[` read at `level` opens a branch at it and every level below (to `order`).
    pub(crate) fn open<const DEPTH: usize>(
        &mut self,
        levels: &Levels<DEPTH>,
        level: usize,
        order: usize,
    ) -> Result<(), Error> {
        let full = Error::Walk(WalkError::ContextsTooDeep { capacity: SLOTS });
        let lasts = levels.lasts.get(level..order).unwrap_or_default();
        if self.saved.len() + lasts.len() > SLOTS {
            return Err(full);
        }
        for &last in lasts {
            self.saved.push(last).map_err(|_| full)?;
        }
        self.levels
            .push(u8::try_from(level).unwrap_or(u8::MAX))
            .map_err(|_| full)
    }

    /// The `]` read at `level` closes the branch: the module after it sees the one before
    /// its `[`.
    pub(crate) fn close<const DEPTH: usize>(
        &mut self,
        levels: &mut Levels<DEPTH>,
        level: usize,
        order: usize,
    ) {
        if self.levels.pop().map(usize::from) != Some(level) {
            return;
        }
        let lasts = levels.lasts.get_mut(level..order).unwrap_or_default();
        for last in lasts.iter_mut().rev() {
            *last = self.saved.pop().flatten();
        }
    }
}

/// Expansions of contextual modules computed while reading ahead, by level and place in
/// the derivation tree (a 64-bit hash of the path from the axiom), for the walk and later
/// read-aheads to take instead of searching again: without them, each level's search
/// repeats the ones below it (figure 1.31 (b) at order 30 read 200 modules for each one
/// derived; remembering 2 a level, 80; [`REMEMBERED`], 8; figure (a), 23: a test checks
/// it stays under 30). The walk
/// takes an entry out when it reads its module: nothing behind the walk is read again.
///
/// Two places share a hash with probability 2⁻⁶⁴ and few entries are compared at a time:
/// a walk of 10⁹ modules confuses two with odds below 10⁻⁸.
#[derive(Debug, Clone)]
pub(crate) struct Expansions<const DEPTH: usize>([[Option<(u64, Expansion)>; REMEMBERED]; DEPTH]);

impl<const DEPTH: usize> Expansions<DEPTH> {
    pub(crate) const fn new() -> Self {
        Self([[None; REMEMBERED]; DEPTH])
    }

    /// The expansion remembered for `path` at `level`; `take` removes it.
    fn get(&mut self, level: usize, path: u64, take: bool) -> Option<Expansion> {
        let entry = self
            .0
            .get_mut(level)?
            .iter_mut()
            .find(|entry| entry.is_some_and(|(known, _)| known == path))?;
        let expansion = entry.map(|(_, expansion)| expansion);
        if take {
            *entry = None;
        }
        expansion
    }

    /// Remembers an expansion in a free entry, or in place of the oldest.
    fn put(&mut self, level: usize, path: u64, expansion: Expansion) {
        let Some(ways) = self.0.get_mut(level) else {
            return;
        };
        let free = ways
            .iter()
            .position(Option::is_none)
            .unwrap_or(REMEMBERED - 1);
        // Newest first: shift the older ones down over the free (or oldest) entry.
        if let Some(entries) = ways.get_mut(..=free) {
            entries.rotate_right(1);
        }
        if let Some(first) = ways.first_mut() {
            *first = Some((path, expansion));
        }
    }
}

/// How the contextual `module`, read at `at` in the deepest of `frames`, expands:
/// remembered, or found from its left context in `levels` and its right context read
/// ahead. The walk `take`s what it finds remembered.
#[allow(clippy::too_many_arguments)]
pub(crate) fn expand_in_context<const DEPTH: usize>(
    grammar: &ParametricGrammar,
    module: &Neighbour,
    (at, take): (u16, bool),
    frames: &[Frame],
    levels: &Levels<DEPTH>,
    expansions: &mut Expansions<DEPTH>,
    work: &mut Work,
) -> Result<Expansion, Error> {
    let level = frames.len().saturating_sub(1);
    let parent = frames.last().copied().unwrap_or(Frame {
        position: 0,
        end: 0,
        key: 0,
        path: 0,
        bound: super::values::Values::default(),
        growing: false,
        drawn: false,
    });
    let id = path_of(parent.path, at);
    if let Some(expansion) = expansions.get(level, id, take) {
        return Ok(expansion);
    }
    let left = levels.left(level);
    let mut ahead = *levels;
    let mut cursor: Vec<Frame, DEPTH> = Vec::new();
    for frame in frames {
        // Cannot fail: `frames` are a walk's, at most DEPTH.
        let _ = cursor.push(*frame);
    }
    let right = read_ahead(grammar, level, &mut cursor, &mut ahead, expansions, work)?;
    // Contexts and environments do not mix (refused when read): no query here.
    let expansion = grammar.expand(module, at, &parent, (left.as_ref(), right.as_ref()), None)?;
    expansions.put(level, id, expansion);
    Ok(expansion)
}

/// Reads on from `cursor` to the next module at `target` a right context sees.
fn read_ahead<const DEPTH: usize>(
    grammar: &ParametricGrammar,
    target: usize,
    cursor: &mut Vec<Frame, DEPTH>,
    ahead: &mut Levels<DEPTH>,
    expansions: &mut Expansions<DEPTH>,
    work: &mut Work,
) -> Result<Option<Neighbour>, Error> {
    loop {
        let level = cursor.len().wrapping_sub(1);
        let Some(top) = cursor.last_mut() else {
            return Ok(None);
        };
        if top.position >= top.end {
            cursor.pop();
            continue;
        }
        work.tick()?;
        let at = top.position;
        let symbol = grammar.module(at).symbol;
        match symbol {
            // A whole branch, at whichever level it is met.
            b'[' => {
                top.position = grammar.branch_end(at, top.end);
                continue;
            }
            // The end of the branch, or a cut: the rest of the branch is gone.
            b']' | b'%' => return Ok(None),
            _ => {}
        }
        top.position += 1;
        let parent = *top;
        let module = grammar.read(at, &parent.bound, None)?;
        if level >= target {
            if grammar.is_ignored(symbol) {
                continue;
            }
            return Ok(Some(module));
        }
        let expansion = if grammar.is_contextual(symbol) {
            expand_in_context(
                grammar,
                &module,
                (at, false),
                cursor,
                ahead,
                expansions,
                work,
            )?
        } else {
            grammar.expand(&module, at, &parent, (None, None), None)?
        };
        ahead.visit(grammar, level, &module);
        match expansion {
            Expansion::Successor(frame) | Expansion::Kept(frame) => {
                // Cannot fail: levels stay below `target`, itself below DEPTH.
                let _ = cursor.push(frame);
            }
            Expansion::Final if grammar.is_ignored(symbol) => {}
            Expansion::Final => return Ok(Some(module)),
        }
    }
}
