//! The derivative dz an orbit carries for distance estimation, as a mantissa pair and a
//! shared exponent, since it grows as fast as the orbit runs: [`Derivative`], kept
//! normalised, for perturbed pixels and the estimate's logarithm; [`LooseDerivative`],
//! renormalised only when it leaves a window, for the orbits' loops.

use super::scaled::Scaled;
use crate::math::bits::leading_zeros;
use crate::math::log::{log2, LOG2_FRAC_BITS};
use crate::math::wide::{complex_mul_down, mul_i32_wide};

/// A derivative as a mantissa pair in Q30 and a shared exponent: (x + iy)·2^e, the larger
/// mantissa kept in [2²⁹, 2³¹) while e > −30, so each fits 32 bits and a step's products
/// are 32×32 → 64 (one instruction on Cortex-M3 and M4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Derivative {
    x: i32,
    y: i32,
    e: i32,
}

impl Derivative {
    /// dz₀ = 0: the derivative of the Mandelbrot set's z₀ = 0.
    pub(super) const ZERO: Self = Self { x: 0, y: 0, e: -30 };

    /// dz ← 2·z·dz + 1, z = (x + iy)·2^−`s` with mantissas below 2⁶² (a perturbed pixel's
    /// point, of any size): its top 31 bits are taken, so that each product is of two
    /// 32-bit factors.
    pub(super) fn step_scaled(&mut self, z: Scaled) {
        let (zx, zy) = ((z.x >> 31) as i32, (z.y >> 31) as i32);
        // z = (zx + i·zy)·2^(31 − s) and dz = (x + iy)·2^(e − 30): 2·z·dz is the
        // product p·2^(2 − s + e); taken down 30 bits, a mantissa in Q30 at exponent
        // e + 62 − s.
        let mut x = (mul_i32_wide(zx, self.x) - mul_i32_wide(zy, self.y)) >> 30;
        let mut y = (mul_i32_wide(zx, self.y) + mul_i32_wide(zy, self.x)) >> 30;
        let mut e = i64::from(self.e) + 62 - i64::from(z.s);
        if e < -30 {
            // Far below 1: kept at 1's exponent, where 1 has the mantissa's top bits.
            let down = (-30 - e).min(63);
            (x, y) = (x >> down, y >> down);
            e = -30;
        }
        self.e = e.min(i64::from(i32::MAX / 2)) as i32;
        if self.e <= 30 {
            x += 1 << (30 - self.e);
        }
        self.normalise(x, y);
    }

    /// The derivative (x + iy)·2^−`s` (mantissas below 2⁶², as [`Scaled`] keeps them).
    pub(super) fn of_scaled(value: Scaled) -> Self {
        let mut dz = Self {
            x: 0,
            y: 0,
            e: 62 - value.s,
        };
        dz.normalise(value.x >> 32, value.y >> 32);
        dz
    }

    /// The mantissas `x`, `y` (at the current exponent) brought back to [2²⁹, 2³¹).
    #[inline(always)]
    pub(super) fn normalise(&mut self, x: i64, y: i64) {
        // Most steps leave both in 32 bits with the larger in [2²⁹, 2³¹): nothing to do.
        let (x32, y32) = (x as i32, y as i32);
        let larger = x32.unsigned_abs() | y32.unsigned_abs();
        if i64::from(x32) == x
            && i64::from(y32) == y
            && larger.wrapping_sub(1 << 29) < (1 << 31) - (1 << 29)
        {
            (self.x, self.y) = (x32, y32);
            return;
        }
        let top = 63 - (x.unsigned_abs() | y.unsigned_abs() | 1).leading_zeros() as i32;
        let (x, y) = if top > 30 {
            let down = top - 30;
            self.e += down;
            (x >> down, y >> down)
        } else if top < 29 && self.e > -30 {
            let up = (29 - top).min(self.e + 30);
            self.e -= up;
            (x << up, y << up)
        } else {
            (x, y)
        };
        // Below 2³¹ in magnitude either way.
        (self.x, self.y) = (x as i32, y as i32);
    }
}

