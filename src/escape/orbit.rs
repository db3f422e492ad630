//! One pixel's orbit: z ← z² + c iterated in a tier's arithmetic until it escapes, repeats
//! or reaches the cap, and the dispatch that compiles it once per tier.
//!
//! Overflow cannot happen, by invariant: an orbit is only squared while |z|² ≤ 4 (so |x|,
//! |y| ≤ 2), and every c is within ±3.5 (checked by the view), so the next value is below
//! 7.5 and its square below 57: inside every tier's range. A Julia start outside radius 2
//! escapes at once (|z₁| ≥ |z₀|² − |k| > 2 because |k| ≤ 2) and is never squared.
//!
//! Mirrored points have the same dwell by construction: a Mandelbrot point is iterated as
//! its twin in the upper half-plane (|im|), so products round down with a plain shift
//! instead of toward zero (which costs a correction per step). A Julia set's half turn
//! needs nothing: z₀ and −z₀ have the same z₁ however products round.

use core::marker::PhantomData;

use super::arithmetic::*;
use super::estimate::Estimate;
use super::kernel::{Kernel, Kind, Orbit, Part};
use super::modes::Inside;
use super::view::SMOOTH_FRACTION_BITS;
use crate::math::log::{log2, LOG2_FRAC_BITS};
use crate::math::wide::{mul_i32_wide, square_i32_wide};

impl Kernel {
    /// The dwell of the point (`re`, `im`).
    #[inline(always)]
    pub(crate) fn dwell(&self, re: Part, im: Part) -> Orbit {
        match self.arithmetic {
            Kind::Narrow => orbit::<Narrow, false>(self, re.0, im.0),
            Kind::Medium => orbit::<Medium, false>(self, re.0, im.0),
            Kind::RoundedMedium => orbit::<RoundedMedium, false>(self, re.0, im.0),
            Kind::Standard => orbit::<Standard, false>(self, re.0, im.0),
            Kind::Deep => orbit::<Deep, false>(self, re.0, im.0),
            Kind::Wide => orbit::<Wide, false>(self, re.0, im.0),
        }
    }

    /// Calls `visitor` with this kernel's tier as a type, so a caller is compiled once per
    /// tier with the orbit in line (see [`TierVisitor`]): a render's tile subdivision, where
    /// most pixels are computed, tests no tier per pixel.
    #[inline(always)]
    pub(crate) fn visit<V: TierVisitor>(&self, visitor: V) -> V::Output {
        match self.arithmetic {
            Kind::Narrow => visitor.visit(InTier::<Narrow>(self, PhantomData)),
            Kind::Medium => visitor.visit(InTier::<Medium>(self, PhantomData)),
            Kind::RoundedMedium => visitor.visit(InTier::<RoundedMedium>(self, PhantomData)),
            Kind::Standard => visitor.visit(InTier::<Standard>(self, PhantomData)),
            Kind::Deep | Kind::Wide => visitor.visit(Called(self)),
        }
    }
}

/// A pixel's dwell in one tier, known at compile time.
pub(crate) trait TierOrbit {
    /// The dwell of the point (`re`, `im`).
    fn dwell(&self, re: Part, im: Part) -> Orbit;

    /// [`dwell`](Self::dwell) for a kernel that is [`traceable`](Kernel::traceable): a
    /// Mandelbrot view's dwells, compiled without the tests for a Julia set's start or
    /// a smooth value's finish (both known false).
    fn traced_dwell(&self, re: Part, im: Part) -> Orbit;
}

/// Code compiled once per tier: [`Kernel::visit`] calls it with the kernel's.
pub(crate) trait TierVisitor {
    /// What the code returns.
    type Output;
    /// Runs with the tier `orbit`.
    fn visit<T: TierOrbit>(self, orbit: T) -> Self::Output;
}

/// A kernel in tier `A`.
struct InTier<'k, A>(&'k Kernel, PhantomData<A>);

impl<A: Arithmetic> TierOrbit for InTier<'_, A> {
    /// The 32-bit tiers' orbit in line where there is a long multiply; `Deep`, and every
    /// tier on Cortex-M0, stay a call, which costs less there (docs/performance.md).
    #[inline(always)]
    fn dwell(&self, re: Part, im: Part) -> Orbit {
        if A::WORD_STEPS && cfg!(not(tinyfractal_no_long_multiply)) {
            orbit_in_line::<A, false>(self.0, re.0, im.0)
        } else {
            orbit::<A, false>(self.0, re.0, im.0)
        }
    }

    #[inline(always)]
    fn traced_dwell(&self, re: Part, im: Part) -> Orbit {
        if A::WORD_STEPS && cfg!(not(tinyfractal_no_long_multiply)) {
            orbit_in_line::<A, true>(self.0, re.0, im.0)
        } else {
            orbit::<A, true>(self.0, re.0, im.0)
        }
    }
}

