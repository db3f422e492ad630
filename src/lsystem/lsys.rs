//! `.lsys` files: systems in a notation close to cpfg's, so that ABOP's examples paste in.
//!
//! ```text
//! # A comment, to the end of the line.
//! plant {
//!   axiom: X
//!   angle: 22.5            # degrees
//!   X --> F-[[X]+X]+F[+FX]-X
//!   F --> FF
//! }
//! ```
//!
//! Several systems to a file, each `name { ... }` on lines of their own. Inside, `key:
//! value` lines (`axiom:`, `angle:` in degrees, `seed:` for the stochastic choices;
//! `ignore:` and `define:` are read for the productions that will use them; the general
//! engine's `width: W S`, `tropism: TX,TY,TZ E`, `colors: RRGGBB ...` and
//! `homomorphism:`, after which productions apply when drawing only) and
//! productions `pred --> successor`, one symbol to a string in ABOP's notation
//! (case-sensitive; `F` draws, `f` moves, `+ - |` turn, `[ ]` branch; spaces between
//! symbols are dropped), or stochastic alternatives `pred --> successor : probability`.
//! Productions with context (`lc < pred > rc`), conditions (`: cond`) or parameters are
//! named in a [`ReadError::Unsupported`] error: this reader does not derive them yet.

use embedded_graphics::pixelcolor::Rgb888;

use super::alphabet::Dialect;
use super::grammar::Grammar;
use super::parametric::grammar::{
    constant, ParametricGrammar, Place, DEFAULT_WIDTH_STEP, MAX_CONSTANTS,
};
use super::parametric::tropism::Tropism;
use crate::error::{Error, Location, ReadError, Unsupported};
use crate::math::{Angle, Real};

/// A `.lsys` file's text.
#[derive(Debug, Clone, Copy)]
pub struct LsysFile<'a> {
    text: &'a str,
}

/// One system of a `.lsys` file: its name and the lines between its braces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LsysEntry<'a> {
    name: &'a str,
    line: u32,
    body: &'a str,
    body_line: u32,
}

impl<'a> LsysFile<'a> {
    /// Wraps the text of a `.lsys` file; nothing is read until asked.
    pub const fn new(text: &'a str) -> Self {
        Self { text }
    }

    /// The systems, in file order; a malformed block ends the iteration with its error.
    pub fn entries(&self) -> LsysEntries<'a> {
        LsysEntries {
            text: self.text,
            position: 0,
            line: 0,
            failed: false,
        }
    }

    /// The system called `name` (case-insensitive, as in `.l` files).
    pub fn entry(&self, name: &str) -> Result<LsysEntry<'a>, Error> {
        for entry in self.entries() {
            let entry = entry?;
            if entry.name.eq_ignore_ascii_case(name) {
                return Ok(entry);
            }
        }
        Err(Error::Read(ReadError::UnknownSystem))
    }

    /// The grammar of the system called `name`.
    pub fn find(&self, name: &str) -> Result<Grammar<'a>, Error> {
        self.entry(name)?.grammar()
    }
}

/// A line without its `#` comment and surrounding space.
fn code(line: &str) -> &str {
    line.split('#').next().unwrap_or_default().trim()
}

/// The name of a line `name {`, if it is one.
fn opening(code: &str) -> Option<&str> {
    let name = code.strip_suffix('{')?.trim_end();
    (!name.is_empty() && !name.contains(char::is_whitespace)).then_some(name)
}

/// Iterator over the systems of an [`LsysFile`].
#[derive(Debug, Clone)]
pub struct LsysEntries<'a> {
    text: &'a str,
    /// Byte position of the next line.
    position: usize,
    /// Lines read so far.
    line: u32,
    failed: bool,
}

impl<'a> LsysEntries<'a> {
    /// The next line and the byte position it starts at.
    fn next_line(&mut self) -> Option<(&'a str, usize)> {
        let rest = self
            .text
            .get(self.position..)
            .filter(|rest| !rest.is_empty())?;
        let length = rest.find('\n').map_or(rest.len(), |end| end + 1);
        let start = self.position;
        self.position += length;
        self.line += 1;
        rest.get(..length).map(|line| (line, start))
    }

    fn fail(&mut self, error: ReadError) -> Option<Result<LsysEntry<'a>, Error>> {
        self.failed = true;
        Some(Err(Error::Read(error)))
    }
}

