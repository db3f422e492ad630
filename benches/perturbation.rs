//! Deep zoom on the host: perturbation (its series and Q60 finish) against `Deep`
//! itself on a view both can draw (the spiral 10⁻⁷ wide, cap 1000, the boards'
//! `deep-zoom`), and perturbation alone past `Deep`'s reach (a minibrot 10⁻²⁰ and a
//! Misiurewicz spiral 10⁻³⁰), 320×240. Also prints the iterations each computes and skips.
//!
//! `cargo bench --bench perturbation`; docs/performance.md quotes these numbers.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use embedded_graphics::prelude::*;
use std::hint::black_box;
use tinyfractal::{
    escape::{Algorithm, ReferencePoint, Render, RenderStats, Tier},
    math::DeepCoord,
    render::DwellBuffer,
    Fractal, View,
};

const SPIRAL: (&str, &str) = ("-0.743643887037151", "0.131825904205330");
const MINIBROT_78: (&str, &str) = (
    "-0.10109636410757091114366614915908574412568301067472",
    "0.95628651094936751151473189358592427640764366257311",
);
const MISIUREWICZ_4_1: (&str, &str) = (
    "-0.1010963638456221610257854457386225654638",
    "0.9562865108091415007710960577299774358098",
);

fn view(centre: (&str, &str), width: &str, max: u32) -> View {
    let parse = |text: &str| DeepCoord::parse(text).unwrap();
    View::deep(
        Fractal::Mandelbrot,
        (parse(centre.0), parse(centre.1)),
        parse(width),
        Size::new(320, 240),
        max,
    )
    .unwrap()
}

/// One render of `view` into `dwells`: by perturbation (the reference in `storage`) when
/// its tier is perturbation, else in its own tier.
fn render(view: View, storage: &mut [ReferencePoint], dwells: &mut [u16]) -> RenderStats {
    let width = view.size().width;
    let mut render = if view.tier() == Tier::Perturbation {
        Render::perturbed(view, Algorithm::Fast, storage).unwrap()
    } else {
        Render::new(view, Algorithm::Fast)
    };
    let Ok(stats) = render.run(&mut DwellBuffer::new(dwells, width));
    stats
}

fn bench(c: &mut Criterion) {
    let deep_zoom = view(SPIRAL, "0.0000001", 1000);
    let cases = [
        ("spiral 1e-7 max-iter 1000", "Deep", deep_zoom),
        (
            "spiral 1e-7 max-iter 1000",
            "perturbation",
            deep_zoom.with_tier(Tier::Perturbation),
        ),
        (
            "minibrot 1e-20 max-iter 2000",
            "perturbation",
            view(MINIBROT_78, "1e-20", 2000),
        ),
        (
            "misiurewicz 1e-30 max-iter 1000",
            "perturbation",
            view(MISIUREWICZ_4_1, "1e-30", 1000),
        ),
    ];
    let mut dwells = vec![0u16; 320 * 240];
    for (name, method, view) in cases {
        let mut storage = vec![ReferencePoint::default(); view.max_iterations() as usize + 1];
        let stats = render(view, &mut storage, &mut dwells);
        // One line per case, read by benches/record.
        println!(
            "work view={} method={method} tier={} iterations={} skipped={} rebases={}",
            name.replace(' ', "_"),
            stats.tier.name(),
            stats.iterations,
            stats.skipped,
            stats.rebases,
        );
        let mut group = c.benchmark_group(format!("deep {name} 320x240"));
        group.sample_size(10);
        group.bench_function(method, |b| {
            b.iter(|| render(black_box(view), &mut storage, &mut dwells))
        });
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
