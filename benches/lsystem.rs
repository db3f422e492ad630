//! L-system throughput: the Koch snowflake at order 8 (196,608 segments), walked alone and
//! walked and rasterised into a 320×240 RGB565 framebuffer.
//!
//! `cargo bench --bench lsystem`; the README quotes these numbers.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use std::hint::black_box;
use tinyfractal::{Angle, Dialect, Grammar, LSystem, Segments};

#[path = "../tests/support/frame.rs"]
mod frame;

type Framebuffer = frame::Frame<Rgb565>;

fn koch() -> Grammar<'static> {
    Grammar::new(Dialect::Fractint, "F--F--F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap()
}

fn bench(c: &mut Criterion) {
    let grammar = koch();
    let segments = 3 * 4u64.pow(8);
    println!(
        "walker state (Segments, default capacities): {} bytes at any order",
        core::mem::size_of::<Segments<'static, 'static>>()
    );
    let mut group = c.benchmark_group("koch-snowflake-order-8");
    group.throughput(Throughput::Elements(segments));
    group.bench_function("segments (walk + turtle)", |b| {
        b.iter(|| {
            let count = Segments::new(black_box(&grammar), 8).unwrap().count();
            assert_eq!(count as u64, segments);
        })
    });
    let mut framebuffer = Framebuffer::filled(Size::new(320, 240), Rgb565::BLACK);
    let drawing = LSystem::new(&grammar, 8)
        .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
        .unwrap();
    group.bench_function("segments + rasterisation (320x240)", |b| {
        b.iter(|| drawing.draw(black_box(&mut framebuffer)).unwrap())
    });
    group.bench_function("fit (sizing + checking passes)", |b| {
        b.iter(|| {
            LSystem::new(black_box(&grammar), 8)
                .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
