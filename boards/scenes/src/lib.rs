//! The scenes every tinyfractal board shows, in order, drawn the same way on the host and on
//! the board: the QEMU test compares the LM3S6965's screen with the host's rendering, the
//! measuring firmware folds them into checksums, and the Pico and the STM32F429I-DISCO
//! show them on their displays. One [`Look`] per display says which colours to use.
#![no_std]
#![deny(missing_docs, unsafe_code)]

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor, Rgb565, Rgb888},
    prelude::*,
};
use tinyfractal::{
    Angle, Coord, Dialect, DrawError, Error, EscapeTime, Fractal, Gradient, Grammar, LSystem,
    Orientation, Real, View,
};

/// What to draw.
#[derive(Debug, Clone, Copy)]
pub enum Scene {
    /// An L-system.
    LSystem {
        /// Axiom.
        axiom: &'static str,
        /// Rules, symbol and body.
        rules: &'static [(char, &'static str)],
        /// `Angle n`, or degrees as decimal text.
        angle: SceneAngle,
        /// Order.
        order: u32,
        /// Which way the first heading points.
        orientation: Orientation,
    },
    /// A Mandelbrot (`julia: None`) or Julia view, as decimal text.
    Escape {
        /// The Julia parameter, or `None` for the Mandelbrot set.
        julia: Option<(&'static str, &'static str)>,
        /// Centre.
        centre: (&'static str, &'static str),
        /// Width.
        width: &'static str,
        /// Iteration cap.
        max_iterations: u32,
    },
}

/// An L-system angle.
#[derive(Debug, Clone, Copy)]
pub enum SceneAngle {
    /// Divisions of a full turn.
    Divisions(u16),
    /// Degrees, as decimal text.
    Degrees(&'static str),
}

/// The firmware's scenes: name and scene.
pub const SCENES: [(&str, Scene); 5] = [
    (
        "plant",
        Scene::LSystem {
            axiom: "X",
            rules: &[('X', "F-[[X]+X]+F[+FX]-X"), ('F', "FF")],
            angle: SceneAngle::Degrees("22.5"),
            order: 5,
            orientation: Orientation::Up,
        },
    ),
    (
        "koch-snowflake",
        Scene::LSystem {
            axiom: "F--F--F",
            rules: &[('F', "F+F--F+F")],
            angle: SceneAngle::Divisions(6),
            order: 4,
            orientation: Orientation::Right,
        },
    ),
    (
        "mandelbrot",
        Scene::Escape {
            julia: None,
            centre: ("-0.75", "0"),
            width: "3.5",
            max_iterations: 64,
        },
    ),
    (
        "julia",
        Scene::Escape {
            julia: Some(("-0.8", "0.156")),
            centre: ("0", "0"),
            width: "3.6",
            max_iterations: 100,
        },
    ),
    (
        // Width 10^-7: needs the 60-bit tier with 128-bit products.
        "deep-zoom",
        Scene::Escape {
            julia: None,
            centre: ("-0.743643887037151", "0.131825904205330"),
            width: "0.0000001",
            max_iterations: 1000,
        },
    ),
];

/// What drawing a scene did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// Segments drawn.
    Segments(u64),
    /// Iterations computed.
    Iterations(u64),
}

fn coord(text: &str) -> Result<Coord, Error> {
    Coord::parse(text).ok_or(Error::ViewOutOfRange)
}

/// The colours a display draws the scenes in.
#[derive(Debug, Clone, Copy)]
pub struct Look<'a, C> {
    /// What the target is cleared to.
    pub background: C,
    /// The L-systems' line colour.
    pub ink: C,
    /// Escape-time gradient keys, spread over 16 colours.
    pub keys: &'a [Rgb888],
    /// Escape-time points that never escape.
    pub inside: C,
}

/// The SSD0323's 4-bit grey: white lines, a dark-light-dark gradient.
pub const GREY: Look<'static, Gray4> = Look {
    background: Gray4::BLACK,
    ink: Gray4::WHITE,
    keys: &[
        Rgb888::new(0x10, 0x10, 0x10),
        Rgb888::new(0x90, 0x90, 0x90),
        Rgb888::WHITE,
        Rgb888::new(0x50, 0x50, 0x50),
    ],
    inside: Gray4::BLACK,
};

/// RGB565 displays (ST7789, ILI9341): green plants on black, a blue-gold gradient.
pub const COLOUR: Look<'static, Rgb565> = Look {
    background: Rgb565::BLACK,
    ink: Rgb565::new(12, 58, 12),
    keys: &[
        Rgb888::new(0x00, 0x07, 0x64),
        Rgb888::new(0x20, 0x6B, 0xCB),
        Rgb888::new(0xED, 0xFF, 0xFF),
        Rgb888::new(0xFF, 0xAA, 0x00),
        Rgb888::new(0x00, 0x02, 0x00),
    ],
    inside: Rgb565::BLACK,
};

impl Scene {
    /// Draws the scene over the whole of `target`: an L-system clears it to
    /// `look.background` first; an escape-time view paints every pixel anyway, so clearing
    /// would only double the traffic to the display.
    pub fn draw<D>(
        &self,
        target: &mut D,
        look: &Look<'_, D::Color>,
    ) -> Result<Work, DrawError<D::Error>>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        match *self {
            Scene::LSystem {
                axiom,
                rules,
                angle,
                order,
                orientation,
            } => {
                target.clear(look.background).map_err(DrawError::Target)?;
                let angle = match angle {
                    SceneAngle::Divisions(n) => Angle::Divisions(n),
                    SceneAngle::Degrees(text) => {
                        Angle::Degrees(Real::parse_decimal(text).ok_or(Error::MissingAngle)?)
                    }
                };
                let mut grammar = Grammar::new(Dialect::Abop, axiom, angle)?;
                for &(symbol, body) in rules {
                    grammar = grammar.with_rule(symbol, body)?;
                }
                let ink = [look.ink];
                let drawing = LSystem::new(&grammar, order)
                    .with_orientation(orientation)
                    .fit(target.bounding_box(), &ink)?;
                let stats = drawing.draw(target).map_err(DrawError::Target)?;
                Ok(Work::Segments(stats.segments))
            }
            Scene::Escape {
                julia,
                centre,
                width,
                max_iterations,
            } => {
                let fractal = match julia {
                    None => Fractal::Mandelbrot,
                    Some((re, im)) => Fractal::Julia {
                        re: coord(re)?,
                        im: coord(im)?,
                    },
                };
                let view = View::new(
                    fractal,
                    (coord(centre.0)?, coord(centre.1)?),
                    coord(width)?,
                    target.bounding_box().size,
                    max_iterations,
                )?;
                let palette = Gradient::<D::Color, 16>::new(look.keys, look.inside)
                    .ok_or(Error::EmptyPalette)?;
                let stats = EscapeTime::new(view, palette)
                    .draw(target)
                    .map_err(DrawError::Target)?;
                Ok(Work::Iterations(stats.iterations))
            }
        }
    }
}

/// How a board moves to the next scene: returns once the button has been pressed and
/// released, or after `ms` milliseconds. `elapsed_ms` counts from the start of the wait, and
/// `pressed` reads the button (its polarity is the board's business).
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
