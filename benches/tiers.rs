//! Calibrates the escape-time tier rule: over a broad set of views (the full Mandelbrot
//! view and zooms, Julia sets over many k, at display sizes and iteration caps up to
//! 65,535, widths down to `Deep`'s finest spacing), the share of each tier's dwells
//! (perturbation's and `Wide`'s too) identical to an exact reference, beside a naive `f32`
//! loop's. The reference is double-double (about 106 bits), and a 256-bit model where it
//! and `Wide` (about 120) differ. `View::new` picks the cheapest tier that keeps 99.9 % and
//! is never worse than `f32`; this program re-derives that rule and writes the evidence to
//! `docs/tiers.md`. Run: `cargo bench --bench tiers` (a few minutes; no criterion).

use std::fmt::Write as _;

use embedded_graphics::prelude::*;
use tinyfractal::{
    escape::{Algorithm, ReferenceOrbit, ReferencePoint, Render, Tier},
    render::DwellBuffer,
    Coord, Fractal, View,
};

use tinyfractal_test_support::{dd, naive};

use dd::Dd;
use num_bigint::BigInt;

/// A view to calibrate on.
#[derive(Clone, Copy)]
struct Case {
    julia: Option<(f64, f64)>,
    centre: (f64, f64),
    width: f64,
    size: (u32, u32),
    max: u32,
}

impl Case {
    fn view(&self) -> View {
        let coord = |v: f64| Coord::from_f64(v).unwrap();
        let fractal = match self.julia {
            None => Fractal::Mandelbrot,
            Some((re, im)) => Fractal::Julia {
                re: coord(re),
                im: coord(im),
            },
        };
        View::new(
            fractal,
            (coord(self.centre.0), coord(self.centre.1)),
            coord(self.width),
            Size::new(self.size.0, self.size.1),
            self.max,
        )
        .unwrap()
    }

    fn name(&self) -> String {
        let what = match self.julia {
            None => "Mandelbrot".to_string(),
            Some((re, im)) => format!("Julia {re}{im:+}i"),
        };
        format!(
            "{what} at {}{:+}i, width {}, {}×{}, max-iter {}",
            self.centre.0, self.centre.1, self.width, self.size.0, self.size.1, self.max
        )
    }
}

/// The sample points of the view's pixels, exactly as the library places them (Q60).
fn points(view: &View) -> Vec<(i128, i128)> {
    let size = view.size();
    let (w, h) = (i128::from(size.width), i128::from(size.height));
    let d = i128::from(view.spacing().to_bits());
    let (cx, cy) = view.centre();
    let offset = |k: i128| {
        let p = d * k;
        // Halved, rounded half away from zero.
        if p >= 0 {
            (p + 1) >> 1
        } else {
            -((-p + 1) >> 1)
        }
    };
    let mut out = Vec::with_capacity((w * h) as usize);
    for j in 0..h {
        for i in 0..w {
            out.push((
                i128::from(cx.to_bits()) + offset(2 * i + 1 - w),
                i128::from(cy.to_bits()) - offset(2 * j + 1 - h),
            ));
        }
    }
    out
}

fn reference(case: &Case, points: &[(i128, i128)]) -> Vec<u32> {
    // The Julia parameter as the library holds it (Q60).
    let q60 = |v: f64| Dd::from_q60(i128::from(Coord::from_f64(v).unwrap().to_bits()));
    let julia = case.julia.map(|(re, im)| (q60(re), q60(im)));
    points
        .iter()
        .map(|&(re, im)| dd::dwell(julia, (Dd::from_q60(re), Dd::from_q60(im)), case.max))
        .collect()
}

