//! `.lsys` files: ABOP's plants as the book prints them, against the same systems given
//! as inline grammars; derivations; errors with their place.

mod common;

use common::shipped_file;
use tinyfractal::{
    error::{Location, ReadError, Unsupported},
    lsystem::{Segments, Walker},
    Angle, Dialect, Error, Grammar, LsysFile,
};

/// A system as the book prints it: name, axiom, productions, angle in degrees.
type BookSystem = (
    &'static str,
    &'static str,
    &'static [(char, &'static str)],
    &'static str,
);

/// ABOP figure 1.24, typed from the book.
const FIGURE_1_24: [BookSystem; 6] = [
    ("Fig1.24a", "F", &[('F', "F[+F]F[-F]F")], "25.7"),
    ("Fig1.24b", "F", &[('F', "F[+F]F[-F][F]")], "20"),
    ("Fig1.24c", "F", &[('F', "FF-[-F+F+F]+[+F-F-F]")], "22.5"),
    ("Fig1.24d", "X", &[('X', "F[+X]F[-X]+X"), ('F', "FF")], "20"),
    (
        "Fig1.24e",
        "X",
        &[('X', "F[+X][-X]FX"), ('F', "FF")],
        "25.7",
    ),
    (
        "Fig1.24f",
        "X",
        &[('X', "F-[[X]+X]+F[+FX]-X"), ('F', "FF")],
        "22.5",
    ),
];

#[test]
fn the_books_plants_read_as_the_same_systems() {
    let text = shipped_file("data/abop.lsys");
    let file = LsysFile::new(&text);
    let names: Vec<&str> = file.entries().map(|e| e.unwrap().name()).collect();
    assert_eq!(
        names,
        [
            "Fig1.24a",
            "Fig1.24b",
            "Fig1.24c",
            "Fig1.24d",
            "Fig1.24e",
            "Fig1.24f",
            "Algae",
            "Lecture",
            "Fig1.27",
            "Parametric1.10",
            "RowOfTrees",
            "Fig1.31a",
            "Fig1.31b",
            "Fig1.31e",
            "Hilbert3D",
            "Fig1.25",
            "Fig1.25Bare",
            "Fig1.26",
            "Fig2.8a",
            "Topiary",
            "MonopodialTree",
            "SympodialTree",
            "LectureScaled",
            "LectureParametric"
        ]
    );
    for (name, axiom, rules, degrees) in FIGURE_1_24 {
        let read = file.find(name).unwrap();
        let mut inline =
            Grammar::new(Dialect::Abop, axiom, Angle::parse_degrees(degrees).unwrap()).unwrap();
        for &(symbol, body) in rules {
            inline.add_rule(symbol, body).unwrap();
        }
        for order in 0..4 {
            let a: Vec<_> = Segments::new(&read, order).unwrap().collect();
            let b: Vec<_> = Segments::new(&inline, order).unwrap().collect();
            assert_eq!(a, b, "{name} order {order}");
        }
    }
}

#[test]
fn derivations_as_the_lecture_writes_them() {
    let text = shipped_file("data/abop.lsys");
    let file = LsysFile::new(&text);
    let derive = |name: &str, order: u32| -> String {
        let grammar = file.find(name).unwrap();
        Walker::new(&grammar, order)
            .unwrap()
            .map(Result::unwrap)
            .collect()
    };
    let algae: Vec<String> = (0..6).map(|order| derive("Algae", order)).collect();
    assert_eq!(
        algae,
        ["A", "AB", "ABA", "ABAAB", "ABAABABA", "ABAABABAABAAB"]
    );
    // Spaces in a successor are layout.
    assert_eq!(derive("Lecture", 1), "F[-L][+L]");
    assert_eq!(derive("Lecture", 2), "F[-F[-L][+L]][+F[-L][+L]]");
}

fn error_of(text: &str) -> Error {
    let file = LsysFile::new(text);
    match file.entries().next() {
        Some(Ok(entry)) => entry.grammar().map(|_| ()).unwrap_err(),
        Some(Err(error)) => error,
        None => panic!("no entry in {text:?}"),
    }
}

