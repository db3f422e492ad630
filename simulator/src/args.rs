//! Command-line parsing with clap (derive).
//!
//! One subcommand per family, `--help` on each, `--version`, and shell completions. The option
//! names are a contract (the README and the issues name them): keep them exactly as they are.

use std::ffi::OsString;
use std::path::PathBuf;

use clap::builder::NonEmptyStringValueParser;
use clap::{error::ErrorKind, Args, CommandFactory, Parser, Subcommand, ValueEnum};

use crate::common::{parse_projection, parse_size, parse_view};
pub use crate::common::{Common, View};

/// What the user asked for.
#[derive(Debug, Clone, PartialEq)]
pub enum Command {
    /// `render lsystem ...`
    RenderLSystem(LSystemArgs),
    /// `render mandelbrot ...` and `render julia --c RE,IM ...`
    RenderEscape(EscapeArgs),
    /// `render ifs ...`
    RenderIfs(crate::ifs_scene::IfsOptions),
    /// `render gingerbread ...`
    RenderGingerbread(crate::ifs_scene::GingerbreadOptions),
    /// `render figure ...`
    RenderFigure(crate::figure_scene::FigureOptions),
    /// `render carpet --order N`
    RenderCarpet(crate::shape_scene::OrderOptions),
    /// `render gasket --order N`
    RenderGasket(crate::shape_scene::OrderOptions),
    /// `render cube --order N ...`
    RenderCube(crate::shape_scene::CubeOptions),
    /// `render terrain ...`
    RenderTerrain(crate::shape_scene::TerrainOptions),
    /// `render terrain2d ...`
    RenderTerrain2d(crate::shape_scene::Terrain2dOptions),
    /// `dimension FILE.png [--background RRGGBB]`
    Dimension {
        /// The picture.
        file: PathBuf,
        /// The background colour, 0xRRGGBB.
        background: u32,
    },
    /// `derive ...`
    Derive(DeriveArgs),
    /// `list PATH.l`
    List(PathBuf),
    /// `gallery [--out DIR]`, and no arguments at all
    Gallery {
        /// The folder the pictures go into.
        out: PathBuf,
    },
    /// `completions SHELL`
    Completions(clap_complete::Shell),
    /// `animate zoom|palette|growth|figure ...`
    Animate(AnimateArgs),
    /// `explore ...`
    Explore(ExploreArgs),
}

/// `explore`'s arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct ExploreArgs {
    /// An L-system file to page through, instead of the Mandelbrot set.
    pub file: Option<PathBuf>,
    /// A gallery scene to start from, paging through the gallery.
    pub scene: Option<String>,
    /// The Julia parameter to start with (`--c`), if any.
    pub julia: Option<(String, String)>,
    /// The first view's centre (`--center`), as text.
    pub centre: (String, String),
    /// The first view's width (`--width`), as text.
    pub width: String,
    /// The first view's iteration cap (`--max-iter`).
    pub max_iterations: u32,
    /// The picture's size (`--size`), a status line below it.
    pub size: (u32, u32),
}

/// `animate`'s arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct AnimateArgs {
    /// What is animated.
    pub kind: Animation,
    /// Frames (for `growth`, orders 0 to `--order`, one frame each).
    pub frames: u32,
    /// `NAME.gif`, `NAME.png` (APNG), or a folder of numbered PNGs.
    pub out: PathBuf,
    /// Milliseconds a frame shows in a GIF or APNG.
    pub delay_ms: u32,
    /// Each frame's size (`--size`).
    pub size: (u32, u32),
    /// Whether to print a line of statistics (`--stats`).
    pub stats: bool,
}

