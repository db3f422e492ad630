//! Each precision tier's arithmetic: its value and product types, how it multiplies and
//! shifts back (Q12 in i32 with 32-bit products, Q28 with the high word or whole 64-bit
//! products, Q60 with 128-bit products built from 32-bit halves, Q124 with the high halves
//! of 256-bit products).
//!
//! The deep tier's 64×64→128 products are built from 32-bit halves (see `mul_wide`), since
//! an i128 multiply is a library call on Cortex-M.

use core::ops::{Add, Sub};

#[cfg(tinyfractal_no_long_multiply)]
use crate::math::wide::twice_product_by_squares;
use crate::math::wide::{
    mul_high_i128, mul_i32_wide, mul_wide_in_line, shift_round, shift_round_i64,
};

/// A tier's value type (`i32`, `i64` or `i128`): the few operations the orbit needs
/// beyond arithmetic, with their unsigned twins.
pub(super) trait Word: Copy + Add<Output = Self> + Sub<Output = Self> {
    /// A coordinate already in the tier's units (within ±3.5, so the cast is exact); an
    /// `i128` is `Wide`'s Q124, from coordinates in Q60.
    fn from_units(units: i64) -> Self;
    fn abs(self) -> Self;
    fn wrapping_sub(self, other: Self) -> Self;
    /// `self` and `other` as unsigned: `self ≤ other`. With `other` = 2·tolerance and
    /// `self` = d + tolerance, this is |d| ≤ tolerance in one comparison.
    fn unsigned_at_most(self, other: Self) -> bool;
    /// 2·self as unsigned, wrapping.
    fn twice(self) -> Self;
}

macro_rules! word {
    ($v:ty, $u:ty, $shift:expr) => {
        // In the narrow tier the cast from i64 is a real narrowing, elsewhere a no-op.
        #[allow(trivial_numeric_casts)]
        impl Word for $v {
            #[inline(always)]
            fn from_units(units: i64) -> Self {
                (units as $v) << $shift
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$v>::abs(self)
            }
            #[inline(always)]
            fn wrapping_sub(self, other: Self) -> Self {
                <$v>::wrapping_sub(self, other)
            }
            #[inline(always)]
            fn unsigned_at_most(self, other: Self) -> bool {
                (self as $u) <= (other as $u)
            }
            #[inline(always)]
            fn twice(self) -> Self {
                (self as $u).wrapping_mul(2) as $v
            }
        }
    };
}

word!(i32, u32, 0);
word!(i64, u64, 0);
word!(i128, u128, 64);

/// One tier's arithmetic: its value type, its product type (with `FOUR`, 4 in the
/// product's units), the product as the tier keeps it (rounded down), x² − y² back in
/// the value's units, 2xy as a value (rounded down), and a value in Q28 for the cardioid
/// test (exact from the narrow tier, so the test is about the point iterated; rounded from
/// the deep one, which the test's margin covers).
pub(super) trait Arithmetic {
    type Value: Word;
    type Product: Copy + PartialOrd + Add<Output = Self::Product> + Sub<Output = Self::Product>;
    const FOUR: Self::Product;
    fn mul(a: Self::Value, b: Self::Value) -> Self::Product;
    fn to_value(d: Self::Product) -> Self::Value;
    fn twice_xy(
        x: Self::Value,
        y: Self::Value,
        x2: Self::Product,
        y2: Self::Product,
    ) -> Self::Value;
    /// z² + c: x² − y² + cr (x² − y² from the squares the loop already has) and
    /// 2xy + ci.
    #[inline(always)]
    fn square_plus(
        (x, y): (Self::Value, Self::Value),
        (x2, y2): (Self::Product, Self::Product),
        (cr, ci): (Self::Value, Self::Value),
    ) -> (Self::Value, Self::Value) {
        (
            Self::to_value(x2 - y2) + cr,
            Self::twice_xy(x, y, x2, y2) + ci,
        )
    }
    /// |z|² > 4, from the squares.
    #[inline(always)]
    fn escapes(x2: Self::Product, y2: Self::Product) -> bool {
        x2 + y2 > Self::FOUR
    }
    fn q28(v: Self::Value) -> i32;
    /// A value in Q60, truncated from `Wide` (distance estimation's start).
    fn q60(v: Self::Value) -> i64;
    /// Whether a step is a few 32-bit multiplies: then the repeat-testing loop takes four
    /// steps a turn and tests once, which leaves the turn's constants in registers; a
    /// 64-bit tier keeps a test after each step, whose values four a turn would spill
    /// (docs/performance.md). Every core tests the same steps, so every core counts the
    /// same iterations.
    const WORD_STEPS: bool = false;
    /// Whether the orbit takes one step a turn: `Wide`, whose steps are calls, and whose
    /// unrolled loops did not fit the LM3S6965's flash.
    const COMPACT: bool = false;
}

