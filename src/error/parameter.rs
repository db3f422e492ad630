//! Generators' parameters: subdivision orders, terrain roughness and sizes, box sizes.

use core::fmt;

use crate::math::Real;

/// A generator was asked for something outside what it accepts. Each variant carries the
/// value given and the bound it broke.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ParameterError {
    /// The order needs cells finer than a pixel of this target (or beyond the generator's
    /// capacity): `max` is the highest order that shows every cell.
    OrderTooHigh {
        /// The order given.
        order: u32,
        /// The highest order this target (and capacity) allows.
        max: u32,
    },
    /// A fractal sum of noise takes 1 to `max` octaves.
    OctavesOutOfRange {
        /// The count given.
        octaves: u32,
        /// The most accepted ([`MAX_OCTAVES`](crate::noise::MAX_OCTAVES)).
        max: u32,
    },
    /// A fractal sum's persistence (gain) is outside [0, 1].
    PersistenceOutOfRange {
        /// The value given.
        persistence: Real,
    },
    /// A fractal sum's lacunarity is outside [1, 4].
    LacunarityOutOfRange {
        /// The value given.
        lacunarity: Real,
    },
    /// A texture's scale (lattice cells across the picture) is not positive.
    ScaleNotPositive {
        /// The value given.
        scale: Real,
    },
    /// Noise coordinates leave the fixed-point range at the finest octave (a scale, a
    /// picture or octaves too large), or a sum of them does.
    NoiseOutOfRange,
    /// A reaction's time step is outside (0, 1].
    TimeStepOutOfRange {
        /// The value given.
        dt: Real,
    },
    /// A reaction's feed or kill rate is outside [0, 1], or (feed + kill)·Δt exceeds 1
    /// (a step would take more B than there is).
    FeedKillOutOfRange {
        /// The feed rate given.
        feed: Real,
        /// The kill rate given.
        kill: Real,
    },
    /// A diffusion rate is negative, or its D·Δt exceeds 1: the explicit step would
    /// overshoot the neighbours' mean and oscillate (and diverge beyond 1.25).
    DiffusionUnstable {
        /// The diffusion rate given.
        diffusion: Real,
        /// The time step given.
        dt: Real,
    },
    /// A reaction's grid side is outside [`min`, `max`].
    GridOutOfRange {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
        /// The smallest side accepted.
        min: u32,
        /// The largest side accepted.
        max: u32,
    },
    /// The roughness is outside (0, 1].
    RoughnessOutOfRange {
        /// The value given.
        roughness: Real,
    },
    /// The standard deviation is negative or above `max`.
    SigmaOutOfRange {
        /// The value given.
        sigma: Real,
        /// The largest accepted ([`Displacement::MAX_SIGMA`](crate::terrain::Displacement::MAX_SIGMA)).
        max: Real,
    },
    /// A terrain's fixed end height is beyond ±`max`.
    EndOutOfRange {
        /// The value given.
        end: Real,
        /// The largest magnitude accepted ([`Terrain::MAX_END`](crate::terrain::Terrain::MAX_END)).
        max: Real,
    },
    /// Midpoint displacement needs 2ᵏ + 1 samples.
    SamplesNotPowerOfTwoPlusOne {
        /// The count given.
        samples: u32,
    },
    /// More samples than the generator's capacity.
    TooManySamples {
        /// The count given.
        samples: u32,
        /// The most accepted.
        max: u32,
    },
    /// A box-counting range without two sizes, or sizes beyond the area.
    BoxSizesOutOfRange {
        /// log₂ of the smallest box side asked.
        smallest: u32,
        /// log₂ of the largest box side asked.
        largest: u32,
        /// log₂ of the largest side the area allows.
        max: u32,
    },
    /// An attractor's parameter, start coordinate or rate times Δt is beyond the range of
    /// its kind's fixed point.
    AttractorValueOutOfRange {
        /// The value given.
        value: Real,
        /// The range: values must stay strictly within ±this.
        max: u32,
    },
    /// An attractor takes a fixed number of parameters.
    ParameterCount {
        /// How many were given.
        given: usize,
        /// How many the kind takes.
        expected: usize,
    },
    /// The camera's elevation is not strictly between −90° and 90°.
    CameraOutOfRange {
        /// The azimuth given, degrees.
        azimuth: Real,
        /// The elevation given, degrees.
        elevation: Real,
    },
}