/// `Deep` or `Wide`, chosen at each pixel: one copy of the tile code for both, and one of
/// `Wide`'s orbit. Their orbits are calls either way, so the choice costs a comparison
/// beside hundreds of steps; with copies of their own for `Wide`, the LM3S6965's firmware
/// did not fit its 256 KiB of flash.
struct Called<'k>(&'k Kernel);

impl TierOrbit for Called<'_> {
    #[inline(always)]
    fn dwell(&self, re: Part, im: Part) -> Orbit {
        match self.0.arithmetic {
            Kind::Wide => orbit::<Wide, false>(self.0, re.0, im.0),
            _ => orbit::<Deep, false>(self.0, re.0, im.0),
        }
    }

    /// `Wide` in its one copy, the tests for a Julia set and a smooth value kept.
    #[inline(always)]
    fn traced_dwell(&self, re: Part, im: Part) -> Orbit {
        match self.0.arithmetic {
            Kind::Wide => orbit::<Wide, false>(self.0, re.0, im.0),
            _ => orbit::<Deep, true>(self.0, re.0, im.0),
        }
    }
}

/// An orbit point and its squares.
struct Z<A: Arithmetic> {
    x: A::Value,
    y: A::Value,
    x2: A::Product,
    y2: A::Product,
}

impl<A: Arithmetic> Z<A> {
    #[inline(always)]
    fn new(x: A::Value, y: A::Value) -> Self {
        Self {
            x,
            y,
            x2: A::mul(x, x),
            y2: A::mul(y, y),
        }
    }

    #[inline(always)]
    fn escaped(&self) -> bool {
        A::escapes(self.x2, self.y2)
    }

    /// One step, z ← z² + c, then its squares; true if it escaped.
    #[inline(always)]
    fn step(&mut self, cr: A::Value, ci: A::Value) -> bool {
        (self.x, self.y) = A::square_plus((self.x, self.y), (self.x2, self.y2), (cr, ci));
        self.x2 = A::mul(self.x, self.x);
        self.y2 = A::mul(self.y, self.y);
        self.escaped()
    }

    /// Whether the point is within the tolerance of a saved one (`saved` less the
    /// tolerance, `span` twice the tolerance).
    #[inline(always)]
    fn repeats(&self, saved: (A::Value, A::Value), span: A::Value) -> bool {
        self.x.wrapping_sub(saved.0).unsigned_at_most(span)
            && self.y.wrapping_sub(saved.1).unsigned_at_most(span)
    }
}

impl Kernel {
    /// The dwell of the Mandelbrot point c (Q60, `Deep`'s units) whose orbit is at z
    /// (Q60) after `steps` steps, in [`HighWords`]: the finish of a perturbed pixel whose
    /// first steps the series skipped. Escape only: repeats there are too rare to pay
    /// for their test (docs/performance.md).
    #[inline(never)]
    pub(crate) fn resume(&self, c: (i64, i64), z: (i64, i64), steps: u32) -> Orbit {
        let mut z = Z::<HighWords>::new(z.0, z.1);
        let mut n = steps;
        while !z.escaped() {
            if n >= self.max {
                return Orbit::inside_after(self, n);
            }
            n += 1;
            z.step(c.0, c.1);
        }
        escaped::<HighWords, false>(self, n, (z.x, z.y), c)
    }
}

/// The dwell of the point (`re`, `im`) in tier `A`'s units.
///
/// The first `FIRST_SAVE` steps test only escape. Then repeats are found by Brent's
/// method: the orbit point saved at n = FIRST_SAVE, 2·FIRST_SAVE, 4·FIRST_SAVE, ... is
/// compared with every point up to the next save (every fourth in the 32-bit tiers, see
/// `Arithmetic::WORD_STEPS`). Each stretch between saves is a loop of its own, so the
/// step itself tests nothing but escape and repeat.
#[inline(never)]
fn orbit<A: Arithmetic, const TRACEABLE: bool>(kernel: &Kernel, re: i64, im: i64) -> Orbit {
    orbit_in_line::<A, TRACEABLE>(kernel, re, im)
}

