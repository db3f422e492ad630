//! Helpers shared by the integration tests: an f64 model of the turtle language, written
//! from the format's description and independent of the engine, and a plain framebuffer.

#![allow(dead_code)]

use std::collections::HashMap;
use std::path::PathBuf;

use embedded_graphics::prelude::*;

use tinyfractal_test_support::frame as support;

/// A system as the model sees it.
#[derive(Debug, Clone)]
pub struct ModelSystem {
    pub fractint: bool,
    pub axiom: String,
    pub rules: HashMap<char, String>,
    /// Divisions of a full turn, or degrees for a free angle.
    pub divisions: Option<u32>,
    pub degrees: f64,
    pub draw_symbols: Vec<char>,
}

pub type ModelSegment = [f64; 4];

impl ModelSystem {
    /// Parses a `.l` entry body the simple way: strip `;` comments, lower-case, split on
    /// spaces, tabs and `=`; repeated rules append.
    pub fn from_fractint_body(body: &str) -> Self {
        let mut system = Self {
            fractint: true,
            axiom: String::new(),
            rules: HashMap::new(),
            divisions: None,
            degrees: 0.0,
            draw_symbols: vec![],
        };
        for line in body.lines() {
            let code = line.split(';').next().unwrap().to_lowercase();
            let words: Vec<&str> = code
                .split([' ', '\t', '=', '\r'])
                .filter(|w| !w.is_empty())
                .collect();
            match words.as_slice() {
                [] => {}
                ["axiom", axiom, ..] => system.axiom = axiom.to_string(),
                ["angle", n, ..] => system.divisions = Some(n.parse().unwrap()),
                [symbol, rest @ ..] if symbol.chars().count() == 1 => {
                    let c = symbol.chars().next().unwrap();
                    system
                        .rules
                        .entry(c)
                        .or_default()
                        .push_str(rest.first().copied().unwrap_or(""));
                }
                other => panic!("model cannot read {other:?}"),
            }
        }
        system
    }

    pub fn abop(axiom: &str, rules: &[(char, &str)], divisions: Option<u32>, degrees: f64) -> Self {
        Self {
            fractint: false,
            axiom: axiom.into(),
            rules: rules.iter().map(|&(c, s)| (c, s.to_string())).collect(),
            divisions,
            degrees,
            draw_symbols: vec![],
        }
    }

    /// The derived string, built in full (this is the model: memory is no concern).
    /// `None` if it would exceed `limit` characters.
    pub fn derive(&self, order: u32, limit: usize) -> Option<String> {
        let normalize = |s: &str| {
            if self.fractint {
                s.to_lowercase()
            } else {
                s.to_string()
            }
        };
        let mut text = normalize(&self.axiom);
        for _ in 0..order {
            let mut next = String::new();
            let chars: Vec<char> = text.chars().collect();
            let mut i = 0;
            while i < chars.len() {
                let c = chars[i];
                let argument_length = self.argument_length(&chars[i..]);
                if argument_length > 0 {
                    next.extend(&chars[i..i + 1 + argument_length]);
                    i += 1 + argument_length;
                    continue;
                }
                match self.rules.get(&c) {
                    Some(body) => next.push_str(&normalize(body)),
                    None => next.push(c),
                }
                if next.len() > limit {
                    return None;
                }
                i += 1;
            }
            text = next;
        }
        Some(text)
    }

    /// Characters of the numeric argument after a command (Fractint only).
    fn argument_length(&self, chars: &[char]) -> usize {
        if !self.fractint || !matches!(chars[0], '\\' | '/' | '@' | 'c' | '<' | '>') {
            return 0;
        }
        let mut n = 1;
        if chars[0] == '@' {
            while chars.get(n).is_some_and(|c| matches!(c, 'i' | 'q')) {
                n += 1;
            }
        }
        while chars
            .get(n)
            .is_some_and(|c| c.is_ascii_digit() || *c == '.')
        {
            n += 1;
        }
        n - 1
    }

