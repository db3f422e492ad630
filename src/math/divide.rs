//! Divisions and roots that no core takes from the library's long routines: 64-bit
//! values divided in 32 bits where they fit (one `udiv` on Cortex-M3 and M4, the short
//! 32-bit routine on M0), a 64-by-32-bit division from 32-bit ones, division by 3 by
//! shifts and by one divisor many times by a multiplier where the core has no divide
//! instruction, and integer square roots from a 32-bit root and a Newton step. The same
//! quotients and roots on every target.

use super::wide::mul_u32_wide;

/// `n / d` as `/` has it (toward zero; `d` not 0), by a 32-bit division where both fit 32
/// bits: one instruction on Cortex-M3 and M4 and a short call on M0, where the 64-bit
/// division is a long library routine on every core.
#[inline(always)]
pub(crate) fn div_narrow(n: i64, d: i64) -> i64 {
    match (i32::try_from(n), i32::try_from(d)) {
        (Ok(n), Ok(d)) if d != 0 && !(n == i32::MIN && d == -1) => i64::from(n / d),
        _ => n / d,
    }
}

/// ⌊`x` / 3⌋ and `x` mod 3: on cores without a divide instruction (ARMv6-M), where `/ 3`
/// is a library call, by shifts and adds ([`div_rem_by_3_shifts`]); elsewhere `/` and `%`,
/// which the compiler takes as a multiply.
#[inline(always)]
pub(crate) fn div_rem_by_3(x: u32) -> (u32, u32) {
    if cfg!(tinyfractal_no_hardware_divide) {
        div_rem_by_3_shifts(x)
    } else {
        (x / 3, x % 3)
    }
}

/// [`div_rem_by_3`] by shifts and adds (Hacker's Delight's `divu3`): q, a sum of shifts of
/// `x`, is ⌊x/3⌋ or up to one below it, so the remainder x − 3q is at most 5, and
/// ⌊11r/32⌋ is 1 exactly where it is 3 or more.
#[inline(always)]
pub(crate) fn div_rem_by_3_shifts(x: u32) -> (u32, u32) {
    let mut q = (x >> 2) + (x >> 4);
    q += q >> 4;
    q += q >> 8;
    q += q >> 16;
    let r = x - 3 * q;
    let carry = (11 * r) >> 5;
    (q + carry, r - 3 * carry)
}

/// `n / d` (`d` not 0) by a 32-bit division where both fit 32 bits: one instruction on
/// Cortex-M3 and M4 and the library's short 32-bit routine on M0, where a 64-bit division
/// is a long library routine on every core.
#[inline(always)]
pub(crate) fn div_u64_narrow(n: u64, d: u64) -> u64 {
    match (u32::try_from(n), u32::try_from(d)) {
        (Ok(n), Ok(d)) if d != 0 => u64::from(n / d),
        _ => n / d,
    }
}

/// ⌊`n` / `d`⌋ for a 64-bit `n` and a 32-bit `d` (not 0) from 32-bit divisions: one
/// instruction each on Cortex-M3 and M4, where a 64-bit division is a long library call.
pub(crate) fn div_u64_by_u32(n: u64, d: u32) -> u64 {
    let (high, low) = ((n >> 32) as u32, n as u32);
    let (quotient, remainder) = (high / d, high % d);
    (u64::from(quotient) << 32) | u64::from(div_with_remainder(remainder, low, d))
}

/// `n / d` as `/` has it (toward zero) for a 32-bit `d` (not 0): the magnitude by
/// [`div_u64_by_u32`], the sign put back; on cores without a divide instruction
/// (ARMv6-M), where 32-bit divisions are library calls too, the library's one 64-bit call.
pub(crate) fn div_i64_by_u32(n: i64, d: u32) -> i64 {
    if cfg!(tinyfractal_no_hardware_divide) {
        return n / i64::from(d);
    }
    // At most |n| ≤ 2⁶³: i64::MIN / 1 wraps back to itself, as `/` gives it.
    let magnitude = div_u64_by_u32(n.unsigned_abs(), d) as i64;
    if n < 0 {
        magnitude.wrapping_neg()
    } else {
        magnitude
    }
}

