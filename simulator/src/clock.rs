//! How long a render took, where the platform has a clock: the playground's WebAssembly
//! build has none (`std::time::Instant::now` panics there) and reports no time.

#[cfg(not(target_arch = "wasm32"))]
pub use std::time::Instant;

/// A moment that is always now: every render takes no time.
#[cfg(target_arch = "wasm32")]
#[derive(Debug, Clone, Copy)]
pub struct Instant;

#[cfg(target_arch = "wasm32")]
impl Instant {
    /// Now.
    pub fn now() -> Self {
        Self
    }

    /// Zero.
    pub fn elapsed(&self) -> std::time::Duration {
        std::time::Duration::ZERO
    }
}
