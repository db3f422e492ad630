//! Exact wide products and rounding helpers, written so that no core calls a library
//! routine for them where it can be avoided (`__aeabi_lmul`, 128-bit multiplies): the
//! same bits on every target. Divisions and roots are in `math::divide`.

/// The exact product of two u32. A single instruction on Cortex-M3/M4 (`umull`); on cores
/// without one (the `tinyfractal_no_long_multiply` cfg, set by build.rs for ARMv6-M) four
/// 16×16 products inline, about a third of the `__aeabi_lmul` call the compiler would make.
#[inline(always)]
pub(crate) fn mul_u32_wide(a: u32, b: u32) -> u64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_u32_halves(a, b)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        u64::from(a) * u64::from(b)
    }
}

/// The exact product of two u32 from 16-bit halves, in 32-bit arithmetic only.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_u32_halves(a: u32, b: u32) -> u64 {
    let (a_low, a_high) = (a & 0xFFFF, a >> 16);
    let (b_low, b_high) = (b & 0xFFFF, b >> 16);
    let (middle, middle_carry) = (a_low * b_high).overflowing_add(a_high * b_low);
    let (low, low_carry) = (a_low * b_low).overflowing_add(middle << 16);
    let high =
        a_high * b_high + (middle >> 16) + (u32::from(middle_carry) << 16) + u32::from(low_carry);
    (u64::from(high) << 32) | u64::from(low)
}

/// The high word of a·x + b·y, exact (a dot product's, as a 2×2 map's row takes it):
/// two `smull`s and an add where there is a long multiply; on cores without one (ARMv6-M)
/// eight 16×16 products whose middle terms are added into the sum once, cheaper than two
/// full [`mul_i32_wide`] products.
#[inline(always)]
pub(crate) fn dot_high(a: i32, x: i32, b: i32, y: i32) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        dot_high_halves(a, x, b, y)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        // Each product is within ±2⁶², so their sum fits, and its high word 32 bits.
        ((mul_i32_wide(a, x) + mul_i32_wide(b, y)) >> 32) as i32
    }
}

/// [`dot_high`] from 16-bit halves in 32-bit arithmetic, with no carries: v = h·2¹⁶ + l
/// with h signed and l in [0, 2¹⁶), so a·x + b·y = H·2³² + M·2¹⁶ + L for H the high
/// halves' products, M the four middle products and L the two low ones. M and L are split
/// again at 16 bits and their parts summed apart (every sum small), which leaves
/// hi = H + Mₕ + ⌊(Mₗ + Lₕ + ⌊Lₗ / 2¹⁶⌋) / 2¹⁶⌋. H wraps in between, as the result fits.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn dot_high_halves(a: i32, x: i32, b: i32, y: i32) -> i32 {
    let split = |v: i32| (v >> 16, v & 0xFFFF);
    let ((ah, al), (xh, xl), (bh, bl), (yh, yl)) = (split(a), split(x), split(b), split(y));
    let high = (ah * xh).wrapping_add(bh * yh);
    // A signed half times an unsigned one is below 2³¹ in magnitude.
    let middles = [ah * xl, al * xh, bh * yl, bl * yh];
    let middle_high: i32 = middles.iter().map(|m| m >> 16).sum();
    let middle_low: i32 = middles.iter().map(|m| m & 0xFFFF).sum();
    // The low halves' products are below 2³² (unsigned).
    let lows = [(al as u32) * (xl as u32), (bl as u32) * (yl as u32)];
    let low_high: u32 = lows.iter().map(|l| l >> 16).sum();
    let low_low: u32 = lows.iter().map(|l| l & 0xFFFF).sum();
    let below = middle_low + (low_high + (low_low >> 16)) as i32;
    high.wrapping_add(middle_high).wrapping_add(below >> 16)
}

/// ⌊a·b / 2³²⌋, the high word of the exact product: one `smull` where there is a long
/// multiply; on cores without one (ARMv6-M) four 16×16 products of signed halves whose
/// middle terms are split and summed apart, with no signs to take off and put back as
/// [`mul_i32_wide`] must.
#[inline(always)]
pub(crate) fn mul_high(a: i32, b: i32) -> i32 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_high_halves(a, b)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        (mul_i32_wide(a, b) >> 32) as i32
    }
}