/// What `animate` animates.
#[derive(Debug, Clone, PartialEq)]
pub enum Animation {
    /// A zoom from `view`'s width to `end_width` (or by `factor` a frame), reusing frames
    /// within `tolerance` % of a pixel unless `exact`.
    Zoom {
        /// The view zoomed into, and its first width.
        view: EscapeArgs,
        /// The last frame's width (`--end-width`), if given.
        end_width: Option<String>,
        /// How much each frame zooms in (`--factor`).
        factor: f64,
        /// How close a reused line must be, in percent of a pixel (`--tolerance`).
        tolerance: u32,
        /// Whether every pixel of every frame is computed (`--exact`).
        exact: bool,
    },
    /// One view, its gradient turned by `step` entries a frame.
    Palette {
        /// The view.
        view: EscapeArgs,
        /// Gradient entries the colours move a frame (`--step`).
        step: u16,
    },
    /// An L-system, one order a frame.
    Growth {
        /// The system.
        source: Source,
        /// The seed of stochastic productions (`--seed`), if given.
        seed: Option<u32>,
    },
    /// The walking (or waving) figure.
    Figure {
        /// The movement (`--pose`).
        pose: crate::figure_scene::PoseName,
    },
}

/// `derive`'s arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct DeriveArgs {
    /// The system.
    pub source: Source,
    /// The order (`--order`).
    pub order: u32,
    /// `--seed`, overriding the system's.
    pub seed: Option<u32>,
    /// The longest string printed (`--max-length`).
    pub max_length: u64,
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

/// `render lsystem`'s arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct LSystemArgs {
    /// The system.
    pub source: Source,
    /// The order (`--order`).
    pub order: u32,
    /// `--seed`, overriding the system's.
    pub seed: Option<u32>,
    /// The options every render takes.
    pub common: Common,
    /// Where to write the segments (`--segments`), if anywhere.
    pub segments: Option<PathBuf>,
    /// `--view`: the window drawn, as fractions of the picture fitted to the whole target.
    pub view: Option<View>,
    /// `--projection`: draw in 3D, seen this way (3D systems are, isometric by default).
    pub projection: Option<tinyfractal::render::Projection>,
    /// `--depth-cue`: colour 3D lines by depth, nearer brighter.
    pub depth_cue: bool,
    /// `--environment`: the world an open system grows in.
    pub environment: Option<crate::environment::Shape>,
}

/// `render mandelbrot` / `render julia`'s arguments, as text checked by the core.
#[derive(Debug, Clone, PartialEq)]
pub struct EscapeArgs {
    /// `None` for the Mandelbrot set, the parameter `(re, im)` for a Julia set.
    pub julia: Option<(String, String)>,
    /// The view's centre (`--center`), as text.
    pub centre: (String, String),
    /// The view's width (`--width`), as text.
    pub width: String,
    /// The iteration cap (`--max-iter`).
    pub max_iterations: u32,
    /// How the pixels are scheduled (`--algorithm`).
    pub algorithm: tinyfractal::escape::Algorithm,
    /// `None` for automatic.
    pub tier: Option<tinyfractal::escape::Tier>,
    /// The palette's name (`--palette`).
    pub palette: String,
    /// The options every render takes.
    pub common: Common,
    /// Where to write the dwells (`--dwell`), if anywhere.
    pub dwell: Option<PathBuf>,
}

#[derive(Debug, Parser)]
#[command(
    name = "tinyfractal",
    version,
    about = "tinyfractal: fixed-point fractals for small displays, rendered on the host",
    long_about = "tinyfractal: fixed-point fractals for small displays, rendered on the host.\n\
                  With no command it renders the gallery into ./gallery/ (what `cargo run --release` does)."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Commands>,
}

