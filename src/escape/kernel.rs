//! The dwell of one pixel: z ← z² + c in the view's fixed-point tier.
//!
//! Overflow cannot happen, by invariant: an orbit is only squared while |z|² ≤ 4 (so |x|,
//! |y| ≤ 2), and every c is within ±3.5 (checked by the view), so the next value is below
//! 7.5 and its square below 57: inside every tier's range (Q12 in i32, Q28 in i32 with the
//! high word of i64 squares (Q24) or whole i64 squares, Q60 in i64 with i128 squares). A
//! Julia start outside radius 2 escapes at once (|z₁| ≥ |z₀|² − |k| > 2 because |k| ≤ 2)
//! and is never squared.
//!
//! The deep tier's 64×64→128 products are built from 32-bit halves (see `mul_wide`), since
//! an i128 multiply is a library call on Cortex-M.
//!
//! Mirrored points have the same dwell by construction: a Mandelbrot point is iterated as
//! its twin in the upper half-plane (|im|), so products round down with a plain shift
//! instead of toward zero (which costs a correction per step). A Julia set's half turn
//! needs nothing: z₀ and −z₀ have the same z₁ however products round.
//!
//! Each tier is a type implementing [`Arithmetic`] (its value and product types, how it
//! multiplies and shifts back), and one generic [`orbit`] iterates them all. This replaced a
//! macro with nine positional parameters; measured under QEMU on the board scenes, the
//! generic kernel takes the same or fewer instructions per frame (Cortex-M0: −3 % on the
//! full view, −5.7 % on the Julia set; M4F: −1.3 % on the deep zoom), except the Julia set
//! on Cortex-M3, +3.4 %, where LLVM keeps the tolerance and the saved point on the stack
//! in the repeat-testing loop. Taking one step a turn there instead of two costs 10 % more
//! on M3 and M4F; the loops take two or four (see `orbit`).

use core::marker::PhantomData;
use core::ops::{Add, Sub};

use super::view::{Fractal, Parts, Shading, Tier, View, SMOOTH_FRACTION_BITS};
use crate::math::log::{log2, LOG2_FRAC_BITS};
#[cfg(tinyfractal_no_long_multiply)]
use crate::math::wide::twice_product_by_squares;
use crate::math::wide::{
    mul_high_i128, mul_i32_wide, mul_wide_in_line, shift_round, shift_round_i64,
};

/// Largest periodicity tolerance of a fast render, 2⁻²² in Q60 bits.
///
/// A tolerance of 1/16 of a pixel alone grows with the pixel: on a 1×1 view it was 0.2,
/// and orbits that escape later were called inside. Over 30,000 random small views, a cap
/// of 2⁻¹⁸ still changed a dwell, 2⁻²⁰ changed none; 2⁻²² leaves a margin of four. It
/// costs 22 % more iterations on the full view at 320×240 (interior orbits must converge
/// further) and nothing on zooms, whose 1/16 pixel is already smaller.
pub const MAX_FAST_TOLERANCE: i64 = 1 << 38;

/// The periodicity tolerance of a fast render with pixel spacing `spacing` (Q60 bits):
/// 1/16 of a pixel, at most [`MAX_FAST_TOLERANCE`].
pub(crate) const fn fast_tolerance(spacing: i64) -> i64 {
    let sixteenth = spacing >> 4;
    if sixteenth < MAX_FAST_TOLERANCE {
        sixteenth
    } else {
        MAX_FAST_TOLERANCE
    }
}

/// How an orbit that repeats is recognised (Brent: compare with a point saved at
/// iterations 64, 128, 256, ...; see `FIRST_SAVE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Periodicity {
    /// Only an exact repeat of the fixed-point orbit: it can never change a dwell.
    Exact,
    /// Within a tolerance (Q60 bits), tied to the pixel spacing: faster, may differ.
    Within(i64),
}

/// A pixel's result.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Orbit {
    /// The pixel's value: the dwell 1..=max, max meaning "did not escape"; or with smooth
    /// shading the normalised count in sixteenths, max·16 meaning "did not escape".
    pub(crate) dwell: u32,
    /// z ← z² + c steps taken.
    pub(crate) iterations: u32,
}

impl Orbit {
    /// Did not escape (a repeat, or the cap), found after `iterations` steps.
    #[inline(always)]
    const fn inside_after(kernel: &Kernel, iterations: u32) -> Self {
        Self {
            dwell: kernel.inside,
            iterations,
        }
    }
}

