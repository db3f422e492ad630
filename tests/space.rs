//! The 3D turtle (ABOP 1.5): the 3D Hilbert curve, an independent f64 model of the turtle,
//! the frame's drift over a million turns, and 2D systems drawn in 3D.

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use proptest::prelude::*;
use tinyfractal::{
    lsystem::{ParametricSegments, Segment3, Segments3, Start},
    render::Projection,
    LsysFile, ParametricGrammar, ParametricLSystem,
};

fn grammar(text: &str) -> ParametricGrammar {
    LsysFile::new(text)
        .entries()
        .next()
        .unwrap()
        .unwrap()
        .parametric()
        .unwrap()
}

fn f(p: [tinyfractal::Real; 3]) -> [f64; 3] {
    p.map(|v| v.to_f64())
}

fn segments(grammar: &ParametricGrammar, order: u32) -> Vec<Segment3> {
    Segments3::<24, 64>::new(grammar, order)
        .unwrap()
        .map(Result::unwrap)
        .collect()
}

/// ABOP p. 20: the 3D Hilbert curve visits every point of its 2ⁿ × 2ⁿ × 2ⁿ grid exactly
/// once, in unit steps, each step from where the last ended.
#[test]
fn hilbert_curve_visits_its_grid_once() {
    let text = "hilbert {\n  axiom: A\n  angle: 90\n  \
        A --> B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n  \
        B --> A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//\n  \
        C --> |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//\n  \
        D --> |CFB-F+B|FA&F^A&&FB-F+B|FC//\n}\n";
    let grammar = grammar(text);
    assert!(grammar.is_3d());
    for order in 1..=3u32 {
        let side = 1i64 << order;
        let segments = segments(&grammar, order);
        assert_eq!(
            segments.len() as i64,
            side * side * side - 1,
            "order {order}"
        );
        let mut seen = std::collections::HashSet::new();
        let grid = |p: [f64; 3]| {
            p.map(|v| {
                let r = v.round();
                assert!((v - r).abs() < 1e-6, "{v} off the grid");
                r as i64
            })
        };
        let mut last = None;
        for s in &segments {
            let (a, b) = (f(s.start), f(s.end));
            let length = (0..3).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
            assert!((length - 1.0).abs() < 1e-6, "step {length}");
            if let Some(last) = last {
                assert_eq!(grid(a), last, "continues");
            }
            seen.insert(grid(a));
            last = Some(grid(b));
        }
        seen.insert(last.unwrap());
        assert_eq!(seen.len() as i64, side * side * side, "every point once");
        for axis in 0..3 {
            let values: Vec<i64> = seen.iter().map(|p| p[axis]).collect();
            let span = values.iter().max().unwrap() - values.iter().min().unwrap();
            assert_eq!(span, side - 1, "a cube of side {side}");
        }
    }
}

/// ABOP's turtle in f64: heading, left, up as columns, turned by its rotation matrices.
struct Model {
    position: [f64; 3],
    frame: [[f64; 3]; 3],
    stack: Vec<([f64; 3], [[f64; 3]; 3])>,
    degrees: f64,
    /// A `$` met a heading near (not at) vertical, within 3°, where it divides by a short vector and
    /// magnifies rounding without bound: no model can be compared there.
    ill_conditioned: bool,
}

impl Model {
    /// Turns `a` about the axis `fixed`, moving `from` towards `to` (H, L, U = 0, 1, 2).
    fn turn(&mut self, from: usize, to: usize, a: f64) {
        let (c, s) = (a.to_radians().cos(), a.to_radians().sin());
        let (x, y) = (self.frame[from], self.frame[to]);
        for i in 0..3 {
            self.frame[from][i] = x[i] * c + y[i] * s;
            self.frame[to][i] = y[i] * c - x[i] * s;
        }
    }

    fn run(&mut self, program: &[(char, Option<f64>)]) -> Vec<([f64; 3], [f64; 3])> {
        let mut out = Vec::new();
        for &(symbol, value) in program {
            let a = value.unwrap_or(self.degrees);
            match symbol {
                'F' | 'f' => {
                    let l = value.unwrap_or(1.0);
                    let start = self.position;
                    for i in 0..3 {
                        self.position[i] += self.frame[0][i] * l;
                    }
                    if symbol == 'F' {
                        out.push((start, self.position));
                    }
                }
                // + turns H towards L; & turns H towards -U (U towards H); \ turns L to U.
                '+' => self.turn(0, 1, a),
                '-' => self.turn(0, 1, -a),
                '&' => self.turn(2, 0, a),
                '^' => self.turn(2, 0, -a),
                '\\' => self.turn(1, 2, a),
                '/' => self.turn(1, 2, -a),
                '|' => self.turn(0, 1, 180.0),
                '$' => {
                    let h = self.frame[0];
                    // L = V x H / |V x H| with V = +y; U = H x L.
                    let l = [h[2], 0.0, -h[0]];
                    let n = (l[0] * l[0] + l[2] * l[2]).sqrt();
                    self.ill_conditioned |= n < 0.05 && n > 1e-9;
                    // Within 2^-20 of vertical, tinyfractal leaves the frame as it is.
                    if n > 2f64.powi(-20) {
                        let l = [l[0] / n, 0.0, l[2] / n];
                        let u = [
                            h[1] * l[2] - h[2] * l[1],
                            h[2] * l[0] - h[0] * l[2],
                            h[0] * l[1] - h[1] * l[0],
                        ];
                        self.frame[1] = l;
                        self.frame[2] = u;
                    }
                }
                '[' => self.stack.push((self.position, self.frame)),
                ']' => {
                    if let Some((p, fr)) = self.stack.pop() {
                        self.position = p;
                        self.frame = fr;
                    }
                }
                _ => {}
            }
        }
        out
    }
}

