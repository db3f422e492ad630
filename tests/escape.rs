//! The escape-time engine against an f64 model written here from the definitions, plus its
//! own promises: tiers, exact mirroring, safe cardioid test, typed errors, runs, steps.

mod common;

use common::{Bitmap, Counting};
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use tinyfractal::error::{FitError, ViewError};
use tinyfractal::{
    escape::{Algorithm, Render, Tier},
    math::Generator,
    render::{DwellBuffer, DwellSink, TwoColor},
    Coord, Error, EscapeTime, Fractal, View,
};

/// Dwells in the crate's slice-backed sink, with a count of writes per pixel beside it.
struct Dwells {
    width: u32,
    values: Vec<u16>,
    writes: Vec<u32>,
    /// Whether it reads only the first half of each run (a target that stops early).
    stops_halfway: bool,
}

impl Dwells {
    fn new(size: Size) -> Self {
        let n = (size.width * size.height) as usize;
        Self {
            width: size.width,
            values: vec![0; n],
            writes: vec![0; n],
            stops_halfway: false,
        }
    }
}

impl DwellSink for Dwells {
    type Error = core::convert::Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Self::Error> {
        let pixels = (area.size.width * area.size.height) as usize;
        let read = if self.stops_halfway {
            pixels / 2
        } else {
            pixels
        };
        for p in area.points().take(read) {
            self.writes[(p.y as u32 * self.width + p.x as u32) as usize] += 1;
        }
        DwellBuffer::new(&mut self.values, self.width).dwells(area, dwells.take(read))
    }
}

fn render(view: View, algorithm: Algorithm) -> (Dwells, tinyfractal::escape::RenderStats) {
    let mut sink = Dwells::new(view.size());
    let stats = Render::new(view, algorithm).run(&mut sink).unwrap();
    assert!(
        sink.writes.iter().all(|&w| w == 1),
        "every pixel written exactly once"
    );
    (sink, stats)
}

/// The model: the definitions in f64.
fn model(
    fractal: Option<(f64, f64)>,
    centre: (f64, f64),
    width: f64,
    size: Size,
    max: u32,
) -> Vec<u16> {
    let (w, h) = (size.width as f64, size.height as f64);
    let d = width / w;
    let mut out = Vec::new();
    for j in 0..size.height {
        for i in 0..size.width {
            let re = centre.0 + (i as f64 + 0.5 - w / 2.0) * d;
            let im = centre.1 - (j as f64 + 0.5 - h / 2.0) * d;
            let (c, mut z) = match fractal {
                None => ((re, im), (0.0, 0.0)),
                Some(k) => (k, (re, im)),
            };
            let mut dwell = max;
            for n in 1..=max {
                z = (z.0 * z.0 - z.1 * z.1 + c.0, 2.0 * z.0 * z.1 + c.1);
                if z.0 * z.0 + z.1 * z.1 > 4.0 {
                    dwell = n;
                    break;
                }
            }
            out.push(dwell as u16);
        }
    }
    out
}

struct Case {
    name: &'static str,
    julia: Option<(f64, f64)>,
    centre: (&'static str, &'static str),
    width: &'static str,
    size: Size,
    max: u32,
    tier: Tier,
}

fn view_of(case: &Case) -> View {
    let fractal = match case.julia {
        None => Fractal::Mandelbrot,
        Some((re, im)) => Fractal::Julia {
            re: Coord::from_f64(re).unwrap(),
            im: Coord::from_f64(im).unwrap(),
        },
    };
    View::new(
        fractal,
        (
            Coord::parse(case.centre.0).unwrap(),
            Coord::parse(case.centre.1).unwrap(),
        ),
        Coord::parse(case.width).unwrap(),
        case.size,
        case.max,
    )
    .unwrap()
}

const CASES: &[Case] = &[
    Case {
        name: "full set",
        julia: None,
        centre: ("-0.75", "0"),
        width: "3.5",
        size: Size::new(320, 240),
        max: 256,
        tier: Tier::Standard,
    },
    Case {
        name: "seahorse valley",
        julia: None,
        centre: ("-0.7435", "0.1314"),
        width: "0.02",
        size: Size::new(200, 150),
        max: 512,
        tier: Tier::Deep,
    },
    Case {
        name: "julia",
        julia: Some((-0.8, 0.156)),
        centre: ("0", "0"),
        width: "3.2",
        size: Size::new(240, 180),
        max: 300,
        tier: Tier::Deep,
    },
    Case {
        name: "small display",
        julia: None,
        centre: ("-0.75", "0"),
        width: "3.5",
        size: Size::new(128, 64),
        max: 64,
        tier: Tier::Medium,
    },
    // A Julia set at the edge of the standard tier: log2(1/d) + 2 log2(max) + 8 = 28 (a
    // board's screen; one step more is tested below).
    Case {
        name: "small julia",
        julia: Some((-0.8, 0.156)),
        centre: ("0", "0"),
        width: "3.6",
        size: Size::new(128, 64),
        max: 100,
        tier: Tier::Standard,
    },
    // At the medium tier's limit (log2(1/d) + log2(max) = 7 + 5 = 12), on the boundary.
    Case {
        name: "medium's limit",
        julia: None,
        centre: ("-0.75", "0.1"),
        width: "1.0",
        size: Size::new(128, 96),
        max: 32,
        tier: Tier::Medium,
    },
    Case {
        name: "deep zoom",
        julia: None,
        centre: ("-0.743643887037151", "0.131825904205330"),
        width: "0.0000001",
        size: Size::new(160, 120),
        max: 1000,
        // z + i = 31 + 10 with a cap over 256: long orbits `Deep` may lose.
        tier: Tier::Wide,
    },
];

