//! Perturbation, and the automatic tier of deep views, against an independent big-number
//! model: each pixel's orbit iterated directly in 256-bit fixed point with `num-bigint`
//! (its own decimal parser, its own points), at 10⁻¹², 10⁻²⁰ (around a minibrot, whose
//! reference passes near 0 so its pixels must rebase) and 10⁻³⁰ (a spiral around a
//! Misiurewicz point); and near the cusp at 0.25, where long orbits need `Wide`.

mod common;

use embedded_graphics::geometry::Size;
use num_bigint::BigInt;
use tinyfractal::{
    error::ViewError,
    escape::{Algorithm, ReferencePoint, Render, RenderStats, Tier},
    math::DeepCoord,
    render::DwellBuffer,
    Error, Fractal, View,
};

/// Fractional bits of the model.
const P: u32 = 256;

/// Decimal text to P-bit fixed point, rounded toward −∞.
fn fixed(text: &str) -> BigInt {
    common::decimal_fixed(text, P)
}

/// Each pixel's dwell, z ← z² + c from 0 in P-bit fixed point, c = centre + (2i + 1 − W)
/// · width / 2W (and − for rows, down).
fn model(centre: (&str, &str), width: &str, size: (u32, u32), max: u32) -> Vec<u16> {
    let (cx, cy, width) = (fixed(centre.0), fixed(centre.1), fixed(width));
    let (w, h) = (i64::from(size.0), i64::from(size.1));
    let mut dwells = Vec::new();
    for j in 0..h {
        let ci = &cy - (&width * (2 * j + 1 - h)) / (2 * w);
        for i in 0..w {
            let cr = &cx + (&width * (2 * i + 1 - w)) / (2 * w);
            dwells.push(orbit_dwell(&cr, &ci, max));
        }
    }
    dwells
}

/// [`model`]'s dwells at a fixed tier's points: the view's centre and spacing in Q60,
/// each pixel (2i + 1 − W) half spacings from the centre, rounded half away from zero, as
/// the crate documents its fixed tiers' points.
fn model_at_q60(view: &View) -> Vec<u16> {
    let (w, h) = (
        i128::from(view.size().width),
        i128::from(view.size().height),
    );
    let d = i128::from(view.spacing().to_bits());
    let half_spacings = |k: i128| {
        let p = d * k;
        p.signum() * ((p.abs() + 1) >> 1)
    };
    let (cx, cy) = view.centre();
    let to_model = |q60: i128| BigInt::from(q60) << (P - 60);
    let points = (0..h).flat_map(|j| {
        (0..w).map(move |i| {
            (
                i128::from(cx.to_bits()) + half_spacings(2 * i + 1 - w),
                i128::from(cy.to_bits()) - half_spacings(2 * j + 1 - h),
            )
        })
    });
    points
        .map(|(re, im)| orbit_dwell(&to_model(re), &to_model(im), view.max_iterations()))
        .collect()
}

/// The dwell of c = cr + i·ci (P-bit fixed point): z ← z² + c from 0.
fn orbit_dwell(cr: &BigInt, ci: &BigInt, max: u32) -> u16 {
    let four = BigInt::from(4) << (2 * P);
    let (mut x, mut y) = (BigInt::from(0), BigInt::from(0));
    for n in 1..=max {
        let (x2, y2) = (&x * &x, &y * &y);
        y = ((&x * &y) >> (P - 1)) + ci;
        x = ((x2 - y2) >> P) + cr;
        if &x * &x + &y * &y > four {
            return n as u16;
        }
    }
    max as u16
}

fn deep_view(centre: (&str, &str), width: &str, size: (u32, u32), max: u32) -> View {
    let parse = |text: &str| DeepCoord::parse(text).unwrap();
    View::deep(
        Fractal::Mandelbrot,
        (parse(centre.0), parse(centre.1)),
        parse(width),
        Size::new(size.0, size.1),
        max,
    )
    .unwrap()
}

