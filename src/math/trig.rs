//! Sines and cosines in Q30 (2³⁰ = 1.0), computed with integer maths only.
//!
//! [`sin_cos`] evaluates a Taylor series in Q62 on the first octant and unfolds it by
//! symmetry, so headings that mirror each other get exactly mirrored values (a snowflake
//! closes bit-exactly). It is a `const fn`: the quarter-wave table for free angles is built
//! at compile time, and the table for `Angle n` once at set-up; nothing is computed per step.

/// 1.0 in Q30.
pub(crate) const ONE_Q30: i32 = 1 << 30;

/// π/4 in Q62.
const FRAC_PI_4_Q62: i128 = 3_622_009_729_038_561_421;

/// Cosine and sine of `numerator / denominator` of a full turn, in Q30, rounded to nearest.
/// `denominator` must be positive. In 64 bits: 128-bit divisions are library calls on
/// Cortex-M, four of them a heading.
pub(crate) const fn sin_cos(numerator: u32, denominator: u32) -> (i32, i32) {
    let d = denominator as u64;
    let eighths = (numerator as u64 % d) * 8;
    let octant = eighths / d;
    let rest = eighths % d;
    // The angle from the nearest multiple of π/2, in [0, π/4], as Q62 radians:
    // ⌊π/4 · w / d⌋ = q·w + ⌊r·w / d⌋ for π/4 = q·d + r (r·w < d² and q·w ≤ π/4 fit 64 bits).
    let within = if octant & 1 == 0 { rest } else { d - rest };
    // 30° and 45° from an axis (the headings of Angle 6, 8, 12, ...) are the constants the
    // series sums to there (tested): no series.
    let (c, s) = if 3 * within == 2 * d {
        (COS_30_Q30, 1 << 29)
    } else if within == d {
        (SQRT_HALF_Q30, SQRT_HALF_Q30)
    } else {
        let (q, r) = (FRAC_PI_4_Q62 as u64 / d, FRAC_PI_4_Q62 as u64 % d);
        octant_cos_sin((q * within + r * within / d) as i128)
    };
    match octant {
        0 => (c, s),
        1 => (s, c),
        2 => (-s, c),
        3 => (-c, s),
        4 => (-c, -s),
        5 => (-s, -c),
        6 => (s, -c),
        _ => (c, -s),
    }
}

/// cos 30° = √3/2 in Q30, rounded to nearest (929,887,696.69...).
const COS_30_Q30: i32 = 929_887_697;

/// √2/2 in Q30, rounded to nearest (759,250,124.994...).
const SQRT_HALF_Q30: i32 = 759_250_125;

/// Cosine and sine of `x` in [0, π/4] (Q62 radians), rounded to Q30.
const fn octant_cos_sin(x: i128) -> (i32, i32) {
    const ONE_Q62: i128 = 1 << 62;
    let x2 = (x * x) >> 62;
    // sin: x - x³/3! + ...; cos: 1 - x²/2! + ...; 14 terms put the error far below 2⁻³⁰.
    let mut sin = 0;
    let mut cos = 0;
    let mut sin_term = x;
    let mut cos_term = ONE_Q62;
    let mut k: i128 = 1;
    // Once both terms are 0 every later one is: stopping there gives the same sums (the
    // series of a heading 0 stops after one term, at π/4 after about ten of the 14).
    while k <= 14 && (sin_term != 0 || cos_term != 0) {
        sin += sin_term;
        cos += cos_term;
        sin_term = next_term(sin_term, x2, (2 * k) * (2 * k + 1));
        cos_term = next_term(cos_term, x2, (2 * k - 1) * (2 * k));
        k += 1;
    }
    (round_q62_to_q30(cos), round_q62_to_q30(sin))
}

/// The next term of a Taylor series, `-term · x² / divisor` in Q62. Out of line: the
/// compiler unrolls the series, and inlined 128-bit steps would fill Cortex-M flash.
/// |term · x²| >> 62 is below |term| ≤ 2⁶², so the division is an i64 one (the same
/// quotient, truncated toward zero; an i128 division is a slow library call on Cortex-M).
#[inline(never)]
const fn next_term(term: i128, x2: i128, divisor: i128) -> i128 {
    let product = ((term * x2) >> 62) as i64;
    (-product / divisor as i64) as i128
}

