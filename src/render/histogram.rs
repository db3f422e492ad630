//! Histogram colouring (XaoS's, Fractint's): each of a palette's levels covers an equal
//! share of the escaping pixels, so a picture whose dwells crowd into a few values still
//! spreads over every colour.
//!
//! From the dwells' counts (a caller's buffer of max-iter + 1 entries), each escaping
//! dwell d takes level ⌊R(d)·L / T⌋, where R(d) is the number of escaping pixels of a
//! smaller dwell (the rank of its first pixel), T the escaping pixels and L the levels:
//! every level then holds T / L pixels, give or take the largest single dwell's count (a
//! dwell is never split between levels; tested). The set takes the palette's inside.

use super::palette::Palette;
use crate::error::{Error, FitError};

/// A palette's `levels` colours equalised over a picture's escaping dwells.
#[derive(Debug)]
pub struct Histogram<'c, P> {
    /// Each escaping dwell's first rank.
    starts: &'c [u32],
    total: u64,
    levels: u16,
    palette: P,
}

impl<'c, P: Palette> Histogram<'c, P> {
    /// Counts `dwells` (each below or at `max`, the inside value) into `counts` (at least
    /// `max` + 1 cells, emptied first) and turns the counts into ranks in place: `palette`
    /// then takes values 0 to `levels` − 1 for the escaping pixels, and its inside
    /// (`levels` of `levels`) for the rest.
    pub fn new(
        counts: &'c mut [u32],
        dwells: impl IntoIterator<Item = u16>,
        max: u16,
        levels: u16,
        palette: P,
    ) -> Result<Self, Error> {
        let needed = usize::from(max) + 1;
        let given = counts.len();
        let counts = counts
            .get_mut(..needed)
            .ok_or(Error::Fit(FitError::BufferTooSmall { needed, given }))?;
        counts.fill(0);
        for dwell in dwells {
            if let Some(count) = counts.get_mut(usize::from(dwell.min(max))) {
                *count = count.saturating_add(1);
            }
        }
        // Counts to first ranks, over the escaping dwells only.
        let mut rank = 0u32;
        for count in counts.iter_mut().take(usize::from(max)) {
            let this = *count;
            *count = rank;
            rank = rank.saturating_add(this);
        }
        Ok(Self {
            starts: counts,
            total: u64::from(rank),
            levels: levels.max(1),
            palette,
        })
    }
}

impl<P: Palette> Palette for Histogram<'_, P> {
    type Color = P::Color;

    fn color(&self, dwell: u16, max: u16) -> P::Color {
        match self.starts.get(usize::from(dwell)) {
            Some(&start) if dwell < max && self.total > 0 => {
                let level = u64::from(start) * u64::from(self.levels) / self.total;
                self.palette
                    .color(u16::try_from(level).unwrap_or(0), self.levels)
            }
            _ => self.palette.color(self.levels, self.levels),
        }
    }
}
