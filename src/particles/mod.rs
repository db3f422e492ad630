//! Particle systems: a fixed-capacity pool fed by an emitter and moved by forces in fixed
//! point, stepped from a main loop and drawn a frame at a time by erasing the last one.
//!
//! [`ParticleSystem`] holds at most `N` particles (a const generic: nothing is allocated)
//! with sub-pixel positions and velocities (Q16.16), ages and lives; an [`Emitter`] (a
//! point, a line or a disc; a rate or bursts; direction, speed and life spread at random)
//! feeds it; [`Forces`] (gravity and wind, drag, a ground that bounces or holds) move it a
//! tick at a time. The generator is seeded, so every target animates the same frames.
//! [`Frames`] draws them, erasing the last frame's squares instead of clearing the display.
//! [`Preset`] lays out a fountain, fire, fireworks, snow or an explosion on any target.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::particles::{Frames, ParticleLook, Preset, TICKS_PER_SECOND};
//! use tinyfractal::render::TwoColor;
//!
//! let mut fountain = Preset::Fountain.system::<64>(Size::new(64, 64), 7);
//! let look = ParticleLook {
//!     palette: TwoColor { inside: BinaryColor::On, outside: BinaryColor::On },
//!     size_at_birth: 1,
//!     size_at_death: 1,
//! };
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let mut frames = Frames::new();
//! // A main loop: a second of ticks, a frame each.
//! for _ in 0..TICKS_PER_SECOND {
//!     fountain.step(1);
//!     let Ok(_) = frames.draw(&fountain, &look, BinaryColor::Off, &mut display);
//! }
//! // Never more particles than the pool holds.
//! assert!(fountain.live().count() <= 64);
//! assert!(fountain.live().count() > 0);
//! ```
//!
//! Memory: a particle is 20 bytes; a system of `N` is `20·N` bytes and about 60 more;
//! [`Frames`] keeps 20 bytes a slot, and a frame's drawing about as much again on the stack.

mod drawing;
mod emitter;
mod particle;
mod presets;
mod system;

pub use drawing::{Frames, ParticleLook};
pub use emitter::{Emitter, Schedule, Shape};
pub use particle::{Particle, PARTICLE_BITS};
pub use presets::{Preset, PresetSizes, TICKS_PER_SECOND};
pub use system::{Forces, Ground, ParticleSystem};
