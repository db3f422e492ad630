//! Where particles come from: a point, a line or a disc, at a steady rate or in bursts,
//! with a direction, speed and lifetime each spread at random about their means.

use super::particle::Particle;
use crate::math::random::Generator;
use crate::math::trig::{cos_of_binary, sin_of_binary};

/// Where an emitter puts its particles, in pixels Q16.16 (y down).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Every particle at this point.
    Point(i32, i32),
    /// Anywhere on the segment between two points.
    Line((i32, i32), (i32, i32)),
    /// Anywhere in the disc of this centre and radius.
    Disc((i32, i32), i32),
}

/// When an emitter emits: at a steady rate, or in bursts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Schedule {
    /// Particles a tick, Q16 (a fraction is carried to the next tick).
    Rate(u32),
    /// `count` particles at once at tick `first`, then every `every` ticks (0: once), each
    /// burst from one point of the shape (a firework's shell).
    Bursts {
        /// Particles a burst.
        count: u32,
        /// The first burst's tick.
        first: u64,
        /// Ticks between bursts; 0 for a single one.
        every: u64,
    },
}

/// What the emitter owes a tick: a rate to accumulate, or a burst.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Emission {
    Rate(u32),
    Burst(u32),
}

/// An emitter: its shape and schedule, and the spread of what it emits. Angles are binary
/// (2³² a turn), counter-clockwise from +x with y up on screen; speeds in pixels a tick,
/// Q16.16; lives in ticks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Emitter {
    /// Where particles appear.
    pub shape: Shape,
    /// When.
    pub schedule: Schedule,
    /// The mean direction.
    pub direction: u32,
    /// How far either side of it a direction may fall.
    pub spread: u32,
    /// The mean speed.
    pub speed: i32,
    /// How far either side of it a speed may fall.
    pub speed_spread: i32,
    /// The mean life.
    pub life: u16,
    /// How far either side of it a life may fall.
    pub life_spread: u16,
    /// The current burst's point, for bursts from one point.
    pub(super) origin: (i32, i32),
}

/// A uniform value in [−spread, spread] from 32 random bits.
fn spread_of(random: u32, spread: u32) -> i64 {
    let width = 2 * u64::from(spread) + 1;
    ((u64::from(random) * width) >> 32) as i64 - i64::from(spread)
}

/// `value · random / 2³²`, a uniform share of `value`.
fn share(value: i32, random: u32) -> i32 {
    ((i64::from(value) * i64::from(random)) >> 32) as i32
}

impl Emitter {
    /// An emitter of `shape` on `schedule`; set the spreads with the fields.
    pub const fn new(shape: Shape, schedule: Schedule) -> Self {
        Self {
            shape,
            schedule,
            direction: 1 << 30,
            spread: 0,
            speed: 0,
            speed_spread: 0,
            life: 30,
            life_spread: 0,
            origin: (0, 0),
        }
    }

    /// What tick `tick` owes.
    pub(super) fn emission(&self, tick: u64) -> Emission {
        match self.schedule {
            Schedule::Rate(rate) => Emission::Rate(rate),
            Schedule::Bursts {
                count,
                first,
                every,
            } => {
                let due = tick == first
                    || (every > 0 && tick > first && (tick - first).is_multiple_of(every));
                Emission::Burst(if due { count } else { 0 })
            }
        }
    }

    /// A point of the shape.
    pub(super) fn place(&self, random: &mut Generator) -> (i32, i32) {
        match self.shape {
            Shape::Point(x, y) => (x, y),
            Shape::Line((x0, y0), (x1, y1)) => {
                let t = random.next_u32();
                (x0 + share(x1 - x0, t), y0 + share(y1 - y0, t))
            }
            Shape::Disc((cx, cy), radius) => {
                // Rejection from the square: at most eight tries, then the centre.
                for _ in 0..8 {
                    let dx = share(2 * radius, random.next_u32()) - radius;
                    let dy = share(2 * radius, random.next_u32()) - radius;
                    let r = i64::from(radius);
                    if i64::from(dx) * i64::from(dx) + i64::from(dy) * i64::from(dy) <= r * r {
                        return (cx + dx, cy + dy);
                    }
                }
                (cx, cy)
            }
        }
    }

    /// A new particle: at a point of the shape (the burst's own, for bursts), with a
    /// direction, speed and life drawn about their means.
    pub(super) fn particle(&self, random: &mut Generator) -> Particle {
        let (x, y) = match self.schedule {
            Schedule::Bursts { .. } => self.origin,
            Schedule::Rate(_) => self.place(random),
        };
        let angle = (i64::from(self.direction) + spread_of(random.next_u32(), self.spread)) as u32;
        let speed =
            i64::from(self.speed) + spread_of(random.next_u32(), self.speed_spread.unsigned_abs());
        let life = i64::from(self.life) + spread_of(random.next_u32(), u32::from(self.life_spread));
        let along = |q30: i32| ((speed * i64::from(q30)) >> 30) as i32;
        Particle {
            x,
            y,
            vx: along(cos_of_binary(angle)),
            // Screen y is down: up is negative.
            vy: -along(sin_of_binary(angle)),
            age: 0,
            life: u16::try_from(life.clamp(1, i64::from(u16::MAX))).unwrap_or(1),
        }
    }
}
