//! The presets: a fountain, fire, fireworks, snow and an explosion, each an emitter and
//! forces laid out on a target of any size (speeds and forces scale with its height, as
//! given for 240 pixels) at thirty ticks a second.

use embedded_graphics::prelude::Size;

use super::emitter::{Emitter, Schedule, Shape};
use super::particle::PARTICLE_BITS;
use super::system::{Forces, Ground, ParticleSystem};

/// Ticks a second: every preset steps a thirtieth of a second at a time.
pub const TICKS_PER_SECOND: u32 = 30;

/// A named particle system.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Preset {
    /// Water thrown up from the bottom's middle, falling back and bouncing.
    Fountain,
    /// Flames rising from a line along the bottom, slowing as they cool.
    Fire,
    /// Shells bursting every second and a half in the upper half, sparks falling.
    Fireworks,
    /// Flakes falling from above the top, drifting in the wind, resting on the ground.
    Snow,
    /// One burst in the middle at the start, its debris bouncing on the ground.
    Explosion,
}

/// A preset's look: its particles' sides at birth and death, for a 240-pixel target.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PresetSizes {
    /// Side at birth.
    pub birth: u8,
    /// Side at the end of life.
    pub death: u8,
}

/// Degrees to a binary angle.
const fn degrees(d: i64) -> u32 {
    ((d.rem_euclid(360) << 32) / 360) as u32
}

/// The layout of a target: fractions of it to pixels, and speeds and forces given for a
/// 240-pixel height to this one's, all Q16.16.
struct Frame {
    width: i64,
    height: i64,
}

impl Frame {
    /// The point `x`‰ across and `y`‰ down.
    fn at(&self, x: i64, y: i64) -> (i32, i32) {
        (
            (((self.width * x) << PARTICLE_BITS) / 1000) as i32,
            (((self.height * y) << PARTICLE_BITS) / 1000) as i32,
        )
    }

    /// `v` pixels a second (at 240 pixels high) in pixels a tick.
    fn speed(&self, v: i64) -> i32 {
        (((v * self.height) << PARTICLE_BITS) / (240 * i64::from(TICKS_PER_SECOND))) as i32
    }

    /// `a` pixels a second² (at 240 pixels high) in pixels a tick².
    fn acceleration(&self, a: i64) -> i32 {
        let ticks = i64::from(TICKS_PER_SECOND);
        (((a * self.height) << PARTICLE_BITS) / (240 * ticks * ticks)) as i32
    }

    /// `s` pixels (at 240 pixels high) in pixels.
    fn length(&self, s: i64) -> i32 {
        (((s * self.height) << PARTICLE_BITS) / 240) as i32
    }
}

/// `per_second` particles a second, a tick's share in Q16.
const fn rate(per_second: u32) -> Schedule {
    Schedule::Rate((per_second << PARTICLE_BITS) / TICKS_PER_SECOND)
}

/// Drag losing `per_mille`‰ of the velocity a second, a tick's share in Q16.
const fn drag(per_mille: i32) -> i32 {
    (per_mille << PARTICLE_BITS) / 1000 / TICKS_PER_SECOND as i32
}

/// Seconds (in thousandths) to ticks.
const fn ticks(milliseconds: u32) -> u16 {
    (milliseconds * TICKS_PER_SECOND / 1000) as u16
}

impl Preset {
    /// Every preset, in the order the command line lists them.
    pub const ALL: [Self; 5] = [
        Self::Fountain,
        Self::Fire,
        Self::Fireworks,
        Self::Snow,
        Self::Explosion,
    ];

