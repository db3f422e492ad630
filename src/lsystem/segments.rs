//! [`Segments`]: the walker's symbols turned into line segments by the turtle, on the fly.

use core::ops::ControlFlow;

use super::grammar::Grammar;
use super::table::{Summary, Table};
use super::turtle::{Segment, Start, Turtle, TurtlePoint, DEFAULT_STACK};
use super::walker::{Next, Walker, DEFAULT_DEPTH};
use crate::error::{Error, WalkError};

/// What a guided walk hands out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Drawn {
    /// A segment, as an unguided walk gives it.
    Segment(Segment),
    /// An expansion that lies within one pixel, drawn as that pixel: a point of it, and
    /// the colour index it is drawn in throughout.
    Dot(TurtlePoint, u8),
}

/// What a guided walk does with an expansion, seen from its table cell and where it starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Decision {
    /// Walk into it.
    Expand,
    /// Move past it: nothing of it shows.
    Skip,
    /// Move past it, drawing it as one dot.
    Dot,
}

/// What a walk did, for statistics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WalkStats {
    /// Segments drawn.
    pub segments: u64,
    /// Polygons filled (`{ }`).
    pub polygons: u64,
    /// Symbols read (expanded and interpreted).
    pub symbols: u64,
    /// The deepest the turtle stack got (bracket nesting).
    pub max_stack: usize,
    /// The deepest expansion (levels, the axiom is 1).
    pub max_depth: usize,
}

/// The segments an L-system draws at an order, in drawing order, computed on the fly.
///
/// This is the raw layer under [`LSystem`](crate::LSystem): no colours, no pixels. A main loop
/// can pull a few segments at a time. Worst-case RAM is the walker (`DEPTH` × 8 bytes), the
/// turtle state and its stack (`STACK` × 32 bytes) and two references: under 1 KiB with the
/// defaults, whatever the order.
///
/// After an `Err` the iterator ends.
#[derive(Debug, Clone)]
pub struct Segments<'g, 'a, const DEPTH: usize = DEFAULT_DEPTH, const STACK: usize = DEFAULT_STACK>
{
    walker: Walker<'g, 'a, DEPTH>,
    turtle: Turtle<'g, STACK>,
    segments: u64,
    failed: bool,
}

impl<'g, 'a> Segments<'g, 'a> {
    /// The segments of `grammar` at `order`, in turtle units from the origin along +x,
    /// with the default capacities.
    pub fn new(grammar: &'g Grammar<'a>, order: u32) -> Result<Self, Error> {
        Self::with_capacity(grammar, order, Start::default())
    }

    /// The segments with an explicit start (position, step and heading), default capacities.
    pub fn starting(grammar: &'g Grammar<'a>, order: u32, start: Start) -> Result<Self, Error> {
        Self::with_capacity(grammar, order, start)
    }
}

impl<'g, 'a, const DEPTH: usize, const STACK: usize> Segments<'g, 'a, DEPTH, STACK> {
    /// The segments with an explicit start and the capacities in the type:
    /// `Segments::<'_, '_, 33, 64>::with_capacity(&grammar, 32, Start::default())`.
    pub fn with_capacity(
        grammar: &'g Grammar<'a>,
        order: u32,
        start: Start,
    ) -> Result<Self, Error> {
        Self::walking(grammar, order, start, false)
    }

    /// A walk whose unit is a pixel: any step is taken, a first one or one shrunk by `@`
    /// far below 2⁻²⁰ (each position rounds by at most 2⁻³³ pixel a step, so a picture of
    /// fewer than 2³² segments is off by less than half a pixel; the step itself keeps its
    /// 32 significant bits, see `Step`).
    pub(crate) fn in_pixels(
        grammar: &'g Grammar<'a>,
        order: u32,
        start: Start,
    ) -> Result<Self, Error> {
        Self::walking(grammar, order, start, true)
    }

    fn walking(
        grammar: &'g Grammar<'a>,
        order: u32,
        start: Start,
        in_pixels: bool,
    ) -> Result<Self, Error> {
        Ok(Self {
            walker: Walker::with_capacity(grammar, order)?,
            turtle: Turtle::new(grammar.headings(), grammar.dialect(), start, in_pixels)?,
            segments: 0,
            failed: false,
        })
    }

    /// Ends the walk with [`WalkError::BudgetExhausted`] after `symbols` symbols.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.walker = self.walker.with_budget(symbols);
        self
    }

    /// How many `@` commands the walk has carried out.
    pub(crate) fn scalings(&self) -> u64 {
        self.turtle.scalings()
    }

    /// What the walk has done so far.
    pub fn stats(&self) -> WalkStats {
        WalkStats {
            segments: self.segments,
            polygons: 0,
            symbols: self.walker.symbols_read(),
            max_stack: self.turtle.max_stack(),
            max_depth: self.walker.max_depth(),
        }
    }

    /// Walks to the end, calling `f` for each segment; the first error stops it.
    pub fn try_for_each_segment(
        &mut self,
        f: impl FnMut(Segment) -> Result<(), Error>,
    ) -> Result<WalkStats, Error> {
        self.for_each_segment(f)?;
        Ok(self.stats())
    }
}

