//! The command line, parsed by clap (derive): one subcommand per family, `--help` on each,
//! `--version`, and shell completions.
//!
//! Each subcommand's options are defined beside the code that runs them (`LSystemOptions`
//! in `lsystem_scene.rs`, ...); here they are only gathered. The option names are a
//! contract (the README and the issues name them): keep them exactly as they are.

use std::ffi::OsString;
use std::path::PathBuf;

use clap::{error::ErrorKind, CommandFactory, Parser, Subcommand};

use crate::animate::AnimateOptions;
use crate::attractor_scene::RenderAttractorOptions;
use crate::bezier_scene::BezierOptions;
use crate::console::Failure;
use crate::derive::DeriveOptions;
use crate::dimension::DimensionOptions;
use crate::escape_scene::{EscapeOptions, JuliaOptions};
use crate::figure_scene::{render_figure, FigureOptions};
use crate::ifs_scene::{render_gingerbread, render_ifs, GingerbreadOptions, IfsOptions};
use crate::lsystem_scene::LSystemOptions;
use crate::noise_scene::{NoiseOptions, RenderNoiseOptions};
use crate::particles_scene::RenderParticleOptions;
use crate::reaction_scene::RenderReactionOptions;
use crate::shape_scene::{
    render_carpet, render_cube, render_gasket, render_terrain, render_terrain2d, CubeOptions,
    OrderOptions, Terrain2dOptions, TerrainOptions,
};
use crate::window::ExploreOptions;

/// The `tinyfractal` command line: one subcommand per family, or none for the gallery.
#[derive(Debug, Parser)]
#[command(
    name = "tinyfractal",
    version,
    about = "tinyfractal: fixed-point fractals for small displays, rendered on the host",
    long_about = "tinyfractal: fixed-point fractals for small displays, rendered on the host.\n\
                  With no command it renders the gallery into ./gallery/ (what `cargo run --release` does)."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Commands>,
    /// Threads to use (default: every core): escape-time pictures split into parts, the
    /// gallery's scenes side by side; the output is the same whatever the number
    #[arg(long, global = true, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
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
    Dimension(DimensionOptions),
    /// Perlin noise at points, one a line: every digit of the engine's value
    Noise(NoiseOptions),
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
    /// Serve the playground (the gallery, an L-system editor and the escape-time explorer
    /// in the browser) on 127.0.0.1, or write its files with --out
    Serve(crate::serve::ServeOptions),
    /// Print a shell completion script
    Completions {
        /// bash, zsh, fish, elvish or powershell
        shell: clap_complete::Shell,
    },
}

/// `render`'s scenes, one per family.
#[derive(Debug, Subcommand)]
enum Scene {
    /// An L-system, from a .l file or inline rules
    Lsystem(LSystemOptions),
    /// The Mandelbrot set
    Mandelbrot(EscapeOptions),
    /// A Julia set
    Julia(JuliaOptions),
    /// An iterated function system by the chaos game (Fractint .ifs or inline maps)
    Ifs(IfsOptions),
    /// The gingerbread man map
    Gingerbread(GingerbreadOptions),
    /// The lecture's articulated figure in a pose (or frames of its walk)
    Figure(FigureOptions),
    /// The Sierpinski carpet
    Carpet(OrderOptions),
    /// The Sierpinski gasket
    Gasket(OrderOptions),
    /// The Sierpinski cube (or the Menger sponge), projected
    Cube(CubeOptions),
    /// A mountain profile by 1D midpoint displacement
    Terrain(TerrainOptions),
    /// Perlin noise as a texture: fBm, turbulence, ridged, clouds, marble, wood
    Noise(RenderNoiseOptions),
    /// Reaction–diffusion (Gray–Scott): spots, stripes, mazes and coral on a grid
    Reaction(RenderReactionOptions),
    /// A landscape by diamond-square (2D midpoint displacement)
    #[command(name = "terrain2d")]
    Terrain2d(Terrain2dOptions),
    /// A strange attractor: Hénon, Lorenz, Rössler, Clifford, de Jong, ... as points or by
    /// density
    Attractor(RenderAttractorOptions),
    /// Quadratic and cubic Bézier curves from their control points (the smooth counterpart)
    Bezier(BezierOptions),
    /// A particle system (fountain, fire, fireworks, snow, explosion) at a moment
    Particles(RenderParticleOptions),
}

/// Parses the arguments after the program name. `Err` carries clap's message (help and
/// version are "errors" of their own kinds, printed to stdout with exit status 0).
pub fn parse<I, T>(args: I) -> Result<Cli, clap::Error>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let args: Vec<OsString> = std::iter::once(OsString::from("tinyfractal"))
        .chain(args.into_iter().map(Into::into))
        .collect();
    Cli::try_parse_from(&args).map_err(|error| negative_number(error, &args))
}

impl Cli {
    /// Runs the command; with none, renders the gallery into `./gallery/`.
    pub fn run(self) -> Result<(), Failure> {
        let threads = self.threads.map(|n| n as usize);
        let command = self.command;
        crate::parallel::with_threads(threads, || match command {
            None => Ok(crate::gallery::run(&PathBuf::from("gallery"))?),
            Some(command) => command.run(),
        })?
    }
}