/// A derivative as the orbits' loops carry it: dz = (x + iy)·2^(e − 28), whose exponent
/// moves by a known amount at each step and whose mantissas are brought back to
/// [2²⁸, 2²⁹) only when the larger leaves [`LOOSE_LOW`, 2²⁹]: a step is then four
/// products, two fixed shifts and one test, where renormalising at every step (as
/// [`Derivative`] does) takes a search for the leading bit of two 64-bit values (what it
/// saves: docs/performance.md, Fractint's modes and distance estimation).
///
/// The larger mantissa (as the "ones' magnitude" `v ^ (v >> 31)`, which is |v| or
/// |v| − 1) stays at most 2²⁹, so |x + iy| ≤ √2·2²⁹; 1 in the mantissas' units, `one` =
/// 2^(28 − e), is at most 2²⁸, the exponent being kept at least 0 where 1 is added (a
/// Julia set's derivative, which adds none, goes down to −30). A step of |z| ≤ 2 scales
/// the pair by at most 1 before adding 1, so every mantissa stays below 2³⁰.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct LooseDerivative {
    x: i32,
    y: i32,
    e: i32,
    /// 1 in the mantissas' units while it is added and e ≤ 28, else 0.
    one: i32,
    /// Whether 1 is added at each step (the Mandelbrot set's dz ← 2·z·dz + 1).
    plus_one: bool,
}

/// The smallest larger mantissa a [`LooseDerivative`] steps on with: 2²² keeps each step's
/// rounding below 2⁻²² of the derivative, so that even long orbits stay well inside the
/// margin Koebe's bounds leave the proofs, and a window of 7 bits is renormalised every
/// few steps (a step of |z| near 1 halves the mantissas; what that costs:
/// docs/performance.md, Fractint's modes and distance estimation).
pub(super) const LOOSE_LOW: u32 = 1 << 22;

/// The largest larger mantissa of a [`LooseDerivative`]: 2²⁹.
const LOOSE_HIGH: u32 = 1 << 29;

/// |v| for v ≥ 0, |v| − 1 below: the magnitude one instruction finds, within 1.
#[inline(always)]
fn ones_magnitude(v: i32) -> u32 {
    (v ^ (v >> 31)) as u32
}

impl LooseDerivative {
    /// Whether 1 is added at each step: the Mandelbrot set's derivative.
    pub(super) const fn adds_one(&self) -> bool {
        self.plus_one
    }

    /// dz = 1, with 1 added at each step if `plus_one`: a Julia set's dz₀ and the
    /// Mandelbrot set's dz₁.
    pub(super) const fn one(plus_one: bool) -> Self {
        Self {
            x: 1 << 28,
            y: 0,
            e: 0,
            one: if plus_one { 1 << 28 } else { 0 },
            plus_one,
        }
    }

    /// `d` carried loosely, with 1 added at each step if `plus_one` (the value the same but
    /// for the mantissas' last two bits, and below 2⁻²⁸ where the lowest exponent cuts it).
    pub(super) fn of(d: Derivative, plus_one: bool) -> Self {
        // (m/4)·2^(e − 28) is m·2^(e − 30): [2²⁷, 2²⁹) where d is normalised.
        let (mut x, mut y, mut e) = (d.x >> 2, d.y >> 2, d.e);
        if plus_one && e < 0 {
            // Kept at exponent 0, where 1 is 2²⁸.
            let down = (-e).min(31) as u32;
            (x, y, e) = (x >> down, y >> down, 0);
        }
        let mut loose = Self {
            x: 0,
            y: 0,
            e,
            one: 0,
            plus_one,
        };
        loose.renormalise(x, y);
        loose
    }

    /// log₂|dz| in Q16, or `None` for dz = 0.
    pub(super) fn log2_magnitude(&self) -> Option<i64> {
        let square = (mul_i32_wide(self.x, self.x) + mul_i32_wide(self.y, self.y)).unsigned_abs();
        let log = i64::from(log2(square, 56)?);
        Some(log / 2 + (i64::from(self.e) << LOG2_FRAC_BITS))
    }

