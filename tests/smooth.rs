//! Smooth shading (the normalised iteration count in sixteenths) against an f64 model that
//! runs every orbit far past the escape, where the formula is continuous; and its promises:
//! no bands, the same picture however it is scheduled, a typed limit.

mod common;

use common::{
    escape_values as values, escape_view as view, julia_parameter as julia_of,
    sample_point as point,
};
use tinyfractal::{
    error::ViewError,
    escape::{Algorithm, Shading},
    Coord, Error, Fractal, View,
};

/// ν = N + 2 − log₂(log₂|z_N|²), with N the first step past |z|² = 10¹² (f64): the
/// normalised count, which is the same for any N past the escape as N grows, and continuous
/// in the point. `None` inside (no escape by `max`).
fn model_nu(julia: Option<(f64, f64)>, p: (f64, f64), max: u32) -> Option<f64> {
    let (c, mut z) = match julia {
        None => (p, (0.0, 0.0)),
        Some(k) => (k, p),
    };
    let mut escaped = false;
    let mut n = 0;
    while n < max || escaped {
        if z.0 * z.0 + z.1 * z.1 > 4.0 {
            escaped = true;
        }
        if z.0 * z.0 + z.1 * z.1 > 1e12 {
            break;
        }
        z = (z.0 * z.0 - z.1 * z.1 + c.0, 2.0 * z.0 * z.1 + c.1);
        n += 1;
    }
    let m2 = z.0 * z.0 + z.1 * z.1;
    (escaped || m2 > 4.0).then(|| f64::from(n) + 2.0 - m2.log2().log2())
}

/// The views the accuracy test runs: the full Mandelbrot view, a zoom at the seahorse
/// valley, and two Julia sets.
fn views() -> Vec<View> {
    vec![
        view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (160, 120), 256),
        view(Fractal::Mandelbrot, (-0.745, 0.11), 0.02, (96, 72), 500),
        view(
            Fractal::Julia {
                re: Coord::from_f64(-0.8).unwrap(),
                im: Coord::from_f64(0.156).unwrap(),
            },
            (0.0, 0.0),
            3.2,
            (160, 120),
            100,
        ),
        view(
            Fractal::Julia {
                re: Coord::from_f64(0.285).unwrap(),
                im: Coord::from_f64(0.01).unwrap(),
            },
            (0.0, 0.0),
            3.0,
            (96, 72),
            200,
        ),
    ]
}

#[test]
fn smooth_values_follow_the_f64_normalised_count() {
    for view in views() {
        let smooth = view.with_shading(Shading::Smooth).unwrap();
        let inside = smooth.inside_value();
        let got = values(smooth, Algorithm::Exact);
        let (size, max) = (view.size(), view.max_iterations());
        let (mut compared, mut close, mut worst_close) = (0u32, 0u32, 0.0f64);
        for j in 0..size.height {
            for i in 0..size.width {
                let value = got[(j * size.width + i) as usize];
                let Some(nu) = model_nu(julia_of(&view), point(&view, i, j), max) else {
                    continue;
                };
                if value == inside || nu < 1.0 {
                    continue;
                }
                compared += 1;
                let error = (f64::from(value) / 16.0 - nu).abs();
                // Rounding to a sixteenth, the table and the two steps past the escape.
                if error <= 0.05 {
                    close += 1;
                }
                // Far from the set the orbit is short and exact: there every pixel agrees.
                if nu < 8.0 {
                    worst_close = worst_close.max(error);
                }
            }
        }
        let share = f64::from(close) / f64::from(compared);
        assert!(compared > 1000, "{view:?}: {compared} pixels compared");
        assert!(share >= 0.995, "{view:?}: {share} within 0.05 of the model");
        assert!(
            worst_close <= 0.05,
            "{view:?}: off by {worst_close} far out"
        );
    }
}

/// The largest jump, in sixteenths, of `values` less the continuous model where a row
/// crosses a band's edge far from the set (dwells at most 16), and how many edges it
/// crossed.
fn jumps_at_band_edges(view: &View, dwells: &[u16], values: &[u16]) -> (u32, f64) {
    let size = view.size();
    let error = |i: u32, j: u32| {
        let nu = model_nu(None, point(view, i, j), view.max_iterations()).unwrap_or(0.0);
        f64::from(values[(j * size.width + i) as usize]) - 16.0 * nu
    };
    let (mut edges, mut worst) = (0, 0.0f64);
    for j in 0..size.height {
        for i in 0..size.width - 1 {
            let (a, b) = (j * size.width + i, j * size.width + i + 1);
            let (a, b) = (dwells[a as usize], dwells[b as usize]);
            if a != b && a.max(b) <= 16 {
                edges += 1;
                worst = worst.max((error(i + 1, j) - error(i, j)).abs());
            }
        }
    }
    (edges, worst)
}

#[test]
fn no_bands_where_dwells_step() {
    // Where a row crosses a band's edge, dwells jump from the continuous count by a band;
    // smooth values stay with it.
    let view = view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (320, 240), 256);
    let dwells = values(view, Algorithm::Exact);
    let smooth = values(
        view.with_shading(Shading::Smooth).unwrap(),
        Algorithm::Exact,
    );
    let (edges, worst) = jumps_at_band_edges(&view, &dwells, &smooth);
    assert!(edges > 1000, "{edges} band edges");
    // Two roundings to a sixteenth and the table: under a sixteenth and a half.
    assert!(worst < 1.5, "a jump of {worst} sixteenths at a band's edge");
    let banded: Vec<u16> = dwells.iter().map(|d| d * 16).collect();
    let (_, banded_worst) = jumps_at_band_edges(&view, &dwells, &banded);
    assert!(
        banded_worst > 12.0,
        "dwells jump by {banded_worst} sixteenths"
    );
}

#[test]
fn fast_and_mirrored_renders_give_the_same_smooth_values() {
    for view in views() {
        let smooth = view.with_shading(Shading::Smooth).unwrap();
        let exact = values(smooth, Algorithm::Exact);
        let fast = values(smooth, Algorithm::Fast);
        let same = exact.iter().zip(&fast).filter(|(a, b)| a == b).count();
        let share = same as f64 / exact.len() as f64;
        assert!(share >= 0.999, "{view:?}: {share} identical");
        assert!(fast.iter().all(|&v| v > 0), "every pixel written");
    }
}

#[test]
fn inside_stays_inside_and_outside_outside() {
    for view in views() {
        let dwells = values(view, Algorithm::Exact);
        let smooth = values(
            view.with_shading(Shading::Smooth).unwrap(),
            Algorithm::Exact,
        );
        let max = view.max_iterations() as u16;
        for (&d, &s) in dwells.iter().zip(&smooth) {
            if d == max {
                assert_eq!(s, max * 16);
            } else {
                assert!(s < max * 16 && s > 0, "dwell {d}, smooth {s}");
            }
        }
    }
}

#[test]
fn the_cap_is_a_typed_limit() {
    let deep = view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (32, 24), 5000);
    assert_eq!(
        deep.with_shading(Shading::Smooth),
        Err(Error::View(ViewError::SmoothIterationsOutOfRange {
            value: 5000,
            max: View::MAX_SMOOTH_ITERATIONS,
        }))
    );
    let message = deep.with_shading(Shading::Smooth).unwrap_err().to_string();
    assert!(message.contains("use 1 to 4095"), "{message}");
    let fits = view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (32, 24), 4095);
    assert_eq!(
        fits.with_shading(Shading::Smooth).unwrap().inside_value(),
        65520
    );
    assert_eq!(fits.inside_value(), 4095);
}