const fn round_q62_to_q30(value: i128) -> i32 {
    super::wide::shift_round(value, 32) as i32
}

/// Points per quarter turn in [`QUARTER_SINE`].
const QUARTER_STEPS: usize = 1024;

/// sin(i/1024 · π/2) in Q30 for i = 0..=1024: 4 KiB of flash, built by the compiler.
// Indexing runs at compile time only: an out-of-range index would fail the build, not panic.
#[allow(clippy::indexing_slicing)]
static QUARTER_SINE: [i32; QUARTER_STEPS + 1] = {
    let mut table = [0; QUARTER_STEPS + 1];
    let mut i = 0;
    while i <= QUARTER_STEPS {
        table[i] = sin_cos(i as u32, 4 * QUARTER_STEPS as u32).1;
        i += 1;
    }
    table
};

/// The table's step, π/2048 radians, in Q40.
const TABLE_STEP_Q40: u128 = 1_686_629_713;

/// `value` (Q40) rounded to Q0 of the same scale: `(value + 2³⁹) >> 40`.
fn round_q40(value: i64) -> i64 {
    (value + (1 << 39)) >> 40
}

/// Cosine and sine of `numerator / denominator` of a full turn, in Q30, within 2 units of
/// the last place (tested against f64): the quarter-wave table at the step below, turned
/// the rest of the way (under π/2048) by the angle-sum formulas with a two-term series.
/// Two 128-bit divisions, for angles that arrive at run time (a figure's joints); the
/// exactly rounded [`sin_cos`] costs 28. `denominator` 0 counts as 1.
pub(crate) fn sin_cos_near(numerator: u64, denominator: u64) -> (i32, i32) {
    const STEPS: u128 = 4 * QUARTER_STEPS as u128;
    let d = u128::from(denominator.max(1));
    let scaled = (u128::from(numerator) % d) * STEPS;
    let (step, rest) = (scaled / d, scaled % d);
    // The rest of the angle in Q40 radians, below 2^31; δ³/6 and δ²/2 in Q40.
    let delta = (rest * TABLE_STEP_Q40 / d) as i64;
    let delta2 = (delta * delta) >> 40;
    let sin_delta = delta - ((delta2 * delta) >> 40) / 6;
    let one_minus_cos = delta2 / 2;
    let index = (step % QUARTER_STEPS as u128) as usize;
    let at = |i: usize| i64::from(QUARTER_SINE.get(i).copied().unwrap_or(ONE_Q30));
    let (sin, cos) = (at(index), at(QUARTER_STEPS - index));
    // sin(a + δ) = sin a · cos δ + cos a · sin δ; cos(a + δ) = cos a · cos δ − sin a · sin δ.
    let s = (sin - round_q40(sin * one_minus_cos) + round_q40(cos * sin_delta)) as i32;
    let c = (cos - round_q40(cos * one_minus_cos) - round_q40(sin * sin_delta)) as i32;
    match step / QUARTER_STEPS as u128 {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    }
}

/// A binary angle: the full turn is 2³², so turning wraps for free.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct BinaryAngle(pub(crate) u32);

impl BinaryAngle {
    const QUARTER: u32 = 1 << 30;

    /// From decimal degrees given as Q32 bits (any sign, any size), rounded to nearest
    /// (halves away from zero).
    ///
    /// A degree is 2³²/360 binary units, so the angle is ±⌊(|d| + 180) / 360⌋ for Q32
    /// bits d, taken modulo 2³² (a full turn). ⌊x / 360⌋ = ⌊⌊x / 8⌋ / 45⌋, and the low
    /// 32 bits of a quotient by 45 need only the high word's remainder: three 32-bit
    /// divisions instead of a 64-bit one (a library call on Cortex-M).
    pub(crate) fn from_degrees_bits(degrees_q32: i64) -> Self {
        // |d| + 180 ≤ 2⁶³ + 180: no overflow.
        let eighths = (degrees_q32.unsigned_abs() + 180) >> 3;
        let high = (eighths >> 32) as u32;
        let middle = ((high % 45) << 16) | ((eighths >> 16) as u32 & 0xFFFF);
        let low = ((middle % 45) << 16) | (eighths as u32 & 0xFFFF);
        let turns = ((middle / 45) << 16).wrapping_add(low / 45);
        Self(if degrees_q32 < 0 {
            turns.wrapping_neg()
        } else {
            turns
        })
    }