/// The dwell at a point (Q60) in 256-bit fixed point, as `dd::dwell` counts it: where the
/// double-double reference (about 106 bits) and `Wide` (about 120) differ, one of them has
/// run out of bits, and this decides.
fn big_dwell(julia: Option<(i128, i128)>, p: (i128, i128), max: u32) -> u32 {
    const P: u32 = 256;
    let big = |q60: i128| BigInt::from(q60) << (P - 60);
    let (c, mut z) = match julia {
        None => ((big(p.0), big(p.1)), (BigInt::from(0), BigInt::from(0))),
        Some(k) => ((big(k.0), big(k.1)), (big(p.0), big(p.1))),
    };
    let four = BigInt::from(4) << (2 * P);
    for n in 1..=max {
        let (x2, y2) = (&z.0 * &z.0, &z.1 * &z.1);
        let y = ((&z.0 * &z.1) >> (P - 1)) + &c.1;
        z = (((x2 - y2) >> P) + &c.0, y);
        if &z.0 * &z.0 + &z.1 * &z.1 > four {
            return n;
        }
    }
    max
}

/// The naive loop a user writes on an FPU, at the same points rounded to `f32`.
fn naive_f32(case: &Case, points: &[(i128, i128)]) -> Vec<u32> {
    let scale = (1u64 << 60) as f64;
    let julia = case.julia.map(|(re, im)| (re as f32, im as f32));
    points
        .iter()
        .map(|&(re, im)| {
            let p = ((re as f64 / scale) as f32, (im as f64 / scale) as f32);
            naive::f32_dwell(julia, p, case.max)
        })
        .collect()
}

/// The tiers calibrated, cheapest first: four fixed ones, perturbation (Mandelbrot views
/// only), and `Wide`, the fixed tier with twice `Deep`'s bits.
const TIERS: [Tier; 6] = [
    Tier::Narrow,
    Tier::Medium,
    Tier::Standard,
    Tier::Deep,
    Tier::Perturbation,
    Tier::Wide,
];

fn tier_dwells(view: View, tier: Tier) -> Vec<u32> {
    let size = view.size();
    let mut values = vec![0u16; (size.width * size.height) as usize];
    let mut sink = DwellBuffer::new(&mut values, size.width);
    let view = view.with_tier(tier);
    if tier == Tier::Perturbation {
        let mut storage = vec![ReferencePoint::default(); ReferenceOrbit::points_needed(&view)];
        Render::perturbed(view, Algorithm::Exact, &mut storage)
            .unwrap()
            .run(&mut sink)
            .unwrap();
    } else {
        Render::new(view, Algorithm::Exact).run(&mut sink).unwrap();
    }
    values.into_iter().map(u32::from).collect()
}

fn share(a: &[u32], b: &[u32]) -> f64 {
    a.iter().zip(b).filter(|(x, y)| x == y).count() as f64 / b.len() as f64
}

