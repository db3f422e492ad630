//! Properties over random input: reading and drawing never panic, never run past their
//! budget, and whatever is drawn stays inside the fitted bounding box.

mod common;

use common::Bitmap;
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use tinyfractal::error::ReadError;
use tinyfractal::{lsystem::Segments, Angle, Dialect, Error, Grammar, LFile, LSystem};

const ALPHABET: &str = "FfGgDdMmXYAB+-|!\\/@IQC<>[]0123456789.=; \n{}aXx";

fn text(max: usize) -> impl Strategy<Value = String> {
    proptest::collection::vec(
        proptest::sample::select(ALPHABET.chars().collect::<Vec<_>>()),
        0..max,
    )
    .prop_map(|chars| chars.into_iter().collect())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Any text read as a `.l` file, and every entry in it drawn, gives Ok or a typed error.
    #[test]
    fn any_l_file_reads_and_draws_without_panicking(body in text(120), name in "[a-z]{0,6}") {
        let file = format!("{name} {{\n{body}\n}}\n");
        for entry in LFile::new(&file).entries() {
            let Ok(entry) = entry else { continue };
            let Ok(grammar) = entry.grammar() else { continue };
            for order in [0, 1, 3, 16] {
                let _ = LSystem::new(&grammar, order)
                    .with_budget(20_000)
                    .fit(Rectangle::new(Point::zero(), Size::new(40, 30)), &[BinaryColor::On])
                    .map(|drawing| drawing.draw(&mut Bitmap::new(40, 30)));
            }
        }
    }

    /// Random inline systems: the walk respects its budget exactly, and a fitted drawing
    /// touches only pixels inside its bounding box, which lies inside the target.
    #[test]
    fn fitted_drawings_stay_inside(axiom in text(12), f_rule in text(16), x_rule in text(16),
                                   divisions in 1u16..=64, order in 0u32..6) {
        let grammar = Grammar::new(Dialect::Fractint, &axiom, Angle::Divisions(divisions))
            .and_then(|g| g.with_rule('F', &f_rule))
            .and_then(|g| g.with_rule('X', &x_rule));
        let Ok(grammar) = grammar else { return Ok(()) };
        let budget = 50_000;
        let mut walk = Segments::new(&grammar, order).unwrap().with_budget(budget);
        for step in walk.by_ref() {
            if let Err(error) = step {
                prop_assert!(!matches!(error, Error::Read(ReadError::UnbalancedBracket { .. })), "bodies were checked");
            }
        }
        prop_assert!(walk.stats().symbols <= budget);

        let area = Rectangle::new(Point::new(3, 2), Size::new(50, 40));
        if let Ok(drawing) = LSystem::new(&grammar, order).with_budget(budget).fit(area, &[BinaryColor::On]) {
            let mut bitmap = Bitmap::new(60, 50);
            drawing.draw(&mut bitmap).unwrap();
            let bounds = drawing.bounding_box();
            prop_assert!(area.contains(bounds.top_left));
            // An empty picture has an empty box, and draws nothing.
            if let Some(corner) = bounds.bottom_right() {
                prop_assert!(area.contains(corner));
            }
            for p in bitmap.bounding_box().points() {
                if bitmap.get(p.x, p.y) {
                    prop_assert!(bounds.contains(p), "{p:?} outside {bounds:?}");
                }
            }
        }
    }
}

/// Random systems through the expansion table and by walking: the same outcome (error or
/// fit), the same pixels, the same statistics.
mod table {
    use super::*;
    use tinyfractal::{
        lsystem::{cells_needed, Cell},
        render::Colors,
    };

    const BODY: &str = "FFFGG++--|![]XYAB";

    fn body(max: usize) -> impl Strategy<Value = String> {
        proptest::collection::vec(
            proptest::sample::select(BODY.chars().collect::<Vec<_>>()),
            0..max,
        )
        .prop_map(|chars| chars.into_iter().collect::<String>())
        .prop_filter("balanced brackets", |s| {
            let mut depth = 0i32;
            s.chars().all(|c| {
                depth += match c {
                    '[' => 1,
                    ']' => -1,
                    _ => 0,
                };
                depth >= 0
            }) && depth == 0
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

        #[test]
        fn the_table_and_the_walk_agree(axiom in body(8), x in body(12), y in body(12),
                                        divisions in 1u16..=16, order in 0u32..5,
                                        width in 8u32..60, height in 8u32..60) {
            let grammar = Grammar::new(Dialect::Fractint, &axiom, Angle::Divisions(divisions))
                .and_then(|g| g.with_rule('X', &x))
                .and_then(|g| g.with_rule('Y', &y));
            let Ok(grammar) = grammar else { return Ok(()) };
            let needed = cells_needed(&grammar, order).unwrap();
            let mut cells = vec![Cell::default(); needed];
            let system = LSystem::new(&grammar, order).with_budget(200_000);
            let area = Rectangle::new(Point::new(1, 2), Size::new(width, height));
            let palette = [BinaryColor::On];
            let walked = system.fit(area, &palette);
            let tabled = system.fit_in(area, Colors::new(&palette).unwrap(), &mut cells);
            match (walked, tabled) {
                (Ok(walked), Ok(tabled)) => {
                    prop_assert_eq!(walked.start(), tabled.start());
                    prop_assert_eq!(walked.bounding_box(), tabled.bounding_box());
                    // A smaller frame than the area, so that some of it is culled.
                    let (mut a, mut b) = (Bitmap::new(40, 30), Bitmap::new(40, 30));
                    let stats = (walked.draw(&mut a).unwrap(), tabled.draw(&mut b).unwrap());
                    prop_assert_eq!(stats.0, stats.1);
                    prop_assert!(a.pixels == b.pixels, "pixels differ");
                }
                // The walk may stop at its budget where the table does not walk.
                (Err(Error::Walk(tinyfractal::error::WalkError::BudgetExhausted { .. })), _) => {}
                (walked, tabled) => prop_assert_eq!(walked.map(|_| ()), tabled.map(|_| ())),
            }
        }
    }
}
