//! Placing an attractor's points seen from the front in the orbit's own fixed point: a
//! 32×32→64 multiply-accumulate and a shift an axis, instead of converting each point to
//! `Real` and projecting it.

use crate::math::wide::RightShift;
use crate::math::Real;
use crate::render::space::SpaceFit;

/// One axis's rule: the column (or row) of a coordinate `v` is ⌊(start + (v − edge)·step)
/// / 2^(32 + shift)⌋ for a distance v − edge (for rows: edge − v) from 0 to `span`, and
/// beyond the area otherwise. `edge` is a value at or beyond the area's edge, `start`
/// where it falls (plus half a pixel, so the floor rounds to nearest) and `step` the
/// pixels a unit of the fixed point, both scaled by 2^(32 + shift).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Rule {
    /// The value at the area's low edge (for rows: its high edge, rows counting down), or
    /// as far out as 32 bits reach, in state bits.
    edge: i32,
    /// The distance from the edge in state bits past which a coordinate is beyond the area
    /// (its column past the area's far edge).
    span: u32,
    /// Pixels a state unit, times 2^(32 + shift).
    step: u32,
    /// Where the edge falls, in pixels from the area's edge plus ½, times 2^(32 + shift).
    start: u64,
    /// The shift beyond 32 bits: the sum's high word is shifted by this.
    shift: u32,
}

impl Rule {
    /// The rule of a box from `low` to `high` (state bits with `bits` fraction bits) placed
    /// at `screen(v) = origin ± v·scale` (− for rows when `down`), in an area starting at
    /// `area_start` and `size` pixels long; `None` where the fixed point cannot place it
    /// exactly enough (a box narrower than a pixel a state unit, or beyond 2¹⁵ pixels).
    fn new(
        down: bool,
        (low, high): (i32, i32),
        bits: u32,
        (scale, origin): (Real, Real),
        (area_start, size): (i32, u32),
    ) -> Option<Self> {
        let edge = if down { high } else { low };
        // Where the edge lands, relative to the area's start, plus ½ (Q32).
        let edge_real = i128::from(edge) << (Real::FRAC_BITS - bits);
        let scaled = (edge_real * i128::from(scale.to_bits())) >> Real::FRAC_BITS;
        let screen = if down {
            i128::from(origin.to_bits()) - scaled
        } else {
            i128::from(origin.to_bits()) + scaled
        };
        let start_q32 = screen - (i128::from(area_start) << 32) + (1 << 31);
        if start_q32 < 0 || size >= 1 << 15 {
            return None;
        }
        // The largest shift that keeps start + span·step (at most size + 2 pixels) in 64
        // bits and step in 32.
        let room = 64 - (size + 3).ilog2() - 1;
        let mut shift = room;
        let step = loop {
            // step = scale · 2^(shift − bits), from scale in Q32.
            let step = (i128::from(scale.to_bits()) << shift) >> (Real::FRAC_BITS + bits);
            if step < 1 << 32 || shift <= 32 {
                break step;
            }
            shift -= 1;
        };
        if shift < 32 || step >= 1 << 32 || step <= 0 {
            return None;
        }
        let start = start_q32 << (shift - 32);
        // Move the edge out to the area's own edge (as far as 32 bits reach), so that a
        // point beyond the fitted box but inside the area is placed too: `start` drops by
        // a whole number of steps, and every point keeps its column.
        let room_out = if down {
            i128::from(i32::MAX) - i128::from(high)
        } else {
            i128::from(low) - i128::from(i32::MIN)
        };
        let out = (start / step).min(room_out);
        let start = start - out * step;
        let edge = if down {
            i32::try_from(i128::from(high) + out).ok()?
        } else {
            i32::try_from(i128::from(low) - out).ok()?
        };
        // The distances that fall before the area's far edge: start + distance·step below
        // size·2^shift, which keeps it in 64 bits.
        let limit = (i128::from(size) << shift) - 1 - start;
        if limit < 0 {
            return None;
        }
        let span = u32::try_from(limit / step).unwrap_or(u32::MAX);
        Some(Self {
            edge,
            span,
            step: u32::try_from(step).ok()?,
            start: u64::try_from(start).ok()?,
            shift: shift - 32,
        })
    }
}

