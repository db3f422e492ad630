//! Every core of the host: a 4096×4096 Mandelbrot's dwells and the gallery's pictures on
//! one thread and on two (`--threads`), the same output either way.
//! `cargo bench -p tinyfractal-simulator --bench threads`.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use embedded_graphics::prelude::Size;
use tinyfractal::escape::Algorithm;
use tinyfractal::{Coord, Fractal, View};
use tinyfractal_simulator::{escape_scene, gallery, parallel};

fn threads(c: &mut Criterion) {
    let view = View::new(
        Fractal::Mandelbrot,
        (Coord::parse("-0.75").unwrap(), Coord::default()),
        Coord::parse("3.5").unwrap(),
        Size::new(4096, 4096),
        256,
    )
    .unwrap();
    let mut group = c.benchmark_group("mandelbrot-4096");
    group.sample_size(10);
    for threads in [1usize, 2] {
        group.bench_function(format!("dwells, {threads} thread(s)"), |b| {
            b.iter(|| {
                parallel::with_threads(Some(threads), || {
                    escape_scene::compute(view, Algorithm::Fast).unwrap()
                })
                .unwrap()
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("gallery");
    group.sample_size(10);
    for threads in [1usize, 2] {
        group.bench_function(format!("every picture, {threads} thread(s)"), |b| {
            b.iter(|| parallel::with_threads(Some(threads), || gallery::pictures(|| {})).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, threads);
criterion_main!(benches);
