//! An autopilot for zooms, as XaoS has: each frame it steers towards a point where the set
//! meets the outside (never into a uniform region), narrows the view, and backs out when it
//! is stuck; seeded, so a run repeats on every target.
//!
//! The rule, all in integers: a pixel is on an edge if it is inside (its value at least the
//! view's inside value) and its right or lower neighbour is not, or the other way round.
//! The target is kept while an edge lies within [`KEEP_RADIUS`] pixels of it; otherwise a
//! new one is drawn, uniformly among the edges of the frame's middle half (among all its
//! edges if the middle has none) by the seeded generator. Each frame moves the centre
//! [`STEER`] of the way to the target and narrows the width to [`NARROWING`] of itself. A
//! frame with no edge at all, or a narrower view no fixed-point tier computes (past `Deep`'s
//! spacing, or one the rule gives to perturbation), backs out: the width grows
//! [`BACK_OUT`]-fold (to at most the whole set's 4) and a new target is drawn next time.

use embedded_graphics::geometry::Size;

use super::view::{Tier, View};
use super::zoom::ZoomValue;
use crate::error::Error;
use crate::math::{Coord, Generator};

/// How much narrower each frame is: 15/16 of the last (a zoom of about 1.07 a frame).
pub const NARROWING: (i64, i64) = (15, 16);

/// How far the centre moves towards the target each frame: a quarter of the way.
pub const STEER: (i64, i64) = (1, 4);

/// How far (pixels, each axis) an edge may lie from the target for it to be kept.
pub const KEEP_RADIUS: i64 = 3;

/// How much wider a view becomes when the autopilot backs out.
pub const BACK_OUT: i64 = 8;

/// The widest view it backs out to: 4, in Q60.
const WIDEST: i64 = 4 << 60;

/// The autopilot's state: its generator, its target and what it did.
#[derive(Debug, Clone)]
pub struct Autopilot {
    random: Generator,
    /// The point steered to (Q60), if any.
    target: Option<(i64, i64)>,
    /// Times it backed out.
    backed_out: u32,
}

impl Autopilot {
    /// An autopilot whose choices come from `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            random: Generator::new(seed),
            target: None,
            backed_out: 0,
        }
    }

    /// Times it backed out so far.
    pub const fn backed_out(&self) -> u32 {
        self.backed_out
    }

    /// The point it steers to (Q60 bits, as [`Coord`] holds them), if any.
    pub const fn target(&self) -> Option<(i64, i64)> {
        self.target
    }

    /// The view after `view`, whose picture is `values` (row by row, as a render or a
    /// [`ZoomFrame`](super::ZoomFrame) leaves them): narrower and closer to the target, or wider if stuck. The view keeps its
    /// fractal, size, cap, shading and modes. Errors only if the stored view cannot be
    /// rebuilt (it was made by [`View::new`], so it can).
    pub fn next<V: ZoomValue>(&mut self, view: &View, values: &[V]) -> Result<View, Error> {
        let size = view.size();
        let inside = view.inside_value();
        let edges = |i0: u32, i1: u32, j0: u32, j1: u32| Edges {
            values,
            size,
            inside,
            area: (i0, i1, j0, j1),
        };
        let whole = edges(0, size.width, 0, size.height);
        let kept = self.target.filter(|&target| {
            let (i, j) = pixel_of(view, target);
            let r = KEEP_RADIUS;
            let clip = |v: i64, n: u32| v.clamp(0, i64::from(n)) as u32;
            edges(
                clip(i - r, size.width),
                clip(i + r + 1, size.width),
                clip(j - r, size.height),
                clip(j + r + 1, size.height),
            )
            .count()
                > 0
        });
        let target = kept.or_else(|| {
            let middle = edges(
                size.width / 4,
                size.width - size.width / 4,
                size.height / 4,
                size.height - size.height / 4,
            );
            let pool = if middle.count() > 0 { middle } else { whole };
            let count = pool.count();
            if count == 0 {
                return None;
            }
            let pick = self.random.next_u32() % count;
            pool.nth(pick).map(|(i, j)| {
                let (re, im) = view.point(i64::from(i), i64::from(j));
                (clamp_i64(re), clamp_i64(im))
            })
        });
        self.target = target;
        let (centre, spacing) = (
            (view.centre.0.to_bits(), view.centre.1.to_bits()),
            view.spacing,
        );
        let width = i128::from(spacing) * i128::from(size.width);
        if let Some((tr, ti)) = target {
            let steer = |from: i64, to: i64| {
                from + ((i128::from(to) - i128::from(from)) * i128::from(STEER.0)
                    / i128::from(STEER.1)) as i64
            };
            let centre = (steer(centre.0, tr), steer(centre.1, ti));
            let narrower = width * i128::from(NARROWING.0) / i128::from(NARROWING.1);
            if let Some(next) = rebuilt(view, centre, narrower) {
                return Ok(next);
            }
        }
        // Stuck: no edge to steer to, or no fixed tier for a narrower view.
        self.target = None;
        self.backed_out += 1;
        let wider = (width * i128::from(BACK_OUT)).min(i128::from(WIDEST));
        rebuilt(view, centre, wider)
            .or_else(|| rebuilt(view, centre, i128::from(WIDEST)))
            .or_else(|| rebuilt(view, (-(3 << 58), 0), i128::from(WIDEST)))
            .ok_or(Error::View(crate::error::ViewError::ZoomNeedsFixedTier))
    }
}