impl<'g, const DEPTH: usize, const STACK: usize> Segments<'g, '_, DEPTH, STACK> {
    /// Moves past an expansion the walk declined, summarised by `cell`, from `position`:
    /// the dot to draw for it, if `decision` says so and it draws anything.
    fn pass_declined(
        &mut self,
        cell: &Summary,
        decision: Decision,
        position: TurtlePoint,
    ) -> Result<Option<Drawn>, Error> {
        let color = self.turtle.color();
        self.turtle
            .pass(cell)
            .ok_or(Error::Walk(WalkError::Overflow))?;
        self.segments = self.segments.saturating_add(cell.segments);
        self.walker.account(cell.symbols, cell.depth);
        Ok(match (decision, cell.drawn) {
            (Decision::Dot, Some(drawn)) => Some(Drawn::Dot(
                TurtlePoint {
                    x: position.x.checked_add(drawn.min.0).unwrap_or(position.x),
                    y: position.y.checked_add(drawn.min.1).unwrap_or(position.y),
                },
                color,
            )),
            _ => None,
        })
    }

    /// The next segment or dot, asking `decide(cell, start, colour)` at every expansion the
    /// table covers. The table must be built for this walk's grammar, order and step.
    pub(crate) fn next_guided(
        &mut self,
        table: &Table<'_>,
        mut decide: impl FnMut(&Summary, TurtlePoint) -> Decision,
    ) -> Option<Result<Drawn, Error>> {
        if self.failed {
            return None;
        }
        loop {
            let (heading, reversed) = self.turtle.table_heading();
            let position = self.turtle.position();
            let mut decision = Decision::Expand;
            let next = self.walker.next_with(|op, left| {
                decision = table
                    .with_cell((op, left), (heading, reversed), |cell| {
                        decide(cell, position)
                    })
                    .unwrap_or(Decision::Expand);
                decision == Decision::Expand
            })?;
            let step = next.and_then(|next| match next {
                Next::Op(op) => {
                    let command = self.walker.grammar().command(op);
                    Ok(self.turtle.execute(command)?.map(Drawn::Segment))
                }
                Next::Declined { op, left } => table
                    .with_cell((op, left), (heading, reversed), |cell| {
                        self.pass_declined(cell, decision, position)
                    })
                    .unwrap_or(Err(Error::Walk(WalkError::Overflow))),
            });
            match step {
                Ok(None) => {}
                Ok(Some(drawn)) => {
                    if let Drawn::Segment(_) = drawn {
                        self.segments += 1;
                    }
                    return Some(Ok(drawn));
                }
                Err(error) => {
                    self.failed = true;
                    return Some(Err(error));
                }
            }
        }
    }
}

impl<const DEPTH: usize, const STACK: usize> Segments<'_, '_, DEPTH, STACK> {
    /// Walks on, handing each segment to `f`, until `f` breaks with a value (`Some(Ok)`),
    /// the walk fails (`Some(Err)`, and it ends) or it ends (`None`). The hot loop, written
    /// out rather than through `next_segment`'s closure, which costs more on Cortex-M.
    #[inline(always)]
    fn walk_until<B>(
        &mut self,
        mut f: impl FnMut(Segment) -> ControlFlow<B>,
    ) -> Option<Result<B, Error>> {
        if self.failed {
            return None;
        }
        loop {
            let step = self.walker.next_op()?.and_then(|op| {
                let command = self.walker.grammar().command(op);
                self.turtle.execute(command)
            });
            match step {
                Ok(None) => {}
                Ok(Some(segment)) => {
                    self.segments += 1;
                    if let ControlFlow::Break(value) = f(segment) {
                        return Some(Ok(value));
                    }
                }
                Err(error) => {
                    self.failed = true;
                    return Some(Err(error));
                }
            }
        }
    }

    /// Calls `f` with every segment to the walk's end, in one loop: the walk's state stays
    /// where it is between segments, where each call of `next` set it up and put it away
    /// again. The
    /// first error, the walk's or `f`'s, stops it.
    #[inline(always)]
    pub(crate) fn for_each_segment<E: From<Error>>(
        &mut self,
        mut f: impl FnMut(Segment) -> Result<(), E>,
    ) -> Result<(), E> {
        match self.walk_until(|segment| match f(segment) {
            Ok(()) => ControlFlow::Continue(()),
            Err(error) => ControlFlow::Break(error),
        }) {
            None => Ok(()),
            Some(Ok(error)) => Err(error),
            Some(Err(error)) => Err(E::from(error)),
        }
    }
}

impl<const DEPTH: usize, const STACK: usize> Iterator for Segments<'_, '_, DEPTH, STACK> {
    type Item = Result<Segment, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        self.walk_until(ControlFlow::Break)
    }
}

/// The next segment of a walk: `step` gives each symbol's outcome (a segment or none)
/// until the walk ends; the first error ends it (the parametric walk's loop; the plain
/// walk writes it out for speed).
#[inline(always)]
pub(crate) fn next_segment<S>(
    failed: &mut bool,
    segments: &mut u64,
    mut step: impl FnMut() -> Option<Result<Option<S>, Error>>,
) -> Option<Result<S, Error>> {
    if *failed {
        return None;
    }
    loop {
        match step()? {
            Ok(None) => {}
            Ok(Some(segment)) => {
                *segments += 1;
                return Some(Ok(segment));
            }
            Err(error) => {
                *failed = true;
                return Some(Err(error));
            }
        }
    }
}