fn module() -> impl Strategy<Value = (char, Option<f64>)> {
    let symbol = proptest::sample::select(vec!['F', 'f', '+', '-', '&', '^', '\\', '/', '|', '$']);
    let value = proptest::option::of((1u32..3600).prop_map(|v| f64::from(v) / 10.0));
    (symbol, value).prop_map(|(s, v)| match s {
        '|' | '$' => (s, None),
        _ => (s, v),
    })
}

/// A random program: modules, some in branches.
fn program() -> impl Strategy<Value = Vec<(char, Option<f64>)>> {
    proptest::collection::vec((module(), 0u8..6), 1..60).prop_map(|parts| {
        let mut out = Vec::new();
        let mut open = 0;
        for (m, roll) in parts {
            match roll {
                0 => {
                    out.push(('[', None));
                    open += 1;
                }
                1 if open > 0 => {
                    out.push((']', None));
                    open -= 1;
                }
                _ => out.push(m),
            }
        }
        out.extend(std::iter::repeat_n((']', None), open));
        out
    })
}

fn text(program: &[(char, Option<f64>)], degrees: f64) -> String {
    let axiom: String = program
        .iter()
        .map(|&(s, v)| match v {
            Some(v) => format!("{s}({v})"),
            None => s.to_string(),
        })
        .collect();
    format!("s {{\n  axiom: {axiom}\n  angle: {degrees}\n}}\n")
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Random programs of every 3D module: the segments match the f64 model to 10⁻⁶ of
    /// their distance from the origin (the sines are within 3·10⁻⁷; positions add up).
    #[test]
    fn segments_match_an_f64_model(program in program(), tenths in 1u32..1800) {
        let degrees = f64::from(tenths) / 10.0;
        let grammar = grammar(&text(&program, degrees));
        let ours = segments(&grammar, 0);
        let mut model = Model {
            position: [0.0; 3],
            frame: [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
            stack: Vec::new(),
            degrees,
            ill_conditioned: false,
        };
        let expected = model.run(&program);
        prop_assume!(!model.ill_conditioned);
        prop_assert_eq!(ours.len(), expected.len());
        for (s, (a, b)) in ours.iter().zip(&expected) {
            for (got, want) in [(f(s.start), a), (f(s.end), b)] {
                let reach = 1.0 + want.iter().map(|v| v * v).sum::<f64>().sqrt();
                for i in 0..3 {
                    prop_assert!((got[i] - want[i]).abs() < 1e-6 * reach, "{:?} vs {:?}", got, want);
                }
            }
        }
    }
}

/// Over 1.5 million turns the frame stays orthonormal: after them, steps along heading,
/// left and down are unit long and square to each other.
#[test]
fn frame_drift_is_bounded_over_a_million_turns() {
    let text = "s {\n  axiom: T(19)F[+(90)F][&(90)F]\n  angle: 22.5\n  \
                T(n) : n > 0 --> T(n-1)T(n-1)\n  T(n) : n == 0 --> +&/\n}\n";
    let grammar = grammar(text);
    let ours = segments(&grammar, 20);
    assert_eq!(ours.len(), 3);
    let direction = |s: &Segment3| {
        let (a, b) = (f(s.start), f(s.end));
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
    };
    let d: Vec<[f64; 3]> = ours.iter().map(direction).collect();
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    for v in &d {
        assert!(
            (dot(*v, *v).sqrt() - 1.0).abs() < 1e-6,
            "length {}",
            dot(*v, *v)
        );
    }
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        assert!(
            dot(d[i], d[j]).abs() < 1e-6,
            "{i}.{j} = {}",
            dot(d[i], d[j])
        );
    }
}

/// A plant turned only by `+` and `-`, drawn by the 3D turtle, is the 2D turtle's plant
/// (heading up rather than right) in the plane z = 0; seen from the front it draws.
#[test]
fn plane_systems_draw_as_in_2d() {
    let text = "s {\n  axiom: F\n  angle: 25.7\n  F --> F[+F]F[-F]F\n}\n";
    let grammar = grammar(text);
    let flat: Vec<_> = ParametricSegments::<17, 64>::new(&grammar, 3, Start::default())
        .unwrap()
        .map(Result::unwrap)
        .collect();
    let space = segments(&grammar, 3);
    assert_eq!(flat.len(), space.len());
    for (a, b) in flat.iter().zip(&space) {
        for (p, q) in [(a.start, b.start), (a.end, b.end)] {
            // 2D heads +x; 3D heads +y: (x, y) in 2D is (-y, x) in 3D... rotated back.
            let q = f(q);
            assert!((p.x.to_f64() - q[1]).abs() < 1e-5, "{p:?} {q:?}");
            assert!((p.y.to_f64() + q[0]).abs() < 1e-5, "{p:?} {q:?}");
            assert_eq!(q[2], 0.0);
        }
    }
    let system = ParametricLSystem::<17, 64>::new(&grammar, 3).with_projection(Projection::Front);
    let area = Rectangle::new(Point::zero(), Size::new(64, 64));
    let drawing = system.fit(area, &[BinaryColor::On]).unwrap();
    let mut display = embedded_graphics::mock_display::MockDisplay::new();
    display.set_allow_overdraw(true);
    drawing.draw(&mut display).unwrap();
    let lit = display.affected_area();
    assert!(lit.size.height > 40, "{lit:?}");
}
