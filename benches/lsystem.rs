//! L-system throughput: the Koch snowflake at order 8 (196,608 segments) into 320×240,
//! side by side with the peer a new user would write: the `lindenmayer` crate's derivation
//! iterator and an `f32` turtle (a sizing walk, then a drawing walk with Bresenham into a
//! byte buffer).
//!
//! `cargo bench --bench lsystem`; `benches/record` keeps the numbers docs/performance.md quotes.

// `criterion_group!` defines a public function without documentation.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
use std::hint::black_box;
use tinyfractal::{
    lsystem::{cells_needed, Cell, Segments},
    render::Colors,
    Angle, Dialect, Grammar, LSystem,
};

use tinyfractal_test_support::frame;

type Framebuffer = frame::Frame<Rgb565>;

const ORDER: u32 = 8;
const SIZE: (usize, usize) = (320, 240);

fn koch() -> Grammar<'static> {
    Grammar::new(Dialect::Fractint, "F--F--F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap()
}

/// The peer: `lindenmayer` derives, an `f32` turtle walks twice (size, then draw with
/// Bresenham into one byte a pixel). Returns the segments drawn.
fn peer(pixels: &mut [u8]) -> u64 {
    let system = lindenmayer::LSystem::new(String::from("F--F--F"), &[('F', "F+F--F+F")]);
    let turn = std::f32::consts::PI / 3.0;
    let walk = |mut visit: Box<dyn FnMut(f32, f32, f32, f32) + '_>| {
        let (mut x, mut y, mut heading) = (0.0f32, 0.0f32, 0.0f32);
        for symbol in system.builder(ORDER as usize) {
            match symbol {
                'F' => {
                    let (nx, ny) = (x + heading.cos(), y + heading.sin());
                    visit(x, y, nx, ny);
                    (x, y) = (nx, ny);
                }
                '+' => heading += turn,
                '-' => heading -= turn,
                _ => {}
            }
        }
    };
    let (mut min, mut max) = ((0.0f32, 0.0f32), (0.0f32, 0.0f32));
    walk(Box::new(|_, _, x, y| {
        min = (min.0.min(x), min.1.min(y));
        max = (max.0.max(x), max.1.max(y));
    }));
    let (w, h) = (SIZE.0 as f32 - 5.0, SIZE.1 as f32 - 5.0);
    let scale = (w / (max.0 - min.0)).min(h / (max.1 - min.1));
    let mut segments = 0;
    walk(Box::new(|x0, y0, x1, y1| {
        let to_pixel = |x: f32, y: f32| {
            (
                ((x - min.0) * scale + 2.0) as i32,
                (SIZE.1 as f32 - 3.0 - (y - min.1) * scale) as i32,
            )
        };
        let ((mut x, mut y), (x1, y1)) = (to_pixel(x0, y0), to_pixel(x1, y1));
        let (dx, dy) = ((x1 - x).abs(), -(y1 - y).abs());
        let (sx, sy) = (if x < x1 { 1 } else { -1 }, if y < y1 { 1 } else { -1 });
        let mut error = dx + dy;
        loop {
            if let Some(p) = pixels.get_mut(y as usize * SIZE.0 + x as usize) {
                *p = 1;
            }
            if x == x1 && y == y1 {
                break;
            }
            let twice = 2 * error;
            if twice >= dy {
                error += dy;
                x += sx;
            }
            if twice <= dx {
                error += dx;
                y += sy;
            }
        }
        segments += 1;
    }));
    segments
}

