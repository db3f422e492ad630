//! One step of each attractor in its fixed point: the maps' equations as [`Kind`] states
//! them, the flows' derivatives times Δt, and the Euler and Runge–Kutta steps over them.
//! Products round down; a value that leaves 32 bits ends the step with `None`.

use super::fixed::{
    cos, cos_q30, high_word, mul, mul_narrow, narrow, scaled_rate, sin, sin_q30, times_q30,
    to_fixed,
};
use super::kind::{Kind, Method};
use super::value::{Checked, Ranges, SafeBox, Unchecked, Value, Word};
use crate::error::{Error, ParameterError};
use crate::math::trig::{binary_angle_of_radians, binary_angle_of_tangent, sin_of_binary};
use crate::math::Real;

/// A state: x, y, z in the kind's fixed point (z is 0 for the 2D maps).
pub(crate) type State = [i32; 3];

/// The Hénon map's fraction bits (and so on: [`Kind::fraction_bits`]).
const HENON: u32 = Kind::Henon.fraction_bits();
const TRIG: u32 = Kind::Clifford.fraction_bits();
const WIDE: u32 = Kind::GumowskiMira.fraction_bits();
const HOP: u32 = Kind::Hopalong.fraction_bits();
const FLOW: u32 = Kind::Lorenz.fraction_bits();

/// An attractor's step with its parameters in its fixed point (for a flow, already
/// multiplied by Δt).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Stepper {
    Henon {
        a: i32,
        b: i32,
    },
    Clifford([i32; 4]),
    DeJong([i32; 4]),
    Pickover([i32; 4]),
    Hopalong {
        a: i32,
        b: i32,
        c: i32,
    },
    Martin {
        a: i32,
    },
    GumowskiMira {
        a: i32,
        b: i32,
        c: i32,
        twice_one_less_c: i32,
    },
    Popcorn {
        h: i32,
    },
    Lorenz {
        flow: Lorenz,
        method: Method,
    },
    Rossler {
        flow: Rossler,
        method: Method,
    },
}

/// The Lorenz flow's rates times Δt.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Lorenz {
    dt: i32,
    sigma_dt: i32,
    rho_dt: i32,
    beta_dt: i32,
}

/// The Rössler flow's rates times Δt.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Rossler {
    dt: i32,
    a_dt: i32,
    b_dt: i32,
    c: i32,
}

/// A parameter (or a rate times Δt) in a kind's fixed point, or the error naming it.
fn fixed(kind: Kind, value: Real) -> Result<i32, Error> {
    let max = kind.range();
    match to_fixed(value, kind.fraction_bits()) {
        Some(bits) if bits.unsigned_abs() < 1 << 31 => Ok(bits),
        _ => Err(Error::Parameter(ParameterError::AttractorValueOutOfRange {
            value,
            max,
        })),
    }
}

/// `a·b` for set-up, in `Real` (a rate times Δt), or the error naming it.
fn product(kind: Kind, a: Real, b: Real) -> Result<i32, Error> {
    let value =
        a.checked_mul(b)
            .ok_or(Error::Parameter(ParameterError::AttractorValueOutOfRange {
                value: a,
                max: kind.range(),
            }))?;
    fixed(kind, value)
}

impl Stepper {
    /// The step of `kind` with parameters `p` (a, b, c, d), time step `dt` and `method`.
    pub(crate) fn new(kind: Kind, p: [Real; 4], dt: Real, method: Method) -> Result<Self, Error> {
        let f = |value: Real| fixed(kind, value);
        let all = || -> Result<[i32; 4], Error> { Ok([f(p[0])?, f(p[1])?, f(p[2])?, f(p[3])?]) };
        Ok(match kind {
            Kind::Henon => Self::Henon {
                a: f(p[0])?,
                b: f(p[1])?,
            },
            Kind::Clifford => Self::Clifford(all()?),
            Kind::DeJong => Self::DeJong(all()?),
            Kind::Pickover => Self::Pickover(all()?),
            Kind::Hopalong => Self::Hopalong {
                a: f(p[0])?,
                b: f(p[1])?,
                c: f(p[2])?,
            },
            Kind::Martin => Self::Martin { a: f(p[0])? },
            Kind::GumowskiMira => Self::GumowskiMira {
                a: f(p[0])?,
                b: f(p[1])?,
                c: f(p[2])?,
                twice_one_less_c: f(Real::from_int(2).saturating_sub(p[2].saturating_add(p[2])))?,
            },
            Kind::Popcorn => Self::Popcorn { h: f(p[0])? },
            Kind::Lorenz => Self::Lorenz {
                flow: Lorenz {
                    dt: f(dt)?,
                    sigma_dt: product(kind, p[0], dt)?,
                    rho_dt: product(kind, p[1], dt)?,
                    beta_dt: product(kind, p[2], dt)?,
                },
                method,
            },
            Kind::Rossler => Self::Rossler {
                flow: Rossler {
                    dt: f(dt)?,
                    a_dt: product(kind, p[0], dt)?,
                    b_dt: product(kind, p[1], dt)?,
                    c: f(p[2])?,
                },
                method,
            },
        })
    }

    /// The state after `s`, or `None` where a value leaves the fixed-point range.
    #[inline]
    pub(crate) fn step(&self, s: State) -> Option<State> {
        self.with_step(Once(s))
    }
}

