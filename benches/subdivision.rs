//! The Sierpiński family and midpoint displacement at the gallery's size: squares, cubes
//! and terrain heights per second, fitted and drawn into a 320×240 framebuffer.
//! `cargo bench --bench subdivision`.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
};
use std::hint::black_box;
use tinyfractal::{
    subdivision::CubeVariant, terrain::Displacement, Carpet, Gasket, Real, SierpinskiCube, Terrain,
    TerrainMap,
};

use tinyfractal_test_support::frame;

fn bench(c: &mut Criterion) {
    let mut target = frame::Frame::filled(Size::new(320, 240), Rgb565::BLACK);
    let area = target.bounding_box();
    let (ink, paper) = (Rgb565::WHITE, Rgb565::BLACK);

    let carpet = Carpet::new(4);
    let mut group = c.benchmark_group("carpet-order-4");
    group.throughput(Throughput::Elements(carpet.squares()));
    group.bench_function("fit + draw 320x240 (squares)", |b| {
        b.iter(|| {
            black_box(carpet)
                .fit(area, ink, paper)
                .unwrap()
                .draw(&mut target)
                .unwrap()
        })
    });
    group.finish();

    let gasket = Gasket::new(7);
    let mut group = c.benchmark_group("gasket-order-7");
    group.throughput(Throughput::Elements(gasket.triangles()));
    group.bench_function("fit + draw 320x240 (triangles)", |b| {
        b.iter(|| {
            black_box(gasket)
                .fit(area, ink, paper)
                .unwrap()
                .draw(&mut target)
                .unwrap()
        })
    });
    group.finish();

    let sponge = SierpinskiCube::new(3, CubeVariant::Axes);
    let mut group = c.benchmark_group("menger-order-3");
    group.throughput(Throughput::Elements(sponge.cubes()));
    group.bench_function("fit + draw 320x240 (cubes)", |b| {
        b.iter(|| {
            black_box(sponge)
                .fit(area, Rgb888::new(200, 180, 120), paper)
                .unwrap()
                .draw(&mut target)
                .unwrap()
        })
    });
    group.finish();

    let displacement = Displacement {
        roughness: Real::from_ratio(7, 10).unwrap(),
        sigma: Real::from_int(20),
        seed: 1,
    };
    let profile = Terrain::new(65_537, displacement);
    let mut group = c.benchmark_group("terrain-65537");
    group.throughput(Throughput::Elements(65_537));
    group.bench_function("heights (points)", |b| {
        b.iter(|| black_box(profile).heights().unwrap().raw().count())
    });
    group.bench_function("fit + draw 320x240 (points)", |b| {
        b.iter(|| {
            black_box(profile)
                .fit(area, ink, paper)
                .unwrap()
                .draw(&mut target)
                .unwrap()
        })
    });
    group.finish();

    let map = TerrainMap::new(257, displacement);
    let mut heights = vec![0; map.cells()];
    let mut group = c.benchmark_group("terrain2d-257");
    group.throughput(Throughput::Elements(map.cells() as u64));
    group.bench_function("diamond-square (points)", |b| {
        b.iter(|| black_box(map).generate(&mut heights).unwrap())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
