//! The escape-time engine, one stage per module:
//! view (and tier) → kernel → schedule → palette → drawable.

pub(crate) mod drawing;
pub(crate) mod kernel;
pub(crate) mod perturbation;
pub(crate) mod scaled;
pub(crate) mod schedule;
pub(crate) mod series;
pub(crate) mod view;
pub(crate) mod zoom;