/// One step from a state: [`Stepper::step`] through the same dispatch as the loops.
struct Once(State);

impl WithStep for Once {
    type Output = Option<State>;
    const MANY_STEPS: bool = false;

    #[inline(always)]
    fn with<const THREE: bool>(self, step: impl Fn(State) -> Option<State>) -> Option<State> {
        step(self.0)
    }
}

/// What runs with a kind's step as a plain function ([`Stepper::with_step`]), so that
/// the step is inlined into the loop that calls it instead of dispatched on the kind at
/// every point.
pub(crate) trait WithStep {
    /// What the run gives back.
    type Output;
    /// Whether the run takes many steps, so that a set-up which makes each cheaper pays.
    const MANY_STEPS: bool;
    /// Runs with `step`, the kind's step; `THREE` for a kind of three dimensions.
    fn with<const THREE: bool>(self, step: impl Fn(State) -> Option<State>) -> Self::Output;
}

impl Stepper {
    /// Runs `run` with this kind's step: one dispatch on the kind, then a loop of its own
    /// for each kind.
    #[inline]
    pub(crate) fn with_step<W: WithStep>(&self, run: W) -> W::Output {
        match *self {
            // The usual parameters inlined; others through a call (a loop of each costs
            // flash the micro:bit does not have).
            Self::Henon { a, b } => match (scaled_rate::<HENON>(b), quartered(a)) {
                // Inlined at both of a loop's steps (the transient's and the points'),
                // where ARMv6-M would otherwise call it.
                (Some(b_scaled), Some(a4)) => run.with::<false>(
                    #[inline(always)]
                    move |s| henon_quick(a, a4, b_scaled, s),
                ),
                (Some(b_scaled), None) => run.with::<false>(move |s| henon_small_b(a, b_scaled, s)),
                (None, _) => run.with::<false>(move |s| henon_called(a, b, s)),
            },
            Self::Clifford(p) => run.with::<false>(move |s| clifford(p, s)),
            Self::DeJong(p) => run.with::<false>(move |s| de_jong(p, s)),
            Self::Pickover(p) => run.with::<true>(move |s| pickover(p, s)),
            Self::Hopalong { a, b, c } => run.with::<false>(move |s| hopalong(a, b, c, s)),
            Self::Martin { a } => run.with::<false>(move |s| martin(a, s)),
            Self::GumowskiMira {
                a,
                b,
                c,
                twice_one_less_c,
            } => run.with::<false>(move |s| gumowski_mira([a, b, c, twice_one_less_c], s)),
            Self::Popcorn { h } => run.with::<false>(move |s| popcorn(h, s)),
            Self::Lorenz { flow, method } => match flow.small_rates() {
                // A loop of many steps finds the box it may step in unchecked, once.
                Some(small) => match W::MANY_STEPS.then(|| small.safe_box(flow.dt, method)) {
                    Some(Some(safe)) => {
                        run.with::<true>(move |s| small.integrate_within(safe, method, s))
                    }
                    _ => run.with::<true>(move |s| integrate(&small, method, s)),
                },
                None => run.with::<true>(move |s| integrate_called(&flow, method, s)),
            },
            Self::Rossler { flow, method } => {
                run.with::<true>(move |s| integrate(&flow, method, s))
            }
        }
    }
}

/// The largest |x| whose square, with [`HENON`] fraction bits, fits 32 bits.
const HENON_LARGEST_SQUARABLE: u32 = ((1u64 << (31 + HENON)) - 1).isqrt() as u32;

/// x² with [`HENON`] fraction bits, or `None` beyond 32 bits: `narrow(mul(x, x))`, the
/// range checked on x itself so that the square stays a 32-bit value for the next product.
#[inline(always)]
fn henon_square(x: i32) -> Option<i32> {
    if x.unsigned_abs() > HENON_LARGEST_SQUARABLE {
        return None;
    }
    Some(mul::<HENON>(x, x) as i32)
}

/// Hénon's x′ = 1 − a·x² + y.
#[inline(always)]
fn henon_x(a: i32, x: i32, y: i32) -> Option<i32> {
    narrow((1 << HENON) + i64::from(y) - mul::<HENON>(a, henon_square(x)?))
}

/// x′ = 1 − a·x² + y, y′ = b·x.
#[inline(always)]
fn henon(a: i32, b: i32, [x, y, _]: State) -> Option<State> {
    Some([henon_x(a, x, y)?, narrow(mul::<HENON>(b, x))?, 0])
}

/// [`henon`] as a call of its own, for the parameters a loop does not inline.
#[inline(never)]
fn henon_called(a: i32, b: i32, s: State) -> Option<State> {
    henon(a, b, s)
}

/// [`henon`] with |b| below ½ given as a factor of [`high_word`]: y′ = b·x is one
/// product's high word, and never beyond 32 bits.
#[inline(always)]
fn henon_small_b(a: i32, b_scaled: i32, [x, y, _]: State) -> Option<State> {
    Some([henon_x(a, x, y)?, high_word(b_scaled, x), 0])
}

/// A bound on |x| below √2 with [`HENON`] fraction bits (so that x² is below 2, a quarter
/// of 32 bits' range): within it [`henon_quick`] takes each product as one high word.
/// 1.40625, wide of the attractor's ±1.3, and one comparison's immediate operand on
/// ARMv7-M, so that it takes no register.
const HENON_QUICK_LIMIT: u32 = 0x5a << (HENON - 6);
// A negative x may be one further out (see `henon_quick`).
const _: () = assert!((HENON_QUICK_LIMIT as u64 + 1).pow(2) < 1 << (2 * HENON + 1));

