//! The expansion table: what each symbol's expansion does, so a picture can be measured and
//! drawn without visiting every segment.
//!
//! With `Angle n` and a fixed step, every step along heading h adds the same vector v[h]
//! (the turtle rounds once per step), so a symbol expanded m times from heading h, reversed
//! or not, always moves by the same sum and draws inside the same box, relative to where it
//! starts; fixed-point sums are exact, so these compose exactly. The table holds, for every
//! symbol with a rule, every m from 1 to the order, every heading and both senses of `!`
//! (the plain one only, where nothing reverses): the displacement, the box of the drawn
//! segments, how far any position visited lies from the start (a bound that rules out
//! overflow), the heading and sense after, what it does to the colour index, and the
//! counts `--stats` reports. It is filled bottom-up, each cell from its rule bodies and the
//! cells one level down.
//!
//! Free angles qualify when their turns reach few headings exactly: 90°, 45°, 22.5°, 11.25°
//! and 5.625° (a binary angle that divides the turn by a power of two, at most 64
//! headings). It does not apply (and the engine walks instead) to other free angles, `@`
//! scaling, `\`, `/`, `D` and `M` (steps of other lengths or headings), nor to branches
//! nested deeper than [`MAX_BODY_NESTING`] inside one body.
//!
//! Storage is the caller's: a slice of [`Cell`]s, `symbols with rules × order × n` of them,
//! twice that where `!` reverses ([`cells_needed`]), 96 bytes each on a 64-bit host; too few
//! and the engine walks. Where a quarter turn of headings turns every direction exactly a
//! quarter turn (`Angle 4k`, free angles of 90°/2ʲ), only the first n/4 headings are kept:
//! an expansion from h + n/4 is the one from h turned, and is turned when read.

use heapless::Vec;

use super::alphabet::{Command, Dialect};
use super::grammar::{Grammar, NUMERIC};
use crate::math::angle::HeadingCycle;
use crate::math::trig::BinaryAngle;
use crate::math::Real;

/// Deepest bracket nesting inside one body the table follows.
pub const MAX_BODY_NESTING: usize = 32;

/// Marks a symbol without a rule in the dense index.
const NONE: u8 = u8::MAX;

/// A box in turtle space, corners inclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Extent {
    pub(crate) min: (Real, Real),
    pub(crate) max: (Real, Real),
}

impl Extent {
    fn point(p: (Real, Real)) -> Self {
        Self { min: p, max: p }
    }

    fn include(&mut self, p: (Real, Real)) {
        self.min = (self.min.0.min(p.0), self.min.1.min(p.1));
        self.max = (self.max.0.max(p.0), self.max.1.max(p.1));
    }

    fn union(self, other: Self) -> Self {
        let mut out = self;
        out.include(other.min);
        out.include(other.max);
        out
    }

    /// The box turned a quarter turn counter-clockwise about the origin: (x, y) → (-y, x).
    /// Callers keep coordinates within ±`i64::MAX` (the reach bound), so negating is exact.
    fn quarter_turned(self) -> Self {
        Self {
            min: (neg(self.max.1), self.min.0),
            max: (neg(self.min.1), self.max.0),
        }
    }

    /// The box moved by `by`; `None` on overflow.
    pub(crate) fn offset(self, by: (Real, Real)) -> Option<Self> {
        Some(Self {
            min: (self.min.0.checked_add(by.0)?, self.min.1.checked_add(by.1)?),
            max: (self.max.0.checked_add(by.0)?, self.max.1.checked_add(by.1)?),
        })
    }
}

/// What an expansion does to the colour index: set it (or not), then add.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct ColorChange {
    set: Option<u8>,
    add: u8,
}

impl ColorChange {
    pub(crate) fn apply(self, color: u8) -> u8 {
        self.set.unwrap_or(color).wrapping_add(self.add)
    }

    fn then(self, next: Self) -> Self {
        match next.set {
            Some(_) => next,
            None => Self {
                set: self.set,
                add: self.add.wrapping_add(next.add),
            },
        }
    }
}

/// One entry of the table: a symbol expanded m times from one heading and sense. Opaque;
/// provide storage as `[Cell::default(); N]` or `vec![Cell::default(); N]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Cell {
    pub(crate) summary: Summary,
}