#[derive(Debug, Subcommand)]
enum Commands {
    /// Render one scene to PNG
    Render {
        #[command(subcommand)]
        scene: Box<Scene>,
    },
    /// Print the string a system derives at an order, on one line
    Derive(DeriveOptions),
    /// The box-counting dimension of a PNG's pixels that are not the background
    Dimension {
        /// The picture
        #[arg(value_name = "FILE.png")]
        file: PathBuf,
        /// The background colour, RRGGBB in hex
        #[arg(long, value_name = "RRGGBB", default_value = "000000", value_parser = parse_rgb)]
        background: u32,
    },
    /// The systems in a .l or .lsys file, one name a line
    List {
        /// The .l file
        #[arg(value_name = "PATH.l")]
        file: PathBuf,
    },
    /// Render the gallery (what `cargo run --release` does)
    Gallery {
        /// The folder to write the pictures into
        #[arg(long, value_name = "DIR", default_value = "gallery")]
        out: PathBuf,
    },
    /// Write an animation: numbered PNG frames, an animated GIF or an APNG
    Animate(AnimateOptions),
    /// Explore in a window (needs the `window` feature): click to zoom in (right: out),
    /// wheel, drag or arrows to pan, +/- iterations (or order), p palette, c colour
    /// cycling, j Julia set of the point under the mouse, s save, r reset, PageUp/PageDown
    /// the systems of an L-system file
    Explore(ExploreOptions),
    /// Print a shell completion script
    Completions {
        /// bash, zsh, fish, elvish or powershell
        shell: clap_complete::Shell,
    },
}

#[derive(Debug, Args)]
struct ExploreOptions {
    /// Page through the systems of this .l or .lsys file instead
    #[arg(long, value_name = "PATH", conflicts_with = "scene")]
    file: Option<PathBuf>,
    /// Page through the gallery's scenes instead, starting at this one (+/- its order,
    /// points, seed or iteration cap)
    #[arg(long, value_name = "NAME")]
    scene: Option<String>,
    /// Start with the Julia set of k = RE,IM
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = parse_pair)]
    c: Option<(String, String)>,
    /// Centre of the first view, RE,IM
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", default_value = "-0.75,0", allow_hyphen_values = true, value_parser = parse_pair)]
    centre: (String, String),
    /// Width of the first view
    #[arg(
        long,
        value_name = "W",
        default_value = "3.5",
        allow_hyphen_values = true
    )]
    width: String,
    /// Iteration cap of the first view, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    max_iterations: u32,
    /// Picture size in pixels, WxH (a status line goes below it)
    #[arg(long = "size", value_name = "WxH", default_value = "320x240", value_parser = parse_size)]
    size: (u32, u32),
}

#[derive(Debug, Args)]
struct AnimateOptions {
    #[command(subcommand)]
    kind: Box<AnimationKind>,
}

#[derive(Debug, Args)]
struct FrameOptions {
    /// Frames to write [default: 100]
    #[arg(long, value_name = "N")]
    frames: Option<u32>,
    /// NAME.gif (animated GIF), NAME.png (APNG), or a folder for frame-0000.png, ...
    #[arg(long, value_name = "PATH", default_value = "animation.gif")]
    out: PathBuf,
    /// How long a frame shows in a GIF or APNG, in milliseconds
    #[arg(long = "delay", value_name = "MS", default_value_t = 40)]
    delay_ms: u32,
    /// Picture size in pixels, WxH
    #[arg(long = "size", value_name = "WxH", default_value = "320x240", value_parser = parse_size)]
    size: (u32, u32),
    /// Print one line of statistics
    #[arg(long)]
    stats: bool,
}

#[derive(Debug, Subcommand)]
enum AnimationKind {
    /// A zoom into the Mandelbrot set (or a Julia set with --c), reusing each frame's
    /// columns and rows for the next
    Zoom(ZoomOptions),
    /// Colour cycling: one view, its gradient turned a step each frame
    Palette(PaletteOptions),
    /// An L-system growing, one order a frame
    Growth(GrowthOptions),
    /// The lecture's figure walking (or waving), one cycle
    Figure(FigureAnimationOptions),
}

#[derive(Debug, Args)]
struct ZoomOptions {
    /// The Julia parameter k, RE,IM (a Julia set instead of the Mandelbrot set)
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = parse_pair)]
    c: Option<(String, String)>,
    /// The width of the last frame (default: --width shrunk by --factor a frame)
    #[arg(long = "end-width", value_name = "W", allow_hyphen_values = true)]
    end_width: Option<String>,
    /// How much each frame zooms in
    #[arg(long, value_name = "F", default_value_t = 1.05)]
    factor: f64,
    /// Reuse a line of the previous frame within this share of a pixel, in percent
    #[arg(long, value_name = "PERCENT", default_value_t = 100)]
    tolerance: u32,
    /// Compute every pixel of every frame
    #[arg(long)]
    exact: bool,
    #[command(flatten)]
    view: AnimatedView,
    #[command(flatten)]
    frames: FrameOptions,
}

