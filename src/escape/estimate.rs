//! What a view asks of distance estimation, and the value it gives a pixel at a distance:
//! shared by the fixed tiers' kernel and perturbed pixels (the estimate itself: `distance`).

use super::view::{Shading, View, DISTANCE_INSIDE};
use crate::math::log::{log2, LOG2_FRAC_BITS};

/// What a view asks of distance estimation: a width within which escaping points are
/// drawn as the set, a shading by distance, or both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Estimate {
    /// log₂ of the width in pixels within which a point is drawn as the set, Q16.
    near_log2: Option<i32>,
    /// Whether the view shades by distance.
    shading: bool,
}

impl Estimate {
    /// What `view` asks, or `None` if it estimates no distances.
    pub(crate) fn of(view: &View) -> Option<Self> {
        view.estimates_distance().then(|| Self {
            near_log2: match view.distance {
                0 => None,
                width => log2(u64::from(width), 8),
            },
            shading: view.shading == Shading::Distance,
        })
    }

    /// Whether the view shades by distance: every escaped pixel's value is the estimate's.
    pub(crate) const fn shades(self) -> bool {
        self.shading
    }

    /// The value of an escaped pixel at `log2_pixels` (Q16) from the set: one above the
    /// `inside` value if it lies within the width (drawn as the set, told from it), the
    /// distance shading's value if the view shades by distance; `None` for the ordinary
    /// value. A pixel whose orbit, run again, did not escape (`None`: at the boundary, in
    /// another arithmetic than the tier's) takes the nearest the shading has, or the
    /// ordinary value.
    pub(super) fn value(self, log2_pixels: Option<i64>, inside: u32) -> Option<u32> {
        let Some(log2_pixels) = log2_pixels else {
            return self.shading.then_some(1);
        };
        if self
            .near_log2
            .is_some_and(|near| log2_pixels < i64::from(near))
        {
            return Some((inside + 1).min(u32::from(u16::MAX)));
        }
        if self.shading {
            let value = 1 + ((log2_pixels + (4 << LOG2_FRAC_BITS)) >> 12);
            let value = value.clamp(1, i64::from(DISTANCE_INSIDE) - 1);
            return Some(value as u32);
        }
        None
    }
}
