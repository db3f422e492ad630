//! Fractint's `.ifs` files: entries `name { ... }`, `name (3D) { ... }` for maps of space;
//! one map a line, `a b c d e f p` (x' = a·x + b·y + e, y' = c·x + d·y + f, chosen with
//! probability p), or in 3D the matrix row by row, the translation and p (13 numbers);
//! `;` starts a comment.

use super::maps::{AffineMap, Ifs, MAX_MAPS};
use crate::error::{Error, Location, ReadError};
use crate::math::Real;

/// A `.ifs` file's text.
#[derive(Debug, Clone, Copy)]
pub struct IfsFile<'a> {
    text: &'a str,
}

/// One entry of a `.ifs` file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IfsEntry<'a> {
    name: &'a str,
    three_d: bool,
    line: u32,
    /// The numbers: from after `{` to before `}`.
    body: &'a str,
    body_line: u32,
    body_column: u32,
}

/// The lines of `text` from line `first`, without comments.
fn lines(text: &str, first: u32) -> impl Iterator<Item = (u32, &str)> {
    text.split('\n').enumerate().map(move |(index, line)| {
        let number = first.saturating_add(u32::try_from(index).unwrap_or(u32::MAX));
        (number, line.split(';').next().unwrap_or_default())
    })
}

impl<'a> IfsFile<'a> {
    /// Wraps the text of a `.ifs` file; nothing is read until asked.
    pub const fn new(text: &'a str) -> Self {
        Self { text }
    }

    /// The entries, in file order; a malformed one ends the iteration with its error.
    pub fn entries(&self) -> impl Iterator<Item = Result<IfsEntry<'a>, Error>> + 'a {
        let text = self.text;
        let mut offset = 0usize;
        let mut line = 1u32;
        let mut failed = false;
        core::iter::from_fn(move || {
            if failed {
                return None;
            }
            let rest = text.get(offset..)?;
            // The next `{` outside comments.
            let mut open = None;
            let mut position = 0;
            for (current, raw) in (line..).zip(rest.split_inclusive('\n')) {
                let code = raw.split(';').next().unwrap_or_default();
                if let Some(brace) = code.find('{') {
                    open = Some((position + brace, current, position));
                    break;
                }
                position += raw.len();
            }
            let (brace, open_line, line_start) = open?;
            let header = rest.get(line_start..brace).unwrap_or_default().trim();
            let mark = header.char_indices().find_map(|(index, _)| {
                header
                    .get(index..index + 4)
                    .filter(|part| part.eq_ignore_ascii_case("(3d)"))
                    .map(|_| index)
            });
            let (name, three_d) = match mark {
                Some(mark) => (header.get(..mark).unwrap_or_default().trim(), true),
                None => (header, false),
            };
            let body_start = brace + 1;
            let Some(close) = rest.get(body_start..).and_then(|body| body.find('}')) else {
                failed = true;
                return Some(Err(Error::Read(ReadError::UnterminatedEntry {
                    at: Location {
                        line: open_line,
                        column: 1,
                    },
                })));
            };
            let body = rest.get(body_start..body_start + close).unwrap_or_default();
            let column = u32::try_from(brace - line_start + 2).unwrap_or(u32::MAX);
            let consumed = body_start + close + 1;
            let newlines = rest
                .get(..consumed)
                .unwrap_or_default()
                .matches('\n')
                .count();
            line = line.saturating_add(u32::try_from(newlines).unwrap_or(u32::MAX));
            offset += consumed;
            Some(Ok(IfsEntry {
                name,
                three_d,
                line: open_line,
                body,
                body_line: open_line,
                body_column: column,
            }))
        })
    }

    /// The entry called `name` (case-insensitive, as Fractint reads them).
    pub fn entry(&self, name: &str) -> Result<IfsEntry<'a>, Error> {
        for entry in self.entries() {
            let entry = entry?;
            if entry.name.eq_ignore_ascii_case(name) {
                return Ok(entry);
            }
        }
        Err(Error::Read(ReadError::UnknownSystem))
    }
}

