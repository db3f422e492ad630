//! What a system draws, in turtle units: lines with their widths and filled polygons,
//! computed on the fly by the walk and the 3D (or matrix) turtle; the segments alone for
//! those who want only lines.

use super::context::MAX_CONTEXT_SLOTS;
use super::environment::{Environment, Held};
use super::grammar::ParametricGrammar;
use heapless::Vec;

use super::space::{AnyTurtle, Drawn, Segment3};
use super::surface::MAX_POLYGON_VERTICES;
use super::tropism::Tropism;
use super::values::DerivedModule;
use super::walker::ParametricWalker;
use crate::error::Error;
use crate::lsystem::turtle::DEFAULT_STACK;
use crate::lsystem::walker::{check_order, DEFAULT_BUDGET, DEFAULT_DEPTH};
use crate::math::Real;

/// One thing a system draws, in turtle units (x right, y up, z towards the viewer).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark<'m> {
    /// A line, `width` turtle units wide (0: one pixel, whatever the scale).
    Line {
        /// Its ends and colour index.
        segment: Segment3,
        /// Its width.
        width: Real,
    },
    /// A filled polygon: its vertices in order, and its colour index (the turtle's at `}`).
    Polygon {
        /// Its vertices.
        vertices: &'m [[Real; 3]],
        /// Its colour index.
        color: u8,
    },
}

/// Options of a walk that draws: the budget, the environment, a tropism in place of the
/// system's own, the growth between orders.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WalkOptions<'g> {
    pub(crate) budget: u64,
    pub(crate) environment: Option<Held<'g>>,
    /// `Some(t)`: this tropism instead of the system's (`None` inside: none).
    pub(crate) tropism: Option<Option<Tropism>>,
    pub(crate) growth: Option<Real>,
}

impl Default for WalkOptions<'_> {
    fn default() -> Self {
        Self {
            budget: DEFAULT_BUDGET,
            environment: None,
            tropism: None,
            growth: None,
        }
    }
}

/// The marks a 3D system draws at an order, computed on the fly: a lending iterator
/// ([`next_mark`](Self::next_mark)), a polygon's vertices borrowed from the turtle until the
/// next mark.
#[derive(Debug, Clone)]
pub struct Marks3<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    walker: ParametricWalker<'g, DEPTH, SLOTS>,
    turtle: AnyTurtle<STACK>,
    environment: Option<Held<'g>>,
    marks: u64,
    /// An error was handed out, or the walk ended.
    done: bool,
    /// The module the walk handed out last (kept here, not passed up by value).
    module: DerivedModule,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    Marks3<'g, DEPTH, STACK, SLOTS>
{
    /// The marks of `grammar` at `order`, from the origin, one unit a step.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        check_order(order, DEPTH)?;
        Ok(Self::starting(grammar, order, WalkOptions::default()))
    }

    /// Built in one piece, as [`ParametricWalker::starting`] is.
    #[inline(always)]
    pub(crate) fn starting(
        grammar: &'g ParametricGrammar,
        order: u32,
        options: WalkOptions<'g>,
    ) -> Self {
        let mut walker = ParametricWalker::starting(grammar, order, options.budget).drawing();
        if let Some(fraction) = options.growth {
            walker = walker.growing(fraction);
        }
        let tropism = options.tropism.unwrap_or(grammar.tropism());
        Self {
            walker,
            turtle: AnyTurtle::for_grammar(grammar, tropism),
            environment: options.environment,
            marks: 0,
            done: false,
            module: DerivedModule::NONE,
        }
    }

    /// Caps the walk at `symbols` modules.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.walker = self.walker.with_budget(symbols);
        self
    }

    /// Grows an open system in `environment`: `env(k)` asks it about the turtle.
    #[must_use]
    pub fn with_environment(mut self, environment: &'g dyn Environment) -> Self {
        self.environment = Some(Held(environment));
        self
    }

    /// Marks handed out so far.
    pub const fn marks(&self) -> u64 {
        self.marks
    }

    /// The next mark, `None` at the end; an error (a capacity, the budget, a polygon left
    /// open at the end) is handed out once and ends the walk.
    #[allow(clippy::should_implement_trait)]
    pub fn next_mark(&mut self) -> Option<Result<Mark<'_>, Error>> {
        match self.next_drawn()? {
            Ok(Drawn::Line { segment, width }) => Some(Ok(Mark::Line { segment, width })),
            Ok(Drawn::Polygon { color }) => Some(Ok(Mark::Polygon {
                vertices: self.turtle.closed_polygon(),
                color,
            })),
            Err(error) => Some(Err(error)),
        }
    }

    /// The next thing drawn (a polygon's vertices are then the turtle's closed polygon).
    fn next_drawn(&mut self) -> Option<Result<Drawn, Error>> {
        if self.done {
            return None;
        }
        loop {
            let read = match self.environment {
                Some(Held(environment)) => {
                    // Every module expanded before the next one is handed out is where
                    // the turtle stands now.
                    let state = self.turtle.state();
                    let ask = |query: Real| environment.query(query, &state);
                    self.walker.next_into(Some(&ask), &mut self.module)
                }
                None => self.walker.next_into(None, &mut self.module),
            };
            let outcome = match read {
                Some(Ok(())) => self.turtle.execute(&self.module),
                Some(Err(error)) => Err(error),
                None => {
                    self.done = true;
                    return self.turtle.finish().err().map(Err);
                }
            };
            match outcome {
                Ok(None) => {}
                Ok(Some(drawn)) => {
                    self.marks += 1;
                    return Some(Ok(drawn));
                }
                Err(error) => {
                    self.done = true;
                    return Some(Err(error));
                }
            }
        }
    }
}