fn bench(c: &mut Criterion) {
    let grammar = koch();
    let segments = 3 * 4u64.pow(ORDER);
    let size = Size::new(SIZE.0 as u32, SIZE.1 as u32);
    println!(
        "walker state (Segments, default capacities): {} bytes at any order",
        size_of::<Segments<'static, 'static>>()
    );
    let mut group = c.benchmark_group("koch-snowflake-order-8");
    group.throughput(Throughput::Elements(segments));
    group.bench_function("segments (walk + turtle)", |b| {
        b.iter(|| {
            let count = Segments::new(black_box(&grammar), ORDER).unwrap().count();
            assert_eq!(count as u64, segments);
        })
    });
    let mut framebuffer = Framebuffer::filled(size, Rgb565::BLACK);
    let walked = LSystem::new(&grammar, ORDER)
        .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
        .unwrap();
    group.bench_function("fit (walk: sizing pass, box predicted)", |b| {
        b.iter(|| {
            LSystem::new(black_box(&grammar), ORDER)
                .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
                .unwrap()
        })
    });
    group.bench_function("draw (walk + rasterise)", |b| {
        b.iter(|| walked.draw(black_box(&mut framebuffer)).unwrap())
    });
    let needed = cells_needed(&grammar, ORDER).unwrap();
    let palette = [Rgb565::WHITE];
    group.bench_function("fit (expansion table)", |b| {
        let mut cells = vec![Cell::default(); needed];
        b.iter(|| {
            let drawing = LSystem::new(black_box(&grammar), ORDER)
                .fit_in(size_box(size), Colors::new(&palette).unwrap(), &mut cells)
                .unwrap();
            black_box(drawing.bounding_box())
        })
    });
    group.bench_function(
        "draw (expansion table: culling, one pixel per sub-pixel subtree)",
        |b| {
            let mut cells = vec![Cell::default(); needed];
            let drawing = LSystem::new(&grammar, ORDER)
                .fit_in(size_box(size), Colors::new(&palette).unwrap(), &mut cells)
                .unwrap();
            b.iter(|| drawing.draw(black_box(&mut framebuffer)).unwrap())
        },
    );
    group.bench_function("fit + draw (expansion table, as the CLI)", |b| {
        let mut cells = vec![Cell::default(); needed];
        b.iter(|| {
            let drawing = LSystem::new(black_box(&grammar), ORDER)
                .fit_in(size_box(size), Colors::new(&palette).unwrap(), &mut cells)
                .unwrap();
            drawing.draw(&mut framebuffer).unwrap()
        })
    });
    group.bench_function(
        "peer: lindenmayer + f32 turtle, two walks + Bresenham",
        |b| {
            let mut pixels = vec![0u8; SIZE.0 * SIZE.1];
            b.iter(|| assert_eq!(peer(black_box(&mut pixels)), segments))
        },
    );
    group.finish();
    general(c);
}

/// The general engine: ABOP's monopodial tree (figure 2.6, parametric, 3D) at its order,
/// 1,023 segments, walked, and fitted and drawn into 320×240 (walked twice, or once with
/// the marks kept).
fn general(c: &mut Criterion) {
    const TREE_SEGMENTS: u64 = 1023;
    let file = tinyfractal::LsysFile::new(include_str!("../data/abop.lsys"));
    let grammar = file.entry("MonopodialTree").unwrap().parametric().unwrap();
    let mut group = c.benchmark_group("monopodial-tree-order-10");
    group.throughput(Throughput::Elements(TREE_SEGMENTS));
    group.bench_function("segments (walk + 3D turtle)", |b| {
        b.iter(|| {
            let walk: tinyfractal::lsystem::Segments3 =
                tinyfractal::lsystem::Segments3::new(black_box(&grammar), 10).unwrap();
            assert_eq!(walk.count() as u64, TREE_SEGMENTS);
        })
    });
    let mut framebuffer = Framebuffer::filled(Size::new(320, 240), Rgb565::BLACK);
    group.bench_function("fit + draw 320x240", |b| {
        b.iter(|| {
            let system: tinyfractal::ParametricLSystem =
                tinyfractal::ParametricLSystem::new(black_box(&grammar), 10);
            let drawing = system
                .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
                .unwrap();
            drawing.draw(&mut framebuffer).unwrap()
        })
    });
    let mut marks = vec![tinyfractal::lsystem::StoredMark::EMPTY; TREE_SEGMENTS as usize];
    group.bench_function("fit keeping marks + draw 320x240", |b| {
        b.iter(|| {
            let system: tinyfractal::ParametricLSystem =
                tinyfractal::ParametricLSystem::new(black_box(&grammar), 10);
            let drawing = system
                .fit_with_marks(framebuffer.bounding_box(), &[Rgb565::WHITE], &mut marks)
                .unwrap();
            assert_eq!(drawing.kept_marks(), Some(TREE_SEGMENTS as usize));
            drawing.draw(&mut framebuffer).unwrap()
        })
    });
    group.finish();
}

