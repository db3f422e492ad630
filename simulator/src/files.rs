//! Input files: bytes to text, which kind of file the text is (Fractint's `.l`, `.lsys`
//! or `.ifs`, by extension in any case or by content), and the names of its entries.

use std::path::Path;

use tinyfractal::{LFile, LsysFile};

/// The largest input file read: Fractint's own files are a few KiB, the largest public
/// collections a few hundred.
const MAX_INPUT_BYTES: u64 = 16 << 20;

/// The text of the file at `path` (see [`decode`]).
pub fn read_text(path: &Path) -> Result<String, String> {
    use std::io::Read;
    let cannot = |e: std::io::Error| format!("cannot read {}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(cannot)?;
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(format!("cannot read {}: it is a folder", path.display()));
    }
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    decode(path, &bytes)
}

/// The text of `bytes`, read from `path`.
///
/// UTF-8 (a byte-order mark skipped) or, failing that, 8-bit text as Fractint's own files are
/// (each byte its Latin-1 character). Too large a file, UTF-16 and binary files are named as
/// such.
pub fn decode(path: &Path, bytes: &[u8]) -> Result<String, String> {
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(format!(
            "{} is larger than {} MiB, the largest input read: give a text file (.l, .lsys, \
             .ifs or .map; such files are a few KiB)",
            path.display(),
            MAX_INPUT_BYTES >> 20
        ));
    }
    if bytes.starts_with(&[0xff, 0xfe]) || bytes.starts_with(&[0xfe, 0xff]) {
        return Err(format!(
            "{} is UTF-16 text: save it as UTF-8 (or 8-bit text, as Fractint's own files are)",
            path.display()
        ));
    }
    if bytes.contains(&0) {
        return Err(format!(
            "{} is a binary file, not text (it holds zero bytes): give a .l, .lsys, .ifs \
             or .map text file",
            path.display()
        ));
    }
    // A UTF-8 byte-order mark is no part of the text.
    let bytes = bytes.strip_prefix(&[0xef, 0xbb, 0xbf]).unwrap_or(bytes);
    Ok(match std::str::from_utf8(bytes) {
        Ok(text) => text.to_string(),
        Err(_) => bytes.iter().map(|&b| char::from(b)).collect(),
    })
}

/// What a text file holds, by its extension (in any case) or, without a known one, by
/// its content.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// Fractint's `.l` L-systems.
    Fractint,
    /// cpfg-like `.lsys` L-systems.
    Lsys,
    /// Fractint's `.ifs` maps.
    Ifs,
}

impl FileKind {
    /// The kind of the file at `path` holding `text`.
    pub fn of(path: &Path, text: &str) -> Self {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or_default();
        if extension.eq_ignore_ascii_case("lsys") {
            Self::Lsys
        } else if extension.eq_ignore_ascii_case("ifs") {
            Self::Ifs
        } else if Self::holds_ifs(text) {
            // Maps where L-systems were expected, whatever the extension (`.l` included).
            Self::Ifs
        } else if extension.eq_ignore_ascii_case("l") || !text.contains("-->") {
            Self::Fractint
        } else {
            Self::Lsys
        }
    }

    /// Whether `text`'s first entry reads as IFS maps and not as a Fractint L-system.
    fn holds_ifs(text: &str) -> bool {
        let maps = tinyfractal::IfsFile::new(text)
            .entries()
            .next()
            .is_some_and(|entry| entry.and_then(|entry| entry.ifs()).is_ok());
        let system = LFile::new(text)
            .entries()
            .next()
            .is_some_and(|entry| entry.and_then(|entry| entry.grammar()).is_ok());
        maps && !system
    }

    /// Refuses an IFS file where L-systems were asked for, naming it.
    pub fn lsystems(self, path: &Path) -> Result<Self, String> {
        if self == Self::Ifs {
            return Err(format!(
                "{} is an IFS file (Fractint's .ifs maps), not L-systems: draw its entries with \
                 `tinyfractal render ifs --file {} --name NAME`",
                path.display(),
                path.display()
            ));
        }
        Ok(self)
    }
}

/// Whether the file at `path` holding `text` is in the `.lsys` notation (`.l` otherwise),
/// or an error naming an IFS file.
pub(crate) fn is_lsys(path: &Path, text: &str) -> Result<bool, String> {
    Ok(FileKind::of(path, text).lsystems(path)? == FileKind::Lsys)
}

/// The names of the entries of `text`, a file of `kind`, each or the error reading it.
pub fn entry_names(kind: FileKind, text: &str) -> Vec<Result<&str, tinyfractal::Error>> {
    match kind {
        FileKind::Lsys => LsysFile::new(text)
            .entries()
            .map(|entry| entry.map(|entry| entry.name()))
            .collect(),
        FileKind::Fractint => LFile::new(text)
            .entries()
            .map(|entry| entry.map(|entry| entry.name()))
            .collect(),
        FileKind::Ifs => tinyfractal::IfsFile::new(text)
            .entries()
            .map(|entry| entry.map(|entry| entry.name()))
            .collect(),
    }
}