    /// The same derivative, normalised.
    #[cfg(test)]
    fn normalised(self) -> Derivative {
        // m·2^(e − 28) is m·2^((e + 2) − 30).
        let mut d = Derivative {
            x: 0,
            y: 0,
            e: self.e.saturating_add(2),
        };
        d.normalise(i64::from(self.x), i64::from(self.y));
        d
    }

    /// dz ← 2·z·dz (+ 1), z in Q28 with |z| ≤ 2 (within a unit of it): the product taken
    /// down 29 bits, so the exponent moves by 2 and 1 by a quarter.
    #[inline(always)]
    pub(super) fn step_q28(&mut self, zx: i32, zy: i32) {
        // 2·z·dz = (zq·m / 2²⁹)·2^(e + 2 − 28) for zq = z·2²⁸.
        let (x, y) = complex_mul_down::<29>((zx, zy), (self.x, self.y));
        self.e += 2;
        self.one >>= 2;
        self.settle(x + self.one, y);
    }

    /// dz ← 2·z·dz (+ 1), z in Q20 with |re|, |im| < 2²⁸ (past the escape, |z| < 256):
    /// z taken with its larger part's leading bit at 28, so the product is taken down a
    /// fixed 30 bits and the exponent moves by z's size.
    #[inline(always)]
    pub(super) fn step_q20(&mut self, zx: i32, zy: i32) {
        // The larger part's leading zeros, at most 14 (a z below 2⁻² is taken as it is).
        let zeros = leading_zeros(ones_magnitude(zx) | ones_magnitude(zy)).min(14);
        // Both parts within 2²⁹ after the shift (at least 1, as the parts are below 2²⁸).
        let up = zeros - 3;
        let (zx, zy) = (zx << up, zy << up);
        // 2·z·dz = (zs·m / 2³⁰)·2^(e + 14 − zeros − 28) for zs = z·2^(20 + up).
        let (x, y) = complex_mul_down::<30>((zx, zy), (self.x, self.y));
        let moved = 14 - zeros;
        self.e += moved as i32;
        self.one >>= moved;
        self.settle(x + self.one, y);
    }

    /// Keeps the stepped mantissas `x`, `y` if the larger is within the window, else
    /// renormalises them.
    #[inline(always)]
    fn settle(&mut self, x: i32, y: i32) {
        let larger = ones_magnitude(x) | ones_magnitude(y);
        if larger.wrapping_sub(LOOSE_LOW) <= LOOSE_HIGH - LOOSE_LOW {
            (self.x, self.y) = (x, y);
        } else {
            self.renormalise(x, y);
        }
    }