/// Polygon fill per pixel beside embedded-graphics' own `Triangle` fill of about the same
/// triangle (its bounding box's base and apex), both into the same framebuffer; and ABOP's
/// bush of figure 1.25 drawn with its leaves and without (the same lines).
fn plants(c: &mut Criterion) {
    use embedded_graphics::primitives::{PrimitiveStyle, Triangle};
    let file = tinyfractal::LsysFile::new(include_str!("../data/abop.lsys"));
    let mut framebuffer = Framebuffer::filled(Size::new(320, 240), Rgb565::BLACK);
    let lit = |framebuffer: &Framebuffer| {
        framebuffer
            .bounding_box()
            .points()
            .filter(|p| framebuffer.pixel(p.x, p.y) != Some(Rgb565::BLACK))
            .count() as u64
    };
    let triangle = tinyfractal::LsysFile::new("t {\n axiom: {.f+(120).f+(120).f}\n angle: 90\n}\n")
        .entry("t")
        .unwrap()
        .parametric()
        .unwrap();
    let system: tinyfractal::ParametricLSystem = tinyfractal::ParametricLSystem::new(&triangle, 0);
    let drawing = system
        .fit(framebuffer.bounding_box(), &[Rgb565::WHITE])
        .unwrap();
    drawing.draw(&mut framebuffer).unwrap();
    let ours = lit(&framebuffer);
    let bounds = drawing.bounding_box();
    let end = bounds.bottom_right().unwrap();
    let theirs = Triangle::new(
        Point::new(bounds.top_left.x, end.y),
        Point::new(end.x, end.y),
        Point::new((bounds.top_left.x + end.x) / 2, bounds.top_left.y),
    )
    .into_styled(PrimitiveStyle::with_fill(Rgb565::WHITE));
    framebuffer.clear(Rgb565::BLACK).unwrap();
    theirs.draw(&mut framebuffer).unwrap();
    let their_pixels = lit(&framebuffer);
    println!("work group=polygon-fill ours_pixels={ours} triangle_pixels={their_pixels}");
    let mut group = c.benchmark_group("polygon-fill");
    group.throughput(Throughput::Elements(ours));
    group.bench_function("a triangle polygon, fit + fill", |b| {
        b.iter(|| drawing.draw(black_box(&mut framebuffer)).unwrap())
    });
    group.throughput(Throughput::Elements(their_pixels));
    group.bench_function("peer: embedded-graphics Triangle fill", |b| {
        b.iter(|| theirs.draw(black_box(&mut framebuffer)).unwrap())
    });
    group.finish();
    let mut group = c.benchmark_group("bush-figure-1.25-order-5");
    group.throughput(Throughput::Elements(420));
    for name in ["Fig1.25", "Fig1.25Bare"] {
        let grammar = file.entry(name).unwrap().parametric().unwrap();
        group.bench_function(format!("{name}: fit + draw lit 320x240"), |b| {
            b.iter(|| {
                let system: tinyfractal::ParametricLSystem =
                    tinyfractal::ParametricLSystem::new(black_box(&grammar), 5);
                let drawing = system
                    .fit(
                        framebuffer.bounding_box(),
                        &[Rgb565::CSS_SADDLE_BROWN, Rgb565::GREEN],
                    )
                    .unwrap();
                drawing.try_draw_lit(&mut framebuffer, None).unwrap()
            })
        });
    }
    group.finish();
}

fn size_box(size: Size) -> embedded_graphics::primitives::Rectangle {
    embedded_graphics::primitives::Rectangle::new(Point::zero(), size)
}

criterion_group!(benches, bench, plants);
criterion_main!(benches);
