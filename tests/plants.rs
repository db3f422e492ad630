//! The book's drawing vocabulary: polygons, widths, tropism, homomorphism, colour lines,
//! wind and growth, each against an independent model (an f64 turtle, eq. 2.4, pixel
//! geometry) or a property the rule implies.

use embedded_graphics::primitives::Rectangle;
use embedded_graphics::{
    pixelcolor::{BinaryColor, Rgb888},
    prelude::*,
};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    error::{ReadError, WalkError},
    lsystem::{Mark, Marks3, ParametricWalker, Segment3, Wind, MAX_POLYGON_VERTICES},
    Error, LsysFile, ParametricGrammar, ParametricLSystem, Real,
};

fn grammar(text: &str) -> Result<ParametricGrammar, Error> {
    LsysFile::new(text).entries().next().unwrap()?.parametric()
}

fn system(body: &str) -> ParametricGrammar {
    grammar(&format!("s {{\n{body}\n}}\n")).unwrap()
}

/// The lit pixels of a drawing of `g` at `order` into a `size`×`size` target.
fn pixels(g: &ParametricGrammar, order: u32, size: u32) -> Vec<Vec<bool>> {
    let mut display = SimulatorDisplay::<BinaryColor>::new(Size::new(size, size));
    let area = Rectangle::new(Point::zero(), Size::new(size, size));
    ParametricLSystem::<17, 16>::new(g, order)
        .fit(area, &[BinaryColor::On])
        .unwrap()
        .draw(&mut display)
        .unwrap();
    (0..size as i32)
        .map(|y| {
            (0..size as i32)
                .map(|x| display.get_pixel(Point::new(x, y)) == BinaryColor::On)
                .collect()
        })
        .collect()
}

/// The polygon `{.f+.f+.f+.f}` at 90° fills exactly the pixels whose centres lie in the
/// square, left and top edges in, right and bottom out: the square its outline (drawn at
/// the same fit, the same four corners) spans from (x0, y0) to (x1, y1) pixel centres
/// fills columns x0..x1 and rows y0..y1, half-open.
#[test]
fn a_square_polygon_fills_its_pixels_by_the_rule() {
    for size in [12, 17, 40, 63] {
        let filled = pixels(&system(" axiom: {.f+.f+.f+.f}\n angle: 90"), 0, size);
        // !(0) keeps the outline on the same (surface) path and fit, one pixel wide.
        let outline = pixels(&system(" axiom: !(0)F+F+F+F\n angle: 90"), 0, size);
        let lit: Vec<(usize, usize)> = (0..size as usize)
            .flat_map(|y| (0..size as usize).map(move |x| (x, y)))
            .filter(|&(x, y)| outline[y][x])
            .collect();
        let (x0, x1) = (
            lit.iter().map(|p| p.0).min().unwrap(),
            lit.iter().map(|p| p.0).max().unwrap(),
        );
        let (y0, y1) = (
            lit.iter().map(|p| p.1).min().unwrap(),
            lit.iter().map(|p| p.1).max().unwrap(),
        );
        assert!(x1 > x0 + 4, "size {size}");
        for (y, row) in filled.iter().enumerate() {
            for (x, &lit) in row.iter().enumerate() {
                let inside = (x0..x1).contains(&x) && (y0..y1).contains(&y);
                assert_eq!(lit, inside, "size {size} pixel ({x}, {y})");
            }
        }
    }
}

/// An f64 3D turtle with ABOP's turns, for vertices, lines and tropism.
#[derive(Clone, Copy)]
struct Turtle {
    p: [f64; 3],
    h: [f64; 3],
    l: [f64; 3],
    u: [f64; 3],
}

