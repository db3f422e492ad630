//! Placing an attractor's points seen from the front in the orbit's own fixed point: a
//! subtraction, a 32×32→64 multiply-accumulate and a shift an axis, instead of converting
//! each point to `Real` and projecting it.

use crate::math::Real;
use crate::render::space::SpaceFit;

/// One axis: the column (or row) of a coordinate `v` is ⌊(start + (v − edge)·step) /
/// 2^shift⌋, where `edge` is a value at or beyond the area's edge, `start` where it falls
/// (plus half a pixel, so the floor rounds to nearest) and `step` the pixels a unit of the
/// fixed point, both scaled by 2^shift.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Axis<const DOWN: bool> {
    /// The value at the area's low edge (for rows: its high edge, rows counting down), or
    /// as far out as 32 bits reach, in state bits.
    edge: i32,
    /// The distance from the edge in state bits past which a coordinate is beyond the area
    /// (its column past the area's far edge).
    span: u32,
    /// Pixels a state unit, times 2^shift.
    step: u32,
    /// Where the edge falls, in pixels from the area's edge plus ½, times 2^shift.
    start: u64,
    /// The shift beyond 32 bits: the product's high word is shifted by this.
    shift: u32,
}

/// `DOWN` for rows: the distance is taken from the high edge down.
impl<const DOWN: bool> Axis<DOWN> {
    /// The axis of a box from `low` to `high` (state bits with `bits` fraction bits) placed
    /// at `screen(v) = origin ± v·scale` (− for rows), in an area starting at `area_start`
    /// and `size` pixels long; `None` where the fixed point cannot place it exactly enough
    /// (a box narrower than a pixel a state unit, or beyond 2¹⁵ pixels).
    fn new(
        (low, high): (i32, i32),
        bits: u32,
        (scale, origin): (Real, Real),
        (area_start, size): (i32, u32),
    ) -> Option<Self> {
        let down = DOWN;
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

    /// The column (row) of `v`, or `None` where it is beyond the area.
    #[inline(always)]
    fn place(&self, v: i32) -> Option<u32> {
        let distance = if DOWN {
            self.edge.wrapping_sub(v)
        } else {
            v.wrapping_sub(self.edge)
        } as u32;
        if distance > self.span {
            return None;
        }
        let total = self.start + crate::math::wide::mul_u32_wide(distance, self.step);
        Some(((total >> 32) as u32) >> self.shift)
    }
}

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
        Some(Self {
            columns: Axis::new(
                (low[0], high[0]),
                bits,
                (scale, origin.0),
                (top_left.0, size.0),
            )?,
            rows: Axis::new(
                (low[1], high[1]),
                bits,
                (scale, origin.1),
                (top_left.1, size.1),
            )?,
        })
    }

    /// The column and row of the point (`u`, `v`) of the picture, or `None` where it is
    /// beyond the area.
    #[inline(always)]
    pub(super) fn place(&self, u: i32, v: i32) -> Option<(u32, u32)> {
        Some((self.columns.place(u)?, self.rows.place(v)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// The column of a distance by the axis's formula, with no span to stop it.
    fn column<const DOWN: bool>(axis: &Axis<DOWN>, distance: u32) -> u128 {
        (u128::from(axis.start) + u128::from(distance) * u128::from(axis.step)) >> (32 + axis.shift)
    }

    /// An axis places exactly the distances whose column is inside the area: its span is
    /// the last of them.
    #[test]
    fn the_span_ends_at_the_areas_far_edge() {
        let placed = core::cell::Cell::new(0);
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(
                    (-(1i32 << 29)..0, 1i32..(1 << 29)),
                    (1i64 << 28..1i64 << 45, 0i64..(1 << 36)),
                    (-300i32..300, 1u32..2000),
                ),
                |((low, high), (scale, offset), (area_start, size))| {
                    // The box's low edge lands `offset` (Q32 pixels) into the area.
                    let low_pixels = ((i128::from(low) << 4) * i128::from(scale)) >> 32;
                    let origin = (i128::from(area_start) << 32) + i128::from(offset) - low_pixels;
                    let origin = i64::try_from(origin).expect("within Q32.32");
                    let scale = (Real::from_bits(scale), Real::from_bits(origin));
                    let Some(axis) = Axis::<false>::new((low, high), 28, scale, (area_start, size))
                    else {
                        return Ok(());
                    };
                    placed.set(placed.get() + 1);
                    prop_assert!(column(&axis, axis.span) < u128::from(size));
                    if axis.span < u32::MAX {
                        prop_assert!(column(&axis, axis.span + 1) >= u128::from(size));
                    }
                    let v = axis.edge.wrapping_add(axis.span as i32);
                    prop_assert_eq!(
                        axis.place(v).map(u128::from),
                        Some(column(&axis, axis.span))
                    );
                    prop_assert_eq!(
                        axis.place(v.wrapping_add(1)).is_none(),
                        axis.span < u32::MAX
                    );
                    Ok(())
                },
            )
            .unwrap();
        // Most boxes are placeable: the test is not of refusals alone.
        assert!(placed.get() > 128, "{} placed", placed.get());
    }
}