/// ⌊(`r`·2³² + `low`) / `d`⌋ for `r` < `d` (so the quotient fits 32 bits): Knuth's
/// algorithm D in base 2¹⁶ as Hacker's Delight gives it (`divlu`), each quotient digit
/// estimated by one 32-bit division and corrected at most twice.
fn div_with_remainder(r: u32, low: u32, d: u32) -> u32 {
    const B: u32 = 1 << 16;
    let shift = d.leading_zeros();
    let d = d << shift;
    let (d1, d0) = (d >> 16, d & 0xFFFF);
    let top = if shift == 0 {
        r
    } else {
        (r << shift) | (low >> (32 - shift))
    };
    let low = low << shift;
    let (low1, low0) = (low >> 16, low & 0xFFFF);
    let digit = |numerator: u32, next: u32| {
        let mut q = numerator / d1;
        let mut rest = numerator - q * d1;
        while q >= B || q * d0 > (rest << 16) + next {
            q -= 1;
            rest += d1;
            if rest >= B {
                break;
            }
        }
        q
    };
    let q1 = digit(top, low1);
    let middle = (top << 16)
        .wrapping_add(low1)
        .wrapping_sub(q1.wrapping_mul(d));
    let q0 = digit(middle, low0);
    (q1 << 16) + q0
}

/// ⌊√`n`⌋ for any u64: a 32-bit root of its top bits, one Newton step with a
/// [`div_u64_by_u32`] division, and at most a few steps down (no 64-bit division, which
/// the library's root takes).
pub(crate) fn isqrt_u64(n: u64) -> u64 {
    let Ok(small) = u32::try_from(n) else {
        // n has 33 to 64 bits: its top 31 or 32 bits, an even shift away.
        let shift = (64 - n.leading_zeros() - 31) & !1;
        let top = (n >> shift) as u32;
        // Above √n: (t + 1)² > top ≥ n / 2^shift. At most 2³² − 1 still is (√n < 2³²).
        let above = ((u64::from(top.isqrt()) + 1) << (shift / 2)).min(u64::from(u32::MAX));
        let divisor = above as u32;
        // Newton's step from above stays at or above ⌊√n⌋, within 2 of it here.
        let mut root = (above + div_u64_by_u32(n, divisor)) / 2;
        while root.checked_mul(root).is_none_or(|square| square > n) {
            root -= 1;
        }
        return root;
    };
    u64::from(small.isqrt())
}

/// ⌊√`n`⌋ for any u128: [`isqrt_u64`] of its top bits (an even shift away, since
/// ⌊√(n / 4ᵏ)⌋ = ⌊⌊√n⌋ / 2ᵏ⌋), then its low k bits one at a time, each kept where its
/// square stays at most `n` (no 128-bit division, which the library's root takes).
pub(crate) fn isqrt_u128(n: u128) -> u128 {
    let Ok(small) = u64::try_from(n) else {
        let half_shift = (128 - n.leading_zeros() - 63) / 2;
        let top = (n >> (2 * half_shift)) as u64;
        let mut root = u128::from(isqrt_u64(top)) << half_shift;
        for bit in (0..half_shift).rev() {
            let candidate = root | (1 << bit);
            // Below 2⁶⁴: the square fits.
            if candidate * candidate <= n {
                root = candidate;
            }
        }
        return root;
    };
    u128::from(isqrt_u64(small))
}

/// One 32-bit divisor, to divide many values by: on cores without a divide instruction
/// (ARMv6-M), where each `/` is a long library call (docs/performance.md, The Sierpiński
/// shapes without library arithmetic), by a
/// 32-bit product's high word and two shifts (Granlund and Montgomery, *Division by
/// invariant integers using multiplication*, 1994, figure 4.1), the multiplier found once;
/// elsewhere `/`, one instruction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Divisor {
    divisor: u32,
    /// ⌊2³²·(2^ℓ − d)/d⌋ + 1 for ℓ = ⌈log₂ d⌉: below 2³².
    multiplier: u32,
    /// min(ℓ, 1) and max(ℓ − 1, 0).
    shifts: (u32, u32),
}

