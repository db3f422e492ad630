//! The attractors by name: their equations, the defaults each starts from, and the
//! fixed-point format each is iterated in.

use crate::math::Real;

/// A strange attractor: a map iterated, or a flow integrated, from a start.
///
/// The maps (x, y → x′, y′; Pickover's in 3D):
/// - `Henon`: x′ = 1 − a·x² + y, y′ = b·x.
/// - `Clifford`: x′ = sin(a·y) + c·cos(a·x), y′ = sin(b·x) + d·cos(b·y).
/// - `DeJong`: x′ = sin(a·y) − cos(b·x), y′ = sin(c·x) − cos(d·y).
/// - `Hopalong` (Martin's): x′ = y − sign(x)·√|b·x − c|, y′ = a − x (sign(0) = 0, as
///   Fractint).
/// - `Martin`: x′ = y − sin(x), y′ = a − x.
/// - `GumowskiMira`: x′ = y + a·(1 − b·y²)·y + G(x), y′ = −x + G(x′), with
///   G(x) = c·x + 2(1 − c)·x²/(1 + x²).
/// - `Popcorn` (Pickover's): x′ = x − a·sin(y + tan 3y), y′ = y − a·sin(x + tan 3x).
/// - `Pickover` (3D): x′ = sin(a·y) − z·cos(b·x), y′ = z·sin(c·x) − cos(d·y), z′ = sin(x).
///
/// The flows, integrated with a time step Δt by [`Method`]:
/// - `Lorenz`: ẋ = a(y − x), ẏ = x(b − z) − y, ż = x·y − c·z (σ, ρ, β).
/// - `Rossler`: ẋ = −(y + z), ẏ = x + a·y, ż = b + z(x − c).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// The Hénon map (a = 1.4, b = 0.3).
    Henon,
    /// Clifford Pickover's "Clifford" attractor (a = −1.4, b = 1.6, c = 1, d = 0.7).
    Clifford,
    /// Peter de Jong's map (a = 1.4, b = −2.3, c = 2.4, d = −2.1).
    DeJong,
    /// Barry Martin's hopalong (Fractint: a = 0.4, b = 1, c = 0).
    Hopalong,
    /// Barry Martin's sine map (Fractint: a = 3.14).
    Martin,
    /// The Gumowski–Mira map (a = 0.008, b = 0.05, c = μ = −0.496).
    GumowskiMira,
    /// Pickover's popcorn map from one start (step a = 0.05, Fractint's).
    Popcorn,
    /// The Lorenz flow (σ = 10, ρ = 28, β = 8/3, Δt = 0.01).
    Lorenz,
    /// The Rössler flow (Fractint: a = b = 0.2, c = 5.7, Δt = 0.04).
    Rossler,
    /// Pickover's 3D map (Fractint: a = 2.24, b = 0.43, c = −0.65, d = −2.43).
    Pickover,
}

/// How a flow is integrated: the classical fourth-order Runge–Kutta step, or Euler's (one
/// derivative a step, as Fractint integrates).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Method {
    /// Fourth-order Runge–Kutta: four derivatives a step.
    #[default]
    Rk4,
    /// Euler: s′ = s + Δt·f(s).
    Euler,
}

impl Method {
    /// The method by its command-line name (`rk4`, `euler`).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "rk4" => Some(Self::Rk4),
            "euler" => Some(Self::Euler),
            _ => None,
        }
    }
}

/// A parameter, start or step given as thousandths: the defaults are exact decimals.
const fn milli(thousandths: i64) -> Real {
    match Real::from_ratio(thousandths, 1000) {
        Some(value) => value,
        None => Real::ZERO,
    }
}

impl Kind {
    /// Every kind, in the order the command line lists them.
    pub const ALL: [Self; 10] = [
        Self::Henon,
        Self::Lorenz,
        Self::Rossler,
        Self::Clifford,
        Self::DeJong,
        Self::Hopalong,
        Self::Martin,
        Self::GumowskiMira,
        Self::Popcorn,
        Self::Pickover,
    ];

