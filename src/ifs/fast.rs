//! The chaos game of a planar IFS seen from the front, played in the pixels' own fixed
//! point: each map conjugated by the fit (X = ox + s·x, Y = oy − s·y), so that a point
//! costs a choice, two 32×32→64 multiply-accumulates an axis and a shift, with no
//! projection after.
//!
//! Points are Q16.16 pixels (pixel (x, y) is centred on (x, y); up to 2¹⁵ pixels), the
//! maps' matrices Q1.31 (each entry in [−1, 1)), their translations Q16.16 pixels. A map
//! is chosen exactly as [`Ifs::choose`] chooses it, from thresholds on the random number:
//! the same sequence of maps as the `Real` game for the same seed.
//!
//! The fit plays [`FIT_POINTS`] points in a provisional scale (the attractor's a-priori
//! bound, |t| / (1 − c) for the largest translation t and matrix norm c, kept under 2¹³
//! pixels), adds the maps' fixed points and their images under every map (points of the
//! attractor a short game may miss), fits their box, then conjugates the maps by the fit:
//! the fit plays a bounded sample, not a second game (its cost: docs/performance.md, The
//! fern against the sketches). Points beyond the
//! sample's box are drawn where they land inside the area (the margin) and clipped outside
//! it.

use super::maps::Ifs;
use crate::math::random::Xorshift32;
use crate::math::wide::dot_high;
use crate::math::Real;
use crate::render::reach::Reach;

/// Most maps the fast game takes (an IFS with more plays the `Real` game): eight keep a
/// drawing's maps at 264 bytes, for the micro:bit's 16 KiB.
pub const FAST_MAPS: usize = 8;

/// Top bits of the random number that index the choice buckets.
const BUCKET_BITS: u32 = 6;

/// Points computed and not plotted at the start of a game (either game).
pub const SKIPPED: u32 = 100;

/// Points the fit plays (after the transient) to measure the attractor's box.
pub const FIT_POINTS: u64 = 1 << 12;

/// The largest matrix norm (row sums) the fast game takes: the attractor's a-priori bound
/// needs a contraction.
const MOST_CONTRACTION: Real = Real::from_bits(((1 << 32) / 1000) * 999);

/// One map in pixel space.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct PixelMap {
    /// X' = hi(2·(a·X + b·Y)) + e, Y' = hi(2·(c·X + d·Y)) + f: a–d Q1.31, e and f Q16.16.
    a: i32,
    b: i32,
    c: i32,
    d: i32,
    e: i32,
    f: i32,
}

impl PixelMap {
    /// The map applied to `(x, y)` (Q16.16), as the game applies it.
    #[inline(always)]
    fn apply(&self, (x, y): (i32, i32)) -> (i32, i32) {
        let along = |p: i32, q: i32, t: i32| {
            // Q1.31 × Q16.16 is Q17.47: twice the high word is the Q16.16 value (its lowest
            // bit dropped), wrapped.
            (dot_high(p, x, q, y) << 1).wrapping_add(t)
        };
        (along(self.a, self.b, self.e), along(self.c, self.d, self.f))
    }

    /// The point the map keeps (Q16.16): (I − M)·p = t by Cramer's rule, in 64 bits
    /// (the matrix in Q1.30, so a product of two entries and a translation fits); `None`
    /// if I − M is singular or the point beyond range.
    #[inline(never)]
    fn fixed_point(&self) -> Option<(i32, i32)> {
        const ONE: i64 = 1 << 30;
        let [a, b, c, d] = [self.a, self.b, self.c, self.d].map(|v| i64::from(v >> 1));
        let (e, f) = (i64::from(self.e), i64::from(self.f));
        // Q2.60, then Q30; the numerators Q16.16 × Q1.30, each term below 2^62.
        let det = ((ONE - a) * (ONE - d) - b * c) >> 30;
        if det == 0 {
            return None;
        }
        let x = ((ONE - d) * e + b * f) / det;
        let y = (c * e + (ONE - a) * f) / det;
        Some((i32::try_from(x).ok()?, i32::try_from(y).ok()?))
    }
}

/// A map index masked to the slots (`FAST_MAPS` is a power of two).
pub(crate) const SLOT_MASK: usize = FAST_MAPS - 1;
const _: () = assert!(FAST_MAPS.is_power_of_two());

/// A bucket whose random numbers choose more than one map.
const MIXED: u8 = u8::MAX;