/// The view's dwells by perturbation, and the render's stats.
fn perturbed(view: View, algorithm: Algorithm) -> (Vec<u16>, RenderStats) {
    let size = view.size();
    let mut storage = vec![ReferencePoint::default(); view.max_iterations() as usize + 1];
    let mut dwells = vec![0; (size.width * size.height) as usize];
    let mut render = Render::perturbed(view, algorithm, &mut storage).unwrap();
    let Ok(stats) = render.run(&mut DwellBuffer::new(&mut dwells, size.width));
    (dwells, stats)
}

/// The view's dwells in its own fixed-point tier, every pixel computed, and the render's
/// stats.
fn in_fixed_tier(view: View) -> (Vec<u16>, RenderStats) {
    let size = view.size();
    let mut dwells = vec![0; (size.width * size.height) as usize];
    let Ok(stats) =
        Render::new(view, Algorithm::Exact).run(&mut DwellBuffer::new(&mut dwells, size.width));
    (dwells, stats)
}

/// The spiral of the boards' deep-zoom view, where both `Deep` and perturbation draw.
const SPIRAL: (&str, &str) = ("-0.743643887037151", "0.131825904205330");

/// (identical, pixels) of our dwells against the model's.
fn agreement(centre: (&str, &str), width: &str, size: (u32, u32), max: u32) -> (usize, usize) {
    let view = deep_view(centre, width, size, max);
    let (ours, _) = perturbed(view, Algorithm::Exact);
    let expected = model(centre, width, size, max);
    let same = ours.iter().zip(&expected).filter(|(a, b)| a == b).count();
    // The views are not flat: a test of one dwell everywhere could not fail.
    let mut distinct = expected.clone();
    distinct.sort_unstable();
    distinct.dedup();
    assert!(
        distinct.len() > 20,
        "{width}: only {} dwells",
        distinct.len()
    );
    (same, expected.len())
}

const SEAHORSE: (&str, &str) = (
    "-0.743643887037158704752191506114774",
    "0.131825904205311970493132056385139",
);
/// The nucleus of a period-78 minibrot (about 2.5·10⁻²¹ across), found by Newton's method
/// near the Misiurewicz point below.
const MINIBROT: (&str, &str) = (
    "-0.10109636410757091114366614915908574412568301067472",
    "0.95628651094936751151473189358592427640764366257311",
);
/// The Misiurewicz point M₄,₁ (z₄ is a repelling fixed point): spirals at every scale.
const MISIUREWICZ: (&str, &str) = (
    "-0.1010963638456221610257854457386225654638",
    "0.9562865108091415007710960577299774358098",
);

#[test]
fn dwells_match_a_big_number_model_at_three_depths() {
    let views = [
        (SEAHORSE, "1e-12", 3000),
        (MINIBROT, "1e-20", 4000),
        (MISIUREWICZ, "1e-30", 1000),
    ];
    let (mut same, mut total) = (0, 0);
    for (centre, width, max) in views {
        let (s, t) = agreement(centre, width, (48, 36), max);
        eprintln!("{width}: {s} of {t} dwells identical");
        same += s;
        total += t;
    }
    assert!(
        same * 1000 >= total * 999,
        "{same} of {total} dwells identical"
    );
}

#[test]
fn views_past_deep_take_perturbation_and_shallower_ones_a_fixed_tier() {
    assert_eq!(
        deep_view(MISIUREWICZ, "1e-30", (48, 36), 100).tier(),
        Tier::Perturbation
    );
    assert_eq!(
        deep_view(MISIUREWICZ, "1e-6", (48, 36), 100).tier(),
        Tier::Deep
    );
}

