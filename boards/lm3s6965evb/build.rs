//! Links the firmware: the root `memory.x` (the LM3S6965) and cortex-m-rt's `link.x`; and
//! decides which QEMU tests can run on this host (`../tools/detect.rs`).
//!
//! `-Tlink.x` comes from here rather than `.cargo/config.toml`, because a build started at
//! the workspace root ignores the board's config, and the ELF would link silently broken.

use std::{fs, path::PathBuf};

include!("../tools/detect.rs");

fn main() {
    detect_host_tools();
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let memory = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../memory.x");
    fs::copy(&memory, out.join("memory.x")).expect("memory.x at the repository root");
    println!("cargo:rerun-if-changed={}", memory.display());
    println!("cargo:rerun-if-changed=build.rs");
    // Search paths for this package's binaries only: `rustc-link-search` would reach every
    // crate that depends on this one, and two `memory.x` files would compete.
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("none") {
        println!("cargo:rustc-link-arg-bins=-L{}", out.display());
        println!("cargo:rustc-link-arg-bins=-Tlink.x");
    }
}