/// Which [`Arithmetic`] a kernel iterates in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Narrow,
    Medium,
    RoundedMedium,
    Standard,
    Deep,
    Wide,
}

/// One coordinate of a pixel's point in the tier's units, converted once per column or
/// row rather than once per pixel.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Part(pub(crate) i64);

/// What is the same for every pixel of a render, in the tier's units: converted once, so
/// a pixel costs its cardioid test and its iterations, nothing more.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Kernel {
    tier: Tier,
    /// The arithmetic the tier iterates in, for this fractal (see `RoundedMedium`).
    arithmetic: Kind,
    max: u32,
    /// The value of a point that does not escape (`max`, or `max`·16 when smooth).
    inside: u32,
    smooth: bool,
    /// The Julia parameter, or `None` for the Mandelbrot set.
    julia: Option<(i64, i64)>,
    /// How close a repeat must be (0: exactly).
    tolerance: i64,
    /// Steps before the first point is saved for the repeat test: FIRST_SAVE, or fewer if
    /// the cap is lower.
    plain: u32,
}

impl Kernel {
    /// The kernel of `view`, recognising repeats as `periodicity` says.
    pub(crate) fn new(view: &View, periodicity: Periodicity) -> Self {
        // A perturbation view rendered without a reference: `Render::new` documents it.
        let tier = match view.tier {
            Tier::Perturbation => Tier::Deep,
            tier => tier,
        };
        let frac = tier.frac_bits();
        let tolerance = match periodicity {
            Periodicity::Exact => 0,
            Periodicity::Within(bits) => bits,
        };
        let kernel = Self {
            tier,
            arithmetic: match (tier, view.fractal) {
                (Tier::Narrow, _) => Kind::Narrow,
                (Tier::Medium, Fractal::Mandelbrot) => Kind::Medium,
                (Tier::Medium, Fractal::Julia { .. }) => Kind::RoundedMedium,
                (Tier::Standard, _) => Kind::Standard,
                (Tier::Deep | Tier::Perturbation, _) => Kind::Deep,
                (Tier::Wide, _) => Kind::Wide,
            },
            max: view.max_iterations,
            inside: u32::from(view.inside_value()),
            smooth: view.shading == Shading::Smooth,
            julia: match view.fractal {
                Fractal::Mandelbrot => None,
                Fractal::Julia { re, im } => {
                    Some((from_q60(re.to_bits(), frac), from_q60(im.to_bits(), frac)))
                }
            },
            // A tolerance below one unit of the tier means exact comparison.
            tolerance: from_q60(tolerance, frac),
            plain: FIRST_SAVE.min(view.max_iterations),
        };
        if kernel.is_dust() {
            // No orbit settles into a cycle: its pixels are never tested for repeats.
            return Self {
                plain: kernel.max,
                ..kernel
            };
        }
        kernel
    }

    /// Whether this is a Julia set whose critical point 0 escapes (k outside the
    /// Mandelbrot set): dust, with no attracting cycle. Repeat tests there could only find
    /// rounding's own cycles (which never escape either, so an exact render keeps every
    /// dwell) or call a slow escape inside within a tolerance. The critical orbit runs to
    /// `CRITICAL_STEPS` whatever the view's cap: a parameter just outside the set escapes
    /// late (−0.8 + 0.156i, the boards' Julia set, at 252).
    fn is_dust(&self) -> bool {
        if self.julia.is_none() {
            return false;
        }
        let critical = Self {
            max: CRITICAL_STEPS,
            inside: u32::MAX,
            smooth: false,
            ..*self
        };
        critical.dwell(Part(0), Part(0)).dwell != u32::MAX
    }

    /// Whether a tile of this kernel's values may be drawn by tracing the outlines of its
    /// regions (see `schedule`): a Mandelbrot view's dwells. Every set of points with
    /// dwell above k is connected there, so a region lies inside another only where a
    /// pixel grid breaks a connection narrower than a pixel. A Julia set's filaments break
    /// often at display sizes (the boards' Julia set at 320×240 lost 50 pixels, and with
    /// them more agreement with an f64 model than the f32 loop loses), and smooth values
    /// change every few cells, where following outlines cost more than subdivision's
    /// scans (the boards' smooth view at 128×64: 25 % more on Cortex-M4F).
    pub(crate) const fn traceable(&self) -> bool {
        self.julia.is_none() && !self.smooth
    }

    /// The tier the kernel computes in.
    pub(crate) const fn tier(&self) -> Tier {
        self.tier
    }

