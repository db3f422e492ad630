//! Drawing through embedded-graphics: MockDisplay patterns, what reaches the target (runs
//! through `fill_solid`, never per-pixel `draw_iter`), and agreement with a per-pixel path.

mod common;

use common::{koch_snowflake, pixel, Bitmap, Counting};
use embedded_graphics::{
    mock_display::MockDisplay,
    pixelcolor::BinaryColor,
    prelude::*,
    primitives::{Line, PrimitiveStyle, Rectangle},
};
use tinyfractal::{
    lsystem::{Placement, Segments},
    render::Orientation,
    Angle, Dialect, Grammar, LSystem, Real,
};

fn square() -> Grammar<'static> {
    Grammar::new(Dialect::Abop, "F+F+F+F", Angle::Divisions(4)).unwrap()
}

#[test]
fn a_placed_square_draws_exactly_its_pixels() {
    let mut display = MockDisplay::<BinaryColor>::new();
    // The square closes on its first pixel: one pixel is drawn twice, on purpose.
    display.set_allow_overdraw(true);
    let placement = Placement {
        origin: Point::new(1, 5),
        step: Real::from_int(4),
        turns: 0,
    };
    let square = square();
    let drawing = LSystem::new(&square, 0)
        .place(placement, &[BinaryColor::On])
        .unwrap();
    drawing.draw(&mut display).unwrap();
    display.assert_pattern(&["      ", " #####", " #   #", " #   #", " #   #", " #####"]);
    assert_eq!(
        drawing.bounding_box(),
        Rectangle::new(Point::new(1, 1), Size::new(5, 5))
    );
    assert_eq!(display.affected_area(), drawing.bounding_box());
}

/// A staircase, worked out by hand: from (0,5) with step 2, `F` right to (2,5), `+F` up to
/// (2,3), `-F` right to (4,3), `+F` up to (4,1), `-F` right to (6,1). Each joint is drawn
/// once: a continuing segment skips its first pixel, so MockDisplay sees no overdraw.
#[test]
fn a_continuing_line_draws_each_joint_once() {
    let stairs = Grammar::new(Dialect::Abop, "F+F-F+F-F", Angle::Divisions(4)).unwrap();
    let mut display = MockDisplay::<BinaryColor>::new();
    let placement = Placement {
        origin: Point::new(0, 5),
        step: Real::from_int(2),
        turns: 0,
    };
    LSystem::new(&stairs, 0)
        .place(placement, &[BinaryColor::On])
        .unwrap()
        .draw(&mut display)
        .unwrap();
    display.assert_pattern(&[
        "       ", "    ###", "    #  ", "  ###  ", "  #    ", "###    ",
    ]);
}

#[test]
fn orientation_rotates_by_quarter_turns() {
    let line = Grammar::new(Dialect::Abop, "FF", Angle::Divisions(4)).unwrap();
    let origin = Point::new(3, 3);
    let place = |orientation| {
        LSystem::new(&line, 0)
            .with_orientation(orientation)
            .place(
                Placement {
                    origin,
                    step: Real::ONE,
                    turns: 0,
                },
                &[BinaryColor::On],
            )
            .unwrap()
            .bounding_box()
    };
    assert_eq!(
        place(Orientation::Right),
        Rectangle::new(origin, Size::new(3, 1))
    );
    assert_eq!(
        place(Orientation::Up),
        Rectangle::new(Point::new(3, 1), Size::new(1, 3))
    );
    assert_eq!(
        place(Orientation::Left),
        Rectangle::new(Point::new(1, 3), Size::new(3, 1))
    );
    assert_eq!(
        place(Orientation::Down),
        Rectangle::new(origin, Size::new(1, 3))
    );
}

fn hilbert() -> Grammar<'static> {
    Grammar::new(Dialect::Abop, "A", Angle::Divisions(4))
        .unwrap()
        .with_rule('A', "+BF-AFA-FB+")
        .unwrap()
        .with_rule('B', "-AF+BFB+FA-")
        .unwrap()
}

#[test]
fn axis_aligned_lines_are_one_fill_solid_each() {
    let mut target = Counting::new(Bitmap::new(128, 128));
    let hilbert = hilbert();
    let drawing = LSystem::new(&hilbert, 5)
        .fit(target.bounding_box(), &[BinaryColor::On])
        .unwrap();
    let stats = drawing.draw(&mut target).unwrap();
    assert_eq!(stats.segments, 4u64.pow(5) - 1);
    assert_eq!(target.draw_iter_pixels, 0, "no per-pixel writes");
    assert_eq!(target.fill_contiguous_calls, 0);
    // One run per segment: a segment on an axis is a single rectangle.
    assert_eq!(target.fill_solid_calls as u64, stats.segments);
}

