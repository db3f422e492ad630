//! The host front end, as a library so that the `tinyfractal` binary, the tests and the
//! fuzz targets share it: the argument parser, each family's host renderer, the gallery and
//! the all-or-nothing output plan. `src/main.rs` only calls [`run`].

pub(crate) mod animate;
pub mod args;
pub(crate) mod attractor_scene;
pub(crate) mod bezier_scene;
pub(crate) mod clock;
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
pub(crate) mod noise_scene;
pub(crate) mod output;
pub(crate) mod palette;
pub mod parallel;
pub(crate) mod particles_scene;
pub(crate) mod plant_animation;
pub(crate) mod progress;
pub(crate) mod reaction_scene;
pub mod scene;
pub(crate) mod serve;
pub(crate) mod shape_scene;
pub(crate) mod systems;
pub(crate) mod window;

use std::process::ExitCode;

use crate::console::Failure;

/// The `tinyfractal` command: parses the process's arguments and runs them.
pub fn run() -> ExitCode {
    output::remove_temporaries_on_interrupt();
    let cli = match args::parse(std::env::args_os().skip(1)) {
        Ok(cli) => cli,
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
    let result = cli.run();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Quiet) => ExitCode::FAILURE,
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
