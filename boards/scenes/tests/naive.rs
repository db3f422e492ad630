//! The loops a user would write draw the scene's picture: the L-system sketch lights
//! about the pixels the engine does (its own fit, so not pixel for pixel).

use std::ops::Range;

use embedded_graphics::{pixelcolor::Gray4, prelude::*};
use tinyfractal::render::Orientation;
use tinyfractal_scenes::naive::{lsystem_f32, monopodial_tree_f32, turn_degrees};
use tinyfractal_scenes::{Scene, System, Work, FERN, GENERAL_SCENES, GREY, KOCH_SNOWFLAKE};
use tinyfractal_test_support::frame::Frame;

/// The box of the pixels `chosen` picks, and how many there are.
fn reach(frame: &Frame<Gray4>, chosen: impl Fn(Gray4) -> bool) -> (Point, Point, usize) {
    let mut count = 0;
    let (mut low, mut high) = (
        Point::new(i32::MAX, i32::MAX),
        Point::new(i32::MIN, i32::MIN),
    );
    for y in 0..frame.size.height as i32 {
        for x in 0..frame.size.width as i32 {
            if frame.pixel(x, y).is_some_and(&chosen) {
                count += 1;
                low = low.component_min(Point::new(x, y));
                high = high.component_max(Point::new(x, y));
            }
        }
    }
    (low, high, count)
}

/// Asserts that a sketch's pixels (box and count, as [`reach`] gives them) are about the
/// scene's: each corner within `slack` pixels, the count's ratio to the scene's in
/// `ratios`.
fn assert_alike(
    sketch: (Point, Point, usize),
    ours: (Point, Point, usize),
    slack: i32,
    ratios: Range<f64>,
) {
    let ((low, high, count), (our_low, our_high, our_count)) = (sketch, ours);
    for (a, b) in [(low, our_low), (high, our_high)] {
        assert!(
            (a - b).x.abs() <= slack && (a - b).y.abs() <= slack,
            "{a:?} {b:?}"
        );
    }
    let ratio = count as f64 / our_count as f64;
    assert!(ratios.contains(&ratio), "{count} against {our_count}");
}

#[test]
fn the_lsystem_sketch_draws_the_scenes_picture() {
    let size = Size::new(128, 64);
    for (system, order, orientation) in [
        (&KOCH_SNOWFLAKE, 4, Orientation::Right),
        (&FERN, 5, Orientation::Up),
    ] {
        let system: &'static System = system;
        let mut ours = Frame::filled(size, GREY.background);
        let scene = Scene::LSystem {
            system,
            order,
            orientation,
        };
        let work = scene.draw(&mut ours, &GREY).unwrap();
        let degrees = turn_degrees(system.angle);
        let mut sketch = Frame::filled(size, Gray4::BLACK);
        let rules = (system.axiom, system.rules, system.draw_symbols);
        let lines = lsystem_f32(
            rules,
            degrees,
            order,
            orientation == Orientation::Up,
            &mut sketch,
        );
        // The same lines (the scene counts segments the same way), in about the same box
        // (the fits' margins differ by a few pixels), lighting about as many pixels.
        let Work::Segments(segments) = work else {
            panic!("{work:?}")
        };
        assert_eq!(lines, segments);
        assert_alike(
            reach(&sketch, |c| c == Gray4::WHITE),
            reach(&ours, |c| c == GREY.ink),
            4,
            0.75..1.33,
        );
    }
}

/// The parametric 3D tree's sketch draws the engine's tree: the same lines, in about the
/// same box, lighting about as many pixels (the engine colours its tree; the sketch draws
/// it white).
#[test]
fn the_tree_sketch_draws_the_scenes_tree() {
    let entry = GENERAL_SCENES
        .iter()
        .find(|entry| entry.name == "monopodial-tree")
        .unwrap();
    let mut ours = Frame::filled(entry.size, GREY.background);
    let Work::Segments(segments) = entry.draw(&mut ours, &GREY).unwrap() else {
        panic!("an L-system counts segments")
    };
    let mut sketch = Frame::filled(entry.size, Gray4::BLACK);
    let lines = monopodial_tree_f32(entry.order, &mut sketch);
    assert_eq!(lines, segments);
    assert_alike(
        reach(&sketch, |c| c != Gray4::BLACK),
        reach(&ours, |c| c != GREY.background),
        4,
        0.75..1.33,
    );
    // One order more outgrows the sketch's buffer: nothing drawn.
    assert_eq!(monopodial_tree_f32(entry.order + 1, &mut sketch), 0);
}

/// A string longer than the buffer draws nothing, and says so by drawing no line.
#[test]
fn an_outgrown_string_draws_nothing() {
    let mut sketch = Frame::filled(Size::new(32, 32), Gray4::BLACK);
    let rules = (KOCH_SNOWFLAKE.axiom, KOCH_SNOWFLAKE.rules, "");
    assert_eq!(lsystem_f32(rules, 60.0, 7, false, &mut sketch), 0);
}