/// Q12 in i32 with 32-bit products (Q24).
pub(super) struct Narrow;
/// Q28 in i32 whose products keep their high word (Q24), shifted back into Q28 with c's
/// low bits added: |x² − y²| ≤ 4 and |xy| ≤ 2 while the orbit runs, so nothing overflows.
/// Rounded down or half up (`ROUNDED`): see `Medium` and `RoundedMedium`.
pub(super) struct HighWord<const ROUNDED: bool>;
/// The Mandelbrot set's `Medium`: products rounded down (the upper register of `smull`),
/// 2xy as xy doubled. The views it is chosen for keep every dwell.
pub(super) type Medium = HighWord<false>;
/// `Medium` for Julia sets: each product's high word rounded half up, and 2xy as the
/// high word of x·2y (one bit more). Truncated products bias a long orbit; rounded, the
/// 320×240 Julia views at 100 iterations keep as many dwells as a naive `f32` loop
/// (docs/tiers.md), at no cost on Cortex-M4, whose `smmulr` (and `smmlar` for the escape
/// test's sum) round within the product (docs/performance.md). Elsewhere rounding costs an add a product, which
/// the Mandelbrot set's `Medium` views (already exact) are spared.
pub(super) type RoundedMedium = HighWord<true>;
/// Q28 in i32 with exact 64-bit products (Q56).
pub(super) struct Standard;
/// Q60 in i64 with exact 128-bit products (Q120).
pub(super) struct Deep;
/// Q124 in i128 whose 256-bit products keep their high halves (Q120, rounded down):
/// twice `Deep`'s bits, for the long orbits of deep views where 60 bits are not enough.
/// |x|, |y| < 7.5 (below 2¹²⁷ in Q124), and a sum of two squares below 114 (below 2¹²⁷
/// in Q120): nothing overflows.
pub(super) struct Wide;

impl Arithmetic for Narrow {
    const WORD_STEPS: bool = true;
    type Value = i32;
    type Product = i32;
    const FOUR: i32 = 4 << 24;
    #[inline(always)]
    fn mul(a: i32, b: i32) -> i32 {
        a * b
    }
    #[inline(always)]
    fn to_value(d: i32) -> i32 {
        d >> 12
    }
    #[inline(always)]
    fn twice_xy(x: i32, y: i32, _: i32, _: i32) -> i32 {
        (x * y) >> 11
    }
    #[inline(always)]
    fn q28(v: i32) -> i32 {
        v << 16
    }
    fn q60(v: i32) -> i64 {
        i64::from(v) << 48
    }
}

impl<const ROUNDED: bool> Arithmetic for HighWord<ROUNDED> {
    const WORD_STEPS: bool = true;
    type Value = i32;
    type Product = i32;
    const FOUR: i32 = 4 << 24;
    #[inline(always)]
    fn mul(a: i32, b: i32) -> i32 {
        if ROUNDED {
            rounded_high_word(a, b)
        } else {
            high_word(a, b)
        }
    }
    #[inline(always)]
    fn to_value(d: i32) -> i32 {
        d << 4
    }
    /// Rounded: the high word of x·2y (|y| ≤ 2 here, so 2y fits), one bit more than
    /// doubling xy's. Truncated: xy's doubled, which is cheaper.
    #[inline(always)]
    fn twice_xy(x: i32, y: i32, _: i32, _: i32) -> i32 {
        if ROUNDED {
            rounded_high_word(x, y << 1) << 4
        } else {
            high_word(x, y) << 5
        }
    }
    #[inline(always)]
    fn q28(v: i32) -> i32 {
        v
    }
    fn q60(v: i32) -> i64 {
        i64::from(v) << 32
    }
}

