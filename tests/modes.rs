//! Fractint's `inside=` and `outside=` modes against an f64 model of Fractint's rules
//! written here: every mode, on Mandelbrot and Julia views, in the halves a mirror would
//! copy; and the combinations that are refused.

mod common;

use common::{
    escape_values as values, escape_view as view, julia_parameter as julia_of,
    sample_point as point,
};
use tinyfractal::{
    error::ViewError,
    escape::{Algorithm, Inside, Outside, Render, Shading, PERIOD_SEARCH, PERIOD_TOLERANCE},
    Coord, Error, Fractal, View,
};

/// Where an f64 orbit ends: escaped at step n at z, or at the cap at z. The engine's count:
/// a Mandelbrot orbit starts at z₁ = c (n = 1), a Julia orbit at z₀ = the pixel (n = 0).
enum End {
    Escaped(u32, (f64, f64)),
    Inside((f64, f64)),
}

fn orbit(julia: Option<(f64, f64)>, p: (f64, f64), max: u32) -> End {
    let (c, mut z, mut n) = match julia {
        None => (p, p, 1),
        Some(k) => (k, p, 0),
    };
    loop {
        if z.0 * z.0 + z.1 * z.1 > 4.0 {
            return End::Escaped(n, z);
        }
        if n >= max {
            return End::Inside(z);
        }
        z = (z.0 * z.0 - z.1 * z.1 + c.0, 2.0 * z.0 * z.1 + c.1);
        n += 1;
    }
}

/// Fractint's `outside=` rule, then its clamp: outside 1..max − 1 becomes 1.
fn model_outside(mode: Outside, n: u32, z: (f64, f64), max: u32) -> u32 {
    if n >= max {
        return max;
    }
    let n_f = f64::from(n);
    let value = match mode {
        Outside::Iter => return n.max(1),
        Outside::Real => n_f + z.0.trunc() + 7.0,
        Outside::Imag => n_f + z.1.trunc() + 7.0,
        Outside::Mult if z.1 != 0.0 => (n_f * (z.0 / z.1)).trunc(),
        Outside::Mult => n_f,
        Outside::Summ => n_f + (z.0 + z.1).trunc(),
        Outside::Atan => (z.1.atan2(z.0).abs() * 256.0 / std::f64::consts::PI).trunc(),
        _ => unreachable!(),
    };
    if value >= 1.0 && value < f64::from(max) {
        value as u32
    } else {
        1
    }
}

/// Fractint's `inside=` rule at z after `max` steps, wrapped into 1..max − 1.
fn model_inside(mode: Inside, z: (f64, f64), c: (f64, f64), max: u32) -> u32 {
    let wrap = |v: u32| if v < max { v } else { (v - 1) % (max - 1) + 1 };
    match mode {
        Inside::MaxIter => max,
        Inside::Zmag => wrap(((z.0 * z.0 + z.1 * z.1) * f64::from(max / 2)) as u32 + 1),
        Inside::Period => {
            let mut w = z;
            for k in 1..=PERIOD_SEARCH {
                if w.0 * w.0 + w.1 * w.1 > 4.0 {
                    return max;
                }
                w = (w.0 * w.0 - w.1 * w.1 + c.0, 2.0 * w.0 * w.1 + c.1);
                if (w.0 - z.0).abs() <= PERIOD_TOLERANCE && (w.1 - z.1).abs() <= PERIOD_TOLERANCE {
                    return wrap(k);
                }
            }
            max
        }
        _ => unreachable!(),
    }
}

/// The share of pixels of `view` (with its modes) where the engine's value is the model's,
/// and how many pixels the mode gave a value other than the plain dwell (so a mode that
/// did nothing cannot pass).
fn agreement(view: View, algorithm: Algorithm) -> (f64, usize) {
    let got = values(view, algorithm);
    let plain = values(view.dwells_only(), Algorithm::Exact);
    let julia = julia_of(&view);
    let size = view.size();
    let max = view.max_iterations();
    let (mut same, mut changed) = (0, 0);
    for j in 0..size.height {
        for i in 0..size.width {
            let p = point(&view, i, j);
            let want = match orbit(julia, p, max) {
                End::Escaped(n, z) => model_outside(view.outside(), n, z, max),
                End::Inside(z) => model_inside(view.inside(), z, julia.unwrap_or(p), max),
            };
            let index = (j * size.width + i) as usize;
            same += usize::from(u32::from(got[index]) == want);
            changed += usize::from(got[index] != plain[index]);
        }
    }
    (same as f64 / got.len() as f64, changed)
}