/// [`orbit`]'s body, for callers that take it in line. `TRACEABLE`: the kernel is
/// [`traceable`](Kernel::traceable), so its tests for a Julia set and a smooth value
/// compile away.
#[inline(always)]
fn orbit_in_line<A: Arithmetic, const TRACEABLE: bool>(kernel: &Kernel, re: i64, im: i64) -> Orbit {
    let orbit = match Orbiting::<A, TRACEABLE>::start(kernel, re, im) {
        Ok(orbiting) => orbiting.run(),
        Err(orbit) => orbit,
    };
    if !TRACEABLE && kernel.estimate.is_some() {
        return estimated_in_tier::<A>(kernel, re, im, orbit);
    }
    orbit
}

/// `orbit`, of the point (`re`, `im`) in tier `A`'s units, as distance estimation has it
/// (see [`Kernel::estimated`]): out of line, after the orbit, so the orbit's loops carry
/// nothing for it. An orbit escaped if it stopped before the cap with a value other than
/// the inside value (inside modes test no repeats, so their orbits reach the cap).
#[inline(never)]
fn estimated_in_tier<A: Arithmetic>(kernel: &Kernel, re: i64, im: i64, orbit: Orbit) -> Orbit {
    if orbit.iterations >= kernel.max || orbit.dwell == kernel.inside {
        return orbit;
    }
    let q60 = |units: i64| A::q60(A::Value::from_units(units));
    let pixel = (q60(re), q60(im));
    // z₁ = c for the Mandelbrot set; a Julia set's pixel is z₀.
    let c = kernel.julia.map_or(pixel, |(kr, ki)| (q60(kr), q60(ki)));
    kernel.estimated(orbit, pixel, c)
}

/// What a stretch of an orbit comes to: `Ok` goes on; `Err` is the orbit's value, found
/// when it escaped or repeated, so that `?` ends the orbit.
type Stretch = Result<(), Orbit>;

/// An orbit under way: z, its c and the steps taken, with the kernel's rules. Its methods
/// are the stretches of [`orbit`]; all are taken in line, so the fields live in registers.
struct Orbiting<'k, A: Arithmetic, const TRACEABLE: bool> {
    kernel: &'k Kernel,
    z: Z<A>,
    /// Passed by value to the escape's valuation: held by reference, it was kept in
    /// memory and stored on every pixel's way in.
    c: (A::Value, A::Value),
    /// The steps taken.
    n: u32,
    /// How close a repeat comes to a saved point, and twice that: orbit points compared
    /// have |x|, |y| ≤ 2, so nothing wraps.
    tolerance: A::Value,
    span: A::Value,
}

impl<'k, A: Arithmetic, const TRACEABLE: bool> Orbiting<'k, A, TRACEABLE> {
    /// The orbit of (`re`, `im`) in the kernel's units, or its value where that is known
    /// before any step: inside the main cardioid or the period-2 bulb, or escaped at once.
    #[inline(always)]
    fn start(kernel: &'k Kernel, re: i64, im: i64) -> Result<Self, Orbit> {
        let (re, im) = (A::Value::from_units(re), A::Value::from_units(im));
        let julia = if TRACEABLE { None } else { kernel.julia };
        let (c, (x, y), n) = match julia {
            None => {
                // An inside mode's value is z at the cap: computed, not known.
                let known = TRACEABLE || kernel.inside_mode == Inside::MaxIter;
                if known && in_cardioid_or_bulb(A::q28(re), A::q28(im)) {
                    return Err(Orbit::inside_after(kernel, 0));
                }
                // The upper half-plane twin: the same dwell, exactly (see the module docs),
                // unless the outside mode tells a point from its conjugate (not mirrored).
                // The first step is free: z₁ = c.
                let twin = TRACEABLE || kernel.outside.symmetric();
                let c = (re, if twin { im.abs() } else { im });
                (c, c, 1)
            }
            Some((kr, ki)) => (
                (A::Value::from_units(kr), A::Value::from_units(ki)),
                (re, im),
                0,
            ),
        };
        let tolerance = A::Value::from_units(kernel.tolerance);
        let orbiting = Self {
            kernel,
            z: Z::new(x, y),
            c,
            n,
            tolerance,
            span: tolerance.twice(),
        };
        if orbiting.z.escaped() {
            return Err(orbiting.escaped_at(n));
        }
        Ok(orbiting)
    }