/// One axis placed as its [`Rule`] places it, in fewer values and steps: the sum
/// start + distance·step is one unsigned multiply-accumulate on the coordinate with its
/// sign bit flipped (for rows: on its complement's), from a base that takes the edge and
/// the flip in, wrapping in 64 bits; and a coordinate is inside where the sum's column is
/// below the area's size.
///
/// That is exact where no coordinate's sum wraps onto the area's: every sum from −(2⁶⁴ −
/// size·2^(32 + shift)) to below 2⁶⁴, which [`Axis::of`] checks. A sum below
/// size·2^(32 + shift) is then a distance from 0 to the span.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Axis<const DOWN: bool> {
    /// start − (edge + 2³¹)·step for columns, start + (edge + 1 − 2³¹)·step for rows,
    /// modulo 2⁶⁴.
    base: u64,
    /// Pixels a state unit, times 2^(32 + shift).
    step: u32,
    /// The shift beyond 32 bits.
    shift: RightShift,
    /// The area's length along the axis, in pixels.
    size: u32,
    /// The base and step of [`Axis::quick`].
    #[cfg(any(test, tinyfractal_no_long_multiply))]
    quick: Quick,
}

/// An axis's sum from the high halves alone ([`Axis::quick`]), taking the coordinate
/// as it is: the base's high word plus the coordinate's high half times the step's.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Quick {
    /// The base's high word plus 2¹⁵·(step >> 16) for columns, (2¹⁵ − 1)·(step >> 16)
    /// for rows, modulo 2³²: the flip of the coordinate's sign bit (for rows, of its
    /// complement's) folded in.
    base: u32,
    /// step >> 16 for columns, its negation for rows, modulo 2³².
    step: u32,
}

/// `DOWN` for rows: the distance is taken from the high edge down.
impl<const DOWN: bool> Axis<DOWN> {
    /// The axis of `rule` over `size` pixels, or `None` where a coordinate's sum would
    /// wrap onto the area's or the rule does not shift the sum's high word (a scale of
    /// more pixels a state unit than a picture has).
    fn of(rule: Rule, size: u32) -> Option<Self> {
        let (edge, step) = (i128::from(rule.edge), i128::from(rule.step));
        let base = if DOWN {
            i128::from(rule.start) + (edge + 1 - (1 << 31)) * step
        } else {
            i128::from(rule.start) - (edge + (1 << 31)) * step
        };
        // The sums run from the base (flipped coordinate 0) up by 2³² − 1 steps.
        let (lowest, highest) = (base, base + (i128::from(u32::MAX) * step));
        let area = i128::from(size) << (32 + rule.shift);
        if lowest <= area - (1 << 64) || highest >= 1 << 64 {
            return None;
        }
        Some(Self::from_parts(
            base as u64,
            rule.step,
            RightShift::new(rule.shift)?,
            size,
        ))
    }

    /// The axis of these parts, with its quick sum's where that is used.
    fn from_parts(base: u64, step: u32, shift: RightShift, size: u32) -> Self {
        Self {
            base,
            step,
            shift,
            size,
            #[cfg(any(test, tinyfractal_no_long_multiply))]
            quick: {
                // (v >> 16) + 2¹⁵ is the high half of v with its sign bit flipped, and
                // !(v >> 16) + 2¹⁵ = 2¹⁵ − 1 − (v >> 16) that of its complement's.
                let high = step >> 16;
                let (flip, factor) = if DOWN {
                    ((1 << 15) - 1, high.wrapping_neg())
                } else {
                    (1 << 15, high)
                };
                Quick {
                    base: ((base >> 32) as u32).wrapping_add(flip * high),
                    step: factor,
                }
            },
        }
    }

    /// The column (row) of `v`, or `None` where it is beyond the area.
    #[inline(always)]
    fn place(&self, v: i32) -> Option<u32> {
        let column = self.unchecked(v);
        (column < self.size).then_some(column)
    }

    /// The column (row) of `v` where it is inside the area; where it is not, some value
    /// at or beyond the area's size, below 2^(32 − shift).
    #[inline(always)]
    fn unchecked(&self, v: i32) -> u32 {
        // Without a long multiply the exact sum is four 16-bit products: most points are
        // placed by one.
        #[cfg(tinyfractal_no_long_multiply)]
        {
            self.quick(v)
                .unwrap_or_else(|| self.exact_out_of_line(Self::flipped(v)))
        }
        #[cfg(not(tinyfractal_no_long_multiply))]
        self.exact(Self::flipped(v))
    }

    /// The coordinate as the sum takes it: columns v + 2³¹, unsigned; rows −v − 1 + 2³¹,
    /// the complement's.
    #[inline(always)]
    fn flipped(v: i32) -> u32 {
        (if DOWN { !v } else { v }) as u32 ^ (1 << 31)
    }

