//! Build script of the probe-rs boards (rp-pico-st7789, stm32f429i-disco): links each with
//! its own `memory.x` (beside its Cargo.toml), cortex-m-rt's `link.x` and defmt's `defmt.x`.
//! `--nmagic` stops the linker padding sections to page boundaries (rp-hal's template does the same).

use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let memory = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("memory.x");
    fs::copy(&memory, out.join("memory.x")).expect("memory.x beside Cargo.toml");
    println!("cargo:rerun-if-changed={}", memory.display());
    println!("cargo:rerun-if-changed=build.rs");
    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("none") {
        println!("cargo:rustc-link-arg-bins=-L{}", out.display());
        println!("cargo:rustc-link-arg-bins=--nmagic");
        println!("cargo:rustc-link-arg-bins=-Tlink.x");
        println!("cargo:rustc-link-arg-bins=-Tdefmt.x");
    }
}
