//! Where a picture's pixels fall on the noise's lattice: the coordinate ⌊scale·i/across⌋
//! of the i-th of `across` points, by one division or stepped along a row.

use crate::math::Real;

/// The coordinate ⌊scale·index/across⌋ (in 2⁻³²) of a grid of `across` points a
/// `scale` apart (`across` taken as at least 1, `scale` not negative); `None` past `Real`'s
/// range. In 64 bits where the product fits (scales below 2¹⁵ cells across a few thousand
/// points): a 128-bit division costs a Cortex-M tens of times more, for the same quotient.
#[inline(never)]
pub(super) fn lattice_point(scale: Real, index: u32, across: u32) -> Option<Real> {
    let (scale, across) = (scale.to_bits(), i64::from(across.max(1)));
    let bits = match scale.checked_mul(i64::from(index)) {
        Some(product) => product / across,
        None => i64::try_from(i128::from(scale) * i128::from(index) / i128::from(across)).ok()?,
    };
    Some(Real::from_bits(bits))
}

/// The coordinates [`lattice_point`] gives for the indices 0, 1, 2, … in turn, by
/// quotient and remainder instead of a 64-bit division each (`scale` taken as at least 0,
/// `across` as at least 1). Past `Real`'s range the coordinates wrap: a caller takes
/// only those its fit checked.
#[derive(Debug, Clone)]
pub(super) struct LatticeSteps {
    next: i64,
    carried: i64,
    quotient: i64,
    remainder: i64,
    across: i64,
}

impl LatticeSteps {
    /// From index 0, `scale` lattice units over `across` points.
    pub(super) fn new(scale: Real, across: u32) -> Self {
        let (scale, across) = (scale.to_bits().max(0), i64::from(across.max(1)));
        Self {
            next: 0,
            carried: 0,
            quotient: scale / across,
            remainder: scale % across,
            across,
        }
    }
}

impl Iterator for LatticeSteps {
    type Item = Real;

    #[inline]
    fn next(&mut self) -> Option<Real> {
        let point = Real::from_bits(self.next);
        self.next = self.next.wrapping_add(self.quotient);
        self.carried += self.remainder;
        if self.carried >= self.across {
            self.carried -= self.across;
            self.next = self.next.wrapping_add(1);
        }
        Some(point)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stepping gives [`lattice_point`]'s coordinates, at scales whose products need 128
    /// bits too.
    #[test]
    fn lattice_steps_are_the_divided_points() {
        let scales = [
            1,
            3,
            1 << 32,
            4_294_967_297,
            17_179_869_184_007,
            i64::MAX / 5,
        ];
        for (scale, across) in scales
            .into_iter()
            .flat_map(|s| [1, 7, 128, 333].map(|a| (s, a)))
        {
            let scale = Real::from_bits(scale);
            let steps = LatticeSteps::new(scale, across);
            for (index, stepped) in (0..1000).zip(steps) {
                let Some(divided) = lattice_point(scale, index, across) else {
                    break;
                };
                assert_eq!(stepped, divided, "{scale:?} {across} {index}");
            }
        }
    }
}