/// A parameter of [`HENON`] fraction bits below 2 as a factor of [`high_word`] beside a
/// value shifted the same: `a << 2`, or `None` where it does not fit.
fn quartered(a: i32) -> Option<i32> {
    a.checked_mul(4)
}

/// [`henon_small_b`] with |a| below 2 given as `a4` = `a << 2`: where |x| is within
/// [`HENON_QUICK_LIMIT`], x² and a·x² are each one product's high word (both factors
/// shifted left by two bits, so the high word is the product shifted right by the
/// fraction bits) and x′ a 32-bit sum checked once; elsewhere the checked step, out of
/// line. The same values as [`henon`].
#[inline(always)]
fn henon_quick(a: i32, a4: i32, b_scaled: i32, s: State) -> Option<State> {
    let [x, y, _] = s;
    // −limit − 1 ≤ x ≤ limit as one comparison: x with its sign's bits flipped is |x| − 1
    // for a negative x, |x| otherwise.
    if ((x ^ (x >> 31)) as u32) > HENON_QUICK_LIMIT {
        let [x_next, y_next] = henon_small_b_called(a, b_scaled, x, y)?;
        return Some([x_next, y_next, 0]);
    }
    let (a_x_squared, b_x) = henon_quick_products(a4, b_scaled, x);
    // |a·x²| < 2^30, so 1 − a·x² fits.
    let x_next = y.checked_add((1 << HENON) - a_x_squared)?;
    Some([x_next, b_x, 0])
}

/// [`henon_quick`]'s two products of x within its limit: a·x² (x² < 2, so its four times
/// fits) and b·x, each one product's high word where there is a long multiply.
#[inline(always)]
fn henon_quick_products(a4: i32, b_scaled: i32, x: i32) -> (i32, i32) {
    #[cfg(tinyfractal_no_long_multiply)]
    {
        henon_quick_halves(a4, b_scaled, x)
    }
    #[cfg(not(tinyfractal_no_long_multiply))]
    {
        let square = high_word(x << 2, x << 2);
        (high_word(a4, square << 2), high_word(b_scaled, x))
    }
}

/// [`henon_quick_products`] from 16-bit halves, in 32-bit sums the bounds on x keep from
/// overflowing: the square's, b·x's and a·x²'s middle products are summed whole, not
/// split again as a product of any two values must be.
///
/// With X = 4x = Xₕ·2¹⁶ + Xₗ (Xₗ unsigned, |Xₕ| < 0.71·2¹⁵), x² = Xₕ² + ⌊(Xₕ·Xₗ +
/// ⌊Xₗ²/2¹⁷⌋) / 2¹⁵⌋; b·x is b4·X for b4 a quarter of the scaled b (|b4| < 2²⁹), its
/// halves' middle products below 2³¹ together; a·x² is a4·S for S = 4x² < 2³¹·0.99, which
/// [`mul_high_near`](crate::math::wide::mul_high_near) takes.
#[cfg(any(test, tinyfractal_no_long_multiply))]
#[inline(always)]
fn henon_quick_halves(a4: i32, b_scaled: i32, x: i32) -> (i32, i32) {
    let wide = x << 2;
    let (high, low) = (wide >> 16, wide & 0xFFFF);
    let b4 = b_scaled >> 2;
    let (b_high, b_low) = (b4 >> 16, b4 & 0xFFFF);
    let below = ((b_low as u32) * (low as u32)) >> 16;
    let b_x = b_high * high + ((b_high * low + b_low * high + below as i32) >> 16);
    let low_square = ((low as u32) * (low as u32)) >> 17;
    let square = high * high + ((high * low + low_square as i32) >> 15);
    let a_x_squared = crate::math::wide::mul_high_near(a4, square << 2);
    (a_x_squared, b_x)
}

/// [`henon_small_b`] as a call of its own: [`henon_quick`]'s step beyond its limit.
/// The state comes and goes as two values, not an array in memory the loop would store
/// each step, and z stays the caller's 0.
#[cold]
#[inline(never)]
fn henon_small_b_called(a: i32, b_scaled: i32, x: i32, y: i32) -> Option<[i32; 2]> {
    let [x_next, y_next, _] = henon_small_b(a, b_scaled, [x, y, 0])?;
    Some([x_next, y_next])
}

/// x′ = sin(a·y) + c·cos(a·x), y′ = sin(b·x) + d·cos(b·y).
fn clifford([a, b, c, d]: [i32; 4], [x, y, _]: State) -> Option<State> {
    let (ax, ay) = (narrow(mul::<TRIG>(a, x))?, narrow(mul::<TRIG>(a, y))?);
    let (bx, by) = (narrow(mul::<TRIG>(b, x))?, narrow(mul::<TRIG>(b, y))?);
    let x_next = i64::from(sin::<TRIG>(ay)) + times_q30(c, cos_q30::<TRIG>(ax));
    let y_next = i64::from(sin::<TRIG>(bx)) + times_q30(d, cos_q30::<TRIG>(by));
    Some([narrow(x_next)?, narrow(y_next)?, 0])
}