#[test]
fn errors_name_what_and_where() {
    let at = |line, column| Location { line, column };
    let cases: [(&str, Error); 9] = [
        (
            "p {\n  axiom: F\n  angle: 20\n  A < F > B --> FF\n}\n",
            Error::Read(ReadError::Unsupported {
                feature: Unsupported::Context,
                at: at(4, 5),
            }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\n  F : t>1 --> FF\n}\n",
            Error::Read(ReadError::Unsupported {
                feature: Unsupported::Condition,
                at: at(4, 5),
            }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\n  F --> FF : 0.5\n  F --> F\n}\n",
            Error::Read(ReadError::Unsupported {
                feature: Unsupported::SecondProduction,
                at: at(5, 3),
            }),
        ),
        (
            "p {\n  axiom: A(1)\n  angle: 20\n  A(x) --> F\n}\n",
            Error::Read(ReadError::Unsupported {
                feature: Unsupported::Parameters,
                at: at(4, 4),
            }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\n  F --> FF\n  F --> F+F\n}\n",
            Error::Read(ReadError::Unsupported {
                feature: Unsupported::SecondProduction,
                at: at(5, 3),
            }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\n  FG --> FF\n}\n",
            Error::Read(ReadError::NotOneSymbol { at: at(4, 3) }),
        ),
        (
            "p {\n  axiom: F\n  angle: twenty\n}\n",
            Error::Read(ReadError::NotANumber { at: at(3, 10) }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\n  F = FF\n}\n",
            Error::Read(ReadError::UnknownLine { at: at(4, 3) }),
        ),
        (
            "p {\n  axiom: F\n  angle: 20\nq {\n  axiom: F\n}\n",
            Error::Read(ReadError::EntryRunsIntoNext { entry: 1, next: 4 }),
        ),
    ];
    for (text, expected) in cases {
        assert_eq!(error_of(text), expected, "{text}");
    }
    assert_eq!(
        error_of("p {\n  angle: 20\n  F --> FF\n}\n"),
        Error::Read(ReadError::MissingAxiom)
    );
    assert_eq!(
        error_of("p {\n  axiom: F\n"),
        Error::Read(ReadError::UnterminatedEntry { at: at(1, 1) })
    );
    assert_eq!(
        error_of("p {\n  axiom: F\n  angle: 20\n  F --> F+F\n  F --> FF : 0.5\n}\n"),
        Error::Read(ReadError::MixedProductions {
            symbol: 'F',
            at: at(5, 7)
        })
    );
    assert_eq!(
        error_of("p {\n  axiom: F\n  angle: 20\n  F --> FF : many\n}\n"),
        Error::Read(ReadError::NotANumber { at: at(4, 14) })
    );
    let message = error_of("p {\n  axiom: F\n  angle: 20\n  F : t>1 --> FF\n}\n").to_string();
    assert!(
        message.contains("conditions") && message.contains("line 4, column 5"),
        "{message}"
    );
}