/// The view options an animation shares with `render mandelbrot`.
#[derive(Debug, Args)]
struct AnimatedView {
    /// Centre of the view (the point zoomed into), RE,IM
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", default_value = "-0.743643887037151,0.131825904205330", allow_hyphen_values = true, value_parser = parse_pair)]
    centre: (String, String),
    /// Width along the real axis (of the first frame)
    #[arg(
        long,
        value_name = "W",
        default_value = "3",
        allow_hyphen_values = true
    )]
    width: String,
    /// Iteration cap, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    max_iterations: u32,
    /// The colours
    #[arg(long, value_enum, default_value = "classic")]
    palette: PaletteName,
}

#[derive(Debug, Args)]
struct PaletteOptions {
    /// The Julia parameter k, RE,IM (a Julia set instead of the Mandelbrot set)
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = parse_pair)]
    c: Option<(String, String)>,
    /// Gradient entries the colours move a frame
    #[arg(long, value_name = "N", default_value_t = 4)]
    step: u16,
    #[command(flatten)]
    view: AnimatedView,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct GrowthOptions {
    #[command(flatten)]
    system: SystemOptions,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Args)]
struct FigureAnimationOptions {
    /// The movement
    #[arg(long, value_enum, default_value = "walk")]
    pose: crate::figure_scene::PoseName,
    #[command(flatten)]
    frames: FrameOptions,
}

#[derive(Debug, Subcommand)]
enum Scene {
    /// An L-system, from a .l file or inline rules
    Lsystem(LSystemOptions),
    /// The Mandelbrot set
    Mandelbrot(EscapeOptions),
    /// A Julia set
    Julia(JuliaOptions),
    /// An iterated function system by the chaos game (Fractint .ifs or inline maps)
    Ifs(crate::ifs_scene::IfsOptions),
    /// The gingerbread man map
    Gingerbread(crate::ifs_scene::GingerbreadOptions),
    /// The lecture's articulated figure in a pose (or frames of its walk)
    Figure(crate::figure_scene::FigureOptions),
    /// The Sierpinski carpet
    Carpet(crate::shape_scene::OrderOptions),
    /// The Sierpinski gasket
    Gasket(crate::shape_scene::OrderOptions),
    /// The Sierpinski cube (or the Menger sponge), projected
    Cube(crate::shape_scene::CubeOptions),
    /// A mountain profile by 1D midpoint displacement
    Terrain(crate::shape_scene::TerrainOptions),
    /// A landscape by diamond-square (2D midpoint displacement)
    #[command(name = "terrain2d")]
    Terrain2d(crate::shape_scene::Terrain2dOptions),
}

#[derive(Debug, Args)]
struct LSystemOptions {
    #[command(flatten)]
    system: SystemOptions,
    /// Write every drawn segment, `x0 y0 x1 y1` in turtle units
    #[arg(long, value_name = "TXT")]
    segments: Option<PathBuf>,
    /// Draw only this window of the picture: fractions of the target the whole picture
    /// fills (0,0 top left, 1,1 bottom right), e.g. 0.4,0.4,0.6,0.6 to zoom 5 times
    #[arg(long, value_name = "X0,Y0,X1,Y1", value_parser = parse_view, allow_hyphen_values = true)]
    view: Option<View>,
    /// Draw an .lsys system with the 3D turtle, seen from the front, isometric, or in
    /// perspective (systems using & ^ \ / $ are drawn in 3D anyway, isometric by default)
    #[arg(long, value_name = "VIEW", value_parser = parse_projection)]
    projection: Option<tinyfractal::render::Projection>,
    /// In 3D, colour each line by its depth, nearer brighter
    #[arg(long = "depth-cue")]
    depth_cue: bool,
    /// The world an open system (env(k) in its productions) grows in: circle:R or heart:R,
    /// R in turtle units, the shape standing on the turtle's start; env(0) is 1 inside
    #[arg(long, value_name = "SHAPE:R", value_parser = crate::environment::Shape::parse)]
    environment: Option<crate::environment::Shape>,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Args)]