/// ⌊a·s / 2³²⌋ for any `a` and an `s` within ±0.99·2³¹ (its high half within ±0.99·2¹⁵),
/// from 16-bit halves with signed low parts, v = h·2¹⁶ + l for l in [−2¹⁵, 2¹⁵): every
/// product is then within 2³⁰ and the middle ones' sum fits one word, where a product of
/// any two values must split it again ([`mul_high_halves`]). For cores without a long
/// multiply; `a`'s split is the loop-invariant one (it may take 64 bits).
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_high_near(a: i32, s: i32) -> i32 {
    // a's high half may be 2¹⁵ (a − l past 32 bits); s's is below, so s − l fits.
    let a_low = i32::from(a as i16);
    let a_high = ((i64::from(a) - i64::from(a_low)) >> 16) as i32;
    let (s_high, s_low) = signed_halves(s);
    let middle = a_high * s_low + a_low * s_high + ((a_low * s_low) >> 16);
    a_high * s_high + (middle >> 16)
}

/// `v` as 16-bit halves with a signed low part, (h, l) for v = h·2¹⁶ + l with l in
/// [−2¹⁵, 2¹⁵): both within ±2¹⁵, so that every product of two halves is within 2³⁰.
/// `v` must be below 2³¹ − 2¹⁵ (beyond it h is 2¹⁵ and v − l passes 32 bits).
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
fn signed_halves(v: i32) -> (i32, i32) {
    let low = i32::from(v as i16);
    ((v - low) >> 16, low)
}

/// [`mul_high`] from 16-bit halves, v = h·2¹⁶ + l with h signed and l in [0, 2¹⁶): a·b =
/// H·2³² + (M₁ + M₂)·2¹⁶ + L, so its high word is H + ⌊M₁/2¹⁶⌋ + ⌊M₂/2¹⁶⌋ +
/// ⌊(M₁ mod 2¹⁶ + M₂ mod 2¹⁶ + ⌊L/2¹⁶⌋) / 2¹⁶⌋, every part small.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_high_halves(a: i32, b: i32) -> i32 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    // A signed half times an unsigned one is below 2³¹ in magnitude.
    let (m1, m2) = (ah * bl, al * bh);
    let low = (al as u32) * (bl as u32);
    let below = (m1 & 0xFFFF) + (m2 & 0xFFFF) + (low >> 16) as i32;
    ah * bh + (m1 >> 16) + (m2 >> 16) + (below >> 16)
}

/// A right shift by 1 to 31 bits, kept as what applies it cheapest. Where there is a long
/// multiply, the factor 2^(32 − s): the high word of the product is the shift, one
/// `umull`, where a shift by a register takes a mask before it (Rust masks a variable
/// shift's count). Elsewhere (ARMv6-M, where a long multiply is four) the count, as a
/// `ShiftCount`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct RightShift(
    #[cfg(tinyfractal_no_long_multiply)] ShiftCount,
    #[cfg(not(tinyfractal_no_long_multiply))] u32,
);

impl RightShift {
    /// A shift by `bits`, or `None` beyond 1 to 31.
    pub(crate) const fn new(bits: u32) -> Option<Self> {
        if bits == 0 || bits > 31 {
            return None;
        }
        #[cfg(tinyfractal_no_long_multiply)]
        {
            match ShiftCount::new(bits) {
                Some(count) => Some(Self(count)),
                None => None,
            }
        }
        #[cfg(not(tinyfractal_no_long_multiply))]
        {
            Some(Self(1 << (32 - bits)))
        }
    }

    /// `v >> bits`.
    #[inline(always)]
    pub(crate) fn apply(self, v: u32) -> u32 {
        #[cfg(tinyfractal_no_long_multiply)]
        {
            self.0.shift(v)
        }
        #[cfg(not(tinyfractal_no_long_multiply))]
        {
            (mul_u32_wide(v, self.0) >> 32) as u32
        }
    }
}

