//! Command-line parsing, by hand: the contract is small and the messages are ours.

use std::fmt;
use std::path::PathBuf;

/// What the user asked for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// `render lsystem ...`
    RenderLSystem(LSystemArgs),
    /// `render mandelbrot ...` and `render julia --c RE,IM ...`
    RenderEscape(EscapeArgs),
    /// `list PATH.l`
    List(PathBuf),
    /// `gallery [--out DIR]`
    Gallery { out: PathBuf },
    /// `help`, `--help`
    Help,
}

/// Where the system comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// `--file PATH --name NAME`
    File { path: PathBuf, name: String },
    /// `--axiom STR --rule C=STR ... (--angle N | --angle-deg DEG)`
    Inline {
        axiom: String,
        rules: Vec<(char, String)>,
        angle: InlineAngle,
        draw_symbols: String,
        dialect: tinyfractal::Dialect,
    },
}

/// `--angle N` or `--angle-deg DEG`.
#[derive(Debug, Clone, PartialEq)]
pub enum InlineAngle {
    Divisions(u16),
    Degrees(String),
}

/// Options every render takes.
#[derive(Debug, Clone, PartialEq)]
pub struct Common {
    pub width: u32,
    pub height: u32,
    pub out: Option<PathBuf>,
    pub segments: Option<PathBuf>,
    pub stats: bool,
    pub window: bool,
}

impl Default for Common {
    fn default() -> Self {
        Self {
            width: 320,
            height: 240,
            out: None,
            segments: None,
            stats: false,
            window: false,
        }
    }
}

impl Common {
    /// Takes one of the options every render has; false if `flag` is not one of them.
    fn take_flag(&mut self, flag: &str, options: &mut Options<'_>) -> Result<bool, UsageError> {
        match flag {
            "--size" => (self.width, self.height) = parse_size(options.value(flag)?)?,
            "--out" => self.out = Some(PathBuf::from(options.value(flag)?)),
            "--stats" => self.stats = true,
            "--window" => self.window = true,
            _ => return Ok(false),
        }
        Ok(true)
    }
}

/// `render lsystem`'s arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct LSystemArgs {
    pub source: Source,
    pub order: u32,
    pub common: Common,
}

/// `render mandelbrot` / `render julia`'s arguments, as text checked by the core.
#[derive(Debug, Clone, PartialEq)]
pub struct EscapeArgs {
    /// `None` for the Mandelbrot set, the parameter `(re, im)` for a Julia set.
    pub julia: Option<(String, String)>,
    pub centre: (String, String),
    pub width: String,
    pub max_iterations: u32,
    pub algorithm: tinyfractal::Algorithm,
    /// `None` for automatic.
    pub tier: Option<tinyfractal::Tier>,
    pub palette: String,
    pub common: Common,
    pub dwell: Option<PathBuf>,
}

/// A usage mistake, with what to do about it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UsageError(pub String);

impl fmt::Display for UsageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} (see `tinyfractal help`)", self.0)
    }
}

fn usage(message: impl Into<String>) -> UsageError {
    UsageError(message.into())
}

pub const HELP: &str = "\
tinyfractal: fixed-point fractals for small displays, rendered on the host

USAGE:
  tinyfractal render lsystem --file PATH.l --name NAME --order N [common options]
  tinyfractal render lsystem --axiom STR --rule C=STR [--rule ...] (--angle N | --angle-deg DEG)
                             [--draw-symbols CHARS] [--dialect fractint|abop] --order N [common]
  tinyfractal render mandelbrot [--center RE,IM] [--width W] [--max-iter N]
      [--algorithm exact|fast] [--precision auto|narrow|medium|standard|deep] [--palette NAME] [common]
  tinyfractal render julia --c RE,IM [same options as mandelbrot]
  tinyfractal list PATH.l            the systems in a file, one name a line
  tinyfractal gallery [--out DIR]    render the gallery (what `cargo run --release` does)

COMMON OPTIONS:
  --size WxH        picture size in pixels (default 320x240)
  --out PNG         write the picture there (default: NAME.png)
  --segments TXT    (lsystem) write every drawn segment, `x0 y0 x1 y1` in turtle units
  --dwell TXT       (mandelbrot, julia) write `W H MAXITER`, then H lines of W dwells
  --stats           print one line of statistics
  --window          show the picture in a window (needs the `window` feature)

DEFAULTS (mandelbrot, julia): --center -0.75,0 --width 3.5 --max-iter 256 --algorithm fast
  --precision auto --palette classic. Palettes: classic, fire, gray, bands, two-color.
";

