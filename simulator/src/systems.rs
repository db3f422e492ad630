//! The systems a command names: read from a file (`.l` or `.lsys`, by content) or given
//! inline, with the file's warnings; and `list`, the names a file holds.

use std::path::{Path, PathBuf};

use clap::builder::NonEmptyStringValueParser;
use clap::{Args, ValueEnum};

use embedded_graphics::pixelcolor::Rgb888;
use tinyfractal::{Grammar, LFile, LsysFile, ParametricGrammar};

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
    /// The grammar and the colours of its `colors:` line (empty without one).
    Parametric(Box<ParametricGrammar>, Vec<Rgb888>),
}

/// Most colours a `colors:` line lists: a Fractint map's 256.
const MAX_ENTRY_COLORS: usize = 256;

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
                    let colors = entry.colors::<MAX_ENTRY_COLORS>().map_err(failed)?;
                    Loaded::Parametric(
                        Box::new(entry.parametric().map_err(failed)?),
                        colors.to_vec(),
                    )
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

/// The highest order an L-system command takes (the walkers' depth is one more).
const MAX_ORDER: i64 = crate::scene::DEPTH as i64 - 1;

/// A system, from a file or inline, and its order: what `render lsystem`, `derive` and
/// `animate growth` share.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct SystemOptions {
    /// A Fractint .l file, or an .lsys file (with --name)
    #[arg(
        long,
        value_name = "PATH.l",
        conflicts_with = "axiom",
        requires = "name"
    )]
    pub file: Option<PathBuf>,
    /// The system in the file (case-insensitive)
    #[arg(long, value_name = "NAME", requires = "file", value_parser = NonEmptyStringValueParser::new())]
    pub name: Option<String>,
    /// An inline system's axiom
    #[arg(long, value_name = "STR", allow_hyphen_values = true)]
    pub axiom: Option<String>,
    /// An inline rule, C=STR (repeat for more)
    #[arg(long = "rule", value_name = "C=STR", allow_hyphen_values = true, conflicts_with = "file", value_parser = parse_rule)]
    pub rules: Vec<(char, String)>,
    /// Divisions of a full turn
    #[arg(long, value_name = "N", conflicts_with_all = ["angle_deg", "file"])]
    pub angle: Option<u16>,
    /// A free angle in degrees, e.g. 22.5 or -90
    #[arg(
        long = "angle-deg",
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = "file",
        value_parser = parse_degrees
    )]
    pub angle_deg: Option<tinyfractal::Angle>,
    /// More symbols that draw (ABOP edge rewriting)
    #[arg(
        long = "draw-symbols",
        value_name = "CHARS",
        default_value = "",
        conflicts_with = "file"
    )]
    pub draw_symbols: String,
    /// The inline system's notation (default abop; .l files are Fractint's)
    #[arg(long, value_enum, conflicts_with = "file")]
    pub dialect: Option<DialectName>,
    /// The order (derivation steps), 0 to 256
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(0..=MAX_ORDER))]
    pub order: u32,
    /// The seed of stochastic productions (overrides the file's `seed:`)
    #[arg(long, value_name = "N")]
    pub seed: Option<u32>,
}

/// `--dialect`: the notation of an inline system.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DialectName {
    /// Fractint's .l notation
    Fractint,
    /// The Algorithmic Beauty of Plants' notation
    Abop,
}

impl SystemOptions {
    /// The system the options name. An inline system needs an angle to be drawn; to be
    /// derived it does not (a quarter turn stands in).
    pub fn source(&self, purpose: Purpose) -> Result<Source, Failure> {
        let options = self.clone();
        let angle_required = purpose == Purpose::Draw;
        Ok(match (options.file, options.axiom) {
            (Some(path), None) => Source::File {
                path,
                // `requires = "name"` makes it present.
                name: options.name.unwrap_or_default(),
            },
            (None, Some(axiom)) => {
                let angle = match (options.angle, options.angle_deg) {
                    (Some(n), _) => tinyfractal::Angle::Divisions(n),
                    (None, Some(degrees)) => degrees,
                    (None, None) if !angle_required => tinyfractal::Angle::Divisions(4),
                    (None, None) => {
                        return Err(Failure::Usage(
                            "an inline system needs --angle N or --angle-deg DEG".to_string(),
                        ))
                    }
                };
                Source::Inline {
                    axiom,
                    rules: options.rules,
                    angle,
                    draw_symbols: options.draw_symbols,
                    dialect: match options.dialect {
                        Some(DialectName::Fractint) => tinyfractal::Dialect::Fractint,
                        Some(DialectName::Abop) | None => tinyfractal::Dialect::Abop,
                    },
                }
            }
            _ => {
                return Err(Failure::Usage(
                    "give a system: --file PATH --name NAME, or --axiom STR".to_string(),
                ))
            }
        })
    }
}

/// Where the system comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// `--file PATH --name NAME`
    File {
        /// The file.
        path: PathBuf,
        /// The system's name in it.
        name: String,
    },
    /// `--axiom STR --rule C=STR ... (--angle N | --angle-deg DEG)`
    Inline {
        /// The axiom (`--axiom`).
        axiom: String,
        /// The rules (`--rule C=STR`), in order.
        rules: Vec<(char, String)>,
        /// The angle (`--angle` or `--angle-deg`).
        angle: tinyfractal::Angle,
        /// More symbols that draw (`--draw-symbols`).
        draw_symbols: String,
        /// The notation (`--dialect`).
        dialect: tinyfractal::Dialect,
    },
}

/// `--angle-deg`'s value.
fn parse_degrees(text: &str) -> Result<tinyfractal::Angle, String> {
    tinyfractal::Angle::parse_degrees(text)
        .ok_or_else(|| format!("`{text}` is not a number of degrees, e.g. 22.5 or -90"))
}

/// `--rule`'s value.
fn parse_rule(text: &str) -> Result<(char, String), String> {
    let (symbol, body) = text
        .split_once('=')
        .ok_or_else(|| format!("`{text}` is not C=STR"))?;
    let mut chars = symbol.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) => Ok((c, body.to_string())),
        _ => Err(format!("`{symbol}` must be exactly one symbol before `=`")),
    }
}