/// What a run of ops does, relative to where it starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Summary {
    /// Where it ends.
    pub(crate) displacement: (Real, Real),
    /// The box of the drawn segments' ends, if any is drawn.
    pub(crate) drawn: Option<Extent>,
    /// How far any position visited (moves count too) lies from the start, at most, along
    /// x or y: a bound that rules out overflow for the sums below it (a box costs eight
    /// 64-bit operations an expansion; this bound two).
    pub(crate) reach: u64,
    /// Heading and sense of `!` after.
    pub(crate) heading: u16,
    pub(crate) reversed: bool,
    pub(crate) color: ColorChange,
    /// No colour command anywhere inside.
    pub(crate) colorless: bool,
    /// Segments drawn, symbols read, deepest walker frames and turtle stack inside.
    pub(crate) segments: u64,
    pub(crate) symbols: u64,
    pub(crate) depth: u32,
    pub(crate) nesting: u32,
}

/// How many cells a table for `grammar` at `order` needs, or `None` if the table does not
/// apply to it (see the module docs).
pub fn cells_needed(grammar: &Grammar<'_>, order: u32) -> Option<usize> {
    let ruled = (0..128u8)
        .filter(|&s| grammar.first_rule(s).is_some())
        .count();
    Layout::of(grammar, order)?.cells(ruled)
}

/// The turtle's direction for heading `h` of `cycle` (Q30): the table for `Angle n`, or
/// the binary angle.
fn direction(grammar: &Grammar<'_>, cycle: HeadingCycle, h: u16) -> (i32, i32) {
    let headings = grammar.headings();
    if headings.divisions() > 0 {
        headings.cos_sin(h)
    } else {
        BinaryAngle(u32::from(h) << cycle.shift).cos_sin()
    }
}

/// Headings whose cells are kept: where a quarter turn of headings turns every direction
/// exactly a quarter turn (`Angle 4k`, free angles of 90°/2ʲ; checked, not assumed), an
/// expansion from h + n/4 is the one from h turned, so only the first quarter is kept and
/// the others are turned when read; otherwise all n.
fn stored_headings(grammar: &Grammar<'_>) -> Option<u16> {
    let cycle = grammar.headings().cycle()?;
    let n = cycle.count;
    let quarter = n / 4;
    let turns_exactly = n % 4 == 0
        && (0..n).all(|h| {
            let (c, s) = direction(grammar, cycle, h);
            direction(grammar, cycle, (h + quarter) % n) == (s.saturating_neg(), c)
        });
    Some(if turns_exactly { quarter } else { n })
}

/// Senses of `!` a walk can be in (2 if the grammar reverses anywhere, else only the plain
/// one, and half the cells); `None` where the table does not apply: a step of another
/// length or heading (`@`, `\`, `/`, `D`, `M`), or stochastic choices, which differ from
/// place to place (no two expansions are alike).
fn senses(grammar: &Grammar<'_>) -> Option<u8> {
    if grammar.is_stochastic() {
        return None;
    }
    let mut senses = 1;
    for &op in grammar.all_ops() {
        match grammar.command(op) {
            Command::Scale(_)
            | Command::FreeLeft(_)
            | Command::FreeRight(_)
            | Command::DrawFree
            | Command::MoveFree => return None,
            Command::Reverse => senses = 2,
            _ => {}
        }
    }
    Some(senses)
}

/// A filled table over borrowed cells, for one step length.
#[derive(Debug, Clone)]
pub(crate) struct Table<'c> {
    cells: &'c [Cell],
    /// Dense index of each symbol with a rule.
    dense: [u8; 128],
    layout: Layout,
    /// The whole picture: the axiom with every expansion left, from the heading built for.
    picture: Summary,
}

/// Summaries of bodies, read from the cells filled so far.
struct Run<'r, 'g, 'a> {
    cells: &'r [Cell],
    context: Context<'r, 'g, 'a>,
}

/// What a table's summaries are made from, besides the cells.
#[derive(Clone, Copy)]
struct Context<'r, 'g, 'a> {
    dense: &'r [u8; 128],
    layout: Layout,
    turn: u16,
    vectors: &'r [(Real, Real)],
    grammar: &'g Grammar<'a>,
}

