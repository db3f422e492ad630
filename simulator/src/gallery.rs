//! The gallery: classic L-systems rendered to PNG files, with a table of what each took.

use std::path::Path;

use tinyfractal::{Angle, Dialect, Error, Grammar, Orientation, Real};

/// One gallery picture: a named system at an order.
pub struct Scene {
    pub name: &'static str,
    pub axiom: &'static str,
    pub rules: &'static [(char, &'static str)],
    pub angle: GalleryAngle,
    pub draw_symbols: &'static str,
    pub order: u32,
    pub orientation: Orientation,
}

/// Angles as the books give them.
#[derive(Clone, Copy)]
pub enum GalleryAngle {
    Divisions(u16),
    Degrees(&'static str),
}

impl Scene {
    pub fn grammar(&self) -> Result<Grammar<'static>, Error> {
        let angle = match self.angle {
            GalleryAngle::Divisions(n) => Angle::Divisions(n),
            GalleryAngle::Degrees(text) => {
                Angle::Degrees(Real::parse_decimal(text).ok_or(Error::AngleOutOfRange {
                    value: 0,
                    at: tinyfractal::Location::default(),
                })?)
            }
        };
        let mut grammar =
            Grammar::new(Dialect::Abop, self.axiom, angle)?.with_draw_symbols(self.draw_symbols)?;
        for &(symbol, body) in self.rules {
            grammar = grammar.with_rule(symbol, body)?;
        }
        Ok(grammar)
    }
}

/// The classics, from Fractint's files and *The Algorithmic Beauty of Plants* (ABOP).
pub const SCENES: &[Scene] = &[
    Scene {
        name: "koch-snowflake",
        axiom: "F--F--F",
        rules: &[('F', "F+F--F+F")],
        angle: GalleryAngle::Divisions(6),
        draw_symbols: "",
        order: 5,
        orientation: Orientation::Right,
    },
    Scene {
        name: "dragon",
        axiom: "FX",
        rules: &[('X', "X+YF+"), ('Y', "-FX-Y")],
        angle: GalleryAngle::Divisions(4),
        draw_symbols: "",
        order: 12,
        orientation: Orientation::Right,
    },
    Scene {
        name: "hilbert",
        axiom: "A",
        rules: &[('A', "+BF-AFA-FB+"), ('B', "-AF+BFB+FA-")],
        angle: GalleryAngle::Divisions(4),
        draw_symbols: "",
        order: 6,
        orientation: Orientation::Right,
    },
    Scene {
        name: "sierpinski-arrowhead",
        axiom: "A",
        rules: &[('A', "B-A-B"), ('B', "A+B+A")],
        angle: GalleryAngle::Divisions(6),
        draw_symbols: "AB",
        order: 7,
        orientation: Orientation::Right,
    },
    Scene {
        name: "gosper",
        axiom: "A",
        rules: &[('A', "A-B--B+A++AA+B-"), ('B', "+A-BB--B-A++A+B")],
        angle: GalleryAngle::Divisions(6),
        draw_symbols: "AB",
        order: 4,
        orientation: Orientation::Right,
    },
    Scene {
        name: "plant",
        axiom: "X",
        rules: &[('X', "F[+X]F[-X]+X"), ('F', "FF")],
        angle: GalleryAngle::Degrees("20"),
        draw_symbols: "",
        order: 7,
        orientation: Orientation::Up,
    },
    Scene {
        name: "fern",
        axiom: "X",
        rules: &[('X', "F-[[X]+X]+F[+FX]-X"), ('F', "FF")],
        angle: GalleryAngle::Degrees("22.5"),
        draw_symbols: "",
        order: 6,
        orientation: Orientation::Up,
    },
    Scene {
        name: "bush",
        axiom: "F",
        rules: &[('F', "FF-[-F+F+F]+[+F-F-F]")],
        angle: GalleryAngle::Degrees("22.5"),
        draw_symbols: "",
        order: 4,
        orientation: Orientation::Up,
    },
];

/// Renders every scene into `out` and prints a table; returns whether all succeeded.
pub fn run(out: &Path) -> bool {
    println!(
        "| {:<22} | {:>5} | {:>8} | {:>9} | {:>9} | file",
        "scene", "order", "segments", "max_stack", "ms"
    );
    println!(
        "|{:-<24}|{:->7}|{:->10}|{:->11}|{:->11}|-----",
        "", "", "", "", ""
    );
    let mut ok = true;
    for scene in SCENES {
        let path = out.join(format!("{}.png", scene.name));
        let result = scene.grammar().and_then(|grammar| {
            crate::scene::render_oriented(&grammar, scene.order, 320, 240, scene.orientation)
        });
        match result {
            Ok(rendered) => match crate::output::save_png(&rendered.display, &path) {
                Ok(()) => println!(
                    "| {:<22} | {:>5} | {:>8} | {:>9} | {:>9.3} | {}",
                    scene.name,
                    scene.order,
                    rendered.stats.segments,
                    rendered.stats.max_stack,
                    rendered.elapsed.as_secs_f64() * 1e3,
                    path.display()
                ),
                Err(error) => {
                    eprintln!(
                        "tinyfractal: error: cannot write {}: {error}",
                        path.display()
                    );
                    ok = false;
                }
            },
            Err(error) => {
                eprintln!("tinyfractal: error: {}: {error}", scene.name);
                ok = false;
            }
        }
    }
    ok
}
