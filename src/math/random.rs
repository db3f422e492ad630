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

/// A seed's share of every hash of it: mixed once for a picture, not once a sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Seeded(u32);

impl Seeded {
    /// The seed mixed.
    pub(crate) const fn new(seed: u64) -> Self {
        Self(mix((seed as u32) ^ mix((seed >> 32) as u32 ^ 0x9E37_79B9)))
    }

    /// 32 random bits for (the seed, `key`, `word`): counter-based, so any sample of a
    /// picture is computed on its own, in any order, the same on every target. 32-bit
    /// multiplies only, which Cortex-M0 has in hardware (its 64-bit products are library
    /// calls; docs/performance.md, The fern against the sketches).
    #[inline]
    pub(crate) const fn hash(self, key: u32, word: u32) -> u32 {
        mix(mix(self.0 ^ key).wrapping_add(word.wrapping_mul(0x9E37_79B9)) ^ 0x85EB_CA6B)
    }

    /// A standard normal variate for (the seed, `key`) in Q16: the sum of 12 uniform
    /// bytes minus their mean (Irwin–Hall), so its mean is 0 and its variance 1 − 2⁻¹⁶
    /// (each byte's uniform on 256 levels has variance (1 − 2⁻¹⁶)/12); its tails stop at
    /// ±6, and its kurtosis is 2.9 against the normal's 3. Three hashes and no multiply
    /// beyond them; the bytes summed two at a time in the halves of a word. Out of line:
    /// a copy at each of a landscape's calls would take the micro:bit's flash.
    #[inline(never)]
    pub(crate) const fn normal_q16(self, key: u32) -> i32 {
        // Bytes 0 and 2 in one half each, then 1 and 3: each half at most 6 × 255.
        let mut halves = 0u32;
        let mut word = 0;
        while word < 3 {
            let bits = self.hash(key, word);
            halves += (bits & 0x00FF_00FF) + ((bits >> 8) & 0x00FF_00FF);
            word += 1;
        }
        let sum = ((halves & 0xFFFF) + (halves >> 16)) as i32;
        // (Σ(b + 1/2))/256 − 6 = (Σb + 6 − 1536)/256, in Q16.
        (sum + 6 - 1536) * 256
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A variate is Irwin–Hall's sum of the twelve bytes of its three hashes, each byte
    /// taken alone here, less their mean, for many keys and seeds.
    #[test]
    fn a_variate_is_the_sum_of_its_hashes_bytes() {
        for seed in [0, 7, u64::MAX, 0x1234_5678_9ABC_DEF0] {
            let seeded = Seeded::new(seed);
            for key in (0..100_000u32).chain([u32::MAX]) {
                let bytes: i32 = (0..3)
                    .flat_map(|word| seeded.hash(key, word).to_le_bytes())
                    .map(i32::from)
                    .sum();
                assert_eq!(
                    seeded.normal_q16(key),
                    (bytes + 6 - 1536) * 256,
                    "{seed} {key}"
                );
            }
        }
    }

    #[test]
    fn normal_variates_have_mean_zero_and_variance_one() {
        let n = 200_000;
        let values: [f64; 2] = (0..n).fold([0.0, 0.0], |[s, s2], key| {
            let v = f64::from(Seeded::new(7).normal_q16(key)) / 65536.0;
            [s + v, s2 + v * v]
        });
        let mean = values[0] / f64::from(n);
        let variance = values[1] / f64::from(n) - mean * mean;
        assert!(mean.abs() < 0.01, "mean {mean}");
        assert!((variance - 1.0).abs() < 0.01, "variance {variance}");
        assert_ne!(Seeded::new(7).normal_q16(1), Seeded::new(8).normal_q16(1));
    }
}
