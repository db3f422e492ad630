//! How a board moves from one scene to the next.

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