impl Arithmetic for Standard {
    const WORD_STEPS: bool = true;
    type Value = i32;
    type Product = i64;
    const FOUR: i64 = 4 << 56;
    #[inline(always)]
    fn mul(a: i32, b: i32) -> i64 {
        mul_i32_wide(a, b)
    }
    #[inline(always)]
    fn to_value(d: i64) -> i32 {
        (d >> 28) as i32
    }
    #[inline(always)]
    fn twice_xy(x: i32, y: i32, x2: i64, y2: i64) -> i32 {
        standard_twice_xy(x, y, x2, y2)
    }
    /// On Cortex-M3/M4: x² − y² as (x + y)(x − y), the same exact value, so the squares
    /// are only summed for the escape test (`smull` and `smlal`, neither kept); and each
    /// product's two words added to c apart (`add` with a shifted operand, twice) instead
    /// of being joined first: the same bits as `(p >> 28) + c`, and cheaper there
    /// (docs/performance.md). Not on a 64-bit host, where the plain form is faster.
    #[cfg(all(target_arch = "arm", not(tinyfractal_no_long_multiply)))]
    #[inline(always)]
    fn square_plus((x, y): (i32, i32), _: (i64, i64), (cr, ci): (i32, i32)) -> (i32, i32) {
        // |x|, |y| ≤ 2 (Q28) here, so x ± y fit in an i32.
        (
            plus_shifted(cr, mul_i32_wide(x + y, x - y), 28),
            plus_shifted(ci, mul_i32_wide(x, y), 27),
        )
    }
    /// |z|² > 4 from the high word first: below 4·2²⁴ there, it is not. The exact test on
    /// both words runs only from there. LLVM merges any test it can see through with the
    /// first into one 64-bit comparison a step, so the sum reaches it through `black_box`
    /// (a store and a load, at escape only), cheaper than a call out of line.
    #[cfg(not(tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn escapes(x2: i64, y2: i64) -> bool {
        let sum = x2 + y2;
        (sum >> 32) as i32 >= 4 << 24 && core::hint::black_box(sum) > Self::FOUR
    }
    #[inline(always)]
    fn q28(v: i32) -> i32 {
        v
    }
    fn q60(v: i32) -> i64 {
        i64::from(v) << 32
    }
}

/// `c + (p >> shift)` in an i32 (0 < shift < 32; the sum fits, as the orbit's invariant
/// guarantees), from p's words: `c + (high << (32 − shift)) + (low >> shift)`.
#[cfg(any(test, all(target_arch = "arm", not(tinyfractal_no_long_multiply))))]
#[inline(always)]
pub(super) fn plus_shifted(c: i32, p: i64, shift: u32) -> i32 {
    let (high, low) = ((p >> 32) as i32, p as u32);
    c.wrapping_add(high << (32 - shift))
        .wrapping_add((low >> shift) as i32)
}

impl Arithmetic for Deep {
    type Value = i64;
    type Product = i128;
    const FOUR: i128 = 4 << 120;
    #[inline(always)]
    fn mul(a: i64, b: i64) -> i128 {
        mul_wide_in_line(a, b)
    }
    #[inline(always)]
    fn to_value(d: i128) -> i64 {
        (d >> 60) as i64
    }
    #[inline(always)]
    fn twice_xy(x: i64, y: i64, _: i128, _: i128) -> i64 {
        (mul_wide_in_line(x, y) >> 59) as i64
    }
    #[inline(always)]
    fn q28(v: i64) -> i32 {
        shift_round_i64(v, 32) as i32
    }
    fn q60(v: i64) -> i64 {
        v
    }
}

impl Arithmetic for Wide {
    const COMPACT: bool = true;
    type Value = i128;
    type Product = i128;
    const FOUR: i128 = 4 << 120;
    #[inline(always)]
    fn mul(a: i128, b: i128) -> i128 {
        mul_high_i128(a, b)
    }
    #[inline(always)]
    fn to_value(d: i128) -> i128 {
        d << 4
    }
    /// 2xy from xy's high half doubled: a bit fewer than x² − y², far below the spacing.
    #[inline(always)]
    fn twice_xy(x: i128, y: i128, _: i128, _: i128) -> i128 {
        mul_high_i128(x, y) << 5
    }
    #[inline(always)]
    fn q28(v: i128) -> i32 {
        shift_round(v, 96) as i32
    }
    fn q60(v: i128) -> i64 {
        (v >> 64) as i64
    }
}