/// The run-based fast path lights exactly the pixels that embedded-graphics' own per-pixel
/// `Line` lights, for axis-aligned curves where line rasterisation has no ties.
#[test]
fn runs_match_per_pixel_lines() {
    let grammar = hilbert();
    let mut fast = Counting::new(Bitmap::new(128, 128));
    let drawing = LSystem::new(&grammar, 5)
        .fit(fast.bounding_box(), &[BinaryColor::On])
        .unwrap();
    drawing.draw(&mut fast).unwrap();

    let mut slow = Bitmap::new(128, 128);
    let start = drawing.start();
    for segment in Segments::starting(&grammar, 5, start).unwrap() {
        let segment = segment.unwrap();
        Line::new(pixel(segment.start), pixel(segment.end))
            .into_styled(PrimitiveStyle::with_stroke(BinaryColor::On, 1))
            .draw(&mut slow)
            .unwrap();
    }
    assert_eq!(fast.inner.pixels, slow.pixels);
    assert!(slow.lit() > 1000);
}

/// Diagonal curves: every pixel the fast path lights is within half a pixel (on the minor
/// axis) of an f64 line through the same rounded ends, and each segment's ends are lit.
#[test]
fn diagonal_runs_stay_on_the_line() {
    let snowflake = koch_snowflake();
    let mut target = Counting::new(Bitmap::new(200, 200));
    let drawing = LSystem::new(&snowflake, 3)
        .fit(target.bounding_box(), &[BinaryColor::On])
        .unwrap();
    drawing.draw(&mut target).unwrap();
    assert_eq!(target.draw_iter_pixels, 0);
    let ends: Vec<(Point, Point)> = Segments::starting(&snowflake, 3, drawing.start())
        .unwrap()
        .map(|s| {
            let s = s.unwrap();
            (pixel(s.start), pixel(s.end))
        })
        .collect();
    let near = |p: Point| {
        ends.iter().any(|&(a, b)| {
            let (dx, dy) = (f64::from(b.x - a.x), f64::from(b.y - a.y));
            let (px, py) = (f64::from(p.x - a.x), f64::from(p.y - a.y));
            let t = ((px * dx + py * dy) / (dx * dx + dy * dy).max(1e-12)).clamp(0.0, 1.0);
            (px - t * dx).hypot(py - t * dy) <= 0.75
        })
    };
    let bitmap = &target.inner;
    for p in bitmap
        .bounding_box()
        .points()
        .filter(|p| bitmap.get(p.x, p.y))
    {
        assert!(near(p), "{p:?} is off every segment");
    }
    for &(a, b) in &ends {
        assert!(bitmap.get(a.x, a.y) && bitmap.get(b.x, b.y));
    }
}

#[test]
fn walker_state_is_small_and_independent_of_order() {
    use core::mem::size_of;
    let walk = size_of::<Segments<'static, 'static>>();
    // Orders up to 16 with branches 20 deep in at most 1 KiB of RAM.
    assert!(walk <= 1024, "Segments is {walk} bytes");
    // The capacities are in the type, not the order: a deeper walk is a bigger type.
    assert!(size_of::<Segments<'static, 'static, 33, 40>>() > walk);
    println!(
        "Segments<17, 20>: {walk} bytes; Grammar: {} bytes",
        size_of::<Grammar<'static>>()
    );
}

/// Any palette colours an L-system's indices: a gradient gives index i its entry i.
#[test]
fn colour_indices_through_any_palette() {
    use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    use tinyfractal::render::{Colors, Gradient};
    let grammar = Grammar::new(Dialect::Fractint, "FC1FC2F", Angle::Divisions(4)).unwrap();
    let gradient = Gradient::<Rgb888, 4>::new(
        &[Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE, Rgb888::WHITE],
        Rgb888::BLACK,
    )
    .unwrap();
    let system = LSystem::new(&grammar, 0).with_margin(0);
    let area = Rectangle::new(Point::zero(), Size::new(10, 1));
    let mut by_gradient = MockDisplay::<Rgb888>::new();
    let mut by_list = MockDisplay::<Rgb888>::new();
    system
        .fit_with(area, &gradient)
        .unwrap()
        .draw(&mut by_gradient)
        .unwrap();
    let list = [Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE];
    system
        .fit_with(area, Colors::new(&list).unwrap())
        .unwrap()
        .draw(&mut by_list)
        .unwrap();
    by_gradient.assert_eq(&by_list);
    assert_eq!(by_list.get_pixel(Point::new(0, 0)), Some(Rgb888::RED));
    assert_eq!(by_list.get_pixel(Point::new(9, 0)), Some(Rgb888::BLUE));
}

/// The walk's worst case per capacity, as docs/memory.md states it: 8 bytes a level, 32 a
/// saved turtle, and 248 more (on a 64-bit host; less on a 32-bit MCU).
#[test]
fn walker_state_grows_by_its_capacities() {
    use core::mem::size_of;
    let size = |depth: usize, stack: usize| 8 * depth + 32 * stack + 248;
    assert_eq!(
        size_of::<Segments<'static, 'static, 17, 20>>(),
        size(17, 20)
    );
    assert_eq!(
        size_of::<Segments<'static, 'static, 33, 64>>(),
        size(33, 64)
    );
    assert_eq!(
        size_of::<Segments<'static, 'static, 257, 1024>>(),
        size(257, 1024)
    );
}