    /// The mantissas `x`, `y` (below 2³¹, at the current exponent) with the larger's
    /// ones' magnitude brought to [2²⁸, 2²⁹), or as high as the lowest exponent lets it,
    /// and 1 made again at the new exponent.
    #[inline(always)]
    fn renormalise(&mut self, x: i32, y: i32) {
        let top = 31 - leading_zeros(ones_magnitude(x) | ones_magnitude(y) | 1) as i32;
        let lowest = if self.plus_one { 0 } else { -30 };
        let (x, y) = if top > 28 {
            let down = (top - 28) as u32;
            self.e += top - 28;
            (x >> down, y >> down)
        } else {
            let up = (28 - top).min(self.e - lowest).max(0) as u32;
            self.e -= up as i32;
            (x << up, y << up)
        };
        (self.x, self.y) = (x, y);
        self.one = if self.plus_one && self.e <= 28 {
            1 << (28 - self.e)
        } else {
            0
        };
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// Normalising keeps the derivative's value, (x + iy)·2^(e − 30), to the mantissas'
    /// last bit, and leaves the larger mantissa in [2²⁹, 2³¹), or smaller only at the
    /// lowest exponent, over mantissas of every size from 0 to 2⁴⁰ and exponents from
    /// the lowest up: the fast path for mantissas already in range, and the shifts.
    #[test]
    fn normalising_keeps_the_value_with_the_mantissa_in_range() {
        let mut runner = TestRunner::deterministic();
        let mantissa = (-(1i64 << 40)..=1 << 40, 0u32..41).prop_map(|(v, s)| v >> s);
        runner
            .run(&(mantissa.clone(), mantissa, -30i32..60), |(x, y, e)| {
                let mut d = Derivative { x: 0, y: 0, e };
                d.normalise(x, y);
                let larger = d.x.unsigned_abs().max(d.y.unsigned_abs());
                prop_assert!(larger < 1 << 31);
                prop_assert!(larger >= 1 << 29 || d.e == -30 || (x, y) == (0, 0));
                // The value at the new exponent: the old one shifted, floored.
                let at = |v: i64| {
                    let moved = i128::from(v) << 64 >> (64 + d.e - e);
                    i64::try_from(moved).unwrap()
                };
                prop_assert!(d.e >= e || (at(x), at(y)) == (i64::from(d.x), i64::from(d.y)));
                prop_assert!(
                    d.e < e || (x >> (d.e - e), y >> (d.e - e)) == (i64::from(d.x), i64::from(d.y))
                );
                Ok(())
            })
            .unwrap();
    }

    /// The loose derivative's value, (x + iy)·2^(e − 28), in f64.
    fn value(d: LooseDerivative) -> (f64, f64) {
        let scale = 2f64.powi(d.e - 28);
        (f64::from(d.x) * scale, f64::from(d.y) * scale)
    }

    /// A normalised derivative's value, (x + iy)·2^(e − 30), in f64.
    fn normalised_value(d: Derivative) -> (f64, f64) {
        let scale = 2f64.powi(d.e - 30);
        (f64::from(d.x) * scale, f64::from(d.y) * scale)
    }

    /// Steps a loose derivative along `points` (Q`bits` each, by `step`) beside the f64
    /// model dz ← 2·z·dz (+ 1) from the same start, and checks that the two stay within
    /// the steps' roundings (each off by 2⁻¹⁹ of the model's bound B ← 2|z|·B + 1, the
    /// size dz would have with no cancellation, times 2|z| where that is above 1, and by
    /// `cut` where the lowest exponent holds the mantissas below the window: a unit of
    /// the exponent after the step, which moves by at most 2 in the orbit and 10 past the
    /// escape); that the mantissas stay in
    /// their window; and (the test runs with overflow checks) that no sum leaves 32 or
    /// 64 bits.
    fn follows_the_model(
        start: Derivative,
        plus_one: bool,
        points: &[(i32, i32)],
        bits: i32,
        step: fn(&mut LooseDerivative, i32, i32),
        cut: f64,
    ) -> Result<(), TestCaseError> {
        let mut loose = LooseDerivative::of(start, plus_one);
        let mut model = normalised_value(start);
        let mut bound = model.0.hypot(model.1);
        let mut error = 2f64.powi(-25) * bound + 2f64.powi(-27);
        let plus = if plus_one { 1.0 } else { 0.0 };
        for &(zx, zy) in points {
            let z = (
                f64::from(zx) * 2f64.powi(-bits),
                f64::from(zy) * 2f64.powi(-bits),
            );
            step(&mut loose, zx, zy);
            model = (
                2.0 * (z.0 * model.0 - z.1 * model.1) + plus,
                2.0 * (z.0 * model.1 + z.1 * model.0),
            );
            let modulus = 2.0 * z.0.hypot(z.1);
            // A step's product rounds down by a unit of its new exponent: at most
            // 2⁻¹⁹·2|z| of the derivative before it (or 2⁻¹⁹ of it for a small z).
            error = modulus * error + 2f64.powi(-19) * modulus.max(1.0) * (bound + error) + cut;
            bound = modulus * bound + plus;
            let (x, y) = value(loose);
            prop_assert!(
                (x - model.0).hypot(y - model.1) <= error,
                "{:?} against {:?}, off by more than {}",
                (x, y),
                model,
                error
            );
            let larger = ones_magnitude(loose.x) | ones_magnitude(loose.y);
            prop_assert!(larger <= LOOSE_HIGH);
            let lowest = if plus_one { 0 } else { -30 };
            prop_assert!(larger >= LOOSE_LOW || loose.e <= lowest + 1);
            let one = if plus_one && loose.e <= 28 {
                1 << (28 - loose.e)
            } else {
                0
            };
            prop_assert_eq!(loose.one, one);
        }
        // Normalised again, the same value to the mantissas' last bits.
        let back = normalised_value(loose.normalised());
        let (x, y) = value(loose);
        prop_assert!((back.0 - x).hypot(back.1 - y) <= 2f64.powi(loose.e - 27));
        Ok(())
    }

    /// A random normalised derivative: mantissas with the larger in [2²⁹, 2³¹), any
    /// exponent a loop meets.
    fn derivatives() -> impl Strategy<Value = Derivative> {
        (
            1i32 << 29..i32::MAX,
            any::<i32>(),
            -30i32..200,
            any::<bool>(),
            any::<bool>(),
        )
            .prop_map(|(big, other, e, swap, negative)| {
                let big = if negative { -big } else { big };
                let other = other / 2;
                let (x, y) = if swap { (other, big) } else { (big, other) };
                let mut d = Derivative { x: 0, y: 0, e };
                d.normalise(i64::from(x), i64::from(y));
                d
            })
    }

    /// Points within radius 2 in Q28 (as the orbits step them), their ends included.
    fn orbit_points() -> impl Strategy<Value = std::vec::Vec<(i32, i32)>> {
        let two = 2i32 << 28;
        let point = prop_oneof![
            (-two..=two, -two..=two).prop_filter("|z| ≤ 2", |&(x, y)| {
                i64::from(x).pow(2) + i64::from(y).pow(2) <= (1i64 << 58)
            }),
            Just((two, 0)),
            Just((-two, 0)),
            Just((0, -two)),
            Just((379_625_062, -379_625_062)),
            (-1000i32..1000, -1000i32..1000),
        ];
        proptest::collection::vec(point, 1..60)
    }

    /// The orbits' step (z in Q28, |z| ≤ 2) follows dz ← 2·z·dz + 1 and dz ← 2·z·dz in
    /// f64, from derivatives of every size, within its roundings.
    #[test]
    fn loose_steps_in_the_orbit_follow_the_model() {
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(derivatives(), any::<bool>(), orbit_points()),
                |(d, plus, points)| {
                    follows_the_model(
                        d,
                        plus,
                        &points,
                        28,
                        LooseDerivative::step_q28,
                        2f64.powi(-25),
                    )
                },
            )
            .unwrap();
    }

