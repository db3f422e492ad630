//! Geometry against independent maths: an f64 model of the turtle (tests/common), segment
//! counts from the grammar, curve length, closure.

mod common;

use common::{
    corpus_file, engine_segments, koch_snowflake, shipped_file, ModelSegment, ModelSystem,
    SHIPPED_L_FILES,
};
use tinyfractal::{lsystem::Segments, Angle, Dialect, Grammar, LFile, Real};

/// Asserts the engine's segments match the model's: same count, and every end within a
/// drift bound that grows with the number of steps taken (fixed-point rounding is at most
/// 2⁻³² per step for `Angle n`; free angles interpolate sines to within 3·10⁻⁷).
fn assert_matches_model(
    label: &str,
    engine: &[ModelSegment],
    model: &[ModelSegment],
    per_step: f64,
) {
    assert_eq!(engine.len(), model.len(), "{label}: segment count");
    let scale = model
        .iter()
        .flat_map(|s| s.iter().map(|v| v.abs()))
        .fold(1.0f64, f64::max);
    for (i, (e, m)) in engine.iter().zip(model).enumerate() {
        let tolerance = per_step * scale * (i as f64 + 1.0) + 1e-9;
        for k in 0..4 {
            assert!(
                (e[k] - m[k]).abs() <= tolerance,
                "{label}: segment {i} differs: engine {e:?}, model {m:?} (tolerance {tolerance:e})"
            );
        }
    }
}

/// Every system of a file against the f64 model, at the highest order up to 6 whose
/// derived string stays small enough for the model; returns how many were checked.
fn check_file_against_the_model(text: &str) -> usize {
    let mut checked = 0;
    for entry in LFile::new(text).entries() {
        let entry = entry.unwrap();
        let grammar = entry.grammar().unwrap();
        let model = ModelSystem::from_fractint_body(entry.body());
        let mut order = 0;
        while order < 6 && model.derive(order + 1, 60_000).is_some() {
            order += 1;
        }
        let derived = model.derive(order, 60_000).unwrap();
        let uses_free_angle = derived.contains(['\\', '/']);
        let per_step = if uses_free_angle { 1e-6 } else { 1e-9 };
        assert_matches_model(
            &format!("{} at order {order}", entry.name()),
            &engine_segments(&grammar, order),
            &model.segments(&derived),
            per_step,
        );
        checked += 1;
    }
    checked
}

#[test]
fn every_shipped_system_matches_the_f64_model() {
    let checked: usize = SHIPPED_L_FILES
        .iter()
        .map(|path| check_file_against_the_model(&shipped_file(path)))
        .sum();
    assert_eq!(checked, 20 + 2);
}

#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn every_corpus_system_matches_the_f64_model() {
    let checked: usize = ["fractint.l", "penrose.l", "tiling.l"]
        .iter()
        .map(|file| check_file_against_the_model(&corpus_file(file)))
        .sum();
    assert_eq!(checked, 90);
}

/// Fractint drew these wrong at high orders because its 32-bit turtle overflowed.
#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn fractint_overflow_cases_are_right_at_high_orders() {
    let text = corpus_file("fractint.l");
    let file = LFile::new(&text);
    for (name, order) in [("Peano2", 7), ("SnowFlake1", 6)] {
        let grammar = file.find(name).unwrap();
        let model = ModelSystem::from_fractint_body(
            file.entries()
                .map(Result::unwrap)
                .find(|e| e.name() == name)
                .unwrap()
                .body(),
        );
        let derived = model.derive(order, 50_000_000).unwrap();
        assert_matches_model(
            &format!("{name} at order {order}"),
            &engine_segments(&grammar, order),
            &model.segments(&derived),
            1e-9,
        );
    }
}

#[test]
fn koch_snowflake_has_three_times_four_to_the_n_segments() {
    let grammar = koch_snowflake();
    for order in 0..=8 {
        let count = Segments::new(&grammar, order).unwrap().count() as u64;
        assert_eq!(count, 3 * 4u64.pow(order), "order {order}");
    }
}

