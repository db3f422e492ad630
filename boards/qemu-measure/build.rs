//! Links the measuring firmware for the QEMU machine that runs its target:
//! thumbv6m → `microbit` (nRF51, 256 KiB flash, 16 KiB RAM), thumbv7m → `lm3s6965evb` (the
//! root `memory.x`), thumbv7em → `mps2-an386` (4 MiB + 4 MiB). `-Tlink.x` comes from here
//! because a build from the workspace root ignores a board's `.cargo/config.toml`.

use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let target = env::var("TARGET").unwrap_or_default();
    let root_memory = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../memory.x");
    let memory = if target.starts_with("thumbv6m") {
        "MEMORY\n{\n  FLASH : ORIGIN = 0x00000000, LENGTH = 256K\n  RAM : ORIGIN = 0x20000000, LENGTH = 16K\n}\n".to_string()
    } else if target.starts_with("thumbv7em") {
        "MEMORY\n{\n  FLASH : ORIGIN = 0x00000000, LENGTH = 4M\n  RAM : ORIGIN = 0x20000000, LENGTH = 4M\n}\n".to_string()
    } else {
        fs::read_to_string(&root_memory).expect("memory.x at the repository root")
    };
    fs::write(out.join("memory.x"), memory).expect("OUT_DIR is writable");
    println!("cargo:rerun-if-changed={}", root_memory.display());
    println!("cargo:rerun-if-changed=build.rs");
    // The general engine's scenes need more RAM than the micro:bit has.
    println!("cargo::rustc-check-cfg=cfg(measure_general)");
    if !target.starts_with("thumbv6m") {
        println!("cargo:rustc-cfg=measure_general");
    }
    // Search paths for this package's binaries only: `rustc-link-search` would reach every
    // crate that depends on this one, and two `memory.x` files would compete.
    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("none") {
        println!("cargo:rustc-link-arg-bins=-L{}", out.display());
        println!("cargo:rustc-link-arg-bins=-Tlink.x");
    }
}
