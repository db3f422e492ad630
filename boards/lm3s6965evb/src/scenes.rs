//! The scenes the firmware shows, in order, drawn the same way on the host and the board.

use core::convert::Infallible;

use embedded_graphics::{
    pixelcolor::{Gray4, GrayColor, Rgb888},
    prelude::*,
};
use tinyfractal::{
    Angle, Coord, Dialect, Error, EscapeTime, Fractal, Gradient, Grammar, LSystem, Orientation,
    Real, View,
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

impl Scene {
    /// Clears `target` and draws the scene into it. The targets here (the framebuffer, the
    /// checksum) cannot fail, so nothing a display says is lost.
    pub fn draw<D>(&self, target: &mut D) -> Result<Work, Error>
    where
        D: DrawTarget<Color = Gray4, Error = Infallible>,
    {
        let Ok(()) = target.clear(Gray4::BLACK);
        match *self {
            Scene::LSystem {
                axiom,
                rules,
                angle,
                order,
                orientation,
            } => {
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
                let drawing = LSystem::new(&grammar, order)
                    .with_orientation(orientation)
                    .fit(target.bounding_box(), &[Gray4::WHITE])?;
                let Ok(stats) = drawing.draw(target);
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
                let keys = [
                    Rgb888::new(0x10, 0x10, 0x10),
                    Rgb888::new(0x90, 0x90, 0x90),
                    Rgb888::WHITE,
                    Rgb888::new(0x50, 0x50, 0x50),
                ];
                let palette =
                    Gradient::<Gray4, 16>::new(&keys, Gray4::BLACK).ok_or(Error::EmptyPalette)?;
                let Ok(stats) = EscapeTime::new(view, &palette).draw(target);
                Ok(Work::Iterations(stats.iterations))
            }
        }
    }
}