impl Divisor {
    /// Division by `divisor`; `None` for 0.
    pub(crate) fn new(divisor: u32) -> Option<Self> {
        if divisor == 0 {
            None
        } else if cfg!(tinyfractal_no_hardware_divide) {
            Some(Self::with_multiplier(divisor))
        } else {
            Some(Self {
                divisor,
                multiplier: 0,
                shifts: (0, 0),
            })
        }
    }

    /// Division by `divisor` (not 0) with its multiplier found.
    fn with_multiplier(divisor: u32) -> Self {
        let ceiling_log = 32 - (divisor - 1).leading_zeros();
        // 2^ℓ − d < d, so the quotient is below 2³².
        let excess = (1u64 << ceiling_log) - u64::from(divisor);
        Self {
            divisor,
            multiplier: ((excess << 32) / u64::from(divisor) + 1) as u32,
            shifts: (ceiling_log.min(1), ceiling_log.saturating_sub(1)),
        }
    }

    /// ⌊`n` / divisor⌋.
    #[inline(always)]
    pub(crate) fn divide(self, n: u32) -> u32 {
        if cfg!(tinyfractal_no_hardware_divide) {
            self.divide_by_multiply(n)
        } else {
            n / self.divisor
        }
    }

    /// [`divide`](Self::divide) by the multiplier: t = ⌊m·n / 2³²⌋, then
    /// (t + ⌊(n − t)/2^s₁⌋) / 2^s₂, exact for every 32-bit `n` (the paper's theorem 4.2).
    #[inline(always)]
    fn divide_by_multiply(self, n: u32) -> u32 {
        let high = (mul_u32_wide(self.multiplier, n) >> 32) as u32;
        (high + ((n - high) >> self.shifts.0)) >> self.shifts.1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The narrow divisions are `/` on i64 and u64, for values of every size (either side
    /// of 32 bits, both signs, and the one quotient that overflows 32 bits).
    #[test]
    fn narrow_division_is_the_wide_one() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let value = (any::<i64>(), 0u32..64).prop_map(|(v, s)| v >> s);
        runner
            .run(&(value.clone(), value), |(n, d)| {
                prop_assume!(d != 0 && !(n == i64::MIN && d == -1));
                prop_assert_eq!(div_narrow(n, d), n / d);
                let (n, d) = (n.unsigned_abs(), d.unsigned_abs());
                prop_assert_eq!(div_u64_narrow(n, d), n / d);
                Ok(())
            })
            .unwrap();
        assert_eq!(div_u64_narrow(u64::from(u32::MAX), 1), u64::from(u32::MAX));
        assert_eq!(div_u64_narrow(1 << 32, 2), 1 << 31);
        let min = i64::from(i32::MIN);
        assert_eq!(div_narrow(min, -1), 1 << 31);
        assert_eq!(div_narrow(-7, 2), -3);
        assert_eq!(div_narrow(7, -2), -3);
    }

    /// Division by a divisor's multiplier is `/`: random values by divisors of every size,
    /// and the ends (1, powers of two and their neighbours, the largest).
    #[test]
    fn division_by_a_multiplier_is_the_operators() {
        use proptest::prelude::*;
        let with_multiplier = Divisor::with_multiplier;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let n = (any::<u32>(), 0u32..32).prop_map(|(v, s)| v >> s);
        let d = (1u32.., 0u32..32).prop_map(|(v, s)| (v >> s).max(1));
        runner
            .run(&(n, d), |(n, d)| {
                prop_assert_eq!(with_multiplier(d).divide_by_multiply(n), n / d);
                prop_assert_eq!(Divisor::new(d).map(|d| d.divide(n)), Some(n / d));
                Ok(())
            })
            .unwrap();
        let ends = [
            0,
            1,
            2,
            3,
            5,
            7,
            (1 << 16) - 1,
            1 << 16,
            (1 << 31) - 1,
            1 << 31,
        ];
        let ends = ends
            .into_iter()
            .chain([(1 << 31) + 1, u32::MAX - 1, u32::MAX]);
        for d in ends.clone().skip(1) {
            for n in ends.clone().chain((0..3000).map(|k| k * 1_431_655)) {
                assert_eq!(with_multiplier(d).divide_by_multiply(n), n / d, "{n} / {d}");
            }
        }
        assert_eq!(Divisor::new(0), None);
    }

    /// The 64-by-32 division is `/` on u64: random values of every size, divisors of
    /// every size, and the edges.
    #[test]
    fn division_by_32_bits_is_the_wide_one() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let n = (any::<u64>(), 0u32..64).prop_map(|(v, s)| v >> s);
        let d = (1u32.., 0u32..32).prop_map(|(v, s)| (v >> s).max(1));
        runner
            .run(&(n, d), |(n, d)| {
                prop_assert_eq!(div_u64_by_u32(n, d), n / u64::from(d));
                Ok(())
            })
            .unwrap();
        for n in [0, 1, u64::MAX, 1 << 62, (1 << 32) - 1, 1 << 32] {
            for d in [1, 2, 3, 0xFFFF, 0x1_0000, 0x8000_0000, u32::MAX] {
                assert_eq!(div_u64_by_u32(n, d), n / u64::from(d), "{n} / {d}");
            }
        }
    }

