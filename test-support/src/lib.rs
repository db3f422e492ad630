//! What the tests and benches of every tinyfractal crate share, in one place instead of
//! files included by path.
//!
//! - [`frame`]: a host framebuffer of any colour and size that counts what it is sent.
//! - [`dd`]: double-double numbers and the escape-time dwell in them, the reference where
//!   `f64` runs out of bits.
//! - [`naive`]: the `f32` escape-time loop a user writes first.
//! - [`qemu`]: the Cortex-M targets and QEMU, for the tests that boot firmware.

pub mod dd;
pub mod frame;
pub mod naive;
pub mod qemu;