    /// The orbit to its end: escaped, repeated, or inside after `max` steps.
    #[inline(always)]
    fn run(mut self) -> Orbit {
        let ended = if A::COMPACT {
            self.one_step_a_turn()
        } else {
            self.stretches()
        };
        match ended {
            Ok(()) => self.at_cap(),
            Err(orbit) => orbit,
        }
    }

    /// The value of the orbit at the cap, not escaped: the cap, or the inside mode's value
    /// of z there.
    #[inline(always)]
    fn at_cap(&self) -> Orbit {
        let kernel = self.kernel;
        if TRACEABLE || kernel.inside_mode == Inside::MaxIter {
            return Orbit::inside_after(kernel, kernel.max);
        }
        inside_in_tier::<A>(kernel, (self.z.x, self.z.y), self.c)
    }

    /// The value of the orbit, escaped at step `n`.
    #[inline(always)]
    fn escaped_at(&self, n: u32) -> Orbit {
        escaped::<A, TRACEABLE>(self.kernel, n, (self.z.x, self.z.y), self.c)
    }

    /// Takes step `n`; the orbit ends if it escapes.
    #[inline(always)]
    fn step(&mut self, n: u32) -> Stretch {
        if self.z.step(self.c.0, self.c.1) {
            return Err(self.escaped_at(n));
        }
        Ok(())
    }

    /// Tests the orbit after step `n` against `saved`; it ends inside if it came back.
    #[inline(always)]
    fn repeat_test(&self, saved: (A::Value, A::Value), n: u32) -> Stretch {
        if self.z.repeats(saved, self.span) {
            return Err(Orbit::inside_after(self.kernel, n));
        }
        Ok(())
    }

    /// The point saved for the repeat tests, less the tolerance: x − saved + tolerance is
    /// then one subtraction.
    #[inline(always)]
    fn saved(&self) -> (A::Value, A::Value) {
        (
            self.z.x.wrapping_sub(self.tolerance),
            self.z.y.wrapping_sub(self.tolerance),
        )
    }

    /// The compact tiers' orbit: the same steps and tests as [`stretches`](Self::stretches),
    /// one step a turn.
    #[inline(always)]
    fn one_step_a_turn(&mut self) -> Stretch {
        let (plain, max) = (self.kernel.plain, self.kernel.max);
        while self.n < plain {
            self.n += 1;
            self.step(self.n)?;
        }
        let (mut saved, mut next_save) = ((self.z.x, self.z.y), plain);
        while self.n < max {
            if self.n == next_save {
                saved = self.saved();
                next_save *= 2;
            }
            self.n += 1;
            self.step(self.n)?;
            self.repeat_test(saved, self.n)?;
        }
        Ok(())
    }

    /// The orbit in stretches: the first `plain` steps test only escape (most points
    /// escape within them); then each stretch between saves tests escape and repeat.
    #[inline(always)]
    fn stretches(&mut self) -> Stretch {
        let (plain, max) = (self.kernel.plain, self.kernel.max);
        self.first_stretch(plain)?;
        // At most 2·max ≤ 2^17 (the view caps max at u16::MAX): it cannot overflow.
        let mut next_save = 2 * plain;
        while self.n < max {
            let saved = self.saved();
            self.stretch(saved, next_save.min(max))?;
            next_save *= 2;
        }
        Ok(())
    }

    // Where there is a long multiply, turns of the loops are counted down (one subtraction
    // and branch a turn; n found again on leaving), four steps a turn before the repeat
    // tests start. On Cortex-M0 (eight low registers, products from halves) the extra
    // counter spills, so it keeps two a turn counted by n (docs/performance.md).

