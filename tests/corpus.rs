//! Every system in Fractint's own `.l` files (shared/corpus) parses and draws. Built as
//! ignored where the corpus is missing (see build.rs), except under `CI=true`.

use std::path::PathBuf;

use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::error::FitError;
use tinyfractal::{Error, LFile, LSystem};

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("TINYFRACTAL_CORPUS_DIR")).join("fractint")
}

fn read(name: &str) -> String {
    let path = corpus_dir().join(name);
    // Fractint's files are 8-bit text; they are ASCII, but read them leniently anyway.
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    bytes.iter().map(|&b| char::from(b)).collect()
}

/// The highest order (up to 12) that walks within `budget` symbols, and what stopped the
/// search (a budget, a stack or a range limit: all typed errors, none a panic).
fn meaningful_order(grammar: &tinyfractal::Grammar<'_>) -> (u32, Option<Error>) {
    let budget = 300_000;
    let mut best = 0;
    for order in 0..=12 {
        match LSystem::new(grammar, order).with_budget(budget).bounds() {
            Ok(_) => best = order,
            // Systems whose axiom is only non-drawing symbols draw from order 1 on.
            Err(Error::Fit(FitError::EmptyDrawing)) => {}
            Err(limit) => return (best, Some(limit)),
        }
    }
    (best, None)
}

#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn every_corpus_system_parses_and_draws() {
    let files = [("fractint.l", 69), ("penrose.l", 13), ("tiling.l", 8)];
    let mut total = 0;
    let mut report = String::new();
    for (file, expected) in files {
        let text = read(file);
        let lfile = LFile::new(&text);
        let entries: Vec<_> = lfile
            .entries()
            .collect::<Result<_, _>>()
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(entries.len(), expected, "{file}: systems found");
        for entry in entries {
            let name = entry.name();
            let grammar = entry
                .grammar()
                .unwrap_or_else(|e| panic!("{file}: {name}: {e}"));
            let (order, limit) = meaningful_order(&grammar);
            assert!(order >= 2, "{name}: only order {order} fits the budget");
            let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(320, 240));
            let drawing = LSystem::new(&grammar, order)
                .fit(
                    display.bounding_box(),
                    &[Rgb888::WHITE, Rgb888::CYAN, Rgb888::YELLOW],
                )
                .unwrap_or_else(|e| panic!("{name} at order {order}: {e}"));
            assert!(
                display
                    .bounding_box()
                    .contains(drawing.bounding_box().top_left)
                    && display
                        .bounding_box()
                        .contains(drawing.bounding_box().bottom_right().unwrap_or_default()),
                "{name}: fitted picture {:?} leaves the display",
                drawing.bounding_box()
            );
            let stats = drawing.draw(&mut display).unwrap_or_default();
            let lit = display
                .bounding_box()
                .points()
                .filter(|&p| display.get_pixel(p) != Rgb888::BLACK)
                .count();
            assert!(stats.segments > 0, "{name}: no segments");
            assert!(lit >= 20, "{name} at order {order}: only {lit} pixels lit");
            report.push_str(&format!(
                "{file:<11} {name:<20} order {order:>2} {:>7} segments {lit:>6} px  {}\n",
                stats.segments,
                limit.map(|e| e.to_string()).unwrap_or_default()
            ));
            total += 1;
        }
    }
    println!("{report}");
    assert_eq!(total, 90);
}