/// x′ = sin(a·y) − cos(b·x), y′ = sin(c·x) − cos(d·y).
fn de_jong([a, b, c, d]: [i32; 4], [x, y, _]: State) -> Option<State> {
    let (ay, bx) = (narrow(mul::<TRIG>(a, y))?, narrow(mul::<TRIG>(b, x))?);
    let (cx, dy) = (narrow(mul::<TRIG>(c, x))?, narrow(mul::<TRIG>(d, y))?);
    let x_next = i64::from(sin::<TRIG>(ay)) - i64::from(cos::<TRIG>(bx));
    let y_next = i64::from(sin::<TRIG>(cx)) - i64::from(cos::<TRIG>(dy));
    Some([narrow(x_next)?, narrow(y_next)?, 0])
}

/// x′ = sin(a·y) − z·cos(b·x), y′ = z·sin(c·x) − cos(d·y), z′ = sin(x).
fn pickover([a, b, c, d]: [i32; 4], [x, y, z]: State) -> Option<State> {
    let (ay, bx) = (narrow(mul::<TRIG>(a, y))?, narrow(mul::<TRIG>(b, x))?);
    let (cx, dy) = (narrow(mul::<TRIG>(c, x))?, narrow(mul::<TRIG>(d, y))?);
    let x_next = i64::from(sin::<TRIG>(ay)) - times_q30(z, cos_q30::<TRIG>(bx));
    let y_next = times_q30(z, sin_q30::<TRIG>(cx)) - i64::from(cos::<TRIG>(dy));
    Some([narrow(x_next)?, narrow(y_next)?, sin::<TRIG>(x)])
}

/// x′ = y − sign(x)·√|b·x − c|, y′ = a − x; the root rounded down.
fn hopalong(a: i32, b: i32, c: i32, [x, y, _]: State) -> Option<State> {
    // |b·x − c| < 2⁴³ in HOP bits: shifted by HOP more it fits 64 bits.
    let inside = (mul::<HOP>(b, x) - i64::from(c)).unsigned_abs();
    let root = i64::try_from((inside << HOP).isqrt()).ok()?;
    let x_next = i64::from(y) - i64::from(x.signum()) * root;
    Some([narrow(x_next)?, narrow(i64::from(a) - i64::from(x))?, 0])
}

/// x′ = y − sin(x), y′ = a − x.
fn martin(a: i32, [x, y, _]: State) -> Option<State> {
    let x_next = i64::from(y) - i64::from(sin::<HOP>(x));
    Some([narrow(x_next)?, narrow(i64::from(a) - i64::from(x))?, 0])
}

/// G(x) = c·x + 2(1 − c)·x²/(1 + x²), the quotient rounded toward zero.
fn gumowski_mira_g(c: i32, twice_one_less_c: i32, x: i32) -> Option<i64> {
    let squared = mul::<WIDE>(x, x); // below 2^38: x is within ±128
    let share = narrow((squared << WIDE) / ((1 << WIDE) + squared))?;
    Some(mul::<WIDE>(c, x) + mul::<WIDE>(twice_one_less_c, share))
}

/// x′ = y + a·(1 − b·y²)·y + G(x), y′ = −x + G(x′).
fn gumowski_mira([a, b, c, twice_one_less_c]: [i32; 4], [x, y, _]: State) -> Option<State> {
    // b·y first: y² alone can leave the range where b·y² does not.
    let by = narrow(mul::<WIDE>(b, y))?;
    let damping = narrow((1 << WIDE) - mul::<WIDE>(by, y))?;
    let ay = narrow(mul::<WIDE>(a, y))?;
    let x_next =
        narrow(i64::from(y) + mul::<WIDE>(ay, damping) + gumowski_mira_g(c, twice_one_less_c, x)?)?;
    let y_next = narrow(gumowski_mira_g(c, twice_one_less_c, x_next)? - i64::from(x))?;
    Some([x_next, y_next, 0])
}

/// h·sin(v + tan 3v), in the popcorn's fixed point.
fn popcorn_term(h: i32, v: i32) -> Option<i64> {
    let triple = narrow(3 * i64::from(v))?;
    let tangent = binary_angle_of_tangent(sin_q30::<WIDE>(triple), cos_q30::<WIDE>(triple));
    let angle = binary_angle_of_radians(v, WIDE).wrapping_add(tangent);
    Some(times_q30(h, sin_of_binary(angle)))
}

/// x′ = x − h·sin(y + tan 3y), y′ = y − h·sin(x + tan 3x).
fn popcorn(h: i32, [x, y, _]: State) -> Option<State> {
    let x_next = narrow(i64::from(x) - popcorn_term(h, y)?)?;
    let y_next = narrow(i64::from(y) - popcorn_term(h, x)?)?;
    Some([x_next, y_next, 0])
}

/// A flow: its derivative at a state, times Δt.
trait Flow: Copy {
    /// Δt·f(s), or `None` where a value leaves the fixed-point range.
    fn delta(&self, s: State) -> Option<State>;
}

/// A flow's Δt·f in the values `V`, as the integrators take it.
trait Delta<V: Value> {
    /// Δt·f(s), or `None` where a value may leave 32 bits.
    fn delta_of(&self, s: [V; 3]) -> Option<[V; 3]>;
}

impl<F: Flow> Delta<Checked> for F {
    #[inline(always)]
    fn delta_of(&self, s: [Checked; 3]) -> Option<[Checked; 3]> {
        Some(self.delta(s.map(|v| v.0))?.map(Word::<true>))
    }
}

