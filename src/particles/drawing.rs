//! A particle system on a target, a frame at a time: the last frame's particles erased in
//! the background colour, then each live particle a square whose colour and size follow its
//! age, so the display is never cleared.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

use super::particle::{Particle, PARTICLE_BITS};
use super::system::ParticleSystem;
use crate::render::palette::Palette;

/// How particles look: their side in pixels at birth and at the end of their life (in
/// between by age), and the palette their age runs through (value `age·255/life` of 255).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParticleLook<P> {
    /// The palette, young to old.
    pub palette: P,
    /// Side at birth, in pixels (0 draws nothing).
    pub size_at_birth: u8,
    /// Side at the end of life.
    pub size_at_death: u8,
}

/// What the last frame drew, slot by slot, so the next can erase it: the caller keeps it
/// between frames (16 bytes and a flag a slot).
#[derive(Debug, Clone)]
pub struct Frames<const N: usize> {
    drawn: [Option<Rectangle>; N],
}

impl<const N: usize> Default for Frames<N> {
    fn default() -> Self {
        Self { drawn: [None; N] }
    }
}

/// A particle's pixel: its position rounded.
fn pixel(particle: &Particle) -> Point {
    let round = |v: i32| ((i64::from(v) + (1 << (PARTICLE_BITS - 1))) >> PARTICLE_BITS) as i32;
    Point::new(round(particle.x), round(particle.y))
}

impl<const N: usize> Frames<N> {
    /// No frame drawn yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Draws `system`'s particles: first erases, in `background`, each square of the last
    /// frame that does not come back unchanged, then draws every live particle. Returns the
    /// particles drawn.
    pub fn draw<D, P>(
        &mut self,
        system: &ParticleSystem<N>,
        look: &ParticleLook<P>,
        background: P::Color,
        target: &mut D,
    ) -> Result<u64, D::Error>
    where
        D: DrawTarget<Color = P::Color>,
        P: Palette,
    {
        let mut next = [None; N];
        let mut colours = [None; N];
        for ((slot, colour), particle) in next.iter_mut().zip(&mut colours).zip(system.particles())
        {
            if !particle.is_alive() {
                continue;
            }
            let life = u32::from(particle.life.max(1));
            let age = u32::from(particle.age).min(life);
            let (birth, death) = (u32::from(look.size_at_birth), u32::from(look.size_at_death));
            let side = (birth * (life - age) + death * age + life / 2) / life;
            if side == 0 {
                continue;
            }
            let centre = pixel(particle);
            let half = (side / 2) as i32;
            *slot = Some(Rectangle::new(
                centre - Point::new(half, half),
                Size::new(side, side),
            ));
            let value = u16::try_from(age * 255 / life).unwrap_or(255);
            *colour = Some(look.palette.color(value, 255));
        }
        for (old, new) in self.drawn.iter().zip(&next) {
            if let Some(old) = old {
                if Some(*old) != *new {
                    target.fill_solid(old, background)?;
                }
            }
        }
        let mut drawn = 0;
        for (square, colour) in next.iter().zip(&colours) {
            if let (Some(square), Some(colour)) = (square, colour) {
                target.fill_solid(square, *colour)?;
                drawn += 1;
            }
        }
        self.drawn = next;
        Ok(drawn)
    }
}