/// Stochastic productions: every walk of a derivation makes the same choices (the fit's and
/// the draw's, and two walks in a row), a seed changes them, and over many places each
/// production is chosen about as often as its probability says (chi-square, 2 degrees of
/// freedom, below 13.8: p = 0.001).
#[test]
fn stochastic_choices_are_repeatable_and_fair() {
    let text = shipped_file("data/abop.lsys");
    let file = LsysFile::new(&text);
    let plant = file.find("Fig1.27").unwrap();
    let derive = |grammar: &Grammar<'_>, order: u32| -> String {
        Walker::new(grammar, order)
            .unwrap()
            .map(Result::unwrap)
            .collect()
    };
    assert_eq!(derive(&plant, 4), derive(&plant, 4));
    let walk: Vec<_> = Segments::new(&plant, 4).unwrap().collect();
    assert_eq!(walk, Segments::new(&plant, 4).unwrap().collect::<Vec<_>>());
    let reseeded = plant.clone().with_seed(2);
    assert_ne!(derive(&plant, 4), derive(&reseeded, 4));

    // 3000 A's (3 X, each 10 Y, each 10 Z, each 10 A), each rewritten once at order 4:
    // B, C or D with 0.2, 0.3, 0.5.
    let mut grammar = Grammar::new(Dialect::Abop, "XXX", Angle::Divisions(4)).unwrap();
    for (symbol, body) in [
        ('X', "YYYYYYYYYY"),
        ('Y', "ZZZZZZZZZZ"),
        ('Z', "AAAAAAAAAA"),
    ] {
        grammar.add_rule(symbol, body).unwrap();
    }
    for (body, p) in [("B", "0.2"), ("C", "0.3"), ("D", "0.5")] {
        grammar
            .add_alternative('A', body, tinyfractal::Real::parse_decimal(p).unwrap())
            .unwrap();
    }
    for seed in [0, 1, 7, 12345] {
        let derived = derive(&grammar.clone().with_seed(seed), 4);
        assert_eq!(derived.len(), 3000);
        let chi_square: f64 = [('B', 0.2), ('C', 0.3), ('D', 0.5)]
            .iter()
            .map(|&(symbol, p)| {
                let observed = derived.chars().filter(|&c| c == symbol).count() as f64;
                let expected = 3000.0 * p;
                (observed - expected).powi(2) / expected
            })
            .sum();
        assert!(chi_square < 13.8, "seed {seed}: chi-square {chi_square}");
    }
}

/// ABOP 1.10's parametric example: the derivation the book prints, step by step.
#[test]
fn the_books_parametric_derivation() {
    let text = shipped_file("data/abop.lsys");
    let entry = LsysFile::new(&text).entry("Parametric1.10").unwrap();
    assert!(entry.is_parametric());
    let grammar = entry.parametric().unwrap();
    let book = [
        "B(2)A(4,4)",
        "B(1)B(4)A(1,0)",
        "B(0)B(3)A(2,1)",
        "CB(2)A(4,3)",
        "CB(1)A(8,7)",
        "CB(0)B(8)A(1.1429,0)",
    ];
    for (order, expected) in book.iter().enumerate() {
        let derived: String =
            tinyfractal::lsystem::ParametricWalker::<17>::new(&grammar, order as u32)
                .unwrap()
                .map(|module| module.unwrap().to_string())
                .collect();
        assert_eq!(&derived, expected, "order {order}");
    }
    // The plain reader names what it cannot derive.
    assert!(matches!(
        entry.grammar(),
        Err(Error::Read(ReadError::Unsupported {
            feature: Unsupported::Condition,
            ..
        }))
    ));
}

/// Expressions: precedence, constants, conditions with logic, and typed errors.
#[test]
fn parametric_expressions_and_their_errors() {
    let derive = |text: &str, order: u32| -> Result<String, Error> {
        let file = LsysFile::new(text);
        let grammar = file.entries().next().unwrap()?.parametric()?;
        tinyfractal::lsystem::ParametricWalker::<17>::new(&grammar, order)?
            .map(|module| module.map(|m| m.to_string()))
            .collect()
    };
    let system = "p {\n  define: k = 2^3 - 1\n  axiom: A(1,2)\n  angle: 90\n  A(x,y) : x < 3 && !(y == 0) --> A(x+1, y*k - (x+y)/2)B(-x^2)\n}\n";
    // A(1,2) -> A(2, 2*7 - 1.5 = 12.5)B(-1) -> A(3, 12.5*7 - 7.25 = 80.25)B(-4)B(-1)
    assert_eq!(derive(system, 2).unwrap(), "A(3,80.25)B(-4)B(-1)");
    let divide = "p {\n  axiom: A(0)\n  angle: 90\n  A(x) --> A(1/x)\n}\n";
    assert_eq!(
        derive(divide, 1),
        Err(Error::Walk(tinyfractal::error::WalkError::Arithmetic {
            symbol: 'A',
            problem: tinyfractal::error::Arithmetic::DivisionByZero,
        }))
    );
    let overflow = "p {\n  axiom: A(2)\n  angle: 90\n  A(x) --> A(x^16)\n}\n";
    assert!(matches!(
        derive(overflow, 2),
        Err(Error::Walk(tinyfractal::error::WalkError::Arithmetic {
            problem: tinyfractal::error::Arithmetic::OutOfRange,
            ..
        }))
    ));
    let unknown = "p {\n  axiom: A(2)\n  angle: 90\n  A(x) --> A(z)\n}\n";
    assert_eq!(
        derive(unknown, 1),
        Err(Error::Read(ReadError::UnknownName {
            at: Location {
                line: 4,
                column: 14
            }
        }))
    );
    let malformed = "p {\n  axiom: A(2)\n  angle: 90\n  A(x) --> A(x+)\n}\n";
    assert!(matches!(
        derive(malformed, 1),
        Err(Error::Read(ReadError::Expression { .. }))
    ));
}