/// The f64 model's dwells for a case.
fn model_of(case: &Case) -> Vec<u16> {
    let centre = (
        case.centre.0.parse().unwrap(),
        case.centre.1.parse().unwrap(),
    );
    model(
        case.julia,
        centre,
        case.width.parse().unwrap(),
        case.size,
        case.max,
    )
}

/// The share of dwells that are the same in `a` and `b`.
fn same(a: &[u16], b: &[u16]) -> f64 {
    a.iter().zip(b).filter(|(x, y)| x == y).count() as f64 / b.len() as f64
}

/// The share of `view`'s dwells, rendered by `algorithm`, that equal `expected`.
fn agreement(view: View, algorithm: Algorithm, expected: &[u16]) -> f64 {
    same(&render(view, algorithm).0.values, expected)
}

#[test]
fn dwells_agree_with_the_f64_model() {
    for case in &CASES[..6] {
        let view = view_of(case);
        assert_eq!(view.tier(), case.tier, "{}: tier", case.name);
        let expected = model_of(case);
        let (exact, exact_stats) = render(view, Algorithm::Exact);
        let (fast, fast_stats) = render(view, Algorithm::Fast);
        let n = expected.len() as f64;
        let inside = |d: u16| u32::from(d) == case.max;
        let side_disagree = exact
            .values
            .iter()
            .zip(&expected)
            .filter(|(a, b)| inside(**a) != inside(**b))
            .count() as f64
            / n;
        let identical = same(&exact.values, &expected);
        let fast_vs_exact = same(&fast.values, &exact.values);
        // In these views, every pixel tracing missed is a speck: an escaping pixel inside
        // the region that does not escape, joined to the outside by a channel narrower
        // than a pixel.
        let inside_value = u16::try_from(case.max).unwrap();
        for (f, e) in fast.values.iter().zip(&exact.values) {
            assert!(
                f == e || *f == inside_value,
                "{}: fast {f}, exact {e}",
                case.name
            );
        }
        println!(
            "{:<16} {:?}: identical {:.4}, inside/outside differ {:.5}, fast = exact {:.5}, fast iterations {:.3} of exact",
            case.name, view.tier(), identical, side_disagree, fast_vs_exact,
            fast_stats.iterations as f64 / exact_stats.iterations as f64
        );
        assert!(identical >= 0.995, "{}: {identical}", case.name);
        assert!(side_disagree <= 0.001, "{}: {side_disagree}", case.name);
        // The seahorse valley, dense with filaments, has the most specks: 0.9988.
        assert!(fast_vs_exact >= 0.998, "{}: {fast_vs_exact}", case.name);
        assert_eq!(exact_stats.pixels, case.size.width * case.size.height);
    }
}

use tinyfractal_test_support::{dd, naive};

use dd::Dd;

fn model_dd(centre: (Coord, Coord), spacing: Coord, size: Size, max: u32) -> Vec<u16> {
    model_dd_of(None, centre, spacing, size, max)
}

/// The double-double model of a Mandelbrot (`julia: None`) or Julia view.
fn model_dd_of(
    julia: Option<(Coord, Coord)>,
    centre: (Coord, Coord),
    spacing: Coord,
    size: Size,
    max: u32,
) -> Vec<u16> {
    let k = julia.map(|(re, im)| {
        (
            Dd::from_q60(re.to_bits().into()),
            Dd::from_q60(im.to_bits().into()),
        )
    });
    let (re0, im0, d) = (
        Dd::from_q60(centre.0.to_bits().into()),
        Dd::from_q60(centre.1.to_bits().into()),
        Dd::from_q60(spacing.to_bits().into()),
    );
    let mut out = Vec::new();
    for j in 0..size.height as i64 {
        for i in 0..size.width as i64 {
            let c = (
                re0.add(d.scale((2 * i + 1 - size.width as i64) as f64 / 2.0)),
                im0.add(d.scale((2 * j + 1 - size.height as i64) as f64 / 2.0).neg()),
            );
            let dwell = dd::dwell(k, c, max);
            out.push(dwell as u16);
        }
    }
    out
}

#[test]
fn a_view_too_deep_for_32_bits_switches_tier_and_agrees() {
    let deep = &CASES[6];
    let view = view_of(deep);
    assert_eq!(view.tier(), Tier::Wide);
    let centre = (
        Coord::parse(deep.centre.0).unwrap(),
        Coord::parse(deep.centre.1).unwrap(),
    );
    let expected = model_dd(centre, view.spacing(), deep.size, deep.max);
    let (exact, fast) = (
        agreement(view, Algorithm::Exact, &expected),
        agreement(view, Algorithm::Fast, &expected),
    );
    let forced = agreement(view.with_tier(Tier::Standard), Algorithm::Exact, &expected);
    println!("deep zoom: exact {exact:.4}, fast {fast:.4}, forced 32-bit {forced:.4}");
    assert!(exact >= 0.995 && fast >= 0.995, "{exact} {fast}");
    assert!(
        forced < 0.995,
        "the 32-bit tier should fall short here ({forced})"
    );
}

