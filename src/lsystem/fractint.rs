//! Fractint's `.l` files: entries `Name { ... }`, read straight from a `&str`.
//!
//! As Fractint reads them: an entry's name ends at a space, tab, `(`, `;` or `{`; entries
//! named `comment`, or with no name, are not systems; text after `;` is a comment; the line
//! holding `{` is otherwise skipped; lines are case-insensitive and split on spaces, tabs
//! and `=`; `Angle n`, `Axiom s` and `c=s` lines (repeated rule lines append); `}` ends it.
//!
//! Where a `}` is missing, Fractint read on into the next entry. A `NAME {` line inside an
//! entry ends it here, and the entry reports that its `}` seems missing (Fractint called the
//! line a syntax error); the next entry is read as written. What Fractint accepted is drawn
//! as it drew it, with a [`ReadWarning`] to show: a second `Axiom` or `Angle` (the last one
//! counts), a `U {` line (a rule rewriting `U` to `{`), a lone `{` (a rule for `{`).

use super::alphabet::Dialect;
use super::grammar::Grammar;
use crate::error::{Error, Location, ReadError, ReadWarning};
use crate::math::{Angle, Real, MAX_ANGLE_DIVISIONS};

/// A `.l` file's text.
#[derive(Debug, Clone, Copy)]
pub struct LFile<'a> {
    text: &'a str,
}

impl<'a> LFile<'a> {
    /// Wraps the text of a `.l` file; nothing is read until asked.
    pub const fn new(text: &'a str) -> Self {
        Self { text }
    }

    /// The entries, in file order. An entry without its closing `}` ends the iteration
    /// with an error.
    pub fn entries(&self) -> Entries<'a> {
        Entries {
            text: self.text,
            position: 0,
            line: 1,
        }
    }

    /// The grammar of the entry called `name` (case-insensitive).
    pub fn find(&self, name: &str) -> Result<Grammar<'a>, Error> {
        self.entry(name)?.grammar()
    }

    /// The entry called `name` (case-insensitive), for its [`warnings`](Entry::warnings)
    /// as well as its grammar.
    pub fn entry(&self, name: &str) -> Result<Entry<'a>, Error> {
        for entry in self.entries() {
            let entry = entry?;
            if entry.name.eq_ignore_ascii_case(name) {
                return Ok(entry);
            }
        }
        Err(Error::Read(ReadError::UnknownSystem))
    }
}

/// One entry of a `.l` file: a name and the text between its braces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entry<'a> {
    name: &'a str,
    /// The line the name is on.
    line: u32,
    body: &'a str,
    /// The line the body starts on.
    body_line: u32,
    /// The line of a `NAME {` that ended the body before any `}`.
    interrupted_by: Option<u32>,
}

