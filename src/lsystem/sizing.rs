//! Sizing an L-system: the box a walk draws, and the start and scale that fit it to an area.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::alphabet::Command;
use super::grammar::Grammar;
use super::table::Extent;
use super::turtle::{Segment, Start, TurtlePoint};
use crate::error::{Error, WalkError};
use crate::math::Real;
use crate::render::fit::{fit, Orientation};

/// The extent of a drawing in turtle space.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bounds {
    /// Smallest x and y of any segment end.
    pub min: TurtlePoint,
    /// Largest x and y of any segment end.
    pub max: TurtlePoint,
}

/// The box of the segments' ends; `None` if there are none.
pub(crate) fn measure(
    segments: impl Iterator<Item = Result<Segment, Error>>,
) -> Result<Option<Bounds>, Error> {
    let mut bounds: Option<Bounds> = None;
    for segment in segments {
        widen(&mut bounds, segment?);
    }
    Ok(bounds)
}

/// `bounds` widened to the segment's ends.
#[inline(always)]
pub(crate) fn widen(bounds: &mut Option<Bounds>, segment: Segment) {
    for p in [segment.start, segment.end] {
        let b = bounds.get_or_insert(Bounds { min: p, max: p });
        b.min.x = b.min.x.min(p.x);
        b.min.y = b.min.y.min(p.y);
        b.max.x = b.max.x.max(p.x);
        b.max.y = b.max.y.max(p.y);
    }
}

/// The smallest first step a sizing walk takes, as a power of 2: a system whose steps grow
/// by more than about 2²⁰⁰ over its walk overflows (the drawing pass shifts its first step
/// by as much again as the fit's scale, within a step's 2⁻²⁵⁵).
pub(super) const MIN_UNIT_EXPONENT: i32 = -200;

/// A sizing walk whose first step is 2^`exponent` units (at most 2³⁰).
pub(super) fn unit_start(exponent: i32) -> Start {
    Start {
        step: Real::from_int(1 << exponent.clamp(0, 30)),
        step_shift: exponent.min(0).unsigned_abs(),
        ..Start::default()
    }
}

/// Where the turtle starts, and its step in pixels, for a picture whose drawn box is
/// `bounds` in units of which a first step is 2^`unit`, fitted into `area` less `margin`. A picture that
/// draws nothing is valid: it is placed at the area's middle.
pub(crate) fn fitted_start(
    bounds: Option<Bounds>,
    unit: i32,
    orientation: Orientation,
    area: &Rectangle,
    margin: u32,
) -> Result<Start, Error> {
    fitted_placement(bounds, unit, orientation, area, margin).map(|(start, _)| start)
}

/// [`fitted_start`], and the scale: pixels per unit of `bounds`.
pub(super) fn fitted_placement(
    bounds: Option<Bounds>,
    unit: i32,
    orientation: Orientation,
    area: &Rectangle,
    margin: u32,
) -> Result<(Start, Real), Error> {
    let (low, high) = bounds.map_or(((Real::ZERO, Real::ZERO), (Real::ZERO, Real::ZERO)), |b| {
        ((b.min.x, b.min.y), (b.max.x, b.max.y))
    });
    let fitted = fit(low, high, orientation, area, margin)?;
    let (x, y) = orientation.to_picture(fitted.origin);
    // Pixels per picture unit, times the unit's steps: pixels per step (a unit below a
    // step as a shift, which keeps the scale's bits).
    let step = fitted
        .scale
        .checked_mul(Real::from_int(1 << unit.clamp(0, 30)))
        .ok_or(Error::Walk(WalkError::Overflow))?;
    Ok((
        Start {
            position: TurtlePoint { x, y },
            step,
            step_shift: unit.min(0).unsigned_abs(),
            turns: 0,
        },
        fitted.scale,
    ))
}

/// What a sizing walk found: the box of what is drawn, and how many segments, symbols and
/// `@` commands.
pub(super) struct Sizing {
    pub(super) bounds: Option<Bounds>,
    pub(super) segments: u64,
    pub(super) symbols: u64,
    pub(super) scalings: u64,
    /// Measured taking steps of any size (see `sized_bounds`): the drawing pass is not
    /// predicted from it, but walked.
    pub(super) wide: bool,
}

/// The largest margin, in units of the last place, [`predicted_box`] is given: 2⁻⁸ pixel.
pub(super) const MAX_MARGIN: i64 = 1 << 24;