/// One step past the small Julia view (29 bits by the rule): Q28 falls short there, so
/// the rule must pick the deep tier.
#[test]
fn julia_sets_with_long_orbits_need_the_deep_tier() {
    let case = Case {
        name: "julia, long orbits",
        julia: Some((-0.8, 0.156)),
        centre: ("0", "0"),
        width: "3.2",
        size: Size::new(64, 48),
        max: 256,
        tier: Tier::Deep,
    };
    let view = view_of(&case);
    assert_eq!(view.tier(), Tier::Deep);
    let expected = model_of(&case);
    let (deep, standard) = (
        agreement(view, Algorithm::Exact, &expected),
        agreement(view.with_tier(Tier::Standard), Algorithm::Exact, &expected),
    );
    println!("julia, long orbits: deep {deep:.4}, forced standard {standard:.4}");
    assert!(deep >= 0.995, "{deep}");
    assert!(standard < 0.995, "Q28 should fall short here ({standard})");
}

#[test]
fn exact_renders_mirror_about_the_real_axis() {
    for height in [120, 121] {
        let view = View::new(
            Fractal::Mandelbrot,
            (Coord::parse("-0.6").unwrap(), Coord::default()),
            Coord::parse("2.9").unwrap(),
            Size::new(97, height),
            200,
        )
        .unwrap();
        let (exact, _) = render(view, Algorithm::Exact);
        let w = 97usize;
        for j in 0..height as usize {
            let mirror = height as usize - 1 - j;
            assert_eq!(
                exact.values[j * w..(j + 1) * w],
                exact.values[mirror * w..(mirror + 1) * w],
                "row {j}"
            );
        }
        // Fast computes only the top half (plus the middle row) and mirrors the rest.
        let (_, fast) = render(view, Algorithm::Fast);
        assert!(fast.pixels <= 97 * height.div_ceil(2));
    }
}

#[test]
fn exact_julia_renders_turn_half_round_about_the_origin() {
    let k = Fractal::Julia {
        re: Coord::parse("-0.8").unwrap(),
        im: Coord::parse("0.156").unwrap(),
    };
    let (w, h) = (81usize, 61usize);
    let view = View::new(
        k,
        (Coord::default(), Coord::default()),
        Coord::parse("3.1").unwrap(),
        Size::new(w as u32, h as u32),
        150,
    )
    .unwrap();
    let (exact, _) = render(view, Algorithm::Exact);
    for j in 0..h {
        for i in 0..w {
            assert_eq!(
                exact.values[j * w + i],
                exact.values[(h - 1 - j) * w + (w - 1 - i)],
                "({i}, {j})"
            );
        }
    }
    let (fast, stats) = render(view, Algorithm::Fast);
    assert_eq!(fast.values, exact.values);
    assert!(stats.pixels <= (w * h.div_ceil(2)) as u32);
}

#[test]
fn bad_views_are_typed_errors_naming_the_failed_condition() {
    let c = (Coord::parse("-0.75").unwrap(), Coord::default());
    let w = Coord::parse("3.5").unwrap();
    let size = Size::new(32, 24);
    let m = Fractal::Mandelbrot;
    let failed =
        |fractal, centre, width, size, max| match View::new(fractal, centre, width, size, max) {
            Err(Error::View(e)) => (e, e.to_string()),
            other => panic!("expected a view error, got {other:?}"),
        };
    for width in ["0", "-1"] {
        let width = Coord::parse(width).unwrap();
        let (error, message) = failed(m, c, width, size, 100);
        assert_eq!(error, ViewError::WidthNotPositive { width });
        assert!(
            message.contains("width") && message.contains("not positive"),
            "{message}"
        );
    }
    assert_eq!(
        View::new(m, c, w, Size::new(0, 5), 100),
        Err(Error::Fit(FitError::ZeroSizeTarget))
    );
    for value in [0, 1_000_000] {
        assert_eq!(
            View::new(m, c, w, size, value),
            Err(Error::View(ViewError::IterationsOutOfRange {
                value,
                max: 65_535
            }))
        );
    }
    // Centre -0.75, width 7.9: the left edge's pixel centres reach -0.75 - 3.95 + 7.9/64.
    let (error, message) = failed(m, c, Coord::parse("7.9").unwrap(), size, 100);
    let ViewError::BeyondLimit { reach, limit } = error else {
        panic!("{error:?}")
    };
    let expected_reach = 0.75 + 3.95 - 7.9 / 64.0;
    assert!((reach.to_f64() - expected_reach).abs() < 1e-12, "{reach}");
    assert_eq!(limit, Coord::parse("3.5").unwrap());
    assert!(
        message.contains("4.57656") && message.contains("±3.5"),
        "{message}"
    );
    // A centre at 7 on 1 pixel reaches 7: still the reach, not a wrap.
    let (error, _) = failed(
        m,
        (Coord::parse("7").unwrap(), Coord::default()),
        w,
        Size::new(1, 1),
        10,
    );
    assert_eq!(
        error,
        ViewError::BeyondLimit {
            reach: Coord::parse("7").unwrap(),
            limit
        }
    );

    // 2^-60 wide on 320 pixels: the spacing rounds to 0, below the finest 2^-54.
    let (error, message) = failed(m, c, Coord::from_bits(1), Size::new(320, 240), 100);
    assert_eq!(
        error,
        ViewError::ZoomTooDeep {
            spacing: Coord::from_bits(0),
            finest: Coord::from_bits(64)
        }
    );
    assert!(
        message.contains("5.55112e-17") && message.contains("deepest tier"),
        "{message}"
    );
    // 10^-14 on 320 pixels: a spacing of 36·2^-60 = 3.1225e-17 (Q60 bits, rounded).
    let (error, message) = failed(
        m,
        c,
        Coord::parse("0.00000000000001").unwrap(),
        Size::new(320, 240),
        100,
    );
    assert!(matches!(error, ViewError::ZoomTooDeep { .. }), "{error:?}");
    assert!(message.contains("3.1225e-17"), "{message}");

    let far = Fractal::Julia {
        re: Coord::parse("1.5").unwrap(),
        im: Coord::parse("1.5").unwrap(),
    };
    let (error, message) = failed(far, c, w, size, 100);
    assert_eq!(
        error,
        ViewError::JuliaParameterTooFar {
            re: Coord::parse("1.5").unwrap(),
            im: Coord::parse("1.5").unwrap()
        }
    );
    assert!(
        message.contains("(1.5, 1.5)") && message.contains("more than 2"),
        "{message}"
    );
    assert_eq!(Coord::parse("8"), None);
    assert_eq!(Coord::parse("1e-3"), Coord::parse("0.001"));
    assert_eq!(Coord::from_f64(f64::NAN), None);
}