struct DeriveOptions {
    #[command(flatten)]
    system: SystemOptions,
    /// The longest string printed, in symbols: an error past it (up to 10000000 checked
    /// before anything is printed; above, the string streams and stops at the limit)
    #[arg(long = "max-length", value_name = "N", default_value_t = DEFAULT_MAX_LENGTH)]
    max_length: u64,
}

/// Frames an animation writes without `--frames`.
const DEFAULT_FRAMES: u32 = 100;

/// The highest order an L-system command takes (the walkers' depth is one more).
const MAX_ORDER: i64 = crate::scene::DEPTH as i64 - 1;

/// `derive`'s default `--max-length`.
pub const DEFAULT_MAX_LENGTH: u64 = 1_000_000;

/// A system, from a file or inline, and its order: what `render lsystem` and `derive` share.
#[derive(Debug, Args)]
struct SystemOptions {
    /// A Fractint .l file, or an .lsys file (with --name)
    #[arg(
        long,
        value_name = "PATH.l",
        conflicts_with = "axiom",
        requires = "name"
    )]
    file: Option<PathBuf>,
    /// The system in the file (case-insensitive)
    #[arg(long, value_name = "NAME", requires = "file", value_parser = NonEmptyStringValueParser::new())]
    name: Option<String>,
    /// An inline system's axiom
    #[arg(long, value_name = "STR", allow_hyphen_values = true)]
    axiom: Option<String>,
    /// An inline rule, C=STR (repeat for more)
    #[arg(long = "rule", value_name = "C=STR", allow_hyphen_values = true, conflicts_with = "file", value_parser = parse_rule)]
    rules: Vec<(char, String)>,
    /// Divisions of a full turn
    #[arg(long, value_name = "N", conflicts_with_all = ["angle_deg", "file"])]
    angle: Option<u16>,
    /// A free angle in degrees, e.g. 22.5 or -90
    #[arg(
        long = "angle-deg",
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = "file",
        value_parser = parse_degrees
    )]
    angle_deg: Option<tinyfractal::Angle>,
    /// More symbols that draw (ABOP edge rewriting)
    #[arg(
        long = "draw-symbols",
        value_name = "CHARS",
        default_value = "",
        conflicts_with = "file"
    )]
    draw_symbols: String,
    /// The inline system's notation (default abop; .l files are Fractint's)
    #[arg(long, value_enum, conflicts_with = "file")]
    dialect: Option<DialectName>,
    /// The order (derivation steps), 0 to 256
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(0..=MAX_ORDER))]
    order: u32,
    /// The seed of stochastic productions (overrides the file's `seed:`)
    #[arg(long, value_name = "N")]
    seed: Option<u32>,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum DialectName {
    Fractint,
    Abop,
}

#[derive(Debug, Args)]
struct EscapeOptions {
    /// Centre of the view, RE,IM [default: -0.75,0 for the Mandelbrot set, 0,0 for a Julia
    /// set]
    #[arg(long = "center", visible_alias = "centre", value_name = "RE,IM", allow_hyphen_values = true, value_parser = parse_pair)]
    centre: Option<(String, String)>,
    /// Width along the real axis [default: 3.5 for the Mandelbrot set, 3.2 for a Julia set]
    #[arg(long, value_name = "W", allow_hyphen_values = true)]
    width: Option<String>,
    /// Iteration cap, 1 to 65535
    #[arg(long = "max-iter", value_name = "N", default_value_t = 256, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=65535))]
    max_iterations: u32,
    /// How pixels are scheduled
    #[arg(long, value_enum, default_value = "fast")]
    algorithm: AlgorithmName,
    /// The fixed-point tier (auto chooses per view)
    #[arg(long, value_enum, default_value = "auto")]
    precision: Precision,
    /// The colours
    #[arg(long, value_enum, default_value = "classic")]
    palette: PaletteName,
    /// Write `W H MAXITER`, then H lines of W dwells
    #[arg(long, value_name = "TXT")]
    dwell: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Args)]