fn mandelbrot_views() -> Vec<View> {
    vec![
        // On the real axis: a mirror would copy the top half.
        view(Fractal::Mandelbrot, (-0.75, 0.0), 3.5, (160, 120), 256),
        view(Fractal::Mandelbrot, (-0.12, 0.78), 0.5, (96, 72), 300),
    ]
}

fn julia_view() -> View {
    view(
        Fractal::Julia {
            // The Douady rabbit: a large inside, period 3.
            re: Coord::from_f64(-0.123).unwrap(),
            im: Coord::from_f64(0.745).unwrap(),
        },
        (0.0, 0.0),
        3.2,
        (128, 96),
        200,
    )
}

#[test]
fn outside_modes_follow_fractints_rules() {
    for base in mandelbrot_views().into_iter().chain([julia_view()]) {
        for mode in Outside::ALL {
            let view = base.with_outside(mode).unwrap();
            let (share, changed) = agreement(view, Algorithm::Exact);
            assert!(share >= 0.99, "{mode:?} {:?}: {share}", view.centre());
            if mode != Outside::Iter {
                assert!(changed > 500, "{mode:?} changed only {changed} pixels");
            }
        }
    }
}

#[test]
fn inside_modes_follow_fractints_rules() {
    for base in mandelbrot_views().into_iter().chain([julia_view()]) {
        for mode in [Inside::Zmag, Inside::Period] {
            let view = base.with_inside(mode);
            let (share, changed) = agreement(view, Algorithm::Exact);
            assert!(share >= 0.99, "{mode:?} {:?}: {share}", view.centre());
            assert!(changed > 300, "{mode:?} changed only {changed} pixels");
        }
    }
}

/// Subdivision fills blocks of one value: the modes' values vary more than dwells, and the
/// fast picture stays within a few specks of the exact one.
#[test]
fn fast_renders_keep_the_modes() {
    let base = &mandelbrot_views()[0];
    for view in [
        base.with_outside(Outside::Imag).unwrap(),
        base.with_outside(Outside::Atan).unwrap(),
        base.with_inside(Inside::Zmag),
        base.with_inside(Inside::Period),
    ] {
        let (share, _) = agreement(view, Algorithm::Fast);
        assert!(share >= 0.98, "{view:?}: {share}");
    }
}

/// The outside modes that tell c from its conjugate are not mirrored: the bottom half of a
/// view on the real axis is its own.
#[test]
fn asymmetric_modes_are_not_mirrored() {
    let base = &mandelbrot_views()[0];
    let size = base.size();
    for mode in [Outside::Imag, Outside::Summ, Outside::Mult] {
        let got = values(base.with_outside(mode).unwrap(), Algorithm::Fast);
        let rows: Vec<&[u16]> = got.chunks(size.width as usize).collect();
        let differ = (0..size.height as usize / 2)
            .filter(|&j| rows[j] != rows[size.height as usize - 1 - j])
            .count();
        assert!(
            differ > 20,
            "{mode:?}: only {differ} rows differ from their mirror"
        );
    }
}

#[test]
fn refused_combinations_name_their_cause() {
    let base = &mandelbrot_views()[0];
    let smooth = base.with_shading(Shading::Smooth).unwrap();
    assert_eq!(
        smooth.with_outside(Outside::Real),
        Err(Error::View(ViewError::OutsideModeWithSmooth))
    );
    let real = base.with_outside(Outside::Real).unwrap();
    assert_eq!(
        real.with_shading(Shading::Smooth),
        Err(Error::View(ViewError::OutsideModeWithSmooth))
    );
    let mut storage = vec![tinyfractal::escape::ReferencePoint::default(); 300];
    let perturbed = Render::perturbed(
        base.with_inside(Inside::Zmag),
        Algorithm::Fast,
        &mut storage,
    );
    assert!(matches!(
        perturbed,
        Err(Error::View(ViewError::NotWithPerturbation))
    ));
}