/// The parametric engine's worst-case RAM, as its docs state it.
#[test]
fn parametric_memory_is_bounded() {
    use core::mem::size_of;
    let grammar = size_of::<tinyfractal::ParametricGrammar>();
    let walk = size_of::<tinyfractal::lsystem::ParametricWalker<'static, 17>>();
    println!("ParametricGrammar: {grammar} bytes; ParametricWalker<17>: {walk} bytes");
    assert!(grammar <= 12 * 1024, "{grammar}");
    assert!(walk <= 21 * 1024 + 512, "{walk}");
}

/// A parametric system drawn: ABOP's row of trees (equation 1.5). Each F(x) becomes four
/// segments whose turns cancel, so after n steps the curve ends at (1 + 2h·cos 86°)ⁿ on the
/// x axis, h = sqrt(p·q), worked out here in f64.
#[test]
fn a_parametric_system_draws() {
    use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    let text = shipped_file("data/abop.lsys");
    let grammar = LsysFile::new(&text)
        .entry("RowOfTrees")
        .unwrap()
        .parametric()
        .unwrap();
    let order = 4;
    let segments: Vec<_> = tinyfractal::lsystem::ParametricSegments::<17, 20>::new(
        &grammar,
        order,
        Default::default(),
    )
    .unwrap()
    .map(Result::unwrap)
    .collect();
    assert_eq!(segments.len(), 4usize.pow(order));
    let h = (0.3f64 * 0.7).sqrt();
    let expected = (1.0 + 2.0 * h * 86f64.to_radians().cos()).powi(order as i32);
    let end = segments.last().unwrap().end;
    assert!(
        (end.x.to_f64() - expected).abs() < 1e-6,
        "{} vs {expected}",
        end.x.to_f64()
    );
    assert!(end.y.to_f64().abs() < 1e-6, "{}", end.y.to_f64());
    let drawing = tinyfractal::ParametricLSystem::<17, 20>::new(&grammar, order)
        .fit(
            Rectangle::new(Point::zero(), Size::new(120, 80)),
            &[BinaryColor::On],
        )
        .unwrap();
    let mut frame = common::Bitmap::new(120, 80);
    let stats = drawing.draw(&mut frame).unwrap();
    assert_eq!(stats.segments, 256);
    assert_eq!(frame.outside, 0);
    let bounds = drawing.bounding_box();
    for y in 0..80 {
        for x in 0..120 {
            if frame.get(x, y) {
                assert!(bounds.contains(Point::new(x, y)));
            }
        }
    }
}