fn add(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `v` rotated by `angle` about the unit `axis` (Rodrigues).
fn rotate(v: [f64; 3], axis: [f64; 3], angle: f64) -> [f64; 3] {
    let (s, c) = angle.sin_cos();
    let k = cross(axis, v);
    let along = dot(axis, v) * (1.0 - c);
    [
        v[0] * c + k[0] * s + axis[0] * along,
        v[1] * c + k[1] * s + axis[1] * along,
        v[2] * c + k[2] * s + axis[2] * along,
    ]
}

impl Turtle {
    fn new() -> Self {
        Self {
            p: [0.0; 3],
            h: [0.0, 1.0, 0.0],
            l: [-1.0, 0.0, 0.0],
            u: [0.0, 0.0, 1.0],
        }
    }

    /// `+`/`-` (about U), `&`/`^` (about L, pitch down is towards −U), `\`/`/` (about H).
    fn turn(&mut self, symbol: char, degrees: f64) {
        let a = degrees.to_radians();
        let (h, l, u) = (self.h, self.l, self.u);
        match symbol {
            '+' => (self.h, self.l) = (rotate(h, u, a), rotate(l, u, a)),
            '-' => (self.h, self.l) = (rotate(h, u, -a), rotate(l, u, -a)),
            '&' => (self.h, self.u) = (rotate(h, l, a), rotate(u, l, a)),
            '^' => (self.h, self.u) = (rotate(h, l, -a), rotate(u, l, -a)),
            '\\' => (self.l, self.u) = (rotate(l, h, a), rotate(u, h, a)),
            '/' => (self.l, self.u) = (rotate(l, h, -a), rotate(u, h, -a)),
            '|' => {
                (self.h, self.l) = (
                    rotate(h, u, std::f64::consts::PI),
                    rotate(l, u, std::f64::consts::PI),
                )
            }
            _ => unreachable!(),
        }
    }

    /// ABOP eq. 2.4: the heading bends towards `t` by e·|H × T| about H × T.
    fn bend(&mut self, t: [f64; 3], e: f64) {
        let c = cross(self.h, t);
        let n = dot(c, c).sqrt();
        if n < 1e-9 {
            return;
        }
        let axis = [c[0] / n, c[1] / n, c[2] / n];
        let a = e * n;
        self.h = rotate(self.h, axis, a);
        self.l = rotate(self.l, axis, a);
        self.u = rotate(self.u, axis, a);
    }
}

fn to_f64(p: [Real; 3]) -> [f64; 3] {
    p.map(Real::to_f64)
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tolerance)
}

/// Which way `&` pitches in the engine, checked once so the model above is the engine's
/// convention and not a guess: `&(90)F` from heading up goes towards −z (away from the
/// viewer: down, ABOP's pitch down about L with U towards the viewer).
#[test]
fn the_model_turns_as_the_engine_does() {
    for (turns, expected) in [
        ("+(90)", '+'),
        ("-(90)", '-'),
        ("&(90)", '&'),
        ("^(90)", '^'),
        ("&(30)\\(90)+(90)", '\\'),
        ("&(30)/(90)+(90)", '/'),
    ] {
        let g = system(&format!(" axiom: {turns}F\n angle: 90"));
        let mut marks = Marks3::<17, 16>::new(&g, 0).unwrap();
        let Some(Ok(Mark::Line { segment, .. })) = marks.next_mark() else {
            panic!("{turns}: no line");
        };
        let mut model = Turtle::new();
        let mut text = turns;
        while let Some(symbol) = text.chars().next() {
            let close = text.find(')').unwrap();
            let degrees: f64 = text[2..close].parse().unwrap();
            model.turn(symbol, degrees);
            text = &text[close + 1..];
        }
        let end = add(model.p, model.h, 1.0);
        assert!(
            close(to_f64(segment.end), end, 1e-6),
            "{turns} ({expected}): {:?} against {end:?}",
            to_f64(segment.end)
        );
    }
}

