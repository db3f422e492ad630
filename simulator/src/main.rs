//! `tinyfractal`: the host front end. Renders scenes to PNG without any display or SDL;
//! with the `window` feature, `--window` also shows them.

use std::process::ExitCode;

fn main() -> ExitCode {
    tinyfractal_simulator::run()
}