    /// A point coordinate (Q60, within ±3.5 as the view guarantees) ready for
    /// [`dwell`](Self::dwell).
    pub(crate) fn part(&self, q60: i64) -> Part {
        Part(from_q60(q60, self.tier.frac_bits()))
    }

    /// [`part`](Self::part) of each coordinate of `q60s`, into `parts`: the rounding's
    /// shift and half found once, not once a coordinate (on the Cortex-M4F, the full
    /// view's coordinates took 33 instructions each, where a part at a time took 72).
    pub(crate) fn fill_parts(&self, q60s: Parts, parts: &mut [Part]) {
        // As `shift_round_i64`, half away from zero (`Deep`: no shift, half 0). Nothing
        // wraps in the view (|q60| ≤ 3.5·2⁶⁰); past its edge the parts are not used.
        let shift = 60u32.saturating_sub(self.tier.frac_bits());
        let half = (1i64 << shift) >> 1;
        let round = |q60: i64, shift: u32| {
            Part(if q60 >= 0 {
                q60.wrapping_add(half) >> shift
            } else {
                (half.wrapping_sub(q60) >> shift).wrapping_neg()
            })
        };
        // Q28's shift by a constant 32: a word, not a double-word shift.
        if shift == 32 {
            for (slot, q60) in parts.iter_mut().zip(q60s) {
                *slot = round(q60, 32);
            }
        } else {
            for (slot, q60) in parts.iter_mut().zip(q60s) {
                *slot = round(q60, shift);
            }
        }
    }

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
    /// The 32-bit tiers' orbit in line where there is a long multiply (with four steps a
    /// turn in Brent's stretches: the full view at 320×240 took 2.3 % fewer instructions on
    /// Cortex-M4F than with a call, the Julia set 1.8 %). `Deep` stays a call: in line, the
    /// deep zoom took 10 % more; so does every tier on Cortex-M0, whose full view took 0.9 %
    /// more in line.
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

/// Q60 to `frac` fractional bits, rounded half away from zero (so negation commutes).
const fn from_q60(bits: i64, frac: u32) -> i64 {
    if frac >= 60 {
        bits
    } else {
        shift_round_i64(bits, 60 - frac)
    }
}

/// A tier's value type (`i32`, `i64` or `i128`): the few operations the orbit needs
/// beyond arithmetic, with their unsigned twins.
trait Word: Copy + Add<Output = Self> + Sub<Output = Self> {
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
trait Arithmetic {
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
    /// Whether a step is a few 32-bit multiplies: then the repeat-testing loop takes four
    /// steps a turn and tests once, which leaves the turn's constants in registers (the
    /// full view at 320×240, measured with the cells' orbit in line: 11 % fewer
    /// instructions on Cortex-M4F, 5 % on M3). A 64-bit tier keeps a test after each step:
    /// four a turn spilled its values, 8 % more for the deep zoom. Every core tests the
    /// same steps, so every core counts the same iterations (Cortex-M0: 2 % fewer
    /// instructions for the full view).
    const WORD_STEPS: bool = false;
    /// Whether the orbit takes one step a turn: `Wide`, whose steps are calls, and whose
    /// unrolled loops did not fit the LM3S6965's flash.
    const COMPACT: bool = false;
}

/// Q12 in i32 with 32-bit products (Q24).
struct Narrow;
/// Q28 in i32 whose products keep their high word (Q24), shifted back into Q28 with c's
/// low bits added: |x² − y²| ≤ 4 and |xy| ≤ 2 while the orbit runs, so nothing overflows.
/// Rounded down or half up (`ROUNDED`): see `Medium` and `RoundedMedium`.
struct HighWord<const ROUNDED: bool>;
/// The Mandelbrot set's `Medium`: products rounded down (the upper register of `smull`),
/// 2xy as xy doubled. The views it is chosen for keep every dwell.
type Medium = HighWord<false>;
/// `Medium` for Julia sets: each product's high word rounded half up, and 2xy as the
/// high word of x·2y (one bit more). Truncated products bias a long orbit; rounded, the
/// 320×240 Julia views at 100 iterations keep as many dwells as a naive `f32` loop
/// (docs/tiers.md), at one instruction a product on Cortex-M4 as truncated (`smmulr`, and
/// `smmlar` for the escape test's sum). Elsewhere rounding costs an add a product, which
/// the Mandelbrot set's `Medium` views (already exact) are spared: rounded, the full view
/// at 128×64 took 10 % more instructions on Cortex-M3.
type RoundedMedium = HighWord<true>;
/// Q28 in i32 with exact 64-bit products (Q56).
struct Standard;
/// Q60 in i64 with exact 128-bit products (Q120).
struct Deep;
/// Q124 in i128 whose 256-bit products keep their high halves (Q120, rounded down):
/// twice `Deep`'s bits, for the long orbits of deep views where 60 bits are not enough.
/// |x|, |y| < 7.5 (below 2¹²⁷ in Q124), and a sum of two squares below 114 (below 2¹²⁷
/// in Q120): nothing overflows.
struct Wide;

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
    /// doubling xy's. Truncated: xy's doubled, one instruction fewer.
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
    /// of being joined first: the same bits as `(p >> 28) + c`, one instruction fewer a
    /// product. Not on a 64-bit host, where the plain form was 20 % faster.
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
    /// (a store and a load, at escape only): as a call out of line it cost 25 instructions
    /// a pixel, 1.5 % of the Julia set at 320×240 on Cortex-M4F and 5.7 % of the full view.
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
}

/// `c + (p >> shift)` in an i32 (0 < shift < 32; the sum fits, as the orbit's invariant
/// guarantees), from p's words: `c + (high << (32 − shift)) + (low >> shift)`.
#[cfg(any(test, all(target_arch = "arm", not(tinyfractal_no_long_multiply))))]
#[inline(always)]
fn plus_shifted(c: i32, p: i64, shift: u32) -> i32 {
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
}

/// Q60 in i64 whose products keep their high words, in Q56: from 32-bit halves, the
/// low halves' product dropped (below a quarter of a unit) and the cross products'
/// sum floored, so each is within 2^-55 of the exact one, in three 32×32 products
/// instead of `Deep`'s four with 128-bit sums. While the orbit runs |x|, |y| ≤ 2, so
/// x² − y² and 2xy shift back into Q60 without overflow; a square of the next point
/// (below 7.5) stays below 2^62, and the sum of two below 2^63. Not a tier of its own:
/// only a perturbed pixel's finish, where neighbouring pixels' orbits are already far
/// more than a spacing apart (the perturbation module's rule).
struct HighWords;

impl HighWords {
    /// (a·b) >> 64 (Q120 to Q56), within 1.25 units below or a quarter above.
    #[inline(always)]
    fn product(a: i64, b: i64) -> i64 {
        // Balanced halves: a = high·2^32 + low with low in [-2^31, 2^31), so every partial
        // product is a signed 32×32 one; |high| < 2^31 for |a| < 8 (Q60).
        let split = |v: i64| (((v - i64::from(v as i32)) >> 32) as i32, v as i32);
        let ((ah, al), (bh, bl)) = (split(a), split(b));
        // Each cross product is below 2^62 in magnitude: their sum fits.
        let cross = mul_i32_wide(ah, bl) + mul_i32_wide(al, bh);
        mul_i32_wide(ah, bh) + (cross >> 32)
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
    /// first steps the series skipped. Escape only: testing repeats there as `orbit`
    /// does was measured at the deep-zoom view, found none and cost 30 % more
    /// instructions on Cortex-M3.
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
        Orbit {
            dwell: if self.smooth {
                let q28 = |(x, y): (i64, i64)| (HighWords::q28(x), HighWords::q28(y));
                smooth_value(n, q28((z.x, z.y)), q28(c), self.max, self.inside)
            } else {
                n.max(1)
            },
            iterations: n,
        }
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
    let max = kernel.max;
    let (re, im) = (A::Value::from_units(re), A::Value::from_units(im));
    let julia = if TRACEABLE { None } else { kernel.julia };
    let ((cr, ci), (x, y), steps) = match julia {
        None => {
            if in_cardioid_or_bulb(A::q28(re), A::q28(im)) {
                return Orbit::inside_after(kernel, 0);
            }
            // The upper half-plane twin: the same dwell, exactly (see the module docs). The
            // first step is free: z₁ = c.
            let c = (re, im.abs());
            (c, c, 1)
        }
        Some((kr, ki)) => (
            (A::Value::from_units(kr), A::Value::from_units(ki)),
            (re, im),
            0,
        ),
    };
    let mut z = Z::<A>::new(x, y);
    // The value of an orbit that escaped at step n (c passed by value: a closure that
    // captured it kept it in memory, stored on every pixel's way in).
    let escaped_at = |n: u32, z: &Z<A>| escaped::<A, TRACEABLE>(kernel, n, (z.x, z.y), (cr, ci));
    if z.escaped() {
        return escaped_at(steps, &z);
    }
    let tolerance = A::Value::from_units(kernel.tolerance);
    // Orbit points compared have |x|, |y| ≤ 2, so nothing wraps.
    let span = tolerance.twice();
    // Most points escape within the first few steps: they run without repeat tests.
    let plain = kernel.plain;
    let mut n = steps;
    if A::COMPACT {
        // The same steps and tests as below, one step a turn.
        while n < plain {
            n += 1;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
        }
        let (mut saved, mut next_save) = ((z.x, z.y), plain);
        while n < max {
            if n == next_save {
                saved = (z.x.wrapping_sub(tolerance), z.y.wrapping_sub(tolerance));
                next_save *= 2;
            }
            n += 1;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
            if z.repeats(saved, span) {
                return Orbit::inside_after(kernel, n);
            }
        }
        return Orbit::inside_after(kernel, max);
    }
    // Where there is a long multiply, turns of the loops are counted down (one
    // subtraction and branch a turn; n found again on leaving), four steps a turn before
    // the repeat tests start: the Julia set at 320×240 on Cortex-M4F took 1.7 % fewer
    // instructions than with two a turn. On Cortex-M0 (eight low registers, products
    // from halves) the extra counter spilled (four a turn cost the Julia set 25 % more,
    // counting down 3–5 %), so it keeps two a turn counted by n.
    // Turns of four steps up to `stop`, counted down, each step tested for escape and
    // each turn ended by `$after` (given the steps done before the turn).
    #[cfg(not(tinyfractal_no_long_multiply))]
    macro_rules! fours_until {
        ($stop:expr, |$done:ident| $after:block) => {{
            let fours = $stop.saturating_sub(n) / 4;
            let mut left = fours;
            while left > 0 {
                let $done = n + 4 * (fours - left);
                for k in 1..=4 {
                    if z.step(cr, ci) {
                        return escaped_at($done + k, &z);
                    }
                }
                $after
                left -= 1;
            }
            n += 4 * fours;
        }};
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        fours_until!(plain, |_done| {});
        // At most three more, each tested and unrolled: a counted loop here cost the
        // Mandelbrot set's first stretch (then 15 steps) more than the fours saved.
        for _ in 0..3 {
            if n < plain {
                n += 1;
                if z.step(cr, ci) {
                    return escaped_at(n, &z);
                }
            }
        }
    }
    #[cfg(tinyfractal_no_long_multiply)]
    {
        while n + 1 < plain {
            if z.step(cr, ci) {
                return escaped_at(n + 1, &z);
            }
            n += 2;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
        }
        if n < plain {
            n += 1;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
        }
    }
    // At most 2·max ≤ 2^17 (the view caps max at u16::MAX): it cannot overflow.
    let mut next_save = 2 * plain;
    while n < max {
        // The saved point, less the tolerance: x − saved + tolerance in one step.
        let saved = (z.x.wrapping_sub(tolerance), z.y.wrapping_sub(tolerance));
        let stop = next_save.min(max);
        // Counted as above.
        #[cfg(not(tinyfractal_no_long_multiply))]
        {
            if A::WORD_STEPS {
                // Four steps a turn and one repeat test, at 4k steps after the save: a
                // cycle of period p is still found, at most 3p steps later.
                fours_until!(stop, |done| {
                    if z.repeats(saved, span) {
                        return Orbit::inside_after(kernel, done + 4);
                    }
                });
            } else {
                // Two steps a turn, each tested.
                let pairs = stop.saturating_sub(n) / 2;
                let mut left = pairs;
                while left > 0 {
                    let done = n + 2 * (pairs - left);
                    if z.step(cr, ci) {
                        return escaped_at(done + 1, &z);
                    }
                    if z.repeats(saved, span) {
                        return Orbit::inside_after(kernel, done + 1);
                    }
                    if z.step(cr, ci) {
                        return escaped_at(done + 2, &z);
                    }
                    if z.repeats(saved, span) {
                        return Orbit::inside_after(kernel, done + 2);
                    }
                    left -= 1;
                }
                n += 2 * pairs;
            }
        }
        // The same turns as above, counted by n (see the first stretch).
        #[cfg(tinyfractal_no_long_multiply)]
        if A::WORD_STEPS {
            while n + 3 < stop {
                if z.step(cr, ci) {
                    return escaped_at(n + 1, &z);
                }
                if z.step(cr, ci) {
                    return escaped_at(n + 2, &z);
                }
                if z.step(cr, ci) {
                    return escaped_at(n + 3, &z);
                }
                n += 4;
                if z.step(cr, ci) {
                    return escaped_at(n, &z);
                }
                if z.repeats(saved, span) {
                    return Orbit::inside_after(kernel, n);
                }
            }
        }
        #[cfg(tinyfractal_no_long_multiply)]
        while !A::WORD_STEPS && n + 1 < stop {
            if z.step(cr, ci) {
                return escaped_at(n + 1, &z);
            }
            if z.repeats(saved, span) {
                return Orbit::inside_after(kernel, n + 1);
            }
            n += 2;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
            if z.repeats(saved, span) {
                return Orbit::inside_after(kernel, n);
            }
        }
        if n < stop {
            n += 1;
            if z.step(cr, ci) {
                return escaped_at(n, &z);
            }
            if z.repeats(saved, span) {
                return Orbit::inside_after(kernel, n);
            }
        }
        next_save *= 2;
    }
    Orbit::inside_after(kernel, max)
}

/// The value of an orbit of c that escaped at step `n` at z.
#[inline(always)]
fn escaped<A: Arithmetic, const TRACEABLE: bool>(
    kernel: &Kernel,
    n: u32,
    (x, y): (A::Value, A::Value),
    (cr, ci): (A::Value, A::Value),
) -> Orbit {
    Orbit {
        dwell: if !TRACEABLE && kernel.smooth {
            smooth_value(
                n,
                (A::q28(x), A::q28(y)),
                (A::q28(cr), A::q28(ci)),
                kernel.max,
                kernel.inside,
            )
        } else {
            n.max(1)
        },
        iterations: n,
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
/// In i64, Q20: a point is only squared while |x|, |y| < 256, so squares stay below 2⁵⁶;
/// the next point is below 2¹⁷ (Q20: 2³⁷), and its |z|² is taken in Q16 from Q8 parts.
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
        let (x2, y2) = (x * x, y * y);
        if (x2 + y2).unsigned_abs() >= BAILOUT * BAILOUT {
            break;
        }
        (x, y) = (((x2 - y2) >> 20) + cr, ((2 * x * y) >> 20) + ci);
        steps += 1;
    }
    let (x, y) = (x >> 12, y >> 12);
    // |z|² is above 4 (the orbit escaped), so both logarithms are positive.
    let modulus = (x * x + y * y).unsigned_abs();
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

/// Steps before the first point is saved for the repeat test: most points escape before,
/// and a plain step costs 12 instructions on Cortex-M4F against 14.5 in Brent's stretches
/// (the full view at 320×240 1.8 % fewer instructions than from 16 on, the 128×64 view
/// 2.7 %; the zoom scene 0.6 % more, its interior pixels found later).
const FIRST_SAVE: u32 = 64;

/// Steps of a Julia parameter's critical orbit that decide whether the set is dust (see
/// [`Kernel::new`]): once per render, a few thousand instructions at most where it escapes.
const CRITICAL_STEPS: u32 = 1024;

/// The high word of the exact product of two i32, rounded down (Q28 × Q28 → Q24): the
/// upper register of `smull`.
#[inline(always)]
fn high_word(a: i32, b: i32) -> i32 {
    (mul_i32_wide(a, b) >> 32) as i32
}

/// The high word of the exact product of two i32, rounded half up (Q28 × Q28 → Q24):
/// `smmulr` on Cortex-M4; elsewhere the high word plus the low word's top bit, one add
/// after `smull` (LLVM makes three more instructions of the 64-bit sum there).
#[inline(always)]
fn rounded_high_word(a: i32, b: i32) -> i32 {
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
fn standard_twice_xy(x: i32, y: i32, x2: i64, y2: i64) -> i32 {
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

/// Inside the main cardioid or the period-2 bulb, decided in Q28 with 64-bit products (no
/// 128-bit library calls on Cortex-M) and a margin of 2⁻²⁰, which covers every rounding
/// below (at most about 2⁻²¹·⁷): a point it accepts is inside for certain, and a point on
/// or next to the boundary is iterated instead. |x|, |y| ≤ 3.5 (the view's limit), so every
/// value below fits its type.
// In line: a call from each tier's subdivision cost the full view 4 % on Cortex-M4F.
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
}