    /// Steps up to `plain`, testing only escape.
    #[cfg(not(tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn first_stretch(&mut self, plain: u32) -> Stretch {
        self.fours_until(plain, |_, _| Ok(()))?;
        // At most three more, each tested and unrolled: a counted loop here cost the
        // Mandelbrot set's first stretch (then 15 steps) more than the fours saved.
        for _ in 0..3 {
            if self.n < plain {
                self.n += 1;
                self.step(self.n)?;
            }
        }
        Ok(())
    }

    /// Steps up to `plain`, testing only escape, two a turn counted by n.
    #[cfg(tinyfractal_no_long_multiply)]
    #[inline(always)]
    fn first_stretch(&mut self, plain: u32) -> Stretch {
        while self.n + 1 < plain {
            self.step(self.n + 1)?;
            self.n += 2;
            self.step(self.n)?;
        }
        if self.n < plain {
            self.n += 1;
            self.step(self.n)?;
        }
        Ok(())
    }

    /// Turns of four steps up to `stop`, counted down, each step tested for escape and
    /// each turn ended by `after` (given the steps done before the turn).
    #[cfg(not(tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn fours_until(&mut self, stop: u32, after: impl Fn(&Self, u32) -> Stretch) -> Stretch {
        let fours = stop.saturating_sub(self.n) / 4;
        let mut left = fours;
        while left > 0 {
            let done = self.n + 4 * (fours - left);
            for k in 1..=4 {
                self.step(done + k)?;
            }
            after(self, done)?;
            left -= 1;
        }
        self.n += 4 * fours;
        Ok(())
    }

    /// The steps up to `stop`, tested for escape and for a repeat of `saved`.
    #[cfg(not(tinyfractal_no_long_multiply))]
    #[inline(always)]
    fn stretch(&mut self, saved: (A::Value, A::Value), stop: u32) -> Stretch {
        if A::WORD_STEPS {
            // Four steps a turn and one repeat test, at 4k steps after the save: a cycle
            // of period p is still found, at most 3p steps later.
            self.fours_until(stop, |orbiting, done| orbiting.repeat_test(saved, done + 4))?;
        } else {
            // Two steps a turn, each tested.
            let pairs = stop.saturating_sub(self.n) / 2;
            let mut left = pairs;
            while left > 0 {
                let done = self.n + 2 * (pairs - left);
                self.step(done + 1)?;
                self.repeat_test(saved, done + 1)?;
                self.step(done + 2)?;
                self.repeat_test(saved, done + 2)?;
                left -= 1;
            }
            self.n += 2 * pairs;
        }
        self.last_step(saved, stop)
    }

    /// The steps up to `stop`, tested for escape and for a repeat of `saved`, counted by n.
    #[cfg(tinyfractal_no_long_multiply)]
    #[inline(always)]
    fn stretch(&mut self, saved: (A::Value, A::Value), stop: u32) -> Stretch {
        if A::WORD_STEPS {
            while self.n + 3 < stop {
                self.step(self.n + 1)?;
                self.step(self.n + 2)?;
                self.step(self.n + 3)?;
                self.n += 4;
                self.step(self.n)?;
                self.repeat_test(saved, self.n)?;
            }
        }
        while !A::WORD_STEPS && self.n + 1 < stop {
            self.step(self.n + 1)?;
            self.repeat_test(saved, self.n + 1)?;
            self.n += 2;
            self.step(self.n)?;
            self.repeat_test(saved, self.n)?;
        }
        self.last_step(saved, stop)
    }

    /// One more step if the stretch's turns left one before `stop`.
    #[inline(always)]
    fn last_step(&mut self, saved: (A::Value, A::Value), stop: u32) -> Stretch {
        if self.n < stop {
            self.n += 1;
            self.step(self.n)?;
            self.repeat_test(saved, self.n)?;
        }
        Ok(())
    }
}

/// The value of an orbit of c that escaped at step `n` at z: its dwell, its smooth value,
/// or its outside mode's value.
#[inline(always)]
fn escaped<A: Arithmetic, const TRACEABLE: bool>(
    kernel: &Kernel,
    n: u32,
    (x, y): (A::Value, A::Value),
    (cr, ci): (A::Value, A::Value),
) -> Orbit {
    Orbit {
        dwell: if TRACEABLE || kernel.plain_escape {
            n.max(1)
        } else if kernel.smooth {
            smooth_value(
                n,
                (A::q28(x), A::q28(y)),
                (A::q28(cr), A::q28(ci)),
                kernel.max,
                kernel.inside,
            )
        } else if kernel.estimate.is_some_and(Estimate::shades) {
            // Replaced by the distance shading's value: any value but the inside one
            // (256), which an escape at step 256 would take under a higher cap.
            1
        } else {
            kernel.outside.value(n, (A::q28(x), A::q28(y)), kernel.max)
        },
        iterations: n,
    }
}

/// [`Inside::value`] from a tier's values, out of line.
#[inline(never)]
fn inside_in_tier<A: Arithmetic>(
    kernel: &Kernel,
    z: (A::Value, A::Value),
    c: (A::Value, A::Value),
) -> Orbit {
    let q28 = |(x, y): (A::Value, A::Value)| (A::q28(x), A::q28(y));
    Orbit {
        dwell: kernel.inside_mode.value(q28(z), q28(c), kernel.max),
        iterations: kernel.max,
    }
}

