//! One `Copy` error type for the whole crate, with messages that say how to fix the input.
//!
//! [`Error`] holds one small enum per stage (reading text, walking, fitting, views), each
//! with its own `Display` in its own module. It stands on `math` alone and names no family's
//! items, so every family can return these without a cycle; the number layer returns its
//! own small results ([`Overflow`],
//! [`AngleOutOfRange`](crate::math::AngleOutOfRange)) that become `Error`s here.

use core::fmt;

use crate::math::Overflow;

mod fit;
mod location;
mod parameter;
mod read;
mod view;
mod walk;

pub use fit::{FitError, MAX_PART_PIXELS};
pub use location::Location;
pub use parameter::ParameterError;
pub use read::{ReadError, ReadWarning, Unsupported};
pub use view::ViewError;
pub use walk::{Arithmetic, WalkError};

/// A draw's outcome as `Drawable::draw` reports it: the target's errors. The engine's
/// cannot happen there (fitting the drawing ran the same computation without one); should
/// one, nothing more is drawn and the default (empty) statistics are returned.
pub(crate) fn only_target_errors<T: Default, E>(result: Result<T, DrawError<E>>) -> Result<T, E> {
    match result {
        Ok(value) => Ok(value),
        Err(DrawError::Target(error)) => Err(error),
        Err(DrawError::Fractal(_)) => Ok(T::default()),
    }
}

/// Everything that can go wrong in tinyfractal, from reading a system to drawing it,
/// grouped by stage so that each group stays small and each message says how to fix it.
///
/// Match a group, then its variant: `Error::Read(ReadError::MissingAxiom)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Error {
    /// The text of a system is malformed.
    Read(ReadError),
    /// A walk reached a capacity, its budget or the fixed-point range.
    Walk(WalkError),
    /// The picture cannot be placed on the target.
    Fit(FitError),
    /// An escape-time view cannot be computed.
    View(ViewError),
    /// A generator's parameter (order, roughness, samples, box sizes) is out of range.
    Parameter(ParameterError),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Read(error) => error.fmt(f),
            Self::Walk(error) => error.fmt(f),
            Self::Fit(error) => error.fmt(f),
            Self::View(error) => error.fmt(f),
            Self::Parameter(error) => error.fmt(f),
        }
    }
}

impl core::error::Error for Error {}

macro_rules! group {
    ($($group:ident($error:ty)),*) => {$(
        impl From<$error> for Error {
            fn from(error: $error) -> Self {
                Self::$group(error)
            }
        }

        impl core::error::Error for $error {}

        impl<E> From<$error> for DrawError<E> {
            fn from(error: $error) -> Self {
                Self::Fractal(Error::$group(error))
            }
        }
    )*};
}

group!(
    Read(ReadError),
    Walk(WalkError),
    Fit(FitError),
    View(ViewError),
    Parameter(ParameterError)
);

/// A map of the number layer left the fixed-point range while walking.
impl From<Overflow> for Error {
    fn from(_: Overflow) -> Self {
        Self::Walk(WalkError::Overflow)
    }
}

/// An error while drawing: either the engine's own [`Error`] or the display's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawError<E> {
    /// The system could not be drawn.
    Fractal(Error),
    /// The draw target reported an error.
    Target(E),
}

impl<E> From<Error> for DrawError<E> {
    fn from(error: Error) -> Self {
        Self::Fractal(error)
    }
}

impl<E: fmt::Debug> fmt::Display for DrawError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Fractal(error) => error.fmt(f),
            Self::Target(error) => write!(f, "the draw target failed: {error:?}"),
        }
    }
}

impl<E: fmt::Debug> core::error::Error for DrawError<E> {}
