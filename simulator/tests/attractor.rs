//! `render attractor` and `animate attractor` from the command line: the points file
//! against an f64 model, the skip, the options each kind refuses, a diverging orbit.

mod common;

use common::{run, scratch, stderr, stdout};

fn points(path: &std::path::Path) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|line| line.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// `--points` writes the orbit in the attractor's units, from `--start` with `--skip 0`,
/// following the Hénon map's equations (an f64 model here) until chaos separates them.
#[test]
fn the_points_file_is_the_orbit() {
    let dir = scratch("henon-points");
    let (png, file) = (dir.join("henon.png"), dir.join("henon.txt"));
    let output = run(&[
        "render",
        "attractor",
        "--kind",
        "henon",
        "--params",
        "1.4,0.3",
        "--start",
        "0.5,0.25",
        "--skip",
        "0",
        "--points-count",
        "100",
        "--size",
        "64x48",
        "--stats",
        "--out",
        png.to_str().unwrap(),
        "--points",
        file.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(stdout(&output).starts_with("points=100 outside=0 kind=henon"));
    let orbit = points(&file);
    assert_eq!(orbit.len(), 100);
    assert_eq!(orbit[0], vec![0.5, 0.25]);
    let (mut x, mut y) = (0.5f64, 0.25f64);
    for point in &orbit[..12] {
        assert!(
            (point[0] - x).abs() < 1e-6 && (point[1] - y).abs() < 1e-6,
            "{point:?}"
        );
        (x, y) = (1.0 - 1.4 * x * x + y, 0.3 * x);
    }
    // --skip starts the file later in the same orbit.
    let later = dir.join("later.txt");
    let output = run(&[
        "render",
        "attractor",
        "--kind",
        "henon",
        "--start",
        "0.5,0.25",
        "--skip",
        "40",
        "--points-count",
        "60",
        "--size",
        "64x48",
        "--out",
        png.to_str().unwrap(),
        "--points",
        later.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(points(&later), orbit[40..]);
}

/// A flow writes x y z, and takes a time step and a method.
#[test]
fn a_flow_writes_three_coordinates() {
    let dir = scratch("lorenz-points");
    let (png, file) = (dir.join("lorenz.png"), dir.join("lorenz.txt"));
    let output = run(&[
        "render",
        "attractor",
        "--kind",
        "lorenz",
        "--dt",
        "0.005",
        "--method",
        "euler",
        "--skip",
        "0",
        "--points-count",
        "3",
        "--size",
        "64x48",
        "--out",
        png.to_str().unwrap(),
        "--points",
        file.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let orbit = points(&file);
    assert_eq!(orbit[0], vec![1.0, 1.0, 1.0]);
    // Euler: s + Δt·f(s) with f(1, 1, 1) = (0, 26, 1 − 8/3).
    let expected = [1.0, 1.0 + 0.005 * 26.0, 1.0 + 0.005 * (1.0 - 8.0 / 3.0)];
    for (got, want) in orbit[1].iter().zip(expected) {
        assert!((got - want).abs() < 1e-6, "{:?}", orbit[1]);
    }
}

#[test]
fn options_that_do_not_fit_the_kind_are_refused() {
    let dir = scratch("attractor-usage");
    let png = dir.join("no.png");
    for (args, expected) in [
        (vec!["--kind", "nope"], "unknown attractor"),
        (vec!["--kind", "henon", "--dt", "0.01"], "is a map"),
        (vec!["--kind", "henon", "--method", "euler"], "is a map"),
        (vec!["--kind", "lorenz", "--start", "1,2"], "X,Y,Z"),
        (vec!["--kind", "henon", "--turn", "30"], "in its"),
        (
            vec!["--kind", "lorenz", "--method", "midpoint"],
            "rk4 or euler",
        ),
    ] {
        let mut all = vec!["render", "attractor", "--out", png.to_str().unwrap()];
        all.extend(&args);
        let output = run(&all);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains(expected),
            "{args:?}: {}",
            stderr(&output)
        );
    }
    // The core's own refusals: a run error naming the cause.
    for (args, expected) in [
        (vec!["--kind", "henon", "--params", "1,2,3"], "takes 2"),
        (vec!["--kind", "henon", "--params", "20,0.3"], "±8"),
        (vec!["--kind", "lorenz", "--dt", "2"], "time step"),
    ] {
        let mut all = vec!["render", "attractor", "--out", png.to_str().unwrap()];
        all.extend(&args);
        let output = run(&all);
        assert_eq!(output.status.code(), Some(1), "{args:?}");
        assert!(
            stderr(&output).contains(expected),
            "{args:?}: {}",
            stderr(&output)
        );
    }
    assert!(!png.exists());
}

/// An orbit that leaves its fixed point's range stops with a message, and nothing is
/// written.
#[test]
fn a_diverging_orbit_is_reported_not_drawn() {
    let dir = scratch("attractor-diverges");
    let png = dir.join("henon.png");
    let output = run(&[
        "render",
        "attractor",
        "--kind",
        "henon",
        "--params",
        "2.5,0.3",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("left ±8"), "{}", stderr(&output));
    assert!(!png.exists());
}

/// An orbit that stands still is drawn (one point, exactly) with a warning saying so and
/// why it may: a flow whose time step is too small to move its state in 2⁻²⁴ (Lorenz from
/// (1, 1, 1) moves by about 2.6·10⁻⁸ a step at Δt = 10⁻⁹, below 2⁻²⁴ ≈ 6·10⁻⁸), a flow
/// at its equilibrium, a map at its fixed point; an orbit that moves, or a lone point, has
/// no warning.
#[test]
fn an_orbit_that_stands_still_is_named() {
    let dir = scratch("attractor-still");
    let png = dir.join("still.png");
    let render = |extra: &[&str]| {
        let mut args = vec!["render", "attractor", "--size", "32x24"];
        if !extra.contains(&"--points-count") {
            args.extend_from_slice(&["--points-count", "50"]);
        }
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--out", png.to_str().unwrap()]);
        let output = run(&args);
        assert!(output.status.success(), "{extra:?}: {}", stderr(&output));
        stderr(&output)
    };
    let tiny = render(&["--kind", "lorenz", "--dt", "0.000000001", "--skip", "0"]);
    assert!(
        tiny.contains("lorenz: the orbit stands still at (1, 1, 1)") && tiny.contains("--dt"),
        "{tiny}"
    );
    let by_density = render(&["--kind", "lorenz", "--dt", "0.000000001", "--density"]);
    assert!(by_density.contains("stands still"), "{by_density}");
    let equilibrium = render(&["--kind", "lorenz", "--start", "0,0,0"]);
    assert!(
        equilibrium.contains("stands still at (0, 0, 0)"),
        "{equilibrium}"
    );
    let fixed = render(&["--kind", "henon", "--params", "0,0", "--start", "1,0"]);
    assert!(
        fixed.contains("henon: the orbit stands still at (1, 0)"),
        "{fixed}"
    );
    assert!(fixed.contains("a fixed point of the map"), "{fixed}");
    let moving: [&[&str]; 3] = [
        &["--kind", "lorenz"],
        &["--kind", "henon"],
        &["--kind", "henon", "--density"],
    ];
    for moving in moving {
        let said = render(moving);
        assert!(!said.contains("stands still"), "{moving:?}: {said}");
    }
    let lone = render(&[
        "--kind",
        "henon",
        "--start",
        "1,0",
        "--params",
        "0,0",
        "--points-count",
        "1",
    ]);
    assert!(!lone.contains("stands still"), "{lone}");
}

/// `animate attractor` turns a 3D attractor a full turn over its frames; its first frame is
/// the unturned render.
#[test]
fn animate_attractor_turns_a_3d_one() {
    let dir = scratch("animate-attractor");
    let frames = dir.join("frames");
    let output = run(&[
        "animate",
        "attractor",
        "--kind",
        "rossler",
        "--points-count",
        "5000",
        "--frames",
        "4",
        "--size",
        "48x32",
        "--out",
        frames.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let frame = |k: u32| {
        image::open(frames.join(format!("frame-{k:04}.png")))
            .unwrap()
            .to_rgb8()
    };
    let still = dir.join("still.png");
    let output = run(&[
        "render",
        "attractor",
        "--kind",
        "rossler",
        "--points-count",
        "5000",
        "--size",
        "48x32",
        "--out",
        still.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(frame(0), image::open(&still).unwrap().to_rgb8());
    assert_ne!(frame(0), frame(1), "the second frame is turned");
    let refused = run(&[
        "animate",
        "attractor",
        "--kind",
        "clifford",
        "--frames",
        "2",
    ]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(stderr(&refused).contains("3D"), "{}", stderr(&refused));
}