/// Q60 in i64 whose products keep their high words, in Q56: from 32-bit halves, the
/// low halves' product dropped (below a quarter of a unit) and the cross products'
/// sum floored, so each is within 2^-55 of the exact one, in three 32×32 products
/// instead of `Deep`'s four with 128-bit sums. While the orbit runs |x|, |y| ≤ 2, so
/// x² − y² and 2xy shift back into Q60 without overflow; a square of the next point
/// (below 7.5) stays below 2^62, and the sum of two below 2^63. Not a tier of its own:
/// only a perturbed pixel's finish, where neighbouring pixels' orbits are already far
/// more than a spacing apart (the perturbation module's rule).
pub(super) struct HighWords;

impl HighWords {
    /// Balanced halves: v = high·2^32 + low with low in [-2^31, 2^31), so every partial
    /// product is a signed 32×32 one; |high| < 2^31 for |v| < 8 (Q60).
    #[inline(always)]
    fn halves(v: i64) -> (i32, i32) {
        (((v - i64::from(v as i32)) >> 32) as i32, v as i32)
    }

    /// (a·b) >> 64 (Q120 to Q56), within 1.25 units below or a quarter above.
    #[inline(always)]
    fn product(a: i64, b: i64) -> i64 {
        let ((ah, al), (bh, bl)) = (Self::halves(a), Self::halves(b));
        // Each cross product is below 2^62 in magnitude: their sum fits.
        let cross = mul_i32_wide(ah, bl) + mul_i32_wide(al, bh);
        mul_i32_wide(ah, bh) + (cross >> 32)
    }

    /// [`product`](Self::product)`(a, a)` in two products: the cross products are equal,
    /// so their sum shifted down 32 is one of them shifted down 31.
    #[inline(always)]
    pub(super) fn square(a: i64) -> i64 {
        let (high, low) = Self::halves(a);
        mul_i32_wide(high, high) + (mul_i32_wide(high, low) >> 31)
    }
}

impl Arithmetic for HighWords {
    type Value = i64;
    type Product = i64;
    const FOUR: i64 = 4 << 56;
    #[inline(always)]
    fn mul(a: i64, b: i64) -> i64 {
        Self::product(a, b)
    }
    #[inline(always)]
    fn to_value(d: i64) -> i64 {
        d << 4
    }
    #[inline(always)]
    fn twice_xy(x: i64, y: i64, _: i64, _: i64) -> i64 {
        Self::product(x, y) << 5
    }
    #[inline(always)]
    fn q28(v: i64) -> i32 {
        Deep::q28(v)
    }
    fn q60(v: i64) -> i64 {
        v
    }
}

/// The high word of the exact product of two i32, rounded down (Q28 × Q28 → Q24): the
/// upper register of `smull`.
#[inline(always)]
pub(super) fn high_word(a: i32, b: i32) -> i32 {
    (mul_i32_wide(a, b) >> 32) as i32
}

/// The high word of the exact product of two i32, rounded half up (Q28 × Q28 → Q24):
/// `smmulr` on Cortex-M4; elsewhere the high word plus the low word's top bit, added after
/// `smull`: cheaper than the 64-bit sum LLVM makes there (docs/performance.md).
#[inline(always)]
pub(super) fn rounded_high_word(a: i32, b: i32) -> i32 {
    let product = mul_i32_wide(a, b);
    #[cfg(tinyfractal_rounding_multiply)]
    {
        ((product + (1 << 31)) >> 32) as i32
    }
    #[cfg(not(tinyfractal_rounding_multiply))]
    {
        ((product >> 32) as i32).wrapping_add(((product as u32) >> 31) as i32)
    }
}