/// Parses the arguments after the program name.
pub fn parse(args: &[String]) -> Result<Command, UsageError> {
    let mut words = args.iter().map(String::as_str);
    match words.next() {
        None => Ok(Command::Gallery {
            out: PathBuf::from("gallery"),
        }),
        Some("help" | "--help" | "-h") => Ok(Command::Help),
        Some("list") => {
            let path = words
                .next()
                .ok_or_else(|| usage("`list` needs a .l file"))?;
            if let Some(extra) = words.next() {
                return Err(usage(format!("unexpected `{extra}` after the file")));
            }
            Ok(Command::List(PathBuf::from(path)))
        }
        Some("gallery") => {
            let mut out = PathBuf::from("gallery");
            let rest: Vec<&str> = words.collect();
            let mut options = Options::new(&rest);
            while let Some(flag) = options.next_flag()? {
                match flag {
                    "--out" => out = PathBuf::from(options.value(flag)?),
                    _ => return Err(usage(format!("unknown option `{flag}` for `gallery`"))),
                }
            }
            Ok(Command::Gallery { out })
        }
        Some("render") => match words.next() {
            Some("lsystem") => {
                let rest: Vec<&str> = words.collect();
                parse_lsystem(&rest).map(Command::RenderLSystem)
            }
            Some(scene @ ("mandelbrot" | "julia")) => {
                let rest: Vec<&str> = words.collect();
                parse_escape(scene == "julia", &rest).map(Command::RenderEscape)
            }
            Some(other) => Err(usage(format!(
                "unknown scene `{other}`: use lsystem, mandelbrot or julia"
            ))),
            None => Err(usage(
                "`render` needs a scene: lsystem, mandelbrot or julia",
            )),
        },
        Some(other) => Err(usage(format!("unknown command `{other}`"))),
    }
}

/// Walks `--flag value` pairs.
struct Options<'s> {
    words: &'s [&'s str],
    position: usize,
}

impl<'s> Options<'s> {
    fn new(words: &'s [&'s str]) -> Self {
        Self { words, position: 0 }
    }

    fn next_flag(&mut self) -> Result<Option<&'s str>, UsageError> {
        let Some(&word) = self.words.get(self.position) else {
            return Ok(None);
        };
        self.position += 1;
        if word.starts_with("--") {
            Ok(Some(word))
        } else {
            Err(usage(format!("unexpected `{word}`: options start with --")))
        }
    }

    fn value(&mut self, flag: &str) -> Result<&'s str, UsageError> {
        let value = self
            .words
            .get(self.position)
            .copied()
            .ok_or_else(|| usage(format!("{flag} needs a value")))?;
        self.position += 1;
        Ok(value)
    }
}

fn parse_number<T: std::str::FromStr>(flag: &str, text: &str) -> Result<T, UsageError> {
    text.parse()
        .map_err(|_| usage(format!("{flag}: `{text}` is not a valid number")))
}

fn parse_size(text: &str) -> Result<(u32, u32), UsageError> {
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| usage(format!("--size: `{text}` is not WxH, e.g. 320x240")))?;
    Ok((parse_number("--size", w)?, parse_number("--size", h)?))
}

fn parse_lsystem(words: &[&str]) -> Result<LSystemArgs, UsageError> {
    let mut file = None;
    let mut name = None;
    let mut axiom = None;
    let mut rules = Vec::new();
    let mut angle = None;
    let mut draw_symbols = String::new();
    let mut dialect = None;
    let mut order = None;
    let mut common = Common::default();
    let mut options = Options::new(words);
    while let Some(flag) = options.next_flag()? {
        if common.take_flag(flag, &mut options)? {
            continue;
        }
        match flag {
            "--file" => file = Some(PathBuf::from(options.value(flag)?)),
            "--name" => name = Some(options.value(flag)?.to_string()),
            "--axiom" => axiom = Some(options.value(flag)?.to_string()),
            "--rule" => {
                let text = options.value(flag)?;
                let (symbol, body) = text
                    .split_once('=')
                    .ok_or_else(|| usage(format!("--rule: `{text}` is not C=STR")))?;
                let mut chars = symbol.chars();
                let (Some(c), None) = (chars.next(), chars.next()) else {
                    return Err(usage(format!(
                        "--rule: `{symbol}` must be exactly one symbol before `=`"
                    )));
                };
                rules.push((c, body.to_string()));
            }
            "--angle" => {
                angle = Some(InlineAngle::Divisions(parse_number(
                    flag,
                    options.value(flag)?,
                )?))
            }
            "--angle-deg" => angle = Some(InlineAngle::Degrees(options.value(flag)?.to_string())),
            "--draw-symbols" => draw_symbols = options.value(flag)?.to_string(),
            "--dialect" => {
                dialect = Some(match options.value(flag)? {
                    "fractint" => tinyfractal::Dialect::Fractint,
                    "abop" => tinyfractal::Dialect::Abop,
                    other => {
                        return Err(usage(format!(
                            "--dialect: `{other}` is not `fractint` or `abop`"
                        )))
                    }
                })
            }
            "--order" => order = Some(parse_number(flag, options.value(flag)?)?),
            "--segments" => common.segments = Some(PathBuf::from(options.value(flag)?)),
            _ => return Err(usage(format!("unknown option `{flag}`"))),
        }
    }
    let order = order.ok_or_else(|| usage("--order N is required"))?;
    let source = match (file, axiom) {
        (Some(path), None) => {
            if !rules.is_empty() || angle.is_some() || !draw_symbols.is_empty() {
                return Err(usage(
                    "--rule, --angle and --draw-symbols go with --axiom, not --file",
                ));
            }
            if dialect.is_some() {
                return Err(usage(
                    "--dialect goes with --axiom: .l files are Fractint's",
                ));
            }
            let name = name.ok_or_else(|| usage("--file needs --name NAME"))?;
            Source::File { path, name }
        }
        (None, Some(axiom)) => {
            if name.is_some() {
                return Err(usage("--name goes with --file"));
            }
            let angle = angle
                .ok_or_else(|| usage("an inline system needs --angle N or --angle-deg DEG"))?;
            Source::Inline {
                axiom,
                rules,
                angle,
                draw_symbols,
                dialect: dialect.unwrap_or(tinyfractal::Dialect::Abop),
            }
        }
        (Some(_), Some(_)) => return Err(usage("give either --file or --axiom, not both")),
        (None, None) => {
            return Err(usage(
                "give a system: --file PATH --name NAME, or --axiom STR",
            ))
        }
    };
    Ok(LSystemArgs {
        source,
        order,
        common,
    })
}

