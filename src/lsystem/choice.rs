//! Stochastic choices without a generator's state: each expansion's key is a hash of its
//! parent's key and its place, so any part of a derivation picks the same productions
//! whether or not the rest was walked, in any order, on every target.

/// MurmurHash3's 32-bit finaliser: every input bit moves every output bit.
pub(crate) const fn mix(mut h: u32) -> u32 {
    h ^= h >> 16;
    h = h.wrapping_mul(0x85EB_CA6B);
    h ^= h >> 13;
    h = h.wrapping_mul(0xC2B2_AE35);
    h ^ (h >> 16)
}

/// The hash of the expansion of the symbol at op `position` inside the expansion `parent`:
/// 32 bits for the choice, of which the frame keeps 16.
pub(crate) const fn child_key(parent: u16, position: u16) -> u32 {
    mix((parent as u32).wrapping_mul(0x9E37_79B9) ^ ((position as u32) << 16))
}

/// Where `key` falls among `total` units of weight: each unit gets an equal share of the
/// 2³² keys (a multiply and a shift, no division).
pub(crate) const fn pick(key: u32, total: u64) -> u64 {
    (key as u64 * total) >> 32
}

/// The 16 bits of a key a frame keeps.
pub(crate) const fn kept(key: u32) -> u16 {
    (key >> 16) as u16
}
