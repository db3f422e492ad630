//! The expansion table against full walks: the same box, the same fit, the same pixels and
//! the same statistics, for every shipped and corpus system the table covers; and orders
//! no walk could finish.

mod common;

use common::{corpus_file, koch_snowflake, shipped_file, Frame, SHIPPED_L_FILES};
use embedded_graphics::{
    pixelcolor::{Rgb888, RgbColor},
    prelude::*,
    primitives::Rectangle,
};
use tinyfractal::{
    lsystem::{cells_needed, Cell, WalkStats},
    render::Colors,
    Error, Grammar, LFile, LSystem,
};

const PALETTE: [Rgb888; 4] = [Rgb888::WHITE, Rgb888::RED, Rgb888::GREEN, Rgb888::BLUE];

/// A picture and the statistics of drawing it.
fn drawn<D: Drawable<Color = Rgb888, Output = WalkStats>>(
    drawing: &D,
    size: Size,
) -> (Frame<Rgb888>, WalkStats) {
    let mut frame = Frame::filled(size, Rgb888::BLACK);
    let stats = drawing.draw(&mut frame).unwrap();
    (frame, stats)
}

/// Fits `grammar` at `order` by walking and through the table; both must agree on
/// everything. `false` if the table does not cover the system.
fn table_agrees_with_walk(grammar: &Grammar<'_>, order: u32, label: &str) -> bool {
    let Some(needed) = cells_needed(grammar, order) else {
        return false;
    };
    let system = LSystem::<'_, '_, 17, 64>::with_capacity(grammar, order).with_budget(u64::MAX);
    let area = Rectangle::new(Point::new(4, 3), Size::new(150, 110));
    let mut cells = vec![Cell::default(); needed];
    let walked = system.fit(area, &PALETTE);
    let tabled = system.fit_in(area, Colors::new(&PALETTE).unwrap(), &mut cells);
    let (walked, tabled) = match (walked, tabled) {
        (Ok(walked), Ok(tabled)) => (walked, tabled),
        (Err(a), Err(b)) => {
            assert_eq!(a, b, "{label}: the same error");
            return true;
        }
        (a, b) => panic!("{label}: walk {:?}, table {:?}", a.err(), b.err()),
    };
    // The same box means the same fit: start and step equal.
    assert_eq!(walked.start(), tabled.start(), "{label}: fitted start");
    assert_eq!(walked.bounding_box(), tabled.bounding_box(), "{label}: box");
    // The whole target, and one that clips the picture (culling).
    for size in [Size::new(160, 120), Size::new(90, 70)] {
        let (walk_frame, walk_stats) = drawn(&walked, size);
        let (table_frame, table_stats) = drawn(&tabled, size);
        assert_eq!(walk_stats, table_stats, "{label}: stats at {size:?}");
        // Inside the target the pictures are the same (culling sends fewer pixels outside
        // it, which the target clips).
        let differ: Vec<_> = (0..size.height as i32)
            .flat_map(|y| (0..size.width as i32).map(move |x| (x, y)))
            .filter(|&(x, y)| walk_frame.pixel(x, y) != table_frame.pixel(x, y))
            .take(5)
            .collect();
        assert!(
            differ.is_empty(),
            "{label}: pixels differ at {size:?}: {differ:?}"
        );
    }
    true
}

/// The highest order up to `max` whose full walk stays under `segments`.
fn orders<'g>(grammar: &'g Grammar<'_>, max: u32, segments: u64) -> impl Iterator<Item = u32> + 'g {
    (0..=max).take_while(move |&order| {
        LSystem::<'_, '_, 17, 64>::with_capacity(grammar, order)
            .with_budget(segments * 4)
            .segments(Default::default())
            .map(|walk| {
                let first: Vec<_> = walk.take(segments as usize + 1).collect();
                first.len() <= segments as usize && first.iter().all(Result::is_ok)
            })
            .unwrap_or(false)
    })
}

fn check_file(text: &str, file: &str, segments: u64) -> usize {
    let mut covered = 0;
    for entry in LFile::new(text).entries() {
        let entry = entry.unwrap();
        let Ok(grammar) = entry.grammar() else {
            continue;
        };
        let mut any = false;
        for order in orders(&grammar, 6, segments) {
            any |= table_agrees_with_walk(
                &grammar,
                order,
                &format!("{file}: {} order {order}", entry.name()),
            );
        }
        covered += usize::from(any);
    }
    covered
}

