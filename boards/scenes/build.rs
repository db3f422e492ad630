//! Decides which QEMU tests can run on this host (`../tools/detect.rs`).

include!("../tools/detect.rs");

fn main() {
    detect_host_tools();
    // ARMv6-M's measuring board, the micro:bit, has 16 KiB of RAM: fewer table cells.
    println!("cargo::rustc-check-cfg=cfg(scenes_small_ram)");
    if std::env::var("TARGET").is_ok_and(|target| target.starts_with("thumbv6m")) {
        println!("cargo:rustc-cfg=scenes_small_ram");
    }
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=../tools/detect.rs");
}
