//! Tropism (ABOP §2.2): after each step the heading bends towards a direction T by
//! α = e·|H × T| about H × T (eq. 2.4), so branches droop under gravity or turn to the
//! light; and the wind that sways a plant, a tropism that changes with time.

use crate::math::frame3::Unit;
use crate::math::trig::{sin_of_binary, ONE_Q30};
use crate::math::Real;

/// A tropism: the direction T the heading bends towards and the elasticity e.
///
/// The bend after each step is e·|H × T| radians, so a longer T bends more: only e·T
/// matters. `tropism: 0,-1,0 0.22` in a `.lsys` entry is ABOP figure 2.8 (a)'s.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tropism {
    /// T, in the turtle's space (x right, y up, z towards the viewer).
    pub direction: [Real; 3],
    /// e.
    pub elasticity: Real,
}

/// A tropism ready for the turtle: T as a Q30 unit vector and e·|T|.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Bend {
    pub(crate) towards: Unit,
    pub(crate) strength: Real,
}

impl Tropism {
    /// The bend it makes; `None` for a zero direction or elasticity (nothing bends) or a
    /// direction too long to measure (beyond 2¹⁵ a component).
    pub(crate) fn bend(&self) -> Option<Bend> {
        let mut squared = Real::ZERO;
        for &c in &self.direction {
            squared = squared.checked_add(c.checked_mul(c)?)?;
        }
        let length = squared.checked_sqrt()?;
        if length.to_bits() == 0 || self.elasticity.to_bits() == 0 {
            return None;
        }
        let towards = self.direction.map(|c| {
            let unit = (i128::from(c.to_bits()) << 30) / i128::from(length.to_bits());
            i32::try_from(unit).unwrap_or(if unit < 0 { -ONE_Q30 } else { ONE_Q30 })
        });
        Some(Bend {
            towards,
            strength: self.elasticity.checked_mul(length)?,
        })
    }

    /// e·T, the one vector a bend depends on.
    fn weighted(&self) -> [Real; 3] {
        self.direction
            .map(|c| c.checked_mul(self.elasticity).unwrap_or(Real::ZERO))
    }
}

/// A periodic wind: a direction (with its strength, as e·T) blown in gusts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Wind {
    /// The wind's e·T at the height of a gust (x right, y up, z towards the viewer).
    pub push: [Real; 3],
    /// Chooses the gusts' shape: the phase of the second harmonic.
    pub seed: u32,
}

impl Wind {
    /// The gust at `frame` of a loop of `frames`: sin(2πt) + ½·sin(4πt + φ) with
    /// t = frame / frames and φ from the seed, in Q30 (between −1.5 and 1.5). Periodic:
    /// frame `frames` is frame 0 again.
    pub(crate) fn gust(&self, frame: u32, frames: u32) -> i32 {
        let frames = u64::from(frames.max(1));
        let turn = ((u64::from(frame % frames as u32) << 32) / frames) as u32;
        let phase = self.seed.wrapping_mul(0x9E37_79B9);
        let first = sin_of_binary(turn);
        let second = sin_of_binary(turn.wrapping_mul(2).wrapping_add(phase));
        first + second / 2
    }

    /// The tropism of a plant whose own is `own` at `frame` of `frames` in this wind: e·T
    /// of both added (elasticity 1). The root does not move: only headings bend.
    pub fn tropism_at(&self, own: Option<Tropism>, frame: u32, frames: u32) -> Tropism {
        let gust = self.gust(frame, frames);
        let base = own.map_or([Real::ZERO; 3], |t| t.weighted());
        let mut direction = [Real::ZERO; 3];
        for ((d, &b), &w) in direction.iter_mut().zip(&base).zip(&self.push) {
            *d = b.saturating_add(w.mul_q30(gust));
        }
        Tropism {
            direction,
            elasticity: Real::ONE,
        }
    }
}