impl Delta<Unchecked> for SmallRateLorenz {
    #[inline(always)]
    fn delta_of(&self, s: [Unchecked; 3]) -> Option<[Unchecked; 3]> {
        self.delta_in(s)
    }
}

impl Delta<Ranges> for SmallRateLorenz {
    fn delta_of(&self, s: [Ranges; 3]) -> Option<[Ranges; 3]> {
        self.delta_in(s)
    }
}

impl Flow for Lorenz {
    /// Δt·(σ(y − x), x(ρ − z) − y, x·y − β·z).
    #[inline(always)]
    fn delta(&self, [x, y, z]: State) -> Option<State> {
        let dx = mul_narrow::<FLOW>(self.sigma_dt, y.checked_sub(x)?)?;
        // 0 < Δt ≤ 1: the products are no larger than y and z.
        let y_dt = mul::<FLOW>(self.dt, y) as i32;
        let z_dt = mul::<FLOW>(self.dt, z) as i32;
        let dy = mul_narrow::<FLOW>(x, self.rho_dt.checked_sub(z_dt)?)?.checked_sub(y_dt)?;
        let dz = mul_narrow::<FLOW>(x, y_dt)?.checked_sub(mul_narrow::<FLOW>(self.beta_dt, z)?)?;
        Some([dx, dy, dz])
    }
}

impl Lorenz {
    /// The same flow with its rates as factors of [`high_word`], where every rate and Δt
    /// is below ½ (the usual time steps).
    fn small_rates(&self) -> Option<SmallRateLorenz> {
        Some(SmallRateLorenz {
            dt: scaled_rate::<FLOW>(self.dt)?,
            sigma_dt: scaled_rate::<FLOW>(self.sigma_dt)?,
            rho_dt: self.rho_dt,
            beta_dt: scaled_rate::<FLOW>(self.beta_dt)?,
        })
    }
}

/// The Lorenz flow with Δt, σΔt and βΔt below ½, scaled to 32 fraction bits: a product
/// by one of them is the high word of one multiply, exactly [`Lorenz`]'s value, and
/// smaller than the other factor (so never beyond 32 bits).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct SmallRateLorenz {
    dt: i32,
    sigma_dt: i32,
    rho_dt: i32,
    beta_dt: i32,
}

impl Flow for SmallRateLorenz {
    /// [`Lorenz::delta`]'s values and checks, its rate products each one multiply's high
    /// word (what that saves: docs/performance.md, The attractors against the sketches).
    #[inline(always)]
    fn delta(&self, s: State) -> Option<State> {
        Some(self.delta_in(s.map(Word::<true>))?.map(|v| v.0))
    }
}

impl SmallRateLorenz {
    /// [`delta`](Flow::delta) in any [`Value`]: Δt·(σ(y − x), x(ρ − z) − y, x·y − β·z).
    #[inline(always)]
    fn delta_in<V: Value>(&self, [x, y, z]: [V; 3]) -> Option<[V; 3]> {
        let dx = y.sub(x)?.rate(self.sigma_dt);
        let y_dt = y.rate(self.dt);
        let z_dt = z.rate(self.dt);
        let dy = x.times::<FLOW>(V::of(self.rho_dt).sub(z_dt)?)?.sub(y_dt)?;
        let dz = x.times::<FLOW>(y_dt)?.sub(z.rate(self.beta_dt))?;
        Some([dx, dy, dz])
    }

    /// A box of states around the attractor from which a step by `method` is proven to
    /// stay in 32 bits (`dt`, Δt in [`FLOW`] fraction bits, finds ρ), or `None`.
    ///
    /// The box is centred on the equilibria's height z = ρ − 1 (at least 0), with
    /// half-widths t·u, 4t·u/3 and 6t·u/5 for x, y and z, u = ρ − 1 (at least 1): about
    /// the attractor's proportions for σ = 10 and β = 8/3. The largest t of 5/4, 1, 3/4,
    /// 1/2 and 1/4 whose box [`Ranges`] prove safe is taken.
    fn safe_box(&self, dt: i32, method: Method) -> Option<SafeBox> {
        let one = 1i64 << FLOW;
        let rho = (i64::from(self.rho_dt) << FLOW).checked_div(i64::from(dt).max(1))?;
        let (centre, unit) = ((rho - one).max(0), (rho - one).max(one));
        [5, 4, 3, 2, 1].into_iter().find_map(|quarters| {
            let reach = |numerator: i64, denominator: i64| {
                Some(unit.checked_mul(quarters * numerator)? / (4 * denominator))
            };
            let range = |middle: i64, half: Option<i64>| {
                let half = half?;
                let end = |v: i64| i32::try_from(v).ok();
                Some(Ranges::new(end(middle - half)?, end(middle + half)?))
            };
            let ranges = [
                range(0, reach(1, 1))?,
                range(0, reach(4, 3))?,
                range(centre, reach(6, 5))?,
            ];
            SafeBox::proven(ranges, |r| integrate_in(self, method, r))
        })
    }

    /// One step by `method`: unchecked from a state in `safe`, checked elsewhere; the
    /// same values either way.
    #[inline(always)]
    fn integrate_within(&self, safe: SafeBox, method: Method, s: State) -> Option<State> {
        if safe.contains(s) {
            let step = integrate_in(self, method, s.map(Word::<false>))?;
            Some(step.map(|v| v.0))
        } else {
            integrate(self, method, s)
        }
    }
}