/// The standard tier's 2xy (Q28, rounded down): `smull` and a shift where there is
/// a long multiply; from the squares the loop already has where there is not (ARMv6-M).
/// Both are exact, so every core gets the same bits.
#[inline(always)]
pub(super) fn standard_twice_xy(x: i32, y: i32, x2: i64, y2: i64) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        // |x|, |y| ≤ 2 (Q28) here, so x + y fits in an i32.
        (twice_product_by_squares(x, y, x2, y2) >> 28) as i32
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        let _ = (x2, y2);
        (mul_i32_wide(x, y) >> 27) as i32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `RoundedMedium`'s high word, whichever instructions the target uses, against its
    /// definition in i128: ⌊a·b / 2³² + ½⌋.
    #[test]
    fn rounded_medium_products_round_half_up() {
        use proptest::prelude::*;
        let round = |v: i128| (v + (1 << 31)).div_euclid(1 << 32);
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(&(any::<i32>(), any::<i32>()), |(a, b)| {
                let product = i128::from(a) * i128::from(b);
                prop_assert_eq!(i128::from(rounded_high_word(a, b)), round(product));
                Ok(())
            })
            .unwrap();
        // Exact halves round up, either sign.
        assert_eq!(rounded_high_word(1 << 15, 1 << 16), 1);
        assert_eq!(rounded_high_word(-(1 << 15), 1 << 16), 0);
    }

    /// The high words' product against the exact 128-bit one, over values of every size
    /// up to 7.5 (Q60) and both signs: within 1.25 units of Q56 below and a quarter above,
    /// as `HighWords` claims.
    #[test]
    fn high_word_products_are_within_a_unit_and_a_quarter() {
        use proptest::prelude::*;
        let limit = 15i64 << 59;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(
                &(-limit..=limit, -limit..=limit, 0u32..63),
                |(a, b, shift)| {
                    let b = b >> shift;
                    let exact = i128::from(a) * i128::from(b);
                    let ours = i128::from(HighWords::product(a, b)) << 64;
                    let unit = 1i128 << 64;
                    prop_assert!(
                        ours - exact <= unit / 4 && exact - ours < unit + unit / 4,
                        "{a} x {b}"
                    );
                    Ok(())
                },
            )
            .unwrap();
    }

    /// A high words' square in two products is the three-product one, bit for bit (the
    /// distance estimate's orbit squares with it and must follow the same points), and so
    /// within its bounds of the exact square, for values of every size up to 7.5 (Q60).
    #[test]
    fn high_word_squares_are_the_products_of_a_value_by_itself() {
        use proptest::prelude::*;
        let limit = 15i64 << 59;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(&(-limit..=limit, 0u32..63), |(a, shift)| {
                let a = a >> shift;
                prop_assert_eq!(HighWords::square(a), HighWords::product(a, a), "{}", a);
                Ok(())
            })
            .unwrap();
        for a in [
            0,
            1,
            -1,
            1 << 32,
            -(1 << 32),
            (1 << 31) - 1,
            -(1 << 31),
            limit,
            -limit,
        ] {
            assert_eq!(HighWords::square(a), HighWords::product(a, a), "{a}");
        }
    }

    /// `Standard`'s step and escape test against the plain i64 sums they stand for
    /// (`(x² − y²) >> 28 + cr`, `2xy >> 28 + ci`, `x² + y² > 4`), over points within
    /// radius 2 and c within ±3.5; and the escape test at 4 exactly and one unit
    /// either side, where the high word alone would be wrong.
    #[test]
    fn standard_step_equals_the_plain_sums() {
        use proptest::prelude::*;
        let (two, limit) = (2i32 << 28, 7i32 << 27);
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(
                &(-two..=two, -two..=two, -limit..=limit, -limit..=limit),
                |(x, y, cr, ci)| {
                    let (x2, y2) = (i64::from(x) * i64::from(x), i64::from(y) * i64::from(y));
                    // Only points within radius 2 are squared.
                    prop_assume!(x2 + y2 <= 4 << 56);
                    let expected = (
                        ((x2 - y2) >> 28) as i32 + cr,
                        ((2 * i64::from(x) * i64::from(y)) >> 28) as i32 + ci,
                    );
                    prop_assert_eq!(Standard::square_plus((x, y), (x2, y2), (cr, ci)), expected);
                    // Cortex-M's form of the same sums.
                    let s = (
                        i64::from(x + y) * i64::from(x - y),
                        i64::from(x) * i64::from(y),
                    );
                    prop_assert_eq!(
                        (plus_shifted(cr, s.0, 28), plus_shifted(ci, s.1, 27)),
                        expected
                    );
                    let (x, y) = expected;
                    let (x2, y2) = (i64::from(x) * i64::from(x), i64::from(y) * i64::from(y));
                    prop_assert_eq!(Standard::escapes(x2, y2), x2 + y2 > 4 << 56);
                    Ok(())
                },
            )
            .unwrap();
        let four = 4i64 << 56;
        assert!(!Standard::escapes(four, 0));
        assert!(!Standard::escapes(four - 1, 0));
        assert!(Standard::escapes(four, 1));
        assert!(Standard::escapes(four + (1 << 32), 0));
        // z = 2 exactly, the tip of the Mandelbrot set: |z|² = 4 does not escape.
        let two = i64::from(two);
        assert!(!Standard::escapes(two * two, 0));
    }
}
