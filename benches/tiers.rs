//! Calibrates the escape-time tier rule: over a broad set of views (the full Mandelbrot
//! view and zooms, Julia sets over many k, at display sizes and iteration caps), the share
//! of each tier's dwells identical to a double-double reference (about 106 bits), beside
//! a naive `f32` loop's. `View::new` picks the cheapest tier that keeps 99.9 % and is
//! never worse than `f32`; this program re-derives that rule and writes the evidence to
//! `docs/tiers.md`. Run: `cargo bench --bench tiers` (a few minutes; no criterion).

use std::fmt::Write as _;

use embedded_graphics::prelude::*;
use tinyfractal::{Algorithm, Coord, DwellBuffer, Fractal, Render, Tier, View};

#[path = "../tests/support/dd.rs"]
mod dd;
#[path = "../tests/support/naive.rs"]
mod naive;

use dd::Dd;

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

fn tier_dwells(view: View, tier: Tier) -> Vec<u32> {
    let size = view.size();
    let mut values = vec![0u16; (size.width * size.height) as usize];
    Render::new(view.with_tier(tier), Algorithm::Exact)
        .run(&mut DwellBuffer::new(&mut values, size.width))
        .unwrap();
    values.into_iter().map(u32::from).collect()
}

fn share(a: &[u32], b: &[u32]) -> f64 {
    a.iter().zip(b).filter(|(x, y)| x == y).count() as f64 / b.len() as f64
}

fn cases() -> Vec<Case> {
    let mut cases = Vec::new();
    let sizes = [(128, 64), (320, 240)];
    for size in sizes {
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
    cases
}

/// One row: the view, its rule inputs, each tier's and f32's agreement.
struct Row {
    case: Case,
    zoom_bits: u32,
    iteration_bits: u32,
    tiers: [f64; 4],
    f32: f64,
    chosen: Tier,
}

fn measure(case: Case) -> Row {
    let view = case.view();
    let points = points(&view);
    let expected = reference(&case, &points);
    let tiers = Tier::ALL.map(|tier| share(&tier_dwells(view, tier), &expected));
    let spacing = view.spacing().to_bits();
    Row {
        case,
        zoom_bits: 60u32.saturating_sub(63 - spacing.leading_zeros()),
        iteration_bits: 32 - case.max.saturating_sub(1).leading_zeros(),
        tiers,
        f32: share(&naive_f32(&case, &points), &expected),
        chosen: view.tier(),
    }
}

/// The rule's bar: at least 99.9 % identical to the reference and no less than `f32`.
fn acceptable(share: f64, f32_share: f64) -> bool {
    share >= 0.999 && share >= f32_share - 1e-12
}

/// A cell's pool: pixels, pixel-weighted tier and `f32` shares, views, the chosen tier.
type Pool = (f64, [f64; 4], f64, usize, Tier);

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
            .or_insert((0.0, [0.0; 4], 0.0, 0, row.chosen));
        cell.0 += pixels;
        for (sum, share) in cell.1.iter_mut().zip(row.tiers) {
            *sum += pixels * share;
        }
        cell.2 += pixels * row.f32;
        cell.3 += 1;
        cell.4 = row.chosen;
    }
    let mut out = String::from(
        "## The rule, re-derived\n\n\
         Views of the same fractal, zoom and iter pooled by pixels; *needs* is the cheapest \
         tier with at least 99.9 % and no less than `f32` on the pool, *chosen* what \
         `View::new` picks (✗ where they differ).\n\n\
         | fractal | zoom | iter | views | Narrow | Medium | Standard | Deep | f32 | needs | chosen |\n\
         |---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut differ = 0;
    for ((julia, zoom, iter), (pixels, sums, f32_sum, views, chosen)) in cells {
        let shares = sums.map(|s| s / pixels);
        let f32_share = f32_sum / pixels;
        let needs = Tier::ALL
            .into_iter()
            .zip(shares)
            .find(|&(_, share)| acceptable(share, f32_share))
            .map_or(Tier::Deep, |(tier, _)| tier);
        if needs != chosen {
            differ += 1;
        }
        let cells: Vec<String> = shares
            .iter()
            .map(|s| format!("{:.2} %", 100.0 * s))
            .collect();
        let _ = writeln!(
            out,
            "| {} | {zoom} | {iter} | {views} | {} | {:.2} % | {needs:?} | {chosen:?}{} |",
            if julia { "Julia" } else { "Mandelbrot" },
            cells.join(" | "),
            100.0 * f32_share,
            if needs == chosen { "" } else { " ✗" }
        );
    }
    let _ = writeln!(
        out,
        "\nThe rule and the measurements differ on {differ} cells."
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
         (about 106 bits) at the same sample points. `zoom` is ⌈log₂(1/d)⌉ for the pixel \
         spacing d, `iter` ⌈log₂(max-iter)⌉. `Medium` rounds its products' high words for \
         Julia sets and truncates them for the Mandelbrot set. The rule (`View::new`) must \
         pick a tier with at least 99.9 % and no less than `f32`; *chosen* is what it picks; \
         ✗ marks a view where it does not meet that.\n\n\
         | view | zoom | iter | Narrow | Medium | Standard | Deep | f32 | chosen |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let mut failures = 0;
    for (_, row) in &rows {
        let index = Tier::ALL.iter().position(|&t| t == row.chosen).unwrap_or(3);
        let meets = acceptable(row.tiers[index], row.f32);
        if !meets {
            failures += 1;
        }
        let cells: Vec<String> = row
            .tiers
            .iter()
            .map(|s| format!("{:.2} %", 100.0 * s))
            .collect();
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
    let _ = writeln!(
        out,
        "\n{} views; on {failures} the chosen tier has under 99.9 % or less than `f32`.\n",
        rows.len()
    );
    out.push_str(&cells(&rows));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/tiers.md");
    std::fs::write(path, &out).unwrap();
    println!("{out}");
}
