//! L-system throughput: the Koch snowflake at order 8 (196,608 segments), walked alone and
//! walked and rasterised into a 320×240 RGB565 framebuffer.
//!
//! `cargo bench --bench lsystem`; the README quotes these numbers.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
use std::hint::black_box;
use tinyfractal::{Angle, Dialect, Grammar, LSystem, Segments};

/// A framebuffer whose `fill_solid` writes rows directly, as a real one would.
struct Framebuffer {
    pixels: Vec<Rgb565>,
}

impl Framebuffer {
    const SIZE: Size = Size::new(320, 240);
    fn new() -> Self {
        Self {
            pixels: vec![Rgb565::BLACK; 320 * 240],
        }
    }
}

impl OriginDimensions for Framebuffer {
    fn size(&self) -> Size {
        Self::SIZE
    }
}

impl DrawTarget for Framebuffer {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if let (Ok(x @ 0..320), Ok(y @ 0..240)) = (usize::try_from(p.x), usize::try_from(p.y)) {
                self.pixels[y * 320 + x] = c;
            }
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Self::Error> {
        let area = area.intersection(&self.bounding_box());
        let Some(bottom_right) = area.bottom_right() else {
            return Ok(());
        };
        for y in area.top_left.y..=bottom_right.y {
            let row = y as usize * 320;
            self.pixels[row + area.top_left.x as usize..=row + bottom_right.x as usize].fill(color);
        }
        Ok(())
    }
}

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
    let mut framebuffer = Framebuffer::new();
    let drawing = LSystem::new(&grammar, 8)
        .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
        .unwrap();
    group.bench_function("segments + rasterisation (320x240)", |b| {
        b.iter(|| drawing.draw(black_box(&mut framebuffer)).unwrap())
    });
    group.bench_function("fit (sizing + checking passes)", |b| {
        b.iter(|| {
            LSystem::new(black_box(&grammar), 8)
                .fit(Framebuffer::new().bounding_box(), &[Rgb565::WHITE])
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