    /// Cosine and sine in Q30: table lookup with linear interpolation (error < 3·10⁻⁷).
    #[inline]
    pub(crate) fn cos_sin(self) -> (i32, i32) {
        (cos_of_binary(self.0), sin_of_binary(self.0))
    }
}

/// A radian in binary-angle units (2⁻³² of a turn): 2³²/(2π) = 683,565,275.58, rounded.
const TURN_UNITS_PER_RADIAN: i32 = 683_565_276;

/// The binary angle of `radians` (fixed point with `bits` fraction bits, at most 32),
/// wrapped to one turn: a 32×32 product and a shift, so a sine of any argument costs the
/// same. The angle is truncated to 2⁻³² turn (1.5·10⁻⁹ rad) and the constant's rounding
/// adds under 10⁻⁹ of the argument.
#[inline(always)]
pub(crate) fn binary_angle_of_radians(radians: i32, bits: u32) -> u32 {
    // Wrapping to u32 is the reduction modulo one turn.
    (super::wide::mul_i32_wide(radians, TURN_UNITS_PER_RADIAN) >> bits) as u32
}

/// The binary angle of tan θ (as radians) from θ's Q30 sine and cosine, wrapped to one
/// turn: what sin(x + tan θ) needs, exact whatever the size of the tangent (a cosine of 0
/// counts as the smallest positive one).
#[inline(always)]
pub(crate) fn binary_angle_of_tangent(sin_q30: i32, cos_q30: i32) -> u32 {
    let cos = if cos_q30 == 0 { 1 } else { cos_q30 };
    // |sin·K| < 2⁶⁰: the quotient fits; wrapping to u32 reduces it modulo a turn.
    (super::wide::mul_i32_wide(sin_q30, TURN_UNITS_PER_RADIAN) / i64::from(cos)) as u32
}

/// atan(2⁻ⁱ) in binary-angle units (2⁻³² of a turn), rounded: CORDIC's rotations.
const CORDIC_ANGLES: [u32; 31] = [
    536_870_912,
    316_933_406,
    167_458_907,
    85_004_756,
    42_667_331,
    21_354_465,
    10_679_838,
    5_340_245,
    2_670_163,
    1_335_087,
    667_544,
    333_772,
    166_886,
    83_443,
    41_722,
    20_861,
    10_430,
    5_215,
    2_608,
    1_304,
    652,
    326,
    163,
    81,
    41,
    20,
    10,
    5,
    3,
    1,
    1,
];

/// The direction of the point (`x`, `y`) as a binary angle (2⁻³² of a turn, counter-clockwise
/// from the positive x axis; atan2 wrapped to one turn): CORDIC in integers, so every core
/// finds the same angle. The point is first scaled to 2⁴⁰ so small ones keep their bits;
/// the 31 rotations leave an error of at most a few dozen units (10⁻⁸ rad). (0, 0) is 0.
pub(crate) fn binary_angle_of_point(x: i32, y: i32) -> u32 {
    let (mut x, mut y) = (i64::from(x), i64::from(y));
    let mut angle = 0u32;
    if x < 0 {
        // A half turn brings it to the right half-plane, where the rotations converge.
        (x, y, angle) = (-x, -y, 1 << 31);
    }
    let magnitude = x.unsigned_abs() | y.unsigned_abs();
    if magnitude == 0 {
        return 0;
    }
    // |x|, |y| ≤ 2³¹; at 2⁴⁰ the gain of 1.65 keeps every sum far below 2⁶³.
    let top = 63 - magnitude.leading_zeros();
    if top < 40 {
        (x, y) = (x << (40 - top), y << (40 - top));
    }
    for (shift, &step) in CORDIC_ANGLES.iter().enumerate() {
        let (dx, dy) = (y >> shift, x >> shift);
        if y > 0 {
            (x, y, angle) = (x + dx, y - dy, angle.wrapping_add(step));
        } else {
            (x, y, angle) = (x - dx, y + dy, angle.wrapping_sub(step));
        }
    }
    angle
}

/// The sine of a binary angle in Q30: the quarter-wave table, linearly interpolated
/// (error < 3·10⁻⁷).
#[inline(always)]
pub(crate) fn sin_of_binary(angle: u32) -> i32 {
    let within = angle & (BinaryAngle::QUARTER - 1);
    let magnitude = match (angle >> 30) & 1 {
        0 => quarter_sine(within),
        _ => quarter_sine(BinaryAngle::QUARTER - within),
    };
    if angle >> 31 == 0 {
        magnitude
    } else {
        -magnitude
    }
}