fn cases() -> Vec<Case> {
    let mut cases = Vec::new();
    let sizes = [(128, 64), (320, 240)];
    // The larger displays: ILI9488's 480×320, and 800×480.
    let larger = [(480, 320), (800, 480)];
    for size in sizes.into_iter().chain(larger) {
        for max in [64, 100, 256, 1000] {
            cases.push(Case {
                julia: None,
                centre: (-0.75, 0.0),
                width: 3.5,
                size,
                max,
            });
        }
    }
    for (centre, widths) in [
        ((-0.7435, 0.1314), [0.2, 0.02, 0.002, 0.0002]),
        ((0.2818, 0.0108), [0.1, 0.01, 0.001, 0.0001]),
    ] {
        for width in widths {
            for max in [256, 1000] {
                cases.push(Case {
                    julia: None,
                    centre,
                    width,
                    size: (320, 240),
                    max,
                });
            }
        }
    }
    let ks = [
        (-0.8, 0.156),
        (-0.4, 0.6),
        (0.285, 0.01),
        (-0.70176, -0.3842),
        (0.355, 0.355),
        (-0.835, -0.2321),
        (-0.1, 0.651),
        (0.0, 0.8),
        (-1.476, 0.0),
        (-0.12, 0.75),
        (-0.75, 0.11),
        (0.3, 0.5),
    ];
    for k in ks {
        for size in sizes {
            for max in [50, 100, 256, 1000] {
                cases.push(Case {
                    julia: Some(k),
                    centre: (0.0, 0.0),
                    width: 3.2,
                    size,
                    max,
                });
            }
        }
        // The whole Julia set on the larger displays.
        for size in larger {
            for max in [50, 100, 256] {
                cases.push(Case {
                    julia: Some(k),
                    centre: (0.0, 0.0),
                    width: 3.2,
                    size,
                    max,
                });
            }
        }
        for width in [0.32, 0.032] {
            for max in [50, 100, 256] {
                cases.push(Case {
                    julia: Some(k),
                    centre: (0.1, 0.1),
                    width,
                    size: (320, 240),
                    max,
                });
            }
        }
    }
    // Long orbits and deep views, on a 64×48 display (a pixel at a cap of 65535 costs):
    // the full view, seahorse valley's spiral, the cardioid's edge near the cusp and the
    // Misiurewicz point M₄,₁, down to `Deep`'s finest spacing, at caps up to 65535.
    let small = (64, 48);
    for max in [4096, 16384, 65535] {
        cases.push(Case {
            julia: None,
            centre: (-0.75, 0.0),
            width: 3.5,
            size: small,
            max,
        });
    }
    for centre in [
        (-0.743643887037151, 0.131825904205330),
        (0.2818, 0.0108),
        (-0.10109636384562216, 0.9562865108091415),
    ] {
        for width in [1e-3, 1e-6, 1e-9, 1e-10, 1e-11, 1e-12, 1e-14] {
            for max in [256, 1000, 2000, 4000, 16384, 65535] {
                cases.push(Case {
                    julia: None,
                    centre,
                    width,
                    size: small,
                    max,
                });
            }
        }
    }
    // The gallery's deep zoom.
    cases.push(Case {
        julia: None,
        centre: (-0.743643887037151, 0.131825904205330),
        width: 1e-9,
        size: (320, 240),
        max: 4000,
    });
    for k in [(-0.8, 0.156), (0.285, 0.01), (-0.12, 0.75)] {
        for (centre, width) in [((0.0, 0.0), 3.2), ((0.1, 0.1), 0.0032)] {
            for max in [4096, 65535] {
                cases.push(Case {
                    julia: Some(k),
                    centre,
                    width,
                    size: small,
                    max,
                });
            }
        }
    }
    // `TIERS_ONLY=TEXT` keeps the views whose name holds TEXT (and writes no file).
    if let Ok(only) = std::env::var("TIERS_ONLY") {
        cases.retain(|case| case.name().contains(&only));
    }
    cases
}

/// One row: the view, its rule inputs, each tier's and f32's agreement (`None` for a tier
/// that does not apply: perturbation on a Julia set, or a fixed tier whose unit is coarser
/// than the pixel spacing).
struct Row {
    case: Case,
    zoom_bits: u32,
    iteration_bits: u32,
    tiers: [Option<f64>; 6],
    f32: f64,
    chosen: Tier,
    /// Pixels where the reference and `Wide` differed, decided by the 256-bit model.
    decided: usize,
}