/// The segments a 3D system draws at an order, in turtle units, computed on the fly: its
/// [`Marks3`]' lines.
#[derive(Debug, Clone)]
pub struct Segments3<
    'g,
    const DEPTH: usize = DEFAULT_DEPTH,
    const STACK: usize = DEFAULT_STACK,
    const SLOTS: usize = MAX_CONTEXT_SLOTS,
> {
    marks: Marks3<'g, DEPTH, STACK, SLOTS>,
    segments: u64,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    Segments3<'g, DEPTH, STACK, SLOTS>
{
    /// The segments of `grammar` at `order`, from the origin, one unit a step.
    pub fn new(grammar: &'g ParametricGrammar, order: u32) -> Result<Self, Error> {
        Ok(Self::from_marks(Marks3::new(grammar, order)?))
    }

    /// The lines of `marks`.
    pub(crate) fn from_marks(marks: Marks3<'g, DEPTH, STACK, SLOTS>) -> Self {
        Self { marks, segments: 0 }
    }

    /// Caps the walk at `symbols` modules.
    #[must_use]
    pub fn with_budget(mut self, symbols: u64) -> Self {
        self.marks = self.marks.with_budget(symbols);
        self
    }

    /// Grows an open system in `environment`: `env(k)` asks it about the turtle.
    #[must_use]
    pub fn with_environment(mut self, environment: &'g dyn Environment) -> Self {
        self.marks = self.marks.with_environment(environment);
        self
    }

    /// Segments drawn so far.
    pub const fn segments(&self) -> u64 {
        self.segments
    }
}

impl<const DEPTH: usize, const STACK: usize, const SLOTS: usize> Iterator
    for Segments3<'_, DEPTH, STACK, SLOTS>
{
    type Item = Result<Segment3, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            match self.marks.next_drawn()? {
                Ok(Drawn::Line { segment, .. }) => {
                    self.segments += 1;
                    return Some(Ok(segment));
                }
                Ok(Drawn::Polygon { .. }) => {}
                Err(error) => return Some(Err(error)),
            }
        }
    }
}

/// The points a fit measures of a walk's marks: each line's ends, and each vertex of a
/// polygon (as a pair of itself).
#[derive(Debug, Clone)]
pub(crate) struct MarkPoints<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize> {
    marks: Marks3<'g, DEPTH, STACK, SLOTS>,
    /// The last polygon's vertices, and how many are handed out.
    pending: Vec<[Real; 3], MAX_POLYGON_VERTICES>,
    next: usize,
}

impl<'g, const DEPTH: usize, const STACK: usize, const SLOTS: usize>
    MarkPoints<'g, DEPTH, STACK, SLOTS>
{
    pub(crate) fn new(marks: Marks3<'g, DEPTH, STACK, SLOTS>) -> Self {
        Self {
            marks,
            pending: Vec::new(),
            next: 0,
        }
    }
}

impl<const DEPTH: usize, const STACK: usize, const SLOTS: usize> Iterator
    for MarkPoints<'_, DEPTH, STACK, SLOTS>
{
    type Item = Result<[[Real; 3]; 2], Error>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(&vertex) = self.pending.get(self.next) {
                self.next += 1;
                return Some(Ok([vertex, vertex]));
            }
            match self.marks.next_mark()? {
                Ok(Mark::Line { segment, .. }) => return Some(Ok([segment.start, segment.end])),
                Ok(Mark::Polygon { vertices, .. }) => {
                    self.pending.clear();
                    // Cannot fail: both hold MAX_POLYGON_VERTICES.
                    let _ = self.pending.extend_from_slice(vertices);
                    self.next = 0;
                }
                Err(error) => return Some(Err(error)),
            }
        }
    }
}