/// A leaf in space: the polygon's vertices (recorded by each `f` of an undotted polygon,
/// and its start) are where an f64 turtle stands after the same moves.
#[test]
fn polygon_vertices_match_an_f64_turtle() {
    let g = system(" axiom: &(35)/(50)F(2){-(22.5)f+(22.5)f+(22.5)f-(22.5)|-(22.5)f+(22.5)f+(22.5)f}\n angle: 22.5");
    let mut marks = Marks3::<17, 16>::new(&g, 0).unwrap();
    let mut polygon = None;
    while let Some(mark) = marks.next_mark() {
        if let Mark::Polygon { vertices, .. } = mark.unwrap() {
            polygon = Some(vertices.iter().map(|&v| to_f64(v)).collect::<Vec<_>>());
        }
    }
    let polygon = polygon.expect("a polygon");
    let mut t = Turtle::new();
    t.turn('&', 35.0);
    t.turn('/', 50.0);
    t.p = add(t.p, t.h, 2.0);
    let mut expected = vec![t.p];
    for (symbol, step) in [
        ('-', true),
        ('+', true),
        ('+', true),
        ('-', false),
        ('|', false),
        ('-', true),
        ('+', true),
        ('+', true),
    ] {
        t.turn(symbol, if symbol == '|' { 180.0 } else { 22.5 });
        if step {
            t.p = add(t.p, t.h, 1.0);
            expected.push(t.p);
        }
    }
    assert_eq!(polygon.len(), expected.len());
    for (v, e) in polygon.iter().zip(&expected) {
        assert!(close(*v, *e, 1e-6), "{v:?} against {e:?}");
    }
}

/// With dots, only the dots are vertices; polygon errors are typed.
#[test]
fn dots_and_polygon_errors() {
    let g = system(" axiom: {F.f+.f+F.}\n angle: 90");
    let mut marks = Marks3::<17, 16>::new(&g, 0).unwrap();
    let Some(Ok(Mark::Polygon { vertices, .. })) = marks.next_mark() else {
        panic!("no polygon first: moves inside a polygon draw no lines");
    };
    let vertices: Vec<_> = vertices.iter().map(|&v| to_f64(v)).collect();
    assert_eq!(vertices.len(), 3);
    assert!(close(vertices[0], [0.0, 1.0, 0.0], 1e-9));
    assert!(close(vertices[1], [0.0, 2.0, 0.0], 1e-9));
    assert!(close(vertices[2], [-1.0, 1.0, 0.0], 1e-9));
    let error = |axiom: &str| {
        let g = system(&format!(" axiom: {axiom}\n angle: 90"));
        let mut marks = Marks3::<17, 16>::new(&g, 0).unwrap();
        loop {
            match marks.next_mark() {
                Some(Ok(_)) => {}
                Some(Err(error)) => return Some(error),
                None => return None,
            }
        }
    };
    assert_eq!(
        error("{.f.f"),
        Some(Error::Walk(WalkError::PolygonNotClosed))
    );
    assert_eq!(error("F}"), Some(Error::Walk(WalkError::PolygonNotOpen)));
    assert_eq!(
        error("{{{.}}}"),
        Some(Error::Walk(WalkError::PolygonsNestTooDeep { capacity: 2 }))
    );
    let many = ".f+".repeat(MAX_POLYGON_VERTICES + 1);
    assert_eq!(
        error(&format!("{{{many}}}")),
        Some(Error::Walk(WalkError::PolygonTooLarge {
            capacity: MAX_POLYGON_VERTICES
        }))
    );
    assert_eq!(error("{.f+.f+.f}"), None);
}

