//! How a board moves from one scene to the next, and the slideshow the real boards run.

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use tinyfractal::error::DrawError;
use tinyfractal::render::Shade;

use crate::catalogue::{
    Entry, DEEP_SCENES, DYNAMICS_SCENES, GENERAL_SCENES, SCENES, TEXTURE_SCENES, ZOOM_SCENES,
};
use crate::look::{Look, Work};

/// How long an animated scene waits between its frames, in milliseconds.
pub const FRAME_MS: u64 = 60;

/// How long a real board shows a scene before the next, in milliseconds.
pub const SHOW_FOR_MS: u64 = 10_000;

/// Shows every scene of the catalogue in turn, forever: the real boards' main loop.
///
/// `now_ms` reads a free-running millisecond clock, `pressed` the board's button (its
/// polarity is the board's business), and `report` hears each scene's name, outcome and
/// drawing time, for the board's log. An animated scene waits [`FRAME_MS`] between
/// frames; each scene shows for [`SHOW_FOR_MS`] or until the button is pressed and
/// released. The textures (noise, reaction–diffusion) and the dynamics (attractors) are
/// shown by a board built with the scenes' `textures` and `dynamics` features, which the
/// real boards' firmware is.
pub fn show_scenes<D>(
    display: &mut D,
    look: &Look<'_, D::Color>,
    mut now_ms: impl FnMut() -> u64,
    mut pressed: impl FnMut() -> bool,
    mut report: impl FnMut(&str, Result<Work, DrawError<D::Error>>, u64),
) -> !
where
    D: DrawTarget,
    D::Color: From<Rgb888> + Shade,
{
    loop {
        let textures: &[Entry] = if cfg!(feature = "textures") {
            &TEXTURE_SCENES
        } else {
            &[]
        };
        let dynamics: &[Entry] = if cfg!(feature = "dynamics") {
            &DYNAMICS_SCENES
        } else {
            &[]
        };
        let every = SCENES.iter().chain(&DEEP_SCENES).chain(&ZOOM_SCENES);
        for entry in every.chain(textures).chain(dynamics) {
            let start = now_ms();
            let result = entry.scene.draw_frames(display, look, || {
                let since = now_ms();
                wait_for_press_or(FRAME_MS, || now_ms().wrapping_sub(since), || false);
            });
            report(entry.name, result, now_ms().wrapping_sub(start));
            let shown = now_ms();
            wait_for_press_or(SHOW_FOR_MS, || now_ms().wrapping_sub(shown), &mut pressed);
        }
        // The general engine's plants: leaves filled and lit, a tree in the wind.
        for entry in &GENERAL_SCENES {
            let start = now_ms();
            let result = entry.draw_frames(display, look, || {
                let since = now_ms();
                wait_for_press_or(FRAME_MS, || now_ms().wrapping_sub(since), || false);
            });
            report(entry.name, result, now_ms().wrapping_sub(start));
            let shown = now_ms();
            wait_for_press_or(SHOW_FOR_MS, || now_ms().wrapping_sub(shown), &mut pressed);
        }
    }
}

/// How a board moves to the next scene.
///
/// Returns once the button has been pressed and released, or after `ms` milliseconds.
/// `elapsed_ms` counts from the start of the wait, and `pressed` reads the button (its polarity
/// is the board's business).
pub fn wait_for_press_or(
    ms: u64,
    mut elapsed_ms: impl FnMut() -> u64,
    mut pressed: impl FnMut() -> bool,
) {
    let mut was_pressed = false;
    while elapsed_ms() < ms {
        let down = pressed();
        if was_pressed && !down {
            return;
        }
        was_pressed |= down;
    }
}

#[cfg(test)]
mod tests {
    use super::wait_for_press_or;
    use core::cell::Cell;

    /// Runs a wait of 100 ms against a button that reads `button(poll)`, one poll per
    /// millisecond; returns the polls made.
    fn polls(button: impl Fn(u64) -> bool) -> u64 {
        let clock = Cell::new(0);
        wait_for_press_or(
            100,
            || clock.get(),
            || {
                let down = button(clock.get());
                clock.set(clock.get() + 1);
                down
            },
        );
        clock.get()
    }

    #[test]
    fn a_press_counts_when_released() {
        assert_eq!(polls(|t| (10..20).contains(&t)), 21);
    }

    #[test]
    fn without_a_release_the_timeout_ends_the_wait() {
        assert_eq!(polls(|_| false), 100);
        assert_eq!(polls(|t| t >= 50), 100);
    }
}
