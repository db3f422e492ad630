//! Golden images: scenes rendered through the simulator display and compared pixel for
//! pixel with reviewed PNGs in tests/golden (embedded-graphics-simulator's `load_png` and
//! `diff`). Regenerate after an intended change with `TINYFRACTAL_BLESS=1 cargo test`, then
//! look at every changed picture before committing it.

mod common;

use std::path::PathBuf;

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use tinyfractal::{
    escape::Shading,
    render::{Gradient, Orientation},
    Angle, Coord, Dialect, EscapeTime, Fractal, Grammar, LFile, LSystem, Real, View,
};

const PALETTE: [Rgb888; 4] = [Rgb888::WHITE, Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE];

fn golden_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.png"))
}

fn check(name: &str, grammar: &Grammar<'_>, order: u32, orientation: Orientation) {
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(96, 96));
    LSystem::new(grammar, order)
        .with_orientation(orientation)
        .fit(display.bounding_box(), &PALETTE)
        .unwrap()
        .draw(&mut display)
        .unwrap();
    check_picture(name, &display);
}

/// Compares `display` with the golden picture `name` (or writes it when blessing).
fn check_picture(name: &str, display: &SimulatorDisplay<Rgb888>) {
    let path = golden_path(name);
    let settings = OutputSettingsBuilder::new().build();
    if std::env::var_os("TINYFRACTAL_BLESS").is_some() {
        display
            .to_rgb_output_image(&settings)
            .save_png(&path)
            .unwrap();
        return;
    }
    let expected = SimulatorDisplay::<Rgb888>::load_png(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (TINYFRACTAL_BLESS=1 creates it)", path.display()));
    if let Some(difference) = display.diff(&expected) {
        let actual = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}.actual.png"));
        display
            .to_rgb_output_image(&settings)
            .save_png(&actual)
            .unwrap();
        let first = difference
            .bounding_box()
            .points()
            .find(|&p| difference.get_pixel(p).is_on())
            .unwrap_or_default();
        panic!(
            "{name}: differs from {} first at {first:?} (got {:?}, want {:?}); actual picture in {}",
            path.display(),
            display.get_pixel(first),
            expected.get_pixel(first),
            actual.display()
        );
    }
}

#[test]
fn koch_snowflake() {
    check(
        "koch-snowflake-3",
        &common::koch_snowflake(),
        3,
        Orientation::Right,
    );
}

#[test]
fn dragon_from_a_file() {
    let text = include_str!("data/small.l");
    let grammar = LFile::new(text).find("Dragon").unwrap();
    check("dragon-8", &grammar, 8, Orientation::Right);
}

#[test]
fn plant_with_a_free_angle() {
    let grammar = Grammar::new(Dialect::Abop, "X", Angle::Degrees(Real::from_int(20)))
        .unwrap()
        .with_rule('X', "F[+X]F[-X]+X")
        .unwrap()
        .with_rule('F', "FF")
        .unwrap();
    check("plant-4", &grammar, 4, Orientation::Up);
}

#[test]
fn colours_and_degree_turns() {
    // Fractint commands: colour changes, the free heading (`\`, `/`, `D`) and `@` scaling.
    let grammar = Grammar::new(
        Dialect::Fractint,
        "C1D\\90C2D\\90C3D\\90C0D",
        Angle::Divisions(4),
    )
    .unwrap()
    .with_rule('d', "D@.5[\\45D]@I.5D")
    .unwrap();
    check("colour-square-3", &grammar, 3, Orientation::Right);
}

#[test]
fn smooth_mandelbrot() {
    // The whole set in a gradient of 256 entries over 16 iterations: dwells would show
    // bands 16 entries apart; smooth values fill them in.
    let c = |v: f64| Coord::from_f64(v).unwrap();
    let size = Size::new(160, 120);
    let view = View::new(Fractal::Mandelbrot, (c(-0.6), c(0.0)), c(3.2), size, 100)
        .unwrap()
        .with_shading(Shading::Smooth)
        .unwrap();
    let keys = [
        Rgb888::new(0x00, 0x07, 0x64),
        Rgb888::new(0x20, 0x6B, 0xCB),
        Rgb888::new(0xED, 0xFF, 0xFF),
        Rgb888::new(0xFF, 0xAA, 0x00),
    ];
    let palette = Gradient::<Rgb888, 256>::new(&keys, Rgb888::BLACK).unwrap();
    let mut display = SimulatorDisplay::<Rgb888>::new(size);
    EscapeTime::new(view, &palette).draw(&mut display).unwrap();
    check_picture("smooth-mandelbrot", &display);
}