/// A line `w` units wide covers w·scale pixels across (±1) at every direction: measured
/// along its normal through its middle, with the scale calibrated by a one-pixel frame 10
/// units square drawn with it.
#[test]
fn a_thick_line_covers_its_width_at_every_direction() {
    let size = 220u32;
    for degrees in (0..180).step_by(15) {
        for width in ["0.15", "0.3", "0.55"] {
            let w: f64 = width.parse().unwrap();
            let text = format!(
                " axiom: F(10)+F(10)+F(10)+F(10)+f(5)+f(5)--({degrees})f(-2)!({width})F(4)\n angle: 90"
            );
            let lit = pixels(&system(&text), 0, size);
            let row = |y: usize| lit[y].iter().filter(|&&p| p).count();
            // The frame's sides: its first and last lit rows and columns.
            let rows: Vec<usize> = (0..size as usize).filter(|&y| row(y) > 0).collect();
            let (top, bottom) = (rows[0], *rows.last().unwrap());
            let scale = (bottom - top) as f64 / 10.0;
            let centre = ((top + bottom) as f64 / 2.0, (top + bottom) as f64 / 2.0);
            let columns: Vec<usize> = (0..size as usize)
                .filter(|&x| (0..size as usize).any(|y| lit[y][x]))
                .collect();
            let centre = (
                (columns[0] + columns.last().unwrap()) as f64 / 2.0,
                centre.1,
            );
            // The line heads up turned by `degrees` to the right: on screen (x right, y
            // down) its direction is (sin, −cos), its normal (cos, sin).
            let a = (degrees as f64).to_radians();
            let normal = (a.cos(), a.sin());
            let (mut low, mut high) = (f64::MAX, f64::MIN);
            let reach = w * scale;
            let mut t = -reach;
            while t <= reach {
                let x = (centre.0 + t * normal.0).round() as usize;
                let y = (centre.1 + t * normal.1).round() as usize;
                if lit[y][x] {
                    low = low.min(t);
                    high = high.max(t);
                }
                t += 0.01;
            }
            let across = high - low;
            let expected = w * scale;
            assert!(
                (across - expected).abs() <= 1.0,
                "{degrees}° width {width}: {across:.2} pixels across, {expected:.2} expected"
            );
        }
    }
}

/// Tropism: every segment of a fixture system ends where an f64 turtle bent by ABOP's
/// eq. 2.4 after each step puts it.
#[test]
fn tropism_bends_as_equation_2_4() {
    let steps = "F&(20)F/(30)F+(45)F[-(60)FF]F^(10)FFFFFFFFFF";
    for (direction, e) in [
        ([0.0, -1.0, 0.0], 0.22),
        ([1.0, 0.5, 0.0], 0.4),
        ([0.0, 0.0, 2.0], 0.1),
    ] {
        let text = format!(
            " axiom: {steps}\n angle: 90\n tropism: {},{},{} {e}",
            direction[0], direction[1], direction[2]
        );
        let g = system(&text);
        let mut marks = Marks3::<17, 16>::new(&g, 0).unwrap();
        let mut drawn: Vec<Segment3> = Vec::new();
        while let Some(mark) = marks.next_mark() {
            if let Mark::Line { segment, .. } = mark.unwrap() {
                drawn.push(segment);
            }
        }
        // The model.
        let mut t = Turtle::new();
        let mut stack = Vec::new();
        let mut expected = Vec::new();
        let chars: Vec<char> = steps.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            let mut degrees = None;
            if chars.get(i + 1) == Some(&'(') {
                let close = chars[i..].iter().position(|&c| c == ')').unwrap() + i;
                let text: String = chars[i + 2..close].iter().collect();
                degrees = Some(text.parse::<f64>().unwrap());
                i = close;
            }
            match c {
                'F' => {
                    let start = t.p;
                    t.p = add(t.p, t.h, 1.0);
                    expected.push((start, t.p));
                    t.bend(direction, e);
                }
                '[' => stack.push(t),
                ']' => t = stack.pop().unwrap(),
                _ => t.turn(c, degrees.unwrap()),
            }
            i += 1;
        }
        assert_eq!(drawn.len(), expected.len());
        let mut bent = false;
        for (segment, (start, end)) in drawn.iter().zip(&expected) {
            assert!(close(to_f64(segment.start), *start, 1e-5), "{direction:?}");
            assert!(
                close(to_f64(segment.end), *end, 1e-5),
                "{direction:?}: {:?} against {end:?}",
                to_f64(segment.end)
            );
        }
        // The same steps without tropism end elsewhere: the bend is real.
        let straight = system(&format!(" axiom: {steps}\n angle: 90"));
        let last = Marks3::<17, 16>::new(&straight, 0).unwrap();
        let mut last = last;
        let mut end = None;
        while let Some(mark) = last.next_mark() {
            if let Mark::Line { segment, .. } = mark.unwrap() {
                end = Some(to_f64(segment.end));
            }
        }
        bent |= !close(end.unwrap(), expected.last().unwrap().1, 0.1);
        assert!(bent);
    }
}

