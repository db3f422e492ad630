//! The expansion table: what each symbol's expansion does, so a picture can be measured and
//! drawn without visiting every segment.
//!
//! With `Angle n` and a fixed step, every step along heading h adds the same vector v[h]
//! (the turtle rounds once per step), so a symbol expanded m times from heading h, reversed
//! or not, always moves by the same sum and draws inside the same box, relative to where it
//! starts; fixed-point sums are exact, so these compose exactly. The table holds, for every
//! symbol with a rule, every m from 1 to the order, every heading and both senses of `!`:
//! the displacement, the box of the drawn segments, the heading and sense after, what it
//! does to the colour index, and the counts `--stats` reports. It is filled bottom-up, each
//! cell from its rule bodies and the cells one level down.
//!
//! Free angles qualify when their turns reach few headings exactly: 90°, 45°, 22.5°, 11.25°
//! and 5.625° (a binary angle that divides the turn by a power of two, at most 64
//! headings). It does not apply (and the engine walks instead) to other free angles, `@`
//! scaling, `\`, `/`, `D` and `M` (steps of other lengths or headings), nor to branches
//! nested deeper than [`MAX_BODY_NESTING`] inside one body.
//!
//! Storage is the caller's: a slice of [`Cell`]s, `symbols with rules × order × n × 2` of
//! them ([`cells_needed`]), about 100 bytes each; too few and the engine walks.

use heapless::Vec;

use super::alphabet::{Command, Dialect};
use super::grammar::{Grammar, NUMERIC};
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
    /// The box of every position visited (for overflow: moves count too).
    pub(crate) visited: Extent,
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
    let n = usize::from(grammar.headings().cycle()?.count);
    // Stochastic choices differ from place to place: no two expansions are alike.
    if !table_applies(grammar) || grammar.is_stochastic() {
        return None;
    }
    let symbols = (0..128u8)
        .filter(|&s| grammar.first_rule(s).is_some())
        .count();
    symbols
        .checked_mul(usize::try_from(order).ok()?)?
        .checked_mul(n)?
        .checked_mul(2)
}

/// Whether every op has a fixed step and an `Angle n` heading.
fn table_applies(grammar: &Grammar<'_>) -> bool {
    grammar.all_ops().iter().all(|&op| {
        !matches!(
            grammar.command(op),
            Command::Scale(_)
                | Command::FreeLeft(_)
                | Command::FreeRight(_)
                | Command::DrawFree
                | Command::MoveFree
        )
    })
}

/// A filled table over borrowed cells, for one step length.
#[derive(Debug, Clone)]
pub(crate) struct Table<'c> {
    cells: &'c [Cell],
    /// Dense index of each symbol with a rule.
    dense: [u8; 128],
    order: u32,
    divisions: u16,
    /// What `+` adds to the heading.
    turn: u16,
    /// v[h]: one step along each heading.
    vectors: Vec<(Real, Real), { crate::math::MAX_ANGLE_DIVISIONS as usize }>,
}

/// Summaries of bodies, read from the cells filled so far.
struct Run<'r, 'g, 'a> {
    cells: &'r [Cell],
    dense: &'r [u8; 128],
    order: u32,
    divisions: u16,
    turn: u16,
    vectors: &'r [(Real, Real)],
    grammar: &'g Grammar<'a>,
}

