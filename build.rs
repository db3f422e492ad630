//! Tells the core which targets have no 32×32→64 multiply instruction: ARMv6-M (Cortex-M0,
//! M0+, M1) and ARMv8-M Baseline (Cortex-M23). There a 64-bit product is a call to
//! `__aeabi_lmul`, and `real::mul_u32_wide` builds it from 16-bit halves instead. (Stable Rust
//! has no `target_feature` cfg for this, so the target name decides.) The products are exact
//! either way: results are bit-identical on every target.

use std::env;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_long_multiply)");
    println!("cargo:rerun-if-changed=build.rs");
    let target = env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("thumbv8m.base") {
        println!("cargo:rustc-cfg=tinyfractal_no_long_multiply");
    }
}
