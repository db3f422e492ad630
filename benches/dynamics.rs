//! The lecture's dynamics on the host: the Hénon and Lorenz attractors by density at
//! 320×240 (beside the f64 loop a user writes, counting into the same buffer), the
//! fountain's particles a tick at a time, and the figure in Bézier curves.
//! `cargo bench --bench dynamics`; `benches/record` keeps the numbers.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use std::hint::black_box;
use tinyfractal::attractor::{Attractor, AttractorPicture, Kind};
use tinyfractal::bezier::Bezier;
use tinyfractal::particles::{Frames, ParticleLook, Preset};
use tinyfractal::render::{Gradient, TwoColor};

use tinyfractal_test_support::frame;

const POINTS: u64 = 1_000_000;

/// The Hénon map in f64 into the same counts, its box known in advance (a user's loop).
fn henon_f64(counts: &mut [u16], width: usize, height: usize) {
    let (mut x, mut y) = (0.0f64, 0.0f64);
    for step in 0..1000 + POINTS {
        (x, y) = (1.0 - 1.4 * x * x + y, 0.3 * x);
        if step >= 1000 {
            let px = ((x + 1.3) / 2.6 * width as f64) as usize;
            let py = ((0.4 - y) / 0.8 * height as f64) as usize;
            if px < width && py < height {
                let cell = &mut counts[py * width + px];
                *cell = cell.saturating_add(1);
            }
        }
    }
}

fn attractors(c: &mut Criterion) {
    let keys = [
        embedded_graphics::pixelcolor::Rgb888::BLACK,
        embedded_graphics::pixelcolor::Rgb888::WHITE,
    ];
    let palette = Gradient::<Rgb565, 16>::new(&keys, Rgb565::BLACK).unwrap();
    let mut framebuffer = frame::Frame::filled(Size::new(320, 240), Rgb565::BLACK);
    let mut counts = vec![0u16; 320 * 240];
    for (kind, points) in [(Kind::Henon, POINTS), (Kind::Lorenz, POINTS / 10)] {
        let mut group = c.benchmark_group(format!("attractor-{}", kind.name()));
        group.throughput(Throughput::Elements(points));
        group.bench_function("fit + density 320x240", |b| {
            b.iter(|| {
                AttractorPicture::new(Attractor::new(black_box(kind)), points)
                    .fit_density(framebuffer.bounding_box(), palette, &mut counts)
                    .unwrap()
                    .draw(&mut framebuffer)
                    .unwrap()
            })
        });
        if kind == Kind::Henon {
            group.bench_function("peer: f64 loop into the same counts", |b| {
                b.iter(|| henon_f64(black_box(&mut counts), 320, 240))
            });
        }
        group.finish();
    }
}

fn particles(c: &mut Criterion) {
    let mut group = c.benchmark_group("particles-fountain-300-ticks");
    let look = ParticleLook {
        palette: TwoColor {
            inside: Rgb565::WHITE,
            outside: Rgb565::WHITE,
        },
        size_at_birth: 2,
        size_at_death: 1,
    };
    let mut framebuffer = frame::Frame::filled(Size::new(320, 240), Rgb565::BLACK);
    group.bench_function("step + draw 320x240, pool of 512", |b| {
        b.iter(|| {
            let mut system = Preset::Fountain.system::<512>(Size::new(320, 240), 1);
            let mut frames = Frames::new();
            for _ in 0..300 {
                system.step(1);
                frames
                    .draw(&system, &look, Rgb565::BLACK, &mut framebuffer)
                    .unwrap();
            }
            system.ticks()
        })
    });
    group.finish();
}

fn curves(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier");
    let mut framebuffer = frame::Frame::filled(Size::new(320, 240), Rgb565::BLACK);
    let curve = Bezier::cubic([
        Point::new(10, 230),
        Point::new(60, -100),
        Point::new(260, 340),
        Point::new(310, 10),
    ]);
    group.bench_function("cubic across 320x240: flatten + draw", |b| {
        b.iter(|| {
            black_box(curve)
                .into_stroked(Rgb565::WHITE)
                .draw(&mut framebuffer)
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, attractors, particles, curves);
criterion_main!(benches);