const WITH_HOMOMORPHISM: &str = "s {
 axiom: A
 angle: 90
 A --> AX
 homomorphism:
 X --> F+F
}
";

/// The homomorphism rewrites modules when drawing only: the derivation (as `derive`
/// walks it) is the system's without it, and the drawing is that of the system whose
/// productions write the homomorphism's successors in.
#[test]
fn a_homomorphism_changes_the_drawing_not_the_derivation() {
    let with = grammar(WITH_HOMOMORPHISM).unwrap();
    assert!(with.has_homomorphism());
    let without = grammar("s {\n axiom: A\n angle: 90\n A --> AX\n}\n").unwrap();
    let written_in = grammar("s {\n axiom: A\n angle: 90\n A --> AF+F\n}\n").unwrap();
    for order in 0..6 {
        let derived = |g: &ParametricGrammar| -> Vec<String> {
            ParametricWalker::<'_, 17>::new(g, order)
                .unwrap()
                .map(|m| m.unwrap().to_string())
                .collect()
        };
        assert_eq!(derived(&with), derived(&without), "order {order}");
        let drawn = |g: &ParametricGrammar| -> Vec<Segment3> {
            ParametricLSystem::<17, 16>::new(g, order)
                .segments_3d()
                .unwrap()
                .map(Result::unwrap)
                .collect()
        };
        assert_eq!(drawn(&with), drawn(&written_in), "order {order}");
        assert_eq!(drawn(&with).len(), 2 * order as usize);
    }
    // A context in the homomorphism is refused where it is written.
    let error = grammar("s {\n axiom: A\n homomorphism:\n B < A --> F\n}\n").unwrap_err();
    assert!(
        matches!(error, Error::Read(ReadError::Unsupported { .. })),
        "{error}"
    );
}

/// `colors:` lines: six hex digits a colour (no `#`: it starts a comment); errors name
/// line and column.
#[test]
fn colour_lines_read_with_typed_errors() {
    let file =
        LsysFile::new("s {\n axiom: F\n angle: 90\n colors: 5a3a1e 2F7D32, ffffff # the last\n}\n");
    let colors = file.entry("s").unwrap().colors::<8>().unwrap();
    assert_eq!(
        colors.as_slice(),
        [
            Rgb888::new(0x5a, 0x3a, 0x1e),
            Rgb888::new(0x2f, 0x7d, 0x32),
            Rgb888::new(255, 255, 255)
        ]
    );
    let bad = LsysFile::new("s {\n axiom: F\n colors: 5a3a1e 12345g\n}\n");
    match bad.entry("s").unwrap().colors::<8>() {
        Err(Error::Read(ReadError::NotAColor { at })) => {
            assert_eq!((at.line, at.column), (3, 17));
        }
        other => panic!("{other:?}"),
    }
    let many = LsysFile::new("s {\n axiom: F\n colors: 000000 111111 222222\n}\n");
    assert!(matches!(
        many.entry("s").unwrap().colors::<2>(),
        Err(Error::Read(ReadError::TooManyColors { max: 2, .. }))
    ));
    let malformed = grammar("s {\n axiom: F\n tropism: 0,-1 0.2\n}\n").unwrap_err();
    assert!(matches!(
        malformed,
        Error::Read(ReadError::MalformedTropism { .. })
    ));
}

