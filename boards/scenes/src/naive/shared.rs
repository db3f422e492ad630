//! What the sketches share beyond their own loops: C's `rand`, the careful sketches' Q16
//! numbers, the L-systems' in-place expansion and the sketches' capacities.
//!
//! Each sketch's loop stays its own; these are the pieces a sketch writer copies from one
//! sketch to the next, so they are one copy here.

/// C's `rand()` step as Arduino and newlib sketches have it (a 32-bit LCG): its bits 16 and
/// up, 0 to 32767.
pub(super) fn c_rand(seed: &mut u32) -> u32 {
    *seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
    (*seed >> 16) & 0x7FFF
}

/// A value in Q16.16, for the careful loop's constants.
pub(super) const fn q16(value: f32) -> i32 {
    (value * 65536.0) as i32
}

/// The careful sketches' product in Q16 (or Q16.16): 32 × 32 → 64 bits, shifted back.
pub(super) fn mul_q16(a: i32, b: i32) -> i32 {
    ((i64::from(a) * i64::from(b)) >> 16) as i32
}

/// The longest string the naive L-system expands, in bytes: one buffer, expanded in place.
pub const NAIVE_STRING: usize = 8 * 1024;

/// Deepest `[` nesting the naive turtle keeps.
pub(super) const NAIVE_TURTLE_STACK: usize = 64;

/// Expands `axiom` by `rules` `order` times in `buffer`, in place, as the L-system
/// sketches do: the string's length, or `None` if it outgrows the buffer.
///
/// The current string moves to the buffer's end and its expansion is written from the
/// start: the writer never passes the reader, each symbol becoming at least one. Inlined
/// into each sketch, so the `f32` one's code is what it was when written out in it.
#[inline(always)]
pub(super) fn expand(
    buffer: &mut [u8; NAIVE_STRING],
    axiom: &str,
    rules: &[(char, &str)],
    order: u32,
) -> Option<usize> {
    buffer
        .get_mut(..axiom.len())?
        .copy_from_slice(axiom.as_bytes());
    let mut length = axiom.len();
    let body = |symbol: u8| {
        rules
            .iter()
            .find(|(s, _)| *s as u32 == u32::from(symbol))
            .map(|(_, body)| body.as_bytes())
    };
    for _ in 0..order {
        let grown: usize = buffer[..length]
            .iter()
            .map(|&s| body(s).map_or(1, <[u8]>::len))
            .sum();
        if grown > NAIVE_STRING {
            return None;
        }
        buffer.copy_within(..length, NAIVE_STRING - length);
        let (mut read, mut write) = (NAIVE_STRING - length, 0);
        while read < NAIVE_STRING {
            let symbol = buffer[read];
            read += 1;
            match body(symbol) {
                Some(body) => {
                    buffer[write..write + body.len()].copy_from_slice(body);
                    write += body.len();
                }
                None => {
                    buffer[write] = symbol;
                    write += 1;
                }
            }
        }
        length = grown;
    }
    Some(length)
}

/// The most heights the naive profile holds.
pub const NAIVE_PROFILE: usize = 1025;

/// The most heights along a side of the naive landscape.
pub const NAIVE_LANDSCAPE_SIDE: usize = 33;
