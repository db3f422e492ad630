//! Bad input gives typed errors that say where and what, never a panic or a hang.

mod common;

use embedded_graphics::{
    mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*, primitives::Rectangle,
};
use tinyfractal::error::{FitError, ReadError, ReadWarning, WalkError};
use tinyfractal::{
    error::{DrawError, Location},
    lsystem::{Placement, Segments},
    Angle, Dialect, Error, Grammar, LFile, LSystem, Real,
};

fn fixture(name: &str) -> String {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn read_bad(name: &str) -> Error {
    LFile::new(&fixture(name))
        .find("bad")
        .map(|_| ())
        .unwrap_err()
}

const fn at(line: u32, column: u32) -> Location {
    Location { line, column }
}

#[test]
fn file_errors_carry_their_place() {
    let cases = [
        (
            "error-unbalanced.l",
            Error::Read(ReadError::UnbalancedBracket { at: at(4, 6) }),
        ),
        (
            "error-unclosed.l",
            Error::Read(ReadError::UnclosedBracket { at: at(4, 6) }),
        ),
        (
            "error-missing-axiom.l",
            Error::Read(ReadError::MissingAxiom),
        ),
        (
            "error-missing-angle.l",
            Error::Read(ReadError::MissingAngle),
        ),
        (
            "error-angle.l",
            Error::Read(ReadError::AngleOutOfRange {
                value: 0,
                max: 64,
                at: at(2, 9),
            }),
        ),
        (
            "error-number.l",
            Error::Read(ReadError::NumberOutOfRange {
                symbol: 'c',
                at: at(4, 6),
            }),
        ),
        (
            "error-unterminated.l",
            Error::Read(ReadError::UnterminatedEntry { at: at(1, 1) }),
        ),
        (
            "error-reserved.l",
            Error::Read(ReadError::ReservedRule {
                symbol: '+',
                at: at(4, 3),
            }),
        ),
        (
            "error-extra-text.l",
            Error::Read(ReadError::ExtraText { at: at(4, 9) }),
        ),
        (
            "error-unknown-line.l",
            Error::Read(ReadError::UnknownLine { at: at(4, 3) }),
        ),
    ];
    for (file, expected) in cases {
        assert_eq!(read_bad(file), expected, "{file}");
    }
}

/// Numeric commands without digits take 0, as in Fractint (they were refused).
#[test]
fn numeric_commands_without_digits_take_zero() {
    let text = fixture("no-digits.l");
    let file = LFile::new(&text);
    let segments = |name: &str, order: u32| -> Vec<_> {
        Segments::new(&file.find(name).unwrap(), order)
            .unwrap()
            .map(Result::unwrap)
            .collect()
    };
    for order in 0..3 {
        assert_eq!(
            segments("NoDigits", order),
            segments("ExplicitZeros", order)
        );
    }
    // `@` alone: a step of 0, so the segments after it are points.
    let steps = segments("ZeroStep", 0);
    assert_eq!(steps.len(), 3);
    assert_ne!(steps[0].start, steps[0].end);
    assert!(steps[1..]
        .iter()
        .all(|s| s.start == s.end && s.start == steps[0].end));
}

/// A missing `}` before a `NAME {` line: the broken entry says so with both lines, and the
/// next entry is still listed and drawn as written.
#[test]
fn a_missing_brace_before_the_next_entry_is_reported_with_both_lines() {
    let text = fixture("error-missing-brace.l");
    let file = LFile::new(&text);
    let names: Vec<&str> = file.entries().map(|e| e.unwrap().name()).collect();
    assert_eq!(names, ["Bad", "Next"]);
    let error = read_bad("error-missing-brace.l");
    assert_eq!(
        error,
        Error::Read(ReadError::EntryRunsIntoNext { entry: 1, next: 6 })
    );
    let message = error.to_string();
    assert!(
        message.contains("line 1")
            && message.contains("line 6")
            && message.contains("is a `}` missing"),
        "{message}"
    );
    let next = file.find("next").unwrap();
    let clean = Grammar::new(Dialect::Fractint, "F--F--F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F--F+F")
        .unwrap();
    assert!(Segments::new(&next, 3)
        .unwrap()
        .eq(Segments::new(&clean, 3).unwrap()));
}

/// What Fractint accepted draws as Fractint drew it (the last `Axiom` and `Angle` count;
/// `U {` rewrites `U` to `{`; a lone `{` is a rule for `{`), and each is a warning.
#[test]
fn what_fractint_accepted_draws_the_same_with_warnings() {
    let text = fixture("warn-missing-brace.l");
    let entry = LFile::new(&text).entry("bad").unwrap();
    let warnings: Vec<ReadWarning> = entry.warnings().collect();
    assert_eq!(
        warnings,
        [
            ReadWarning::BraceRule {
                symbol: 'U',
                line: 7
            },
            ReadWarning::RepeatedAngle { first: 3, again: 8 },
            ReadWarning::RepeatedAxiom { first: 4, again: 9 },
            ReadWarning::LoneBrace { line: 10 },
        ]
    );
    for warning in &warnings {
        let message = warning.to_string();
        assert!(message.contains("is a `}` missing"), "{message}");
    }
    assert!(
        warnings[1].to_string().contains("line 8") && warnings[1].to_string().contains("line 3")
    );
    // Fractint's reading, written out: the last angle and axiom, and the one F rule.
    let fractint = Grammar::new(Dialect::Fractint, "F--F--F", Angle::Divisions(6))
        .unwrap()
        .with_rule('F', "F+F-F")
        .unwrap();
    let read = entry.grammar().unwrap();
    for order in 0..4 {
        assert!(
            Segments::new(&read, order)
                .unwrap()
                .eq(Segments::new(&fractint, order).unwrap()),
            "order {order}"
        );
    }
    // A clean entry has no warnings.
    let small = fixture("small.l");
    for entry in LFile::new(&small).entries() {
        assert_eq!(entry.unwrap().warnings().count(), 0);
    }
}

/// Files that are not `.l` files, or numbers that are not divisions, are named as such.
#[test]
fn wrong_kinds_of_input_are_recognised() {
    assert_eq!(
        read_bad("error-angle-fraction.l"),
        Error::Read(ReadError::AngleNotWhole { at: at(2, 9) })
    );
    assert!(read_bad("error-angle-fraction.l")
        .to_string()
        .contains("not a whole number"));
    assert_eq!(
        read_bad("error-ifs.l"),
        Error::Read(ReadError::RowOfNumbers { line: 2 })
    );
    assert!(read_bad("error-ifs.l").to_string().contains("IFS file"));
    assert_eq!(
        read_bad("error-old-mac.l"),
        Error::Read(ReadError::OldMacLineEndings)
    );
    let text = fixture("error-old-mac.l");
    let first = LFile::new(&text).entries().next().unwrap();
    assert_eq!(first, Err(Error::Read(ReadError::OldMacLineEndings)));
    // The same file with CRLF line endings reads.
    let crlf = text.replace('\r', "\r\n");
    assert!(LFile::new(&crlf).find("bad").is_ok());
}

#[test]
fn messages_say_where_and_how_to_fix() {
    let message = read_bad("error-unbalanced.l").to_string();
    assert_eq!(
        message,
        "unbalanced `]` at line 4, column 6: remove it or add the matching `[` before it"
    );
    let message = read_bad("error-number.l").to_string();
    assert!(message.contains("`c` at line 4, column 6"), "{message}");
    let deep = Error::Walk(WalkError::StackTooDeep { capacity: 20 }).to_string();
    assert!(
        deep.contains("20 levels") && deep.contains("raise the STACK capacity"),
        "{deep}"
    );
}

#[test]
fn unknown_system_name() {
    let text = fixture("small.l");
    assert_eq!(
        LFile::new(&text).find("nope").map(|_| ()),
        Err(Error::Read(ReadError::UnknownSystem))
    );
    // `comment` blocks are not systems.
    assert_eq!(
        LFile::new(&text).find("comment").map(|_| ()),
        Err(Error::Read(ReadError::UnknownSystem))
    );
}

#[test]
fn inline_grammar_errors() {
    let new = |axiom| Grammar::new(Dialect::Abop, axiom, Angle::Divisions(4));
    // An empty axiom is a system that draws nothing.
    assert_eq!(Segments::new(&new("  ").unwrap(), 5).unwrap().count(), 0);
    assert_eq!(
        new("F]").map(|_| ()),
        Err(Error::Read(ReadError::UnbalancedBracket {
            at: Location::column(2)
        }))
    );
    assert_eq!(
        new("Fé").map(|_| ()),
        Err(Error::Read(ReadError::NonAsciiSymbol {
            at: Location::column(2)
        }))
    );
    for divisions in [0, 65, 1000] {
        assert!(matches!(
            Grammar::new(Dialect::Abop, "F", Angle::Divisions(divisions)),
            Err(Error::Read(ReadError::AngleOutOfRange { .. }))
        ));
    }
    let grammar = new("F").unwrap();
    assert!(matches!(
        grammar.clone().with_rule('[', "F"),
        Err(Error::Read(ReadError::ReservedRule { .. }))
    ));
    // One more rule line than fits.
    let mut many = Ok(grammar);
    for _ in 0..=Grammar::MAX_RULES {
        many = many.and_then(|g| g.with_rule('X', "F"));
    }
    assert!(matches!(
        many,
        Err(Error::Read(ReadError::TooManyRules {
            max: Grammar::MAX_RULES,
            ..
        }))
    ));
}

#[test]
fn too_deep_nesting_is_a_typed_error() {
    let grammar = Grammar::new(Dialect::Abop, "F", Angle::Divisions(4))
        .unwrap()
        .with_rule('F', "[[F]]")
        .unwrap();
    // Each order nests two more branches: order 10 needs 20 levels, order 11 needs 22.
    assert!(Segments::new(&grammar, 10).unwrap().all(|s| s.is_ok()));
    let errors: Vec<Error> = Segments::new(&grammar, 11)
        .unwrap()
        .filter_map(Result::err)
        .collect();
    assert_eq!(
        errors,
        vec![Error::Walk(WalkError::StackTooDeep { capacity: 20 })]
    );
    // A larger stack in the type lifts the limit.
    let deep = Segments::<'_, '_, 17, 32>::with_capacity(&grammar, 11, Default::default()).unwrap();
    assert!(deep.into_iter().all(|s| s.is_ok()));
}

#[test]
fn absurd_orders_fail_fast() {
    let grammar = Grammar::new(Dialect::Abop, "F", Angle::Divisions(4))
        .unwrap()
        .with_rule('F', "F+F-F-FF+F+F-F")
        .unwrap();
    assert_eq!(
        Segments::new(&grammar, 1000).map(|_| ()),
        Err(Error::Walk(WalkError::OrderTooHigh {
            order: 1000,
            max: 16
        }))
    );
    // Order 16 would be 14^16 symbols; the budget stops it.
    let started = std::time::Instant::now();
    let result = LSystem::new(&grammar, 16).with_budget(1_000_000).fit(
        Rectangle::new(Point::zero(), Size::new(64, 64)),
        &[BinaryColor::On],
    );
    assert_eq!(
        result.map(|_| ()),
        Err(Error::Walk(WalkError::BudgetExhausted {
            budget: 1_000_000
        }))
    );
    assert!(
        started.elapsed().as_secs() < 5,
        "the budget must bound the time"
    );
}

#[test]
fn zero_size_targets_and_empty_palettes() {
    let grammar = Grammar::new(Dialect::Abop, "F+F", Angle::Divisions(4)).unwrap();
    let system = LSystem::new(&grammar, 0);
    for size in [Size::new(0, 10), Size::new(10, 0), Size::zero()] {
        assert_eq!(
            system
                .fit(Rectangle::new(Point::zero(), size), &[BinaryColor::On])
                .map(|_| ()),
            Err(Error::Fit(FitError::ZeroSizeTarget))
        );
    }
    // "F+F" with 90° turns: one unit across and one up. One pixel across an axis it
    // extends along is too small; an N×1 target holds a horizontal line (the turtle starts
    // heading right).
    for size in [Size::new(1, 10), Size::new(10, 1), Size::new(1, 1)] {
        let fitted = system.fit(Rectangle::new(Point::zero(), size), &[BinaryColor::On]);
        let error = Error::Fit(FitError::TargetTooSmall {
            width: size.width,
            height: size.height,
        });
        assert_eq!(fitted.map(|_| ()), Err(error));
        assert!(error.to_string().contains("too small"), "{error}");
    }
    let level = Grammar::new(Dialect::Abop, "FF", Angle::Divisions(4)).unwrap();
    let mut display = MockDisplay::<BinaryColor>::new();
    LSystem::new(&level, 0)
        .fit(
            Rectangle::new(Point::zero(), Size::new(10, 1)),
            &[BinaryColor::On],
        )
        .unwrap()
        .draw(&mut display)
        .unwrap();
    // A line across (the fit keeps a margin where the target can afford it).
    let drawn = display.affected_area().size;
    assert!(drawn.height == 1 && drawn.width >= 6, "{drawn:?}");
    let no_colours: &[BinaryColor] = &[];
    assert_eq!(
        system
            .fit(Rectangle::new(Point::zero(), Size::new(8, 8)), no_colours)
            .map(|_| ()),
        Err(Error::Fit(FitError::EmptyPalette))
    );
}

/// A system that draws nothing at an order (rules that erase everything) is a valid, empty
/// picture: `fit` gives a drawing that draws nothing, with or without the table; only
/// `bounds` says there is nothing to measure.
#[test]
fn a_picture_of_nothing_is_valid() {
    let text = fixture("draws-nothing.l");
    let file = LFile::new(&text);
    for name in ["Erased", "Turns", "EmptyAxiom"] {
        let grammar = file.find(name).unwrap();
        let system = LSystem::new(&grammar, 3);
        let mut cells = vec![tinyfractal::lsystem::Cell::default(); 1024];
        for drawing in [
            system
                .fit(
                    Rectangle::new(Point::zero(), Size::new(8, 8)),
                    &[BinaryColor::On],
                )
                .unwrap(),
            system
                .fit_in(
                    Rectangle::new(Point::zero(), Size::new(8, 8)),
                    tinyfractal::render::Colors::new(&[BinaryColor::On]).unwrap(),
                    &mut cells,
                )
                .unwrap(),
        ] {
            let mut display = MockDisplay::<BinaryColor>::new();
            let stats = drawing.draw(&mut display).unwrap();
            assert_eq!(stats.segments, 0, "{name}");
            assert_eq!(display.affected_area().size, Size::zero(), "{name}");
            assert_eq!(drawing.bounding_box().size, Size::zero(), "{name}");
        }
        assert_eq!(system.bounds(), Err(Error::Fit(FitError::EmptyDrawing)));
    }
    // At order 0 `Erased` draws its axiom.
    let grammar = file.find("Erased").unwrap();
    assert_eq!(Segments::new(&grammar, 0).unwrap().count(), 2);
}

#[test]
fn fixed_point_overflow_and_underflow_are_reported() {
    let line = Grammar::new(Dialect::Abop, "FFFF", Angle::Divisions(4)).unwrap();
    let huge = Placement {
        origin: Point::zero(),
        step: Real::from_int(1 << 30),
        turns: 0,
    };
    assert_eq!(
        LSystem::new(&line, 0)
            .place(huge, &[BinaryColor::On])
            .map(|_| ()),
        Err(Error::Walk(WalkError::Overflow))
    );
    let shrinking = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(4))
        .unwrap()
        .with_rule('f', "@.1F")
        .unwrap();
    let errors: Vec<_> = Segments::new(&shrinking, 12)
        .unwrap()
        .filter_map(Result::err)
        .collect();
    assert_eq!(errors, vec![Error::Walk(WalkError::StepUnderflow)]);
    // A step growing 8 times an order leaves I32F32 turtle units at order 11 (8^11 = 2^33):
    // reported, not drawn wrong (Fractint's Island1 grows its moves like this).
    let growing = Grammar::new(Dialect::Fractint, "F", Angle::Divisions(4))
        .unwrap()
        .with_rule('f', "@8F")
        .unwrap();
    assert_eq!(
        Segments::new(&growing, 11).unwrap().find_map(Result::err),
        Some(Error::Walk(WalkError::Overflow))
    );
    // The fit measures it in a smaller unit and draws it, at order 6 and at 11 alike
    // (tests/scaling.rs has the wider systems), as one line across.
    let area = Rectangle::new(Point::zero(), Size::new(64, 64));
    for order in [6, 11, 60] {
        let fitted = LSystem::<'_, '_, 100, 20>::with_capacity(&growing, order)
            .fit(area, &[BinaryColor::On])
            .unwrap();
        // Margins of 2 leave x 2..=61; the centre row 31.5 rounds half away from zero to 32.
        assert_eq!(
            fitted.bounding_box(),
            Rectangle::new(Point::new(2, 32), Size::new(60, 1)),
            "order {order}"
        );
    }
    // Past 2²⁰⁰ of growth (8⁸⁰ = 2²⁴⁰) even the smallest unit overflows: said, not drawn wrong.
    let fitted =
        LSystem::<'_, '_, 100, 20>::with_capacity(&growing, 80).fit(area, &[BinaryColor::On]);
    assert_eq!(fitted.map(|_| ()), Err(Error::Walk(WalkError::Overflow)));
}