/// The map `random` chooses among `count` with `thresholds`: the first whose threshold
/// is above it, else the last.
#[inline(never)]
fn fast_search(thresholds: &[u32; FAST_MAPS], count: usize, random: u32) -> usize {
    let last = count.saturating_sub(1);
    let mut index = 0;
    while index < last {
        match thresholds.get(index) {
            Some(&threshold) if random >= threshold => index += 1,
            _ => break,
        }
    }
    index
}

/// Never used: a map index is below the count, itself at most `FAST_MAPS`.
const IDENTITY: PixelMap = PixelMap {
    a: i32::MAX,
    b: 0,
    c: 0,
    d: i32::MAX,
    e: 0,
    f: 0,
};

/// A planar IFS conjugated into pixel space, with its choice thresholds.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PixelMaps {
    maps: [PixelMap; FAST_MAPS],
    /// Map i is chosen for random numbers below `thresholds[i]` (and at or above the ones
    /// before); the last for every number left.
    thresholds: [u32; FAST_MAPS],
    /// The map of every random number with these top bits, where they all choose one
    /// ([`MIXED`] where the thresholds split them): one load for most choices.
    buckets: [u8; 1 << BUCKET_BITS],
    count: usize,
    /// Where the game starts: the attractor space's origin.
    start: (i32, i32),
}

/// `value` (Q32) as Q1.31, if in [−1, 1).
fn q31(value: Real) -> Option<i32> {
    i32::try_from(value.to_bits() >> 1).ok()
}

/// `value` (Q32) as Q16.16, if within ±2¹⁵.
fn q16(value: Real) -> Option<i32> {
    i32::try_from(value.to_bits() >> 16).ok()
}

impl PixelMaps {
    /// `ifs`'s maps conjugated by X = ox + s·x, Y = oy − s·y (`None` for a map out of the
    /// fast game's range: more than [`FAST_MAPS`] maps, an entry beyond [−1, 1), a
    /// translation beyond 2¹⁵ pixels).
    #[inline(never)]
    pub(crate) fn new(ifs: &Ifs, scale: Real, origin: (Real, Real)) -> Option<Self> {
        if ifs.is_empty() || ifs.len() > FAST_MAPS {
            return None;
        }
        let (weighted, total) = ifs.weighted();
        let mut maps = [PixelMap::default(); FAST_MAPS];
        let mut thresholds = [0u32; FAST_MAPS];
        let mut count = 0;
        let mut sum = 0u64;
        let (ox, oy) = origin;
        for ((slot, threshold), (map, weight)) in
            maps.iter_mut().zip(thresholds.iter_mut()).zip(weighted)
        {
            let [[a, b, _], [c, d, _], _] = map.matrix;
            let [e, f, _] = map.translation;
            let mul = |x: Real, y: Real| x.checked_mul(y);
            // X' = a·X − b·Y + (ox − a·ox + b·oy + s·e)
            let ex = ox
                .checked_sub(mul(a, ox)?)?
                .checked_add(mul(b, oy)?)?
                .checked_add(mul(scale, e)?)?;
            // Y' = −c·X + d·Y + (oy + c·ox − d·oy − s·f)
            let fy = oy
                .checked_add(mul(c, ox)?)?
                .checked_sub(mul(d, oy)?)?
                .checked_sub(mul(scale, f)?)?;
            *slot = PixelMap {
                a: q31(a)?,
                b: q31(Real::ZERO.checked_sub(b)?)?,
                c: q31(Real::ZERO.checked_sub(c)?)?,
                d: q31(d)?,
                e: q16(ex)?,
                f: q16(fy)?,
            };
            // Chosen while pick = ⌊r·total / 2³²⌋ < sum, that is r < ⌈sum·2³² / total⌉.
            sum += u64::from(weight);
            let bound =
                ((u128::from(sum) << 32) + u128::from(total) - 1) / u128::from(total.max(1));
            *threshold = u32::try_from(bound).unwrap_or(u32::MAX);
            count += 1;
        }
        if count == 0 {
            return None;
        }
        let mut fast = Self {
            maps,
            thresholds,
            buckets: [MIXED; 1 << BUCKET_BITS],
            count,
            start: (q16(ox)?, q16(oy)?),
        };
        let below = 32 - BUCKET_BITS;
        for (top, bucket) in (0u32..).zip(fast.buckets.iter_mut()) {
            let first = fast_search(&thresholds, count, top << below);
            let last = fast_search(&thresholds, count, (top << below) | ((1 << below) - 1));
            if first == last {
                *bucket = u8::try_from(first).unwrap_or(MIXED);
            }
        }
        Some(fast)
    }

