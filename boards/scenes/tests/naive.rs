//! The loops a user would write draw the scene's picture: the L-system sketch lights
//! about the pixels the engine does (its own fit, so not pixel for pixel).

use std::ops::Range;

use embedded_graphics::{pixelcolor::Gray4, prelude::*};
use tinyfractal::render::Orientation;
use tinyfractal_scenes::naive::{
    lsystem_f32, lsystem_fixed, monopodial_tree_f32, monopodial_tree_fixed, turn_degrees,
    turn_divisions,
};
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
        // The careful sketch: the same lines, and but for 2 % of its pixels the float sketch's
        // picture (its directions from a Q16 sine table, its fit in Q16.16).
        let divisions = turn_divisions(system.angle).unwrap();
        let mut careful = Frame::filled(size, Gray4::BLACK);
        let up = orientation == Orientation::Up;
        assert_eq!(
            lsystem_fixed(rules, divisions, order, up, &mut careful),
            lines
        );
        assert!(
            differing(&careful, &sketch) * 50 < lit(&sketch),
            "{} of {}",
            differing(&careful, &sketch),
            lit(&sketch)
        );
    }
}

/// Pixels that differ between two pictures of the same size.
fn differing(a: &Frame<Gray4>, b: &Frame<Gray4>) -> usize {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .filter(|(a, b)| a != b)
        .count()
}

/// Pixels lit on black.
fn lit(frame: &Frame<Gray4>) -> usize {
    frame.pixels.iter().filter(|&&c| c != Gray4::BLACK).count()
}

