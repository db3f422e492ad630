// Included by the build scripts of the crates whose tests boot QEMU (`include!`): decides,
// at build time, which of those tests can run here. A test that cannot is compiled with
// `#[ignore = "..."]` naming what to install, so `cargo test` reports it as ignored, never
// as a silent `ok`. Under `CI=true` nothing is ignored: a missing piece fails the test.
//
// - `tinyfractal_no_qemu`: `qemu-system-arm` is not on the PATH.
// - `tinyfractal_no_thumb_targets`: the Cortex-M standard libraries are not installed for
//   the toolchain (`rustup target add` them). Under `CI=true` the tests add them with
//   rustup themselves.

/// Prints the cfg lines (and what makes cargo decide again).
fn detect_host_tools() {
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_qemu)");
    println!("cargo::rustc-check-cfg=cfg(tinyfractal_no_thumb_targets)");
    println!("cargo:rerun-if-env-changed=CI");
    println!("cargo:rerun-if-env-changed=PATH");
    // Installing QEMU or rustup changes a folder on the PATH: decide again then.
    for folder in std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()) {
        if folder.is_dir() {
            println!("cargo:rerun-if-changed={}", folder.display());
        }
    }
    if std::env::var("CI").as_deref() == Ok("true") {
        return;
    }
    if !runs("qemu-system-arm", &["--version"]) {
        println!("cargo:rustc-cfg=tinyfractal_no_qemu");
    }
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    // Adding a target adds a folder here: decide again then.
    if let Ok(output) = std::process::Command::new(&rustc).args(["--print", "sysroot"]).output() {
        let rustlib = std::path::Path::new(String::from_utf8_lossy(&output.stdout).trim()).join("lib/rustlib");
        if rustlib.is_dir() {
            println!("cargo:rerun-if-changed={}", rustlib.display());
        }
    }
    let installed = ["thumbv6m-none-eabi", "thumbv7m-none-eabi", "thumbv7em-none-eabihf"]
        .iter()
        .all(|target| {
            std::process::Command::new(&rustc)
                .args(["--print", "target-libdir", "--target", target])
                .output()
                .ok()
                .filter(|output| output.status.success())
                .is_some_and(|output| {
                    std::path::Path::new(String::from_utf8_lossy(&output.stdout).trim()).is_dir()
                })
        });
    if !installed {
        println!("cargo:rustc-cfg=tinyfractal_no_thumb_targets");
    }
}

fn runs(program: &str, args: &[&str]) -> bool {
    std::process::Command::new(program)
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok_and(|status| status.success())
}