impl<'c> Table<'c> {
    /// Fills `cells` for `grammar` at `order` with steps of `step`; `None` if the table does
    /// not apply, the cells are too few, or a sum overflows (the engine then walks).
    pub(crate) fn build(
        grammar: &Grammar<'_>,
        order: u32,
        step: Real,
        cells: &'c mut [Cell],
    ) -> Option<Self> {
        let needed = cells_needed(grammar, order)?;
        let cells = cells.get_mut(..needed)?;
        let headings = grammar.headings();
        let cycle = headings.cycle()?;
        let divisions = cycle.count;
        let mut vectors = Vec::new();
        for h in 0..divisions {
            // The turtle's own direction for the heading: the table, or the binary angle.
            let (cos, sin) = if headings.divisions() > 0 {
                headings.cos_sin(h)
            } else {
                BinaryAngle(u32::from(h) << cycle.shift).cos_sin()
            };
            vectors.push((step.mul_q30(cos), step.mul_q30(sin))).ok()?;
        }
        let mut dense = [NONE; 128];
        let mut count = 0u8;
        for symbol in 0..128u8 {
            if grammar.first_rule(symbol).is_some() {
                *dense.get_mut(usize::from(symbol))? = count;
                count += 1;
            }
        }
        // Fill level by level: a cell at level m reads only cells at level m - 1.
        for m in 1..=order {
            for symbol in 0..128u8 {
                let Some(&index) = dense.get(usize::from(symbol)) else {
                    continue;
                };
                if index == NONE {
                    continue;
                }
                for heading in 0..divisions {
                    for reversed in [false, true] {
                        let run = Run {
                            cells: &*cells,
                            dense: &dense,
                            order,
                            divisions,
                            turn: cycle.turn,
                            vectors: &vectors,
                            grammar,
                        };
                        let summary = run.expansion(symbol, m, heading, reversed)?;
                        let at = cell_index(index, m, heading, reversed, order, divisions)?;
                        cells.get_mut(at)?.summary = summary;
                    }
                }
            }
        }
        Some(Table {
            cells,
            dense,
            order,
            divisions,
            turn: cycle.turn,
            vectors,
        })
    }

    /// The cell of `symbol` expanded `m` times (1..=order) from `heading` and `reversed`;
    /// `None` for a symbol without a rule.
    #[inline]
    pub(crate) fn cell(
        &self,
        symbol: u8,
        m: u32,
        heading: u16,
        reversed: bool,
    ) -> Option<&Summary> {
        lookup(
            self.cells,
            &self.dense,
            self.order,
            self.divisions,
            symbol,
            m,
            heading,
            reversed,
        )
    }

    /// The summary of the whole picture: the axiom with `order` expansions left, from
    /// `heading`.
    pub(crate) fn picture(&self, grammar: &Grammar<'_>, heading: u16) -> Option<Summary> {
        let run = Run {
            cells: self.cells,
            dense: &self.dense,
            order: self.order,
            divisions: self.divisions,
            turn: self.turn,
            vectors: &self.vectors,
            grammar,
        };
        let mut summary = run.body(grammar.axiom_ops(), self.order, heading, false)?;
        // The axiom's own frame.
        summary.depth += 1;
        Some(summary)
    }
}

#[allow(clippy::too_many_arguments)]
#[inline]
fn lookup<'c>(
    cells: &'c [Cell],
    dense: &[u8; 128],
    order: u32,
    divisions: u16,
    symbol: u8,
    m: u32,
    heading: u16,
    reversed: bool,
) -> Option<&'c Summary> {
    let index = *dense.get(usize::from(symbol))?;
    if index == NONE {
        return None;
    }
    let at = cell_index(index, m, heading, reversed, order, divisions)?;
    cells.get(at).map(|cell| &cell.summary)
}