    /// The drawn segments of the derived string with a float turtle: start at the origin,
    /// heading +x, step 1, y up, `+` counter-clockwise.
    pub fn segments(&self, derived: &str) -> Vec<ModelSegment> {
        #[derive(Clone, Copy)]
        struct T {
            x: f64,
            y: f64,
            step: f64,
            k: i64,
            angle: f64,
            free: f64,
            reversed: bool,
        }
        let n = self.divisions.map(i64::from);
        let mut t = T {
            x: 0.0,
            y: 0.0,
            step: 1.0,
            k: 0,
            angle: 0.0,
            free: 0.0,
            reversed: false,
        };
        let mut stack = vec![];
        let mut out = vec![];
        let chars: Vec<char> = derived.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            let length = self.argument_length(&chars[i..]);
            let argument: String = chars[i + 1..i + 1 + length].iter().collect();
            i += 1 + length;
            let main_heading = |t: &T| match n {
                Some(n) => std::f64::consts::TAU * t.k as f64 / n as f64,
                None => t.angle.to_radians(),
            };
            let mut walk = |t: &mut T, heading: f64, draw: bool| {
                let (x, y) = (t.x + t.step * heading.cos(), t.y + t.step * heading.sin());
                if draw {
                    out.push([t.x, t.y, x, y]);
                }
                (t.x, t.y) = (x, y);
            };
            let turn = |t: &mut T, left: bool| match n {
                Some(n) => t.k = (t.k + if left { 1 } else { -1 }).rem_euclid(n),
                None => t.angle += if left { self.degrees } else { -self.degrees },
            };
            let number = |text: &str| -> f64 { text.parse().unwrap() };
            let (main, free, reversed) = (main_heading(&t), t.free.to_radians(), t.reversed);
            if self.fractint {
                match c {
                    'f' => walk(&mut t, main, true),
                    'g' => walk(&mut t, main, false),
                    'd' => walk(&mut t, free, true),
                    'm' => walk(&mut t, free, false),
                    '+' => turn(&mut t, !reversed),
                    '-' => turn(&mut t, reversed),
                    '|' => match n {
                        Some(n) => t.k = (t.k - n / 2).rem_euclid(n),
                        None => t.angle += 180.0,
                    },
                    '!' => t.reversed = !t.reversed,
                    '\\' => t.free += if t.reversed { -1.0 } else { 1.0 } * number(&argument),
                    '/' => t.free -= if t.reversed { -1.0 } else { 1.0 } * number(&argument),
                    '@' => {
                        let digits = argument.trim_start_matches(['i', 'q']);
                        let mut factor = number(digits);
                        if argument.contains('q') {
                            factor = factor.sqrt();
                        }
                        if argument[..argument.len() - digits.len()].contains('i') {
                            factor = 1.0 / factor;
                        }
                        t.step *= factor;
                    }
                    '[' => stack.push(t),
                    ']' => t = stack.pop().expect("balanced"),
                    _ => {}
                }
            } else {
                match c {
                    'F' => walk(&mut t, main, true),
                    'f' => walk(&mut t, main, false),
                    '+' => turn(&mut t, true),
                    '-' => turn(&mut t, false),
                    '|' => match n {
                        Some(n) => t.k = (t.k - n / 2).rem_euclid(n),
                        None => t.angle += 180.0,
                    },
                    '[' => stack.push(t),
                    ']' => t = stack.pop().expect("balanced"),
                    c if self.draw_symbols.contains(&c) => walk(&mut t, main, true),
                    _ => {}
                }
            }
        }
        out
    }
}

/// The engine's segments as f64.
pub fn engine_segments(grammar: &tinyfractal::Grammar<'_>, order: u32) -> Vec<ModelSegment> {
    tinyfractal::lsystem::Segments::new(grammar, order)
        .unwrap()
        .map(|s| {
            let s = s.unwrap();
            [
                s.start.x.to_f64(),
                s.start.y.to_f64(),
                s.end.x.to_f64(),
                s.end.y.to_f64(),
            ]
        })
        .collect()
}

/// A file of Fractint's own corpus (`../shared/corpus`, or `TINYFRACTAL_CORPUS`), read as
/// 8-bit text. Tests that call it are built as ignored where the corpus is missing (see
/// build.rs), except under `CI=true`.
pub fn corpus_file(name: &str) -> String {
    let path = PathBuf::from(env!("TINYFRACTAL_CORPUS_DIR"))
        .join("fractint")
        .join(name);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e} (put shared/ beside the repository, or set TINYFRACTAL_CORPUS)",
            path.display()
        )
    });
    bytes.iter().map(|&b| char::from(b)).collect()
}

/// A file the project ships: `data/NAME` or `tests/data/NAME`.
pub fn shipped_file(path: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(path);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The `.l` files the project ships, for tests that need real files.
pub const SHIPPED_L_FILES: [&str; 2] = ["data/classics.l", "tests/data/small.l"];

/// The Koch snowflake (Fractint's Koch1): 3·4ⁿ segments at order n.
pub fn koch_snowflake() -> tinyfractal::Grammar<'static> {
    tinyfractal::Grammar::new(
        tinyfractal::Dialect::Fractint,
        "F--F--F",
        tinyfractal::Angle::Divisions(6),
    )
    .unwrap()
    .with_rule('F', "F+F--F+F")
    .unwrap()
}

/// The pixel a drawing pass puts a turtle point on (orientation right: the row is -y).
pub fn pixel(p: tinyfractal::lsystem::TurtlePoint) -> Point {
    Point::new(p.x.round_to_i32(), -p.y.round_to_i32())
}