/// Steps that `@` shrinks below what a turtle unit resolves still fit and draw right: the
/// fit measures in a larger unit. Checked against the spiral's box worked out in f64.
#[test]
fn steps_shrunk_below_the_unit_still_draw_right() {
    let text = fixture("tiny-steps.l");
    let grammar = LFile::new(&text).find("spiral").unwrap();
    let order = 30;
    // In turtle units the walk cannot measure it.
    let system = LSystem::<'_, '_, 32, 20>::with_capacity(&grammar, order);
    assert_eq!(system.bounds(), Err(Error::Walk(WalkError::StepUnderflow)));
    let area = Rectangle::new(Point::zero(), Size::new(101, 61));
    let drawing = system.fit(area, &[BinaryColor::On]).unwrap();
    // The model: `(F+@.5)^30 A`, segment k of length 2^-k heading k quarter turns left.
    let (mut x, mut y) = (0.0f64, 0.0f64);
    let (mut min, mut max) = ((0.0f64, 0.0f64), (0.0f64, 0.0f64));
    for k in 0..order {
        let length = 0.5f64.powi(k as i32);
        match k % 4 {
            0 => x += length,
            1 => y += length,
            2 => x -= length,
            _ => y -= length,
        }
        min = (min.0.min(x), min.1.min(y));
        max = (max.0.max(x), max.1.max(y));
    }
    // Margins of 2: 96 by 56 pixels for the box, the tighter axis wins.
    let scale = (96.0 / (max.0 - min.0)).min(56.0 / (max.1 - min.1));
    let step = drawing.start().step.to_f64();
    assert!(
        (step - scale).abs() < 1e-6 * scale,
        "step {step}, model {scale}"
    );
    let mut frame = common::Bitmap::new(101, 61);
    let stats = drawing.draw(&mut frame).unwrap();
    assert_eq!(stats.segments, u64::from(order));
    assert_eq!(frame.outside, 0);
}

