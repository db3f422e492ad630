//! Progress on stderr for long runs: bars and spinners drawn only when stderr is a
//! terminal (indicatif hides them otherwise), and a draw target that moves a bar.

use std::time::Duration;

use embedded_graphics::{prelude::*, primitives::Rectangle};

#[cfg(not(target_arch = "wasm32"))]
pub use indicatif::ProgressBar;
#[cfg(target_arch = "wasm32")]
pub use quiet::ProgressBar;

/// A bar over `total` steps.
pub fn bar(total: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::new(total);
    #[cfg(not(target_arch = "wasm32"))]
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} {elapsed}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    bar
}

/// The playground's WebAssembly build has no terminal, and indicatif's clock would need the
/// browser's (through wasm-bindgen): a bar that shows nothing and keeps nothing.
#[cfg(target_arch = "wasm32")]
mod quiet {
    use std::time::Duration;

    /// A bar nobody sees.
    #[derive(Debug, Default)]
    pub struct ProgressBar;

    impl ProgressBar {
        /// A bar over `total` steps.
        pub fn new(_total: u64) -> Self {
            Self
        }

        /// A spinner.
        pub fn new_spinner() -> Self {
            Self
        }

        /// A hidden bar.
        pub fn hidden() -> Self {
            Self
        }

        /// Nothing to say.
        pub fn set_message(&self, _message: String) {}

        /// Nothing to tick.
        pub fn enable_steady_tick(&self, _every: Duration) {}

        /// Nothing to clear.
        pub fn finish_and_clear(&self) {}

        /// Nothing to move.
        pub fn set_position(&self, _position: u64) {}

        /// Nothing to move.
        pub fn inc(&self, _steps: u64) {}

        /// Runs `work` (nothing to hide while it writes).
        pub fn suspend<R>(&self, work: impl FnOnce() -> R) -> R {
            work()
        }
    }
}

/// A spinner for a pass whose length is not known from outside (a fit's measuring walk).
pub fn spinner(what: &str) -> ProgressBar {
    let spinner = ProgressBar::new_spinner();
    spinner.set_message(what.to_string());
    spinner.enable_steady_tick(Duration::from_millis(120));
    spinner
}

/// Writes between moves of the bar: often enough to see, rare enough to cost nothing.
const TICK: u64 = 1 << 16;

/// A draw target that counts the writes reaching `inner` and moves `bar` by them: one a
/// point for the chaos game's and the gingerbread man's single-pixel writes.
pub struct Ticking<'b, 't, T> {
    inner: &'t mut T,
    bar: &'b ProgressBar,
    writes: u64,
}

impl<'b, 't, T> Ticking<'b, 't, T> {
    pub fn new(inner: &'t mut T, bar: &'b ProgressBar) -> Self {
        Self {
            inner,
            bar,
            writes: 0,
        }
    }

    fn tick(&mut self) {
        self.writes += 1;
        if self.writes.is_multiple_of(TICK) {
            self.bar.set_position(self.writes);
        }
    }
}

impl<T: Dimensions> Dimensions for Ticking<'_, '_, T> {
    fn bounding_box(&self) -> Rectangle {
        self.inner.bounding_box()
    }
}

impl<T: DrawTarget> DrawTarget for Ticking<'_, '_, T> {
    type Color = T::Color;
    type Error = T::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        self.tick();
        self.inner.draw_iter(pixels)
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Self::Color>,
    {
        self.tick();
        self.inner.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        self.tick();
        self.inner.fill_solid(area, color)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::BinaryColor;
    use embedded_graphics_simulator::SimulatorDisplay;

    /// The bar follows the writes, in steps of `TICK`, and the pixels still arrive.
    #[test]
    fn a_ticking_target_moves_the_bar_by_its_writes() {
        let mut display = SimulatorDisplay::<BinaryColor>::new(Size::new(4, 4));
        let bar = ProgressBar::hidden();
        let mut ticking = Ticking::new(&mut display, &bar);
        let point = Rectangle::new(Point::new(1, 2), Size::new(1, 1));
        for _ in 0..3 * TICK + 5 {
            ticking.fill_solid(&point, BinaryColor::On).unwrap();
        }
        assert_eq!(bar.position(), 3 * TICK);
        assert_eq!(display.get_pixel(Point::new(1, 2)), BinaryColor::On);
    }
}
