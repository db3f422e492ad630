//! Escape-time speed: `exact` and `fast` against a naive f64 per-pixel loop, on the full
//! Mandelbrot view and a boundary-heavy zoom, 320×240. Also prints the work each does as a
//! fraction of the naive loop's, and the draw calls per frame.
//!
//! `cargo bench --bench escape`; docs/performance.md quotes these numbers.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use embedded_graphics::prelude::*;
use std::hint::black_box;
use tinyfractal::{
    escape::{Algorithm, Render},
    render::DwellBuffer,
    Coord, Fractal, View,
};

/// What a user would write first: f64, every pixel, no tricks. Returns total iterations.
fn naive(centre: (f64, f64), width: f64, size: Size, max: u32) -> u64 {
    let d = width / f64::from(size.width);
    let mut total = 0u64;
    for j in 0..size.height {
        for i in 0..size.width {
            let cr = centre.0 + (f64::from(i) + 0.5 - f64::from(size.width) / 2.0) * d;
            let ci = centre.1 - (f64::from(j) + 0.5 - f64::from(size.height) / 2.0) * d;
            let (mut x, mut y) = (0.0f64, 0.0f64);
            let mut n = 0;
            while n < max {
                n += 1;
                (x, y) = (x * x - y * y + cr, 2.0 * x * y + ci);
                if x * x + y * y > 4.0 {
                    break;
                }
            }
            total += u64::from(n);
        }
    }
    total
}

fn bench(c: &mut Criterion) {
    let size = Size::new(320, 240);
    let views = [
        ("full view", (-0.75, 0.0), 3.5, "-0.75", "0", "3.5"),
        (
            "seahorse zoom",
            (-0.7435, 0.1314),
            0.02,
            "-0.7435",
            "0.1314",
            "0.02",
        ),
    ];
    for (name, centre, width, re, im, w) in views {
        let view = View::new(
            Fractal::Mandelbrot,
            (Coord::parse(re).unwrap(), Coord::parse(im).unwrap()),
            Coord::parse(w).unwrap(),
            size,
            256,
        )
        .unwrap();
        let naive_iterations = naive(centre, width, size, 256);
        // The dwells land in a buffer, as the naive loop's would in a frame.
        let mut dwells = vec![0u16; (size.width * size.height) as usize];
        for algorithm in [Algorithm::Exact, Algorithm::Fast] {
            let stats = Render::new(view, algorithm)
                .run(&mut DwellBuffer::new(&mut dwells, size.width))
                .unwrap();
            // One line per view and algorithm, read by benches/record.
            println!(
                "work view={} algorithm={algorithm:?} tier={} iterations={} naive={naive_iterations} pixels={} of={} draw_calls={}",
                name.replace(' ', "-"),
                stats.tier.name(),
                stats.iterations,
                stats.pixels,
                size.width * size.height,
                stats.draw_calls
            );
        }
        let mut group = c.benchmark_group(format!("mandelbrot {name} 320x240 max-iter 256"));
        group.sample_size(20);
        group.bench_function("naive f64 per pixel", |b| {
            b.iter(|| naive(black_box(centre), width, size, 256))
        });
        for algorithm in [Algorithm::Exact, Algorithm::Fast] {
            group.bench_function(format!("{algorithm:?}"), |b| {
                b.iter(|| {
                    Render::new(black_box(view), algorithm)
                        .run(&mut DwellBuffer::new(&mut dwells, size.width))
                        .unwrap()
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
