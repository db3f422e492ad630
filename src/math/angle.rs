//! Turn angles and the turtle's direction table: exact for `n` divisions of a full turn,
//! interpolated for free angles in degrees.

use heapless::Vec;

use super::real::Real;
use super::trig;

/// Most divisions of a full turn for `Angle n` (Fractint allowed 50).
pub const MAX_ANGLE_DIVISIONS: u16 = 64;

/// `Angle n` with `n` of 0 or over [`MAX_ANGLE_DIVISIONS`].
///
/// The number layer's own small result: the reader that found the angle adds where.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AngleOutOfRange {
    /// The divisions asked for.
    pub divisions: u16,
}

/// How far `+` and `-` turn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Angle {
    /// `n` equal divisions of a full turn (Fractint's `Angle n`), exact for every heading.
    Divisions(u16),
    /// A free angle in degrees (ABOP's δ); headings use a 1024-point quarter-wave table with
    /// interpolation (error below 3·10⁻⁷).
    Degrees(Real),
}

impl Angle {
    /// A free angle from decimal degrees with an optional sign (`22.5`, `-90`), exactly
    /// rounded: the one parser for degrees given as text. `None` if `text` is not a number
    /// or beyond ±2³¹ degrees.
    pub fn parse_degrees(text: &str) -> Option<Self> {
        Real::parse_signed(text.trim()).map(Self::Degrees)
    }
}

/// The turtle's direction vectors: for `Angle n`, cos and sin of each heading in Q30;
/// for a free angle, the turn as a binary angle.
#[derive(Debug, Clone)]
pub(crate) struct Headings {
    /// Headings 0..=n/2; the rest mirror them exactly.
    half_table: Vec<(i32, i32), { MAX_ANGLE_DIVISIONS as usize / 2 + 1 }>,
    divisions: u16,
    free_turn: trig::BinaryAngle,
    /// Trailing zeros of the free turn: the free headings a turtle reaches are multiples
    /// of 2^shift.
    free_shift: u32,
}

impl Headings {
    /// Four divisions of a full turn: a default that always exists.
    pub(crate) fn quarter_turns() -> Self {
        let mut half_table = Vec::new();
        for k in 0..=2 {
            let _ = half_table.push(trig::sin_cos(k, 4));
        }
        Self {
            half_table,
            divisions: 4,
            free_turn: trig::BinaryAngle::default(),
            free_shift: 31,
        }
    }

    pub(crate) fn new(angle: Angle) -> Result<Self, AngleOutOfRange> {
        let mut headings = Self {
            half_table: Vec::new(),
            divisions: 0,
            free_turn: trig::BinaryAngle::default(),
            free_shift: 31,
        };
        match angle {
            Angle::Divisions(n) => {
                if n == 0 || n > MAX_ANGLE_DIVISIONS {
                    return Err(AngleOutOfRange { divisions: n });
                }
                headings.divisions = n;
                for k in 0..=n / 2 {
                    // Past a quarter turn (n even), heading k mirrors heading n/2 - k:
                    // `sin_cos` sums the same series for both, so it is summed once.
                    let mirrored = n % 2 == 0 && 4 * k > n;
                    let value = match headings.half_table.get(usize::from(n / 2 - k)) {
                        Some(&(c, s)) if mirrored => (-c, s),
                        _ => trig::sin_cos(u32::from(k), u32::from(n)),
                    };
                    let _ = headings.half_table.push(value);
                }
            }
            Angle::Degrees(degrees) => {
                headings.free_turn = trig::BinaryAngle::from_degrees_bits(degrees.to_bits());
                headings.free_shift = headings.free_turn.0.trailing_zeros().min(31);
            }
        }
        Ok(headings)
    }

    /// Number of divisions, or 0 for a free angle.
    #[inline]
    pub(crate) const fn divisions(&self) -> u16 {
        self.divisions
    }

    /// The headings a turtle can reach by turns, when they are few and exact: `Angle n`
    /// gives n; a free angle whose binary turn δ generates at most `MAX_ANGLE_DIVISIONS`
    /// binary angles (δ a multiple of 2³² / n for a power of two n: 90°, 45°, 22.5°, ...)
    /// gives that n. `None` for any other free angle.
    pub(crate) fn cycle(&self) -> Option<HeadingCycle> {
        if self.divisions > 0 {
            return Some(HeadingCycle {
                count: self.divisions,
                turn: 1,
                shift: 0,
            });
        }
        let delta = self.free_turn.0;
        // Headings k·δ mod 2³² are the multiples of 2^z, z = trailing zeros of δ: 2^(32-z)
        // of them (at least 2, so that `|`, half a turn, is one of them).
        let zeros = self.free_shift;
        let count = 1u64 << (32 - zeros);
        (count <= u64::from(MAX_ANGLE_DIVISIONS)).then(|| HeadingCycle {
            count: u16::try_from(count).unwrap_or(MAX_ANGLE_DIVISIONS),
            turn: u16::try_from(u64::from(delta >> zeros) % count).unwrap_or(0),
            shift: zeros,
        })
    }
}

/// The finite set of headings of a turtle: `count` of them, index h; `+` adds `turn`; for a
/// free angle, heading h is the binary angle h << `shift` (for `Angle n`, `shift` is 0 and
/// the heading is the division).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct HeadingCycle {
    pub(crate) count: u16,
    pub(crate) turn: u16,
    pub(crate) shift: u32,
}

impl Headings {
    /// Trailing zeros of the free turn (at most 31): free headings reached by turns are
    /// multiples of 2 to this power.
    #[inline]
    pub(crate) const fn cycle_shift(&self) -> u32 {
        self.free_shift
    }

    /// The binary-angle turn of `+` for a free angle.
    #[inline]
    pub(crate) const fn free_turn(&self) -> trig::BinaryAngle {
        self.free_turn
    }

    /// Cosine and sine of heading `k` (0..n), exact mirror images for `k` and `n - k`.
    #[inline]
    pub(crate) fn cos_sin(&self, k: u16) -> (i32, i32) {
        let mirrored = k > self.divisions / 2;
        let index = if mirrored { self.divisions - k } else { k };
        let (c, s) = self
            .half_table
            .get(usize::from(index))
            .copied()
            .unwrap_or((trig::ONE_Q30, 0));
        if mirrored {
            (c, -s)
        } else {
            (c, s)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every heading of `Angle n` is the exactly rounded direction, however the table got
    /// it (summed, or mirrored from the heading short of half a turn).
    #[test]
    fn every_heading_is_its_exact_direction() {
        for n in 1..=MAX_ANGLE_DIVISIONS {
            let headings = Headings::new(Angle::Divisions(n)).unwrap();
            for k in 0..n {
                assert_eq!(
                    headings.cos_sin(k),
                    trig::sin_cos(u32::from(k), u32::from(n)),
                    "{k}/{n}"
                );
            }
        }
    }
}
