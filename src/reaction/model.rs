//! The Gray–Scott model's parameters, checked once and turned into the step's integer
//! coefficients, and the named presets.

use crate::error::{Error, ParameterError};
use crate::math::Real;

/// Fraction bits of the step's rates: `D·Δt/20`, `f·Δt`, `(k + f)·Δt` and `Δt` are
/// multiples of 2⁻¹⁵, like a cell, so a cell's change before it is rounded is a multiple
/// of 2⁻³⁰ that fits 32 bits.
pub(super) const COEFFICIENT_BITS: u32 = 15;

/// Fraction bits of a cell: 1.0 is 2¹⁵, in a `u16`.
pub const CELL_FRAC_BITS: u32 = 15;

/// A concentration of 1 in a cell.
pub const ONE: u16 = 1 << CELL_FRAC_BITS;

/// The Gray–Scott model as Karl Sims states it: feed `f`, kill `k`, diffusion rates `D_A`
/// and `D_B`, and the time step `Δt`.
///
/// A step is A′ = A + (D_A ∇²A − AB² + f(1 − A))·Δt and
/// B′ = B + (D_B ∇²B + AB² − (k + f)B)·Δt, with ∇² the 3×3 kernel (centre −1, edges 0.2,
/// corners 0.05) on a grid whose edges wrap, each concentration then clamped to [0, 1].
///
/// The clamp is what the usual implementations do, and what keeps Sims's start stable:
/// with Δt = 1, a seeded cell (A = B = 1) goes to A = −0.22 and B = 1.68 in two steps, and
/// the unclamped explicit step then diverges for some rates (waves, mitosis from spots),
/// in f64 as in any arithmetic. It never acts on diffusion alone: with D·Δt ≤ 1 a cell
/// moves towards its neighbours' mean and stays within their range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GrayScott {
    /// The feed rate `f`: how fast A is replenished towards 1.
    pub feed: Real,
    /// The kill rate `k`: how fast B is removed (beyond the feed).
    pub kill: Real,
    /// A's diffusion rate, `D_A` (Sims: 1).
    pub diffusion_a: Real,
    /// B's diffusion rate, `D_B` (Sims: 0.5).
    pub diffusion_b: Real,
    /// The time step `Δt` (Sims: 1).
    pub dt: Real,
}

impl Default for GrayScott {
    /// Sims's coral: f = 0.0545, k = 0.062.
    fn default() -> Self {
        Preset::Coral.model()
    }
}

impl GrayScott {
    /// The model with feed `f` and kill `k`, Sims's diffusion rates (1 and 0.5) and Δt = 1.
    pub fn new(feed: Real, kill: Real) -> Self {
        Self {
            feed,
            kill,
            diffusion_a: Real::ONE,
            diffusion_b: Real::from_bits(1 << 31),
            dt: Real::ONE,
        }
    }

    /// The step's integer coefficients; an error if a rate is out of range or would make
    /// the step unstable.
    ///
    /// Accepted: 0 < Δt ≤ 1; f and k in [0, 1] with (f + k)·Δt ≤ 1, so a step never takes
    /// more B than there is; 0 ≤ D·Δt ≤ 1 for each diffusion rate, so diffusion moves a cell
    /// towards the weighted mean of its neighbours and never past it (with this kernel the
    /// explicit step oscillates from D·Δt > 1 and diverges beyond 1.25). Each rate is the
    /// product rounded to 2⁻³² (as `Real` multiplies), then to 2⁻¹⁵.
    #[inline(never)]
    pub(super) fn coefficients(&self) -> Result<Coefficients, Error> {
        let parameter = |error| Err(Error::Parameter(error));
        let (zero, one) = (Real::ZERO, Real::ONE);
        if self.dt <= zero || self.dt > one {
            return parameter(ParameterError::TimeStepOutOfRange { dt: self.dt });
        }
        let in_unit = |rate: Real| rate >= zero && rate <= one;
        let times_dt = |rate: Real| rate.checked_mul(self.dt).unwrap_or(Real::from_int(2));
        let decay = times_dt(
            self.feed
                .checked_add(self.kill)
                .unwrap_or(Real::from_int(2)),
        );
        if !in_unit(self.feed) || !in_unit(self.kill) || decay > one {
            return parameter(ParameterError::FeedKillOutOfRange {
                feed: self.feed,
                kill: self.kill,
            });
        }
        let (diffusion_a, diffusion_b) = (times_dt(self.diffusion_a), times_dt(self.diffusion_b));
        for (diffusion, rate) in [
            (self.diffusion_a, diffusion_a),
            (self.diffusion_b, diffusion_b),
        ] {
            if diffusion < zero || rate > one {
                return parameter(ParameterError::DiffusionUnstable {
                    diffusion,
                    dt: self.dt,
                });
            }
        }
        // Every rate is now in [0, 1]: at most 2¹⁵ in Q15.
        let q15 = |rate: Real, divisor: i64| {
            let shift = Real::FRAC_BITS - COEFFICIENT_BITS;
            let bits = rate.to_bits() / divisor;
            ((bits + (1 << (shift - 1))) >> shift) as i32
        };
        Ok(Coefficients::of_rates(
            [q15(diffusion_a, 20), q15(diffusion_b, 20)],
            [q15(times_dt(self.feed), 1), q15(decay, 1)],
            q15(self.dt, 1),
        ))
    }
}

/// The separable kernel's weight of a cell's own value: 20·∇² is the column sums'
/// [1 4 1] less 36 times the centre (see the grid's `Column`).
pub(super) const KERNEL_CENTRE: i32 = 36;