fn measure(case: Case) -> Row {
    let view = case.view();
    let points = points(&view);
    let mut expected = reference(&case, &points);
    let applies = |tier: Tier| match tier {
        Tier::Perturbation => case.julia.is_none(),
        tier => view.with_tier(tier).resolves_pixels(),
    };
    let wide = applies(Tier::Wide).then(|| tier_dwells(view, Tier::Wide));
    let mut decided = 0;
    if let Some(wide) = &wide {
        let q60 = |v: f64| i128::from(Coord::from_f64(v).unwrap().to_bits());
        let julia = case.julia.map(|(re, im)| (q60(re), q60(im)));
        for ((reference, &wide), &point) in expected.iter_mut().zip(wide).zip(&points) {
            if *reference != wide {
                *reference = big_dwell(julia, point, case.max);
                decided += 1;
            }
        }
    }
    let tiers = TIERS.map(|tier| {
        applies(tier).then(|| match (tier, &wide) {
            (Tier::Wide, Some(wide)) => share(wide, &expected),
            _ => share(&tier_dwells(view, tier), &expected),
        })
    });
    let spacing = view.spacing().to_bits();
    Row {
        case,
        zoom_bits: 60u32.saturating_sub(63 - spacing.leading_zeros()),
        iteration_bits: 32 - case.max.saturating_sub(1).leading_zeros(),
        tiers,
        f32: share(&naive_f32(&case, &points), &expected),
        chosen: view.tier(),
        decided,
    }
}

/// A share as the tables print it: a percentage, or a dash where the tier does not apply.
fn percent(share: Option<f64>) -> String {
    share.map_or("—".to_string(), |s| format!("{:.2} %", 100.0 * s))
}

/// The rule's bar: at least 99.9 % identical to the reference and no less than `f32`.
fn acceptable(share: f64, f32_share: f64) -> bool {
    share >= 0.999 && share >= f32_share - 1e-12
}

/// A cell's pool: pixels, pixel-weighted tier shares (with the pixels they cover), the
/// `f32` share, views, and the chosen tier.
type Pool = (f64, [(f64, f64); 6], f64, usize, Tier);