    /// The command-line name.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Henon => "henon",
            Self::Clifford => "clifford",
            Self::DeJong => "dejong",
            Self::Hopalong => "hopalong",
            Self::Martin => "martin",
            Self::GumowskiMira => "gumowski-mira",
            Self::Popcorn => "popcorn",
            Self::Lorenz => "lorenz",
            Self::Rossler => "rossler",
            Self::Pickover => "pickover",
        }
    }

    /// The kind by its command-line name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|kind| kind.name() == name)
    }

    /// True for the flows (integrated with a time step), false for the maps.
    pub const fn is_flow(self) -> bool {
        matches!(self, Self::Lorenz | Self::Rossler)
    }

    /// 3 for the flows and Pickover's map, 2 for the others.
    pub const fn dimensions(self) -> usize {
        match self {
            Self::Lorenz | Self::Rossler | Self::Pickover => 3,
            _ => 2,
        }
    }

    /// How many parameters the equations take (a, b, c, d in order).
    pub const fn parameter_count(self) -> usize {
        match self {
            Self::Martin | Self::Popcorn => 1,
            Self::Henon => 2,
            Self::Hopalong | Self::GumowskiMira | Self::Lorenz | Self::Rossler => 3,
            Self::Clifford | Self::DeJong | Self::Pickover => 4,
        }
    }

    /// The parameters it starts with (Fractint's where Fractint has the type, the
    /// classical ones otherwise); unused ones are 0.
    pub const fn default_parameters(self) -> [Real; 4] {
        let z = Real::ZERO;
        match self {
            Self::Henon => [milli(1400), milli(300), z, z],
            Self::Clifford => [milli(-1400), milli(1600), milli(1000), milli(700)],
            Self::DeJong => [milli(1400), milli(-2300), milli(2400), milli(-2100)],
            Self::Hopalong => [milli(400), milli(1000), z, z],
            Self::Martin => [milli(3140), z, z, z],
            Self::GumowskiMira => [milli(8), milli(50), milli(-496), z],
            Self::Popcorn => [milli(50), z, z, z],
            Self::Lorenz => [
                milli(10_000),
                milli(28_000),
                match Real::from_ratio(8, 3) {
                    Some(beta) => beta,
                    None => z,
                },
                z,
            ],
            Self::Rossler => [milli(200), milli(200), milli(5700), z],
            Self::Pickover => [milli(2240), milli(430), milli(-650), milli(-2430)],
        }
    }

    /// The first point (before the transient is skipped).
    pub const fn default_start(self) -> [Real; 3] {
        let z = Real::ZERO;
        match self {
            Self::GumowskiMira => [milli(100), milli(100), z],
            Self::Popcorn => [milli(1000), milli(500), z],
            Self::Lorenz | Self::Rossler => [Real::ONE, Real::ONE, Real::ONE],
            _ => [z, z, z],
        }
    }

    /// A flow's time step (0.01 for Lorenz, Fractint's 0.04 for Rössler); `None` for a map.
    pub const fn default_time_step(self) -> Option<Real> {
        match self {
            Self::Lorenz => Some(milli(10)),
            Self::Rossler => Some(milli(40)),
            _ => None,
        }
    }

    /// Fraction bits of the fixed point it is iterated in: its state stays within
    /// ±2^(31 − bits), wide enough for its attractor at the default parameters with room
    /// to spare (Hénon ±8 at 2⁻²⁸, Lorenz ±128 at 2⁻²⁴, Martin ±2048 at 2⁻²⁰).
    pub const fn fraction_bits(self) -> u32 {
        match self {
            Self::Henon => 28,
            Self::Clifford | Self::DeJong | Self::Pickover => 27,
            Self::GumowskiMira | Self::Popcorn | Self::Lorenz | Self::Rossler => 24,
            Self::Hopalong | Self::Martin => 20,
        }
    }

    /// True where the orbit keeps spreading outward for long after its first points
    /// (hopalong, Martin, popcorn: their pictures grow with the points), so a picture must
    /// be fitted to the whole orbit; false for the attractors an orbit fills within its
    /// first few thousand points.
    pub const fn spreads(self) -> bool {
        matches!(self, Self::Hopalong | Self::Martin | Self::Popcorn)
    }

    /// The range of its state: values stay strictly within ±this.
    pub const fn range(self) -> u32 {
        1 << (31 - self.fraction_bits())
    }
}
