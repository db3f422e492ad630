//! Tells the core which targets have no 32×32→64 multiply instruction: ARMv6-M (Cortex-M0,
//! M0+, M1) and ARMv8-M Baseline (Cortex-M23). There a 64-bit product is a call to
//! `__aeabi_lmul`, and `math::wide::mul_u32_wide` builds it from 16-bit halves instead. (Stable Rust
//! has no `target_feature` cfg for this, so the target name decides.) The products are exact
//! either way: results are bit-identical on every target. Likewise
//! `tinyfractal_rounding_multiply` marks ARMv7E-M, whose `smmulr` rounds a product's high
//! word in one instruction; elsewhere the same bits come from the low word's top bit. And
//! `tinyfractal_few_registers` marks ARMv6-M and ARMv8-M Baseline, whose data-processing
//! instructions reach only eight registers: a loop that holds many values is laid out
//! differently there, with the same results. `tinyfractal_no_hardware_divide` and
//! `tinyfractal_no_leading_zeros` mark ARMv6-M, which divides and counts a word's leading
//! zeros in library calls.
//!
//! It also finds Fractint's corpus for the tests that read it (`TINYFRACTAL_CORPUS`, or
//! `shared/corpus` beside the repository): where it is missing they are built as ignored
//! (the `tinyfractal_corpus` cfg is unset), except under `CI=true`, where they must run.
//! Nothing in the library depends on either.

use std::env;
use std::path::PathBuf;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_long_multiply)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_hardware_divide)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_leading_zeros)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_corpus)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_rounding_multiply)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_few_registers)");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=TINYFRACTAL_CORPUS");
    println!("cargo:rerun-if-env-changed=CI");
    let corpus = env::var_os("TINYFRACTAL_CORPUS").map_or_else(
        // Read when the script runs, not when it was compiled: a target folder copied
        // from another clone kept that clone's path.
        || {
            PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default())
                .join("../shared/corpus")
        },
        PathBuf::from,
    );
    // Watching a folder that does not exist would rerun this on every build; after adding
    // shared/ later, set TINYFRACTAL_CORPUS (or touch build.rs) to be seen.
    if corpus.exists() {
        println!("cargo:rerun-if-changed={}", corpus.display());
    }
    if corpus.join("fractint").is_dir() || env::var("CI").as_deref() == Ok("true") {
        println!("cargo:rustc-cfg=tinyfractal_corpus");
    }
    println!(
        "cargo:rustc-env=TINYFRACTAL_CORPUS_DIR={}",
        corpus.display()
    );
    let target = env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("thumbv8m.base") {
        println!("cargo:rustc-cfg=tinyfractal_no_long_multiply");
        println!("cargo:rustc-cfg=tinyfractal_few_registers");
    }
    // ARMv6-M divides in library calls even for 32 bits: there a 64-bit division is one
    // call where the 32-bit way is several. It also counts a word's leading zeros in a
    // library call, which `math::bits` replaces.
    if target.starts_with("thumbv6m") {
        println!("cargo:rustc-cfg=tinyfractal_no_hardware_divide");
        println!("cargo:rustc-cfg=tinyfractal_no_leading_zeros");
    }
    // ARMv7E-M (Cortex-M4/M7) has the DSP extension's rounding high-word multiplies.
    if target.starts_with("thumbv7em") {
        println!("cargo:rustc-cfg=tinyfractal_rounding_multiply");
    }
}