/// The rule re-derived: views with the same fractal, zoom and iteration bits pooled by
/// pixels, the cheapest tier with 99.9 % and no less than `f32`, beside `View::new`'s.
fn cells(rows: &[(usize, Row)]) -> String {
    use std::collections::BTreeMap;
    let mut cells: BTreeMap<(bool, u32, u32), Pool> = BTreeMap::new();
    for (_, row) in rows {
        let pixels = f64::from(row.case.size.0 * row.case.size.1);
        let key = (row.case.julia.is_some(), row.zoom_bits, row.iteration_bits);
        let cell = cells
            .entry(key)
            .or_insert((0.0, [(0.0, 0.0); 6], 0.0, 0, row.chosen));
        cell.0 += pixels;
        for (sum, share) in cell.1.iter_mut().zip(row.tiers) {
            if let Some(share) = share {
                *sum = (sum.0 + pixels * share, sum.1 + pixels);
            }
        }
        cell.2 += pixels * row.f32;
        cell.3 += 1;
        cell.4 = row.chosen;
    }
    let mut out = String::from(
        "## The rule, re-derived\n\n\
         Views of the same fractal, zoom and iter pooled by pixels; *needs* is the cheapest \
         tier with at least 99.9 % and no less than `f32` on the pool (*none* where no tier \
         has it), *chosen* what `View::new` picks (✗ where it does not hold).\n\n\
         | fractal | zoom | iter | views | Narrow | Medium | Standard | Deep | Perturbation | Wide | f32 | needs | chosen |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let (mut differ, mut unheld) = (0, 0);
    for ((julia, zoom, iter), (pixels, sums, f32_sum, views, chosen)) in cells {
        // A tier that does not apply to every view of the pool does not apply to it.
        let shares = sums.map(|(sum, covered)| (covered == pixels).then(|| sum / pixels));
        let f32_share = f32_sum / pixels;
        let holds = |tier: Tier| {
            TIERS
                .iter()
                .position(|&t| t == tier)
                .and_then(|index| shares[index])
                .is_some_and(|share| acceptable(share, f32_share))
        };
        let needs = TIERS.into_iter().find(|&tier| holds(tier));
        // Wrong: the chosen tier does not hold (a finer tier than needed, or perturbation
        // where it costs fewer instructions than `Deep`, is not wrong).
        let wrong = !holds(chosen);
        differ += usize::from(wrong);
        unheld += usize::from(needs.is_none());
        let cells: Vec<String> = shares.into_iter().map(percent).collect();
        let _ = writeln!(
            out,
            "| {} | {zoom} | {iter} | {views} | {} | {:.2} % | {} | {chosen:?}{} |",
            if julia { "Julia" } else { "Mandelbrot" },
            cells.join(" | "),
            100.0 * f32_share,
            needs.map_or("none".to_string(), |tier| format!("{tier:?}")),
            if wrong { " ✗" } else { "" },
        );
    }
    let _ = writeln!(
        out,
        "\nThe rule picks a tier that does not hold on {differ} cells; no tier holds on \
         {unheld}."
    );
    out
}

fn main() {
    // `cargo bench` passes `--bench`; nothing else is read.
    let cases = cases();
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let rows = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let index = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(&case) = cases.get(index) else { break };
                let row = measure(case);
                eprintln!("{}/{} {}", index + 1, cases.len(), case.name());
                rows.lock().unwrap().push((index, row));
            });
        }
    });
    let mut rows = rows.into_inner().unwrap();
    rows.sort_by_key(|(index, _)| *index);

    let mut out = String::from(
        "# Escape-time tiers, calibrated\n\n\
         Generated by `cargo bench --bench tiers` (benches/tiers.rs): do not edit.\n\n\
         Each view's dwells from every tier (`Algorithm::Exact`) and from a naive `f32` loop \
         (separate multiply and add), as the share identical to a double-double reference \
         (about 106 bits) at the same sample points; where it and `Wide` (about 120 bits) \
         differ, a 256-bit model (`num-bigint`) decides. `zoom` is ⌈log₂(1/d)⌉ for the pixel \
         spacing d, `iter` ⌈log₂(max-iter)⌉. `Medium` rounds its products' high words for \
         Julia sets and truncates them for the Mandelbrot set. Perturbation (Mandelbrot \
         views only) iterates each pixel's difference from an exact reference orbit. A dash: \
         the tier does not apply (perturbation on a Julia set; a fixed tier coarser than the \
         pixel spacing). The rule (`View::new`) must pick a tier with at least 99.9 % and no \
         less than `f32` on the pool of views with its zoom and iter (below); *chosen* is what \
         it picks; ✗ marks a single view where it does not meet that. The views at 64×48 reach caps of 65,535 and widths down to \
         `Deep`'s finest spacing (2⁻⁵⁴; past it only perturbation draws, checked against a \
         256-bit model in `tests/perturbation.rs`).\n\n\
         | view | zoom | iter | Narrow | Medium | Standard | Deep | Perturbation | Wide | f32 | chosen |\n\
         |---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut failures = 0;
    for (_, row) in &rows {
        let index = TIERS.iter().position(|&t| t == row.chosen).unwrap_or(3);
        let meets = row.tiers[index].is_some_and(|share| acceptable(share, row.f32));
        if !meets {
            failures += 1;
        }
        let cells: Vec<String> = row.tiers.into_iter().map(percent).collect();
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {:.2} % | {:?}{} |",
            row.case.name(),
            row.zoom_bits,
            row.iteration_bits,
            cells.join(" | "),
            100.0 * row.f32,
            row.chosen,
            if meets { "" } else { " ✗" }
        );
    }
    let decided: usize = rows.iter().map(|(_, row)| row.decided).sum();
    let pixels: u32 = rows
        .iter()
        .map(|(_, row)| row.case.size.0 * row.case.size.1)
        .sum();
    let _ = writeln!(
        out,
        "\n{} views; on {failures} the chosen tier has under 99.9 % or less than `f32`. The \
         256-bit model decided {decided} of {pixels} pixels.\n",
        rows.len()
    );
    out.push_str(&cells(&rows));
    if std::env::var_os("TIERS_ONLY").is_none() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/tiers.md");
        std::fs::write(path, &out).unwrap();
    }
    println!("{out}");
}