impl<'a> Entry<'a> {
    /// The entry's name as written.
    pub const fn name(&self) -> &'a str {
        self.name
    }

    /// The 1-based line the entry starts on.
    pub const fn line(&self) -> u32 {
        self.line
    }

    /// The text between the entry's braces (without the `{` line).
    pub const fn body(&self) -> &'a str {
        self.body
    }

    /// Reads the entry into a grammar (Fractint dialect).
    pub fn grammar(&self) -> Result<Grammar<'a>, Error> {
        self.read(true)
    }

    /// Reads the entry to derive its string only: an entry with no `Angle` line (the
    /// lecture's algae, A → AB, B → A) is accepted, its grammar turning by a quarter turn
    /// that a derivation never uses.
    pub fn grammar_to_derive(&self) -> Result<Grammar<'a>, Error> {
        self.read(false)
    }

    /// The entry's grammar; with `angle_required` false, a quarter turn where no angle is
    /// given.
    fn read(&self, angle_required: bool) -> Result<Grammar<'a>, Error> {
        if let Some(next) = self.interrupted_by {
            return Err(Error::Read(ReadError::EntryRunsIntoNext {
                entry: self.line,
                next,
            }));
        }
        let mut axiom = None;
        let mut angle = None;
        for (line, words) in self.lines() {
            let mut words = words;
            let Some((keyword, keyword_at)) = words.next() else {
                continue;
            };
            let at = |column: u32| Location { line, column };
            if keyword.eq_ignore_ascii_case("axiom") {
                axiom = Some(
                    words
                        .next()
                        .map_or(("", at(keyword_at)), |(w, c)| (w, at(c))),
                );
            } else if keyword.eq_ignore_ascii_case("angle") {
                let (value, column) = words.next().ok_or(Error::Read(ReadError::MissingAngle))?;
                if value.contains('.') && Real::parse_signed(value).is_some() {
                    return Err(Error::Read(ReadError::AngleNotWhole { at: at(column) }));
                }
                let parsed = value.parse::<i64>().ok();
                let out_of_range = Error::Read(ReadError::AngleOutOfRange {
                    value: parsed.unwrap_or(0),
                    max: MAX_ANGLE_DIVISIONS,
                    at: at(column),
                });
                let divisions = parsed
                    .and_then(|v| u16::try_from(v).ok())
                    .filter(|n| (1..=MAX_ANGLE_DIVISIONS).contains(n))
                    .ok_or(out_of_range)?;
                angle = Some(Angle::Divisions(divisions));
            } else if keyword.len() != 1 {
                let error = if Real::parse_signed(keyword).is_some() {
                    ReadError::RowOfNumbers { line }
                } else {
                    ReadError::UnknownLine { at: at(keyword_at) }
                };
                return Err(Error::Read(error));
            } else {
                words.next();
            }
            if let Some((_, column)) = words.next() {
                return Err(Error::Read(ReadError::ExtraText { at: at(column) }));
            }
        }
        let angle = match angle {
            Some(angle) => angle,
            None if !angle_required => Angle::Divisions(4),
            None => return Err(Error::Read(ReadError::MissingAngle)),
        };
        let (axiom, axiom_at) = axiom.ok_or(Error::Read(ReadError::MissingAxiom))?;
        let mut grammar = Grammar::new_at(Dialect::Fractint, axiom, angle, axiom_at)?;
        for (line, mut words) in self.lines() {
            let Some((symbol, symbol_at)) = words.next() else {
                continue;
            };
            let mut chars = symbol.chars();
            if let (Some(c), None) = (chars.next(), chars.next()) {
                let (body, column) = words.next().unwrap_or(("", symbol_at + 2));
                grammar.add_rule_at(c, body, Location { line, column })?;
            }
        }
        Ok(grammar)
    }

    /// What this entry does that Fractint accepted but that is probably a mistake (most
    /// often a missing `}`): the entry draws as Fractint drew it, and a front end shows these.
    pub fn warnings(&self) -> Warnings<'a> {
        Warnings {
            lines: self.body.split('\n'),
            line: self.body_line,
            first_axiom: None,
            first_angle: None,
        }
    }

    /// The body's lines, comments removed, as words with their 1-based columns.
    fn lines(&self) -> impl Iterator<Item = (u32, Words<'a>)> + 'a {
        let first = self.body_line;
        self.body.split('\n').enumerate().map(move |(index, line)| {
            let code = line.split(';').next().unwrap_or_default();
            let number = first.saturating_add(u32::try_from(index).unwrap_or(u32::MAX));
            (
                number,
                Words {
                    text: code,
                    position: 0,
                },
            )
        })
    }
}

/// The words of one line and their columns; separators are spaces, tabs, `\r` and `=`.
#[derive(Debug, Clone)]
struct Words<'a> {
    text: &'a str,
    position: usize,
}

impl<'a> Iterator for Words<'a> {
    type Item = (&'a str, u32);

    fn next(&mut self) -> Option<Self::Item> {
        let is_separator = |b: u8| matches!(b, b' ' | b'\t' | b'\r' | b'=');
        let bytes = self.text.as_bytes();
        let start = self.position
            + bytes
                .get(self.position..)?
                .iter()
                .position(|&b| !is_separator(b))?;
        let length = bytes
            .get(start..)?
            .iter()
            .position(|&b| is_separator(b))
            .unwrap_or(bytes.len() - start);
        self.position = start + length;
        let word = self.text.get(start..start + length)?;
        Some((word, u32::try_from(start + 1).unwrap_or(u32::MAX)))
    }
}

/// The warnings of an [`Entry`], in line order.
#[derive(Debug, Clone)]
pub struct Warnings<'a> {
    lines: core::str::Split<'a, char>,
    /// The number of the next line.
    line: u32,
    first_axiom: Option<u32>,
    first_angle: Option<u32>,
}

impl Iterator for Warnings<'_> {
    type Item = ReadWarning;

    fn next(&mut self) -> Option<ReadWarning> {
        loop {
            let text = self.lines.next()?;
            let line = self.line;
            self.line = self.line.saturating_add(1);
            let mut words = Words {
                text: text.split(';').next().unwrap_or_default(),
                position: 0,
            }
            .map(|(word, _)| word);
            let Some(first) = words.next() else {
                continue;
            };
            let repeated = |seen: &mut Option<u32>| match *seen {
                Some(first) => Some(first),
                None => {
                    *seen = Some(line);
                    None
                }
            };
            if first.eq_ignore_ascii_case("axiom") {
                if let Some(first) = repeated(&mut self.first_axiom) {
                    return Some(ReadWarning::RepeatedAxiom { first, again: line });
                }
            } else if first.eq_ignore_ascii_case("angle") {
                if let Some(first) = repeated(&mut self.first_angle) {
                    return Some(ReadWarning::RepeatedAngle { first, again: line });
                }
            } else if first == "{" {
                return Some(ReadWarning::LoneBrace { line });
            } else if let (Some(symbol), Some("{")) = (single_char(first), words.next()) {
                return Some(ReadWarning::BraceRule { symbol, line });
            }
        }
    }
}