/// What a step multiplies by, each rounded once from the model's exact values.
///
/// The terms a cell's own value is multiplied by are folded into one rate a chemical
/// (`own_a`, `own_b`), so a change is two products, the reaction and for A a constant:
/// A's change D_A·(Σ − 36·A) − AB² + f·(1 − A) is the same integer as D_A·Σ − (36·D_A +
/// f)·A − AB² + f·1, and B's D_B·(Σ − 36·B) + AB² − (k + f)·B as D_B·Σ − (36·D_B + k +
/// f)·B + AB².
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Coefficients {
    /// `D_A·Δt/20` in Q15: the kernel's weights are 4/20 and 1/20.
    pub diffusion_a: i32,
    /// `D_B·Δt/20` in Q15.
    pub diffusion_b: i32,
    /// `36·diffusion_a + f·Δt` in Q15: what A's change takes a unit of the cell's A (the
    /// kernel's centre and the feed's −f·A), at most 36·1,638 + 2¹⁵.
    pub own_a: i32,
    /// `36·diffusion_b + (k + f)·Δt` in Q15: what B's change takes a unit of the cell's B.
    pub own_b: i32,
    /// `f·Δt·1` in Q30: the feed's f·1, at most 2³⁰.
    pub feed_one: i32,
    /// `Δt` in Q15, for the reaction AB²·Δt (exact when Δt is 1).
    pub dt: i32,
}

impl Coefficients {
    /// The coefficients of the rates in Q15: `D_A·Δt/20` and `D_B·Δt/20` (each at most
    /// 1,638), `f·Δt` and `(k + f)·Δt` (each at most 2¹⁵), and `Δt`.
    pub(super) const fn of_rates(
        [diffusion_a, diffusion_b]: [i32; 2],
        [feed, decay]: [i32; 2],
        dt: i32,
    ) -> Self {
        Self {
            diffusion_a,
            diffusion_b,
            own_a: KERNEL_CENTRE * diffusion_a + feed,
            own_b: KERNEL_CENTRE * diffusion_b + decay,
            feed_one: feed * ONE as i32,
            dt,
        }
    }
}

/// Named (f, k) pairs: the patterns every Gray–Scott demo names, and Pearson's classes.
///
/// Pearson's classes (1993) are here where a source places one at a point. Each preset has
/// D_A = 1, D_B = 0.5, Δt = 1 (Sims's scaling, in which these f and k give Pearson's
/// patterns). Sources in `docs/families.md`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Preset {
    /// Sims's default, coral growth: f = 0.0545, k = 0.062.
    Coral,
    /// Sims's mitosis, spots that divide: f = 0.0367, k = 0.0649.
    Mitosis,
    /// Worms (stripes that grow and fill): f = 0.078, k = 0.061.
    Worms,
    /// A maze of stripes: f = 0.029, k = 0.057.
    Maze,
    /// Holes in a B sheet: f = 0.039, k = 0.058.
    Holes,
    /// Ring waves that travel out and wrap: f = 0.014, k = 0.041.
    Waves,
    /// Solitons, spots that stay: f = 0.03, k = 0.062.
    Solitons,
    /// The U-skate world (Munafo): f = 0.062, k = 0.06093.
    UskateWorld,
    /// Pearson's γ: stripes and spots that keep oscillating, f = 0.022, k = 0.051.
    PearsonGamma,
    /// Pearson's θ: a field of negative worms, f = 0.046, k = 0.061.
    PearsonTheta,
    /// Pearson's μ: solitons that multiply into worms, f = 0.046, k = 0.065.
    PearsonMu,
}

impl Preset {
    /// Every preset, in the order `--help` lists them.
    pub const ALL: [Self; 11] = [
        Self::Coral,
        Self::Mitosis,
        Self::Worms,
        Self::Maze,
        Self::Holes,
        Self::Waves,
        Self::Solitons,
        Self::UskateWorld,
        Self::PearsonGamma,
        Self::PearsonTheta,
        Self::PearsonMu,
    ];

    /// The preset's name, as the CLI spells it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Coral => "coral",
            Self::Mitosis => "mitosis",
            Self::Worms => "worms",
            Self::Maze => "maze",
            Self::Holes => "holes",
            Self::Waves => "waves",
            Self::Solitons => "solitons",
            Self::UskateWorld => "u-skate",
            Self::PearsonGamma => "gamma",
            Self::PearsonTheta => "theta",
            Self::PearsonMu => "mu",
        }
    }

    /// (f, k) in units of 10⁻⁵, as published.
    const fn feed_kill(self) -> (i64, i64) {
        match self {
            Self::Coral => (5450, 6200),
            Self::Mitosis => (3670, 6490),
            Self::Worms => (7800, 6100),
            Self::Maze => (2900, 5700),
            Self::Holes => (3900, 5800),
            Self::Waves => (1400, 4100),
            Self::Solitons => (3000, 6200),
            Self::UskateWorld => (6200, 6093),
            Self::PearsonGamma => (2200, 5100),
            Self::PearsonTheta => (4600, 6100),
            Self::PearsonMu => (4600, 6500),
        }
    }

    /// The preset's model, with Sims's diffusion rates and Δt = 1.
    pub fn model(self) -> GrayScott {
        let (feed, kill) = self.feed_kill();
        // n·10⁻⁵ rounded to 2⁻³², in 64 bits (n < 10⁵).
        let rate = |n: i64| Real::from_bits(((n << 32) + 50_000) / 100_000);
        GrayScott::new(rate(feed), rate(kill))
    }
}
