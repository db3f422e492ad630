//! A word's leading zeros where the core has no instruction for them.
//!
//! ARMv6-M (Cortex-M0/M0+) has no `clz`: `u32::leading_zeros` is a call to the library's
//! `__clzsi2`, a loop of tests and moves behind a call. The logarithm's leading bit and
//! the derivative's normalising, taken at every escaping pixel's estimate and smooth
//! value, find them inline instead, by a product and a table of 32 bytes (what that saves: docs/performance.md,
//! Fractint's modes and distance estimation). Elsewhere it is the instruction.

/// The leading zeros of `v`, as `u32::leading_zeros` counts them (32 for 0).
#[inline(always)]
pub(crate) fn leading_zeros(v: u32) -> u32 {
    #[cfg(tinyfractal_no_leading_zeros)]
    {
        leading_zeros_by_product(v)
    }
    #[cfg(not(tinyfractal_no_leading_zeros))]
    {
        v.leading_zeros()
    }
}

/// A multiplier whose top five bits, times each of the 32 words 2^(k + 1) − 1, differ: a
/// de Bruijn sequence's, as used to find a word's leading bit by a product.
const SMEARED_MULTIPLIER: u32 = 0x07C4_ACDD;

/// The leading zeros of 2^(k + 1) − 1 by the top five bits of its product with
/// [`SMEARED_MULTIPLIER`]: 31 − k.
// Indexing runs at compile time only: an out-of-range index would fail the build, not panic.
#[allow(clippy::indexing_slicing)]
#[cfg_attr(not(tinyfractal_no_leading_zeros), allow(dead_code))]
static ZEROS_BY_PRODUCT: [u8; 32] = {
    let mut table = [0; 32];
    let mut k = 0;
    while k < 32 {
        let smeared = u32::MAX >> (31 - k);
        table[(smeared.wrapping_mul(SMEARED_MULTIPLIER) >> 27) as usize] = 31 - k as u8;
        k += 1;
    }
    table
};

/// The leading zeros of `v` without a branch or a call: every bit below the leading one
/// set (v becomes 2^(k + 1) − 1 for the leading bit k), then the product with
/// [`SMEARED_MULTIPLIER`] picks k's entry of [`ZEROS_BY_PRODUCT`].
#[cfg_attr(not(tinyfractal_no_leading_zeros), allow(dead_code))]
#[inline(always)]
fn leading_zeros_by_product(mut v: u32) -> u32 {
    if v == 0 {
        return 32;
    }
    v |= v >> 1;
    v |= v >> 2;
    v |= v >> 4;
    v |= v >> 8;
    v |= v >> 16;
    let entry = (v.wrapping_mul(SMEARED_MULTIPLIER) >> 27) as usize;
    u32::from(ZEROS_BY_PRODUCT.get(entry).copied().unwrap_or(0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The product counts as the instruction does: every single bit, every run of ones
    /// below a leading bit, 0 and the ends, and random words of every length.
    #[test]
    fn the_search_counts_leading_zeros() {
        let ends = [0, u32::MAX];
        let bits = (0..32).flat_map(|top: u32| {
            let bit = 1u32 << top;
            [bit, bit | (bit - 1), bit.wrapping_add(1)]
        });
        for v in ends.into_iter().chain(bits) {
            assert_eq!(leading_zeros_by_product(v), v.leading_zeros(), "{v:#x}");
            assert_eq!(leading_zeros(v), v.leading_zeros(), "{v:#x}");
        }
        proptest!(|(v: u32, length in 0..=32u32)| {
            let v = v.checked_shr(32 - length).unwrap_or(0);
            prop_assert_eq!(leading_zeros_by_product(v), v.leading_zeros());
        });
    }
}
