//! Distance estimation against an f64 model written here (d = |z|·ln|z| / |dz|, the orbit
//! run on to |z| ≥ 256 as documented), on several views: the pixels drawn as the set, the
//! distance shading, the inside kept, and the strands a one-bit panel keeps connected.

mod common;

use common::{
    escape_values as values, escape_view as view, julia_parameter as julia_of,
    sample_point as point,
};
use tinyfractal::{
    error::ViewError,
    escape::{Algorithm, Render, Shading, DISTANCE_INSIDE},
    Coord, Error, Fractal, View,
};

/// The estimated distance of the pixel at `p` in pixels (`spacing` a pixel), or `None`
/// where the orbit does not escape by `max`.
fn model_distance(julia: Option<(f64, f64)>, p: (f64, f64), max: u32, spacing: f64) -> Option<f64> {
    let (c, mut z, mut dz, mut n) = match julia {
        None => (p, p, (1.0, 0.0), 1),
        Some(k) => (k, p, (1.0, 0.0), 0),
    };
    let plus = if julia.is_none() { 1.0 } else { 0.0 };
    while z.0 * z.0 + z.1 * z.1 <= 4.0 {
        if n >= max {
            return None;
        }
        dz = (
            2.0 * (z.0 * dz.0 - z.1 * dz.1) + plus,
            2.0 * (z.0 * dz.1 + z.1 * dz.0),
        );
        z = (z.0 * z.0 - z.1 * z.1 + c.0, 2.0 * z.0 * z.1 + c.1);
        n += 1;
    }
    for _ in 0..32 {
        if z.0 * z.0 + z.1 * z.1 >= 256.0 * 256.0 {
            break;
        }
        dz = (
            2.0 * (z.0 * dz.0 - z.1 * dz.1) + plus,
            2.0 * (z.0 * dz.1 + z.1 * dz.0),
        );
        z = (z.0 * z.0 - z.1 * z.1 + c.0, 2.0 * z.0 * z.1 + c.1);
    }
    let modulus = (z.0 * z.0 + z.1 * z.1).sqrt();
    let derivative = (dz.0 * dz.0 + dz.1 * dz.1).sqrt();
    Some(modulus * modulus.ln() / derivative / spacing)
}

/// [`model_distance`] of pixel (i, j) of `view`, at its cap, in its pixels.
fn pixel_distance(view: &View, i: u32, j: u32) -> Option<f64> {
    model_distance(
        julia_of(view),
        point(view, i, j),
        view.max_iterations(),
        view.spacing().to_f64(),
    )
}

fn views() -> Vec<View> {
    vec![
        view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (160, 120), 256),
        // Seahorse valley.
        view(Fractal::Mandelbrot, (-0.745, 0.11), 0.03, (128, 96), 500),
        // The tip of the antenna.
        view(Fractal::Mandelbrot, (-1.78, 0.0), 0.1, (128, 96), 300),
        view(
            Fractal::Julia {
                re: Coord::from_f64(-0.8).unwrap(),
                im: Coord::from_f64(0.156).unwrap(),
            },
            (0.0, 0.0),
            3.2,
            (128, 96),
            300,
        ),
    ]
}

/// Fractint's default width, 0.71 of a pixel, in 256ths.
const WIDTH: u16 = 182;