impl<'a> IfsEntry<'a> {
    /// The entry's name.
    pub const fn name(&self) -> &'a str {
        self.name
    }

    /// Whether it is marked `(3D)`.
    pub const fn is_3d(&self) -> bool {
        self.three_d
    }

    /// The line its name is on.
    pub const fn line(&self) -> u32 {
        self.line
    }

    /// Reads the maps: 7 numbers a line (13 in 3D), probabilities summing to 1 (within
    /// 0.005, as Fractint's thirds written `.333333` do).
    pub fn ifs(&self) -> Result<Ifs, Error> {
        let mut ifs = Ifs::new();
        self.ifs_into(&mut ifs)?;
        Ok(ifs)
    }

    /// [`ifs`](Self::ifs) into `ifs` (emptied first), in place: no copy of the maps on an
    /// MCU's stack.
    pub fn ifs_into(&self, ifs: &mut Ifs) -> Result<(), Error> {
        let expected = if self.three_d { 13 } else { 7 };
        ifs.clear();
        if self.three_d {
            ifs.set_3d();
        }
        let mut sum: i64 = 0;
        // As written, for maps of probability 0 or less, which Fractint draws.
        let mut probabilities = [Real::ZERO; MAX_MAPS];
        let mut unchosen = false;
        for (line, code) in lines(self.body, self.body_line) {
            // The first line starts after the `{`.
            let base = if line == self.body_line {
                self.body_column
            } else {
                1
            };
            let column_of = |token: &str| {
                let offset = (token.as_ptr() as usize).saturating_sub(code.as_ptr() as usize);
                base.saturating_add(u32::try_from(offset).unwrap_or(u32::MAX))
            };
            let mut numbers = [Real::ZERO; 13];
            let mut found = 0;
            let mut first = None;
            for token in code.split([' ', '\t', '\r', ',']).filter(|t| !t.is_empty()) {
                let at = Location {
                    line,
                    column: column_of(token),
                };
                first.get_or_insert(at);
                let value =
                    Real::parse_signed(token).ok_or(Error::Read(ReadError::NotANumber { at }))?;
                if let Some(slot) = numbers.get_mut(found) {
                    *slot = value;
                }
                found += 1;
            }
            let Some(at) = first else { continue };
            if found != expected {
                return Err(Error::Read(ReadError::WrongColumnCount {
                    expected,
                    found,
                    at,
                }));
            }
            let n = |i: usize| numbers.get(i).copied().unwrap_or(Real::ZERO);
            let (map, probability) = if self.three_d {
                (
                    AffineMap {
                        matrix: [[n(0), n(1), n(2)], [n(3), n(4), n(5)], [n(6), n(7), n(8)]],
                        translation: [n(9), n(10), n(11)],
                    },
                    n(12),
                )
            } else {
                (
                    AffineMap::planar([n(0), n(1), n(2), n(3), n(4), n(5)]),
                    n(6),
                )
            };
            sum = sum.saturating_add(probability.to_bits());
            if let Some(slot) = probabilities.get_mut(ifs.len()) {
                *slot = probability;
            }
            // A map Fractint never chooses is weighed below, with all the others.
            let placeholder = if probability.to_bits() <= 0 {
                unchosen = true;
                Real::ONE
            } else {
                probability
            };
            ifs.add_at(map, placeholder, at)?;
        }
        let whole = Location {
            line: self.line,
            column: 1,
        };
        if ifs.is_empty() {
            return Err(Error::Read(ReadError::NoMaps { at: whole }));
        }
        let tolerance = (1i64 << Real::FRAC_BITS) / 200;
        if (sum - Real::ONE.to_bits()).abs() > tolerance {
            return Err(Error::Read(ReadError::ProbabilitiesDoNotSum {
                sum: Real::from_bits(sum),
                at: whole,
            }));
        }
        if unchosen {
            ifs.weigh_as_fractint(probabilities.get(..ifs.len()).unwrap_or(&[]));
        }
        Ok(())
    }
}
