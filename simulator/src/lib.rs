//! The host front end, as a library so that the `tinyfractal` binary, the tests and the
//! fuzz targets share it: the argument parser, each family's host renderer, the gallery and
//! the all-or-nothing output plan. `src/main.rs` only calls [`run`].

pub(crate) mod animate;
pub mod args;
pub(crate) mod common;
pub(crate) mod console;
pub(crate) mod delivery;
pub(crate) mod derive;
pub(crate) mod dimension;
pub(crate) mod environment;
pub mod escape_scene;
pub mod explore;
pub(crate) mod figure_scene;
pub mod files;
pub mod gallery;
pub(crate) mod ifs_scene;
pub(crate) mod lsystem_scene;
pub(crate) mod output;
pub(crate) mod palette;
pub(crate) mod progress;
pub mod scene;
pub(crate) mod shape_scene;
pub(crate) mod systems;
pub(crate) mod window;

use std::process::ExitCode;

use crate::args::Command;
use crate::console::Failure;

/// The `tinyfractal` command: parses the process's arguments and runs them.
pub fn run() -> ExitCode {
    output::remove_temporaries_on_interrupt();
    let command = match args::parse(std::env::args_os().skip(1)) {
        Ok(command) => command,
        Err(error) if !error.use_stderr() => {
            // --help and --version.
            let _ = error.print();
            return ExitCode::SUCCESS;
        }
        Err(error) => {
            console::complain(&format!(
                "tinyfractal: {}(see `tinyfractal help`, or `tinyfractal help COMMAND`)\n",
                error.render()
            ));
            return ExitCode::from(2);
        }
    };
    let result = (|| -> Result<(), Failure> {
        match command {
            Command::Completions(shell) => args::completions(shell)?,
            Command::List(path) => systems::list(&path)?,
            Command::Animate(arguments) => animate::animate(&arguments)?,
            Command::Explore(arguments) => window::explore_window(&arguments)?,
            Command::Derive(arguments) => derive::derive(&arguments)?,
            Command::Gallery { out } => gallery::run(&out)?,
            Command::RenderLSystem(lsystem) => lsystem_scene::render_lsystem(&lsystem)?,
            Command::RenderEscape(escape) => escape_scene::render_escape(&escape)?,
            Command::RenderIfs(options) => ifs_scene::render_ifs(&options)?,
            Command::RenderGingerbread(options) => ifs_scene::render_gingerbread(&options)?,
            Command::RenderFigure(options) => figure_scene::render_figure(&options)?,
            Command::RenderCarpet(options) => shape_scene::render_carpet(&options)?,
            Command::RenderGasket(options) => shape_scene::render_gasket(&options)?,
            Command::RenderCube(options) => shape_scene::render_cube(&options)?,
            Command::RenderTerrain(options) => shape_scene::render_terrain(&options)?,
            Command::RenderTerrain2d(options) => shape_scene::render_terrain2d(&options)?,
            Command::Dimension { file, background } => dimension::dimension(&file, background)?,
        }
        Ok(())
    })();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // Standard output was closed (`| head`): a quiet stop.
        Err(Failure::Run(message)) if message == console::QUIET => ExitCode::FAILURE,
        Err(Failure::Run(message)) => {
            console::complain(&format!("tinyfractal: error: {message}\n"));
            ExitCode::FAILURE
        }
        Err(Failure::Usage(message)) => {
            console::complain(&format!(
                "tinyfractal: error: {message}\n(see `tinyfractal help`, or `tinyfractal help \
                 COMMAND`)\n"
            ));
            ExitCode::from(2)
        }
    }
}
