//! Links the measuring firmware for the QEMU machine that runs its target:
//! thumbv6m → `microbit` (nRF51, 256 KiB flash, 16 KiB RAM), thumbv7m → `mps2-an385` and
//! thumbv7em → `mps2-an386` (4 MiB + 4 MiB: carrying every engine at once, this firmware is
//! larger than the LM3S6965's 256 KiB of flash; no board's own firmware is). `-Tlink.x` comes from here
//! because a build from the workspace root ignores a board's `.cargo/config.toml`.

use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let target = env::var("TARGET").unwrap_or_default();
    let memory = if target.starts_with("thumbv6m") {
        "MEMORY\n{\n  FLASH : ORIGIN = 0x00000000, LENGTH = 256K\n  RAM : ORIGIN = 0x20000000, LENGTH = 16K\n}\n"
    } else {
        "MEMORY\n{\n  FLASH : ORIGIN = 0x00000000, LENGTH = 4M\n  RAM : ORIGIN = 0x20000000, LENGTH = 4M\n}\n"
    };
    fs::write(out.join("memory.x"), memory).expect("OUT_DIR is writable");
    println!("cargo:rerun-if-changed=build.rs");
    // The default build (every scene not in a build of its own): one name for it, where
    // the code would otherwise repeat the list of the other builds' features.
    println!("cargo::rustc-check-cfg=cfg(measure_default)");
    let own_build = ["NEWER", "PANELS", "SHAPES", "TERRAIN"]
        .iter()
        .any(|feature| env::var_os(format!("CARGO_FEATURE_{feature}")).is_some());
    if !own_build {
        println!("cargo:rustc-cfg=measure_default");
    }
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