#[test]
fn the_table_agrees_with_full_walks_on_shipped_files() {
    let mut covered = 0;
    for file in SHIPPED_L_FILES {
        covered += check_file(&shipped_file(file), file, 20_000);
    }
    assert!(covered >= 15, "{covered} systems covered");
}

#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn the_table_agrees_with_full_walks_on_the_corpus() {
    let mut covered = 0;
    for file in ["fractint.l", "penrose.l", "tiling.l"] {
        covered += check_file(&corpus_file(file), file, 20_000);
    }
    println!("{covered} corpus systems covered by the table");
    assert!(covered >= 60, "{covered} systems covered");
}

/// Free angles whose turns reach few headings exactly (22.5°, 45°, 90°) go through the
/// table too; others (25.7°, 60° as a binary angle) do not.
#[test]
fn free_angles_of_power_of_two_divisions_agree_with_walks() {
    use tinyfractal::{Angle, Dialect, Real};
    type Rules = &'static [(char, &'static str)];
    let systems: [(&str, Rules, &str); 4] = [
        ("X", &[('X', "F-[[X]+X]+F[+FX]-X"), ('F', "FF")], "22.5"),
        ("F", &[('F', "FF-[-F+F+F]+[+F-F-F]")], "22.5"),
        ("F+F+F+F", &[('F', "F+F-F-FF+F+F-F")], "90"),
        ("F", &[('F', "F+F--F|F+F")], "45"),
    ];
    for (axiom, rules, degrees) in systems {
        let mut grammar =
            Grammar::new(Dialect::Abop, axiom, Angle::parse_degrees(degrees).unwrap()).unwrap();
        for &(symbol, body) in rules {
            grammar.add_rule(symbol, body).unwrap();
        }
        assert!(cells_needed(&grammar, 3).is_some(), "{degrees}° is covered");
        for order in 0..5 {
            assert!(table_agrees_with_walk(
                &grammar,
                order,
                &format!("{axiom} {degrees}° order {order}")
            ));
        }
    }
    for degrees in ["25.7", "60", "20"] {
        let grammar = Grammar::new(
            Dialect::Abop,
            "F",
            Angle::Degrees(Real::parse_decimal(degrees).unwrap()),
        )
        .unwrap()
        .with_rule('F', "F+F")
        .unwrap();
        assert_eq!(cells_needed(&grammar, 3), None, "{degrees}°");
    }
}

/// Koch1 at order 16: 3·4¹⁶ ≈ 1.3·10¹⁰ segments, drawn at 320×240 from the table, with
/// the true segment count.
#[test]
fn koch_at_order_16_draws_from_the_table() {
    let grammar = koch_snowflake();
    let order = 16;
    let mut cells = vec![Cell::default(); cells_needed(&grammar, order).unwrap()];
    let drawing = LSystem::new(&grammar, order)
        .fit_in(
            Rectangle::new(Point::zero(), Size::new(320, 240)),
            Colors::new(&PALETTE).unwrap(),
            &mut cells,
        )
        .unwrap();
    let (frame, stats) = drawn(&drawing, Size::new(320, 240));
    assert_eq!(stats.segments, 3 * 4u64.pow(16));
    assert_eq!(stats.max_depth, 17);
    // The snowflake's outline: a closed curve, drawn as pixels along it.
    let lit = frame.pixels.iter().filter(|&&c| c != Rgb888::BLACK).count();
    assert!(lit > 1000, "{lit} pixels");
    // Without the table the walk gives up at its budget.
    let walked = LSystem::new(&grammar, order)
        .fit(Rectangle::new(Point::zero(), Size::new(320, 240)), &PALETTE);
    assert!(matches!(
        walked,
        Err(Error::Walk(
            tinyfractal::error::WalkError::BudgetExhausted { .. }
        ))
    ));
}

/// The table's worst case per cell, as the docs state it.
#[test]
fn a_cell_is_at_most_96_bytes() {
    let bytes = size_of::<Cell>();
    println!("Cell: {bytes} bytes");
    assert!(bytes <= 96, "{bytes}");
    // Koch1 at order 16: one symbol with a rule, 16 levels, 6 headings, one sense (no `!`).
    assert_eq!(cells_needed(&koch_snowflake(), 16), Some(96));
}