/// A forced tier whose unit is larger than the pixel spacing cannot tell pixels apart; the
/// view says so (the CLI warns), and names the tier the rule would choose.
#[test]
fn a_forced_tier_too_coarse_for_the_pixels_is_reported() {
    let view = |width: &str| {
        View::new(
            Fractal::Mandelbrot,
            // c = i, a Misiurewicz point: detail at every scale.
            (Coord::default(), Coord::parse("1").unwrap()),
            Coord::parse(width).unwrap(),
            Size::new(64, 48),
            1000,
        )
        .unwrap()
    };
    // Units: narrow 2^-12, medium 2^-24, standard 2^-28; spacings width/64.
    let cases = [
        ("3.5", Tier::Narrow, true),
        ("0.0001", Tier::Narrow, false),
        ("0.0001", Tier::Medium, true),
        ("0.000000005", Tier::Medium, false),
        ("0.000000005", Tier::Standard, false),
        ("0.000001", Tier::Standard, true),
        ("0.000000005", Tier::Deep, true),
    ];
    for (width, tier, resolves) in cases {
        let automatic = view(width);
        assert!(
            automatic.resolves_pixels(),
            "{width}: the automatic tier resolves"
        );
        let forced = automatic.with_tier(tier);
        assert_eq!(forced.resolves_pixels(), resolves, "{width} {tier:?}");
        assert_eq!(forced.automatic_tier(), automatic.tier());
        // Independent check: a tier that cannot tell pixels apart gives the picture fewer
        // distinct dwells than the automatic one (flat or in blocks).
        if !resolves {
            let distinct = |view: View| {
                let mut values = render(view, Algorithm::Exact).0.values;
                values.sort_unstable();
                values.dedup();
                values.len()
            };
            let (coarse, fine) = (distinct(forced), distinct(automatic));
            assert!(coarse * 2 < fine, "{width} {tier:?}: {coarse} vs {fine}");
        }
    }
}

#[test]
fn output_goes_in_runs_never_pixel_by_pixel() {
    let view = view_of(&CASES[0]);
    let palette = TwoColor {
        inside: BinaryColor::On,
        outside: BinaryColor::Off,
    };
    for algorithm in [Algorithm::Exact, Algorithm::Fast] {
        let mut target = Counting::new(Bitmap::new(320, 240));
        let stats = EscapeTime::new(view, palette)
            .with_algorithm(algorithm)
            .draw(&mut target)
            .unwrap();
        assert_eq!(target.draw_iter_pixels, 0);
        assert_eq!(target.run_pixels, 320 * 240, "each pixel sent once");
        assert_eq!(
            stats.draw_calls as usize,
            target.fill_solid_calls + target.fill_contiguous_calls
        );
        match algorithm {
            Algorithm::Exact => assert_eq!(stats.draw_calls, 240, "one call per row"),
            // 10 × 2 tiles of the top half, each also mirrored, each in at least one band of
            // rows; bands of one dwell leave by `fill_solid`, the rest by `fill_contiguous`,
            // and the two alternate, so no tile sends two bands of a kind in a row.
            Algorithm::Fast => {
                let calls = stats.draw_calls as usize;
                assert!((2 * 10 * 2..=2 * 10 * 2 * 8).contains(&calls), "{calls}");
                assert!(target.fill_solid_calls > 2 * 10, "bands of one dwell");
            }
        }
        println!(
            "{algorithm:?}: {} fill_solid, {} fill_contiguous",
            target.fill_solid_calls, target.fill_contiguous_calls
        );
    }
}

#[test]
fn fast_full_view_does_under_a_tenth_of_the_naive_iterations() {
    let case = &CASES[0];
    let view = view_of(case);
    let naive: u64 = model(None, (-0.75, 0.0), 3.5, case.size, case.max)
        .iter()
        .map(|&d| u64::from(d))
        .sum();
    let (_, fast) = render(view, Algorithm::Fast);
    let fraction = fast.iterations as f64 / naive as f64;
    println!(
        "fast: {} iterations = {fraction:.4} of naive {naive}; {} pixels computed",
        fast.iterations, fast.pixels
    );
    assert!(fraction < 0.10, "{fraction}");
}