impl<'a> Iterator for LsysEntries<'a> {
    type Item = Result<LsysEntry<'a>, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed {
            return None;
        }
        // Up to the next `name {`.
        let (name, line) = loop {
            let (text, _) = self.next_line()?;
            let code = code(text);
            if code.is_empty() {
                continue;
            }
            match opening(code) {
                Some(name) => break (name, self.line),
                None => {
                    let at = Location {
                        line: self.line,
                        column: 1,
                    };
                    return self.fail(ReadError::UnknownLine { at });
                }
            }
        };
        // The body: whole lines up to a line `}`.
        let (body_start, body_line) = (self.position, line + 1);
        loop {
            let Some((text, start)) = self.next_line() else {
                return self.fail(ReadError::UnterminatedEntry {
                    at: Location { line, column: 1 },
                });
            };
            let code = code(text);
            if code == "}" {
                let body = self.text.get(body_start..start).unwrap_or_default();
                return Some(Ok(LsysEntry {
                    name,
                    line,
                    body,
                    body_line,
                }));
            }
            if opening(code).is_some() {
                let next = self.line;
                return self.fail(ReadError::EntryRunsIntoNext { entry: line, next });
            }
        }
    }
}

impl<'a> LsysEntry<'a> {
    /// The system's name.
    pub const fn name(&self) -> &'a str {
        self.name
    }

    /// The 1-based line the system starts on.
    pub const fn line(&self) -> u32 {
        self.line
    }
}

impl<'a> LsysEntry<'a> {
    /// Reads the system into a grammar (ABOP's notation).
    pub fn grammar(&self) -> Result<Grammar<'a>, Error> {
        self.read(true)
    }

    /// Reads the system to derive its string only: a system with no `angle:` line (the
    /// lecture's algae, A → AB, B → A) is accepted, its grammar turning by a quarter turn
    /// that a derivation never uses.
    pub fn grammar_to_derive(&self) -> Result<Grammar<'a>, Error> {
        self.read(false)
    }

    /// The system's grammar; with `angle_required` false, a quarter turn where no angle is
    /// given.
    fn read(&self, angle_required: bool) -> Result<Grammar<'a>, Error> {
        let mut axiom = None;
        let mut angle = None;
        let mut seed = None;
        for (line, text) in self.lines() {
            let at = |column: usize| Location {
                line,
                column: u32::try_from(column + 1).unwrap_or(u32::MAX),
            };
            if let Some((key, value)) = key_value(text) {
                let value_at = at(offset(text, value));
                match key {
                    "axiom" => axiom = Some((value, value_at)),
                    "angle" => {
                        let degrees = Angle::parse_degrees(value)
                            .ok_or(Error::Read(ReadError::NotANumber { at: value_at }))?;
                        angle = Some(degrees);
                    }
                    "seed" => {
                        let number = value
                            .parse::<u32>()
                            .map_err(|_| Error::Read(ReadError::NotANumber { at: value_at }))?;
                        seed = Some(number);
                    }
                    // Kept for the productions that use them, which are not derived yet;
                    // the colours are the caller's palette.
                    "ignore" | "define" | "colors" => {}
                    _ => return Err(Error::Read(ReadError::UnknownLine { at: at(0) })),
                }
            } else if find_str(text, "-->").is_none() {
                let column = text.len() - text.trim_start().len();
                return Err(Error::Read(ReadError::UnknownLine { at: at(column) }));
            }
        }
        let angle = match angle {
            Some(angle) => angle,
            None if !angle_required => Angle::Divisions(4),
            None => return Err(Error::Read(ReadError::MissingAngle)),
        };
        let (axiom, axiom_at) = axiom.ok_or(Error::Read(ReadError::MissingAxiom))?;
        let mut grammar = Grammar::new_at(Dialect::Abop, axiom, angle, axiom_at)?;
        grammar.set_seed(seed.unwrap_or(0));
        let mut seen = [false; 128];
        let mut sums = ProbabilitySums::default();
        for (line, text) in self.lines() {
            let Some((left, right)) = split_at_str(text, "-->") else {
                continue;
            };
            let at = |part: &str| Location {
                line,
                column: u32::try_from(offset(text, part) + 1).unwrap_or(u32::MAX),
            };
            // Unsupported notation is reported at its first character.
            let unsupported = |feature, part: &str, marks: &[char]| {
                let from = part.find(marks).unwrap_or(0);
                Error::Read(ReadError::Unsupported {
                    feature,
                    at: at(part.get(from..).unwrap_or(part)),
                })
            };
            // `lc < pred > rc : condition`: context markers come before the condition.
            let before_condition = left.split(':').next().unwrap_or(left);
            if before_condition.contains(['<', '>']) {
                return Err(unsupported(Unsupported::Context, left, &['<', '>']));
            }
            if left.contains(':') {
                return Err(unsupported(Unsupported::Condition, left, &[':']));
            }
            // `--> successor : probability`: a stochastic alternative.
            let (right, probability) = match right.rsplit_once(':') {
                Some((successor, p)) => {
                    let p = p.trim();
                    let value = Real::parse_decimal(p)
                        .ok_or(Error::Read(ReadError::NotANumber { at: at(p) }))?;
                    sums.add(left, value, at(left.trim_start()))?;
                    (successor, Some(value))
                }
                None => (right, None),
            };
            for part in [left, right] {
                if part.contains('(') {
                    return Err(unsupported(Unsupported::Parameters, part, &['(']));
                }
            }
            let predecessor = left.trim();
            let mut chars = predecessor.chars();
            let (Some(symbol), None) = (chars.next(), chars.next()) else {
                return Err(Error::Read(ReadError::NotOneSymbol {
                    at: at(predecessor),
                }));
            };
            let index = usize::from(u8::try_from(symbol).unwrap_or(0) & 0x7f);
            if probability.is_none() && seen.get(index).copied().unwrap_or(false) {
                return Err(unsupported(Unsupported::SecondProduction, predecessor, &[]));
            }
            if let Some(slot) = seen.get_mut(index) {
                *slot = true;
            }
            let successor = right.trim();
            grammar.add_production(symbol, successor, probability, at(successor))?;
        }
        sums.check()?;
        Ok(grammar)
    }

    /// The body's lines with their numbers, comments removed, blank ones skipped.
    fn lines(&self) -> impl Iterator<Item = (u32, &'a str)> + 'a {
        let first = self.body_line;
        self.body
            .split('\n')
            .enumerate()
            .map(move |(index, line)| {
                let number = first.saturating_add(u32::try_from(index).unwrap_or(u32::MAX));
                (
                    number,
                    line.split('#').next().unwrap_or_default().trim_end(),
                )
            })
            .filter(|(_, line)| !line.trim().is_empty())
    }
}