#[allow(unused_imports)]
pub use support::{Bitmap, Frame};

/// Wraps a target and counts what reaches it: per-pixel writes, runs, and pixels.
pub struct Counting<T> {
    pub inner: T,
    pub draw_iter_pixels: usize,
    pub fill_solid_calls: usize,
    pub fill_contiguous_calls: usize,
    /// Pixels covered by `fill_solid` and `fill_contiguous` areas.
    pub run_pixels: usize,
}

impl<T> Counting<T> {
    pub fn new(inner: T) -> Self {
        Self {
            inner,
            draw_iter_pixels: 0,
            fill_solid_calls: 0,
            fill_contiguous_calls: 0,
            run_pixels: 0,
        }
    }
}

impl<T: OriginDimensions> OriginDimensions for Counting<T> {
    fn size(&self) -> Size {
        self.inner.size()
    }
}

impl<T: DrawTarget + OriginDimensions> DrawTarget for Counting<T> {
    type Color = T::Color;
    type Error = T::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<T::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), T::Error> {
        let pixels: Vec<_> = pixels.into_iter().collect();
        self.draw_iter_pixels += pixels.len();
        self.inner.draw_iter(pixels)
    }

    fn fill_solid(
        &mut self,
        area: &embedded_graphics::primitives::Rectangle,
        color: T::Color,
    ) -> Result<(), T::Error> {
        self.fill_solid_calls += 1;
        self.run_pixels += (area.size.width * area.size.height) as usize;
        self.inner.fill_solid(area, color)
    }

    fn fill_contiguous<I: IntoIterator<Item = T::Color>>(
        &mut self,
        area: &embedded_graphics::primitives::Rectangle,
        colors: I,
    ) -> Result<(), T::Error> {
        self.fill_contiguous_calls += 1;
        self.run_pixels += (area.size.width * area.size.height) as usize;
        self.inner.fill_contiguous(area, colors)
    }
}

/// An escape-time view from f64 numbers (every test view is within `Coord`'s range).
pub fn escape_view(
    fractal: tinyfractal::Fractal,
    centre: (f64, f64),
    width: f64,
    size: (u32, u32),
    max: u32,
) -> tinyfractal::View {
    let c = |v: f64| tinyfractal::Coord::from_f64(v).unwrap();
    tinyfractal::View::new(
        fractal,
        (c(centre.0), c(centre.1)),
        c(width),
        Size::new(size.0, size.1),
        max,
    )
    .unwrap()
}

/// Every pixel's value of `view`, row by row, by `algorithm`.
pub fn escape_values(
    view: tinyfractal::View,
    algorithm: tinyfractal::escape::Algorithm,
) -> Vec<u16> {
    let size = view.size();
    let mut values = vec![0; (size.width * size.height) as usize];
    let mut sink = tinyfractal::render::DwellBuffer::new(&mut values, size.width);
    let Ok(_) = tinyfractal::escape::Render::new(view, algorithm).run(&mut sink);
    values
}

/// The sample point of pixel (i, j), as the view defines it, in f64.
pub fn sample_point(view: &tinyfractal::View, i: u32, j: u32) -> (f64, f64) {
    let (size, d) = (view.size(), view.spacing().to_f64());
    let (re, im) = view.centre();
    (
        re.to_f64() + (f64::from(i) + 0.5 - f64::from(size.width) / 2.0) * d,
        im.to_f64() - (f64::from(j) + 0.5 - f64::from(size.height) / 2.0) * d,
    )
}

/// A view's Julia parameter in f64, or `None` for the Mandelbrot set.
pub fn julia_parameter(view: &tinyfractal::View) -> Option<(f64, f64)> {
    match view.fractal() {
        tinyfractal::Fractal::Mandelbrot => None,
        tinyfractal::Fractal::Julia { re, im } => Some((re.to_f64(), im.to_f64())),
    }
}

/// Decimal text (`-0.25`, `1e-30`) to fixed point with `bits` fractional bits, rounded
/// toward −∞ (independent of the crate's parser).
pub fn decimal_fixed(text: &str, bits: u32) -> num_bigint::BigInt {
    use num_bigint::BigInt;
    let (mantissa, exponent) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i64>().unwrap()),
        None => (text, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: BigInt = format!("{whole}{fraction}").parse().unwrap();
    let power = exponent - fraction.len() as i64;
    let scaled = digits << bits;
    if power >= 0 {
        scaled * BigInt::from(10).pow(power as u32)
    } else {
        let divisor = BigInt::from(10).pow((-power) as u32);
        let quotient = &scaled / &divisor;
        // BigInt division truncates toward zero; floor it.
        if &quotient * &divisor != scaled && scaled < BigInt::from(0) {
            quotient - 1
        } else {
            quotient
        }
    }
}