    /// Each map's fixed point (Q16.16), where the map has one within range.
    fn fixed_points(&self) -> impl Iterator<Item = (i32, i32)> + '_ {
        self.maps
            .iter()
            .take(self.count)
            .filter_map(PixelMap::fixed_point)
    }

    /// The map `random` chooses: its bucket's, or found among the thresholds.
    #[inline(always)]
    fn choose(&self, random: u32) -> (usize, &PixelMap) {
        let bucket = self
            .buckets
            .get((random >> (32 - BUCKET_BITS)) as usize)
            .copied();
        let index = match bucket {
            Some(index) if index != MIXED => usize::from(index),
            _ => fast_search(&self.thresholds, self.count, random),
        };
        // The index is below the count already; masked, the compiler knows it is a slot.
        let index = index & SLOT_MASK;
        match self.maps.get(index) {
            Some(map) => (index, map),
            None => (0, &IDENTITY),
        }
    }

    /// The game of `points` points from the start (after the transient), seeded.
    pub(crate) fn game(&self, seed: u64) -> PixelGame<'_> {
        let mut game = PixelGame {
            maps: self,
            generator: Xorshift32::new(seed),
            point: self.start,
        };
        for _ in 0..SKIPPED {
            game.next_point();
        }
        game
    }
}

/// A chaos game in pixel space: endless; the caller counts the points.
#[derive(Debug, Clone)]
pub(crate) struct PixelGame<'m> {
    maps: &'m PixelMaps,
    generator: Xorshift32,
    point: (i32, i32),
}

impl PixelGame<'_> {
    /// The next point (Q16.16 pixels) and the map that put it there.
    #[inline(always)]
    pub(crate) fn next_point(&mut self) -> (usize, (i32, i32)) {
        let (index, map) = self.maps.choose(self.generator.next_u32());
        let next = map.apply(self.point);
        self.point = next;
        (index, next)
    }
}

/// Calls `each` `count` times, counting in 32 bits: a 64-bit count is a pair of registers
/// and a carry on a 32-bit core, every point (docs/performance.md, The fern against the
/// sketches).
#[inline(always)]
pub(crate) fn repeat(count: u64, mut each: impl FnMut()) {
    let mut left = count;
    while left > 0 {
        let chunk = u32::try_from(left).unwrap_or(u32::MAX);
        for _ in 0..chunk {
            each();
        }
        left -= u64::from(chunk);
    }
}

/// The pixel (column, row) a Q16.16 point is on.
#[inline(always)]
pub(crate) fn pixel((x, y): (i32, i32)) -> (i32, i32) {
    ((x + (1 << 15)) >> 16, (y + (1 << 15)) >> 16)
}

/// The largest row sum of the maps' matrices, and the largest translation.
fn bounds(ifs: &Ifs) -> (Real, Real) {
    let (mut norm, mut reach) = (Real::ZERO, Real::ZERO);
    for map in ifs.maps() {
        for row in map.matrix.iter().take(2) {
            let sum = row
                .iter()
                .take(2)
                .fold(Real::ZERO, |s, v| s.saturating_add(v.abs()));
            norm = norm.max(sum);
        }
        for t in map.translation.iter().take(2) {
            reach = reach.max(t.abs());
        }
    }
    (norm, reach)
}