impl<'a> LsysEntry<'a> {
    /// The colours of its `colors:` line (`colors: 5a3a1e 7a5230 3f6b2a ...`, six
    /// hexadecimal digits each, spaces or commas between; a `#` starts a comment as
    /// everywhere), the colour map its colour modules index; empty without one. At most `N` are kept: more is an
    /// error naming the first one too many.
    pub fn colors<const N: usize>(&self) -> Result<heapless::Vec<Rgb888, N>, Error> {
        let mut colors = heapless::Vec::new();
        for (line, text) in self.lines() {
            let Some(("colors", value)) = key_value(text) else {
                continue;
            };
            let tokens = value.split([' ', '\t', ',']).filter(|t| !t.is_empty());
            for token in tokens {
                let at = Location {
                    line,
                    column: u32::try_from(offset(text, token) + 1).unwrap_or(u32::MAX),
                };
                let color = hex_color(token).ok_or(Error::Read(ReadError::NotAColor { at }))?;
                colors
                    .push(color)
                    .map_err(|_| Error::Read(ReadError::TooManyColors { max: N, at }))?;
            }
        }
        Ok(colors)
    }

    /// Whether the system needs the general engine (read it with
    /// [`parametric`](Self::parametric) then): parameters, conditions, contexts, or modules
    /// only it interprets, the 3D turns `& ^ \\ / $`, the scale symbols `r R`, the colour
    /// modules `' ; ,` and the cut `%`.
    pub fn is_parametric(&self) -> bool {
        let general = |string: &str| {
            string.contains(GENERAL_MODULES)
                || find_str(string, "env(").is_some()
                || string.contains(['D', 'T'])
        };
        self.lines().any(|(_, text)| match key_value(text) {
            Some(("tropism" | "width" | "homomorphism", _)) => true,
            Some((key, value)) => key == "axiom" && (value.contains('(') || general(value)),
            None => split_at_str(text, "-->").is_some_and(|(left, right)| {
                left.contains(['(', ':', '<', '>']) || right.contains('(') || general(right)
            }),
        })
    }

    /// Reads a parametric system: `define:`d constants, the axiom, and productions
    /// `A(x,y) : condition --> successor` (ABOP 1.10). Context and probabilities are
    /// [`ReadError::Unsupported`] here.
    pub fn parametric(&self) -> Result<ParametricGrammar, Error> {
        let mut grammar = ParametricGrammar::new();
        self.parametric_into(&mut grammar)?;
        Ok(grammar)
    }

