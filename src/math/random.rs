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

/// The chaos game's stream: Marsaglia's xorshift32 (shifts 13, 17, 5).
///
/// Three shifts and three exclusive-ors a number, where PCG32's 64-bit multiply is several
/// 32-bit ones on a Cortex-M core (measured in docs/performance.md, The fern against the
/// sketches); its period, 2³² − 1, is longer than any game played. Seeded through
/// SplitMix64's finaliser (a state of 0 would stay 0). Not `Copy`, like any stream: a
/// copy would repeat its numbers.
#[allow(missing_copy_implementations)]
#[derive(Debug, Clone)]
pub struct Xorshift32(u32);

impl Xorshift32 {
    /// The stream for `seed`.
    pub const fn new(seed: u64) -> Self {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        let state = (z ^ (z >> 31)) as u32;
        Self(if state == 0 { 0x9E37_79B9 } else { state })
    }

    /// The next number.
    #[inline(always)]
    pub fn next_u32(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }
}

/// Mixes 32 bits (Wellons' lowbias32): every input bit moves about half the output bits.
#[inline]
const fn mix(mut h: u32) -> u32 {
    h ^= h >> 16;
    h = h.wrapping_mul(0x7FEB_352D);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846C_A68B);
    h ^ (h >> 16)
}

/// 32 random bits for (`seed`, `key`, `word`): counter-based, so any sample of a picture is
/// computed on its own, in any order, the same on every target. 32-bit multiplies only
/// (single instructions on Cortex-M0).
#[inline]
pub(crate) const fn hash(seed: u64, key: u32, word: u32) -> u32 {
    let seeded = mix((seed as u32) ^ mix((seed >> 32) as u32 ^ 0x9E37_79B9));
    mix(mix(seeded ^ key).wrapping_add(word.wrapping_mul(0x9E37_79B9)) ^ 0x85EB_CA6B)
}

/// A standard normal variate for (`seed`, `key`) in Q16: the sum of 12 uniform bytes
/// minus their mean (Irwin–Hall), so its mean is 0 and its variance 1 − 2⁻¹⁶ (each byte's
/// uniform on 256 levels has variance (1 − 2⁻¹⁶)/12); its tails stop at ±6, and its
/// kurtosis is 2.9 against the normal's 3. Three hashes and no multiply beyond them.
pub(crate) const fn normal_q16(seed: u64, key: u32) -> i32 {
    let mut sum: i32 = 0;
    let mut word = 0;
    while word < 3 {
        let bits = hash(seed, key, word);
        sum += (bits & 0xFF) as i32
            + ((bits >> 8) & 0xFF) as i32
            + ((bits >> 16) & 0xFF) as i32
            + (bits >> 24) as i32;
        word += 1;
    }
    // (Σ(b + 1/2))/256 − 6 = (Σb + 6 − 1536)/256, in Q16.
    (sum + 6 - 1536) * 256
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_variates_have_mean_zero_and_variance_one() {
        let n = 200_000;
        let values: [f64; 2] = (0..n).fold([0.0, 0.0], |[s, s2], key| {
            let v = f64::from(normal_q16(7, key)) / 65536.0;
            [s + v, s2 + v * v]
        });
        let mean = values[0] / f64::from(n);
        let variance = values[1] / f64::from(n) - mean * mean;
        assert!(mean.abs() < 0.01, "mean {mean}");
        assert!((variance - 1.0).abs() < 0.01, "variance {variance}");
        assert_ne!(normal_q16(7, 1), normal_q16(8, 1));
    }
}
