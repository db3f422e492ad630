//! A fit that keeps its marks (`fit_with_marks`) draws exactly what a fit that walks again
//! draws, for every system of the book's file, in every projection, with and without
//! depth cue, flat, lit, and lit through a depth buffer; its buffer holds a line a record and a
//! polygon of n vertices in 1 + ⌊n / 2⌋, counted here from the walk's own marks; a buffer
//! one record short, or a perspective, walks again.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::lsystem::{Mark, Marks3, StoredMark};
use tinyfractal::render::Projection;
use tinyfractal::{LsysFile, ParametricGrammar, ParametricLSystem, Real};

const ABOP: &str = include_str!("../data/abop.lsys");
const LECTURE: &str = include_str!("../data/lecture.lsys");

const PALETTE: [Rgb888; 4] = [
    Rgb888::new(200, 40, 40),
    Rgb888::new(40, 200, 40),
    Rgb888::new(40, 40, 200),
    Rgb888::new(220, 220, 220),
];

/// Every system of the repository's `.lsys` files, at an order small enough for a test.
fn systems() -> Vec<(String, ParametricGrammar, u32)> {
    let mut all = Vec::new();
    for text in [ABOP, LECTURE] {
        for entry in LsysFile::new(text).entries() {
            let entry = entry.unwrap();
            let name = entry.name().to_string();
            let Ok(grammar) = entry.parametric() else {
                continue;
            };
            if grammar.uses_environment() {
                continue;
            }
            all.push((name, grammar, 4));
        }
    }
    assert!(all.len() >= 20, "{} systems", all.len());
    all
}

/// The records a walk's marks take: a line one, a polygon of n vertices 1 + ⌊n / 2⌋.
fn records_needed(grammar: &ParametricGrammar, order: u32) -> usize {
    let mut marks: Marks3<'_> = Marks3::new(grammar, order).unwrap();
    let mut records = 0;
    while let Some(mark) = marks.next_mark() {
        records += match mark.unwrap() {
            Mark::Line { .. } => 1,
            Mark::Polygon { vertices, .. } => 1 + vertices.len() / 2,
        };
    }
    records
}

/// How a test draws.
#[derive(Debug, Clone, Copy)]
enum Draw {
    /// `try_draw`: flat colours in walk order.
    Flat,
    /// `try_draw_lit` in walk order.
    Lit,
    /// `try_draw_lit` through a depth buffer.
    LitSorted,
}

/// The pixels of `system` fitted into 96×80 and drawn as `how` says; with `records`,
/// fitted keeping its marks in that many, and how many it kept.
fn drawn(
    system: &ParametricLSystem<'_>,
    how: Draw,
    records: Option<usize>,
) -> (Vec<Rgb888>, Option<usize>) {
    let size = Size::new(96, 80);
    let area = Rectangle::new(Point::zero(), size);
    let mut display = SimulatorDisplay::<Rgb888>::new(size);
    let mut buffer = vec![StoredMark::EMPTY; records.unwrap_or(0)];
    let drawing = match records {
        Some(_) => system.fit_with_marks(area, &PALETTE, &mut buffer),
        None => system.fit(area, &PALETTE),
    }
    .unwrap();
    let kept = drawing.kept_marks();
    let mut depth = vec![0u16; 96 * 80];
    match how {
        Draw::Flat => drawing.try_draw(&mut display),
        Draw::Lit => drawing.try_draw_lit(&mut display, None),
        Draw::LitSorted => drawing.try_draw_lit(&mut display, Some(&mut depth)),
    }
    .unwrap();
    let pixels = area.points().map(|p| display.get_pixel(p)).collect();
    (pixels, kept)
}

#[test]
fn kept_marks_draw_what_a_second_walk_draws() {
    let projections = [
        None,
        Some(Projection::Front),
        Some(Projection::Isometric),
        Some(Projection::Perspective {
            distance: Real::from_int(3),
        }),
    ];
    let mut replayed = 0;
    for (name, grammar, order) in systems() {
        let needed = records_needed(&grammar, order);
        for projection in projections {
            for depth_cue in [false, true] {
                let mut system = ParametricLSystem::new(&grammar, order).with_depth_cue(depth_cue);
                if let Some(projection) = projection {
                    system = system.with_projection(projection);
                }
                let seen_in_3d = system.projection();
                for how in [Draw::Flat, Draw::Lit, Draw::LitSorted] {
                    let (walked, none) = drawn(&system, how, None);
                    assert_eq!(none, None);
                    let (kept, count) = drawn(&system, how, Some(needed));
                    let (short, short_count) = drawn(&system, how, Some(needed.saturating_sub(1)));
                    let what = format!("{name} {projection:?} cue {depth_cue} {how:?}");
                    assert!(walked == kept, "{what}: kept marks drew other pixels");
                    assert!(walked == short, "{what}: a short buffer drew other pixels");
                    match seen_in_3d {
                        Some(Projection::Perspective { .. }) | None => {
                            assert_eq!(count, None, "{what}")
                        }
                        Some(_) => {
                            assert_eq!(count, Some(needed), "{what}");
                            replayed += 1;
                        }
                    }
                    if needed > 0 {
                        assert_eq!(short_count, None, "{what}: a short buffer kept its marks");
                    }
                }
            }
        }
    }
    assert!(replayed > 50, "{replayed} drawings replayed");
}

/// docs/memory.md states 64 bytes a record.
#[test]
fn a_record_takes_64_bytes() {
    assert_eq!(StoredMark::BYTES, 64);
}
