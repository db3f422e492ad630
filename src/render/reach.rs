//! The values a sample of points meets along one axis, kept for a fit: a box measured
//! while a game or an orbit runs, at a comparison a point where it stays inside.

/// The values met along one axis: from `low` to `low + width`.
///
/// Kept as a low end and a width so that a value inside (nearly every one, once an orbit
/// has been round its attractor) is one subtraction and one comparison, not two of each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Reach {
    /// The lowest value met.
    pub(crate) low: i32,
    width: u32,
}

impl Reach {
    /// The one value `v`.
    pub(crate) fn of(v: i32) -> Self {
        Self { low: v, width: 0 }
    }

    /// The highest value met.
    pub(crate) fn high(self) -> i32 {
        self.low.wrapping_add(self.width as i32)
    }

    /// Takes `v` in. Its distance above `low`, unsigned, is beyond the width exactly where
    /// it is above the high end or below `low`: there the distance wraps to v − low + 2³²,
    /// above high − low since v + 2³² is above every i32.
    #[inline(always)]
    pub(crate) fn widen(&mut self, v: i32) {
        let above = v.wrapping_sub(self.low) as u32;
        if above > self.width {
            if v < self.low {
                self.width = self.high().wrapping_sub(v) as u32;
                self.low = v;
            } else {
                self.width = above;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reach over any values is from their least to their greatest.
    #[test]
    fn a_reach_is_from_the_least_to_the_greatest() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let values = proptest::collection::vec(any::<i32>(), 1..40);
        let edges = proptest::sample::select(&[i32::MIN, i32::MAX, 0, -1][..]);
        runner
            .run(&(values, edges), |(values, edge)| {
                let mut reach = Reach::of(edge);
                for &v in &values {
                    reach.widen(v);
                }
                let least = values.iter().copied().fold(edge, i32::min);
                let greatest = values.iter().copied().fold(edge, i32::max);
                prop_assert_eq!((reach.low, reach.high()), (least, greatest));
                Ok(())
            })
            .unwrap();
    }
}
