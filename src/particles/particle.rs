//! A particle: sub-pixel position and velocity in Q16.16, age and life in ticks.

/// Fraction bits of positions, velocities and accelerations.
pub const PARTICLE_BITS: u32 = 16;

/// A particle: where, how fast, how old and how long it lives (ticks).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Particle {
    /// Position in pixels, Q16.16 (x right, y down).
    pub x: i32,
    /// See `x`.
    pub y: i32,
    /// Velocity in pixels a tick, Q16.16.
    pub vx: i32,
    /// See `vx`.
    pub vy: i32,
    /// Ticks since it was emitted.
    pub age: u16,
    /// Ticks it lives; it is gone once `age` reaches it.
    pub life: u16,
}

impl Particle {
    /// True while it lives.
    pub const fn is_alive(&self) -> bool {
        self.age < self.life
    }
}