    /// [`exact`](Self::exact) in a call of its own, so that the quick path keeps nothing
    /// for it.
    #[cfg(tinyfractal_no_long_multiply)]
    #[cold]
    #[inline(never)]
    fn exact_out_of_line(&self, flipped: u32) -> u32 {
        self.exact(flipped)
    }

    /// [`unchecked`](Self::unchecked)'s column of the flipped coordinate: the high word of
    /// the base plus the flipped coordinate times the step, shifted.
    #[inline(always)]
    fn exact(&self, flipped: u32) -> u32 {
        let sum = self
            .base
            .wrapping_add(crate::math::wide::mul_u32_wide(flipped, self.step));
        self.shift.apply((sum >> 32) as u32)
    }

    /// [`unchecked`](Self::unchecked)'s column of `v` from the product of the two
    /// factors' high halves alone, where that settles it; `None` where it does not.
    ///
    /// With f the flipped coordinate and a = base_hi + (f >> 16)·(step >> 16) (which
    /// [`Quick`] takes from `v` itself), the exact high word is a + δ (modulo 2³²) for
    /// the other three 16-bit products and the low words' carry, 0 ≤ δ <
    /// [`QUICK_REACH`]; where a and a + `QUICK_REACH` fall in one column (and so do not
    /// wrap past 2³²), that is the column. Used where there is no long multiply (with
    /// one, the exact sum is an instruction), tested everywhere.
    #[cfg(any(test, tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn quick(&self, v: i32) -> Option<u32> {
        let high = (v >> 16) as u32;
        let top = self
            .quick
            .base
            .wrapping_add(high.wrapping_mul(self.quick.step));
        let column = self.shift.apply(top);
        (self.shift.apply(top.wrapping_add(QUICK_REACH)) == column).then_some(column)
    }
}

/// More than the part of a sum's high word that [`Axis::quick`] leaves out: the three
/// 16-bit products below the high halves' and the low words' carry add less than
/// 2·(2¹⁶ − 1)²/2¹⁶ + 2 < 2¹⁷ to it.
#[cfg(any(test, tinyfractal_no_long_multiply))]
const QUICK_REACH: u32 = 1 << 17;

/// A front view's placement of points in the orbit's fixed point: each picture coordinate
/// to a column and row of the area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Placer {
    columns: Axis<false>,
    rows: Axis<true>,
}

impl Placer {
    /// The placement of the box `low`..`high` (picture x and y in state bits of `bits`
    /// fraction bits) by `space`, a front view, in an area from `top_left` of `size`;
    /// `None` where the view is not a front one or the fixed point cannot place it.
    pub(super) fn new(
        space: &SpaceFit,
        (low, high): ([i32; 2], [i32; 2]),
        bits: u32,
        (top_left, size): ((i32, i32), (u32, u32)),
    ) -> Option<Self> {
        let (scale, origin) = space.front_linear()?;
        let columns = Rule::new(
            false,
            (low[0], high[0]),
            bits,
            (scale, origin.0),
            (top_left.0, size.0),
        )?;
        let rows = Rule::new(
            true,
            (low[1], high[1]),
            bits,
            (scale, origin.1),
            (top_left.1, size.1),
        )?;
        // A row beyond the area, times the width, stays within 32 bits (see `cell`).
        if size.0 > 1 << rows.shift {
            return None;
        }
        Some(Self {
            columns: Axis::of(columns, size.0)?,
            rows: Axis::of(rows, size.1)?,
        })
    }

    /// The column and row of the point (`u`, `v`) of the picture, or `None` where it is
    /// beyond the area.
    #[inline(always)]
    pub(super) fn place(&self, u: i32, v: i32) -> Option<(u32, u32)> {
        Some((self.columns.place(u)?, self.rows.place(v)?))
    }