impl Commands {
    fn run(self) -> Result<(), Failure> {
        match self {
            Self::Render { scene } => scene.run(),
            Self::Derive(options) => options.run(),
            Self::Dimension(options) => options.run(),
            Self::Noise(options) => options.run(),
            Self::List { file } => Ok(crate::systems::list(&file)?),
            Self::Gallery { out } => Ok(crate::gallery::run(&out)?),
            Self::Animate(options) => options.run(),
            Self::Explore(options) => options.run(),
            Self::Serve(options) => Ok(options.run()?),
            Self::Completions { shell } => Ok(completions(shell)?),
        }
    }
}

impl Scene {
    fn run(self) -> Result<(), Failure> {
        match self {
            Self::Lsystem(options) => options.run(),
            Self::Mandelbrot(options) => options.run(),
            Self::Julia(options) => options.run(),
            Self::Ifs(options) => Ok(render_ifs(&options)?),
            Self::Gingerbread(options) => Ok(render_gingerbread(&options)?),
            Self::Figure(options) => Ok(render_figure(&options)?),
            Self::Carpet(options) => Ok(render_carpet(&options)?),
            Self::Gasket(options) => Ok(render_gasket(&options)?),
            Self::Cube(options) => Ok(render_cube(&options)?),
            Self::Terrain(options) => Ok(render_terrain(&options)?),
            Self::Terrain2d(options) => Ok(render_terrain2d(&options)?),
            Self::Noise(options) => options.run(),
            Self::Reaction(options) => options.run(),
            Self::Attractor(options) => options.run(),
            Self::Bezier(options) => options.run(),
            Self::Particles(options) => options.run(),
        }
    }
}

/// Writes a shell completion script for `shell` to stdout (made whole first: the
/// generator panics on a failed write).
fn completions(shell: clap_complete::Shell) -> Result<(), String> {
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "tinyfractal", &mut script);
    crate::console::print(&String::from_utf8_lossy(&script))
}

/// Clap reads a negative number after an option that takes none as an unknown option,
/// and names only its first character or two (`unexpected argument '-0'` for `-0.5`):
/// said as what it is, naming the option and the whole value.
fn negative_number(error: clap::Error, args: &[OsString]) -> clap::Error {
    let negative =
        |text: &str| text.len() > 1 && text.starts_with('-') && text[1..].parse::<f64>().is_ok();
    let invalid = match error.get(clap::error::ContextKind::InvalidArg) {
        Some(clap::error::ContextValue::String(invalid)) => invalid.clone(),
        _ => return error,
    };
    if error.kind() != ErrorKind::UnknownArgument {
        return error;
    }
    let option = args.windows(2).find_map(|pair| {
        let (option, value) = (pair[0].to_str()?, pair[1].to_str()?);
        (option.starts_with("--") && value.starts_with(invalid.as_str()) && negative(value))
            .then(|| (option.to_string(), value.to_string()))
    });
    match option {
        Some((option, value)) => usage(
            ErrorKind::ValueValidation,
            &format!(
                "{option} {value}: {option} takes a number of 0 or more, not a negative number"
            ),
        ),
        None => error,
    }
}

fn usage(kind: ErrorKind, message: &str) -> clap::Error {
    Cli::command().error(kind, message)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(text: &str) -> Vec<String> {
        text.split_whitespace().map(String::from).collect()
    }

    /// The options a parse gave `render SCENE`.
    fn scene(text: &str) -> Scene {
        match parse(args(text)) {
            Ok(Cli {
                command: Some(Commands::Render { scene }),
                ..
            }) => *scene,
            other => panic!("{text}: {other:?}"),
        }
    }

    #[test]
    fn inline_defaults_to_abop() {
        let Scene::Lsystem(options) =
            scene("render lsystem --axiom F --rule F=F+F --angle 4 --order 3 --size 64x48")
        else {
            panic!("not an L-system")
        };
        assert_eq!(options.system.order, 3);
        assert_eq!((options.common.width(), options.common.height()), (64, 48));
        let source = options.system.source(crate::systems::Purpose::Draw);
        assert!(matches!(
            source,
            Ok(crate::systems::Source::Inline {
                dialect: tinyfractal::Dialect::Abop,
                ..
            })
        ));
    }

    #[test]
    fn negative_numbers_are_values() {
        let Scene::Julia(options) =
            scene("render julia --c -0.8,0.156 --center -0.5,-0.25 --width 3.2")
        else {
            panic!("not a Julia set")
        };
        assert_eq!(options.c, ("-0.8".into(), "0.156".into()));
        assert_eq!(options.view.centre, Some(("-0.5".into(), "-0.25".into())));
    }

    #[test]
    fn an_inline_system_to_draw_needs_an_angle() {
        let Scene::Lsystem(options) = scene("render lsystem --axiom F --order 2") else {
            panic!("not an L-system")
        };
        let drawn = options.system.source(crate::systems::Purpose::Draw);
        assert!(
            matches!(&drawn, Err(Failure::Usage(message)) if message.contains("--angle N")),
            "{drawn:?}"
        );
        // A derivation does not draw: a quarter turn stands in.
        assert!(options
            .system
            .source(crate::systems::Purpose::Derive)
            .is_ok());
    }

    #[test]
    fn mistakes_are_reported() {
        for bad in [
            "render lsystem --axiom F --angle 4",
            "render lsystem --file x.l --order 2",
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
