//! The systems a command names: read from a file (`.l` or `.lsys`, by content) or given
//! inline, with the file's warnings; and `list`, the names a file holds.

use std::path::Path;

use tinyfractal::{Grammar, LFile, LsysFile, ParametricGrammar};

use crate::args::Source;
use crate::console::{self, warn, Failure};
use crate::files::{entry_names, is_lsys, read_text, FileKind};

/// `tinyfractal list FILE`: the names of the systems a file holds, one a line.
pub fn list(path: &Path) -> Result<(), String> {
    let text = read_text(path)?;
    let failed = |e: tinyfractal::Error| format!("{}: {e}", path.display());
    let names: Vec<&str> = entry_names(FileKind::of(path, &text), &text)
        .into_iter()
        .collect::<Result<_, _>>()
        .map_err(failed)?;
    let mut listed = String::new();
    for name in names {
        listed.push_str(name);
        listed.push('\n');
    }
    console::print(&listed)
}

/// A system as a source names it: plain (Fractint, ABOP, stochastic) or parametric.
pub(crate) enum Loaded<'a> {
    Plain(Box<Grammar<'a>>),
    Parametric(Box<ParametricGrammar>),
}

/// The system a source names, the name to report it by, and the kind of its file (`None`
/// inline); warnings go to stderr. The file is read once, here.
pub(crate) fn load<'a>(
    source: &'a Source,
    file_text: &'a mut String,
) -> Result<(Loaded<'a>, String, Option<FileKind>), String> {
    load_for(source, file_text, Purpose::Draw)
}

/// What a system is loaded for: a drawing needs its angle, a derivation does not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Purpose {
    Draw,
    Derive,
}

/// [`load`] for `purpose`.
pub(crate) fn load_for<'a>(
    source: &'a Source,
    file_text: &'a mut String,
    purpose: Purpose,
) -> Result<(Loaded<'a>, String, Option<FileKind>), String> {
    Ok(match source {
        Source::File { path, name } => {
            *file_text = read_text(path)?;
            let file_text: &'a String = file_text;
            let failed = |e: tinyfractal::Error| format!("{name} in {}: {e}", path.display());
            if is_lsys(path, file_text)? {
                let entry = LsysFile::new(file_text).entry(name).map_err(failed)?;
                let loaded = if entry.is_parametric() {
                    Loaded::Parametric(Box::new(entry.parametric().map_err(failed)?))
                } else if purpose == Purpose::Derive {
                    Loaded::Plain(Box::new(entry.grammar_to_derive().map_err(failed)?))
                } else {
                    Loaded::Plain(Box::new(entry.grammar().map_err(failed)?))
                };
                return Ok((loaded, name.clone(), Some(FileKind::Lsys)));
            }
            let entry = LFile::new(file_text).entry(name).map_err(failed)?;
            let grammar = match purpose {
                Purpose::Derive => entry.grammar_to_derive(),
                Purpose::Draw => entry.grammar(),
            }
            .map_err(failed)?;
            for warning in entry.warnings() {
                warn(&format!("{name} in {}: {warning}", path.display()));
            }
            (
                Loaded::Plain(Box::new(grammar)),
                name.clone(),
                Some(FileKind::Fractint),
            )
        }
        Source::Inline {
            axiom,
            rules,
            angle,
            draw_symbols,
            dialect,
        } => {
            let label = "inline system";
            let with = |e: tinyfractal::Error| format!("{label}: {e}");
            let mut grammar = Grammar::new(*dialect, axiom, *angle)
                .map_err(with)?
                .with_draw_symbols(draw_symbols)
                .map_err(with)?;
            for (symbol, body) in rules {
                grammar = grammar
                    .with_rule(*symbol, body)
                    .map_err(|e| format!("{label}: rule {symbol}={body}: {e}"))?;
            }
            (
                Loaded::Plain(Box::new(grammar)),
                "lsystem".to_string(),
                None,
            )
        }
    })
}

/// `--seed` is for the stochastic productions only `.lsys` files have: given for a `.l`
/// file's or an inline system, it is a usage error, not ignored.
pub fn seed_applies(kind: Option<FileKind>, seed: Option<u32>, name: &str) -> Result<(), Failure> {
    if seed.is_some() && kind != Some(FileKind::Lsys) {
        return Err(Failure::Usage(format!(
            "--seed does not apply to {name}: only `.lsys` systems have stochastic \
             productions (leave out --seed)"
        )));
    }
    Ok(())
}