/// A turn that divides the circle into more directions than the careful turtle keeps, or
/// into none, draws nothing; whole divisions are found from degrees.
#[test]
fn the_careful_turtle_keeps_whole_divisions_only() {
    use tinyfractal::{Angle, Real};
    assert_eq!(turn_divisions(Angle::Divisions(6)), Some(6));
    assert_eq!(turn_divisions(KOCH_SNOWFLAKE.angle), Some(6));
    assert_eq!(turn_divisions(FERN.angle), Some(16));
    assert_eq!(turn_divisions(Angle::Degrees(Real::from_int(25))), None);
    assert_eq!(turn_divisions(Angle::Divisions(65)), None);
    let mut sketch = Frame::filled(Size::new(32, 32), Gray4::BLACK);
    let rules = (KOCH_SNOWFLAKE.axiom, KOCH_SNOWFLAKE.rules, "");
    assert_eq!(lsystem_fixed(rules, 0, 2, false, &mut sketch), 0);
    assert_eq!(lsystem_fixed(rules, 65, 2, false, &mut sketch), 0);
    assert_eq!(lsystem_fixed(rules, 6, 7, false, &mut sketch), 0);
    assert_eq!(lsystem_fixed(rules, 6, 2, false, &mut sketch), 48);
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
    // The careful sketch: the same lines, and the float sketch's tree within a pixel (Q16
    // vectors turned by a Q16 sine table, unrenormalised, as the float ones).
    let mut careful = Frame::filled(entry.size, Gray4::BLACK);
    assert_eq!(monopodial_tree_fixed(entry.order, &mut careful), segments);
    let mut float = Frame::filled(entry.size, Gray4::BLACK);
    monopodial_tree_f32(entry.order, &mut float);
    assert_eq!(apart(&careful, &float), 0);
    assert_eq!(monopodial_tree_fixed(entry.order + 1, &mut careful), 0);
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

/// The sponge's sketches, in `f32` and in fixed point, draw the 400 cubes of order 2 over
/// about the scene's box, lighting about as many pixels; and the same picture but for
/// pixels on the triangles' edges.
#[test]
fn the_sponge_sketches_draw_the_scenes_sponge() {
    use tinyfractal_scenes::{
        naive::{sponge_f32, sponge_fixed},
        Shape,
    };
    let size = Size::new(128, 64);
    let mut ours = Frame::filled(size, GREY.background);
    Scene::Subdivision {
        shape: Shape::Cube(tinyfractal::subdivision::CubeVariant::Axes),
        order: 2,
    }
    .draw(&mut ours, &GREY)
    .unwrap();
    let sketches: [fn(u32, &mut Frame<Gray4>) -> u64; 2] = [sponge_f32, sponge_fixed];
    let [float, fixed] = sketches.map(|sketch| {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        assert_eq!(sketch(2, &mut frame), 400);
        assert_alike(
            reach(&frame, |c| c != Gray4::BLACK),
            reach(&ours, |c| c != GREY.background),
            4,
            0.8..1.25,
        );
        frame
    });
    let differing = (0..64)
        .flat_map(|y| (0..128).map(move |x| (x, y)))
        .filter(|&(x, y)| fixed.pixel(x, y) != float.pixel(x, y))
        .count();
    assert!(differing * 100 < 128 * 64, "{differing} pixels differ");
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

/// How far a frame's grey levels (row by row) are from `levels`: the largest difference,
/// and the share of pixels with the same level.
fn levels_apart(frame: &Frame<Gray4>, levels: &[i32]) -> (i32, f64) {
    let drawn: Vec<i32> = (0..frame.size.height as i32)
        .flat_map(|y| (0..frame.size.width as i32).map(move |x| (x, y)))
        .map(|(x, y)| i32::from(frame.pixel(x, y).unwrap().luma()))
        .collect();
    assert_eq!(drawn.len(), levels.len());
    let most = drawn.iter().zip(levels).map(|(a, b)| (a - b).abs()).max();
    let same = drawn.iter().zip(levels).filter(|(a, b)| a == b).count();
    (most.unwrap(), same as f64 / drawn.len() as f64)
}

/// The B field of Sims's Gray–Scott (D_A = 1, D_B = ½, Δt = 1, the 3×3 kernel, periodic
/// edges) in f64 after `steps` steps from the square start, on a `w`×`h` grid.
fn gray_scott_model((feed, kill): (f64, f64), (w, h): (usize, usize), steps: u32) -> Vec<f64> {
    let mut grid = vec![[1.0f64, 0.0]; w * h];
    let side = (w.min(h) / 8).max(1);
    let (x0, y0) = ((w - side) / 2, (h - side) / 2);
    for y in y0..y0 + side {
        for x in x0..x0 + side {
            grid[y * w + x][1] = 1.0;
        }
    }
    for _ in 0..steps {
        let old = grid.clone();
        for y in 0..h {
            for x in 0..w {
                let mut laplacian = [0.0; 2];
                for dy in 0..3 {
                    for dx in 0..3 {
                        let weight = match (dx, dy) {
                            (1, 1) => -1.0,
                            (1, _) | (_, 1) => 0.2,
                            _ => 0.05,
                        };
                        let cell = old[((y + h + dy - 1) % h) * w + (x + w + dx - 1) % w];
                        laplacian[0] += weight * cell[0];
                        laplacian[1] += weight * cell[1];
                    }
                }
                let [a, b] = old[y * w + x];
                let abb = a * b * b;
                grid[y * w + x] = [
                    (a + laplacian[0] - abb + feed * (1.0 - a)).clamp(0.0, 1.0),
                    (b + 0.5 * laplacian[1] + abb - (kill + feed) * b).clamp(0.0, 1.0),
                ];
            }
        }
    }
    grid.iter().map(|cell| cell[1]).collect()
}

/// The Gray–Scott sketches, in `f32` and in Q16, draw the grey levels of an f64 model's B
/// field (the scene's grid, rates and steps): at most one level apart on every pixel, and
/// the same level on most; the model at other rates (coral's) is not that close.
#[test]
fn the_gray_scott_sketches_draw_the_model() {
    use tinyfractal::reaction::Preset;
    use tinyfractal_scenes::naive::{gray_scott_f32, gray_scott_fixed};
    let rates = |preset: Preset| {
        let model = preset.model();
        (model.feed.to_f64(), model.kill.to_f64())
    };
    let (grid, steps, size) = ((24, 24), 700, Size::new(128, 64));
    let levels = |field: &[f64]| -> Vec<i32> {
        let mut levels = Vec::new();
        for j in 0..size.height as usize {
            for i in 0..size.width as usize {
                let cell = field[(j * grid.1 / size.height as usize) * grid.0
                    + i * grid.0 / size.width as usize];
                levels.push((cell.clamp(0.0, 1.0) * 15.0 + 0.5) as i32);
            }
        }
        levels
    };
    let model = levels(&gray_scott_model(rates(Preset::Mitosis), grid, steps));
    let other = levels(&gray_scott_model(rates(Preset::Coral), grid, steps));
    let (feed, kill) = rates(Preset::Mitosis);
    type Sketch = fn((f32, f32), (usize, usize), u32, &mut Frame<Gray4>) -> u64;
    let sketches: [Sketch; 2] = [gray_scott_f32, gray_scott_fixed];
    for sketch in sketches {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        let cell_steps = sketch((feed as f32, kill as f32), grid, steps, &mut frame);
        assert_eq!(cell_steps, 700 * 24 * 24);
        let apart = |levels: &[i32]| levels_apart(&frame, levels);
        let (most, same) = apart(&model);
        assert!(most <= 1 && same > 0.98, "{most} {same}");
        let (most, same) = apart(&other);
        assert!(most > 1 || same < 0.9, "{most} {same}");
    }
}

/// The fixed-point Bézier sketch's forward differences land on the cubic's own points (an
/// f64 model of each curve at t = k/16 and k/8, rounded, joined by the same `Line`s), and
/// one step less does not.
#[test]
fn the_fixed_bezier_sketch_steps_onto_the_curves_points() {
    use embedded_graphics::primitives::{Line, PrimitiveStyle};
    use tinyfractal_scenes::{design_placement, naive::bezier_fixed, SMOOTH_FIGURE};
    let size = Size::new(128, 64);
    let model = |steps: u32, frame: &mut Frame<Gray4>| {
        let place = design_placement(frame.bounding_box());
        for curve in &SMOOTH_FIGURE {
            let [p0, p1, p2, p3] = curve.map(&place);
            let at = |t: f64| {
                let u = 1.0 - t;
                let axis = |v0: i32, v1: i32, v2: i32, v3: i32| {
                    let value = u * u * u * f64::from(v0)
                        + 3.0 * u * u * t * f64::from(v1)
                        + 3.0 * u * t * t * f64::from(v2)
                        + t * t * t * f64::from(v3);
                    (value + 0.5).floor() as i32
                };
                Point::new(axis(p0.x, p1.x, p2.x, p3.x), axis(p0.y, p1.y, p2.y, p3.y))
            };
            for k in 0..steps {
                let (from, to) = (
                    at(f64::from(k) / f64::from(steps)),
                    at(f64::from(k + 1) / f64::from(steps)),
                );
                Line::new(from, to)
                    .into_styled(PrimitiveStyle::with_stroke(Gray4::WHITE, 1))
                    .draw(frame)
                    .unwrap();
            }
        }
    };
    for steps in [16, 8] {
        let mut expected = Frame::filled(size, Gray4::BLACK);
        model(steps, &mut expected);
        let mut sketch = Frame::filled(size, Gray4::BLACK);
        let place = design_placement(sketch.bounding_box());
        let lines = bezier_fixed(&SMOOTH_FIGURE, place, steps, &mut sketch);
        assert_eq!(lines, u64::from(steps) * SMOOTH_FIGURE.len() as u64);
        assert!(sketch == expected, "{steps} steps");
        let mut coarser = Frame::filled(size, Gray4::BLACK);
        model(steps / 2, &mut coarser);
        assert!(sketch != coarser, "{steps} steps against half as many");
    }
}

/// The fountain sketches' last frame, in `f32` and in Q16.16, against an f64 model of the
/// same pool, generator and forces: every lit pixel within one of a modelled particle's,
/// most of them on one, the particle-steps within 1 %; and not against the model five
/// frames earlier.
#[test]
fn the_fountain_sketches_draw_the_model() {
    use tinyfractal_scenes::naive::{fountain_f32, fountain_fixed};
    const N: usize = 128;
    let size = Size::new(128, 64);
    let model = |frames: u32| {
        let (w, h) = (f64::from(size.width), f64::from(size.height));
        let scale = h / 240.0 / 30.0;
        let (gravity, ground) = (300.0 * scale / 30.0, h * 0.95);
        let mut seed: u32 = 1;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            f64::from(seed >> 8) / 16_777_216.0
        };
        let mut particles = [(0.0f64, 0.0f64, 0.0f64, 0.0f64, 0u32, 0u32); N];
        let mut steps = 0u64;
        for _ in 0..frames {
            for _ in 0..4 {
                let slot = (0..N)
                    .find(|&i| particles[i].4 >= particles[i].5)
                    .unwrap_or_else(|| (0..N).max_by_key(|&i| particles[i].4).unwrap());
                let vx = (random() - 0.5) * 90.0 * scale;
                let vy = -(250.0 + (random() - 0.5) * 60.0) * scale;
                let life = 57 + (random() * 18.0) as u32;
                particles[slot] = (w * 0.5, ground, vx, vy, 0, life);
            }
            for p in particles.iter_mut().filter(|p| p.4 < p.5) {
                p.3 += gravity;
                p.0 += p.2;
                p.1 += p.3;
                if p.1 > ground {
                    p.1 = ground;
                    p.3 = -p.3 * 0.25;
                }
                p.4 += 1;
                steps += 1;
            }
        }
        let lit: std::collections::BTreeSet<(i32, i32)> = particles
            .iter()
            .filter(|p| p.4 < p.5)
            .map(|p| (p.0.floor() as i32, p.1.floor() as i32))
            .collect();
        (lit, steps)
    };
    let (expected, steps) = model(60);
    let (earlier, _) = model(55);
    let sketches: [fn(u32, &mut Frame<Gray4>) -> u64; 2] = [fountain_f32, fountain_fixed];
    for sketch in sketches {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        let drawn = sketch(60, &mut frame);
        assert!(
            drawn.abs_diff(steps) * 100 <= steps,
            "{drawn} against {steps}"
        );
        let lit = lit_pixels(&frame);
        let near = |set: &std::collections::BTreeSet<(i32, i32)>, (x, y): (i32, i32)| {
            (-1..=1).any(|dx| (-1..=1).any(|dy| set.contains(&(x + dx, y + dy))))
        };
        assert!(
            lit.iter().all(|&p| near(&expected, p)),
            "a pixel far from the model"
        );
        let (of_model, of_sketch) = shares(&lit, &expected);
        assert!(
            of_model > 0.95 && of_sketch > 0.95,
            "{of_model} {of_sketch}"
        );
        let (of_earlier, _) = shares(&lit, &earlier);
        assert!(of_earlier < 0.5, "five frames before: {of_earlier}");
    }
}

/// The grey levels of fBm (six octaves, halving) of Perlin's improved 2D noise in f64 over
/// a `size` picture `scale` lattice cells across, for `permutation` (his reference code's
/// fade, grad and lerp).
fn perlin_model(permutation: &[u8; 256], size: Size, scale: f64) -> Vec<i32> {
    let p: Vec<usize> = (0..512)
        .map(|i| usize::from(permutation[i % 256]))
        .collect();
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
    let grad = |hash: usize, x: f64, y: f64| {
        let h = hash & 15;
        let u = if h < 8 { x } else { y };
        let v = match h {
            0..4 => y,
            12 | 14 => x,
            _ => 0.0,
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    };
    let noise = |x: f64, y: f64| {
        let (fx, fy) = (x.floor(), y.floor());
        let (cx, cy) = ((fx as i64 & 255) as usize, (fy as i64 & 255) as usize);
        let (x, y) = (x - fx, y - fy);
        let (u, v) = (fade(x), fade(y));
        let a = p[cx] + cy;
        let b = p[cx + 1] + cy;
        lerp(
            v,
            lerp(u, grad(p[p[a]], x, y), grad(p[p[b]], x - 1.0, y)),
            lerp(
                u,
                grad(p[p[a + 1]], x, y - 1.0),
                grad(p[p[b + 1]], x - 1.0, y - 1.0),
            ),
        )
    };
    let step = scale / f64::from(size.width);
    let mut levels = Vec::new();
    for j in 0..size.height {
        for i in 0..size.width {
            let (x, y) = (f64::from(i) * step, f64::from(j) * step);
            let (mut sum, mut total) = (0.0, 0.0);
            for octave in 0..6 {
                let frequency = f64::from(1u32 << octave);
                sum += noise(x * frequency, y * frequency) / frequency;
                total += 1.0 / frequency;
            }
            let value = (sum / total + 1.0) / 2.0;
            levels.push((value.clamp(0.0, 1.0) * 15.0 + 0.5) as i32);
        }
    }
    levels
}

/// The noise sketches, in `f32` and in Q16.16, draw the grey levels of an f64 model of
/// Perlin's fBm (the scene's six octaves, four cells across, his permutation): at most one
/// level apart on every pixel and the same on most; another permutation's are not.
#[test]
fn the_noise_sketches_draw_the_model() {
    use tinyfractal::noise::Perlin;
    use tinyfractal_scenes::naive::{noise_f32, noise_fixed};
    let size = Size::new(128, 64);
    let permutation = *Perlin::seeded(0).permutation();
    let model = perlin_model(&permutation, size, 4.0);
    let other = perlin_model(Perlin::seeded(1).permutation(), size, 4.0);
    type Sketch = fn(&[u8; 256], u32, f32, &mut Frame<Gray4>) -> u64;
    let sketches: [Sketch; 2] = [noise_f32, noise_fixed];
    for sketch in sketches {
        let mut frame = Frame::filled(size, Gray4::BLACK);
        assert_eq!(sketch(&permutation, 6, 4.0, &mut frame), 6 * 128 * 64);
        let apart = |levels: &[i32]| levels_apart(&frame, levels);
        let (most, same) = apart(&model);
        assert!(most <= 1 && same > 0.95, "{most} {same}");
        let (most, same) = apart(&other);
        assert!(most > 1 && same < 0.5, "{most} {same}");
    }
}

/// C's `rand` as the sketches have it.
fn c_rand(seed: &mut u32) -> u32 {
    *seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
    (*seed >> 16) & 0x7FFF
}

/// Irwin and Hall's normal deviate from four `rand` values, in f64.
fn irwin_hall(state: &mut u32) -> f64 {
    let sum: f64 = (0..4).map(|_| f64::from(c_rand(state))).sum();
    (sum - 65_534.0) * 3f64.sqrt() / 32_768.0
}

/// The careful profile sketch draws an f64 model's profile, each column's ground within a
/// pixel of the model's: midpoint displacement with the same deviates.
#[test]
fn the_careful_terrain_sketch_draws_the_model_profile() {
    use tinyfractal_scenes::naive::terrain_fixed;
    let (size, samples) = (Size::new(128, 64), 129);
    for (roughness, sigma, seed) in [(0.7, 40.0, 7), (0.5, 10.0, 1), (0.9, 100.0, 12345)] {
        let mut heights = vec![0.0f64; samples];
        let (mut state, mut step, mut scale) = (seed, samples - 1, f64::from(sigma));
        while step > 1 {
            let half = step / 2;
            for left in (0..samples - step).step_by(step) {
                heights[left + half] =
                    (heights[left] + heights[left + step]) / 2.0 + irwin_hall(&mut state) * scale;
            }
            step = half;
            scale *= f64::from(roughness);
        }
        let low = heights.iter().copied().fold(f64::MAX, f64::min);
        let high = heights.iter().copied().fold(f64::MIN, f64::max);
        let mut sketch = Frame::filled(size, Gray4::new(5));
        assert_eq!(
            terrain_fixed((roughness, sigma, seed), samples, &mut sketch),
            129
        );
        for x in 0..128 {
            let column: Vec<bool> = (0..64)
                .map(|y| sketch.pixel(x, y) == Some(Gray4::WHITE))
                .collect();
            let ground = column.iter().filter(|&&g| g).count() as i32;
            assert!(
                column[64 - ground as usize..].iter().all(|&g| g),
                "column {x}"
            );
            assert!((0..64).all(|y| sketch.pixel(x, y) != Some(Gray4::new(5))));
            let sample = heights[x as usize * (samples - 1) / 127];
            let model = ((sample - low) / (high - low) * 63.0).floor() as i32 + 1;
            assert!(
                (ground - model).abs() <= 1,
                "column {x}: {ground} against {model}"
            );
        }
    }
    let mut sketch = Frame::filled(size, Gray4::BLACK);
    assert_eq!(terrain_fixed((0.7, 40.0, 7), 2000, &mut sketch), 0);
}

/// The careful landscape sketch paints an f64 model's landscape: diamond-square with the
/// same deviates, shaded as the float sketch shades; on all but 1 % of the pixels (where a
/// band's edge falls between them) a grey within a level of the model's (rounding a
/// product of Q16 constants can fall either side of a level's half).
#[test]
fn the_careful_landscape_sketch_paints_the_model_landscape() {
    use tinyfractal_scenes::naive::landscape_fixed;
    const BANDS: [(f64, f64); 6] = [
        (0.0, 0.2),
        (80.0 / 255.0, 0.4),
        (100.0 / 255.0, 0.75),
        (110.0 / 255.0, 0.5),
        (180.0 / 255.0, 0.45),
        (225.0 / 255.0, 0.95),
    ];
    let (size, side) = (Size::new(128, 64), 33usize);
    for (roughness, sigma, seed) in [(0.6f32, 40.0f32, 3u32), (0.8, 20.0, 99)] {
        let mut heights = vec![0.0f64; side * side];
        let at = |x: usize, y: usize| y * side + x;
        let (mut state, mut step, mut scale) = (seed, side - 1, f64::from(sigma));
        while step > 1 {
            let half = step / 2;
            for y in (half..side).step_by(step) {
                for x in (half..side).step_by(step) {
                    let mean = (heights[at(x - half, y - half)]
                        + heights[at(x + half, y - half)]
                        + heights[at(x - half, y + half)]
                        + heights[at(x + half, y + half)])
                        / 4.0;
                    heights[at(x, y)] = mean + irwin_hall(&mut state) * scale;
                }
            }
            for y in (0..side).step_by(half) {
                let first = if (y / half) % 2 == 0 { half } else { 0 };
                for x in (first..side).step_by(step) {
                    let neighbours: Vec<f64> = [(-1i32, 0i32), (1, 0), (0, -1), (0, 1)]
                        .iter()
                        .map(|(dx, dy)| (x as i32 + dx * half as i32, y as i32 + dy * half as i32))
                        .filter(|(nx, ny)| {
                            (0..side as i32).contains(nx) && (0..side as i32).contains(ny)
                        })
                        .map(|(nx, ny)| heights[at(nx as usize, ny as usize)])
                        .collect();
                    let mean = neighbours.iter().sum::<f64>() / neighbours.len() as f64;
                    heights[at(x, y)] = mean + irwin_hall(&mut state) * scale;
                }
            }
            step = half;
            scale *= f64::from(roughness);
        }
        let low = heights.iter().copied().fold(f64::MAX, f64::min);
        let high = heights.iter().copied().fold(f64::MIN, f64::max);
        let last = (side - 1) as f64;
        let height = |x: usize, y: usize| heights[y.min(side - 1) * side + x.min(side - 1)];
        let mut sketch = Frame::filled(size, Gray4::new(5));
        assert_eq!(
            landscape_fixed((roughness, sigma, seed), side, &mut sketch),
            33 * 33
        );
        let mut near = 0;
        for py in 0..64 {
            for px in 0..128 {
                let (gx, gy) = (f64::from(px) * last / 127.0, f64::from(py) * last / 63.0);
                let (x, y) = (gx as usize, gy as usize);
                let (fx, fy) = (gx - x as f64, gy - y as f64);
                let top = height(x, y) * (1.0 - fx) + height(x + 1, y) * fx;
                let bottom = height(x, y + 1) * (1.0 - fx) + height(x + 1, y + 1) * fx;
                let level = ((top * (1.0 - fy) + bottom * fy) - low) / (high - low);
                let band = BANDS.iter().rev().find(|(start, _)| level >= *start);
                let mut grey = band.map_or(0.0, |(_, grey)| *grey);
                if level >= 100.0 / 255.0 {
                    let slope = (height(x.saturating_sub(1), y.saturating_sub(1))
                        - height(x + 1, y + 1))
                        * last
                        / (high - low);
                    grey *= (1.0 - slope / 8.0).clamp(0.5, 1.4);
                }
                let model = (grey.clamp(0.0, 1.0) * 15.0 + 0.5) as u8;
                let drawn = sketch.pixel(px, py).unwrap().luma();
                near += usize::from(drawn.abs_diff(model) <= 1);
            }
        }
        assert!(near * 100 >= 128 * 64 * 99, "{near} of {} alike", 128 * 64);
    }
    let mut sketch = Frame::filled(size, Gray4::BLACK);
    assert_eq!(landscape_fixed((0.6, 40.0, 3), 30, &mut sketch), 0);
}

/// The careful figure sketch draws the float sketch's walk: the same parts each frame, and
/// the same last pose within a pixel (its angles binary, its sines from a Q16 table, its
/// points truncated from Q16.16 rather than from `f32`, so a point on a pixel's edge may
/// fall either side).
#[test]
fn the_careful_figure_sketch_walks_as_the_float_one() {
    use tinyfractal_scenes::naive::{figure_f32, figure_fixed};
    for (size, frames) in [
        (Size::new(128, 64), 16),
        (Size::new(320, 240), 5),
        (Size::new(64, 64), 1),
    ] {
        let mut float = Frame::filled(size, Gray4::new(5));
        let mut fixed = Frame::filled(size, Gray4::new(5));
        let parts = figure_f32(frames, &mut float);
        assert_eq!(figure_fixed(frames, &mut fixed), parts);
        assert_eq!(parts, u64::from(frames) * 22);
        // Each lit pixel of either within a pixel of one lit in the other.
        assert_eq!(apart(&fixed, &float), 0);
    }
}

/// Lit pixels of either picture with none lit within a pixel of it in the other.
fn apart(a: &Frame<Gray4>, b: &Frame<Gray4>) -> usize {
    let (a, b) = (lit_pixels(a), lit_pixels(b));
    let alone = |a: &std::collections::BTreeSet<(i32, i32)>,
                 b: &std::collections::BTreeSet<(i32, i32)>| {
        a.iter()
            .filter(|&&(x, y)| !(-1..=1).any(|dy| (-1..=1).any(|dx| b.contains(&(x + dx, y + dy)))))
            .count()
    };
    alone(&a, &b) + alone(&b, &a)
}