impl<'r, 'g, 'a> Context<'r, 'g, 'a> {
    /// Summaries read from `cells`.
    const fn over(self, cells: &'r [Cell]) -> Run<'r, 'g, 'a> {
        Run {
            cells,
            context: self,
        }
    }
}

impl<'c> Table<'c> {
    /// Fills `cells` for `grammar` at `order` with steps of `step`, and sums up the
    /// picture drawn from `heading`; `None` if the table does not apply, the cells are too
    /// few, or a sum overflows (the engine then walks).
    pub(crate) fn build(
        grammar: &Grammar<'_>,
        order: u32,
        step: Real,
        heading: u16,
        cells: &'c mut [Cell],
    ) -> Option<Self> {
        let layout = Layout::of(grammar, order)?;
        // The symbols with rules, in the order of their dense indices.
        let mut ruled: Vec<u8, 128> = Vec::new();
        let mut dense = [NONE; 128];
        for symbol in 0..128u8 {
            if grammar.first_rule(symbol).is_some() {
                *dense.get_mut(usize::from(symbol))? = u8::try_from(ruled.len()).ok()?;
                ruled.push(symbol).ok()?;
            }
        }
        let cells = cells.get_mut(..layout.cells(ruled.len())?)?;
        let cycle = grammar.headings().cycle()?;
        let mut vectors: Vec<(Real, Real), { crate::math::MAX_ANGLE_DIVISIONS as usize }> =
            Vec::new();
        for h in 0..layout.divisions {
            let (cos, sin) = direction(grammar, cycle, h);
            vectors.push((step.mul_q30(cos), step.mul_q30(sin))).ok()?;
        }
        let context = Context {
            dense: &dense,
            layout,
            turn: cycle.turn,
            vectors: &vectors,
            grammar,
        };
        // Fill level by level: a cell at level m reads only cells at level m - 1.
        for m in 1..=order {
            for (index, &symbol) in (0u8..).zip(&ruled) {
                for heading in 0..layout.stored {
                    for reversed in [false, true].into_iter().take(usize::from(layout.senses)) {
                        let summary = context
                            .over(cells)
                            .expansion(symbol, m, heading, reversed)?;
                        let at = layout.index(index, m, heading, reversed)?;
                        cells.get_mut(at)?.summary = summary;
                    }
                }
            }
        }
        let mut picture = context
            .over(cells)
            .body(grammar.axiom_ops(), order, heading, false)?;
        // The axiom's own frame.
        picture.depth += 1;
        Some(Table {
            cells,
            dense,
            layout,
            picture,
        })
    }

    /// `f` of the cell of `symbol` expanded `m` times (1..=order) from `heading` and
    /// `reversed`; `None` for a symbol without a rule. The kept cell itself where it is
    /// the one asked for (no copy), else the kept one turned.
    #[inline]
    pub(crate) fn with_cell<R>(
        &self,
        (symbol, m): (u8, u32),
        (heading, reversed): (u16, bool),
        f: impl FnOnce(&Summary) -> R,
    ) -> Option<R> {
        let kept = lookup(
            self.cells,
            &self.dense,
            self.layout,
            symbol,
            m,
            heading,
            reversed,
        )?;
        Some(kept.with(f))
    }

    /// The summary of the whole picture: the axiom with `order` expansions left, from the
    /// heading the table was built for.
    pub(crate) const fn picture(&self) -> &Summary {
        &self.picture
    }
}

#[inline]
fn lookup<'c>(
    cells: &'c [Cell],
    dense: &[u8; 128],
    layout: Layout,
    symbol: u8,
    m: u32,
    heading: u16,
    reversed: bool,
) -> Option<Kept<'c>> {
    let index = *dense.get(usize::from(symbol))?;
    if index == NONE || heading >= layout.divisions {
        return None;
    }
    // Headings past the kept quarter are a kept one turned once, twice or three times.
    let turns = heading / layout.stored;
    let at = layout.index(index, m, heading - turns * layout.stored, reversed)?;
    Some(Kept {
        summary: &cells.get(at)?.summary,
        turns,
        layout,
    })
}

/// A kept cell, and the quarter turns that make it the one asked for.
struct Kept<'c> {
    summary: &'c Summary,
    turns: u16,
    layout: Layout,
}

impl Kept<'_> {
    /// The cell asked for: the kept one, turned (a copy) if it has to be.
    fn with<R>(&self, f: impl FnOnce(&Summary) -> R) -> R {
        if self.turns == 0 {
            return f(self.summary);
        }
        let mut summary = *self.summary;
        for _ in 0..self.turns {
            summary = summary.quarter_turned(self.layout.stored, self.layout.divisions);
        }
        f(&summary)
    }
}

/// How the cells are laid out: by symbol (dense index), level, heading and sense.
#[derive(Debug, Clone, Copy)]
struct Layout {
    order: u32,
    divisions: u16,
    /// Headings kept (see [`stored_headings`]): n, or n/4.
    stored: u16,
    /// 1 where nothing reverses (only the plain sense is kept), else 2.
    senses: u8,
}

