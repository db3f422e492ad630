//! Fractint's `inside=` and `outside=` colourings: a pixel's value from where its orbit
//! ended, not only when, so the bands of dwell show the orbits' last points.
//!
//! Each rule is Fractint's (its `standard_fractal`), computed from the orbit's last point in
//! Q28 with integer maths, so every core gives the same value. Values always lie in
//! 1..max − 1 for a pixel a palette should colour, or are `max` for its inside colour.

use crate::math::trig::binary_angle_of_point;

/// What an orbit that never escaped is worth (Fractint's `inside=`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Inside {
    /// The cap: the palette's inside colour (Fractint's `inside=maxiter`).
    #[default]
    MaxIter,
    /// ⌊|z|²·⌊max/2⌋⌋ + 1 at the cap (Fractint's `zmag`), wrapped into 1..max − 1 as
    /// Fractint wraps colour indices: the attracting cycles' rings.
    Zmag,
    /// The period of the cycle the orbit settled into (Fractint's `period`): from z at the
    /// cap, the first k ≤ [`PERIOD_SEARCH`] steps after which both coordinates are back
    /// within 2⁻²⁰ ([`PERIOD_TOLERANCE`]), wrapped into 1..max − 1; the cap (the inside
    /// colour) where none is found.
    Period,
}

/// What an orbit that escaped is worth (Fractint's `outside=`).
///
/// From its dwell n and its first point z past radius 2; Fractint's `+ 7` keeps the values
/// positive. A value outside 1..max − 1 becomes 1, as Fractint makes those outside 1..max.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Outside {
    /// The dwell n (Fractint's `iter`).
    #[default]
    Iter,
    /// n + ⌊re z⌋ + 7, ⌊⌋ toward zero (`real`).
    Real,
    /// n + ⌊im z⌋ + 7 (`imag`).
    Imag,
    /// ⌊n · re z / im z⌋, or n where im z = 0 (`mult`).
    Mult,
    /// n + ⌊re z + im z⌋ (`summ`).
    Summ,
    /// ⌊|arg z| · 256/π⌋: the angle alone, in 256 steps (`atan`, Fractint's 256 colours).
    Atan,
}

/// Most steps [`Inside::Period`] looks ahead for the orbit's return.
pub const PERIOD_SEARCH: u32 = 1024;

/// How close (each coordinate) [`Inside::Period`]'s orbit must come back: 2⁻²⁰.
pub const PERIOD_TOLERANCE: f64 = 1.0 / (1 << 20) as f64;

/// [`PERIOD_TOLERANCE`] in Q28.
const PERIOD_TOLERANCE_Q28: i64 = 1 << 8;

impl Inside {
    /// Every mode, in the order of its CLI names.
    pub const ALL: [Self; 3] = [Self::MaxIter, Self::Zmag, Self::Period];

    /// The mode's name, as Fractint and the CLI spell it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::MaxIter => "maxiter",
            Self::Zmag => "zmag",
            Self::Period => "period",
        }
    }

    /// The value of an orbit of c (Q28) at z (Q28) after `max` steps, |z| ≤ 2.
    pub(crate) fn value(self, z: (i32, i32), c: (i32, i32), max: u32) -> u32 {
        match self {
            Self::MaxIter => max,
            Self::Zmag => {
                let (x, y) = (i64::from(z.0), i64::from(z.1));
                // Q56, at most 4·2⁵⁶. Its product with ⌊max/2⌋ < 2¹⁵ is 73 bits, taken in
                // two halves: ⌊(a·2³² + b)/2⁵⁶⌋ = ⌊(a + ⌊b/2³²⌋)/2²⁴⌋ exactly.
                let square = (x * x + y * y).unsigned_abs();
                let half = u64::from(max / 2);
                let (high, low) = (square >> 32, square & 0xFFFF_FFFF);
                let scaled = (high * half + ((low * half) >> 32)) >> 24;
                wrap(
                    u32::try_from(scaled).unwrap_or(u32::MAX).saturating_add(1),
                    max,
                )
            }
            Self::Period => match period(z, c) {
                Some(period) => wrap(period, max),
                None => max,
            },
        }
    }
}

impl Outside {
    /// Every mode, in the order of its CLI names.
    pub const ALL: [Self; 6] = [
        Self::Iter,
        Self::Real,
        Self::Imag,
        Self::Mult,
        Self::Summ,
        Self::Atan,
    ];

    /// The mode's name, as Fractint and the CLI spell it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Iter => "iter",
            Self::Real => "real",
            Self::Imag => "imag",
            Self::Mult => "mult",
            Self::Summ => "summ",
            Self::Atan => "atan",
        }
    }

    /// Whether c and its conjugate get the same value (their orbits are each other's
    /// conjugates), so a view on the real axis may be mirrored.
    pub(crate) const fn symmetric(self) -> bool {
        matches!(self, Self::Iter | Self::Real | Self::Atan)
    }

    /// The value of an orbit that escaped at step `n` at z (Q28, |re|, |im| < 8). Escaping
    /// at the cap counts as inside, as its dwell does.
    pub(crate) fn value(self, n: u32, z: (i32, i32), max: u32) -> u32 {
        const ONE: i64 = 1 << 28;
        if n >= max {
            return n.max(1);
        }
        let (x, y) = (i64::from(z.0), i64::from(z.1));
        let n64 = i64::from(n);
        // Rust's division truncates toward zero, as C's (long) cast does.
        let value = match self {
            Self::Iter => n64.max(1),
            Self::Real => n64 + x / ONE + 7,
            Self::Imag => n64 + y / ONE + 7,
            Self::Mult if y != 0 => n64 * x / y,
            Self::Mult => n64,
            Self::Summ => n64 + (x + y) / ONE,
            Self::Atan => {
                // |arg| as a fraction of a half turn, 2³¹ = π: 256 steps are its top 8 bits.
                let angle = binary_angle_of_point(z.0, z.1) as i32;
                i64::from(angle.unsigned_abs() >> 23)
            }
        };
        match u32::try_from(value) {
            Ok(value) if value >= 1 && value < max => value,
            _ => 1,
        }
    }
}

/// `value` (at least 1) wrapped into 1..max − 1: what Fractint does to colour indices past
/// its palette's end, so a value never reads as the inside colour. A cap of 1 has no room:
/// the cap.
fn wrap(value: u32, max: u32) -> u32 {
    if max <= 1 {
        return max;
    }
    if value < max {
        value
    } else {
        (value - 1) % (max - 1) + 1
    }
}

/// The steps after which the orbit of c from z (both Q28, |z| ≤ 2) first comes back within
/// [`PERIOD_TOLERANCE`] of z, looking [`PERIOD_SEARCH`] steps ahead; `None` if it does not
/// (or leaves radius 2). In i64 with products rounded down, as `Standard` computes.
fn period(z: (i32, i32), c: (i32, i32)) -> Option<u32> {
    const FOUR: i64 = 4 << 28;
    let (x0, y0) = (i64::from(z.0), i64::from(z.1));
    let (cr, ci) = (i64::from(c.0), i64::from(c.1));
    let (mut x, mut y) = (x0, y0);
    for k in 1..=PERIOD_SEARCH {
        let (x2, y2) = ((x * x) >> 28, (y * y) >> 28);
        if x2 + y2 > FOUR {
            return None;
        }
        (x, y) = (x2 - y2 + cr, ((x * y) >> 27) + ci);
        if (x - x0).abs() <= PERIOD_TOLERANCE_Q28 && (y - y0).abs() <= PERIOD_TOLERANCE_Q28 {
            return Some(k);
        }
    }
    None
}