/// Stochastic productions with parameters and conditions: the same seed gives the same
/// string on every walk, another seed another string, and each alternative is taken about
/// as often as its probability says (512 choices; within 4 standard deviations).
#[test]
fn stochastic_parametric_choices_are_stable_and_fair() {
    let text = |seed: u32| {
        format!(
            "s {{\n  axiom: S(0)\n  angle: 90\n  seed: {seed}\n  S(n) : n < 9 --> S(n+1)S(n+1)\n  \
             S(n) : n >= 9 --> X(n)\n  X(n) --> B(n) : 0.25\n  X(n) --> C(n*2) : 0.75\n}}\n"
        )
    };
    let derive = |seed: u32| -> String {
        let text = text(seed);
        let file = LsysFile::new(&text);
        let grammar = file
            .entries()
            .next()
            .unwrap()
            .unwrap()
            .parametric()
            .unwrap();
        tinyfractal::lsystem::ParametricWalker::<17>::new(&grammar, 11)
            .unwrap()
            .map(|module| module.unwrap().to_string())
            .collect()
    };
    let first = derive(7);
    assert_eq!(first, derive(7));
    assert_ne!(first, derive(8));
    let b = first.matches("B(9)").count() as f64;
    let c = first.matches("C(18)").count() as f64;
    assert_eq!(b + c, 512.0, "{first}");
    let sd = (512.0f64 * 0.25 * 0.75).sqrt();
    assert!((b - 128.0).abs() < 4.0 * sd, "{b} of 512");
}

/// `%` drops the rest of its branch (up to the `]` that closes it, or the end of the
/// string), even where that rest comes from other productions' successors.
#[test]
fn cut_drops_the_rest_of_the_branch() {
    let derive = |text: &str, order: u32| -> String {
        let file = LsysFile::new(text);
        let grammar = file
            .entries()
            .next()
            .unwrap()
            .unwrap()
            .parametric()
            .unwrap();
        tinyfractal::lsystem::ParametricWalker::<17>::new(&grammar, order)
            .unwrap()
            .map(|module| module.unwrap().to_string())
            .collect()
    };
    let text = "c {\n  axiom: X[Y]Z\n  angle: 30\n  X --> a[b%c[d]e]f\n  Z --> z%\n}\n";
    assert_eq!(derive(text, 1), "a[b]f[Y]z");
    // The rest of the branch beyond the cutting successor: A's `%` drops B's expansion.
    let text = "c {\n  axiom: [AB]D\n  angle: 30\n  A --> a%\n  B --> bbb\n}\n";
    assert_eq!(derive(text, 1), "[a]D");
    let text = "c {\n  axiom: A\n  angle: 30\n  A --> F[+B]FA\n  B --> F%GH\n}\n";
    assert_eq!(derive(text, 3), "F[+F]FF[+F]FF[+B]FA");
}

/// Trigonometry in degrees, and the bad input the issue names: a wrong number of
/// parameters, unbalanced parentheses, a tangent of 90°.
#[test]
fn trigonometry_and_arity() {
    let derive = |text: &str, order: u32| -> Result<String, Error> {
        let file = LsysFile::new(text);
        let grammar = file.entries().next().unwrap()?.parametric()?;
        tinyfractal::lsystem::ParametricWalker::<17>::new(&grammar, order)?
            .map(|module| module.map(|m| m.to_string()))
            .collect()
    };
    let trig =
        "p {\n  axiom: A(30)\n  angle: 90\n  A(x) --> B(sin(x), cos(2*x), tan(45), sin(-x))\n}\n";
    assert_eq!(derive(trig, 1).unwrap(), "B(0.5,0.5,1,-0.5)");
    let vertical = "p {\n  axiom: A(90)\n  angle: 90\n  A(x) --> B(tan(x))\n}\n";
    assert!(matches!(
        derive(vertical, 1),
        Err(Error::Walk(tinyfractal::error::WalkError::Arithmetic {
            problem: tinyfractal::error::Arithmetic::DivisionByZero,
            ..
        }))
    ));
    let arity = "p {\n  axiom: A(1)\n  angle: 90\n  A(x) --> A(x,1)\n}\n";
    assert_eq!(
        derive(arity, 1),
        Err(Error::Read(ReadError::WrongArity {
            symbol: 'A',
            found: 2,
            expected: 1,
            at: Location {
                line: 4,
                column: 12
            },
        }))
    );
    let unbalanced = "p {\n  axiom: A(1)\n  angle: 90\n  A(x) --> A((x+1)\n}\n";
    assert!(matches!(
        derive(unbalanced, 1),
        Err(Error::Read(ReadError::Expression { .. }))
    ));
}