impl Layout {
    /// The layout of `grammar`'s table at `order`; `None` where the table does not apply.
    fn of(grammar: &Grammar<'_>, order: u32) -> Option<Self> {
        Some(Self {
            order,
            divisions: grammar.headings().cycle()?.count,
            stored: stored_headings(grammar)?,
            senses: senses(grammar)?,
        })
    }

    /// How many cells it has for `symbols` symbols with rules.
    fn cells(self, symbols: usize) -> Option<usize> {
        symbols
            .checked_mul(usize::try_from(self.order).ok()?)?
            .checked_mul(usize::from(self.stored))?
            .checked_mul(usize::from(self.senses))
    }

    /// Where the cell of the symbol with dense index `dense`, expanded `m` times from
    /// `heading` and `reversed`, is; `None` outside the table.
    fn index(self, dense: u8, m: u32, heading: u16, reversed: bool) -> Option<usize> {
        let level = usize::try_from(m.checked_sub(1)?).ok()?;
        if m > self.order || heading >= self.stored || u8::from(reversed) >= self.senses {
            return None;
        }
        let row = usize::from(dense) * usize::try_from(self.order).ok()? + level;
        let at = row * usize::from(self.stored) + usize::from(heading);
        Some(at * usize::from(self.senses) + usize::from(reversed))
    }
}

/// -value (exact within the reach bound; saturating at the one value outside it).
fn neg(value: Real) -> Real {
    Real::from_bits(value.to_bits().saturating_neg())
}

/// The larger of |x| and |y|.
fn magnitude(p: (Real, Real)) -> u64 {
    p.0.to_bits()
        .unsigned_abs()
        .max(p.1.to_bits().unsigned_abs())
}

/// A saved turtle inside one body.
#[derive(Clone, Copy)]
struct Saved {
    position: (Real, Real),
    heading: u16,
    reversed: bool,
    color: ColorChange,
}

impl Run<'_, '_, '_> {
    fn cell(&self, symbol: u8, m: u32, heading: u16, reversed: bool) -> Option<Kept<'_>> {
        lookup(
            self.cells,
            self.context.dense,
            self.context.layout,
            symbol,
            m,
            heading,
            reversed,
        )
    }

    /// `symbol` expanded `m` ≥ 1 times: its rule lines, each op with `m - 1` left.
    fn expansion(&self, symbol: u8, m: u32, heading: u16, reversed: bool) -> Option<Summary> {
        let grammar = self.context.grammar;
        let first = grammar.first_rule(symbol)?;
        let ops = |index: u8| grammar.rule(index).map(|rule| grammar.ops(rule.body));
        let mut total = self.body(ops(first)?, m - 1, heading, reversed)?;
        // Fractint's repeated lines go on from where the last one ended.
        let mut line = grammar.next_line(first);
        while let Some(index) = line {
            let part = self.body(ops(index)?, m - 1, total.heading, total.reversed)?;
            total.append(&part)?;
            line = grammar.next_line(index);
        }
        // The expansion's own frame.
        total.depth += 1;
        Some(total)
    }

    /// A body's ops, each with `left` expansions left, from `heading` and `reversed`.
    fn body(&self, ops: &[u8], left: u32, heading: u16, reversed: bool) -> Option<Summary> {
        let n = self.context.layout.divisions;
        let mut s = Summary {
            heading,
            reversed,
            colorless: true,
            // Every op is read once here; expansions add theirs.
            symbols: u64::try_from(ops.len()).ok()?,
            ..Summary::default()
        };
        let mut stack: Vec<Saved, MAX_BODY_NESTING> = Vec::new();
        // Whether the position is the end of a segment this body drew (already in the box).
        let mut drawn_to = false;
        for &op in ops {
            if left > 0 && op < NUMERIC {
                if let Some(child) = self.cell(op, left, s.heading, s.reversed) {
                    let nesting = u32::try_from(stack.len()).ok()?;
                    child.with(|child| {
                        s.append(child)?;
                        // The child's branches sit inside the ones open here.
                        s.nesting = s.nesting.max(nesting + child.nesting);
                        Some(())
                    })?;
                    drawn_to = false;
                    continue;
                }
            }
            let command = self.context.grammar.command(op);
            match command {
                Command::Draw | Command::Move => {
                    let (vx, vy) = *self.context.vectors.get(usize::from(s.heading))?;
                    let start = s.displacement;
                    let end = (start.0.checked_add(vx)?, start.1.checked_add(vy)?);
                    let draws = command == Command::Draw;
                    if draws {
                        match &mut s.drawn {
                            Some(drawn) if drawn_to => drawn.include(end),
                            Some(drawn) => {
                                drawn.include(start);
                                drawn.include(end);
                            }
                            None => {
                                let mut drawn = Extent::point(start);
                                drawn.include(end);
                                s.drawn = Some(drawn);
                            }
                        }
                        s.segments += 1;
                    }
                    drawn_to = draws;
                    s.reach = s.reach.max(magnitude(end));
                    s.displacement = end;
                }
                Command::Left | Command::Right => {
                    let left_turn = (command == Command::Left) != s.reversed;
                    // Headings wrap by a comparison (`turn` < n): Cortex-M0 has no divide.
                    let turned = s.heading
                        + if left_turn {
                            self.context.turn
                        } else {
                            n - self.context.turn
                        };
                    s.heading = if turned >= n { turned - n } else { turned };
                }
                Command::Around => {
                    let turned = s.heading + (n - n / 2);
                    s.heading = if turned >= n { turned - n } else { turned };
                }
                Command::Reverse => s.reversed = !s.reversed,
                Command::SetColor(value) => {
                    s.color = s.color.then(ColorChange {
                        set: Some(value),
                        add: 0,
                    });
                    s.colorless = false;
                }
                Command::RaiseColor(by) => {
                    s.color = s.color.then(ColorChange { set: None, add: by });
                    s.colorless = false;
                }
                Command::LowerColor(by) => {
                    s.color = s.color.then(ColorChange {
                        set: None,
                        add: by.wrapping_neg(),
                    });
                    s.colorless = false;
                }
                Command::Push => {
                    stack
                        .push(Saved {
                            position: s.displacement,
                            heading: s.heading,
                            reversed: s.reversed,
                            color: s.color,
                        })
                        .ok()?;
                    s.nesting = s.nesting.max(u32::try_from(stack.len()).ok()?);
                }
                Command::Pop => {
                    drawn_to = false;
                    let saved = stack.pop()?;
                    s.displacement = saved.position;
                    s.heading = saved.heading;
                    s.reversed = saved.reversed;
                    // Fractint's `]` keeps the colour; ABOP's restores it.
                    if self.context.grammar.dialect() == Dialect::Abop {
                        s.color = saved.color;
                    }
                }
                Command::Nothing => {}
                Command::Scale(_)
                | Command::FreeLeft(_)
                | Command::FreeRight(_)
                | Command::DrawFree
                | Command::MoveFree
                | Command::DrawBy(_)
                | Command::MoveBy(_) => return None,
            }
        }
        Some(s)
    }
}

