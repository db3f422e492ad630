//! Distance estimation against an f64 model written here (d = |z|·ln|z| / |dz|, the orbit
//! run on to |z| ≥ 256 as documented), on several views: the pixels drawn as the set, the
//! distance shading, the inside kept, and the strands a one-bit panel keeps connected.

mod common;

use common::{
    decimal_fixed, escape_values as values, escape_view as view, julia_parameter as julia_of,
    sample_point as point,
};
use embedded_graphics::geometry::Size;
use num_bigint::BigInt;
use proptest::prelude::*;
use tinyfractal::{
    escape::{Algorithm, ReferencePoint, Render, Shading, DISTANCE_INSIDE},
    math::DeepCoord,
    render::DwellBuffer,
    Coord, Fractal, View,
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

/// The Julia set of c = −0.8 + 0.156i, whole, at `size`, 300 iterations.
fn julia_view(size: (u32, u32)) -> View {
    let c = |v: f64| Coord::from_f64(v).unwrap();
    view(
        Fractal::Julia {
            re: c(-0.8),
            im: c(0.156),
        },
        (0.0, 0.0),
        3.2,
        size,
        300,
    )
}

fn views() -> Vec<View> {
    vec![
        view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (160, 120), 256),
        // Seahorse valley.
        view(Fractal::Mandelbrot, (-0.745, 0.11), 0.03, (128, 96), 500),
        // The tip of the antenna.
        view(Fractal::Mandelbrot, (-1.78, 0.0), 0.1, (128, 96), 300),
        julia_view((128, 96)),
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

/// A block whose border escapes is filled only where its border proves the set far
/// enough that no pixel inside is drawn as it: every pixel the fast render with the
/// estimate draws outside the set is the one computed alone, on views where such blocks
/// fill (a tenth fewer pixels computed than escape at least), at several widths, for the
/// Mandelbrot set and a Julia set.
#[test]
fn escaping_blocks_fill_only_where_the_set_is_proven_far() {
    let bases = [
        view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (320, 240), 256),
        view(Fractal::Mandelbrot, (-0.5, 0.3), 5.0, (257, 131), 100),
        view(Fractal::Mandelbrot, (-1.25, 0.4), 0.5, (200, 150), 300),
        julia_view((240, 160)),
    ];
    for base in bases {
        for width in [26, WIDTH, 768] {
            let view = base.with_distance(width);
            let exact = values(view, Algorithm::Exact);
            let size = view.size();
            let mut fast = vec![0; exact.len()];
            let mut render = Render::new(view, Algorithm::Fast);
            let Ok(stats) = render.run(&mut DwellBuffer::new(&mut fast, size.width));
            // Blocks with an inside border fill as without the estimate (a few pixels
            // near the cardioid's cusp escape inside such blocks); every other pixel is
            // the one computed.
            let inside = view.max_iterations() as u16;
            let differ = (fast.iter().zip(&exact))
                .filter(|&(&f, &e)| f != inside && f != e)
                .count();
            let shown: Vec<_> = (fast.iter().zip(&exact).enumerate())
                .filter(|&(_, (&f, &e))| f != inside && f != e)
                .map(|(i, (f, e))| (i % size.width as usize, i / size.width as usize, *f, *e))
                .take(8)
                .collect();
            assert_eq!(differ, 0, "{:?} at width {width}: {shown:?}", view.centre());
            let escaping = exact.iter().filter(|&&v| v != inside).count();
            assert!(
                (stats.pixels as usize) * 10 < escaping * 9,
                "{:?} at width {width}: {} pixels computed, {escaping} escape",
                view.centre(),
                stats.pixels
            );
        }
    }
}

/// On random views of the Mandelbrot set and of a Julia set, at random widths, every
/// pixel the fast render with the estimate draws outside the set is the one computed
/// alone: the blocks filled where their borders prove the set far change no pixel.
#[test]
fn proven_far_blocks_change_no_pixel_on_random_views() {
    let config = ProptestConfig {
        cases: 64,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    let widths = prop_oneof![Just(26u16), Just(WIDTH), Just(768), 1u16..3000];
    let strategy = (
        (-2.2..0.6f64, -1.3..1.3f64),
        -5.0..1.8f64,
        (40u32..220, 30u32..160),
        any::<bool>(),
        widths,
        40u32..400,
    );
    let compared = std::sync::atomic::AtomicUsize::new(0);
    proptest::test_runner::TestRunner::new(config)
        .run(&strategy, |(centre, log_width, size, julia, width, max)| {
            let c = |v: f64| Coord::from_f64(v).unwrap();
            let (fractal, centre) = if julia {
                let fractal = Fractal::Julia {
                    re: c(-0.8),
                    im: c(0.156),
                };
                (fractal, (centre.0 + 0.75, centre.1))
            } else {
                (Fractal::Mandelbrot, centre)
            };
            let size = Size::new(size.0, size.1);
            let at = (c(centre.0), c(centre.1));
            // Views reaching past the engine's limits are refused: not this test's.
            let Ok(base) = View::new(fractal, at, c(2f64.powf(log_width)), size, max) else {
                return Ok(());
            };
            let view = base.with_distance(width);
            let exact = values(view, Algorithm::Exact);
            let fast = values(view, Algorithm::Fast);
            let inside = view.max_iterations() as u16;
            let differ = (fast.iter().zip(&exact))
                .filter(|&(&f, &e)| f != inside && f != e)
                .count();
            prop_assert_eq!(differ, 0, "{:?} {} at width {}", centre, log_width, width);
            compared.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            Ok(())
        })
        .unwrap();
    let compared = compared.into_inner();
    assert!(compared >= 50, "only {compared} views compared");
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

/// Fractional bits of the deep model.
const P: u32 = 256;

/// `value` (fixed point, `bits` fractional bits) in f64, from its top 62 bits.
fn big_to_f64(value: &BigInt, bits: u32) -> f64 {
    let shift = value.bits().saturating_sub(62);
    let top = i64::try_from(&(value >> shift)).unwrap();
    top as f64 * 2f64.powi(shift as i32 - bits as i32)
}

/// [`model_distance`] for the Mandelbrot set in P-bit fixed point (z and dz both), for
/// views far below f64's resolution: the distance in units of the spacing, or `None`.
fn deep_model_distance(c: (&BigInt, &BigInt), max: u32, spacing: f64) -> Option<f64> {
    let one = BigInt::from(1) << P;
    let square = |a: &BigInt, b: &BigInt| (a * b) >> P;
    let step = |z: &mut (BigInt, BigInt), dz: &mut (BigInt, BigInt)| {
        let (x, y) = (&z.0, &z.1);
        *dz = (
            ((square(x, &dz.0) - square(y, &dz.1)) << 1) + &one,
            (square(x, &dz.1) + square(y, &dz.0)) << 1,
        );
        *z = (square(x, x) - square(y, y) + c.0, (square(x, y) << 1) + c.1);
    };
    let modulus_squared = |z: &(BigInt, BigInt)| square(&z.0, &z.0) + square(&z.1, &z.1);
    let (mut z, mut dz) = ((c.0.clone(), c.1.clone()), (one.clone(), BigInt::from(0)));
    let four = &one * 4;
    let mut n = 1;
    while modulus_squared(&z) <= four {
        if n >= max {
            return None;
        }
        step(&mut z, &mut dz);
        n += 1;
    }
    let far = &one * 65536;
    for _ in 0..32 {
        if modulus_squared(&z) >= far {
            break;
        }
        step(&mut z, &mut dz);
    }
    let (x, y) = (big_to_f64(&z.0, P), big_to_f64(&z.1, P));
    let (dx, dy) = (big_to_f64(&dz.0, P), big_to_f64(&dz.1, P));
    let modulus = x.hypot(y);
    Some(modulus * modulus.ln() / dx.hypot(dy) / spacing)
}

/// A perturbed render's values of `view`.
fn perturbed_values(view: View) -> Vec<u16> {
    let size = view.size();
    let mut storage = vec![ReferencePoint::default(); view.max_iterations() as usize + 1];
    let mut values = vec![0; (size.width * size.height) as usize];
    let mut render = Render::perturbed(view, Algorithm::Fast, &mut storage).unwrap();
    let Ok(_) = render.run(&mut DwellBuffer::new(&mut values, size.width));
    values
}

/// The deep model's distances, in pixels, of the pixels of the Mandelbrot view `view` at
/// `centre` (decimal text), `width` across: c = centre + (2i + 1 − W)·width / 2W, and −
/// for rows, down.
fn model_distances(view: &View, centre: (&str, &str), width: &str) -> Vec<Option<f64>> {
    let size = view.size();
    let fixed = |text: &str| decimal_fixed(text, P);
    let (cx, cy, w) = (fixed(centre.0), fixed(centre.1), fixed(width));
    let (pw, ph) = (i64::from(size.width), i64::from(size.height));
    let spacing = big_to_f64(&w, P) / size.width as f64;
    let mut distances = Vec::new();
    for j in 0..ph {
        let ci = &cy - (&w * (2 * j + 1 - ph)) / (2 * pw);
        for i in 0..pw {
            let cr = &cx + (&w * (2 * i + 1 - pw)) / (2 * pw);
            distances.push(deep_model_distance(
                (&cr, &ci),
                view.max_iterations(),
                spacing,
            ));
        }
    }
    distances
}

/// Perturbed deep views estimate distances as a 256-bit model of z and dz does: at 10⁻¹²
/// in the seahorse valley, beside a minibrot at 10⁻²⁰ (whose pixels rebase, z passing far
/// closer to 0 than a fixed point holds while dz is huge) and at a Misiurewicz point at
/// 10⁻³⁰ (the series skipping most iterations, dz starting from its derivative): the
/// pixels drawn as the set, and the distance shading.
#[test]
fn perturbed_views_estimate_as_a_big_number_model() {
    let views = [
        (
            (
                "-0.743643887037158704752191506114774",
                "0.131825904205311970493132056385139",
            ),
            "1e-12",
            4000,
        ),
        (
            (
                "-0.1010963641075709111436661491590857441256830106",
                "0.9562865109493675115147318935859242764076436625",
            ),
            "1e-20",
            3000,
        ),
        (
            (
                "-0.1010963638456221610257854457386225654638",
                "0.9562865108091415007710960577299774358098",
            ),
            "1e-30",
            1000,
        ),
    ];
    let width = f64::from(WIDTH) / 256.0;
    let (mut marked, mut unmarked) = (0, 0);
    for (centre, span, max) in views {
        let parse = |text: &str| DeepCoord::parse(text).unwrap();
        let base = View::deep(
            Fractal::Mandelbrot,
            (parse(centre.0), parse(centre.1)),
            parse(span),
            Size::new(40, 30),
            max,
        )
        .unwrap();
        let distances = model_distances(&base, centre, span);
        let near = perturbed_values(base.with_distance(WIDTH));
        let (mut compared, mut same) = (0, 0);
        for (&value, distance) in near.iter().zip(&distances) {
            let Some(distance) = *distance else {
                assert_eq!(value, max as u16, "{span}: an inside pixel left the set");
                continue;
            };
            if (distance / width - 1.0).abs() < 0.1 {
                continue;
            }
            compared += 1;
            let drawn = value == max as u16 + 1;
            same += usize::from(drawn == (distance < width));
            marked += usize::from(drawn);
            unmarked += usize::from(!drawn);
        }
        eprintln!("{span}: {same} of {compared} alike");
        assert!(same * 100 >= compared * 99, "{span}: {same} of {compared}");

        let shaded = perturbed_values(base.with_shading(Shading::Distance).unwrap());
        let want: Vec<f64> = distances
            .iter()
            .map(|distance| match distance {
                None => DISTANCE_INSIDE as f64,
                Some(d) => (1.0 + (16.0 * (d.log2() + 4.0)).floor()).clamp(1.0, 255.0),
            })
            .collect();
        let close = shaded
            .iter()
            .zip(&want)
            .filter(|(&got, &want)| (f64::from(got) - want).abs() <= 1.0)
            .count();
        assert!(
            close * 100 >= shaded.len() * 99,
            "{span}: {close} of {} shaded alike",
            shaded.len()
        );
        let mut levels: Vec<u16> = want.iter().map(|&w| w as u16).collect();
        levels.sort_unstable();
        levels.dedup();
        assert!(levels.len() >= 10, "{span}: only {} levels", levels.len());
    }
    assert!(
        marked >= 20 && unmarked >= 20,
        "{marked} pixels drawn as the set, {unmarked} not: both kinds must be there"
    );
}

/// With distance shading a pixel that escapes at step 256 under a higher cap is not the
/// set (whose value, `DISTANCE_INSIDE`, is 256 too).
#[test]
fn an_escape_at_the_inside_values_count_is_not_the_set() {
    let base = view(Fractal::Mandelbrot, (-0.745, 0.11), 0.03, (128, 96), 1000);
    let shaded = values(
        base.with_shading(Shading::Distance).unwrap(),
        Algorithm::Exact,
    );
    let dwells = values(base, Algorithm::Exact);
    let at_256: Vec<usize> = (0..dwells.len()).filter(|&i| dwells[i] == 256).collect();
    assert!(
        !at_256.is_empty(),
        "no pixel escapes at 256: the test tests nothing"
    );
    for i in at_256 {
        assert_ne!(shaded[i], DISTANCE_INSIDE, "pixel {i} escapes at 256");
    }
}