    /// [`parametric`](Self::parametric) into `grammar` (emptied first), in place: a grammar
    /// is 12 KiB, and each move of one is a copy on an MCU's stack.
    pub fn parametric_into(&self, grammar: &mut ParametricGrammar) -> Result<(), Error> {
        grammar.clear();
        let mut constants: heapless::Vec<(&'a str, Real), MAX_CONSTANTS> = heapless::Vec::new();
        let mut axiom = None;
        for (line, text) in self.lines() {
            let place = |part: &str| Place {
                base: Location {
                    line,
                    column: u32::try_from(offset(text, part) + 1).unwrap_or(u32::MAX),
                },
            };
            let Some((key, value)) = key_value(text) else {
                continue;
            };
            match key {
                "axiom" => axiom = Some((value, place(value))),
                "angle" => {
                    let at = place(value).at(0);
                    let degrees = Angle::parse_degrees(value)
                        .ok_or(Error::Read(ReadError::NotANumber { at }))?;
                    grammar.set_angle(degrees, at)?;
                }
                "ignore" => grammar.set_ignore(value),
                "tropism" => grammar.set_tropism(Some(tropism(value, place(value).at(0))?)),
                "width" => {
                    let at = place(value).at(0);
                    let mut numbers = value.split_whitespace().map(|number| {
                        Real::parse_signed(number)
                            .filter(|w| *w >= Real::ZERO)
                            .ok_or(Error::Read(ReadError::NotANumber { at }))
                    });
                    let width = numbers.next().unwrap_or(Ok(Real::ZERO))?;
                    let step = numbers.next().unwrap_or(Ok(DEFAULT_WIDTH_STEP))?;
                    if numbers.next().is_some() {
                        return Err(Error::Read(ReadError::NotANumber { at }));
                    }
                    grammar.set_width(width, step);
                }
                "seed" => {
                    let seed = value.parse::<u32>().map_err(|_| {
                        Error::Read(ReadError::NotANumber {
                            at: place(value).at(0),
                        })
                    })?;
                    grammar.set_seed(seed);
                }
                "define" => {
                    let (name, expression) =
                        value
                            .split_once('=')
                            .ok_or(Error::Read(ReadError::Expression {
                                at: place(value).at(0),
                            }))?;
                    let expression = expression.trim();
                    let value = constant(expression, &constants, place(expression))?;
                    constants.push((name.trim(), value)).map_err(|_| {
                        Error::Read(ReadError::TooManyRules {
                            max: MAX_CONSTANTS,
                            at: place(value_text(text)).at(0),
                        })
                    })?;
                }
                _ => {}
            }
        }
        let (text, place) = axiom.ok_or(Error::Read(ReadError::MissingAxiom))?;
        grammar.set_axiom(text, &constants, place)?;
        let mut sums = ProbabilitySums::default();
        for (line, text) in self.lines() {
            let Some((left, right)) = split_at_str(text, "-->") else {
                if key_value(text).is_some_and(|(key, _)| key == "homomorphism") {
                    grammar.start_homomorphism();
                }
                continue;
            };
            let place = |part: &str| Place {
                base: Location {
                    line,
                    column: u32::try_from(offset(text, part) + 1).unwrap_or(u32::MAX),
                },
            };
            let (left_side, condition) = match left.split_once(':') {
                Some((left_side, condition)) => (left_side, Some(condition.trim())),
                None => (left, None),
            };
            // `--> successor : probability`.
            let (successor, probability) = match right.rsplit_once(':') {
                Some((successor, p)) => {
                    let p = p.trim();
                    let value = constant(p, &constants, place(p))?;
                    sums.add(left, value, place(left.trim_start()).at(0))?;
                    (successor, Some((value, place(p).at(0))))
                }
                None => (right, None),
            };
            let left_side = left_side.trim();
            let successor = successor.trim();
            grammar.add_production(
                (left_side, place(left_side)),
                condition.map(|condition| (condition, place(condition))),
                (successor, place(successor)),
                probability,
                &constants,
            )?;
        }
        sums.check()?;
        grammar.check_arities()?;
        grammar.check_open()
    }
}

/// `TX,TY,TZ E`: a tropism's direction and elasticity.
fn tropism(value: &str, at: Location) -> Result<Tropism, Error> {
    let malformed = Error::Read(ReadError::MalformedTropism { at });
    let (direction, elasticity) = value
        .trim()
        .split_once(char::is_whitespace)
        .ok_or(malformed)?;
    let mut components = direction.split(',').map(|c| Real::parse_signed(c.trim()));
    let mut next = || components.next().flatten().ok_or(malformed);
    let direction = [next()?, next()?, next()?];
    if components.next().is_some() {
        return Err(malformed);
    }
    let elasticity = Real::parse_signed(elasticity.trim()).ok_or(malformed)?;
    Ok(Tropism {
        direction,
        elasticity,
    })
}

/// Most distinct left sides with probabilities in one system.
const MAX_STOCHASTIC_SIDES: usize = 16;

/// The probabilities given for each left side (contexts, predecessor and condition as
/// written), which must sum to 1.
#[derive(Debug, Default)]
struct ProbabilitySums<'a> {
    sides: heapless::Vec<(&'a str, Real, Location), MAX_STOCHASTIC_SIDES>,
}

impl<'a> ProbabilitySums<'a> {
    fn add(&mut self, side: &'a str, probability: Real, at: Location) -> Result<(), Error> {
        let same = |known: &str| known.split_whitespace().eq(side.split_whitespace());
        if let Some((_, sum, _)) = self.sides.iter_mut().find(|(known, ..)| same(known)) {
            *sum = Real::from_bits(sum.to_bits().saturating_add(probability.to_bits()));
            return Ok(());
        }
        self.sides.push((side, probability, at)).map_err(|_| {
            Error::Read(ReadError::TooManyRules {
                max: MAX_STOCHASTIC_SIDES,
                at,
            })
        })
    }