/// Wind sways a plant periodically and leaves its root where it stands.
#[test]
fn wind_is_periodic_and_the_root_stays() {
    let g = system(" axiom: FF[+F[-F]F]F[-F+F]F\n angle: 25");
    let wind = Wind {
        push: [Real::from_ratio(3, 10).unwrap(), Real::ZERO, Real::ZERO],
        seed: 7,
    };
    let frames = 12;
    let first = |frame: u32| -> Vec<Segment3> {
        let tropism = wind.tropism_at(g.tropism(), frame, frames);
        ParametricLSystem::<17, 16>::new(&g, 0)
            .with_tropism(Some(tropism))
            .segments_3d()
            .unwrap()
            .map(Result::unwrap)
            .collect()
    };
    assert_eq!(first(0), first(frames));
    assert_eq!(first(5), first(5 + frames));
    let tops: Vec<f64> = (0..frames)
        .map(|frame| {
            let segments = first(frame);
            assert_eq!(segments[0].start, [Real::ZERO; 3], "the root moved");
            segments.last().unwrap().end[0].to_f64()
        })
        .collect();
    // It sways both ways.
    let (low, high) = tops
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), &t| (l.min(t), h.max(t)));
    assert!(high - low > 0.5, "{tops:?}");
    // The gust is sin(2πt) + sin(4πt + φ)/2: its f64 model at every frame.
    for frame in 0..frames {
        let tropism = wind.tropism_at(None, frame, frames);
        let t = f64::from(frame) / f64::from(frames);
        let phase =
            f64::from(7u32.wrapping_mul(0x9E37_79B9)) / 2f64.powi(32) * std::f64::consts::TAU;
        let gust = (std::f64::consts::TAU * t).sin()
            + 0.5 * (2.0 * std::f64::consts::TAU * t + phase).sin();
        assert!(
            (tropism.direction[0].to_f64() - 0.3 * gust).abs() < 1e-6,
            "frame {frame}"
        );
    }
}

/// Growth between orders: at 0 the plant is the lower order's, at 1 the higher's (the
/// shrunk or grown steps of length 0 aside), and in between its new branches are shorter.
#[test]
fn growth_runs_from_one_order_to_the_next() {
    let g = system(" axiom: X\n angle: 25\n X --> F[+X]F[-X]+X\n F --> FF");
    let drawn = |order: u32, fraction: Option<Real>| -> Vec<Segment3> {
        let mut system = ParametricLSystem::<17, 16>::new(&g, order);
        if let Some(fraction) = fraction {
            system = system.growing(fraction);
        }
        system
            .segments_3d()
            .unwrap()
            .map(Result::unwrap)
            .filter(|s| s.start != s.end)
            .collect()
    };
    for order in 1..5 {
        assert_eq!(
            drawn(order, Some(Real::ZERO)),
            drawn(order - 1, None),
            "order {order} at 0"
        );
        assert_eq!(
            drawn(order, Some(Real::ONE)),
            drawn(order, None),
            "order {order} at 1"
        );
        let length = |segments: &[Segment3]| -> f64 {
            segments
                .iter()
                .map(|s| {
                    let (a, b) = (to_f64(s.start), to_f64(s.end));
                    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
                })
                .sum()
        };
        let (low, half, high) = (
            length(&drawn(order - 1, None)),
            length(&drawn(order, Some(Real::from_ratio(1, 2).unwrap()))),
            length(&drawn(order, None)),
        );
        assert!(low < half && half < high, "{low} {half} {high}");
        // The total length is linear in the fraction: each step is (1 − t) of its parent's
        // or t of its own.
        assert!(
            (half - (low + high) / 2.0).abs() < 1e-6,
            "{low} {half} {high}"
        );
    }
}

/// docs/memory.md's figures for a walk that draws surfaces: the polygons the turtle records
/// are 2 × 32 vertices of 24 bytes, and a whole walk with the boards' capacities
/// (`Marks3<16, 20, 0>`) stays under 10 KiB on a 64-bit host.
#[test]
fn a_surface_walk_is_bounded() {
    let size = size_of::<Marks3<'static, 16, 20, 0>>();
    println!("Marks3<16, 20, 0>: {size} bytes");
    assert!(size <= 10 * 1024, "{size}");
    assert_eq!(
        tinyfractal::lsystem::MAX_OPEN_POLYGONS * MAX_POLYGON_VERTICES * 24,
        1536
    );
}