/// The cosine of a binary angle in Q30 (the sine a quarter turn on).
#[inline(always)]
pub(crate) fn cos_of_binary(angle: u32) -> i32 {
    sin_of_binary(angle.wrapping_add(BinaryAngle::QUARTER))
}

/// sin of `position / 2³⁰` of a quarter turn, `position` in 0..=2³⁰.
#[inline]
fn quarter_sine(position: u32) -> i32 {
    const FRACTION_BITS: u32 = 20; // 2^30 / QUARTER_STEPS = 2^20 positions between points
    let index = (position >> FRACTION_BITS) as usize;
    let fraction = (position & ((1 << FRACTION_BITS) - 1)) as i32;
    let low = QUARTER_SINE.get(index).copied().unwrap_or(ONE_Q30);
    let high = QUARTER_SINE.get(index + 1).copied().unwrap_or(ONE_Q30);
    // A table step (below 2²¹) times a fraction (below 2²⁰): 64 bits hold it and its
    // rounding, because a 128-bit shift is several words' work on a 32-bit core and the
    // 64-bit product a library call on ARMv6-M (docs/performance.md).
    let delta = super::wide::mul_i32_wide(high - low, fraction);
    low + super::wide::shift_round_i64(delta, FRACTION_BITS) as i32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Degrees become binary angles as their definition in 128 bits has it: d·2³²/360
    /// (d in Q32 bits) rounded half away from zero, modulo 2³²; random values of every
    /// size, and the halves and their neighbours, where rounding decides.
    #[test]
    fn degrees_are_rounded_binary_angles() {
        use proptest::prelude::*;
        let by_definition = |d: i64| {
            let (n, half) = (i128::from(d).unsigned_abs(), 180u128);
            let q = ((n + half) / 360) as u32;
            if d < 0 {
                q.wrapping_neg()
            } else {
                q
            }
        };
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let degrees = (any::<i64>(), 0u32..64).prop_map(|(v, s)| v >> s);
        runner
            .run(&degrees, |d| {
                prop_assert_eq!(BinaryAngle::from_degrees_bits(d).0, by_definition(d));
                Ok(())
            })
            .unwrap();
        let halves = (any::<i64>(), 2u32..64).prop_map(|(v, s)| (v >> s) / 360 * 360 + 180);
        runner
            .run(&halves, |h| {
                for d in [h - 1, h, h + 1, -h - 1, -h, -h + 1] {
                    prop_assert_eq!(BinaryAngle::from_degrees_bits(d).0, by_definition(d));
                }
                Ok(())
            })
            .unwrap();
        for d in [0, 1, -1, 180, -180, 360, i64::MAX, i64::MIN, i64::MIN + 1] {
            assert_eq!(BinaryAngle::from_degrees_bits(d).0, by_definition(d), "{d}");
        }
        assert_eq!(BinaryAngle::from_degrees_bits(90 << 32).0, 1 << 30);
    }

    fn q30(v: f64) -> f64 {
        v * f64::from(ONE_Q30)
    }

    /// Rounded to nearest, as documented: within half a unit of f64's value (and its
    /// own error, far below 10⁻⁶ of a unit), for every heading of up to 360 divisions.
    #[test]
    fn exact_divisions_are_rounded_to_nearest() {
        for n in 1..=360u32 {
            for k in 0..n {
                let (c, s) = sin_cos(k, n);
                let angle = core::f64::consts::TAU * k as f64 / n as f64;
                for (got, want) in [(c, angle.cos()), (s, angle.sin())] {
                    assert!(
                        (f64::from(got) - q30(want)).abs() <= 0.5 + 1e-6,
                        "{k}/{n}: {got} for {}",
                        q30(want)
                    );
                }
            }
        }
        // cos 60° and sin 30° are exactly ½.
        assert_eq!(sin_cos(1, 6), (1 << 29, sin_cos(1, 6).1));
        assert_eq!(sin_cos(1, 12).1, 1 << 29);
    }

    /// The constants `sin_cos` uses at 30° and 45° from an axis are what the series sums to
    /// there.
    #[test]
    fn special_angles_are_the_series_sums() {
        let x = |w: i128, d: i128| FRAC_PI_4_Q62 * w / d;
        assert_eq!(octant_cos_sin(x(2, 3)), (COS_30_Q30, 1 << 29));
        assert_eq!(octant_cos_sin(x(1, 1)), (SQRT_HALF_Q30, SQRT_HALF_Q30));
    }

    /// Headings a half turn apart from each other's mirror (θ and π - θ) have the same sine
    /// and opposite cosines, exactly: `Headings` computes one from the other.
    #[test]
    fn supplementary_headings_are_exact_mirrors() {
        for n in (2..=64u32).step_by(2) {
            for k in 0..=n / 2 {
                let (c, s) = sin_cos(k, n);
                assert_eq!(sin_cos(n / 2 - k, n), (-c, s), "{k}/{n}");
            }
        }
    }

    #[test]
    fn mirrored_headings_are_exact_negatives() {
        for n in [3u32, 5, 6, 7, 10, 12, 34, 49] {
            for k in 0..n {
                let (c, s) = sin_cos(k, n);
                let (c2, s2) = sin_cos(n - k, n);
                assert_eq!((c, -s), (c2, s2));
            }
        }
    }

    #[test]
    fn near_sines_are_within_two_units() {
        let mut worst = 0.0f64;
        let check = |k: u64, n: u64, worst: &mut f64| {
            let (c, s) = sin_cos_near(k, n);
            let angle = core::f64::consts::TAU * (k % n) as f64 / n as f64;
            for (got, want) in [(c, angle.cos()), (s, angle.sin())] {
                *worst = worst.max((f64::from(got) - q30(want)).abs());
            }
        };
        for n in 1..=64u64 {
            for k in 0..n {
                check(k, n, &mut worst);
            }
        }
        // Degrees as Q32 fractions of 360 << 32, over the whole turn.
        let turn = 360u64 << 32;
        let mut k = 0x1234_5678_9ABCu64;
        for _ in 0..20_000 {
            k = k
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            check(k % turn, turn, &mut worst);
        }
        assert!(worst <= 2.0, "{worst} units of 2^-30");
    }

    #[test]
    fn binary_angles_interpolate_closely() {
        for degrees in [
            0.0f64, 1.0, 22.5, 25.7, 45.0, 89.99, 90.0, 137.5, 196.5, 270.0, 359.9,
        ] {
            let bits = (degrees * 4_294_967_296.0) as i64;
            let (c, s) = BinaryAngle::from_degrees_bits(bits).cos_sin();
            let r = degrees.to_radians();
            assert!((f64::from(c) - q30(r.cos())).abs() < 400.0, "cos {degrees}");
            assert!((f64::from(s) - q30(r.sin())).abs() < 400.0, "sin {degrees}");
        }
    }

    /// CORDIC's angle against f64's atan2 over points of every size and quadrant.
    #[test]
    fn point_angles_follow_atan2() {
        let mut worst: f64 = 0.0;
        let mut seed = 12345u32;
        for i in 0..20_000 {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            let scale = 1i64 << (i % 31);
            let x = ((seed as i32) as i64 % scale) as i32;
            let y = (((seed.rotate_left(16)) as i32) as i64 % scale) as i32;
            if x == 0 && y == 0 {
                assert_eq!(binary_angle_of_point(0, 0), 0);
                continue;
            }
            let got =
                binary_angle_of_point(x, y) as i32 as f64 / 2f64.powi(32) * core::f64::consts::TAU;
            let want = f64::from(y).atan2(f64::from(x));
            let mut error = (got - want).abs();
            if error > core::f64::consts::PI {
                error = core::f64::consts::TAU - error;
            }
            worst = worst.max(error);
        }
        assert!(worst < 1e-7, "worst {worst}");
        // The axes and diagonals.
        let turn = |a: u32| f64::from(a) / 2f64.powi(32);
        assert!((turn(binary_angle_of_point(5, 5)) - 0.125).abs() < 1e-8);
        assert!((turn(binary_angle_of_point(0, 7)) - 0.25).abs() < 1e-8);
        assert!((turn(binary_angle_of_point(-7, 0)) - 0.5).abs() < 1e-8);
        assert!((turn(binary_angle_of_point(i32::MIN, i32::MIN)) - 0.625).abs() < 1e-8);
    }
}
