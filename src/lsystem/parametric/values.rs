//! What a parametric walk hands out: a module's symbol and its parameter values.

use core::fmt;

use crate::math::Real;

/// Most parameters a module has.
pub const MAX_PARAMS: usize = 4;

/// A module's parameter values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Values {
    pub(super) values: [Real; MAX_PARAMS],
    pub(super) count: u8,
}

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