#[test]
fn koch_curve_length_grows_by_four_thirds() {
    let grammar = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap();
    for order in 0..=7 {
        let segments = engine_segments(&grammar, order);
        let length: f64 = segments
            .iter()
            .map(|s| (s[2] - s[0]).hypot(s[3] - s[1]))
            .sum();
        let (first, last) = (segments[0], segments[segments.len() - 1]);
        let span = (last[2] - first[0]).hypot(last[3] - first[1]);
        let expected = (4.0f64 / 3.0).powi(order as i32);
        assert!(
            (length / span - expected).abs() < 1e-9 * expected,
            "order {order}: length/span {} vs (4/3)^n {expected}",
            length / span
        );
        assert!((span - 3f64.powi(order as i32)).abs() < 1e-6, "span {span}");
    }
}

/// Closed curves end exactly, to the last bit, where they began: mirrored headings have
/// exactly negated sines and cosines.
#[test]
fn closed_curves_close_exactly() {
    let text = shipped_file("data/classics.l");
    let file = LFile::new(&text);
    let snowflake = koch_snowflake();
    let mut cases: Vec<(String, Grammar<'_>, u32)> = vec![("snowflake".into(), snowflake, 7)];
    for (name, order) in [
        ("KochSnowflake", 5),
        ("QuadraticKochIsland", 3),
        ("KochA", 3),
        ("KochB", 3),
        ("KochC", 4),
        ("KochD", 4),
        ("KochE", 4),
        ("KochF", 4),
    ] {
        cases.push((name.into(), file.find(name).unwrap(), order));
    }
    for (name, grammar, order) in &cases {
        let all: Vec<_> = Segments::new(grammar, *order)
            .unwrap()
            .map(Result::unwrap)
            .collect();
        let (first, last) = (all[0], all[all.len() - 1]);
        assert_eq!(
            last.end, first.start,
            "{name} at order {order} does not close"
        );
        // And each segment starts where the last one ended (none of these move without drawing).
        assert!(
            all.windows(2).all(|w| w[0].end == w[1].start),
            "{name} has a gap"
        );
    }
}

#[test]
fn free_angle_plant_matches_the_model() {
    let rules = [('X', "F[+X]F[-X]+X"), ('F', "FF")];
    let grammar = rules.iter().fold(
        Grammar::new(Dialect::Abop, "X", Angle::Degrees(Real::from_int(20))).unwrap(),
        |g, &(c, body)| g.with_rule(c, body).unwrap(),
    );
    let model = ModelSystem::abop("X", &rules, None, 20.0);
    for order in 0..=6 {
        let derived = model.derive(order, 1 << 22).unwrap();
        assert_matches_model(
            &format!("plant at order {order}"),
            &engine_segments(&grammar, order),
            &model.segments(&derived),
            1e-6,
        );
    }
}

#[test]
fn abop_extra_drawing_symbols_draw() {
    let rules = [('A', "A-B--B+A++AA+B-"), ('B', "+A-BB--B-A++A+B")];
    let grammar = rules.iter().fold(
        Grammar::new(Dialect::Abop, "A", Angle::Divisions(6))
            .unwrap()
            .with_draw_symbols("AB")
            .unwrap(),
        |g, &(c, body)| g.with_rule(c, body).unwrap(),
    );
    let mut model = ModelSystem::abop("A", &rules, Some(6), 0.0);
    model.draw_symbols = vec!['A', 'B'];
    for order in 0..=4 {
        let derived = model.derive(order, 1 << 20).unwrap();
        let segments = engine_segments(&grammar, order);
        assert_eq!(
            segments.len(),
            7usize.pow(order),
            "Gosper curve: 7^n segments"
        );
        assert_matches_model("gosper", &segments, &model.segments(&derived), 1e-9);
    }
}