fn parse_pair(flag: &str, text: &str) -> Result<(String, String), UsageError> {
    let (re, im) = text
        .split_once(',')
        .ok_or_else(|| usage(format!("{flag}: `{text}` is not RE,IM, e.g. -0.75,0")))?;
    Ok((re.trim().to_string(), im.trim().to_string()))
}

fn parse_escape(julia: bool, words: &[&str]) -> Result<EscapeArgs, UsageError> {
    let mut args = EscapeArgs {
        julia: None,
        centre: ("-0.75".into(), "0".into()),
        width: "3.5".into(),
        max_iterations: 256,
        algorithm: tinyfractal::Algorithm::Fast,
        tier: None,
        palette: "classic".into(),
        common: Common::default(),
        dwell: None,
    };
    let mut options = Options::new(words);
    while let Some(flag) = options.next_flag()? {
        if args.common.take_flag(flag, &mut options)? {
            continue;
        }
        match flag {
            "--c" if julia => args.julia = Some(parse_pair(flag, options.value(flag)?)?),
            "--center" | "--centre" => args.centre = parse_pair(flag, options.value(flag)?)?,
            "--width" => args.width = options.value(flag)?.to_string(),
            "--max-iter" => args.max_iterations = parse_number(flag, options.value(flag)?)?,
            "--algorithm" => {
                args.algorithm = match options.value(flag)? {
                    "exact" => tinyfractal::Algorithm::Exact,
                    "fast" => tinyfractal::Algorithm::Fast,
                    other => {
                        return Err(usage(format!(
                            "--algorithm: `{other}` is not `exact` or `fast`"
                        )))
                    }
                }
            }
            "--precision" => {
                let name = options.value(flag)?;
                args.tier = match name {
                    "auto" => None,
                    _ => Some(
                        tinyfractal::Tier::ALL
                            .into_iter()
                            .find(|tier| tier.name() == name)
                            .ok_or_else(|| {
                                usage(format!(
                                    "--precision: `{name}` is not auto, narrow, standard or deep"
                                ))
                            })?,
                    ),
                }
            }
            "--palette" => args.palette = options.value(flag)?.to_string(),
            "--dwell" => args.dwell = Some(PathBuf::from(options.value(flag)?)),
            _ => return Err(usage(format!("unknown option `{flag}`"))),
        }
    }
    if julia && args.julia.is_none() {
        return Err(usage("`render julia` needs --c RE,IM"));
    }
    Ok(args)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(text: &str) -> Vec<String> {
        text.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn inline_defaults_to_abop() {
        let parsed = parse(&args(
            "render lsystem --axiom F --rule F=F+F --angle 4 --order 3 --size 64x48",
        ));
        let Ok(Command::RenderLSystem(a)) = parsed else {
            panic!("{parsed:?}")
        };
        assert_eq!(a.order, 3);
        assert_eq!((a.common.width, a.common.height), (64, 48));
        assert!(matches!(
            a.source,
            Source::Inline {
                dialect: tinyfractal::Dialect::Abop,
                ..
            }
        ));
    }

    #[test]
    fn mistakes_are_reported() {
        for bad in [
            "render lsystem --axiom F --angle 4",
            "render lsystem --file x.l --order 2",
            "render lsystem --axiom F --order 2",
            "render lsystem --axiom F --angle 4 --order two",
            "render lsystem --axiom F --rule FF=F --angle 4 --order 1",
            "render lsystem --axiom F --angle 4 --order 1 --size 10",
            "render julia",
            "render mandelbrot --center 1",
            "render mandelbrot --algorithm slow",
            "render mandelbrot --precision huge",
            "render mandelbrot --c 0,0",
            "frobnicate",
        ] {
            assert!(parse(&args(bad)).is_err(), "{bad}");
        }
    }
}