/// The Bézier sketch draws the scene's curves: about the same pixels in the same box.
#[test]
fn the_bezier_sketch_draws_the_scenes_curves() {
    use tinyfractal_scenes::{design_placement, naive::bezier_f32, SMOOTH_FIGURE};
    let size = Size::new(128, 64);
    let mut ours = Frame::filled(size, GREY.background);
    Scene::Bezier {
        curves: &SMOOTH_FIGURE,
    }
    .draw(&mut ours, &GREY)
    .unwrap();
    let mut sketch = Frame::filled(size, Gray4::BLACK);
    let place = design_placement(sketch.bounding_box());
    let lines = bezier_f32(&SMOOTH_FIGURE, place, 16, &mut sketch);
    assert_eq!(lines, 16 * SMOOTH_FIGURE.len() as u64);
    assert_alike(
        reach(&sketch, |c| c == Gray4::WHITE),
        reach(&ours, |c| c == GREY.ink),
        1,
        0.8..1.25,
    );
}

/// The profile sketch draws one column of ground a pixel column, from the bottom, the
/// lowest height one pixel high and the highest the whole column.
#[test]
fn the_terrain_sketch_draws_ground_from_the_bottom() {
    use tinyfractal_scenes::naive::terrain_f32;
    let size = Size::new(128, 64);
    let mut sketch = Frame::filled(size, Gray4::new(5));
    assert_eq!(terrain_f32((0.7, 40.0, 7), 129, &mut sketch), 129);
    let mut grounds = Vec::new();
    for x in 0..128 {
        let column: Vec<bool> = (0..64)
            .map(|y| sketch.pixel(x, y) == Some(Gray4::WHITE))
            .collect();
        let ground = column.iter().filter(|&&g| g).count();
        // Sky above, ground below: no pixel left in the background.
        assert!(column[64 - ground..].iter().all(|&g| g), "column {x}");
        assert!((0..64).all(|y| sketch.pixel(x, y) != Some(Gray4::new(5))));
        grounds.push(ground);
    }
    assert_eq!(grounds.iter().min(), Some(&1));
    assert_eq!(grounds.iter().max(), Some(&64));
    assert_eq!(terrain_f32((0.7, 40.0, 7), 2000, &mut sketch), 0);
}

/// The sponge's sketch draws the 400 cubes of order 2 over about the scene's box, lighting
/// about as many pixels.
#[test]
fn the_sponge_sketch_draws_the_scenes_sponge() {
    use tinyfractal_scenes::{naive::sponge_f32, Shape};
    let size = Size::new(128, 64);
    let mut ours = Frame::filled(size, GREY.background);
    Scene::Subdivision {
        shape: Shape::Cube(tinyfractal::subdivision::CubeVariant::Axes),
        order: 2,
    }
    .draw(&mut ours, &GREY)
    .unwrap();
    let mut sketch = Frame::filled(size, Gray4::BLACK);
    assert_eq!(sponge_f32(2, &mut sketch), 400);
    assert_alike(
        reach(&sketch, |c| c != Gray4::BLACK),
        reach(&ours, |c| c != GREY.background),
        4,
        0.8..1.25,
    );
}

/// The landscape's sketch makes its 33² heights and paints every pixel, in bands: the
/// lowest pixels water (dark), the highest snow (light), and shades between.
#[test]
fn the_landscape_sketch_paints_every_pixel_in_bands() {
    use tinyfractal_scenes::naive::landscape_f32;
    let size = Size::new(128, 64);
    // On two backgrounds the same picture: every pixel painted.
    let mut sketch = Frame::filled(size, Gray4::BLACK);
    assert_eq!(landscape_f32((0.6, 40.0, 3), 33, &mut sketch), 33 * 33);
    let mut again = Frame::filled(size, Gray4::WHITE);
    landscape_f32((0.6, 40.0, 3), 33, &mut again);
    assert!(sketch.pixels == again.pixels);
    let lumas: std::collections::BTreeSet<u8> = sketch.pixels.iter().map(|p| p.luma()).collect();
    assert!(lumas.len() >= 6, "{lumas:?}");
    assert!(
        lumas.contains(&3) && lumas.iter().any(|&l| l >= 13),
        "{lumas:?}"
    );
    assert_eq!(landscape_f32((0.6, 40.0, 3), 30, &mut sketch), 0);
}

/// The pixels an f64 model of an attractor's sketch lights: `step` from `start`, 1,000
/// steps skipped, then `points` points each placed by `place`.
fn modelled<S: Copy>(
    size: Size,
    start: S,
    step: impl Fn(S) -> S,
    place: impl Fn(S, Size) -> (f64, f64),
    points: u32,
) -> std::collections::BTreeSet<(i32, i32)> {
    let mut state = start;
    let mut lit = std::collections::BTreeSet::new();
    for n in 0..1000 + points {
        state = step(state);
        if n >= 1000 {
            let (x, y) = place(state, size);
            let (x, y) = (x.floor() as i32, y.floor() as i32);
            if (0..size.width as i32).contains(&x) && (0..size.height as i32).contains(&y) {
                lit.insert((x, y));
            }
        }
    }
    lit
}