    /// The cell of the point (`u`, `v`) in the area's cells, a row after another (row ×
    /// width + column): `None` where its column is beyond the area, and a cell at or past
    /// the last (width × height) where its row is, which the caller's count of cells
    /// refuses. So the row takes no comparison of its own: below 2^(32 − shift), times a
    /// width of at most 2^shift ([`Placer::new`] checks it), plus a column, it does not
    /// wrap.
    #[inline(always)]
    pub(super) fn cell(&self, u: i32, v: i32) -> Option<u32> {
        let column = self.columns.place(u)?;
        Some(self.rows.unchecked(v) * self.columns.size + column)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// The column of a distance by the rule's formula, with no span to stop it.
    fn column(rule: &Rule, distance: u64) -> u128 {
        (u128::from(rule.start) + u128::from(distance) * u128::from(rule.step)) >> (32 + rule.shift)
    }

    /// The place of `v` by the rule: its column where its distance from the edge is from 0
    /// to the span.
    fn by_rule(rule: &Rule, down: bool, v: i32) -> Option<u32> {
        let distance = if down {
            i64::from(rule.edge) - i64::from(v)
        } else {
            i64::from(v) - i64::from(rule.edge)
        };
        let distance = u64::try_from(distance).ok()?;
        (distance <= u64::from(rule.span)).then(|| column(rule, distance) as u32)
    }

    /// Whether the axis of `rule` places each of `coordinates` as the rule does; `None`
    /// where the rule has no axis.
    fn places_as_rule<const DOWN: bool>(
        rule: Rule,
        size: u32,
        coordinates: impl Iterator<Item = i32>,
    ) -> Option<Result<(), TestCaseError>> {
        let axis = Axis::<DOWN>::of(rule, size)?;
        Some((|| {
            for v in coordinates {
                prop_assert_eq!(axis.place(v), by_rule(&rule, DOWN, v), "{}", v);
            }
            Ok(())
        })())
    }

    /// A rule's span is the last distance whose column is inside the area, and an axis
    /// places every coordinate (the span's ends, the edge's, 32 bits' and others) as its
    /// rule does, columns and rows.
    #[test]
    fn axes_place_as_their_rules_up_to_the_areas_far_edge() {
        let (placed, axes) = (core::cell::Cell::new(0), core::cell::Cell::new(0));
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(
                    (-(1i32 << 29)..0, 1i32..(1 << 29)),
                    (1i64 << 28..1i64 << 45, 0i64..(1 << 36)),
                    (-300i32..300, 1u32..2000),
                    (any::<bool>(), any::<[i32; 4]>()),
                ),
                |((low, high), (scale, offset), (area_start, size), (down, others))| {
                    // The box's edge lands `offset` (Q32 pixels) into the area.
                    let edge = if down { -high } else { low };
                    let edge_pixels = ((i128::from(edge) << 4) * i128::from(scale)) >> 32;
                    let origin = (i128::from(area_start) << 32) + i128::from(offset) - edge_pixels;
                    let origin = i64::try_from(origin).expect("within Q32.32");
                    let scale = (Real::from_bits(scale), Real::from_bits(origin));
                    let Some(rule) = Rule::new(down, (low, high), 28, scale, (area_start, size))
                    else {
                        return Ok(());
                    };
                    placed.set(placed.get() + 1);
                    prop_assert!(column(&rule, rule.span.into()) < u128::from(size));
                    if rule.span < u32::MAX {
                        prop_assert!(column(&rule, u64::from(rule.span) + 1) >= u128::from(size));
                    }
                    let sign = if down { -1 } else { 1 };
                    let far = rule.edge.wrapping_add(sign * rule.span as i32);
                    let ends = [
                        far,
                        far.wrapping_add(sign),
                        rule.edge,
                        rule.edge.wrapping_sub(sign),
                        i32::MIN,
                        i32::MAX,
                        0,
                    ];
                    let coordinates = ends.into_iter().chain(others);
                    // An axis refused is drawn by the projection instead.
                    let placed_by_axis = if down {
                        places_as_rule::<true>(rule, size, coordinates)
                    } else {
                        places_as_rule::<false>(rule, size, coordinates)
                    };
                    if let Some(result) = placed_by_axis {
                        result?;
                        axes.set(axes.get() + 1);
                    }
                    Ok(())
                },
            )
            .unwrap();
        // Most boxes are placeable: the test is not of refusals alone.
        assert!(placed.get() > 128, "{} placed", placed.get());
        assert!(axes.get() > 128, "{} axes", axes.get());
    }

    /// Checks [`Axis::quick`] against [`Axis::exact`] for the flipped coordinates
    /// `flipped` of an axis of these parts; returns how many it places.
    fn quick_as_exact<const DOWN: bool>(
        (base, step, shift): (u64, u32, u32),
        flipped: impl Iterator<Item = u32>,
    ) -> Result<u32, TestCaseError> {
        let axis = Axis::<DOWN>::from_parts(base, step, RightShift::new(shift).unwrap(), 128);
        let mut decided = 0;
        for f in flipped {
            // The coordinate whose flip is f.
            let v = (f ^ (1 << 31)) as i32;
            let v = if DOWN { !v } else { v };
            prop_assert_eq!(Axis::<DOWN>::flipped(v), f);
            if let Some(column) = axis.quick(v) {
                decided += 1;
                prop_assert_eq!(column, axis.exact(f), "{:#x}", f);
            }
        }
        Ok(decided)
    }

