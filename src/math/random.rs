//! The seeded generator: PCG32 (`rand_pcg`, value-stable across versions and targets), so
//! a seed gives the same numbers on the host and every MCU.

use rand_core::{RngCore, SeedableRng};
use rand_pcg::Pcg32;

/// A seeded stream of 32-bit numbers, the same on every target.
#[derive(Debug, Clone)]
pub struct Generator(Pcg32);

impl Generator {
    /// The stream for `seed`.
    pub fn new(seed: u64) -> Self {
        Self(Pcg32::seed_from_u64(seed))
    }

    /// The next number.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        self.0.next_u32()
    }
}
