//! The particle pool and its step: emitters feed a fixed-capacity pool, forces and drag
//! move every live particle by a fixed time step, the ground bounces them.
//!
//! Positions are pixels and velocities pixels a tick, in Q16.16; a tick is the system's
//! time step. Positions advance by v + a/2 and velocities by a each tick (the exact
//! parabola at every tick, without drag), then drag takes its share of the velocity.

use super::emitter::{Emission, Emitter};
use super::particle::{Particle, PARTICLE_BITS};
use crate::math::random::Generator;

/// One in Q16.16.
const ONE: i32 = 1 << PARTICLE_BITS;

/// What moves the particles, per tick: acceleration (gravity and wind together), drag (the
/// share of the velocity lost a tick, Q16), and the ground.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Forces {
    /// Acceleration in pixels a tick², Q16.16 (gravity down is positive y).
    pub ax: i32,
    /// See `ax`.
    pub ay: i32,
    /// The share of the velocity lost each tick, Q16 (0: none, 65536: all).
    pub drag: i32,
    /// The ground's row in pixels, Q16.16, and what it does.
    pub ground: Option<(i32, Ground)>,
}

/// What the ground does to a particle that reaches it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ground {
    /// It bounces back up with this share of its speed (Q16).
    Bounce(i32),
    /// It stays where it fell until its life ends (snow).
    Rest,
}

/// A pool of at most `N` particles, its emitter, forces and seeded generator: the same seed
/// gives the same particles, tick for tick, on every target.
///
/// When the pool is full an emitted particle replaces the oldest one (the largest age; of
/// equals, the first in the pool), so emission never fails and the newest particles are
/// always shown. Nothing is allocated: the pool is part of the system.
#[derive(Debug, Clone)]
pub struct ParticleSystem<const N: usize> {
    particles: [Particle; N],
    emitter: Emitter,
    forces: Forces,
    random: Generator,
    /// Particles owed by the emitter's rate, Q16.
    owed: u32,
    ticks: u64,
    replaced: u64,
}

impl<const N: usize> ParticleSystem<N> {
    /// An empty system fed by `emitter`, moved by `forces`, drawing its randomness from
    /// `seed`.
    pub fn new(emitter: Emitter, forces: Forces, seed: u64) -> Self {
        Self {
            particles: [Particle::default(); N],
            emitter,
            forces,
            random: Generator::new(seed),
            owed: 0,
            ticks: 0,
            replaced: 0,
        }
    }

    /// The pool: every slot, live or not (see [`Particle::is_alive`]).
    pub fn particles(&self) -> &[Particle; N] {
        &self.particles
    }

    /// The live particles.
    pub fn live(&self) -> impl Iterator<Item = &Particle> {
        self.particles.iter().filter(|p| p.is_alive())
    }

    /// Ticks stepped so far.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Live particles replaced because the pool was full, so far.
    pub fn replaced(&self) -> u64 {
        self.replaced
    }

    /// Steps `ticks` ticks: each emits what the emitter owes, then moves every live particle
    /// and ages it. Returns the particle-steps taken (live particles moved, summed).
    pub fn step(&mut self, ticks: u32) -> u64 {
        let mut moved = 0;
        for _ in 0..ticks {
            self.emit();
            let forces = self.forces;
            for particle in &mut self.particles {
                if particle.is_alive() {
                    advance(particle, &forces);
                    moved += 1;
                }
            }
            self.ticks += 1;
        }
        moved
    }

    /// Emits what this tick owes.
    fn emit(&mut self) {
        let count = match self.emitter.emission(self.ticks) {
            Emission::Rate(per_tick) => {
                self.owed = self.owed.saturating_add(per_tick);
                let whole = self.owed >> PARTICLE_BITS;
                self.owed &= (1 << PARTICLE_BITS) - 1;
                whole
            }
            Emission::Burst(count) => {
                if count > 0 {
                    // A burst starts from one point of the shape.
                    self.emitter.origin = self.emitter.place(&mut self.random);
                }
                count
            }
        };
        for _ in 0..count {
            let born = self.emitter.particle(&mut self.random);
            let slot = self.free_slot();
            if let Some(slot) = self.particles.get_mut(slot) {
                if slot.is_alive() {
                    self.replaced += 1;
                }
                *slot = born;
            }
        }
    }

    /// The first dead slot, or the oldest particle's where every slot lives.
    fn free_slot(&self) -> usize {
        let mut oldest = (0, 0u16);
        for (i, particle) in self.particles.iter().enumerate() {
            if !particle.is_alive() {
                return i;
            }
            if particle.age > oldest.1 {
                oldest = (i, particle.age);
            }
        }
        oldest.0
    }
}

/// One tick of a particle: x += v + a/2, v += a, drag, the ground, age.
#[inline]
fn advance(p: &mut Particle, forces: &Forces) {
    p.x = p.x.saturating_add(p.vx).saturating_add(forces.ax >> 1);
    p.y = p.y.saturating_add(p.vy).saturating_add(forces.ay >> 1);
    p.vx = p.vx.saturating_add(forces.ax);
    p.vy = p.vy.saturating_add(forces.ay);
    if forces.drag != 0 {
        p.vx -= ((i64::from(p.vx) * i64::from(forces.drag)) >> PARTICLE_BITS) as i32;
        p.vy -= ((i64::from(p.vy) * i64::from(forces.drag)) >> PARTICLE_BITS) as i32;
    }
    if let Some((ground, what)) = forces.ground {
        if p.y > ground {
            match what {
                Ground::Bounce(keep) => {
                    // Mirrored about the ground, and back up with its share of the speed.
                    p.y = ground - (p.y - ground).min(ONE * 4);
                    if p.vy > 0 {
                        p.vy = -(((i64::from(p.vy) * i64::from(keep)) >> PARTICLE_BITS) as i32);
                    }
                }
                Ground::Rest => {
                    p.y = ground;
                    (p.vx, p.vy) = (0, 0);
                }
            }
        }
    }
    p.age = p.age.saturating_add(1);
}
