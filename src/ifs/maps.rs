//! An IFS: affine maps in fixed point with their probabilities as integer weights.

use heapless::Vec;

use crate::error::{Error, Location, ReadError};
use crate::math::affine::Affine3;
use crate::math::Real;

/// [`Ifs::MAX_MAPS`], for the crate's own types and arrays.
pub(crate) const MAX_MAPS: usize = 32;

/// One map of an IFS: an [`Affine3`] (a 2D map has z rows of 0).
pub type AffineMap = Affine3;

/// Maps with weights: each map's share of the 2³² random numbers, a multiply and a shift
/// to choose (no floats, no division).
#[derive(Debug, Clone, Default)]
pub struct Ifs {
    maps: Vec<(AffineMap, u32), MAX_MAPS>,
    total: u64,
    three_d: bool,
}

impl Ifs {
    /// Most maps an IFS holds (Fractint's own `fractint.ifs` has an entry of 22).
    pub const MAX_MAPS: usize = MAX_MAPS;

    /// No maps yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Removes every map, in place.
    pub(crate) fn clear(&mut self) {
        self.maps.clear();
        self.total = 0;
        self.three_d = false;
    }

    /// Adds a map chosen with `probability` (weights need not sum to 1 here; the `.ifs`
    /// reader checks that they do). `at` places errors.
    pub(crate) fn add_at(
        &mut self,
        map: AffineMap,
        probability: Real,
        at: Location,
    ) -> Result<(), Error> {
        // Weights in units of 2^-24: a probability of 1 is 2^24.
        let weight = u32::try_from(probability.to_bits() >> 8)
            .ok()
            .filter(|&w| w > 0)
            .ok_or(Error::Read(ReadError::ProbabilityOutOfRange { at }))?;
        self.maps
            .push((map, weight))
            .map_err(|_| Error::Read(ReadError::TooManyMaps { max: MAX_MAPS, at }))?;
        self.total += u64::from(weight);
        self.three_d |= map.matrix[2] != [Real::ZERO; 3] || map.translation[2] != Real::ZERO;
        Ok(())
    }

    /// Gives the maps the weights Fractint's choice gives them from `probabilities` (each
    /// map's, in order, as written: some 0 or negative), in units of 2⁻²⁴: Fractint walks
    /// the maps adding probabilities until the sum reaches a random number in [0, 1], and
    /// takes the last map if it never does. So a map is chosen for the random numbers
    /// between the largest sum before it and its own sum (none if that is not larger: a
    /// map of probability 0 or less is never chosen), and the last map for every number
    /// above all the sums before it (what the others leave).
    pub(crate) fn weigh_as_fractint(&mut self, probabilities: &[Real]) {
        const ONE: i64 = 1 << 24;
        let (mut sum, mut reached) = (0i64, 0i64);
        let last = self.maps.len().saturating_sub(1);
        self.total = 0;
        for (index, ((_, weight), probability)) in
            self.maps.iter_mut().zip(probabilities).enumerate()
        {
            let share = if index == last {
                ONE - reached
            } else {
                sum += probability.to_bits() >> 8;
                let upto = sum.clamp(0, ONE);
                let share = upto - reached;
                reached = reached.max(upto);
                share
            };
            *weight = u32::try_from(share.max(0)).unwrap_or(0);
            self.total += u64::from(*weight);
        }
    }

    /// Maps that are never chosen (a weight of 0: see `weigh_as_fractint`).
    pub fn never_chosen(&self) -> usize {
        self.maps.iter().filter(|(_, weight)| *weight == 0).count()
    }

    /// Adds a map chosen with `probability`.
    pub fn add(&mut self, map: AffineMap, probability: Real) -> Result<(), Error> {
        self.add_at(map, probability, Location::column(1))
    }

    /// Marks the system as 3D (a `(3D)` entry), even if its maps keep z = 0.
    pub(crate) fn set_3d(&mut self) {
        self.three_d = true;
    }

    /// Whether it maps space rather than the plane.
    pub fn is_3d(&self) -> bool {
        self.three_d
    }

    /// The maps, in order.
    pub fn maps(&self) -> impl Iterator<Item = &AffineMap> {
        self.maps.iter().map(|(map, _)| map)
    }

    /// The number of maps.
    pub fn len(&self) -> usize {
        self.maps.len()
    }

    /// Whether it has no maps.
    pub fn is_empty(&self) -> bool {
        self.maps.is_empty()
    }

    /// The maps with their weights, in order, and the weights' sum.
    pub(crate) fn weighted(&self) -> (impl Iterator<Item = (&AffineMap, u32)>, u64) {
        (
            self.maps.iter().map(|(map, weight)| (map, *weight)),
            self.total,
        )
    }

    /// The map a random number picks, and its index.
    #[inline]
    pub(crate) fn choose(&self, random: u32) -> (usize, &AffineMap) {
        let mut pick = (u64::from(random) * self.total) >> 32;
        for (index, (map, weight)) in self.maps.iter().enumerate() {
            if pick < u64::from(*weight) {
                return (index, map);
            }
            pick -= u64::from(*weight);
        }
        // Unreachable with maps (pick < total); an empty system stays at the origin.
        (0, &IDENTITY)
    }
}

const IDENTITY: AffineMap = AffineMap {
    matrix: [
        [Real::ONE, Real::ZERO, Real::ZERO],
        [Real::ZERO, Real::ONE, Real::ZERO],
        [Real::ZERO, Real::ZERO, Real::ONE],
    ],
    translation: [Real::ZERO; 3],
};