    /// Each sum is 1 to within 0.005 (three thirds written `0.333` pass).
    fn check(&self) -> Result<(), Error> {
        let tolerance = (1u64 << Real::FRAC_BITS) / 200;
        for &(_, sum, at) in &self.sides {
            if sum.to_bits().abs_diff(Real::ONE.to_bits()) > tolerance {
                return Err(Error::Read(ReadError::ProbabilitiesDoNotSum { sum, at }));
            }
        }
        Ok(())
    }
}

/// Modules only the general engine interprets.
const GENERAL_MODULES: [char; 16] = [
    '&', '^', '\\', '/', '$', 'r', 'R', '\'', ';', ',', '%', '{', '}', '.', '!', '_',
];

/// The value part of a `key: value` line.
fn value_text(line: &str) -> &str {
    line.split_once(':').map_or(line, |(_, value)| value.trim())
}

/// `key: value` of a line, for the keys of the notation (`axiom:`, `angle:`, ...).
fn key_value(line: &str) -> Option<(&str, &str)> {
    let (key, value) = line.split_once(':')?;
    let key = key.trim();
    (!key.is_empty()
        && key.chars().all(|c| c.is_ascii_alphabetic())
        && find_str(line, "-->").is_none())
    .then(|| (key, value.trim()))
}

/// Where `pattern` first starts in `text`, by bytes: `str`'s own search of a string
/// pattern (two-way) costs about 5 KiB of Cortex-M flash, for lines of a few dozen bytes.
fn find_str(text: &str, pattern: &str) -> Option<usize> {
    if pattern.is_empty() {
        return Some(0);
    }
    text.as_bytes()
        .windows(pattern.len())
        .position(|window| window == pattern.as_bytes())
}

/// `text` before and after the first `pattern` (as `str::split_once`, through
/// [`find_str`]).
fn split_at_str<'t>(text: &'t str, pattern: &str) -> Option<(&'t str, &'t str)> {
    let at = find_str(text, pattern)?;
    Some((text.get(..at)?, text.get(at + pattern.len()..)?))
}

/// `RRGGBB` in hexadecimal.
fn hex_color(digits: &str) -> Option<Rgb888> {
    if digits.len() != 6 || !digits.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let channel = |at: usize| u8::from_str_radix(digits.get(at..at + 2)?, 16).ok();
    Some(Rgb888::new(channel(0)?, channel(2)?, channel(4)?))
}

/// Where `part`, a slice of `line`, starts in it.
fn offset(line: &str, part: &str) -> usize {
    (part.as_ptr() as usize).saturating_sub(line.as_ptr() as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The byte search agrees with `str`'s own, at the start, the end, twice, nowhere,
    /// after multi-byte characters and with an empty pattern.
    #[test]
    fn the_byte_search_agrees_with_str() {
        for text in [
            "-->F",
            "F-->",
            "F-->G-->H",
            "F->G",
            "ä β-->γ",
            "",
            "--",
            "env(x)",
        ] {
            for pattern in ["-->", "env(", ""] {
                assert_eq!(
                    find_str(text, pattern),
                    text.find(pattern),
                    "{text} {pattern}"
                );
                assert_eq!(
                    split_at_str(text, pattern),
                    text.split_once(pattern),
                    "{text} {pattern}"
                );
            }
        }
    }
}
