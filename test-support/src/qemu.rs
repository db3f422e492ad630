//! What the QEMU tests share.
//!
//! The Cortex-M targets, installed by rustup when they are missing, and QEMU itself. Whether a
//! test runs at all is decided at build time (`detect.rs`): here a missing piece is a failure
//! that says what to install.

use std::path::Path;
use std::process::Command;

/// Makes sure `target`'s standard library is installed for the toolchain that builds the
/// firmware in `folder` (its `rust-toolchain.toml` applies).
///
/// Rustup adds a missing one, since it does not add the file's targets to a toolchain that is
/// already installed.
pub fn ensure_target(folder: &Path, target: &str) {
    let libdir = Command::new("rustc")
        .current_dir(folder)
        .args(["--print", "target-libdir", "--target", target])
        .output()
        .ok()
        .map(|output| String::from_utf8_lossy(&output.stdout).trim().to_string());
    if libdir.is_some_and(|dir| Path::new(&dir).is_dir()) {
        return;
    }
    let status = Command::new("rustup")
        .current_dir(folder)
        .args(["target", "add", target])
        .status();
    assert!(
        status.is_ok_and(|s| s.success()),
        "the {target} standard library is missing and rustup could not add it: \
         run `rustup target add {target}`"
    );
}

/// `qemu-system-arm` with `args`, failing with what to install when it is missing.
pub fn qemu() -> Command {
    let found = Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .is_ok_and(|output| output.status.success());
    assert!(
        found,
        "qemu-system-arm is missing: apt-get install qemu-system-arm (CI=true requires it)"
    );
    Command::new("qemu-system-arm")
}
