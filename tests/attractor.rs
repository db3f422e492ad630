//! The attractors against independent f64 models of their equations, their known fixed
//! points and equilibria, and published measures (Hénon's dimension, Lorenz's mean z).

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use tinyfractal::attractor::{Attractor, AttractorPicture, Kind, Method};
use tinyfractal::error::{ParameterError, WalkError};
use tinyfractal::{BoxCounter, Error, Real};

fn real(value: f64) -> Real {
    Real::from_f64(value).unwrap()
}

fn f64s(point: [Real; 3]) -> [f64; 3] {
    point.map(Real::to_f64)
}

/// The orbit as f64 triples.
fn orbit(attractor: &Attractor, skip: u64, count: u64) -> Vec<[f64; 3]> {
    attractor
        .orbit(skip, count)
        .map(|point| f64s(point.unwrap()))
        .collect()
}

fn henon_f64([x, y, _]: [f64; 3], a: f64, b: f64) -> [f64; 3] {
    [1.0 - a * x * x + y, b * x, 0.0]
}

/// The Hénon map's fixed point: x = (−(1 − b) + √((1 − b)² + 4a)) / 2a, y = b·x.
#[test]
fn henon_fixed_point_holds_still() {
    let (a, b) = (1.4f64, 0.3f64);
    let x = (-(1.0 - b) + ((1.0 - b) * (1.0 - b) + 4.0 * a).sqrt()) / (2.0 * a);
    let y = b * x;
    assert!((x - 0.631_354_48).abs() < 1e-8 && (y - 0.189_406_34).abs() < 1e-8);
    let henon = Attractor::new(Kind::Henon);
    let fixed = [real(x), real(y), Real::ZERO];
    let next = f64s(henon.step(fixed).unwrap());
    // One step moves it by its rounding only: a few units of 2⁻²⁸ (x′ has three).
    assert!((next[0] - x).abs() < 4.0 / f64::from(1 << 28), "{next:?}");
    assert!((next[1] - y).abs() < 2.0 / f64::from(1 << 28), "{next:?}");
}

/// The first points agree with an f64 orbit of the same equations until chaos (a
/// Lyapunov exponent of 0.42 a step) has grown the 2⁻²⁸ roundings: within 10⁻⁶ for the
/// first 14 steps, within 10⁻² for the first 25.
#[test]
fn henon_follows_an_f64_orbit_until_chaos_separates_them() {
    let henon = Attractor::new(Kind::Henon);
    let ours = orbit(&henon, 0, 200);
    let agreeing = |tolerance: f64| {
        let mut model = [0.0, 0.0, 0.0];
        let mut agreeing = 0;
        for point in &ours {
            if (point[0] - model[0]).abs() > tolerance || (point[1] - model[1]).abs() > tolerance {
                break;
            }
            agreeing += 1;
            model = henon_f64(model, 1.4, 0.3);
        }
        agreeing
    };
    let (close, near) = (agreeing(1e-6), agreeing(1e-2));
    assert!(
        close >= 14 && near >= 25,
        "{close} steps within 1e-6, {near} within 1e-2"
    );
    // And every point, separated or not, is on the attractor's known box.
    let long = orbit(&henon, 100, 100_000);
    for [x, y, _] in long {
        assert!(x.abs() < 1.3 && y.abs() < 0.4, "({x}, {y})");
    }
}

/// Box counting over a density picture of 10⁶ points: near 1.261 ± 0.003 (Russell, Hanson
/// and Ott 1980), within what a 1024-pixel picture resolves.
#[test]
fn henon_has_its_published_dimension() {
    let size = Size::new(1024, 1024);
    let mut bits = vec![0u32; BoxCounter::<BinaryColor>::words_needed(size, 0)];
    let mut counter = BoxCounter::new(size, 0, BinaryColor::Off, &mut bits).unwrap();
    let stats = AttractorPicture::new(Attractor::new(Kind::Henon), 1_000_000)
        .fit(Rectangle::new(Point::zero(), size), BinaryColor::On)
        .unwrap()
        .draw(&mut counter)
        .unwrap();
    assert_eq!(stats.points, 1_000_000);
    let dimension = counter.dimension().unwrap().value.to_f64();
    assert!((dimension - 1.26).abs() < 0.05, "dimension {dimension}");
}