/// The smooth value of an orbit that escaped at step `n` with z (Q28), its c (Q28): the
/// normalised iteration count ν = N + 2 − log₂(log₂|z_N|²) in sixteenths, taken at the
/// first N past the escape with |z_N| ≥ 256 (three steps from |z| = 3; at most
/// `SMOOTH_STEPS`, for points that crawl out along the tip at −2). There the `+ c` that
/// makes ν jump at a band's edge is below 10⁻⁴ of z²: the value is continuous across the
/// bands to well within its sixteenth (checked against an f64 model that runs to
/// |z| = 10⁶ in the tests). Clamped to 1..inside − 1, so an escaping pixel is never taken
/// for the "not yet computed" 0 or for inside; escaping at the cap counts as inside, as its
/// dwell does.
///
/// In Q20: a point is only squared while |x|, |y| < 256 (2²⁸), so its parts are 32-bit
/// factors (products from halves on cores without a long multiply) and its squares stay
/// below 2⁵⁶; the next point is below 2¹⁷ (Q20: 2³⁷), and its |z|² is taken in Q16 from
/// Q8 parts, below 2²⁵.
#[inline(never)]
pub(crate) fn smooth_value(n: u32, z: (i32, i32), c: (i32, i32), max: u32, inside: u32) -> u32 {
    const BAILOUT: u64 = 256 << 20;
    if n >= max {
        return inside;
    }
    let (cr, ci) = (i64::from(c.0) >> 8, i64::from(c.1) >> 8);
    let (mut x, mut y) = (i64::from(z.0) >> 8, i64::from(z.1) >> 8);
    let mut steps = 0;
    while steps < SMOOTH_STEPS && x.unsigned_abs() < BAILOUT && y.unsigned_abs() < BAILOUT {
        // Both below 2²⁸: the casts keep them.
        let (xs, ys) = (x as i32, y as i32);
        let (x2, y2) = (square_i32_wide(xs), square_i32_wide(ys));
        if (x2 + y2).unsigned_abs() >= BAILOUT * BAILOUT {
            break;
        }
        // 2xy / 2²⁰ = xy / 2¹⁹.
        (x, y) = (((x2 - y2) >> 20) + cr, (mul_i32_wide(xs, ys) >> 19) + ci);
        steps += 1;
    }
    // Below 2²⁵ (a part below 2³⁷ + |c|, taken down 12 bits): the casts keep them.
    let (x, y) = ((x >> 12) as i32, (y >> 12) as i32);
    // |z|² is above 4 (the orbit escaped), so both logarithms are positive.
    let modulus = (square_i32_wide(x) + square_i32_wide(y)).unsigned_abs();
    let nu = log2(modulus, 16)
        .and_then(|bits| log2(u64::try_from(bits).ok()?, LOG2_FRAC_BITS))
        .map_or(0, |log_log| {
            ((i64::from(n) + i64::from(steps) + 2) << LOG2_FRAC_BITS) - i64::from(log_log)
        });
    // Q16 → sixteenths, rounded.
    let shift = LOG2_FRAC_BITS - SMOOTH_FRACTION_BITS;
    let value = (nu + (1 << (shift - 1))) >> shift;
    u32::try_from(value)
        .unwrap_or(0)
        .clamp(1, inside.saturating_sub(1).max(1))
}

/// Most steps a smooth value takes past the escape.
const SMOOTH_STEPS: u32 = 32;