impl Flow for Rossler {
    /// Δt·(−(y + z), x + a·y, b + z(x − c)).
    #[inline(always)]
    fn delta(&self, [x, y, z]: State) -> Option<State> {
        let dx = -mul::<FLOW>(self.dt, y.checked_add(z)?);
        let dy = mul::<FLOW>(self.dt, x) + mul::<FLOW>(self.a_dt, y);
        // 0 < Δt ≤ 1: the product is no larger than x − c, which fits 32 bits.
        let x_less_c_dt = mul::<FLOW>(self.dt, x.checked_sub(self.c)?) as i32;
        let dz = i64::from(self.b_dt) + mul::<FLOW>(z, x_less_c_dt);
        Some([narrow(dx)?, narrow(dy)?, narrow(dz)?])
    }
}

/// `s + k`, each coordinate checked.
#[inline(always)]
fn ahead<V: Value>([x, y, z]: [V; 3], [dx, dy, dz]: [V; 3]) -> Option<[V; 3]> {
    Some([x.add(dx)?, y.add(dy)?, z.add(dz)?])
}

/// `s + k/2`, the halves rounded down.
#[inline(always)]
fn half_ahead<V: Value>(s: [V; 3], [dx, dy, dz]: [V; 3]) -> Option<[V; 3]> {
    ahead(s, [dx.half(), dy.half(), dz.half()])
}

/// One coordinate of RK4's step: s + (k₁ + 2k₂ + 2k₃ + k₄)/6, each sum checked.
#[inline(always)]
fn combined<V: Value>(s: V, k1: V, k2: V, k3: V, k4: V) -> Option<V> {
    let middle = k2.add(k3)?;
    let sum = k1.add(k4)?.add(middle)?.add(middle)?;
    s.add(sum.sixth())
}

/// One step of `flow` by `method`, checked.
#[inline(always)]
fn integrate(flow: &impl Flow, method: Method, s: State) -> Option<State> {
    Some(integrate_in(flow, method, s.map(Word::<true>))?.map(|v| v.0))
}

/// [`integrate`] as a call of its own, for the flows a loop does not inline.
#[inline(never)]
fn integrate_called(flow: &impl Flow, method: Method, s: State) -> Option<State> {
    integrate(flow, method, s)
}

/// One step of `flow` by `method`, in any [`Value`].
#[inline(always)]
fn integrate_in<V: Value>(flow: &impl Delta<V>, method: Method, s: [V; 3]) -> Option<[V; 3]> {
    match method {
        Method::Euler => euler(flow, s),
        Method::Rk4 => runge_kutta4(flow, s),
    }
}

/// `flow`'s Δt·f at `s`, as the integrators take it: inlined where there is a long multiply; a
/// call on ARMv6-M, whose products are built from 16-bit halves (an RK4 step inlining
/// that four times would not fit the micro:bit's flash).
#[cfg_attr(not(tinyfractal_no_long_multiply), inline(always))]
#[cfg_attr(tinyfractal_no_long_multiply, inline(never))]
fn derivative<V: Value>(flow: &impl Delta<V>, s: [V; 3]) -> Option<[V; 3]> {
    flow.delta_of(s)
}

/// Euler's step of a flow: s + k₁, k₁ = Δt·f(s).
#[inline(always)]
fn euler<V: Value>(flow: &impl Delta<V>, s: [V; 3]) -> Option<[V; 3]> {
    ahead(s, derivative(flow, s)?)
}