impl fmt::Display for ParameterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::OrderTooHigh { order, max } => write!(
                f,
                "order {order} is too high: on this target (and within the generator's \
                 capacity) every cell is at least a pixel up to order {max}; lower the order \
                 or draw larger"
            ),
            Self::OctavesOutOfRange { octaves, max } => write!(
                f,
                "{octaves} octaves is out of range: use 1 to {max} (6 is the classic fBm)"
            ),
            Self::PersistenceOutOfRange { persistence } => write!(
                f,
                "persistence {persistence} is outside [0, 1]: each octave's amplitude over the \
                 last one's, e.g. 0.5"
            ),
            Self::LacunarityOutOfRange { lacunarity } => write!(
                f,
                "lacunarity {lacunarity} is outside [1, 4]: each octave's frequency over the \
                 last one's, e.g. 2"
            ),
            Self::ScaleNotPositive { scale } => write!(
                f,
                "scale {scale} is not positive: give the lattice cells across the picture, e.g. 4"
            ),
            Self::NoiseOutOfRange => write!(
                f,
                "the noise's coordinates leave the fixed-point range (about ±2^31 lattice \
                 cells) at the finest octave: lower the scale, the octaves or the lacunarity"
            ),
            Self::TimeStepOutOfRange { dt } => write!(
                f,
                "the time step {dt} is outside (0, 1]: give a positive Δt of at most 1"
            ),
            Self::FeedKillOutOfRange { feed, kill } => write!(
                f,
                "feed {feed} and kill {kill} are out of range: each must be in [0, 1] and \
                 (feed + kill)·Δt at most 1 (patterns live near feed 0.01–0.08, kill \
                 0.045–0.07)"
            ),
            Self::DiffusionUnstable { diffusion, dt } => write!(
                f,
                "diffusion {diffusion} with time step {dt} is unstable: D·Δt must be in [0, 1] \
                 (the step would overshoot and oscillate); lower the rate or Δt"
            ),
            Self::GridOutOfRange {
                width,
                height,
                min,
                max,
            } => write!(
                f,
                "the grid {width}x{height} is out of range: each side must be {min} to {max} \
                 cells"
            ),
            Self::AttractorValueOutOfRange { value, max } => write!(
                f,
                "{value} is out of range: this attractor is iterated in a fixed point that holds \
                 values strictly within ±{max} (its parameters, start, and rates times the time \
                 step alike)"
            ),
            Self::ParameterCount { given, expected } => write!(
                f,
                "{given} parameters given, but this attractor takes {expected} (a, b, c, d in \
                 order)"
            ),
            Self::RoughnessOutOfRange { roughness } => write!(
                f,
                "roughness {roughness} is outside (0, 1]: use e.g. 0.5 (smooth) to 0.9 (rough); \
                 0.7071 is Brownian motion"
            ),
            Self::SigmaOutOfRange { sigma, max } => write!(
                f,
                "sigma {sigma} is out of range: use a standard deviation from 0 to {max}"
            ),
            Self::EndOutOfRange { end, max } => {
                write!(f, "end height {end} is out of range: use -{max} to {max}")
            }
            Self::SamplesNotPowerOfTwoPlusOne { samples } => write!(
                f,
                "{samples} samples: midpoint displacement needs 2^k + 1 (3, 5, 9, 17, ..., 1025)"
            ),
            Self::TooManySamples { samples, max } => {
                write!(f, "{samples} samples is more than the {max} supported")
            }
            Self::BoxSizesOutOfRange {
                smallest,
                largest,
                max,
            } => write!(
                f,
                "box sides 2^{smallest} to 2^{largest} do not fit: give at least two sizes \
                 with the largest at most 2^{max} (the area's shorter side)"
            ),
            Self::CameraOutOfRange { azimuth, elevation } => write!(
                f,
                "camera azimuth {azimuth}, elevation {elevation}: use an elevation strictly \
                 between -90 and 90 degrees"
            ),
        }
    }
}
