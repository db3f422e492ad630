//! The numbers a flow's step computes in: checked values, values proven to stay in range,
//! and ranges of values, so that one step's code both runs and proves a box of states safe.
//!
//! A step is written once over [`Value`]. With [`Checked`] every sum and product is
//! checked back into 32 bits, as [`fixed`](super::fixed) does; with [`Ranges`] each value
//! is an interval of every value it can take for states in a box, and an operation whose
//! result might leave 32 bits gives `None`. A box whose step takes no such operation is a
//! [`SafeBox`]: for a state in it the step can take no check, and [`Unchecked`] runs the
//! same operations without them, giving the checked step's values.

use super::fixed::{high_word, mul, mul_narrow, sixth};

/// A number a flow's step computes in.
pub(super) trait Value: Copy {
    /// A constant.
    fn of(value: i32) -> Self;
    /// `self + other`, or `None` where it may leave 32 bits.
    fn add(self, other: Self) -> Option<Self>;
    /// `self − other`, or `None` where it may leave 32 bits.
    fn sub(self, other: Self) -> Option<Self>;
    /// `rate·self` for a rate given as a factor of [`high_word`] (never beyond 32 bits).
    fn rate(self, rate: i32) -> Self;
    /// `self·other` with `F` fraction bits, rounded down, or `None` where it may leave
    /// 32 bits.
    fn times<const F: u32>(self, other: Self) -> Option<Self>;
    /// Half, rounded down.
    fn half(self) -> Self;
    /// A sixth, rounded half away from zero ([`sixth`]).
    fn sixth(self) -> Self;
}

/// A 32-bit value whose every sum and product is checked (`CHECKED`), or a value of a
/// step from a state in a [`SafeBox`], where no operation can leave 32 bits, so none is
/// checked and each gives the checked value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Word<const CHECKED: bool>(pub(super) i32);

/// A value whose every sum and product is checked.
pub(super) type Checked = Word<true>;

/// A value of a step from a state in a [`SafeBox`], unchecked.
pub(super) type Unchecked = Word<false>;

impl<const CHECKED: bool> Value for Word<CHECKED> {
    #[inline(always)]
    fn of(value: i32) -> Self {
        Self(value)
    }

    #[inline(always)]
    fn add(self, other: Self) -> Option<Self> {
        if CHECKED {
            self.0.checked_add(other.0).map(Self)
        } else {
            Some(Self(self.0.wrapping_add(other.0)))
        }
    }

    #[inline(always)]
    fn sub(self, other: Self) -> Option<Self> {
        if CHECKED {
            self.0.checked_sub(other.0).map(Self)
        } else {
            Some(Self(self.0.wrapping_sub(other.0)))
        }
    }

    #[inline(always)]
    fn rate(self, rate: i32) -> Self {
        Self(high_word(rate, self.0))
    }

    #[inline(always)]
    fn times<const F: u32>(self, other: Self) -> Option<Self> {
        if CHECKED {
            mul_narrow::<F>(self.0, other.0).map(Self)
        } else {
            Some(Self(mul::<F>(self.0, other.0) as i32))
        }
    }

    #[inline(always)]
    fn half(self) -> Self {
        Self(self.0 >> 1)
    }

    #[inline(always)]
    fn sixth(self) -> Self {
        Self(sixth(self.0))
    }
}

/// Every value a step's value can take for states in a box: `lo..=hi`, both in 32 bits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Ranges {
    lo: i32,
    hi: i32,
}

impl Ranges {
    /// `lo..=hi` of 64-bit ends, or `None` where either leaves 32 bits.
    fn within(lo: i64, hi: i64) -> Option<Self> {
        Some(Self {
            lo: i32::try_from(lo).ok()?,
            hi: i32::try_from(hi).ok()?,
        })
    }

    /// Every value from `lo` to `hi`.
    pub(super) fn new(lo: i32, hi: i32) -> Self {
        Self {
            lo: lo.min(hi),
            hi: lo.max(hi),
        }
    }

    /// Each end through `f`, which never decreases.
    fn rising(self, f: impl Fn(i32) -> i32) -> Self {
        Self {
            lo: f(self.lo),
            hi: f(self.hi),
        }
    }
}

impl Value for Ranges {
    fn of(value: i32) -> Self {
        Self::new(value, value)
    }

    fn add(self, other: Self) -> Option<Self> {
        let wide = |v: i32| i64::from(v);
        Self::within(
            wide(self.lo) + wide(other.lo),
            wide(self.hi) + wide(other.hi),
        )
    }

    fn sub(self, other: Self) -> Option<Self> {
        let wide = |v: i32| i64::from(v);
        Self::within(
            wide(self.lo) - wide(other.hi),
            wide(self.hi) - wide(other.lo),
        )
    }

    fn rate(self, rate: i32) -> Self {
        // A product's high word rises with the value for a rate of 0 or more and falls
        // with it otherwise.
        Self::new(high_word(rate, self.lo), high_word(rate, self.hi))
    }

    fn times<const F: u32>(self, other: Self) -> Option<Self> {
        // A product of two ranges is largest and smallest at their ends; rounding down
        // keeps the order.
        let ends = [
            mul::<F>(self.lo, other.lo),
            mul::<F>(self.lo, other.hi),
            mul::<F>(self.hi, other.lo),
            mul::<F>(self.hi, other.hi),
        ];
        let lo = ends.iter().copied().min()?;
        let hi = ends.iter().copied().max()?;
        Self::within(lo, hi)
    }