/// A deep view with a long orbit (10⁻¹² over 64 pixels at 4000 iterations, here the same
/// spacing on 32×24): the automatic tier counts the cap and takes `Wide`, which keeps
/// 99.9 % of the model's dwells where `Deep` keeps fewer (docs/tiers.md: perturbation
/// keeps 99.9 % there too, and 99.8 % at z = 43).
#[test]
fn the_automatic_tier_of_a_deep_view_with_a_long_orbit_keeps_its_dwells() {
    let (width, size, max) = ("0.5e-12", (32, 24), 4000);
    let view = deep_view(SPIRAL, width, size, max);
    assert_eq!(view.tier(), Tier::Wide);
    let expected = model_at_q60(&view);
    let identical = |dwells: &[u16]| dwells.iter().zip(&expected).filter(|(a, b)| a == b).count();
    let (wide, _) = in_fixed_tier(view);
    let same = identical(&wide);
    assert!(
        same * 1000 >= expected.len() * 999,
        "{same} of {} dwells identical",
        expected.len()
    );
    // `Deep` forced on it loses dwells: the choice matters here.
    let (deep, _) = in_fixed_tier(view.with_tier(Tier::Deep));
    let deep_same = identical(&deep);
    assert!(deep_same < same, "Deep {deep_same}, Wide {same}");
    // With a short orbit (z + i = 46 + 4) the same view stays in `Deep`, and with a cap of
    // 2000 (z + i = 46 + 11) it takes perturbation.
    assert_eq!(deep_view(SPIRAL, width, size, 16).tier(), Tier::Deep);
    assert_eq!(
        deep_view(SPIRAL, width, size, 2000).tier(),
        Tier::Perturbation
    );
}

/// Near the cusp at 0.25 (10⁻⁶ over 64 pixels at 1000 iterations, here the same spacing
/// on 32×24) orbits crawl through the cusp's gate and their rounding is magnified past 60
/// bits: `Deep` and perturbation each lose dwells (98 % on the 64×48 view,
/// docs/tiers.md). The automatic tier is `Wide`, which keeps 99.9 % of the model's.
#[test]
fn the_automatic_tier_near_the_cusp_keeps_its_dwells_where_60_bits_do_not() {
    let (centre, width, size, max) = (("0.2818", "0.0108"), "0.5e-6", (32, 24), 1000);
    let view = deep_view(centre, width, size, max);
    assert_eq!(view.tier(), Tier::Wide);
    let expected = model_at_q60(&view);
    let identical = |dwells: &[u16]| dwells.iter().zip(&expected).filter(|(a, b)| a == b).count();
    let (wide, _) = in_fixed_tier(view);
    let (deep, _) = in_fixed_tier(view.with_tier(Tier::Deep));
    let (perturbation, _) = perturbed(view, Algorithm::Exact);
    let shares = [&wide, &deep, &perturbation].map(|dwells| identical(dwells));
    eprintln!("Wide, Deep, perturbation: {shares:?} of {}", expected.len());
    assert!(
        shares[0] * 1000 >= expected.len() * 999,
        "Wide: {} of {} dwells identical",
        shares[0],
        expected.len()
    );
    assert!(
        shares[1] * 1000 < expected.len() * 999 && shares[2] * 1000 < expected.len() * 999,
        "the view must be one 60 bits do not hold: {shares:?} of {}",
        expected.len()
    );
    // With a cap of 256 the same view stays in `Deep`.
    assert_eq!(deep_view(centre, width, size, 256).tier(), Tier::Deep);
}

#[test]
fn bad_input_is_a_typed_error_naming_the_limit() {
    let parse = |text: &str| DeepCoord::parse(text).unwrap();
    let view = View::deep(
        Fractal::Mandelbrot,
        (parse(MISIUREWICZ.0), parse(MISIUREWICZ.1)),
        parse("1e-44"),
        Size::new(320, 240),
        100,
    );
    let Err(Error::View(error @ ViewError::PerturbationTooDeep { .. })) = view else {
        panic!("{view:?}");
    };
    assert!(error.to_string().contains("2^-148"), "{error}");
    let view = deep_view(MISIUREWICZ, "1e-30", (48, 36), 100);
    let mut short = [ReferencePoint::default(); 100];
    let Err(Error::View(ViewError::ReferenceTooShort {
        needed: 101,
        given: 100,
    })) = Render::perturbed(view, Algorithm::Fast, &mut short)
    else {
        panic!("a short reference was accepted");
    };
}