/// The Lorenz derivative, and one RK4 step of it, in f64.
fn lorenz_rk4(s: [f64; 3], dt: f64) -> [f64; 3] {
    let f = |[x, y, z]: [f64; 3]| [10.0 * (y - x), x * (28.0 - z) - y, x * y - 8.0 / 3.0 * z];
    let add =
        |s: [f64; 3], k: [f64; 3], h: f64| [s[0] + h * k[0], s[1] + h * k[1], s[2] + h * k[2]];
    let k1 = f(s);
    let k2 = f(add(s, k1, dt / 2.0));
    let k3 = f(add(s, k2, dt / 2.0));
    let k4 = f(add(s, k3, dt));
    [0, 1, 2].map(|i| s[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

#[test]
fn lorenz_rk4_follows_an_f64_rk4() {
    let lorenz = Attractor::new(Kind::Lorenz);
    let ours = orbit(&lorenz, 0, 400);
    let mut model = [1.0, 1.0, 1.0];
    for (step, point) in ours.iter().enumerate() {
        for i in 0..3 {
            // 2⁻²⁴ roundings in each of the step's products, grown by the flow's
            // divergence over 4 time units.
            assert!(
                (point[i] - model[i]).abs() < 1e-3,
                "step {step}: {point:?} against {model:?}"
            );
        }
        model = lorenz_rk4(model, 0.01);
    }
}

#[test]
fn lorenz_equilibria_hold_still() {
    let root = 72f64.sqrt();
    for sign in [1.0, -1.0] {
        let start = [real(sign * root), real(sign * root), real(27.0)];
        let lorenz = Attractor::new(Kind::Lorenz).with_start(start).unwrap();
        // One time unit: the equilibrium is unstable (growth e^{0.094 t}), so only the
        // start's rounding moves it.
        for point in orbit(&lorenz, 0, 100) {
            assert!((point[0] - sign * root).abs() < 1e-4, "{point:?}");
            assert!((point[1] - sign * root).abs() < 1e-4, "{point:?}");
            assert!((point[2] - 27.0).abs() < 1e-4, "{point:?}");
        }
    }
    // The origin too, exactly.
    let origin = Attractor::new(Kind::Lorenz)
        .with_start([Real::ZERO; 3])
        .unwrap();
    assert!(orbit(&origin, 0, 100).iter().all(|p| *p == [0.0; 3]));
}

#[test]
fn lorenz_stays_in_its_box_with_its_known_mean_height() {
    let lorenz = Attractor::new(Kind::Lorenz);
    let points = orbit(&lorenz, 1000, 200_000);
    let mut sum_z = 0.0;
    for [x, y, z] in &points {
        assert!(
            x.abs() < 25.0 && y.abs() < 35.0 && *z > 0.0 && *z < 55.0,
            "{x} {y} {z}"
        );
        sum_z += z;
    }
    let mean = sum_z / points.len() as f64;
    // The long-run mean of z on the attractor is about 23.5 (the f64 model here: 23.55).
    assert!((mean - 23.5).abs() < 0.5, "mean z {mean}");
}

#[test]
fn euler_is_one_derivative_a_step() {
    let lorenz = Attractor::new(Kind::Lorenz)
        .with_method(Method::Euler)
        .unwrap();
    let ours = orbit(&lorenz, 0, 50);
    let mut model = [1.0f64, 1.0, 1.0];
    for point in ours {
        for i in 0..3 {
            assert!((point[i] - model[i]).abs() < 1e-4, "{point:?} {model:?}");
        }
        let [x, y, z] = model;
        let d = [10.0 * (y - x), x * (28.0 - z) - y, x * y - 8.0 / 3.0 * z];
        model = [0, 1, 2].map(|i| model[i] + 0.01 * d[i]);
    }
}

/// Each kind against its f64 model for its first steps (the sines' table is within
/// 3·10⁻⁷; the fixed points' roundings 2⁻²⁰ to 2⁻²⁸).
#[test]
fn every_kind_follows_its_f64_model() {
    type Model = fn([f64; 3], [f64; 4]) -> [f64; 3];
    let models: [(Kind, Model, usize, f64); 8] = [
        (Kind::Henon, |s, p| henon_f64(s, p[0], p[1]), 14, 1e-6),
        (
            Kind::Clifford,
            |[x, y, _], [a, b, c, d]| {
                [
                    (a * y).sin() + c * (a * x).cos(),
                    (b * x).sin() + d * (b * y).cos(),
                    0.0,
                ]
            },
            10,
            1e-4,
        ),
        (
            Kind::DeJong,
            |[x, y, _], [a, b, c, d]| {
                [
                    (a * y).sin() - (b * x).cos(),
                    (c * x).sin() - (d * y).cos(),
                    0.0,
                ]
            },
            10,
            1e-4,
        ),
        (
            Kind::Hopalong,
            |[x, y, _], [a, b, c, _]| {
                let s = if x > 0.0 {
                    1.0
                } else if x < 0.0 {
                    -1.0
                } else {
                    0.0
                };
                [y - s * (b * x - c).abs().sqrt(), a - x, 0.0]
            },
            30,
            1e-4,
        ),
        (
            Kind::Martin,
            |[x, y, _], [a, ..]| [y - x.sin(), a - x, 0.0],
            12,
            1e-4,
        ),
        (
            Kind::GumowskiMira,
            |[x, y, _], [a, b, c, _]| {
                let g = |x: f64| c * x + 2.0 * (1.0 - c) * x * x / (1.0 + x * x);
                let x_next = y + a * (1.0 - b * y * y) * y + g(x);
                [x_next, -x + g(x_next), 0.0]
            },
            10,
            1e-4,
        ),
        (
            Kind::Popcorn,
            |[x, y, _], [h, ..]| {
                [
                    x - h * (y + (3.0 * y).tan()).sin(),
                    y - h * (x + (3.0 * x).tan()).sin(),
                    0.0,
                ]
            },
            10,
            1e-4,
        ),
        (
            Kind::Pickover,
            |[x, y, z], [a, b, c, d]| {
                [
                    (a * y).sin() - z * (b * x).cos(),
                    z * (c * x).sin() - (d * y).cos(),
                    x.sin(),
                ]
            },
            10,
            1e-4,
        ),
    ];
    for (kind, model, steps, tolerance) in models {
        let attractor = Attractor::new(kind);
        let p = attractor.parameters().map(Real::to_f64);
        let mut expected = f64s(attractor.start());
        if kind.dimensions() == 2 {
            expected[2] = 0.0;
        }
        for (step, point) in orbit(&attractor, 0, steps as u64).into_iter().enumerate() {
            for i in 0..3 {
                assert!(
                    (point[i] - expected[i]).abs() < tolerance,
                    "{}: step {step}: {point:?} against {expected:?}",
                    kind.name()
                );
            }
            expected = model(expected, p);
        }
    }
}

#[test]
fn rossler_follows_an_f64_rk4() {
    let rossler = Attractor::new(Kind::Rossler);
    let (a, b, c, dt) = (0.2, 0.2, 5.7, 0.04);
    let f = |[x, y, z]: [f64; 3]| [-(y + z), x + a * y, b + z * (x - c)];
    let add =
        |s: [f64; 3], k: [f64; 3], h: f64| [s[0] + h * k[0], s[1] + h * k[1], s[2] + h * k[2]];
    let mut model = [1.0, 1.0, 1.0];
    for (step, point) in orbit(&rossler, 0, 500).into_iter().enumerate() {
        for i in 0..3 {
            assert!(
                (point[i] - model[i]).abs() < 1e-3,
                "step {step}: {point:?} {model:?}"
            );
        }
        let k1 = f(model);
        let k2 = f(add(model, k1, dt / 2.0));
        let k3 = f(add(model, k2, dt / 2.0));
        let k4 = f(add(model, k3, dt));
        model =
            [0, 1, 2].map(|i| model[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
}

#[test]
fn the_skip_starts_the_orbit_later() {
    let henon = Attractor::new(Kind::Henon);
    let all = orbit(&henon, 0, 50);
    assert_eq!(all[0], [0.0; 3], "--skip 0 starts at the start");
    assert_eq!(orbit(&henon, 10, 40), all[10..]);
}

/// The drawings' loop names the step an orbit leaves its range at, as the orbit's own
/// iterator does: from the start, and past a transient that ends before the escape.
#[test]
fn a_drawing_names_the_step_the_orbit_escapes_at() {
    let diverging = Attractor::new(Kind::Henon)
        .with_parameters(&[real(2.5), real(0.3)])
        .unwrap();
    let area = Rectangle::new(Point::zero(), Size::new(64, 32));
    let escaped_at = |skip: u64| {
        let from_iterator = diverging.orbit(skip, 1000).find_map(Result::err);
        let from_drawing = AttractorPicture::new(diverging, 1000)
            .with_skip(skip)
            .fit(area, BinaryColor::On)
            .err();
        (from_iterator, from_drawing)
    };
    for skip in [0, 2] {
        let (from_iterator, from_drawing) = escaped_at(skip);
        let Some(Error::Walk(WalkError::OrbitEscaped { step, .. })) = from_iterator else {
            panic!("the orbit escapes: {from_iterator:?}");
        };
        assert!(
            step > skip,
            "escapes in the loop, not the transient: {step}"
        );
        assert_eq!(from_drawing, from_iterator, "skip {skip}");
    }
}

#[test]
fn a_diverging_orbit_is_an_error_not_a_wrap() {
    let diverging = Attractor::new(Kind::Henon)
        .with_parameters(&[real(2.5), real(0.3)])
        .unwrap();
    let results: Vec<_> = diverging.orbit(0, 1000).collect();
    let error = results.iter().find_map(|r| r.as_ref().err()).copied();
    assert!(
        matches!(
            error,
            Some(Error::Walk(WalkError::OrbitEscaped { range: 8, .. }))
        ),
        "{error:?}"
    );
    assert!(
        results.last().unwrap().is_err(),
        "the orbit ends at its error"
    );
    let message = error.unwrap().to_string();
    assert!(message.contains("left ±8"), "{message}");
    // Drawing it reports the same error.
    let mut display = embedded_graphics::mock_display::MockDisplay::<BinaryColor>::new();
    display.set_allow_overdraw(true);
    let fitted = AttractorPicture::new(diverging, 1000)
        .with_skip(0)
        .fit(display.bounding_box(), BinaryColor::On);
    assert!(fitted.is_err());
}

#[test]
fn bad_parameters_are_typed_errors() {
    let henon = Attractor::new(Kind::Henon);
    assert_eq!(
        henon.with_parameters(&[real(1.4)]),
        Err(Error::Parameter(ParameterError::ParameterCount {
            given: 1,
            expected: 2
        }))
    );
    assert!(matches!(
        henon.with_parameters(&[real(9.0), real(0.3)]),
        Err(Error::Parameter(ParameterError::AttractorValueOutOfRange {
            max: 8,
            ..
        }))
    ));
    assert!(matches!(
        henon.with_start([real(100.0), Real::ZERO, Real::ZERO]),
        Err(Error::Parameter(
            ParameterError::AttractorValueOutOfRange { .. }
        ))
    ));
    let lorenz = Attractor::new(Kind::Lorenz);
    for dt in [0.0, -0.01, 1.5] {
        assert!(matches!(
            lorenz.with_time_step(real(dt)),
            Err(Error::Parameter(ParameterError::TimeStepOutOfRange { .. }))
        ));
    }
}

#[test]
fn every_default_draws_inside_its_fit() {
    for kind in Kind::ALL {
        let mut display = embedded_graphics::mock_display::MockDisplay::<BinaryColor>::new();
        display.set_allow_overdraw(true);
        let stats = AttractorPicture::new(Attractor::new(kind), 5_000)
            .fit(display.bounding_box(), BinaryColor::On)
            .map_err(|e| format!("{}: {e}", kind.name()))
            .unwrap()
            .draw(&mut display)
            .unwrap();
        assert_eq!(stats.points, 5_000, "{}", kind.name());
        // Fitted to its first 5,000 points: all of them inside.
        assert_eq!(stats.outside, 0, "{}", kind.name());
        assert_eq!(Kind::from_name(kind.name()), Some(kind));
    }
}
