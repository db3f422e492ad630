//! Decides which QEMU tests can run on this host (`../tools/detect.rs`).

include!("../tools/detect.rs");

fn main() {
    detect_host_tools();
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=../tools/detect.rs");
}