    /// The quick column, where it gives one, is the exact one, for columns and rows: for
    /// random axes and coordinates, and for coordinates whose exact sums fall a few units
    /// either side of a column's edge; and it gives one for most random coordinates where
    /// the shift is 20 or more.
    #[test]
    fn quick_columns_are_exact_columns() {
        let (decided, tried) = (core::cell::Cell::new(0u32), core::cell::Cell::new(0u32));
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(
                    (any::<u64>(), 1u32.., 1u32..32),
                    (any::<[u32; 8]>(), 0u32..64),
                ),
                |((base, step, shift), (others, nudge))| {
                    let sum = |f: u32| base.wrapping_add(u64::from(f) * u64::from(step));
                    // Coordinates whose exact sum is the next column's first, give or take
                    // 32 units: the sum grows by the step a unit.
                    let near_edges = others.map(|f| {
                        let high = (sum(f) >> 32) as u32;
                        let edge = (high >> shift).wrapping_add(1).wrapping_shl(shift);
                        let units = (u64::from(edge) << 32).wrapping_sub(sum(f)) / u64::from(step);
                        ((u64::from(f) + units) as u32)
                            .wrapping_add(nudge)
                            .wrapping_sub(32)
                    });
                    let parts = (base, step, shift);
                    let placed = quick_as_exact::<false>(parts, others.into_iter())?
                        + quick_as_exact::<true>(parts, others.into_iter())?;
                    if shift >= 20 {
                        decided.set(decided.get() + placed);
                        tried.set(tried.get() + 2 * others.len() as u32);
                    }
                    quick_as_exact::<false>(parts, near_edges.into_iter())?;
                    quick_as_exact::<true>(parts, near_edges.into_iter())?;
                    Ok(())
                },
            )
            .unwrap();
        // Undecided at most 2¹⁷/2²⁰ of the time at shifts of 20 or more.
        let (decided, tried) = (decided.get(), tried.get());
        assert!(decided > tried / 2, "{decided} of {tried}");
    }

    /// A point's cell is its row × width + column where it is inside the area, and at or
    /// past the last cell where only its row is beyond (a column beyond: none).
    #[test]
    fn cells_are_rows_and_columns_inside_and_past_the_last_outside() {
        let tried = core::cell::Cell::new(0);
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(
                    (1i64 << 28..1i64 << 45, 0i64..(1 << 33)),
                    (1u32..700, 1u32..700),
                    any::<[[i32; 2]; 6]>(),
                ),
                |((scale, offset), (width, height), points)| {
                    // A box of ±1 at 28 fraction bits, its corner `offset` into the area.
                    let (low, high) = (-(1 << 28), 1 << 28);
                    let pixels = |v: i32| ((i128::from(v) << 4) * i128::from(scale)) >> 32;
                    let origin = Real::from_bits((i128::from(offset) - pixels(low)) as i64);
                    let origin_down = Real::from_bits((i128::from(offset) + pixels(high)) as i64);
                    let scale = Real::from_bits(scale);
                    let (Some(across), Some(down)) = (
                        Rule::new(false, (low, high), 28, (scale, origin), (0, width)),
                        Rule::new(true, (low, high), 28, (scale, origin_down), (0, height)),
                    ) else {
                        return Ok(());
                    };
                    let (Some(columns), Some(rows)) =
                        (Axis::of(across, width), Axis::of(down, height))
                    else {
                        return Ok(());
                    };
                    prop_assume!(width <= 1 << down.shift);
                    tried.set(tried.get() + 1);
                    let placer = Placer { columns, rows };
                    let edges = [
                        [i32::MIN, i32::MIN],
                        [i32::MAX, i32::MAX],
                        [0, 0],
                        [low, high],
                    ];
                    for [u, v] in points.into_iter().chain(edges) {
                        let expected = match (by_rule(&across, false, u), by_rule(&down, true, v)) {
                            (Some(column), Some(row)) => Some(Some(row * width + column)),
                            (Some(_), None) => Some(None),
                            (None, _) => None,
                        };
                        let cell = placer.cell(u, v);
                        match expected {
                            Some(Some(inside)) => prop_assert_eq!(cell, Some(inside)),
                            Some(None) => prop_assert!(cell.is_some_and(|c| c >= width * height)),
                            None => prop_assert_eq!(cell, None),
                        }
                    }
                    Ok(())
                },
            )
            .unwrap();
        assert!(tried.get() > 128, "{} tried", tried.get());
    }
}