/// Beside the minibrot above, not on it: the reference does not pass near 0 where the
/// pixels inside and around the minibrot do, so those pixels' z = Z + δ becomes far
/// smaller than δ (the classic glitch), and they must rebase.
const BESIDE_MINIBROT: (&str, &str) = (
    "-0.10109636410757091114066614915908574412568301067472",
    "0.95628651094936751151273189358592427640764366257311",
);

#[test]
fn glitching_pixels_rebase_and_match_the_model() {
    let (centre, width, size, max) = (BESIDE_MINIBROT, "1e-20", (48, 36), 4000);
    let (dwells, stats) = perturbed(deep_view(centre, width, size, max), Algorithm::Exact);
    let expected = model(centre, width, size, max);
    let same = dwells.iter().zip(&expected).filter(|(a, b)| a == b).count();
    let inside = expected.iter().filter(|&&d| d == max as u16).count();
    eprintln!("rebases {} same {same} inside {inside}", stats.rebases);
    assert!(stats.rebases > 100, "{} rebases", stats.rebases);
    assert!(
        inside > 20,
        "the minibrot is in view: {inside} pixels inside"
    );
    assert!(
        same * 1000 >= expected.len() * 999,
        "{same} of {}",
        expected.len()
    );
}

/// The series skips the first iterations: at the deep-zoom view (10⁻⁷, where `Deep`
/// works: its dwells are `Wide`'s, the automatic tier's) every pixel's dwell stays
/// `Deep`'s, and the steps computed fall by more than half; at 10⁻³⁰ the series skips
/// most of each pixel's iterations and the dwells stay the big-number model's.
#[test]
fn the_series_skips_iterations_and_keeps_the_dwells() {
    let view = deep_view(SPIRAL, "1e-7", (64, 32), 1000);
    assert_eq!(view.tier(), Tier::Wide);
    let (wide, _) = in_fixed_tier(view);
    let view = view.with_tier(Tier::Deep);
    let (ours, stats) = perturbed(view.with_tier(Tier::Perturbation), Algorithm::Exact);
    let (deep, fixed) = in_fixed_tier(view);
    assert_eq!(deep, wide);
    assert_eq!(ours, deep);
    assert!(
        stats.skipped > 0 && 2 * stats.iterations < fixed.iterations,
        "{stats:?}"
    );

    let view = deep_view(MISIUREWICZ, "1e-30", (48, 36), 1000);
    let (ours, stats) = perturbed(view, Algorithm::Exact);
    assert!(stats.skipped > stats.iterations, "{stats:?}");
    assert_eq!(ours, model(MISIUREWICZ, "1e-30", (48, 36), 1000));
}

/// The deep-zoom view at a display's size, by perturbation (the series, then the finish
/// by high words) against `Deep`: 99.9 % of dwells identical (measured: 76,787 of 76,800;
/// the 13 others are where the series' tolerance of 2⁻⁸ of a pixel's image tips a dwell),
/// and fewer than half the iterations computed.
#[test]
fn the_deep_zoom_view_keeps_deeps_dwells_at_display_size() {
    let view = deep_view(SPIRAL, "1e-7", (320, 240), 1000);
    let (ours, stats) = perturbed(view.with_tier(Tier::Perturbation), Algorithm::Exact);
    let (deep, fixed) = in_fixed_tier(view);
    let same = ours.iter().zip(&deep).filter(|(a, b)| a == b).count();
    assert!(same * 1000 >= deep.len() * 999, "{same} of {}", deep.len());
    assert!(2 * stats.iterations < fixed.iterations, "{stats:?}");
}