/// Defines `ShiftCount` with a variant for each count, and `ShiftCount::new`, which
/// turns a count into its variant.
macro_rules! shift_counts {
    ($($name:ident = $count:literal),+ $(,)?) => {
        /// A shift's count from 1 to 31 as a type whose every value the compiler knows is
        /// below 32, so that `v >> count` needs neither the mask Rust puts before a
        /// variable shift nor the test `unbounded_shr` puts there: one `lsrs` on ARMv6-M.
        #[cfg(any(test, tinyfractal_no_long_multiply))]
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        // A word, not a byte: ARMv6-M loads a word from the stack in one instruction.
        #[repr(u32)]
        pub(crate) enum ShiftCount {
            $(
                #[doc = concat!("A shift by ", stringify!($count), ".")]
                $name = $count,
            )+
        }

        #[cfg(any(test, tinyfractal_no_long_multiply))]
        impl ShiftCount {
            /// The count `bits`, or `None` beyond 1 to 31.
            pub(crate) const fn new(bits: u32) -> Option<Self> {
                match bits {
                    $($count => Some(Self::$name),)+
                    _ => None,
                }
            }
        }
    };
}

shift_counts!(
    By1 = 1,
    By2 = 2,
    By3 = 3,
    By4 = 4,
    By5 = 5,
    By6 = 6,
    By7 = 7,
    By8 = 8,
    By9 = 9,
    By10 = 10,
    By11 = 11,
    By12 = 12,
    By13 = 13,
    By14 = 14,
    By15 = 15,
    By16 = 16,
    By17 = 17,
    By18 = 18,
    By19 = 19,
    By20 = 20,
    By21 = 21,
    By22 = 22,
    By23 = 23,
    By24 = 24,
    By25 = 25,
    By26 = 26,
    By27 = 27,
    By28 = 28,
    By29 = 29,
    By30 = 30,
    By31 = 31,
);

#[cfg(any(test, tinyfractal_no_long_multiply))]
impl ShiftCount {
    /// `v >> count`.
    #[inline(always)]
    pub(crate) fn shift(self, v: u32) -> u32 {
        v >> (self as u32)
    }
}

/// The exact square of an i32, from its magnitude (`umull`, or 16-bit halves). Where a
/// loop also multiplies the signed value, a square of the signed value would share its
/// sign extension with those products, which LLVM may then carry as a 64-bit value and
/// multiply 64 × 64 (docs/performance.md, Fractint's modes and distance estimation).
#[inline(always)]
pub(crate) fn square_i32_wide(v: i32) -> i64 {
    mul_u32_wide(v.unsigned_abs(), v.unsigned_abs()) as i64
}

/// The exact product of two i32 (`smull`, or 16-bit halves: see [`mul_u32_wide`]).
#[inline(always)]
pub(crate) fn mul_i32_wide(a: i32, b: i32) -> i64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_i32_halves(a, b)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        i64::from(a) * i64::from(b)
    }
}

/// The exact product of an i32 and a factor within ±2¹⁵ (`smull`, or two 16-bit products
/// where there is no long multiply: `a`'s halves each times `small`, every part within 32
/// bits, with no signs to take off and put back as [`mul_i32_wide`] must).
#[inline(always)]
pub(crate) fn mul_i32_by_small(a: i32, small: i32) -> i64 {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_i32_by_small_halves(a, small)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        i64::from(a) * i64::from(small)
    }
}

/// The exact product of an i64 from −2⁴⁷ to below 2⁴⁷ and a factor below 2¹⁶ (a multiply
/// where there is a long one; elsewhere, ARMv6-M, where it would be a library call, three
/// 32-bit products: `v`'s high word times the factor, below 2³¹ in magnitude, and its low
/// word's 16-bit halves times it).
#[inline(always)]
pub(crate) fn mul_i64_by_small(v: i64, small: u32) -> i64 {
    debug_assert!(matches!(v >> 47, -1 | 0) && small < 1 << 16, "{v} {small}");
    #[cfg(tinyfractal_no_long_multiply)]
    {
        mul_i64_by_small_parts(v, small)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        v * i64::from(small)
    }
}