#[test]
fn pixels_near_the_set_are_the_models() {
    let width = f64::from(WIDTH) / 256.0;
    for base in views() {
        for algorithm in [Algorithm::Exact, Algorithm::Fast] {
            let view = base.with_distance(WIDTH);
            let got = values(view, algorithm);
            let plain = values(base, Algorithm::Exact);
            let max = view.max_iterations();
            let (mut compared, mut same, mut marked) = (0, 0, 0);
            let size = view.size();
            for j in 0..size.height {
                for i in 0..size.width {
                    let index = (j * size.width + i) as usize;
                    let distance = pixel_distance(&view, i, j);
                    let Some(distance) = distance else {
                        // Every inside pixel stays inside.
                        if plain[index] == max as u16 {
                            assert_eq!(got[index], max as u16, "{i},{j} left the set");
                        }
                        continue;
                    };
                    if (distance / width - 1.0).abs() < 0.1 {
                        continue;
                    }
                    let near = distance < width;
                    compared += 1;
                    same += usize::from((got[index] == max as u16 + 1) == near);
                    marked += usize::from(near && plain[index] != max as u16);
                }
            }
            let share = same as f64 / compared as f64;
            assert!(share >= 0.99, "{:?} {algorithm:?}: {share}", view.centre());
            assert!(
                marked > 20,
                "{:?}: only {marked} pixels drawn as the set",
                view.centre()
            );
        }
    }
}

#[test]
fn distance_shading_follows_the_model() {
    for base in views() {
        let view = base.with_shading(Shading::Distance).unwrap();
        assert_eq!(view.inside_value(), DISTANCE_INSIDE);
        let got = values(view, Algorithm::Exact);
        let size = view.size();
        let (mut compared, mut close) = (0, 0);
        for j in 0..size.height {
            for i in 0..size.width {
                let index = (j * size.width + i) as usize;
                let distance = pixel_distance(&view, i, j);
                let want = match distance {
                    None => DISTANCE_INSIDE as f64,
                    Some(d) => (1.0 + (16.0 * (d.log2() + 4.0)).floor()).clamp(1.0, 255.0),
                };
                compared += 1;
                close += usize::from((f64::from(got[index]) - want).abs() <= 1.0);
            }
        }
        let share = close as f64 / compared as f64;
        assert!(share >= 0.99, "{:?}: {share}", view.centre());
    }
}

/// Pieces of the pixels drawn as the set (values from `inside` up), 8-connected.
fn pieces(values: &[u16], width: usize, inside: u16) -> usize {
    let height = values.len() / width;
    let mut seen = vec![false; values.len()];
    let mut count = 0;
    for start in 0..values.len() {
        if seen[start] || values[start] < inside {
            continue;
        }
        count += 1;
        let mut stack = vec![start];
        seen[start] = true;
        while let Some(at) = stack.pop() {
            let (x, y) = ((at % width) as i64, (at / width) as i64);
            for (dx, dy) in [
                (-1, -1),
                (0, -1),
                (1, -1),
                (-1, 0),
                (1, 0),
                (-1, 1),
                (0, 1),
                (1, 1),
            ] {
                let (nx, ny) = (x + dx, y + dy);
                if nx < 0 || ny < 0 || nx >= width as i64 || ny >= height as i64 {
                    continue;
                }
                let next = (ny as usize) * width + nx as usize;
                if !seen[next] && values[next] >= inside {
                    seen[next] = true;
                    stack.push(next);
                }
            }
        }
    }
    count
}

/// On a 128×64 one-bit panel the seahorse valley's strands break into specks; drawn with
/// the estimate they hold together.
#[test]
fn strands_stay_connected_on_a_one_bit_panel() {
    let base = view(
        Fractal::Mandelbrot,
        (-0.7435, 0.1314),
        0.01,
        (128, 64),
        1000,
    );
    let inside = base.max_iterations() as u16;
    let plain = pieces(&values(base, Algorithm::Exact), 128, inside);
    let estimated = pieces(
        &values(base.with_distance(WIDTH), Algorithm::Fast),
        128,
        inside,
    );
    assert!(plain >= 10, "the plain picture has {plain} pieces");
    assert!(
        estimated * 5 <= plain,
        "{estimated} pieces with the estimate, {plain} without"
    );
}

#[test]
fn perturbation_refuses_the_estimate() {
    let base = &views()[0];
    let mut storage = vec![tinyfractal::escape::ReferencePoint::default(); 300];
    let perturbed = Render::perturbed(base.with_distance(WIDTH), Algorithm::Fast, &mut storage);
    assert!(matches!(
        perturbed,
        Err(Error::View(ViewError::NotWithPerturbation))
    ));
}
