//! `tinyfractal derive`: the string a system derives at an order, on one line, within
//! `--max-length`.

use std::io::{self, Write};

use clap::Args;

use tinyfractal::lsystem::{ParametricWalker, Walker, DEFAULT_BUDGET};

use crate::console::{self, Failure};
use crate::scene;
use crate::systems::{load_for, seed_applies, Loaded, Purpose, SystemOptions};

/// `derive`'s options.
#[derive(Debug, Args)]
pub struct DeriveOptions {
    #[command(flatten)]
    pub system: SystemOptions,
    /// The longest string printed, in symbols: an error past it (up to 10000000 checked
    /// before anything is printed; above, the string streams and stops at the limit)
    #[arg(long = "max-length", value_name = "N", default_value_t = DEFAULT_MAX_LENGTH)]
    pub max_length: u64,
}

/// `derive`'s default `--max-length`.
pub const DEFAULT_MAX_LENGTH: u64 = 1_000_000;

impl DeriveOptions {
    /// `derive`: the string at the order, on one line, if it is at most `--max-length`
    /// symbols (measured first, so nothing is printed past the limit).
    pub fn run(&self) -> Result<(), Failure> {
        derive(self)
    }
}

fn derive(arguments: &DeriveOptions) -> Result<(), Failure> {
    let source = arguments.system.source(Purpose::Derive)?;
    let mut file_text = String::new();
    let (loaded, name, kind) = load_for(&source, &mut file_text, Purpose::Derive)?;
    seed_applies(kind, arguments.system.seed, &name)?;
    let budget = derive_budget(arguments);
    let mut grammar = match loaded {
        Loaded::Plain(grammar) => *grammar,
        Loaded::Parametric(mut grammar, _) => {
            if let Some(seed) = arguments.system.seed {
                grammar.set_seed(seed);
            }
            let walk = || {
                ParametricWalker::<'_, { scene::DEPTH }>::new(&grammar, arguments.system.order)
                    .map(|walker| walker.with_budget(budget))
            };
            return Ok(print_derivation(walk, arguments, &name)?);
        }
    };
    if let Some(seed) = arguments.system.seed {
        grammar.set_seed(seed);
    }
    let walk = || {
        Walker::<'_, '_, { scene::DEPTH }>::with_capacity(&grammar, arguments.system.order).map(
            |walker| {
                let mut walker = walker.with_budget(budget);
                core::iter::from_fn(move || walker.next_symbol())
            },
        )
    };
    Ok(print_derivation(walk, arguments, &name)?)
}

/// Reads a walk may take: expansions that print nothing still take reads, so they are
/// bounded too.
fn derive_budget(arguments: &DeriveOptions) -> u64 {
    arguments.max_length.saturating_mul(64).max(DEFAULT_BUDGET)
}

/// Longest `--max-length` that is checked before anything is printed: counting this many
/// symbols takes well under a second.
const COUNTED_FIRST: u64 = 10_000_000;

/// Prints a derivation on one line if it has at most `--max-length` symbols. Up to
/// [`COUNTED_FIRST`], `walk` is walked once to count them, then again to print, so nothing
/// is printed past the limit and nothing is kept in memory; past it the string streams as
/// it is derived (`derive ... | head` ends at once) and the run stops with the error at
/// the limit.
fn print_derivation<W, I, T>(walk: W, arguments: &DeriveOptions, name: &str) -> Result<(), String>
where
    W: Fn() -> Result<I, tinyfractal::Error>,
    I: Iterator<Item = Result<T, tinyfractal::Error>>,
    T: std::fmt::Display,
{
    let order = arguments.system.order;
    let failed = |e: tinyfractal::Error| format!("{name} at order {order}: {e}");
    let too_long = || {
        format!(
            "{name} at order {order}: the derived string is longer than {} symbols: \
             lower the order or raise --max-length",
            arguments.max_length
        )
    };
    let counted_first = arguments.max_length <= COUNTED_FIRST;
    if counted_first {
        let mut length = 0u64;
        for symbol in walk().map_err(failed)? {
            symbol.map_err(failed)?;
            length += 1;
            if length > arguments.max_length {
                return Err(too_long());
            }
        }
    }
    /// Why printing stopped.
    enum Stop {
        Walk(tinyfractal::Error),
        TooLong,
        Output(io::Error),
    }
    let mut out = io::BufWriter::new(io::stdout().lock());
    let written = (|| -> Result<(), Stop> {
        let mut length = 0u64;
        for symbol in walk().map_err(Stop::Walk)? {
            length += 1;
            if length > arguments.max_length {
                return Err(Stop::TooLong);
            }
            write!(out, "{}", symbol.map_err(Stop::Walk)?).map_err(Stop::Output)?;
        }
        writeln!(out)
            .and_then(|()| out.flush())
            .map_err(Stop::Output)
    })();
    match written {
        Ok(()) => Ok(()),
        Err(Stop::Walk(e)) => Err(failed(e)),
        Err(Stop::TooLong) => {
            // What was printed ends its line, so the message is not glued to it.
            let _ = writeln!(out).and_then(|()| out.flush());
            Err(too_long())
        }
        Err(Stop::Output(e)) => Err(console::failed(&e)),
    }
}