/// Branches nested deeper than the MCU default (20 saved turtles) are a typed error naming
/// the capacity there, and draw with a larger one (the CLI's is 1024).
#[test]
fn deep_nesting_needs_a_larger_stack_not_a_different_file() {
    let text = fixture("deep-nesting.l");
    let grammar = LFile::new(&text).find("deeptree").unwrap();
    let area = Rectangle::new(Point::zero(), Size::new(64, 64));
    assert_eq!(
        LSystem::new(&grammar, 2)
            .fit(area, &[BinaryColor::On])
            .map(|_| ()),
        Err(Error::Walk(WalkError::StackTooDeep { capacity: 20 }))
    );
    let drawing = LSystem::<'_, '_, 17, 64>::with_capacity(&grammar, 2)
        .fit(area, &[BinaryColor::On])
        .unwrap();
    let stats = drawing.draw(&mut common::Bitmap::new(64, 64)).unwrap();
    assert_eq!(stats.max_stack, 60);
}

/// A target that fails on its first write: the error comes back out, typed.
struct FailingTarget;

impl OriginDimensions for FailingTarget {
    fn size(&self) -> Size {
        Size::new(32, 32)
    }
}

impl DrawTarget for FailingTarget {
    type Color = BinaryColor;
    type Error = &'static str;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        _: I,
    ) -> Result<(), &'static str> {
        Err("bus error")
    }
}

#[test]
fn target_errors_propagate() {
    let grammar = Grammar::new(Dialect::Abop, "F+F", Angle::Divisions(4)).unwrap();
    let drawing = LSystem::new(&grammar, 0)
        .fit(FailingTarget.bounding_box(), &[BinaryColor::On])
        .unwrap();
    assert_eq!(drawing.draw(&mut FailingTarget), Err("bus error"));
    assert_eq!(
        drawing.try_draw(&mut FailingTarget),
        Err(DrawError::Target("bus error"))
    );
    // A mock display rejects nothing here: the same drawing succeeds.
    let mut display = MockDisplay::<BinaryColor>::new();
    display.set_allow_overdraw(true);
    assert!(drawing.draw(&mut display).is_ok());
}