/// `view` at `centre` and `width` (Q60), if a fixed tier computes it.
fn rebuilt(view: &View, centre: (i64, i64), width: i128) -> Option<View> {
    let width = Coord::from_bits(i64::try_from(width).ok()?);
    let next = View::new(
        view.fractal,
        (Coord::from_bits(centre.0), Coord::from_bits(centre.1)),
        width,
        view.size,
        view.max_iterations,
    )
    .ok()?
    .with_shading(view.shading)
    .ok()?
    .with_outside(view.outside)
    .ok()?
    .with_inside(view.inside)
    .with_distance(view.distance);
    (next.tier() != Tier::Perturbation && next.resolves_pixels()).then_some(next)
}

fn clamp_i64(value: i128) -> i64 {
    value.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64
}

/// The pixel (column, row) nearest the point `p` (Q60) of `view`, possibly outside it.
fn pixel_of(view: &View, p: (i64, i64)) -> (i64, i64) {
    let size = view.size();
    let spacing = i128::from(view.spacing.max(1));
    let steps = |offset: i128| (offset.div_euclid(spacing)) as i64;
    let i =
        steps(i128::from(p.0) - i128::from(view.centre.0.to_bits())) + i64::from(size.width / 2);
    let j = i64::from(size.height / 2)
        - 1
        - steps(i128::from(p.1) - i128::from(view.centre.1.to_bits()));
    (i, j)
}

/// The edge pixels of a rectangle of a frame (columns `area.0..area.1`, rows
/// `area.2..area.3`).
struct Edges<'a, V> {
    values: &'a [V],
    size: Size,
    inside: u16,
    area: (u32, u32, u32, u32),
}

impl<V> Clone for Edges<'_, V> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<V> Copy for Edges<'_, V> {}

impl<V: ZoomValue> Edges<'_, V> {
    fn is_inside(&self, i: u32, j: u32) -> Option<bool> {
        let index = j as usize * self.size.width as usize + i as usize;
        self.values.get(index).map(|&v| v.value() >= self.inside)
    }

    fn is_edge(&self, i: u32, j: u32) -> bool {
        let Some(here) = self.is_inside(i, j) else {
            return false;
        };
        let right = (i + 1 < self.size.width)
            .then(|| self.is_inside(i + 1, j))
            .flatten();
        let below = (j + 1 < self.size.height)
            .then(|| self.is_inside(i, j + 1))
            .flatten();
        right.is_some_and(|r| r != here) || below.is_some_and(|b| b != here)
    }

    fn pixels(self) -> impl Iterator<Item = (u32, u32)> {
        let (i0, i1, j0, j1) = self.area;
        (j0..j1).flat_map(move |j| (i0..i1).map(move |i| (i, j)))
    }

    fn count(self) -> u32 {
        self.pixels().filter(|&(i, j)| self.is_edge(i, j)).count() as u32
    }

    fn nth(self, n: u32) -> Option<(u32, u32)> {
        self.pixels()
            .filter(|&(i, j)| self.is_edge(i, j))
            .nth(n as usize)
    }
}