struct JuliaOptions {
    /// The Julia parameter k, RE,IM
    #[arg(long = "c", value_name = "RE,IM", allow_hyphen_values = true, value_parser = parse_pair)]
    c: (String, String),
    #[command(flatten)]
    view: EscapeOptions,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum PaletteName {
    Classic,
    Fire,
    Gray,
    Bands,
    TwoColor,
    SmoothClassic,
    SmoothFire,
    SmoothGray,
}

impl PaletteName {
    fn name(self) -> &'static str {
        match self {
            Self::Classic => "classic",
            Self::Fire => "fire",
            Self::Gray => "gray",
            Self::Bands => "bands",
            Self::TwoColor => "two-color",
            Self::SmoothClassic => "smooth-classic",
            Self::SmoothFire => "smooth-fire",
            Self::SmoothGray => "smooth-gray",
        }
    }
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum AlgorithmName {
    Exact,
    Fast,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum Precision {
    Auto,
    Narrow,
    Medium,
    Standard,
    Deep,
    Wide,
    Perturbation,
}

impl Precision {
    fn tier(self) -> Option<tinyfractal::escape::Tier> {
        match self {
            Self::Auto => None,
            Self::Narrow => Some(tinyfractal::escape::Tier::Narrow),
            Self::Medium => Some(tinyfractal::escape::Tier::Medium),
            Self::Standard => Some(tinyfractal::escape::Tier::Standard),
            Self::Deep => Some(tinyfractal::escape::Tier::Deep),
            Self::Wide => Some(tinyfractal::escape::Tier::Wide),
            Self::Perturbation => Some(tinyfractal::escape::Tier::Perturbation),
        }
    }
}

/// Parses the arguments after the program name. `Err` carries clap's message (help and
/// version are "errors" of their own kinds, printed to stdout with exit status 0).
pub fn parse<I, T>(args: I) -> Result<Command, clap::Error>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let args: Vec<OsString> = std::iter::once(OsString::from("tinyfractal"))
        .chain(args.into_iter().map(Into::into))
        .collect();
    let cli = Cli::try_parse_from(&args).map_err(|error| negative_count(error, &args))?;
    Ok(match cli.command {
        None => Command::Gallery {
            out: PathBuf::from("gallery"),
        },
        Some(Commands::Gallery { out }) => Command::Gallery { out },
        Some(Commands::List { file }) => Command::List(file),
        Some(Commands::Derive(options)) => Command::Derive(DeriveArgs {
            order: options.system.order,
            seed: options.system.seed,
            source: source(options.system, false)?,
            max_length: options.max_length,
        }),
        Some(Commands::Completions { shell }) => Command::Completions(shell),
        Some(Commands::Animate(options)) => Command::Animate(animation(*options.kind)?),
        Some(Commands::Explore(options)) => Command::Explore(ExploreArgs {
            file: options.file,
            scene: options.scene,
            julia: options.c,
            centre: options.centre,
            width: options.width,
            max_iterations: options.max_iterations,
            size: options.size,
        }),
        Some(Commands::Render { scene }) => match *scene {
            Scene::Lsystem(options) => Command::RenderLSystem(lsystem(options)?),
            Scene::Mandelbrot(options) => Command::RenderEscape(escape(None, options)),
            Scene::Julia(options) => Command::RenderEscape(escape(Some(options.c), options.view)),
            Scene::Ifs(options) => Command::RenderIfs(options),
            Scene::Gingerbread(options) => Command::RenderGingerbread(options),
            Scene::Figure(options) => Command::RenderFigure(options),
            Scene::Carpet(options) => Command::RenderCarpet(options),
            Scene::Gasket(options) => Command::RenderGasket(options),
            Scene::Cube(options) => Command::RenderCube(options),
            Scene::Terrain(options) => Command::RenderTerrain(options),
            Scene::Terrain2d(options) => Command::RenderTerrain2d(options),
        },
        Some(Commands::Dimension { file, background }) => Command::Dimension { file, background },
    })
}

/// Writes a shell completion script for `shell` to stdout (made whole first: the
/// generator panics on a failed write).
pub fn completions(shell: clap_complete::Shell) -> Result<(), String> {
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "tinyfractal", &mut script);
    crate::console::print(&String::from_utf8_lossy(&script))
}