impl Sizing {
    /// How far (in units of the last place, 2⁻³²) each position of the drawing pass from
    /// `start`, at `scale` pixels a unit of this walk, can be from `start + scale × p` for
    /// this walk's position p, where that pass is this walk scaled and cannot fail (see
    /// [`predicted_box`]); `None` where it is not, or the margin would pass [`MAX_MARGIN`].
    ///
    /// Each step of the pass rounds once (half an ulp). Without `@` this walk's steps are
    /// exact (its unit is 2ᵏ steps and directions are Q30), so that is all. Each `@` rounds
    /// both walks' step lengths: with factors of at most 1 in size, the pass's step stays
    /// within half an ulp × (1 + scale) per `@` so far of the scaled step, and so does each
    /// step's vector, plus its own rounding in both walks. Counted over every step and
    /// every `@` of the walk, generously. Lengths (`DrawBy`, `MoveBy`) do not qualify.
    /// If the turtle only moves by drawing, every place it stands on is the origin or a
    /// segment's end, inside the box; moves (`f`, `G`, `M`) are counted by the symbols read
    /// and need a scale of at most ½ (then every place this walk reached, below 2³¹, lands
    /// within 2³⁰ of the start).
    pub(super) fn margin(&self, grammar: &Grammar<'_>, scale: Real, start: Start) -> Option<i64> {
        if self.wide || start.step_shift > 0 {
            return None;
        }
        let mut moves = false;
        for &op in grammar.all_ops() {
            match grammar.command(op) {
                Command::Move | Command::MoveFree => moves = true,
                Command::Scale(factor) if factor.abs() > Real::ONE => return None,
                Command::MoveBy(_) | Command::DrawBy(_) => return None,
                _ => {}
            }
        }
        let steps = if moves {
            let near = |v: Real| v.abs() < Real::from_int(1 << 29);
            let small = scale <= Real::from_ratio(1, 2)?;
            if !(small && near(start.position.x) && near(start.position.y)) {
                return None;
            }
            self.symbols
        } else {
            self.segments
        };
        let steps = i64::try_from(steps).ok()?;
        // Half an ulp a step, half for the product in `predicted_box`, and one to spare.
        let margin = if self.scalings == 0 {
            steps.checked_add(2)?
        } else {
            // (1 + scale) / 2 ≤ 1 + ⌈scale⌉ ulp, for each `@` and each step's own rounding.
            let per_rounding = (scale.to_bits() >> 32).checked_add(2)?;
            let scalings = i64::try_from(self.scalings).ok()?.checked_add(1)?;
            steps
                .checked_mul(scalings)?
                .checked_mul(per_rounding)?
                .checked_add(2)?
        };
        (margin <= MAX_MARGIN).then_some(margin)
    }
}

/// The pixel box a drawing pass from `start` would measure, without walking it, from a
/// sizing walk that drew inside `bounds`, picture units of `scale` pixels, where each of
/// the pass's positions is `start + scale × p` for the walk's p within `margin` units of
/// the last place (see [`Sizing::margin`]). The box is the pass's own when each of its edges rounds
/// to the same pixel anywhere within that margin; `None` when one might round either way
/// (then the pass is walked).
pub(super) fn predicted_box(
    orientation: Orientation,
    bounds: Option<Bounds>,
    scale: Real,
    start: Start,
    margin: i64,
) -> Option<Rectangle> {
    let Some(bounds) = bounds else {
        return Some(pixel_box(orientation, None, start));
    };
    let mapped = |p: TurtlePoint, by: i64| -> Option<TurtlePoint> {
        let at = |origin: Real, p: Real| {
            let bits = origin.checked_add(scale.checked_mul(p)?)?.to_bits();
            Some(Real::from_bits(bits.checked_add(by)?))
        };
        Some(TurtlePoint {
            x: at(start.position.x, p.x)?,
            y: at(start.position.y, p.y)?,
        })
    };
    let settled = |p: TurtlePoint| -> Option<TurtlePoint> {
        let (low, high) = (mapped(p, -margin)?, mapped(p, margin)?);
        let same = pixel_of(orientation, low) == pixel_of(orientation, high);
        same.then_some(low)
    };
    let (min, max) = (settled(bounds.min)?, settled(bounds.max)?);
    Some(pixel_box(orientation, Some(Bounds { min, max }), start))
}

/// A pair as a turtle point.
pub(super) fn point((x, y): (Real, Real)) -> TurtlePoint {
    TurtlePoint { x, y }
}

/// A table's box as turtle-space bounds.
pub(super) fn bounds(extent: Extent) -> Bounds {
    Bounds {
        min: point(extent.min),
        max: point(extent.max),
    }
}

/// The heading index the turtle starts with after `turns` turns (as `Turtle::new` turns).
pub(super) fn start_heading(grammar: &Grammar<'_>, turns: i32) -> u16 {
    let Some(cycle) = grammar.headings().cycle() else {
        return 0;
    };
    let n = u32::from(cycle.count.max(1));
    let k = ((turns.unsigned_abs() % 65_536) * u32::from(cycle.turn)) % n;
    let heading = if turns >= 0 { k } else { (n - k) % n };
    u16::try_from(heading).unwrap_or(0)
}

/// The pixel a point of a drawing pass (whose turtle works in pixels) lands on.
#[inline(always)]
pub(crate) fn pixel_of(orientation: Orientation, p: TurtlePoint) -> Point {
    let (x, y) = orientation.to_screen((p.x, p.y));
    Point::new(x.round_to_i32(), y.round_to_i32())
}

/// The pixel box of a drawing pass's `pixels` (turtle points in pixels); for a picture of
/// nothing, an empty box where the turtle starts.
pub(crate) fn pixel_box(
    orientation: Orientation,
    pixels: Option<Bounds>,
    start: Start,
) -> Rectangle {
    let empty = Rectangle::new(pixel_of(orientation, start.position), Size::zero());
    pixels.map_or(empty, |pixels| {
        let (a, b) = (
            pixel_of(orientation, pixels.min),
            pixel_of(orientation, pixels.max),
        );
        Rectangle::with_corners(
            Point::new(a.x.min(b.x), a.y.min(b.y)),
            Point::new(a.x.max(b.x), a.y.max(b.y)),
        )
    })
}