/// [`mul_i64_by_small`] from `v`'s signed high word and its low word's halves.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_i64_by_small_parts(v: i64, small: u32) -> i64 {
    let (high, low) = ((v >> 32) as i32, v as u32);
    let low_product = u64::from((low & 0xFFFF) * small) + (u64::from((low >> 16) * small) << 16);
    (i64::from(high * small as i32) << 32) + low_product as i64
}

/// [`mul_i32_by_small`] from `a`'s halves: (aₕ·m)·2¹⁶ + aₗ·m, with |aₕ·m| ≤ 2³⁰ and
/// |aₗ·m| < 2³¹ for |m| ≤ 2¹⁵.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_i32_by_small_halves(a: i32, small: i32) -> i64 {
    let (high, low) = (a >> 16, a & 0xFFFF);
    (i64::from(high * small) << 16) + i64::from(low * small)
}

/// The exact product of two i32 from 16-bit halves of their magnitudes.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn mul_i32_halves(a: i32, b: i32) -> i64 {
    // |a·b| ≤ 2^62: the magnitude fits in an i64.
    let magnitude = mul_u32_halves(a.unsigned_abs(), b.unsigned_abs()) as i64;
    if (a ^ b) < 0 {
        -magnitude
    } else {
        magnitude
    }
}

/// The complex product z·m taken down `SHIFT` bits (16 to 32), each part rounded down:
/// (⌊(z₀m₀ − z₁m₁) / 2^SHIFT⌋, ⌊(z₀m₁ + z₁m₀) / 2^SHIFT⌋), for parts within
/// [`COMPLEX_PART`] and results within 32 bits. Where there is a long multiply, four
/// 64-bit products; elsewhere (ARMv6-M, where each would be a signed product from halves)
/// [`complex_mul_down_halves`].
#[inline(always)]
pub(crate) fn complex_mul_down<const SHIFT: u32>(z: (i32, i32), m: (i32, i32)) -> (i32, i32) {
    debug_assert!(
        [z.0, z.1, m.0, m.1]
            .iter()
            .all(|v| v.unsigned_abs() <= COMPLEX_PART as u32),
        "a part beyond 2²⁹ + 2¹⁵: {z:?} {m:?}"
    );
    #[cfg(tinyfractal_no_long_multiply)]
    {
        complex_mul_down_halves::<SHIFT>(z, m)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        let product = |a: i32, b: i32| i64::from(a) * i64::from(b);
        (
            ((product(z.0, m.0) - product(z.1, m.1)) >> SHIFT) as i32,
            ((product(z.0, m.1) + product(z.1, m.0)) >> SHIFT) as i32,
        )
    }
}

/// The largest part [`complex_mul_down`] takes: 2²⁹ + 2¹⁵.
pub(crate) const COMPLEX_PART: i32 = (1 << 29) + (1 << 15);

/// [`complex_mul_down`] from 16-bit halves with signed low parts, v = h·2¹⁶ + l with
/// |l| ≤ 2¹⁵ and |h| ≤ 2¹³ + 1: a sum of products a·b is H·2³² + M·2¹⁶ + L, and its
/// value taken down `SHIFT` bits is H·2^(32 − SHIFT) + ⌊(M + ⌊L/2¹⁶⌋) / 2^(SHIFT − 16)⌋.
/// Every part fits 32 bits: the high products' sums within 2²⁷, the middle ones' (four
/// products below 2²⁸·1.0002) within 2³⁰, and the low ones' within ±2³¹, which a
/// difference keeps and a sum (up to 2³¹ itself) is taken unsigned, lifted by 2³¹ − 2¹⁶.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn complex_mul_down_halves<const SHIFT: u32>(
    z: (i32, i32),
    m: (i32, i32),
) -> (i32, i32) {
    let ((zh0, zl0), (zh1, zl1)) = (signed_halves(z.0), signed_halves(z.1));
    let ((mh0, ml0), (mh1, ml1)) = (signed_halves(m.0), signed_halves(m.1));
    let down = |high: i32, middle: i32, low_down: i32| {
        (high << (32 - SHIFT)) + ((middle + low_down) >> (SHIFT - 16))
    };
    let real = down(
        zh0 * mh0 - zh1 * mh1,
        zh0 * ml0 + zl0 * mh0 - zh1 * ml1 - zl1 * mh1,
        (zl0 * ml0 - zl1 * ml1) >> 16,
    );
    // The low products' sum, from −2³¹ + 2¹⁶ to 2³¹, lifted into u32.
    const LIFT: u32 = (1 << 31) - (1 << 16);
    let lifted = ((zl0 * ml1) as u32)
        .wrapping_add((zl1 * ml0) as u32)
        .wrapping_add(LIFT);
    let imaginary = down(
        zh0 * mh1 + zh1 * mh0,
        zh0 * ml1 + zl0 * mh1 + zh1 * ml0 + zl1 * mh0,
        (lifted >> 16) as i32 - (LIFT >> 16) as i32,
    );
    (real, imaginary)
}

