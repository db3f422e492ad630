//! Where in a system's text a problem was found, for messages.

use core::fmt;

/// Where in the source text a problem was found (1-based; `line` is 0 for text that did not
/// come from a file, such as a rule passed on the command line).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Location {
    /// 1-based line in the file, or 0 when the text was not read from a file.
    pub line: u32,
    /// 1-based column (in bytes) within the line or the inline text.
    pub column: u32,
}

impl Location {
    /// A location inside inline text (no file line).
    pub const fn column(column: u32) -> Self {
        Self { line: 0, column }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "column {}", self.column)
        } else {
            write!(f, "line {}, column {}", self.line, self.column)
        }
    }
}
