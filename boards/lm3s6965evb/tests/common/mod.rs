//! What the QEMU tests share: finding QEMU (and failing loudly under CI without it).

#![allow(dead_code)]

use std::process::{Command, Stdio};

/// Whether the test can run: `qemu-system-arm` is installed. Without it the test prints a
/// loud warning and passes, except under `CI=true`, where it fails.
pub fn qemu_or_skip(test: &str) -> bool {
    let found = Command::new("qemu-system-arm")
        .arg("--version")
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !found {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "qemu-system-arm is missing under CI: .ci/run must install it"
        );
        eprintln!("\n*** WARNING: qemu-system-arm not found: {test} did NOT run. ***");
        eprintln!("*** Install it (apt-get install qemu-system-arm) to check the firmware. ***\n");
    }
    found
}