    /// The command-line name.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Fountain => "fountain",
            Self::Fire => "fire",
            Self::Fireworks => "fireworks",
            Self::Snow => "snow",
            Self::Explosion => "explosion",
        }
    }

    /// The preset by its command-line name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|preset| preset.name() == name)
    }

    /// Its particles' sides, scaled to a target `height` pixels high (at least 1).
    pub fn sizes(self, height: u32) -> PresetSizes {
        let (birth, death) = match self {
            Self::Fountain | Self::Fireworks => (2, 1),
            Self::Fire => (3, 1),
            Self::Snow => (2, 2),
            Self::Explosion => (3, 1),
        };
        let scaled = |side: u32| u8::try_from((side * height).div_ceil(240).max(1)).unwrap_or(1);
        PresetSizes {
            birth: scaled(birth),
            death: scaled(death),
        }
    }

    /// The system on a target of `size`, its randomness from `seed`.
    pub fn system<const N: usize>(self, size: Size, seed: u64) -> ParticleSystem<N> {
        let frame = Frame {
            width: i64::from(size.width),
            height: i64::from(size.height),
        };
        let (emitter, forces) = match self {
            Self::Fountain => {
                let mut emitter = Emitter::new(
                    Shape::Point(frame.at(500, 950).0, frame.at(500, 950).1),
                    rate(120),
                );
                (emitter.direction, emitter.spread) = (degrees(90), degrees(10));
                (emitter.speed, emitter.speed_spread) = (frame.speed(250), frame.speed(30));
                (emitter.life, emitter.life_spread) = (ticks(2200), ticks(300));
                let forces = Forces {
                    ay: frame.acceleration(300),
                    ground: Some((frame.at(0, 950).1, Ground::Bounce(1 << 14))),
                    ..Forces::default()
                };
                (emitter, forces)
            }
            Self::Fire => {
                let mut emitter = Emitter::new(
                    Shape::Line(frame.at(300, 980), frame.at(700, 980)),
                    rate(240),
                );
                (emitter.direction, emitter.spread) = (degrees(90), degrees(15));
                (emitter.speed, emitter.speed_spread) = (frame.speed(70), frame.speed(30));
                (emitter.life, emitter.life_spread) = (ticks(1000), ticks(400));
                let forces = Forces {
                    ay: -frame.acceleration(60),
                    drag: drag(1000),
                    ..Forces::default()
                };
                (emitter, forces)
            }
            Self::Fireworks => {
                let (centre, radius) = (frame.at(500, 350), frame.length(60));
                let schedule = Schedule::Bursts {
                    count: 80,
                    first: 0,
                    every: 45,
                };
                let mut emitter = Emitter::new(Shape::Disc(centre, radius), schedule);
                (emitter.direction, emitter.spread) = (0, degrees(180) - 1);
                (emitter.speed, emitter.speed_spread) = (frame.speed(90), frame.speed(25));
                (emitter.life, emitter.life_spread) = (ticks(1600), ticks(300));
                let forces = Forces {
                    ay: frame.acceleration(70),
                    drag: drag(900),
                    ..Forces::default()
                };
                (emitter, forces)
            }
            Self::Snow => {
                let mut emitter = Emitter::new(
                    Shape::Line(frame.at(-100, -20), frame.at(1000, -20)),
                    rate(45),
                );
                (emitter.direction, emitter.spread) = (degrees(-90), degrees(12));
                (emitter.speed, emitter.speed_spread) = (frame.speed(35), frame.speed(12));
                (emitter.life, emitter.life_spread) = (ticks(12_000), ticks(2000));
                let forces = Forces {
                    ax: frame.acceleration(8),
                    ay: frame.acceleration(5),
                    drag: drag(400),
                    ground: Some((frame.at(0, 970).1, Ground::Rest)),
                };
                (emitter, forces)
            }
            Self::Explosion => {
                let schedule = Schedule::Bursts {
                    count: 300,
                    first: 0,
                    every: 0,
                };
                let mut emitter = Emitter::new(
                    Shape::Point(frame.at(500, 600).0, frame.at(500, 600).1),
                    schedule,
                );
                (emitter.direction, emitter.spread) = (0, degrees(180) - 1);
                (emitter.speed, emitter.speed_spread) = (frame.speed(150), frame.speed(90));
                (emitter.life, emitter.life_spread) = (ticks(3000), ticks(1000));
                let forces = Forces {
                    ay: frame.acceleration(120),
                    drag: drag(700),
                    ground: Some((frame.at(0, 950).1, Ground::Bounce(1 << 15))),
                    ..Forces::default()
                };
                (emitter, forces)
            }
        };
        ParticleSystem::new(emitter, forces, seed)
    }
}