    /// The steps past the escape (z in Q20, parts below 2²⁸: |z| from below 2⁻² to 256)
    /// follow the model too.
    #[test]
    fn loose_steps_past_the_escape_follow_the_model() {
        let mut runner = TestRunner::deterministic();
        let part = prop_oneof![
            -(1i32 << 28) + 1..1 << 28,
            -(1i32 << 22)..1 << 22,
            Just((1 << 28) - 1),
            Just(-(1 << 28) + 1),
        ];
        let points = proptest::collection::vec((part.clone(), part), 1..8);
        runner
            .run(
                &(derivatives(), any::<bool>(), points),
                |(d, plus, points)| {
                    follows_the_model(
                        d,
                        plus,
                        &points,
                        20,
                        LooseDerivative::step_q20,
                        2f64.powi(-17),
                    )
                },
            )
            .unwrap();
    }

    /// Carried loosely and normalised again, a derivative keeps its value to the
    /// mantissas' last two bits (or to 2⁻²⁸ where 1 is added and it is below 1).
    #[test]
    fn loose_and_normalised_are_the_same_derivative() {
        let mut runner = TestRunner::deterministic();
        runner
            .run(&(derivatives(), any::<bool>()), |(d, plus)| {
                let loose = LooseDerivative::of(d, plus);
                let (x, y) = value(loose);
                let (dx, dy) = normalised_value(d);
                let tolerance = 2f64
                    .powi(d.e - 27)
                    .max(if plus { 2f64.powi(-27) } else { 0.0 });
                prop_assert!((x - dx).hypot(y - dy) <= tolerance);
                Ok(())
            })
            .unwrap();
    }
}
