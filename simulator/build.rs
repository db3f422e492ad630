//! Builds the playground's WebAssembly module (the `web` crate, for
//! `wasm32-unknown-unknown`, in its own target folder beside this build's) so that
//! `tinyfractal serve` embeds it: `cargo run --release -- serve` is all a user types.
//!
//! Where it cannot be built (no `wasm32-unknown-unknown` target installed, say) the
//! binary is built without it, with a warning, and `serve` says what to do. The build is
//! skipped when this crate is itself built for WebAssembly (inside that build).

use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The module's file name, as cargo names the `web` crate's `cdylib`.
const MODULE: &str = "tinyfractal_web.wasm";

fn main() {
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_playground)");
    println!("cargo:rerun-if-changed=build.rs");
    let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let root = manifest.join("..");
    for path in [
        "src",
        "simulator/src",
        "simulator/Cargo.toml",
        "web",
        "boards/scenes/src",
        "Cargo.toml",
        "Cargo.lock",
    ] {
        println!("cargo:rerun-if-changed={}", root.join(path).display());
    }
    if env::var("TARGET").is_ok_and(|target| target.starts_with("wasm32")) {
        return;
    }
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap_or_default());
    let module = out.join(MODULE);
    match build(&root, &out) {
        Ok(built) => {
            if std::fs::copy(&built, &module).is_ok() {
                println!("cargo:rustc-cfg=tinyfractal_playground");
            }
        }
        Err(why) => {
            println!("cargo:warning=the playground's WebAssembly module was not built ({why}); `tinyfractal serve` will say how to build it");
        }
    }
}

/// Builds the module with the `wasm` profile into a target folder shared by this build's
/// profiles (beside `debug` and `release`), and returns its path.
fn build(root: &Path, out: &Path) -> Result<PathBuf, String> {
    // OUT_DIR is TARGET/PROFILE/build/PACKAGE-HASH/out (or TARGET/TRIPLE/PROFILE/...).
    let target_dir = out
        .ancestors()
        .nth(4)
        .ok_or("no target folder above OUT_DIR")?
        .join("playground");
    let cargo = env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(cargo)
        .current_dir(root)
        .args([
            "build",
            "--package",
            "tinyfractal-web",
            "--profile",
            "wasm",
            "--target",
            "wasm32-unknown-unknown",
            "--target-dir",
        ])
        .arg(&target_dir)
        // The outer build's wrappers and flags (clippy's, the host's) are not the module's.
        .env_remove("RUSTC_WORKSPACE_WRAPPER")
        .env_remove("RUSTC_WRAPPER")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("RUSTFLAGS")
        .env_remove("CLIPPY_ARGS")
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET")
        .status()
        .map_err(|e| format!("cargo did not start: {e}"))?;
    if !status.success() {
        return Err("`rustup target add wasm32-unknown-unknown` may be missing".to_string());
    }
    Ok(target_dir
        .join("wasm32-unknown-unknown")
        .join("wasm")
        .join(MODULE))
}