    fn half(self) -> Self {
        self.rising(|v| v >> 1)
    }

    fn sixth(self) -> Self {
        self.rising(sixth)
    }
}

/// A box of states (x, y and z each within bounds) from which a step is proven to take
/// no value beyond 32 bits ([`Ranges`]): from a state in it the step may run
/// [`Unchecked`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct SafeBox {
    /// Each coordinate's least value.
    pub(super) low: [i32; 3],
    /// Each coordinate's greatest value less its least.
    pub(super) span: [u32; 3],
}

impl SafeBox {
    /// The box of `ranges`, if `step` from every state in it is proven to stay in 32 bits.
    pub(super) fn proven(
        ranges: [Ranges; 3],
        step: impl Fn([Ranges; 3]) -> Option<[Ranges; 3]>,
    ) -> Option<Self> {
        step(ranges)?;
        Some(Self {
            low: ranges.map(|r| r.lo),
            span: ranges.map(|r| r.hi.abs_diff(r.lo)),
        })
    }

    /// Whether `state` is in the box: each coordinate one subtraction and one unsigned
    /// comparison.
    #[inline(always)]
    pub(super) fn contains(&self, [x, y, z]: [i32; 3]) -> bool {
        let ([x0, y0, z0], [dx, dy, dz]) = (self.low, self.span);
        let inside = |v: i32, low: i32, span: u32| v.wrapping_sub(low) as u32 <= span;
        inside(x, x0, dx) && inside(y, y0, dy) && inside(z, z0, dz)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// Each operation on ranges holds the checked operation's value for every pair of
    /// values in them, and refuses where some pair's checked operation does.
    #[test]
    fn ranges_hold_every_checked_value() {
        let mut runner = TestRunner::deterministic();
        let value = prop_oneof![any::<i32>(), -(1i32 << 20)..(1 << 20), -300..300];
        runner
            .run(
                &(
                    [value.clone(), value.clone(), value.clone(), value],
                    0.0..=1.0f64,
                    0.0..=1.0f64,
                ),
                |([a0, a1, b0, b1], s, t)| {
                    let (a, b) = (Ranges::new(a0, a1), Ranges::new(b0, b1));
                    // A value inside each range, chosen by s and t.
                    let pick = |r: Ranges, f: f64| {
                        (f64::from(r.lo) + f * (f64::from(r.hi) - f64::from(r.lo))) as i32
                    };
                    let (x, y): (Checked, Checked) = (Word(pick(a, s)), Word(pick(b, t)));
                    let holds = |r: Option<Ranges>, v: Option<Checked>| match (r, v) {
                        (Some(r), Some(v)) => r.lo <= v.0 && v.0 <= r.hi,
                        (Some(_), None) => false,
                        (None, _) => true,
                    };
                    prop_assert!(holds(a.add(b), x.add(y)));
                    prop_assert!(holds(a.sub(b), x.sub(y)));
                    prop_assert!(holds(a.times::<24>(b), x.times::<24>(y)));
                    prop_assert!(holds(Some(a.rate(b0)), Some(x.rate(b0))));
                    prop_assert!(holds(Some(a.half()), Some(x.half())));
                    prop_assert!(holds(Some(a.sixth()), Some(x.sixth())));
                    // Where the ranges prove an operation safe, unchecked gives its value.
                    let (u, v): (Unchecked, Unchecked) = (Word(x.0), Word(y.0));
                    if a.times::<24>(b).is_some() {
                        prop_assert_eq!(
                            u.times::<24>(v).map(|w| w.0),
                            x.times::<24>(y).map(|w| w.0)
                        );
                    }
                    if a.add(b).is_some() {
                        prop_assert_eq!(u.add(v).map(|w| w.0), x.add(y).map(|w| w.0));
                    }
                    if a.sub(b).is_some() {
                        prop_assert_eq!(u.sub(v).map(|w| w.0), x.sub(y).map(|w| w.0));
                    }
                    Ok(())
                },
            )
            .unwrap();
    }

    /// A box holds its corners and nothing past them, at the ends of 32 bits too.
    #[test]
    fn boxes_hold_their_corners_only() {
        let ranges = [
            Ranges::new(-5, 7),
            Ranges::new(i32::MIN, i32::MIN + 2),
            Ranges::new(i32::MAX - 1, i32::MAX),
        ];
        let safe = SafeBox::proven(ranges, Some).unwrap();
        assert!(safe.contains([-5, i32::MIN, i32::MAX]));
        assert!(safe.contains([7, i32::MIN + 2, i32::MAX - 1]));
        assert!(!safe.contains([8, i32::MIN, i32::MAX]));
        assert!(!safe.contains([-6, i32::MIN, i32::MAX]));
        assert!(!safe.contains([0, i32::MIN + 3, i32::MAX]));
        assert!(!safe.contains([0, i32::MAX, i32::MAX]));
        assert!(!safe.contains([0, i32::MIN, i32::MAX - 2]));
        assert!(!safe.contains([0, i32::MIN, i32::MIN]));
        assert_eq!(SafeBox::proven(ranges, |_| None), None);
    }
}