    /// Division by 3 by shifts is `/` and `%`: every value below 2²⁴ (every cell
    /// coordinate a subdivision reaches, and more), random words of every size, the top
    /// of the range.
    #[test]
    fn division_by_3_by_shifts_is_the_operators() {
        use proptest::prelude::*;
        for x in (0..1 << 24).chain(u32::MAX - 1000..=u32::MAX) {
            assert_eq!(div_rem_by_3_shifts(x), (x / 3, x % 3), "{x}");
        }
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let x = (any::<u32>(), 0u32..32).prop_map(|(v, s)| v >> s);
        runner
            .run(&x, |x| {
                prop_assert_eq!(div_rem_by_3_shifts(x), (x / 3, x % 3));
                prop_assert_eq!(div_rem_by_3(x), (x / 3, x % 3));
                Ok(())
            })
            .unwrap();
    }

    /// The root is the library's: random values of every size, squares and their
    /// neighbours, and the edges.
    #[test]
    fn the_root_is_the_library_root() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let n = (any::<u64>(), 0u32..64).prop_map(|(v, s)| v >> s);
        runner
            .run(&n, |n| {
                prop_assert_eq!(isqrt_u64(n), n.isqrt());
                Ok(())
            })
            .unwrap();
        let roots = (any::<u32>(), 0u32..32).prop_map(|(v, s)| u64::from(v >> s));
        runner
            .run(&roots, |r| {
                let square = r * r;
                for n in [square.saturating_sub(1), square, square + 1, square + 2 * r] {
                    prop_assert_eq!(isqrt_u64(n), n.isqrt());
                }
                Ok(())
            })
            .unwrap();
        for n in [
            0,
            1,
            2,
            3,
            4,
            u64::MAX,
            u64::MAX - 1,
            1 << 32,
            (1 << 32) - 1,
            1 << 62,
        ] {
            assert_eq!(isqrt_u64(n), n.isqrt(), "{n}");
        }
    }

    /// The 128-bit root is the library's, for values of every size and squares' edges.
    #[test]
    fn the_wide_root_is_the_library_root() {
        use proptest::prelude::*;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let n = (any::<u128>(), 0u32..128).prop_map(|(v, s)| v >> s);
        runner
            .run(&n, |n| {
                prop_assert_eq!(isqrt_u128(n), n.isqrt());
                Ok(())
            })
            .unwrap();
        let roots = (any::<u64>(), 0u32..64).prop_map(|(v, s)| u128::from(v >> s));
        runner
            .run(&roots, |r| {
                let square = r * r;
                for n in [square.saturating_sub(1), square, square + 1, square + 2 * r] {
                    prop_assert_eq!(isqrt_u128(n), n.isqrt());
                }
                Ok(())
            })
            .unwrap();
        for n in [
            0,
            1,
            u128::MAX,
            u128::MAX - 1,
            1 << 64,
            (1 << 64) - 1,
            1 << 84,
        ] {
            assert_eq!(isqrt_u128(n), n.isqrt(), "{n}");
        }
    }
}