/// Whether a line (comment removed) opens an entry: a name of two or more characters, not
/// `Axiom` or `Angle` and without `=`, then `{` or `(`.
fn is_entry_header(code: &str) -> bool {
    let line = code.trim_start_matches([' ', '\t', '\r']);
    let name_length = line.find([' ', '\t', '(', '{', '\r']).unwrap_or(line.len());
    let (name, rest) = line.split_at_checked(name_length).unwrap_or((line, ""));
    name.len() > 1
        && !name.contains('=')
        && !name.eq_ignore_ascii_case("axiom")
        && !name.eq_ignore_ascii_case("angle")
        && rest.trim_start_matches([' ', '\t']).starts_with(['{', '('])
}

/// Whether the text's first line ends with a lone carriage return (old Mac OS files), which
/// would make the whole file one line.
fn ends_lines_with_cr_only(text: &str) -> bool {
    text.find(['\r', '\n']).is_some_and(|end| {
        text.get(end..)
            .is_some_and(|rest| rest.starts_with('\r') && !rest.starts_with("\r\n"))
    })
}

/// The character of a one-character word.
fn single_char(word: &str) -> Option<char> {
    let mut chars = word.chars();
    chars.next().filter(|_| chars.next().is_none())
}

/// Iterator over the entries of a [`LFile`].
#[derive(Debug, Clone)]
pub struct Entries<'a> {
    text: &'a str,
    position: usize,
    line: u32,
}

impl<'a> Entries<'a> {
    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.position).copied()
    }

    fn bump(&mut self) {
        if self.peek() == Some(b'\n') {
            self.line += 1;
        }
        self.position += 1;
    }

    fn skip_comment(&mut self) {
        while self.peek().is_some_and(|b| b != b'\n') {
            self.bump();
        }
    }

    /// Moves past the next `target` outside comments; false at the end of the text.
    fn skip_past(&mut self, target: u8) -> bool {
        while let Some(byte) = self.peek() {
            if byte == b';' {
                self.skip_comment();
                continue;
            }
            self.bump();
            if byte == target {
                return true;
            }
        }
        false
    }
}

impl<'a> Iterator for Entries<'a> {
    type Item = Result<Entry<'a>, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.position == 0 && ends_lines_with_cr_only(self.text) {
            self.position = self.text.len();
            return Some(Err(Error::Read(ReadError::OldMacLineEndings)));
        }
        loop {
            // Skip blank space and comments up to a name.
            while let Some(byte) = self.peek() {
                match byte {
                    b';' => self.skip_comment(),
                    b' ' | b'\t' | b'\r' | b'\n' | 0x1a => self.bump(),
                    _ => break,
                }
            }
            self.peek()?;
            let line = self.line;
            let name_start = self.position;
            while self
                .peek()
                .is_some_and(|b| !matches!(b, b' ' | b'\t' | b'(' | b';' | b'{' | b'\r' | b'\n'))
            {
                self.bump();
            }
            let name = self.text.get(name_start..self.position).unwrap_or_default();
            let unterminated = Error::Read(ReadError::UnterminatedEntry {
                at: Location { line, column: 1 },
            });
            if !self.skip_past(b'{') {
                self.position = self.text.len();
                return Some(Err(unterminated));
            }
            // The rest of the `{` line is not read (Fractint skips it), unless it closes.
            let brace_line_end = self.text.get(self.position..).and_then(|rest| {
                let end = rest.find('\n').unwrap_or(rest.len());
                rest.get(..end)
            });
            let closes_at_once = brace_line_end.is_some_and(|rest| {
                rest.split(';')
                    .next()
                    .is_some_and(|code| code.contains('}'))
            });
            if !closes_at_once {
                self.skip_comment();
                self.bump();
            }
            let body_start = self.position;
            let body_line = self.line;
            let mut interrupted_by = None;
            let body_end = loop {
                let rest = self.text.get(self.position..).unwrap_or_default();
                if rest.is_empty() {
                    return Some(Err(unterminated));
                }
                let line_length = rest.find('\n').map_or(rest.len(), |end| end + 1);
                let line_text = rest.get(..line_length).unwrap_or_default();
                let code = line_text.split(';').next().unwrap_or_default();
                if let Some(brace) = code.find('}') {
                    let end = self.position + brace;
                    self.position = end + 1;
                    break end;
                }
                if is_entry_header(code) {
                    interrupted_by = Some(self.line);
                    break self.position;
                }
                self.position += line_length;
                if line_text.ends_with('\n') {
                    self.line += 1;
                }
            };
            let body = self.text.get(body_start..body_end).unwrap_or_default();
            if name.is_empty() || name.eq_ignore_ascii_case("comment") {
                continue;
            }
            return Some(Ok(Entry {
                name,
                line,
                body,
                body_line,
                interrupted_by,
            }));
        }
    }
}
