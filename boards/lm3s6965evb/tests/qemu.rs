//! Boots the firmware in QEMU's `lm3s6965evb` (headless), takes a screendump of every scene
//! through the monitor, and compares it with the same scene rendered on the host: every
//! pixel must be identical. That is the proof that fixed point makes the MCU and the host
//! agree.
//!
//! QEMU shows each OLED pixel as a 4×4 block, grey level n as n·0x11 in R, G and B.
//! Without `qemu-system-arm` the test is built as ignored (and says what to install),
//! except under `CI=true`, where it runs and fails (`.ci/run` installs QEMU).

use tinyfractal_test_support::qemu as tools;

use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::net::UnixStream;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use tinyfractal_lm3s6965evb::{
    framebuffer,
    scenes::{self, DEEP_SCENES, SCENES, ZOOM_SCENES},
    Framebuffer,
};

const MAGNIFY: usize = 4;

/// Builds the firmware in its own target folder (the outer `cargo test` holds the main one).
fn build_firmware() -> PathBuf {
    let board = Path::new(env!("CARGO_MANIFEST_DIR"));
    tools::ensure_target(board, "thumbv7m-none-eabi");
    let target_dir = board.join("../../target/qemu-firmware");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .args([
            "build",
            "--release",
            "--target",
            "thumbv7m-none-eabi",
            "--manifest-path",
        ])
        .arg(board.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&target_dir)
        .status()
        .expect("cargo runs");
    assert!(status.success(), "the firmware must build");
    target_dir.join("thumbv7m-none-eabi/release/tinyfractal-lm3s6965evb")
}

/// The HMP monitor: send a command, wait for the next prompt.
struct Monitor(UnixStream);

impl Monitor {
    fn connect(path: &Path) -> Self {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            if let Ok(stream) = UnixStream::connect(path) {
                stream
                    .set_read_timeout(Some(Duration::from_secs(60)))
                    .unwrap();
                let mut monitor = Monitor(stream);
                monitor.until_prompt();
                return monitor;
            }
            assert!(
                Instant::now() < deadline,
                "QEMU's monitor socket never appeared"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    fn until_prompt(&mut self) {
        let mut seen = Vec::new();
        let mut buffer = [0u8; 4096];
        while !seen.ends_with(b"(qemu) ") {
            let n = self.0.read(&mut buffer).expect("monitor answers");
            assert!(n > 0, "monitor closed");
            seen.extend_from_slice(&buffer[..n]);
        }
    }

    fn command(&mut self, command: &str) {
        self.0.write_all(format!("{command}\n").as_bytes()).unwrap();
        self.until_prompt();
    }
}

/// A binary PPM (P6): width, height and RGB bytes.
fn read_ppm(path: &Path) -> (usize, usize, Vec<u8>) {
    let bytes = std::fs::read(path).unwrap();
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        fields.push(String::from_utf8_lossy(&bytes[start..at]).into_owned());
    }
    assert_eq!(fields[0], "P6");
    let (w, h) = (fields[1].parse().unwrap(), fields[2].parse().unwrap());
    (w, h, bytes[at + 1..].to_vec())
}

#[test]
#[cfg_attr(
    tinyfractal_no_qemu,
    ignore = "needs qemu-system-arm: apt-get install qemu-system-arm"
)]
#[cfg_attr(
    all(tinyfractal_no_thumb_targets, not(tinyfractal_no_qemu)),
    ignore = "needs the thumbv7m-none-eabi target: rustup target add thumbv7m-none-eabi"
)]
fn firmware_matches_the_host_pixel_for_pixel() {
    let elf = build_firmware();
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("qemu");
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    let socket = work.join("monitor.sock");
    let mut qemu = tools::qemu()
        .args([
            "-cpu",
            "cortex-m3",
            "-machine",
            "lm3s6965evb",
            "-display",
            "none",
        ])
        .arg("-monitor")
        .arg(format!("unix:{},server,nowait", socket.display()))
        .args(["-semihosting-config", "enable=on,target=native", "-kernel"])
        .arg(&elf)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("QEMU starts");
    let (lines, receive) = mpsc::channel();
    let stdout = qemu.stdout.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if lines.send(line).is_err() {
                break;
            }
        }
    });
    let mut monitor = Monitor::connect(&socket);
    let next_line = || {
        receive
            .recv_timeout(Duration::from_secs(180))
            .expect("the firmware speaks")
    };

    for (index, entry) in SCENES
        .iter()
        .chain(&DEEP_SCENES)
        .chain(&ZOOM_SCENES)
        .enumerate()
    {
        let (name, scene) = (entry.name, entry.scene);
        let line = next_line();
        assert!(
            line.starts_with(&format!("scene {index} {name} done")),
            "firmware said: {line}"
        );
        let dump = work.join(format!("{index}-{name}.ppm"));
        monitor.command(&format!("screendump {}", dump.display()));
        let (w, h, rgb) = read_ppm(&dump);
        assert_eq!(
            (w, h),
            (
                framebuffer::WIDTH as usize * MAGNIFY,
                framebuffer::HEIGHT as usize * MAGNIFY
            )
        );

        let mut host = Framebuffer::new();
        let work_done = scene.draw(&mut host, &scenes::GREY).unwrap();
        assert!(
            line.ends_with(&format!("{work_done:?}")),
            "same work on both: {line} vs {work_done:?}"
        );
        let mut lit = 0;
        for y in 0..h {
            for x in 0..w {
                let level = host.level((x / MAGNIFY) as u32, (y / MAGNIFY) as u32);
                let expected = level * 0x11;
                let pixel = &rgb[(y * w + x) * 3..(y * w + x) * 3 + 3];
                assert!(
                    pixel.iter().all(|&c| c == expected),
                    "{name}: OLED pixel ({}, {}) is {pixel:?} in QEMU, grey {level} on the host",
                    x / MAGNIFY,
                    y / MAGNIFY
                );
                lit += usize::from(level > 0);
            }
        }
        assert!(
            lit > 16 * 100,
            "{name}: the scene should light a good part of the screen"
        );
        println!(
            "{name}: all {} OLED pixels identical ({line})",
            framebuffer::WIDTH * framebuffer::HEIGHT
        );
        monitor.command("sendkey ctrl");
    }
    assert_eq!(next_line(), "all scenes done");
    let status = qemu.wait().unwrap();
    assert!(
        status.success(),
        "the firmware exits through semihosting: {status}"
    );
}