/// Inside the main cardioid or the period-2 bulb, decided in Q28 with 64-bit products (no
/// 128-bit library calls on Cortex-M) and a margin of 2⁻²⁰, which covers every rounding
/// below (at most about 2⁻²¹·⁷): a point it accepts is inside for certain, and a point on
/// or next to the boundary is iterated instead. |x|, |y| ≤ 3.5 (the view's limit), so every
/// value below fits its type.
// In line: it is called for every cell of every tier's subdivision.
#[inline(always)]
pub(crate) fn in_cardioid_or_bulb(x: i32, y: i32) -> bool {
    const ONE: i32 = 1 << 28;
    // 2^-20 in Q56.
    const MARGIN: i64 = 1 << 36;
    // Both lie within -1.25 ≤ x ≤ 0.375, |y| ≤ 0.65: most of a picture fails these cheaper
    // comparisons first.
    if !(-(ONE + ONE / 4)..=3 * ONE / 8).contains(&x) || y.unsigned_abs() > (ONE / 20 * 13) as u32 {
        return false;
    }
    // Q56.
    let y2 = mul_i32_wide(y, y);
    // Period-2 bulb: (x + 1)² + y² < 1/16.
    let x1 = x + ONE;
    if mul_i32_wide(x1, x1) + y2 + MARGIN < 1 << 52 {
        return true;
    }
    // Cardioid: q(q + x - 1/4) < y²/4 with q = (x - 1/4)² + y², all below 2^63.
    let xq = x - ONE / 4;
    // Q28, rounded down: the margin covers it.
    let q = (mul_i32_wide(xq, xq) + y2) >> 28;
    // From q ≥ 2 on, q + xq ≥ 1/4 and q ≥ y², so q(q + xq) ≥ y²/4: outside. Below it, q and
    // q + xq fit in an i32.
    if q >= 2 << 28 {
        return false;
    }
    let q = q as i32;
    mul_i32_wide(q, q + xq) + MARGIN < y2 / 4
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::escape::kernel::{Periodicity, FIRST_SAVE};
    use crate::escape::view::{Fractal, Tier, View};
    use crate::math::Coord;

    /// `Wide`'s one-step loop saves and tests at the same steps as the unrolled loops: on
    /// a grid over the full view, where its orbits and `Deep`'s agree to far below the
    /// tolerance, every pixel stops at the same step in both, by escape or by a repeat.
    #[test]
    fn the_compact_loop_tests_repeats_at_the_same_steps() {
        let view = View::new(
            Fractal::Mandelbrot,
            (Coord::from_f64(-0.75).unwrap(), Coord::from_bits(0)),
            Coord::from_f64(3.0).unwrap(),
            embedded_graphics::geometry::Size::new(64, 48),
            1000,
        )
        .unwrap();
        let periodicity = Periodicity::Within(1 << 36);
        let deep = Kernel::new(&view.with_tier(Tier::Deep), periodicity);
        let wide = Kernel::new(&view.with_tier(Tier::Wide), periodicity);
        let (mut repeats, mut compared) = (0, 0);
        for j in 0..48 {
            for i in 0..64 {
                let (re, im) = (
                    q60(-2.25 + 3.0 * i as f64 / 64.0),
                    q60(1.125 - 2.25 * j as f64 / 48.0),
                );
                let a = deep.dwell(deep.part(re), deep.part(im));
                let b = wide.dwell(wide.part(re), wide.part(im));
                assert_eq!((a.dwell, a.iterations), (b.dwell, b.iterations), "{i},{j}");
                repeats += usize::from(a.dwell == 1000 && a.iterations < 1000);
                compared += 1;
            }
        }
        assert!(repeats > 100, "{repeats} of {compared} stopped by a repeat");
    }

    fn q60(v: f64) -> i64 {
        (v * (1u64 << 60) as f64) as i64
    }

    fn q28(v: f64) -> i32 {
        (v * f64::from(1 << 28)) as i32
    }

    #[test]
    fn cardioid_and_bulb_contain_their_centres_only() {
        for (re, im) in [
            (0.0, 0.0),
            (-0.5, 0.3),
            (-1.0, 0.0),
            (-1.2, 0.1),
            (0.2, 0.0),
        ] {
            assert!(in_cardioid_or_bulb(q28(re), q28(im)), "{re},{im}");
        }
        for (re, im) in [
            (0.3, 0.0),
            (-0.75, 0.2),
            (-1.3, 0.0),
            (0.26, 0.0),
            (-2.0, 0.0),
            (1.9, 1.9),
        ] {
            assert!(!in_cardioid_or_bulb(q28(re), q28(im)), "{re},{im}");
        }
    }

    #[test]
    fn tiers_agree_on_simple_points() {
        let view = View::new(
            Fractal::Mandelbrot,
            (Coord::default(), Coord::default()),
            Coord::from_f64(3.0).unwrap(),
            embedded_graphics::geometry::Size::new(100, 100),
            500,
        )
        .unwrap();
        for (re, im, dwell) in [(1.0, 0.0, 3), (-0.1, 0.1, u32::MAX), (-2.1, 0.0, 1)] {
            let expected = if dwell == u32::MAX { 500 } else { dwell };
            for tier in Tier::ALL {
                let kernel = Kernel::new(&view.with_tier(tier), Periodicity::Exact);
                let orbit = kernel.dwell(kernel.part(q60(re)), kernel.part(q60(im)));
                assert_eq!(orbit.dwell, expected, "{re},{im} {tier:?}");
            }
            // The perturbed pixels' finish, from z₁ = c.
            let c = (q60(re), q60(im));
            let kernel = Kernel::new(&view, Periodicity::Exact);
            assert_eq!(kernel.resume(c, c, 1).dwell, expected, "{re},{im} finish");
        }
    }

    /// A Julia set of a parameter outside the Mandelbrot set (its critical orbit escapes)
    /// tests no repeats, in every tier; one inside keeps Brent's test.
    #[test]
    fn dust_julia_sets_test_no_repeats() {
        let julia = |re: f64, im: f64, tier| {
            let view = View::new(
                Fractal::Julia {
                    re: Coord::from_f64(re).unwrap(),
                    im: Coord::from_f64(im).unwrap(),
                },
                (Coord::default(), Coord::default()),
                Coord::from_f64(3.0).unwrap(),
                embedded_graphics::geometry::Size::new(320, 240),
                100,
            )
            .unwrap();
            Kernel::new(&view.with_tier(tier), Periodicity::Exact).plain
        };
        for tier in Tier::ALL {
            // 0 escapes at step 252 for −0.8 + 0.156i (in f64), past the cap of 100,
            // and at 15 for −0.8 + 0.2i; −0.1 + 0.1i is in the main cardioid.
            assert_eq!(julia(-0.8, 0.156, tier), 100, "{tier:?}");
            assert_eq!(julia(-0.8, 0.2, tier), 100, "{tier:?}");
            assert_eq!(julia(-0.1, 0.1, tier), FIRST_SAVE, "{tier:?}");
        }
    }

    /// The smooth value follows its rule in 32-bit factors: a model in 128 bits steps z in
    /// Q20 (z² and 2xy rounded down) while both parts are below 256 and |z| < 256, then
    /// takes ν from |z|² of the Q8 parts, from escaped points of every size in 32 bits
    /// (Q28) and just beyond |z| = 2, c within ±3.5. It fails with 2xy taken down 20 bits
    /// from xy.
    #[test]
    fn the_smooth_value_follows_its_rule() {
        extern crate std;
        use proptest::prelude::*;
        let model = |n: u32, z: (i32, i32), c: (i32, i32), max: u32, inside: u32| -> u32 {
            const BAILOUT: i128 = 256 << 20;
            if n >= max {
                return inside;
            }
            let (cr, ci) = (i128::from(c.0) >> 8, i128::from(c.1) >> 8);
            let (mut x, mut y) = (i128::from(z.0) >> 8, i128::from(z.1) >> 8);
            let mut steps = 0;
            while steps < SMOOTH_STEPS && x.abs() < BAILOUT && y.abs() < BAILOUT {
                if x * x + y * y >= BAILOUT * BAILOUT {
                    break;
                }
                (x, y) = (((x * x - y * y) >> 20) + cr, ((2 * x * y) >> 20) + ci);
                steps += 1;
            }
            let (x, y) = (x >> 12, y >> 12);
            let modulus = u64::try_from(x * x + y * y).unwrap();
            // A point back below |z| = 1 (c beyond 2) has no ν: the least value.
            let Some(log_log) =
                log2(modulus, 16).and_then(|bits| log2(u64::try_from(bits).ok()?, LOG2_FRAC_BITS))
            else {
                return 1;
            };
            let nu = ((i64::from(n) + i64::from(steps) + 2) << LOG2_FRAC_BITS) - i64::from(log_log);
            let shift = LOG2_FRAC_BITS - SMOOTH_FRACTION_BITS;
            let value = (nu + (1 << (shift - 1))) >> shift;
            u32::try_from(value).unwrap_or(0).clamp(1, inside - 1)
        };
        let c = -(7 << 27)..=(7 << 27);
        // Escaped points: a part beyond 2, or |z| near 2 and beyond it.
        let near_two = (-(1i32 << 30)..(1 << 30), 0.0..std::f64::consts::TAU).prop_map(|(r, a)| {
            let r = f64::from(r.unsigned_abs() >> 6) + 2.0 * f64::from(1 << 28);
            ((r * a.cos()) as i32, (r * a.sin()) as i32)
        });
        let z = prop_oneof![(any::<i32>(), any::<i32>()), near_two];
        proptest!(|(z in z, c in (c.clone(), c), n in 0..300u32)| {
            prop_assert_eq!(smooth_value(n, z, c, 256, 257), model(n, z, c, 256, 257));
        });
    }
}