/// The pixels a sketch lit on black.
fn lit_pixels(frame: &Frame<Gray4>) -> std::collections::BTreeSet<(i32, i32)> {
    let mut lit = std::collections::BTreeSet::new();
    for y in 0..frame.size.height as i32 {
        for x in 0..frame.size.width as i32 {
            if frame.pixel(x, y).is_some_and(|c| c != Gray4::BLACK) {
                lit.insert((x, y));
            }
        }
    }
    lit
}

/// The share of `model`'s pixels a sketch lit, and of the sketch's the model lit.
fn shares(
    sketch: &std::collections::BTreeSet<(i32, i32)>,
    model: &std::collections::BTreeSet<(i32, i32)>,
) -> (f64, f64) {
    let both = sketch.intersection(model).count() as f64;
    (both / model.len() as f64, both / sketch.len() as f64)
}

/// The Hénon sketches, in `f32` and in Q4.28, light the pixels an f64 orbit of the map
/// lights in their box (the orbits part after a few dozen steps, the attractor they fill
/// does not), and not those of an orbit placed two pixels off.
#[test]
fn the_henon_sketches_draw_the_attractor() {
    use tinyfractal_scenes::naive::{henon_f32, henon_fixed};
    let size = Size::new(128, 64);
    let place = |shift: f64| {
        move |(x, y): (f64, f64), size: Size| {
            (
                (x + 1.5) * f64::from(size.width) / 3.0 + shift,
                (0.45 - y) * f64::from(size.height) / 0.9,
            )
        }
    };
    let step = |(x, y): (f64, f64)| (1.0 - 1.4 * x * x + y, 0.3 * x);
    let model = modelled(size, (0.0, 0.0), step, place(0.0), 20_000);
    let off = modelled(size, (0.0, 0.0), step, place(2.0), 20_000);
    for sketch in [henon_f32::<Frame<Gray4>>, henon_fixed::<Frame<Gray4>>] {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        assert_eq!(sketch(20_000, &mut frame), 20_000);
        let lit = lit_pixels(&frame);
        let (of_model, of_sketch) = shares(&lit, &model);
        assert!(
            of_model > 0.95 && of_sketch > 0.95,
            "{of_model} {of_sketch}"
        );
        let (of_off, _) = shares(&lit, &off);
        assert!(of_off < 0.75, "two pixels off: {of_off}");
    }
}

/// The Lorenz sketches, in `f32` and in Q16.16, light the pixels an f64 RK4 orbit of the
/// flow lights in their box (x across, z up), and not those of an orbit placed six pixels
/// off.
#[test]
fn the_lorenz_sketches_draw_the_attractor() {
    use tinyfractal_scenes::naive::{lorenz_f32, lorenz_fixed};
    type State = [f64; 3];
    fn f([x, y, z]: State) -> State {
        [10.0 * (y - x), x * (28.0 - z) - y, x * y - 8.0 / 3.0 * z]
    }
    fn ahead(s: State, k: State, h: f64) -> State {
        [s[0] + h * k[0], s[1] + h * k[1], s[2] + h * k[2]]
    }
    let step = |s: State| {
        let dt = 0.01;
        let k1 = f(s);
        let k2 = f(ahead(s, k1, dt / 2.0));
        let k3 = f(ahead(s, k2, dt / 2.0));
        let k4 = f(ahead(s, k3, dt));
        std::array::from_fn(|i| s[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    };
    let place = |shift: f64| {
        move |s: State, size: Size| {
            (
                (s[0] + 25.0) * f64::from(size.width) / 50.0 + shift,
                (50.0 - s[2]) * f64::from(size.height) / 50.0,
            )
        }
    };
    let size = Size::new(128, 64);
    let model = modelled(size, [1.0; 3], step, place(0.0), 20_000);
    let off = modelled(size, [1.0; 3], step, place(6.0), 20_000);
    for sketch in [lorenz_f32::<Frame<Gray4>>, lorenz_fixed::<Frame<Gray4>>] {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        assert_eq!(sketch(20_000, &mut frame), 20_000);
        let lit = lit_pixels(&frame);
        let (of_model, of_sketch) = shares(&lit, &model);
        // The flow's projection is dense at 128×64: orbits part, and a trajectory of 200
        // time units lights about nine in ten of another's pixels.
        assert!(
            of_model > 0.88 && of_sketch > 0.88,
            "{of_model} {of_sketch}"
        );
        let (of_off, _) = shares(&lit, &off);
        assert!(of_off < 0.84, "six pixels off: {of_off}");
    }
}