/// The box (low, high, in attractor units) of the first [`FIT_POINTS`] points of `ifs`'s
/// game from `seed` (fewer if it plays fewer), played in a provisional scale; `None` if the
/// fast game cannot play it (a map not contracting, an entry beyond [−1, 1)).
pub(crate) fn sample_box(ifs: &Ifs, seed: u64, points: u64) -> Option<([Real; 3], [Real; 3])> {
    let (norm, reach) = bounds(ifs);
    if norm > MOST_CONTRACTION {
        return None;
    }
    // The attractor lies within reach / (1 − norm) of the origin: keep that under 2^13
    // pixels with a power-of-two scale 2^k (k ≤ 16).
    let radius = reach
        .checked_div(Real::ONE.checked_sub(norm)?)?
        .max(Real::ONE);
    let mut k = 16u32;
    while k > 0 && radius.to_bits() >> (32 - k) >= 1 << 13 {
        k -= 1;
    }
    if radius.to_bits() >> (32 - k) >= 1 << 13 {
        return None;
    }
    let scale = Real::from_int(1 << k);
    let maps = PixelMaps::new(ifs, scale, (Real::ZERO, Real::ZERO))?;
    let mut game = maps.game(seed);
    let (x, y) = game.next_point().1;
    let (mut across, mut down) = (Reach::of(x), Reach::of(y));
    let mut extend = |(x, y): (i32, i32)| {
        across.widen(x);
        down.widen(y);
    };
    // In 32 bits, as [`repeat`] counts.
    let fit_points = u32::try_from(points.clamp(1, FIT_POINTS)).unwrap_or(1);
    for _ in 1..fit_points {
        extend(game.next_point().1);
    }
    // The maps' fixed points are on the attractor, and so are their images: the extremes
    // a short game may miss (the fern's stem ends at map 1's fixed point).
    for fixed in maps.fixed_points() {
        extend(fixed);
        for map in maps.maps.iter().take(maps.count) {
            extend(map.apply(fixed));
        }
    }
    // Q16.16 provisional pixels to attractor units (Q32): · 2^16 / 2^k; y points down.
    let unit = |v: i32| Real::from_bits(i64::from(v) << (16 - k));
    let negated = |v: i32| Real::from_bits(-(i64::from(v) << (16 - k)));
    Some((
        [unit(across.low), negated(down.high()), Real::ZERO],
        [unit(across.high()), negated(down.low), Real::ZERO],
    ))
}

#[cfg(test)]
mod tests {
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;

    use super::*;
    use crate::ifs::{ChaosGame, IfsFile};
    use crate::render::space::SpaceFit;

    const FERN: &str = "fern {\n 0 0 0 .16 0 0 .01\n .85 .04 -.04 .85 0 1.6 .85\n\
                        .2 -.26 .23 .22 0 1.6 .07\n -.15 .28 .26 .24 0 .44 .07\n}\n\
                        gasket {\n .5 0 0 .5 0 0 .333\n .5 0 0 .5 .5 0 .333\n\
                        .5 0 0 .5 .25 .5 .334\n}\n";

    /// The game in pixel space chooses the maps the `Real` game chooses for the same seed,
    /// and puts each point within a pixel of where the fit places the `Real` game's.
    #[test]
    fn the_pixel_game_is_the_real_game_placed() {
        for name in ["fern", "gasket"] {
            let ifs = IfsFile::new(FERN).entry(name).unwrap().ifs().unwrap();
            for (size, seed) in [((128, 64), 1), ((320, 240), 7), ((61, 97), 3)] {
                let area = Rectangle::new(Point::new(3, 2), Size::new(size.0, size.1));
                let (low, high) = sample_box(&ifs, seed, 30_000).unwrap();
                let space = SpaceFit::front_box(low, high, &area, 2).unwrap();
                let (scale, origin) = space.front_linear().unwrap();
                let maps = PixelMaps::new(&ifs, scale, origin).unwrap();
                let mut fast = maps.game(seed);
                let mut outside = 0;
                for point in ChaosGame::new(&ifs, seed, 30_000) {
                    let point = point.unwrap();
                    let (map, q) = fast.next_point();
                    assert_eq!(map, point.map, "{name}");
                    let (placed, _) = space.place(point.position);
                    let (x, y) = pixel(q);
                    assert!(
                        (x - placed.x).abs() <= 1 && (y - placed.y).abs() <= 1,
                        "{name} {size:?}: ({x}, {y}) against {placed:?}"
                    );
                    outside += usize::from(!area.contains(Point::new(x, y)));
                }
                // The sample's box holds the rest of the game but for a handful.
                assert!(outside <= 30, "{name} {size:?}: {outside} outside");
            }
        }
    }

    /// A map that does not contract, or a matrix entry beyond [−1, 1), leaves the fast game.
    #[test]
    fn only_contracting_maps_play_fast() {
        let wide = "w {\n 1.2 0 0 .5 0 0 .5\n .5 0 0 .5 1 0 .5\n}\n";
        let ifs = IfsFile::new(wide).entry("w").unwrap().ifs().unwrap();
        assert!(sample_box(&ifs, 1, 100).is_none());
    }
}