impl Summary {
    /// This run as it is from a heading a quarter turn (`quarter` of `divisions`) further
    /// counter-clockwise, where the step vectors turn exactly with it.
    fn quarter_turned(&self, quarter: u16, divisions: u16) -> Self {
        let (x, y) = self.displacement;
        let heading = self.heading + quarter;
        Self {
            displacement: (neg(y), x),
            drawn: self.drawn.map(Extent::quarter_turned),
            heading: if heading >= divisions {
                heading - divisions
            } else {
                heading
            },
            ..*self
        }
    }

    /// This run followed by `next` (which starts where this one ends, in its heading and
    /// sense), in place: a summary is about 100 bytes, and the table appends one for every
    /// op of every body it fills.
    fn append(&mut self, next: &Summary) -> Option<()> {
        let at = self.displacement;
        // Every position inside `next`, moved by `at`, lies within `reach` of this run's
        // start: none of the sums below overflows.
        let reach = magnitude(at).checked_add(next.reach)?;
        if reach > i64::MAX.unsigned_abs() {
            return None;
        }
        let moved = |p: (Real, Real)| {
            (
                Real::from_bits(p.0.to_bits().wrapping_add(at.0.to_bits())),
                Real::from_bits(p.1.to_bits().wrapping_add(at.1.to_bits())),
            )
        };
        if let Some(b) = next.drawn {
            let b = Extent {
                min: moved(b.min),
                max: moved(b.max),
            };
            self.drawn = Some(match self.drawn {
                Some(a) => a.union(b),
                None => b,
            });
        }
        self.reach = self.reach.max(reach);
        self.displacement = moved(next.displacement);
        self.heading = next.heading;
        self.reversed = next.reversed;
        self.color = self.color.then(next.color);
        self.colorless &= next.colorless;
        self.segments = self.segments.saturating_add(next.segments);
        self.symbols = self.symbols.saturating_add(next.symbols);
        self.depth = self.depth.max(next.depth);
        self.nesting = self.nesting.max(next.nesting);
        Some(())
    }
}
