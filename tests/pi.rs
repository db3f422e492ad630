//! Boll's π across the tiers: at c = −0.75 + εi (the neck between the cardioid and the
//! period-2 bulb) the dwell times ε tends to π, and at c = 0.25 + ε (the cusp) the dwell
//! times √ε does. The expected dwells are the published ones (D. Boll, 1991, as tabulated
//! by A. Klebanoff, "π in the Mandelbrot set", Fractals 9 (2001)), not the engine's: the
//! orbits crawl through a parabolic gate for thousands of steps, where rounding that
//! a tier cannot carry shows up as a dwell off by far more than the convention's ±1.

use embedded_graphics::geometry::Size;
use tinyfractal::{
    escape::{Algorithm, ReferenceOrbit, ReferencePoint, Render, Tier},
    math::DeepCoord,
    render::DwellBuffer,
    Fractal, View,
};

/// Published counts at c = −0.75 + εi: (ε, iterations before |z| > 2). Beyond 10⁻⁴ the
/// counts (314,160 at 10⁻⁵, 31,415,928 at 10⁻⁷) pass the cap of 65,535.
const NECK: [(&str, u32); 4] = [
    ("0.1", 33),
    ("0.01", 315),
    ("0.001", 3143),
    ("0.0001", 31417),
];

/// Published counts at c = 0.25 + ε for ε = 10⁻², 10⁻⁴, 10⁻⁶, 10⁻⁸: (c, iterations).
/// Beyond 10⁻⁸ the counts (314,157 at 10⁻¹⁰, 3,141,591 at 10⁻¹²) pass the cap.
const CUSP: [(&str, u32); 4] = [
    ("0.26", 30),
    ("0.2501", 312),
    ("0.250001", 3140),
    ("0.25000001", 31414),
];

/// The dwell at exactly `c` (a one-pixel view samples its centre) in `tier`, or by the
/// automatic tier (`None`).
fn dwell(c: (&str, &str), tier: Option<Tier>) -> (u32, Tier) {
    let centre = (
        DeepCoord::parse(c.0).unwrap(),
        DeepCoord::parse(c.1).unwrap(),
    );
    // One pixel 2⁻³⁰ wide: the point is all that matters.
    let width = DeepCoord::parse("0.000000000931322574615478515625").unwrap();
    let size = Size::new(1, 1);
    let view = View::deep(
        Fractal::Mandelbrot,
        centre,
        width,
        size,
        View::MAX_ITERATIONS,
    )
    .unwrap();
    let view = tier.map_or(view, |tier| view.with_tier(tier));
    let mut value = [0u16];
    let mut sink = DwellBuffer::new(&mut value, 1);
    if view.tier() == Tier::Perturbation {
        let mut storage = vec![ReferencePoint::default(); ReferenceOrbit::points_needed(&view)];
        let Ok(_) = Render::perturbed(view, Algorithm::Exact, &mut storage)
            .unwrap()
            .run(&mut sink);
    } else {
        let Ok(_) = Render::new(view, Algorithm::Exact).run(&mut sink);
    }
    (u32::from(value[0]), view.tier())
}

/// How many of each list a tier reaches (its rounding carried through the gate): the
/// neck's and the cusp's first cases. A coarser tier past these is off by more than ±1
/// (`Standard` at 0.25 + 10⁻⁶ counts 3145 against 3140), which is what the tier rule and
/// its calibration are for.
const REACH: [(Option<Tier>, usize, usize); 7] = [
    (Some(Tier::Narrow), 2, 1),
    (Some(Tier::Medium), 3, 2),
    (Some(Tier::Standard), 4, 2),
    (Some(Tier::Deep), 4, 4),
    (Some(Tier::Wide), 4, 4),
    (Some(Tier::Perturbation), 4, 4),
    (None, 4, 4),
];

#[test]
fn dwells_at_the_neck_and_the_cusp_tend_to_pi() {
    // The published counts themselves: N·ε and N·√ε approach π.
    for (epsilon, n) in NECK {
        let product = f64::from(n) * epsilon.parse::<f64>().unwrap();
        assert!(
            (product - core::f64::consts::PI).abs() < 0.3,
            "{epsilon}: {product}"
        );
    }
    for (c, n) in CUSP {
        let epsilon = c.parse::<f64>().unwrap() - 0.25;
        let product = f64::from(n) * epsilon.sqrt();
        assert!(
            (product - core::f64::consts::PI).abs() < 0.2,
            "{c}: {product}"
        );
    }
    for (tier, neck, cusp) in REACH {
        let reached = NECK
            .iter()
            .take(neck)
            .map(|&(epsilon, n)| (("-0.75", epsilon), n))
            .chain(CUSP.iter().take(cusp).map(|&(c, n)| ((c, "0"), n)));
        for (c, published) in reached {
            let (dwell, computed_in) = dwell(c, tier);
            assert!(
                dwell.abs_diff(published) <= 1,
                "{c:?} in {computed_in:?} (asked {tier:?}): dwell {dwell}, published {published}"
            );
        }
    }
}
