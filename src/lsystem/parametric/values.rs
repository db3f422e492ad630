//! What a parametric walk hands out: a module's symbol and its parameter values.

use core::fmt;

use crate::math::Real;

/// Most parameters a module has.
pub const MAX_PARAMS: usize = 4;

/// A module's parameter values.
///
/// Two are equal where their values are ([`as_slice`](Self::as_slice)): the slots past
/// the count are whatever a buffer held before, and mean nothing.
#[derive(Debug, Clone, Copy, Default)]
pub struct Values {
    pub(super) values: [Real; MAX_PARAMS],
    pub(super) count: u8,
}

impl PartialEq for Values {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl Eq for Values {}

impl Values {
    /// The first value, if any.
    pub fn first(&self) -> Option<Real> {
        self.as_slice().first().copied()
    }

    /// The values, in order.
    pub fn as_slice(&self) -> &[Real] {
        self.values
            .get(..usize::from(self.count))
            .unwrap_or_default()
    }
}

/// A module of a derived string: its symbol and parameter values. Displays as
/// `A(1.1429,0)`: values with at most 4 decimals, trailing zeros dropped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DerivedModule {
    /// The symbol.
    pub symbol: char,
    /// The parameter values.
    pub values: Values,
}

impl DerivedModule {
    /// No module: what a buffer for one holds before the first.
    pub(crate) const NONE: Self = Self {
        symbol: '\0',
        values: Values {
            values: [Real::ZERO; MAX_PARAMS],
            count: 0,
        },
    };
}

impl fmt::Display for DerivedModule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        f.write_char(self.symbol)?;
        if self.values.count == 0 {
            return Ok(());
        }
        f.write_char('(')?;
        for (index, value) in self.values.as_slice().iter().enumerate() {
            if index > 0 {
                f.write_char(',')?;
            }
            value.write_four_decimals(f)?;
        }
        f.write_char(')')
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values are equal by their counted values alone, whatever the slots past the count.
    #[test]
    fn equality_ignores_the_slots_past_the_count() {
        let one = Real::ONE;
        let a = Values {
            values: [one, one, Real::ZERO, Real::ZERO],
            count: 2,
        };
        let stale = Values {
            values: [one, one, one, Real::from_int(7)],
            count: 2,
        };
        assert_eq!(a, stale);
        let longer = Values { count: 3, ..stale };
        assert_ne!(a, longer);
        let other = Values {
            values: [one, Real::ZERO, Real::ZERO, Real::ZERO],
            count: 2,
        };
        assert_ne!(a, other);
    }
}