/// 2ab as (a + b)² − a² − b², given the squares, with (a + b)² from 16-bit halves: where
/// there is no long multiply (ARMv6-M) a square needs neither signs nor a fourth 16×16
/// product, so this costs about half a signed product. `a + b` must fit in an i32.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
pub(crate) fn twice_product_by_squares(a: i32, b: i32, a_squared: i64, b_squared: i64) -> i64 {
    let sum = (a + b).unsigned_abs();
    // (a + b)² ≤ 2^62 for a sum within i32. The compiler shares the two equal cross
    // products of a square: three 16×16 multiplies.
    let sum_squared = mul_u32_halves(sum, sum) as i64;
    sum_squared - a_squared - b_squared
}

/// The exact product of two i64 as i128, from four 32×32→64 products: an i128 multiply is
/// a library call on Cortex-M, and these are single instructions on M3/M4.
pub(crate) fn mul_wide(a: i64, b: i64) -> i128 {
    mul_wide_in_line(a, b)
}

/// [`mul_wide`] in line, for the `Deep` tier's orbit: a call there, with both of a tile's
/// ways of computing a cell compiled (see `TierOrbit`), costs far more.
#[inline(always)]
pub(crate) fn mul_wide_in_line(a: i64, b: i64) -> i128 {
    // On 64-bit hosts the native product is the same exact value, in one or two
    // instructions.
    #[cfg(target_pointer_width = "64")]
    {
        i128::from(a) * i128::from(b)
    }
    #[cfg(not(target_pointer_width = "64"))]
    {
        mul_wide_by_halves(a, b)
    }
}