fn cell_index(
    dense: u8,
    m: u32,
    heading: u16,
    reversed: bool,
    order: u32,
    divisions: u16,
) -> Option<usize> {
    let level = usize::try_from(m.checked_sub(1)?).ok()?;
    if m > order || heading >= divisions {
        return None;
    }
    let row = usize::from(dense) * usize::try_from(order).ok()? + level;
    Some((row * usize::from(divisions) + usize::from(heading)) * 2 + usize::from(reversed))
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
    fn cell(&self, symbol: u8, m: u32, heading: u16, reversed: bool) -> Option<&Summary> {
        lookup(
            self.cells,
            self.dense,
            self.order,
            self.divisions,
            symbol,
            m,
            heading,
            reversed,
        )
    }

    /// `symbol` expanded `m` ≥ 1 times: its rule lines, each op with `m - 1` left.
    fn expansion(&self, symbol: u8, m: u32, heading: u16, reversed: bool) -> Option<Summary> {
        let mut total = Summary {
            heading,
            reversed,
            colorless: true,
            ..Summary::default()
        };
        let mut line = self.grammar.first_rule(symbol);
        while let Some(index) = line {
            let rule = self.grammar.rule(index)?;
            let part = self.body(
                self.grammar.ops(rule.body),
                m - 1,
                total.heading,
                total.reversed,
            )?;
            total = then(total, part)?;
            line = self.grammar.next_line(index);
        }
        // The expansion's own frame.
        total.depth += 1;
        Some(total)
    }

    /// A body's ops, each with `left` expansions left, from `heading` and `reversed`.
    fn body(&self, ops: &[u8], left: u32, heading: u16, reversed: bool) -> Option<Summary> {
        let n = self.divisions;
        let mut s = Summary {
            heading,
            reversed,
            colorless: true,
            ..Summary::default()
        };
        let mut stack: Vec<Saved, MAX_BODY_NESTING> = Vec::new();
        for &op in ops {
            s.symbols += 1;
            if left > 0 && op < NUMERIC {
                if let Some(child) = self.cell(op, left, s.heading, s.reversed) {
                    let nesting = u32::try_from(stack.len()).ok()?;
                    s = then(s, *child)?;
                    // The child's branches sit inside the ones open here.
                    s.nesting = s.nesting.max(nesting + child.nesting);
                    continue;
                }
            }
            match self.grammar.command(op) {
                Command::Draw | Command::Move => {
                    let (vx, vy) = *self.vectors.get(usize::from(s.heading))?;
                    let start = s.displacement;
                    let end = (start.0.checked_add(vx)?, start.1.checked_add(vy)?);
                    if matches!(self.grammar.command(op), Command::Draw) {
                        let drawn = s.drawn.get_or_insert(Extent::point(start));
                        drawn.include(start);
                        drawn.include(end);
                        s.segments += 1;
                    }
                    s.visited.include(end);
                    s.displacement = end;
                }
                Command::Left | Command::Right => {
                    let left_turn = matches!(self.grammar.command(op), Command::Left) != s.reversed;
                    s.heading = if left_turn {
                        (s.heading + self.turn) % n
                    } else {
                        (s.heading + n - self.turn) % n
                    };
                }
                Command::Around => s.heading = (s.heading + n - n / 2) % n,
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
                    let saved = stack.pop()?;
                    s.displacement = saved.position;
                    s.heading = saved.heading;
                    s.reversed = saved.reversed;
                    // Fractint's `]` keeps the colour; ABOP's restores it.
                    if self.grammar.dialect() == Dialect::Abop {
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

/// `first` followed by `next` (which starts where `first` ends, in its heading and sense).
fn then(first: Summary, next: Summary) -> Option<Summary> {
    let at = first.displacement;
    let drawn = match (first.drawn, next.drawn) {
        (a, None) => a,
        (None, Some(b)) => Some(b.offset(at)?),
        (Some(a), Some(b)) => Some(a.union(b.offset(at)?)),
    };
    Some(Summary {
        displacement: (
            at.0.checked_add(next.displacement.0)?,
            at.1.checked_add(next.displacement.1)?,
        ),
        drawn,
        visited: first.visited.union(next.visited.offset(at)?),
        heading: next.heading,
        reversed: next.reversed,
        color: first.color.then(next.color),
        colorless: first.colorless && next.colorless,
        segments: first.segments.saturating_add(next.segments),
        symbols: first.symbols.saturating_add(next.symbols),
        depth: first.depth.max(next.depth),
        nesting: first.nesting.max(next.nesting),
    })
}