/// Clap reads a negative number after an option that takes a count as an unknown
/// option (`unexpected argument '-1'`): said as what it is, naming the option.
fn negative_count(error: clap::Error, args: &[OsString]) -> clap::Error {
    let negative =
        |text: &str| text.len() > 1 && text.starts_with('-') && text[1..].parse::<f64>().is_ok();
    let invalid = match error.get(clap::error::ContextKind::InvalidArg) {
        Some(clap::error::ContextValue::String(invalid)) => invalid.clone(),
        _ => return error,
    };
    if error.kind() != ErrorKind::UnknownArgument || !negative(&invalid) {
        return error;
    }
    let option = args.windows(2).find_map(|pair| {
        let (option, value) = (pair[0].to_str()?, pair[1].to_str()?);
        (option.starts_with("--") && value == invalid).then(|| option.to_string())
    });
    match option {
        Some(option) => usage(
            ErrorKind::ValueValidation,
            &format!(
                "{option} {invalid}: {option} takes a count of 0 or more, not a negative number"
            ),
        ),
        None => error,
    }
}

fn usage(kind: ErrorKind, message: &str) -> clap::Error {
    Cli::command().error(kind, message)
}

fn lsystem(options: LSystemOptions) -> Result<LSystemArgs, clap::Error> {
    let (order, seed) = (options.system.order, options.system.seed);
    Ok(LSystemArgs {
        source: source(options.system, true)?,
        order,
        seed,
        common: options.common,
        segments: options.segments,
        view: options.view,
        projection: options.projection,
        depth_cue: options.depth_cue,
        environment: options.environment,
    })
}

/// The system the options name. An inline system needs an angle to be drawn
/// (`angle_required`); to be derived it does not (a quarter turn stands in).
fn source(options: SystemOptions, angle_required: bool) -> Result<Source, clap::Error> {
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
                    return Err(usage(
                        ErrorKind::MissingRequiredArgument,
                        "an inline system needs --angle N or --angle-deg DEG",
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
            return Err(usage(
                ErrorKind::MissingRequiredArgument,
                "give a system: --file PATH --name NAME, or --axiom STR",
            ))
        }
    })
}

fn animation(kind: AnimationKind) -> Result<AnimateArgs, clap::Error> {
    let animated = |julia: Option<(String, String)>, view: AnimatedView| EscapeArgs {
        julia,
        centre: view.centre,
        width: view.width,
        max_iterations: view.max_iterations,
        algorithm: tinyfractal::escape::Algorithm::Exact,
        tier: None,
        palette: view.palette.name().to_string(),
        common: Common {
            size: (0, 0),
            out: None,
            stats: false,
            window: false,
            dimension: false,
        },
        dwell: None,
    };
    let (kind, frames) = match kind {
        AnimationKind::Zoom(options) => (
            Animation::Zoom {
                view: animated(options.c, options.view),
                end_width: options.end_width,
                factor: options.factor,
                tolerance: options.tolerance,
                exact: options.exact,
            },
            options.frames,
        ),
        AnimationKind::Palette(options) => (
            Animation::Palette {
                view: animated(options.c, options.view),
                step: options.step,
            },
            options.frames,
        ),
        AnimationKind::Growth(options) => {
            if options.frames.frames.is_some() {
                return Err(usage(
                    ErrorKind::ArgumentConflict,
                    "--frames does not apply to growth: it writes one frame an order, 0 to \
                     --order (leave out --frames)",
                ));
            }
            let mut frames = options.frames;
            // Orders 0 to N: N + 1 frames.
            frames.frames = Some(options.system.order.saturating_add(1));
            let seed = options.system.seed;
            (
                Animation::Growth {
                    source: source(options.system, true)?,
                    seed,
                },
                frames,
            )
        }
        AnimationKind::Figure(options) => {
            (Animation::Figure { pose: options.pose }, options.frames)
        }
    };
    let count = frames.frames.unwrap_or(DEFAULT_FRAMES);
    if count == 0 {
        return Err(usage(
            ErrorKind::ValueValidation,
            "--frames 0: give at least one frame",
        ));
    }
    Ok(AnimateArgs {
        kind,
        frames: count,
        out: frames.out,
        delay_ms: frames.delay_ms,
        size: frames.size,
        stats: frames.stats,
    })
}

