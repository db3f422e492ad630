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

/// An escape-time gallery picture.
pub struct EscapeScene {
    pub name: &'static str,
    pub julia: Option<(&'static str, &'static str)>,
    pub centre: (&'static str, &'static str),
    pub width: &'static str,
    pub max_iterations: u32,
    pub palette: &'static str,
}

pub const ESCAPE_SCENES: &[EscapeScene] = &[
    EscapeScene {
        name: "mandelbrot",
        julia: None,
        centre: ("-0.75", "0"),
        width: "3.5",
        max_iterations: 256,
        palette: "classic",
    },
    EscapeScene {
        name: "seahorse-valley",
        julia: None,
        centre: ("-0.7435", "0.1314"),
        width: "0.02",
        max_iterations: 512,
        palette: "fire",
    },
    EscapeScene {
        name: "julia",
        julia: Some(("-0.8", "0.156")),
        centre: ("0", "0"),
        width: "3.2",
        max_iterations: 300,
        palette: "classic",
    },
    EscapeScene {
        // Width 10^-9: beyond the 32-bit tier, computed in Q60 with 128-bit products.
        name: "deep-zoom",
        julia: None,
        centre: ("-0.743643887037151", "0.131825904205330"),
        width: "0.000000001",
        max_iterations: 4000,
        palette: "fire",
    },
];

fn row(scene: &str, detail: &str, work: &str, elapsed: std::time::Duration, file: &Path) {
    println!(
        "| {:<22} | {:<14} | {:>18} | {:>9.3} | {}",
        scene,
        detail,
        work,
        elapsed.as_secs_f64() * 1e3,
        file.display()
    );
}

/// Renders every scene into `out` and prints a table; returns whether all succeeded.
pub fn run(out: &Path) -> bool {
    println!(
        "| {:<22} | {:<14} | {:>18} | {:>9} | file",
        "scene", "detail", "work", "ms"
    );
    println!("|{:-<24}|{:-<16}|{:->20}|{:->11}|-----", "", "", "", "");
    let mut ok = true;
    let mut report =
        |name: &str, result: Result<(String, String, std::time::Duration), String>, path: &Path| {
            match result {
                Ok((detail, work, elapsed)) => row(name, &detail, &work, elapsed, path),
                Err(error) => {
                    eprintln!("tinyfractal: error: {name}: {error}");
                    ok = false;
                }
            }
        };
    for scene in SCENES {
        let path = out.join(format!("{}.png", scene.name));
        let result = scene
            .grammar()
            .and_then(|grammar| {
                crate::scene::render_oriented(&grammar, scene.order, 320, 240, scene.orientation)
            })
            .map_err(|e| e.to_string())
            .and_then(|rendered| {
                save(&rendered.display, &path)?;
                Ok((
                    format!("order {}", scene.order),
                    format!("{} segments", rendered.stats.segments),
                    rendered.elapsed,
                ))
            });
        report(scene.name, result, &path);
    }
    for scene in ESCAPE_SCENES {
        let path = out.join(format!("{}.png", scene.name));
        let request = crate::escape_scene::Request {
            julia: scene.julia,
            centre: scene.centre,
            width: scene.width,
            size: embedded_graphics::geometry::Size::new(320, 240),
            max_iterations: scene.max_iterations,
            algorithm: tinyfractal::Algorithm::Fast,
            tier: None,
            palette: scene.palette,
        };
        let result = crate::escape_scene::render(&request).and_then(|rendered| {
            save(&rendered.display, &path)?;
            Ok((
                format!("{} tier", rendered.stats.tier.name()),
                format!("{} iterations", rendered.stats.iterations),
                rendered.elapsed,
            ))
        });
        report(scene.name, result, &path);
    }
    ok
}

fn save(
    display: &embedded_graphics_simulator::SimulatorDisplay<embedded_graphics::pixelcolor::Rgb888>,
    path: &Path,
) -> Result<(), String> {
    crate::output::save_png(display, path)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}