/// [`mul_wide`] from four 32×32→64 products.
#[cfg(any(test, not(target_pointer_width = "64")))]
fn mul_wide_by_halves(a: i64, b: i64) -> i128 {
    let negative = (a < 0) != (b < 0);
    let (a, b) = (a.unsigned_abs(), b.unsigned_abs());
    let (a_low, a_high) = (a as u32, (a >> 32) as u32);
    let (b_low, b_high) = (b as u32, (b >> 32) as u32);
    let middle = u128::from(mul_u32_wide(a_low, b_high)) + u128::from(mul_u32_wide(a_high, b_low));
    let magnitude = (u128::from(mul_u32_wide(a_high, b_high)) << 64)
        + (middle << 32)
        + u128::from(mul_u32_wide(a_low, b_low));
    // |a·b| < 2^126: the magnitude fits in i128.
    let magnitude = magnitude as i128;
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// ⌊a·b / 2¹²⁸⌋, the high half of the exact 256-bit product, for the `Wide` tier: four
/// 64×64→128 products of the magnitudes, then the floor for a negative product (so the
/// tier rounds down, as the others do). |a|, |b| must be below 2¹²⁷. A call on Cortex-M,
/// where its 128-bit products are library calls themselves: in line, each of the orbit's
/// copies took kilobytes of flash.
#[cfg_attr(target_arch = "arm", inline(never))]
pub(crate) fn mul_high_i128(a: i128, b: i128) -> i128 {
    let negative = (a < 0) != (b < 0);
    let (a, b) = (a.unsigned_abs(), b.unsigned_abs());
    let low_half = |v: u128| u128::from(v as u64);
    let (a_low, a_high) = (low_half(a), a >> 64);
    let (b_low, b_high) = (low_half(b), b >> 64);
    let low = a_low * b_low;
    let (cross_1, cross_2) = (a_low * b_high, a_high * b_low);
    // Below 3·2⁶⁴: the carry into the high half.
    let middle = low_half(cross_1) + low_half(cross_2) + (low >> 64);
    // Below 2¹²⁶ + 3·2⁶⁴ for magnitudes below 2¹²⁷: it fits an i128.
    let high = a_high * b_high + (cross_1 >> 64) + (cross_2 >> 64) + (middle >> 64);
    let inexact = (middle as u64 | low as u64) != 0;
    let high = high as i128;
    if negative {
        -high - i128::from(inexact)
    } else {
        high
    }
}

/// `value / 2^shift` rounded half away from zero (so negation commutes), for one width.
macro_rules! shift_round_in {
    ($(#[$doc:meta])* $name:ident, $t:ty) => {
        $(#[$doc])*
        pub(crate) const fn $name(value: $t, shift: u32) -> $t {
            let half: $t = 1 << (shift - 1);
            if value >= 0 {
                (value + half) >> shift
            } else {
                -((-value + half) >> shift)
            }
        }
    };
}

shift_round_in!(
    /// `value / 2^shift`, rounded half away from zero.
    shift_round,
    i128
);
shift_round_in!(
    /// [`shift_round`] in 64 bits, for per-pixel work on 32-bit cores (a 128-bit shift costs
    /// a dozen instructions there). `|value| + 2^(shift-1)` must fit in an i64.
    shift_round_i64,
    i64
);

/// `numerator / denominator` rounded half away from zero; the denominator must not be 0.
pub(crate) const fn div_round(numerator: i128, denominator: i128) -> i128 {
    let negative = (numerator < 0) != (denominator < 0);
    let n = numerator.unsigned_abs();
    let d = denominator.unsigned_abs();
    let q = (n + d / 2) / d;
    if negative {
        -(q as i128)
    } else {
        q as i128
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The halves' dot product's and product's high words are the exact ones (i128, i64),
    /// for values of every size and sign, the extremes included.
    #[test]
    fn dot_products_from_halves_are_exact() {
        use proptest::prelude::*;
        let exact = |a: i32, x: i32, b: i32, y: i32| {
            ((i128::from(a) * i128::from(x) + i128::from(b) * i128::from(y)) >> 32) as i32
        };
        let value = (any::<i32>(), 0u32..32).prop_map(|(v, s)| v >> s);
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(
                &(value.clone(), value.clone(), value.clone(), value),
                |(a, x, b, y)| {
                    prop_assert_eq!(dot_high_halves(a, x, b, y), exact(a, x, b, y));
                    let high = ((i64::from(a) * i64::from(x)) >> 32) as i32;
                    prop_assert_eq!(mul_high_halves(a, x), high);
                    prop_assert_eq!(mul_high(a, x), high);
                    prop_assert_eq!(dot_high(a, x, b, y), exact(a, x, b, y));
                    Ok(())
                },
            )
            .unwrap();
        let edges = [i32::MIN, i32::MIN + 1, -1, 0, 1, 0xFFFF, 0x1_0000, i32::MAX];
        for a in edges {
            for x in edges {
                let high = ((i64::from(a) * i64::from(x)) >> 32) as i32;
                assert_eq!(mul_high_halves(a, x), high, "{a} {x}");
                for (b, y) in [(a, x), (x, a), (i32::MAX, i32::MIN), (0, 0)] {
                    assert_eq!(
                        dot_high_halves(a, x, b, y),
                        exact(a, x, b, y),
                        "{a} {x} {b} {y}"
                    );
                }
            }
        }
    }

    /// A right shift applies as `>>`, for every count it takes, and refuses the others.
    #[test]
    fn right_shifts_are_shifts() {
        let values = [0, 1, 0x8000_0000, u32::MAX, 0x1234_5678, 0xFFFF];
        for bits in 1..32 {
            let shift = RightShift::new(bits).expect("1 to 31");
            for v in values {
                assert_eq!(shift.apply(v), v >> bits, "{v} {bits}");
            }
        }
        assert_eq!(RightShift::new(0), None);
        assert_eq!(RightShift::new(32), None);
    }

    /// ARMv6-M's shift count is the count it was made from, shifts as `>>`, and refuses
    /// 0 and counts from 32.
    #[test]
    fn shift_counts_are_their_counts() {
        let values = [0, 1, 0x8000_0000, u32::MAX, 0x1234_5678, 0xFFFF];
        for bits in 1..32 {
            let count = ShiftCount::new(bits).expect("1 to 31");
            assert_eq!(count as u32, bits);
            for v in values {
                assert_eq!(count.shift(v), v >> bits, "{v} {bits}");
            }
        }
        for bits in [0, 32, 33, 255, u32::MAX] {
            assert_eq!(ShiftCount::new(bits), None);
        }
    }

    /// The complex product from halves is the one from 64-bit products, taken down 29 and
    /// 30 bits (the loose derivative's steps), for parts of every size and sign within
    /// [`COMPLEX_PART`], their ends and the low halves' end (−2¹⁵) included; with overflow
    /// checks on, a partial sum past 32 bits fails it too.
    #[test]
    fn complex_products_from_halves_are_exact() {
        use proptest::prelude::*;
        let exact = |z: (i32, i32), m: (i32, i32), shift: u32| {
            let p = |a: i32, b: i32| i128::from(a) * i128::from(b);
            (
                i32::try_from((p(z.0, m.0) - p(z.1, m.1)) >> shift).unwrap(),
                i32::try_from((p(z.0, m.1) + p(z.1, m.0)) >> shift).unwrap(),
            )
        };
        let check = |z: (i32, i32), m: (i32, i32)| {
            assert_eq!(
                complex_mul_down_halves::<29>(z, m),
                exact(z, m, 29),
                "{z:?} {m:?}"
            );
            assert_eq!(
                complex_mul_down_halves::<30>(z, m),
                exact(z, m, 30),
                "{z:?} {m:?}"
            );
            assert_eq!(complex_mul_down::<29>(z, m), exact(z, m, 29), "{z:?} {m:?}");
        };
        let part = prop_oneof![
            -COMPLEX_PART..=COMPLEX_PART,
            (any::<i32>(), 3u32..32).prop_map(|(v, s)| v >> s),
            // Low halves at −2¹⁵, where the low products reach 2³⁰.
            (-(1i32 << 13)..=1 << 13).prop_map(|h| (h << 16) | 0x8000),
        ];
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(
                &((part.clone(), part.clone()), (part.clone(), part)),
                |(z, m)| {
                    check(z, m);
                    Ok(())
                },
            )
            .unwrap();
        let ends = [
            COMPLEX_PART,
            -COMPLEX_PART,
            (1 << 29) | 0x8000,
            -(1 << 29) | 0x8000,
            0x8000_u32 as i32 | -(1 << 16),
            1 << 29,
            -(1 << 29),
            0,
            -1,
            0x7FFF,
            -0x8000,
        ];
        for z0 in ends {
            for z1 in ends {
                for m0 in ends {
                    for m1 in ends {
                        check((z0, z1), (m0, m1));
                    }
                }
            }
        }
    }

    #[test]
    fn products_from_halves_are_exact() {
        let edges = [
            0,
            1,
            2,
            0xFFFF,
            0x1_0000,
            0x1_0001,
            0x7FFF_FFFF,
            0x8000_0000,
            u32::MAX,
        ];
        let mut state = 0x2545_F491_u32;
        let mut values = edges.to_vec();
        for _ in 0..2000 {
            // xorshift32: a spread of bit patterns, reproducible.
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            values.push(state);
        }
        for &a in &values {
            for &b in values.iter().step_by(37).chain(&edges) {
                assert_eq!(mul_u32_halves(a, b), u64::from(a) * u64::from(b), "{a} {b}");
                let (a, b) = (a as i32, b as i32);
                assert_eq!(mul_i32_halves(a, b), i64::from(a) * i64::from(b), "{a} {b}");
                // A factor within ±0.99·2³¹ (its ends too) beside any other.
                let near = (b as i64 * 99 / 100) as i32;
                for s in [
                    near,
                    -near,
                    (0.99 * 2f64.powi(31)) as i32,
                    -(0.99 * 2f64.powi(31)) as i32,
                ] {
                    let exact = ((i64::from(a) * i64::from(s)) >> 32) as i32;
                    assert_eq!(mul_high_near(a, s), exact, "{a} {s}");
                }
                // The small factor at its ends, ±2¹⁵, and within them.
                for small in [b >> 16, b >> 17, 1 << 15, -(1 << 15), 0, 1, -1] {
                    let exact = i64::from(a) * i64::from(small);
                    assert_eq!(mul_i32_by_small_halves(a, small), exact, "{a} {small}");
                    assert_eq!(mul_i32_by_small(a, small), exact, "{a} {small}");
                }
                // An i64 from −2⁴⁷ to below 2⁴⁷ (its ends too) times a factor below 2¹⁶.
                let wide = (i64::from(a) << 16) | i64::from(b as u32 >> 16);
                for v in [wide, wide / 2, -(wide / 2), (1 << 47) - 1, -(1 << 47), 0] {
                    for small in [b as u32 >> 16, (1 << 16) - 1, 0, 1, 255] {
                        let exact = v * i64::from(small);
                        assert_eq!(mul_i64_by_small_parts(v, small), exact, "{v} {small}");
                        assert_eq!(mul_i64_by_small(v, small), exact, "{v} {small}");
                    }
                }
                // The sum must fit in an i32: halve both.
                let (a, b) = (a / 2, b / 2);
                let (a2, b2) = (i64::from(a) * i64::from(a), i64::from(b) * i64::from(b));
                assert_eq!(
                    twice_product_by_squares(a, b, a2, b2),
                    2 * i64::from(a) * i64::from(b),
                    "{a} {b}"
                );
            }
        }
    }

    /// The 256-bit high half against schoolbook multiplication in 32-bit limbs of the
    /// two's complement values, at edges and a spread of patterns, both signs.
    #[test]
    fn high_halves_of_256_bit_products_are_floors() {
        extern crate std;
        // a·b mod 2²⁵⁶ from the two's complement limbs, then its high 128 bits: the floor.
        fn model(a: i128, b: i128) -> i128 {
            let limbs = |v: i128| {
                let fill = if v < 0 { u32::MAX } else { 0 };
                let mut out = [fill; 8];
                for (k, limb) in out.iter_mut().take(4).enumerate() {
                    *limb = (v >> (32 * k)) as u32;
                }
                out
            };
            let (a, b) = (limbs(a), limbs(b));
            let mut product = [0u64; 9];
            for i in 0..8 {
                let mut carry = 0u64;
                for j in 0..8 - i {
                    let t = product[i + j] + u64::from(a[i]) * u64::from(b[j]) + carry;
                    product[i + j] = t & 0xFFFF_FFFF;
                    carry = t >> 32;
                }
            }
            (4..8)
                .rev()
                .fold(0i128, |high, k| (high << 32) | product[k] as i128)
        }
        let mut values: std::vec::Vec<i128> = std::vec![
            0,
            1,
            -1,
            2,
            -2,
            1 << 64,
            -(1 << 64),
            (1 << 64) - 1,
            i128::MAX,
            -i128::MAX,
            1 << 126,
            -(1 << 126),
            7 << 124
        ];
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        for _ in 0..300 {
            // xorshift64, two draws a value, with its width varied.
            let mut next = || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state
            };
            let v = (i128::from(next()) << 64 | i128::from(next())) >> (1 + next() % 100);
            values.push(v);
        }
        for &a in &values {
            for &b in values.iter().step_by(7) {
                assert_eq!(mul_high_i128(a, b), model(a, b), "{a} × {b}");
            }
        }
    }

    #[test]
    fn wide_products_are_exact() {
        let values = [
            0i64,
            1,
            -1,
            i64::MAX,
            i64::MIN + 1,
            1 << 40,
            -(1 << 33) + 5,
            0x7FFF_FFFF,
            -0x8000_0001,
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(
                    mul_wide_by_halves(a, b),
                    i128::from(a) * i128::from(b),
                    "{a} × {b}"
                );
            }
        }
    }
}