fn escape(julia: Option<(String, String)>, options: EscapeOptions) -> EscapeArgs {
    // Each set's whole picture by default.
    let (centre, width) = match julia {
        None => (("-0.75", "0"), "3.5"),
        Some(_) => (("0", "0"), "3.2"),
    };
    EscapeArgs {
        julia,
        centre: options
            .centre
            .unwrap_or_else(|| (centre.0.to_string(), centre.1.to_string())),
        width: options.width.unwrap_or_else(|| width.to_string()),
        max_iterations: options.max_iterations,
        algorithm: match options.algorithm {
            AlgorithmName::Exact => tinyfractal::escape::Algorithm::Exact,
            AlgorithmName::Fast => tinyfractal::escape::Algorithm::Fast,
        },
        tier: options.precision.tier(),
        palette: options.palette.name().to_string(),
        common: options.common,
        dwell: options.dwell,
    }
}

fn parse_rgb(text: &str) -> Result<u32, String> {
    let hex = text.trim().trim_start_matches('#');
    match u32::from_str_radix(hex, 16) {
        Ok(value) if hex.len() == 6 => Ok(value),
        _ => Err(format!(
            "`{text}` is not a colour RRGGBB in hex, e.g. 000000 or ffffff"
        )),
    }
}

fn parse_degrees(text: &str) -> Result<tinyfractal::Angle, String> {
    tinyfractal::Angle::parse_degrees(text)
        .ok_or_else(|| format!("`{text}` is not a number of degrees, e.g. 22.5 or -90"))
}

fn parse_pair(text: &str) -> Result<(String, String), String> {
    let (re, im) = text
        .split_once(',')
        .ok_or_else(|| format!("`{text}` is not RE,IM, e.g. -0.75,0"))?;
    Ok((re.trim().to_string(), im.trim().to_string()))
}

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

#[cfg(test)]
mod tests {
    use super::*;

    fn args(text: &str) -> Vec<String> {
        text.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn inline_defaults_to_abop() {
        let parsed = parse(args(
            "render lsystem --axiom F --rule F=F+F --angle 4 --order 3 --size 64x48",
        ));
        let Ok(Command::RenderLSystem(a)) = parsed else {
            panic!("{parsed:?}")
        };
        assert_eq!(a.order, 3);
        assert_eq!((a.common.width(), a.common.height()), (64, 48));
        assert!(matches!(
            a.source,
            Source::Inline {
                dialect: tinyfractal::Dialect::Abop,
                ..
            }
        ));
    }

    #[test]
    fn negative_numbers_are_values() {
        let parsed = parse(args(
            "render julia --c -0.8,0.156 --center -0.5,-0.25 --width 3.2",
        ));
        let Ok(Command::RenderEscape(a)) = parsed else {
            panic!("{parsed:?}")
        };
        assert_eq!(a.julia, Some(("-0.8".into(), "0.156".into())));
        assert_eq!(a.centre, ("-0.5".into(), "-0.25".into()));
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
            "render lsystem --file x.l --name y --axiom F --order 1",
            "render lsystem --file x.l --name y --angle 4 --order 1",
            "render julia",
            "render mandelbrot --center 1",
            "render mandelbrot --algorithm slow",
            "render mandelbrot --precision huge",
            "render mandelbrot --c 0,0",
            "render mandelbrot --palette neon",
            "frobnicate",
        ] {
            assert!(parse(args(bad)).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_command_is_well_formed() {
        Cli::command().debug_assert();
    }
}