/// The classical Runge–Kutta step of a flow: s + (k₁ + 2k₂ + 2k₃ + k₄)/6 with
/// k₁ = Δt·f(s), k₂ = Δt·f(s + k₁/2), k₃ = Δt·f(s + k₂/2), k₄ = Δt·f(s + k₃) (halves
/// rounded down).
#[inline(always)]
fn runge_kutta4<V: Value>(flow: &impl Delta<V>, s: [V; 3]) -> Option<[V; 3]> {
    let k1 = derivative(flow, s)?;
    let k2 = derivative(flow, half_ahead(s, k1)?)?;
    let k3 = derivative(flow, half_ahead(s, k2)?)?;
    let k4 = derivative(flow, ahead(s, k3)?)?;
    let [s0, s1, s2] = s;
    Some([
        combined(s0, k1[0], k2[0], k3[0], k4[0])?,
        combined(s1, k1[1], k2[1], k3[1], k4[1])?,
        combined(s2, k1[2], k2[2], k3[2], k4[2])?,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::TestRunner;

    /// `mul` then `narrow`, the checked product the fast forms stand for.
    fn checked(a: i32, b: i32, bits: u32) -> Option<i32> {
        i32::try_from((i64::from(a) * i64::from(b)) >> bits).ok()
    }

    /// The Lorenz flow with small rates gives [`Lorenz::delta`]'s values and refusals.
    #[test]
    fn small_rate_lorenz_is_lorenz() {
        let below_half = -(1 << (FLOW - 1)) + 1..(1 << (FLOW - 1));
        let rates = (
            1..(1 << (FLOW - 1)),
            below_half.clone(),
            any::<i32>(),
            below_half,
        );
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(rates, any::<[i32; 3]>(), any::<[i32; 3]>()),
                |((dt, sigma_dt, rho_dt, beta_dt), wide, narrow_state)| {
                    let flow = Lorenz {
                        dt,
                        sigma_dt,
                        rho_dt,
                        beta_dt,
                    };
                    let small = flow.small_rates().expect("rates below ½");
                    // The attractor's own scale as well as the whole 32 bits.
                    let near = narrow_state.map(|v| v >> 6);
                    for state in [wide, near] {
                        prop_assert_eq!(small.delta(state), flow.delta(state));
                    }
                    Ok(())
                },
            )
            .unwrap();
        // A rate of ½ or more keeps the general form.
        let half = Lorenz {
            dt: 1 << (FLOW - 1),
            sigma_dt: 1,
            rho_dt: 1,
            beta_dt: 1,
        };
        assert_eq!(half.small_rates(), None);
    }

    /// The general Lorenz derivative against its definition in 64 bits, each product and
    /// sum checked into 32 bits.
    #[test]
    fn lorenz_delta_is_its_checked_definition() {
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(1..=(1i32 << FLOW), any::<[i32; 3]>(), any::<[i32; 3]>()),
                |(dt, [sigma_dt, rho_dt, beta_dt], state)| {
                    let flow = Lorenz {
                        dt,
                        sigma_dt,
                        rho_dt,
                        beta_dt,
                    };
                    let [x, y, z] = state.map(|v| v >> 4);
                    let expected = (|| {
                        let dx = checked(sigma_dt, y.checked_sub(x)?, FLOW)?;
                        let y_dt = checked(dt, y, FLOW)?;
                        let z_dt = checked(dt, z, FLOW)?;
                        let dy = checked(x, rho_dt.checked_sub(z_dt)?, FLOW)?.checked_sub(y_dt)?;
                        let dz = checked(x, y_dt, FLOW)?.checked_sub(checked(beta_dt, z, FLOW)?)?;
                        Some([dx, dy, dz])
                    })();
                    prop_assert_eq!(flow.delta([x, y, z]), expected);
                    Ok(())
                },
            )
            .unwrap();
    }

    /// Hénon's step with a small b, and the square checked on x, give the checked
    /// products' values and refusals, at the square's limit too.
    #[test]
    fn henon_forms_are_the_checked_products() {
        let henon_checked = |a: i32, b: i32, [x, y, _]: State| -> Option<State> {
            let squared = checked(x, x, HENON)?;
            let product = (i64::from(a) * i64::from(squared)) >> HENON;
            let x_next = i32::try_from((1i64 << HENON) + i64::from(y) - product).ok()?;
            Some([x_next, checked(b, x, HENON)?, 0])
        };
        let limit = HENON_LARGEST_SQUARABLE as i32;
        for x in [limit, limit + 1, -limit, -limit - 1, i32::MIN, i32::MAX, 0] {
            assert_eq!(henon_square(x), checked(x, x, HENON), "{x}");
            assert_eq!(henon(1, 1, [x, 0, 0]), henon_checked(1, 1, [x, 0, 0]));
        }
        // The quick step at its limits: |x| at and past it, a at ±2's edges, y at 32 bits'.
        let quick = HENON_QUICK_LIMIT as i32;
        let b = scaled_rate::<HENON>(-(1 << (HENON - 1)) + 1).expect("b below ½");
        for x in [quick - 1, quick, quick + 1, -quick, -quick - 1, -quick - 2] {
            for a in [i32::MAX / 4, i32::MIN / 4, 1, -1] {
                for y in [i32::MIN, i32::MAX, 0, -(1 << 30), 1 << 30] {
                    let a4 = quartered(a).expect("a below 2");
                    assert_eq!(
                        henon_quick(a, a4, b, [x, y, 0]),
                        henon_checked(a, -(1 << (HENON - 1)) + 1, [x, y, 0]),
                        "{a} {x} {y}"
                    );
                }
            }
        }
        let below_half = -(1 << (HENON - 1)) + 1..(1 << (HENON - 1));
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(any::<i32>(), below_half, any::<[i32; 2]>()),
                |(a, b, [x, y])| {
                    let state = [x >> 2, y, 0];
                    let expected = henon_checked(a, b, state);
                    prop_assert_eq!(henon(a, b, state), expected);
                    let scaled = scaled_rate::<HENON>(b).expect("b below ½");
                    prop_assert_eq!(henon_small_b(a, scaled, state), expected);
                    if let Some(a4) = quartered(a) {
                        prop_assert_eq!(henon_quick(a, a4, scaled, state), expected);
                    }
                    Ok(())
                },
            )
            .unwrap();
    }

    /// The quick step's products from 16-bit halves (ARMv6-M's) against the exact products
    /// in 64 bits, over the quick step's whole domain: every x within its limit, a below 2
    /// and b below ½, their ends included.
    #[test]
    fn henon_quick_halves_are_the_exact_products() {
        let exact = |a4: i32, b_scaled: i32, x: i32| {
            let high = |p: i64, q: i64| ((p * q) >> 32) as i32;
            let wide = i64::from(x) << 2;
            let square = i64::from(high(wide, wide));
            (
                high(i64::from(a4), square << 2),
                high(i64::from(b_scaled), i64::from(x)),
            )
        };
        let limit = HENON_QUICK_LIMIT as i32;
        let below_half = -(1 << (HENON - 1)) + 1..(1 << (HENON - 1));
        let ends_of_x = [
            limit,
            limit - 1,
            -limit,
            -limit - 1,
            0,
            1,
            -1,
            0xFFFF,
            -0x10000,
        ];
        let ends_of_a4 = [i32::MIN, i32::MAX & !3, 4, -4, 0, 0x7FFF_8000, -0x8000];
        let ends_of_b = [below_half.start, below_half.end - 1, 0, 1, -1];
        for x in ends_of_x {
            for a4 in ends_of_a4 {
                for b in ends_of_b {
                    let b_scaled = scaled_rate::<HENON>(b).expect("b below ½");
                    let products = henon_quick_halves(a4, b_scaled, x);
                    assert_eq!(products, exact(a4, b_scaled, x), "{a4} {b} {x}");
                }
            }
        }
        let mut runner = TestRunner::deterministic();
        runner
            .run(
                &(-limit - 1..=limit, any::<i32>(), below_half),
                |(x, a, b)| {
                    let (a4, b_scaled) = (a & !3, scaled_rate::<HENON>(b).expect("b below ½"));
                    prop_assert_eq!(henon_quick_halves(a4, b_scaled, x), exact(a4, b_scaled, x));
                    Ok(())
                },
            )
            .unwrap();
        // Every x the quick step takes, for the default a and b and their negations.
        let [a, b, ..] = Kind::Henon
            .default_parameters()
            .map(|p| to_fixed(p, HENON).unwrap());
        let (a4, b_scaled) = (a << 2, scaled_rate::<HENON>(b).unwrap());
        for x in (-limit - 1..=limit).step_by(997) {
            for (a4, b_scaled) in [(a4, b_scaled), (-a4, -b_scaled)] {
                assert_eq!(
                    henon_quick_halves(a4, b_scaled, x),
                    exact(a4, b_scaled, x),
                    "{x}"
                );
            }
        }
    }

    /// The default Lorenz flow's step, by RK4 or Euler: its box holds nearly every state
    /// of a long orbit, and from each the step with the box gives the checked step's state.
    #[test]
    fn lorenz_safe_box_holds_the_attractor_and_changes_nothing() {
        let kind = Kind::Lorenz;
        let dt = kind.default_time_step().unwrap();
        for method in [Method::Rk4, Method::Euler] {
            let stepper = Stepper::new(kind, kind.default_parameters(), dt, method).unwrap();
            let Stepper::Lorenz { flow, .. } = stepper else {
                panic!("not a Lorenz flow");
            };
            let small = flow.small_rates().unwrap();
            let safe = small.safe_box(flow.dt, method).expect("a safe box");
            let mut state = kind.default_start().map(|v| to_fixed(v, FLOW).unwrap());
            let (mut inside, steps) = (0, 50_000);
            for _ in 0..steps {
                inside += usize::from(safe.contains(state));
                let next = integrate(&small, method, state).unwrap();
                assert_eq!(small.integrate_within(safe, method, state), Some(next));
                assert_eq!(stepper.step(state), Some(next));
                state = next;
            }
            assert!(
                inside * 100 >= steps * 99,
                "{method:?}: {inside} of {steps} inside"
            );
        }
    }

    /// For random Lorenz flows, every state of a box the ranges prove safe steps without a
    /// refusal, and unchecked gives the checked state.
    #[test]
    fn lorenz_safe_boxes_are_safe() {
        let mut runner = TestRunner::deterministic();
        let rate = |low: i32, high: i32| (low << (FLOW - 8))..(high << (FLOW - 8));
        let (cases, boxed) = (core::cell::Cell::new(0), core::cell::Cell::new(0));
        runner
            .run(
                &(
                    (rate(1, 8), rate(1, 64), rate(1, 255), rate(1, 32)),
                    any::<bool>(),
                    proptest::collection::vec(any::<[u32; 3]>(), 64),
                ),
                |((dt, sigma_dt, rho_dt, beta_dt), euler, picks)| {
                    let flow = Lorenz {
                        dt,
                        sigma_dt,
                        rho_dt,
                        beta_dt,
                    };
                    let method = if euler { Method::Euler } else { Method::Rk4 };
                    let small = flow.small_rates().expect("rates below ½");
                    cases.set(cases.get() + 1);
                    let Some(safe) = small.safe_box(dt, method) else {
                        return Ok(());
                    };
                    boxed.set(boxed.get() + 1);
                    // States across the box, its corners included.
                    for pick in picks {
                        let state: State = core::array::from_fn(|i| {
                            let (low, span) = (safe.low[i], safe.span[i]);
                            let offset = match pick[i] % 3 {
                                0 => 0,
                                1 => span,
                                _ => pick[i] % span.max(1),
                            };
                            low.wrapping_add(offset as i32)
                        });
                        prop_assert!(safe.contains(state));
                        let checked = integrate(&small, method, state);
                        prop_assert!(checked.is_some(), "{state:?} refused in {safe:?}");
                        let fast = integrate_in(&small, method, state.map(Word::<false>));
                        prop_assert_eq!(fast.map(|s| s.map(|v| v.0)), checked);
                    }
                    Ok(())
                },
            )
            .unwrap();
        // Most flows of these rates have a box: the test is not empty.
        assert!(
            boxed.get() * 2 > cases.get(),
            "{} of {}",
            boxed.get(),
            cases.get()
        );
    }
}