#[test]
fn rendering_in_steps_gives_the_same_picture() {
    let view = view_of(&CASES[1]);
    let (whole, _) = render(view, Algorithm::Fast);
    let mut sink = Dwells::new(view.size());
    let mut render = Render::new(view, Algorithm::Fast);
    let mut steps = 0;
    let mut last = 0;
    loop {
        let progress = render.step(&mut sink, 20_000).unwrap();
        assert!(progress.done > last || progress.is_complete());
        last = progress.done;
        steps += 1;
        if progress.is_complete() {
            break;
        }
    }
    assert!(steps > 3, "a small budget takes several steps ({steps})");
    assert_eq!(sink.values, whole.values);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    /// The fast repeat test never decides a dwell differently from the exact orbit, at any
    /// pixel size: views one or two pixels wide, where subdivision has nothing to fill, so
    /// Fast and Exact differ only in their periodicity tests (and symmetry, which is exact).
    #[test]
    fn fast_repeats_agree_with_exact_orbits_at_any_pixel_size(
        width_exp in -7.0f64..0.6, re in -2.2f64..0.8, im in -1.3f64..1.3, columns in 1u32..=2,
        rows in 1u32..=24, max in 1u32..2500, julia in prop::option::of((-0.9f64..0.5, -0.9f64..0.9)),
    ) {
        let fractal = julia.map_or(Fractal::Mandelbrot, |(kr, ki)| Fractal::Julia {
            re: Coord::from_f64(kr).unwrap(),
            im: Coord::from_f64(ki).unwrap(),
        });
        let centre = (Coord::from_f64(re).unwrap(), Coord::from_f64(im).unwrap());
        let width = Coord::from_f64(10f64.powf(width_exp)).unwrap();
        if let Ok(view) = View::new(fractal, centre, width, Size::new(columns, rows), max) {
            let (exact, _) = render(view, Algorithm::Exact);
            let (fast, _) = render(view, Algorithm::Fast);
            prop_assert_eq!(fast.values, exact.values);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// A fast render (a Mandelbrot view's tiles traced, a Julia set's subdivided) misses
    /// few of the pixels that escape early, in random views from the whole picture down to
    /// 10⁻⁵ wide: at most 1 % of a 64×48 view among the pixels escaping in the first half
    /// of the iterations. What it misses are specks that a channel narrower than a pixel
    /// joins to the rest, nearly all of them dust escaping just before the cap; in a view
    /// made of such dust it can miss more of those (the saved case at −0.3808 − 0.5923i
    /// missed 62 of 3,072 before tiles were sampled for dust, every one escaping after 270
    /// or more of its 448 iterations), so their share is bounded over many views instead
    /// (`fast_renders_miss_few_pixels_over_many_views`, `fast_renders_find_most_dust`).
    #[test]
    fn fast_views_differ_from_exact_in_few_pixels(
        re in -2.0f64..0.5, im in -1.2f64..1.2, width_exp in -5.0f64..0.6, max in 20u32..700,
        julia in prop::option::of((-0.75f64..0.25, -0.5f64..0.5)),
    ) {
        let c = |v: f64| Coord::from_f64(v).unwrap();
        let fractal = julia.map_or(Fractal::Mandelbrot, |(kr, ki)| Fractal::Julia { re: c(kr), im: c(ki) });
        if let Ok(view) = View::new(fractal, (c(re), c(im)), c(10f64.powf(width_exp)), Size::new(64, 48), max) {
            let (exact, exact_stats) = render(view, Algorithm::Exact);
            let (fast, fast_stats) = render(view, Algorithm::Fast);
            let early = fast.values.iter().zip(&exact.values)
                .filter(|&(f, &e)| *f != e && u32::from(e) < max / 2).count();
            prop_assert!(early <= 64 * 48 / 100, "{early} pixels escaping early differ");
            prop_assert!(fast_stats.pixels <= exact_stats.pixels);
        }
    }
}

/// Over 500 random views drawn as the property test above draws them (a fixed seed), a
/// fast render misses at most one pixel in 50,000 of the exact render's, dust included.
#[test]
fn fast_renders_miss_few_pixels_over_many_views() {
    let mut random = Generator::new(20_261_205);
    // A uniform number in [0, 1).
    let mut uniform = move || f64::from(random.next_u32()) / 2f64.powi(32);
    let c = |v: f64| Coord::from_f64(v).unwrap();
    let (mut pixels, mut missed) = (0, 0);
    for _ in 0..500 {
        let (re, im) = (-2.0 + 2.5 * uniform(), -1.2 + 2.4 * uniform());
        let width = 10f64.powf(-5.0 + 5.6 * uniform());
        let max = 20 + (680.0 * uniform()) as u32;
        let fractal = if uniform() < 0.5 {
            Fractal::Mandelbrot
        } else {
            let (kr, ki) = (-0.75 + uniform(), -0.5 + uniform());
            Fractal::Julia {
                re: c(kr),
                im: c(ki),
            }
        };
        let size = Size::new(64, 48);
        if let Ok(view) = View::new(fractal, (c(re), c(im)), c(width), size, max) {
            let (exact, _) = render(view, Algorithm::Exact);
            let (fast, _) = render(view, Algorithm::Fast);
            pixels += exact.values.len();
            missed += fast
                .values
                .iter()
                .zip(&exact.values)
                .filter(|(f, e)| f != e)
                .count();
        }
    }
    assert!(
        pixels > 400 * 64 * 48,
        "most views are valid ({pixels} pixels)"
    );
    assert!(
        missed * 50_000 <= pixels,
        "{missed} of {pixels} pixels missed"
    );
}

/// A view of dust escaping just before the cap, near the set's edge, where outlines cannot
/// see the specks a channel narrower than a pixel cuts off: the fast render samples the
/// tiles whose outlines escape late and computes whole those where dust shows, so it
/// misses under 0.8 % of the pixels the exact render draws (tracing alone missed 1.1 %).
#[test]
fn fast_renders_find_most_dust() {
    let c = |v: &str| Coord::parse(v).unwrap();
    let view = View::new(
        Fractal::Mandelbrot,
        (c("-0.3808"), c("-0.5923")),
        c("0.00065"),
        Size::new(320, 240),
        500,
    )
    .unwrap();
    let (exact, _) = render(view, Algorithm::Exact);
    let (fast, stats) = render(view, Algorithm::Fast);
    let escaping = exact.values.iter().filter(|&&e| e < 500).count();
    let missed = fast
        .values
        .iter()
        .zip(&exact.values)
        .filter(|(f, e)| f != e)
        .count();
    assert!(escaping > 5_000, "a view of dust: {escaping} pixels escape");
    assert!(
        missed * 1000 < exact.values.len() * 8,
        "{missed} pixels missed"
    );
    assert!(
        (stats.pixels as usize) < exact.values.len() / 2,
        "{} computed",
        stats.pixels
    );
}

/// The whole Mandelbrot set, 3.5 wide about −0.75.
fn full_view(size: Size, max: u32) -> View {
    View::new(
        Fractal::Mandelbrot,
        (Coord::parse("-0.75").unwrap(), Coord::default()),
        Coord::parse("3.5").unwrap(),
        size,
        max,
    )
    .unwrap()
}

/// The full view at 32×24 and 1000 iterations: a pixel is 0.11 wide, and a tolerance of
/// 1/16 of it flipped two pixels to "inside".
#[test]
fn fast_full_view_at_a_coarse_size_equals_exact() {
    let view = full_view(Size::new(32, 24), 1000);
    assert_eq!(
        render(view, Algorithm::Fast).0.values,
        render(view, Algorithm::Exact).0.values
    );
}

proptest! {
    /// Whatever the cardioid/bulb test marks inside (a 1×1 exact render with no iterations)
    /// does not escape in 20,000 f64 iterations.
    #[test]
    fn the_cardioid_test_never_marks_an_escaping_point(re in -2.0f64..0.5, im in 0.0f64..1.2) {
        let view = View::new(Fractal::Mandelbrot, (Coord::from_f64(re).unwrap(), Coord::from_f64(im).unwrap()), Coord::parse("0.001").unwrap(), Size::new(1, 1), 50).unwrap();
        let (dwell, stats) = render(view, Algorithm::Exact);
        if stats.iterations == 0 && dwell.values[0] == 50 {
            let (mut x, mut y) = (0.0f64, 0.0f64);
            for _ in 0..20_000 {
                (x, y) = (x * x - y * y + re, 2.0 * x * y + im);
                prop_assert!(x * x + y * y <= 4.0, "{re},{im} escapes");
            }
        }
    }
}

/// Every palette kind works with the usual colour types, built from `Rgb888` keys, and a
/// fast render writes each pixel of a MockDisplay exactly once (it panics on overdraw).
#[test]
fn palettes_for_every_colour_type() {
    use embedded_graphics::{
        mock_display::MockDisplay,
        pixelcolor::{BinaryColor, Gray4, Rgb565, Rgb888},
    };
    use tinyfractal::render::{Bands, Gradient};
    let view = full_view(Size::new(64, 48), 60);
    let keys = [Rgb888::BLUE, Rgb888::WHITE, Rgb888::new(255, 160, 0)];

    let mut binary = MockDisplay::<BinaryColor>::new();
    EscapeTime::new(
        view,
        TwoColor {
            inside: BinaryColor::On,
            outside: BinaryColor::Off,
        },
    )
    .draw(&mut binary)
    .unwrap();
    // The cardioid's centre region is inside; the corners are outside.
    assert_eq!(binary.get_pixel(Point::new(40, 24)), Some(BinaryColor::On));
    assert_eq!(binary.get_pixel(Point::new(0, 0)), Some(BinaryColor::Off));

    let mut gray = MockDisplay::<Gray4>::new();
    let gradient = Gradient::<Gray4, 16>::new(&keys, Gray4::BLACK).unwrap();
    EscapeTime::new(view, &gradient).draw(&mut gray).unwrap();
    assert_eq!(gray.get_pixel(Point::new(40, 24)), Some(Gray4::BLACK));

    let mut rgb = MockDisplay::<Rgb565>::new();
    let bands = [(2, Rgb565::BLUE), (5, Rgb565::GREEN), (20, Rgb565::RED)];
    EscapeTime::new(view, Bands::new(&bands, Rgb565::BLACK).unwrap())
        .draw(&mut rgb)
        .unwrap();
    // Pixel (0, 0) samples c ≈ (-2.45, 1.28): dwell 1, the first band.
    assert_eq!(rgb.get_pixel(Point::new(0, 0)), Some(Rgb565::BLUE));

    // Cycling: an offset of k shifts dwell d to the colour of d + k.
    let cycled = gradient.with_offset(3);
    use tinyfractal::render::Palette;
    assert_eq!(cycled.color(2, 60), gradient.color(5, 60));
    for k in [0u16, 1, 7, 15, 16, 19, 400, u16::MAX] {
        let cycled = gradient.with_offset(k);
        for d in 0..59 {
            assert_eq!(
                cycled.color(d, 60),
                gradient.color(d + k % 16, 100),
                "{k} {d}"
            );
        }
        // Offsets are absolute: cycling again starts from the same table.
        assert_eq!(cycled.with_offset(3), gradient.with_offset(3));
        assert_eq!(cycled.with_offset(0), gradient);
    }
    assert_eq!(
        cycled.color(60, 60),
        Gray4::BLACK,
        "inside keeps its colour"
    );
}

#[test]
fn a_render_fits_in_a_few_kilobytes() {
    let bytes = size_of::<Render>();
    // 4 KiB of tile dwells (32×64), 768 bytes of tile coordinates, the view (with its
    // 72-byte deep centre and spacing), the kernel constants, the counters, and a
    // perturbed render's series (16 terms of 16 bytes in one scale) and finish.
    assert!(bytes <= 5600, "Render is {bytes} bytes");
    // With 32-row tiles, 2 KiB of dwells fewer.
    let small = size_of::<Render<'_, 1024>>();
    assert_eq!(bytes - small, 2048);
}

/// A naive `f32` loop, as a user writes it on an FPU (separate multiply and add), at the
/// same sample points.
fn naive_f32(julia: Option<(f64, f64)>, view: &View) -> Vec<u16> {
    let julia = julia.map(|(re, im)| (re as f32, im as f32));
    let size = view.size();
    let d = view.spacing().to_f64();
    let (cx, cy) = (view.centre().0.to_f64(), view.centre().1.to_f64());
    let mut out = Vec::new();
    for j in 0..size.height {
        for i in 0..size.width {
            let p = (
                (cx + (f64::from(i) + 0.5 - f64::from(size.width) / 2.0) * d) as f32,
                (cy - (f64::from(j) + 0.5 - f64::from(size.height) / 2.0) * d) as f32,
            );
            let dwell = naive::f32_dwell(julia, p, view.max_iterations());
            out.push(dwell as u16);
        }
    }
    out
}

/// The calibrated tier rule on the views people draw (the gallery's and the boards'):
/// the chosen tier keeps 99.9 % of dwells identical to a double-double reference and no
/// fewer than a naive `f32` loop, printed side by side (`docs/tiers.md` has 414 views).
#[test]
fn the_chosen_tier_beats_f32_on_display_views() {
    let cases = [
        (
            "full view",
            None,
            ("-0.75", "0"),
            "3.5",
            (320, 240),
            256,
            Tier::Standard,
        ),
        (
            "julia",
            Some((-0.8, 0.156)),
            ("0", "0"),
            "3.2",
            (320, 240),
            100,
            Tier::Medium,
        ),
        (
            "board julia",
            Some((-0.8, 0.156)),
            ("0", "0"),
            "3.6",
            (128, 64),
            100,
            Tier::Standard,
        ),
        (
            "board full view",
            None,
            ("-0.75", "0"),
            "3.5",
            (128, 64),
            64,
            Tier::Medium,
        ),
        (
            "ILI9488 full view",
            None,
            ("-0.75", "0"),
            "3.5",
            (480, 320),
            256,
            Tier::Standard,
        ),
        (
            "800x480 julia",
            Some((-0.8, 0.156)),
            ("0", "0"),
            "3.2",
            (800, 480),
            100,
            Tier::Standard,
        ),
        (
            "julia, long orbits",
            Some((-0.8, 0.156)),
            ("0", "0"),
            "3.2",
            (320, 240),
            300,
            Tier::Deep,
        ),
    ];
    for (name, julia, centre, width, (w, h), max, tier) in cases {
        let case = Case {
            name,
            julia,
            centre,
            width,
            size: Size::new(w, h),
            max,
            tier,
        };
        let view = view_of(&case);
        assert_eq!(view.tier(), tier, "{name}");
        let k = julia.map(|(re, im)| (Coord::from_f64(re).unwrap(), Coord::from_f64(im).unwrap()));
        let reference = model_dd_of(k, view.centre(), view.spacing(), view.size(), max);
        let ours = agreement(view, Algorithm::Exact, &reference);
        let fast = agreement(view, Algorithm::Fast, &reference);
        let f32_share = same(&naive_f32(julia, &view), &reference);
        println!(
            "{name:<20} {tier:?}: ours {:.3} % (fast {:.3} %), f32 {:.3} %",
            100.0 * ours,
            100.0 * fast,
            100.0 * f32_share
        );
        assert!(ours >= 0.999, "{name}: {ours}");
        assert!(ours >= f32_share, "{name}: ours {ours} < f32 {f32_share}");
        // The fast render, whose instructions the boards count, too.
        assert!(fast >= f32_share, "{name}: fast {fast} < f32 {f32_share}");
    }
}

/// The coarse-to-fine preview: after its block rows every pixel holds its block's middle
/// dwell (one write each, one `uniform` a block); the finished picture is the direct
/// render's, pixel for pixel; and it costs at most 10 % more iterations.
#[test]
fn a_preview_shows_everything_at_once_and_ends_in_the_same_picture() {
    let cases = [
        (None, ("-0.75", "0"), "3.5", Size::new(320, 240), 256),
        (
            Some((-0.8, 0.156)),
            ("0", "0"),
            "3.2",
            Size::new(320, 240),
            100,
        ),
        (
            None,
            ("-0.7435", "0.1314"),
            "0.02",
            Size::new(203, 151),
            512,
        ),
    ];
    for (julia, centre, width, size, max) in cases {
        let case = Case {
            name: "preview",
            julia,
            centre,
            width,
            size,
            max,
            tier: Tier::Standard,
        };
        let view = view_of(&case);
        for algorithm in [Algorithm::Exact, Algorithm::Fast] {
            let (direct, direct_stats) = render(view, algorithm);
            let block = 8;
            let mut sink = Dwells::new(size);
            let mut preview = Render::new(view, algorithm).with_preview(block);
            // The preview's block rows alone: a step of one iteration does one unit.
            let rows = size.height.div_ceil(block);
            for _ in 0..rows {
                preview.step(&mut sink, 1).unwrap();
            }
            assert!(
                sink.writes.iter().all(|&w| w == 1),
                "{width}: preview covers"
            );
            // Under Exact the direct render computed that middle pixel too; Fast may have
            // filled it by subdivision instead.
            if algorithm == Algorithm::Exact {
                for (index, &dwell) in sink.values.iter().enumerate() {
                    let (x, y) = (index as u32 % size.width, index as u32 / size.width);
                    let (bx, by) = (x / block * block, y / block * block);
                    let (mx, my) = (
                        bx + block.min(size.width - bx) / 2,
                        by + block.min(size.height - by) / 2,
                    );
                    let middle = direct.values[(my * size.width + mx) as usize];
                    assert_eq!(dwell, middle, "({x}, {y}) shows its block's middle");
                }
            }
            let stats = preview.run(&mut sink).unwrap();
            assert!(
                sink.writes.iter().all(|&w| w == 2),
                "then every pixel once more"
            );
            assert_eq!(
                sink.values, direct.values,
                "{width} {algorithm:?}: same picture"
            );
            let extra = stats.iterations as f64 / direct_stats.iterations as f64 - 1.0;
            println!(
                "{width} {algorithm:?}: preview costs {:.1} % more iterations",
                100.0 * extra
            );
            assert!(extra <= 0.10, "{width} {algorithm:?}: {extra}");
        }
    }
}

/// A traced tile's cells not computed are filled as it is first sent: a sink that stops
/// reading early still gets the right dwells in the mirror image and the tiles below
/// (the full view, mirrored, its tiles sharing rows).
#[test]
fn a_sink_that_stops_reading_early_still_gets_right_dwells() {
    let view = full_view(Size::new(96, 160), 200);
    let (whole, _) = render(view, Algorithm::Fast);
    let mut sink = Dwells::new(view.size());
    sink.stops_halfway = true;
    Render::new(view, Algorithm::Fast).run(&mut sink).unwrap();
    let mut read = 0;
    for (at, &writes) in sink.writes.iter().enumerate() {
        if writes > 0 {
            assert_eq!(sink.values[at], whole.values[at], "pixel {at}");
            read += 1;
        }
    }
    assert!(read > 96 * 160 / 3, "{read}");
}

/// A sink that fails on its `fail_at`-th run, once.
struct FailsOnce {
    dwells: Dwells,
    calls: u32,
    fail_at: u32,
}

impl DwellSink for FailsOnce {
    type Error = ();

    fn dwells<I: Iterator<Item = u16>>(&mut self, area: &Rectangle, dwells: I) -> Result<(), ()> {
        self.calls += 1;
        if self.calls == self.fail_at {
            return Err(());
        }
        let Ok(()) =
            DwellBuffer::new(&mut self.dwells.values, self.dwells.width).dwells(area, dwells);
        Ok(())
    }
}

/// After a sink's error, stepping again finishes the same picture: the tile that failed is
/// computed again, without taking its own last row for the row it shares with the tile
/// above (with either height of tile).
#[test]
fn a_render_goes_on_after_a_sink_error() {
    // Views where taking the failed tile's own last row changes the picture.
    goes_on_after_a_sink_error::<1024>(("-0.7", "0.35"), "0.4");
    goes_on_after_a_sink_error::<2048>(("-0.745", "0.11"), "0.02");
}

fn goes_on_after_a_sink_error<const CELLS: usize>((re, im): (&str, &str), width: &str) {
    let view = View::new(
        Fractal::Mandelbrot,
        (Coord::parse(re).unwrap(), Coord::parse(im).unwrap()),
        Coord::parse(width).unwrap(),
        Size::new(64, 200),
        200,
    )
    .unwrap();
    let fresh = || Render::<'_, CELLS>::with_capacity(view, Algorithm::Fast);
    let mut counted = FailsOnce {
        dwells: Dwells::new(view.size()),
        calls: 0,
        fail_at: 0,
    };
    fresh().run(&mut counted).unwrap();
    // Every run, including those of tiles that share a row.
    assert!(counted.calls >= 8, "{}", counted.calls);
    for fail_at in 1..=counted.calls {
        let mut sink = FailsOnce {
            dwells: Dwells::new(view.size()),
            calls: 0,
            fail_at,
        };
        let mut render = fresh();
        assert!(render.run(&mut sink).is_err());
        render.run(&mut sink).unwrap();
        assert!(
            sink.dwells.values == counted.dwells.values,
            "{CELLS} cells: failing at run {fail_at}"
        );
    }
}

/// A render split into parts (`Render::parts`, `run_part`), each computed by a render of its
/// own as a thread would, writes every pixel exactly once and the whole render's dwell.
#[test]
fn parts_rendered_apart_make_the_whole_picture() {
    for case in CASES {
        let view = view_of(case);
        for algorithm in [Algorithm::Exact, Algorithm::Fast] {
            let (whole, _) = render(view, algorithm);
            let (units, grain) = Render::new(view, algorithm).parts();
            let groups = units.div_ceil(grain);
            for pieces in [2u32, 3, 7] {
                let mut merged = vec![0u16; whole.values.len()];
                let mut writes = vec![0u32; whole.values.len()];
                let mut iterations = 0;
                for piece in 0..pieces {
                    let (first, last) = (groups * piece / pieces, groups * (piece + 1) / pieces);
                    let mut sink = Dwells::new(view.size());
                    let stats = Render::new(view, algorithm)
                        .run_part(&mut sink, first * grain..last * grain)
                        .unwrap();
                    iterations += stats.iterations;
                    for (index, &count) in sink.writes.iter().enumerate() {
                        if count > 0 {
                            merged[index] = sink.values[index];
                            writes[index] += count;
                        }
                    }
                }
                assert!(
                    writes.iter().all(|&w| w == 1),
                    "{}: each pixel once",
                    case.name
                );
                assert!(
                    merged == whole.values,
                    "{} {algorithm:?} in {pieces}",
                    case.name
                );
                assert!(iterations > 0);
            }
        }
    }
}
