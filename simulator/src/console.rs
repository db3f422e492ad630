//! What a command prints on standard output, with its failures handled.
//!
//! A closed pipe (`list FILE | head -1`) stops the run quietly, any other failure (a full
//! device) is an error that names standard output; neither is a panic.

use std::io::{self, Write};

/// The message of a quiet stop: [`run`](crate::run) prints nothing for it and exits with
/// status 1, as a tool stopped by a closed pipe does.
pub const QUIET: &str = "";

/// Writes `text` to standard output and flushes it.
pub fn print(text: &str) -> Result<(), String> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| failed(&e))
}

/// The message for a write to standard output that failed: [`QUIET`] for a closed pipe.
pub fn failed(error: &io::Error) -> String {
    if error.kind() == io::ErrorKind::BrokenPipe {
        QUIET.to_string()
    } else {
        format!("cannot write to standard output: {error}")
    }
}

/// Writes `text` to standard error, ignoring a failure there (a closed or full standard
/// error has nowhere left to report to, and must not panic).
pub fn complain(text: &str) {
    let mut err = io::stderr().lock();
    let _ = err.write_all(text.as_bytes()).and_then(|()| err.flush());
}

/// Why a command failed, and so its exit status.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Failure {
    /// A run's error (exit status 1): the message names the cause and what to do.
    Run(String),
    /// A usage error found after parsing (exit status 2), such as an option the file's
    /// system does not take, or options that do not fit together.
    Usage(String),
    /// Standard output was closed (`| head`): a quiet stop, nothing printed (exit status 1).
    Quiet,
}

impl From<String> for Failure {
    /// A run's error; [`QUIET`], what [`failed`] says of a closed pipe, is [`Failure::Quiet`].
    fn from(message: String) -> Self {
        if message == QUIET {
            Self::Quiet
        } else {
            Self::Run(message)
        }
    }
}

impl core::fmt::Display for Failure {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Run(message) | Self::Usage(message) => f.write_str(message),
            Self::Quiet => f.write_str("standard output was closed"),
        }
    }
}

impl std::error::Error for Failure {}

/// Says something the user should know on stderr; the run goes on.
pub fn warn(message: &str) {
    complain(&format!("tinyfractal: warning: {message}\n"));
}
