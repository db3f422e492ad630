//! The chaos game: the lecture's fern, 100,000 points, played alone and fitted and drawn
//! into 320×240. `cargo bench --bench ifs`; `benches/record` keeps the numbers.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use std::hint::black_box;
use tinyfractal::{ifs::IfsPicture, ChaosGame, IfsFile};

use tinyfractal_test_support::frame;

const POINTS: u64 = 100_000;

fn bench(c: &mut Criterion) {
    let ifs = IfsFile::new(include_str!("../data/lecture.ifs"))
        .entry("fern")
        .unwrap()
        .ifs()
        .unwrap();
    let mut group = c.benchmark_group("ifs-fern-100k");
    group.throughput(Throughput::Elements(POINTS));
    group.bench_function("chaos game", |b| {
        b.iter(|| {
            assert_eq!(
                ChaosGame::new(black_box(&ifs), 1, POINTS).count() as u64,
                POINTS
            )
        })
    });
    let mut framebuffer = frame::Frame::filled(Size::new(320, 240), Rgb565::BLACK);
    group.bench_function("fit + draw 320x240", |b| {
        b.iter(|| {
            let drawing = IfsPicture::new(black_box(&ifs), POINTS)
                .fit(framebuffer.bounding_box(), &[Rgb565::GREEN])
                .unwrap();
            drawing.draw(&mut framebuffer).unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
