//! The explorer in a real SDL window under Xvfb, driven by X input events (xdotool): a
//! click zooms, `s` saves the window's picture, and that picture equals the headless
//! render of the same view. Built with `--features window`; it needs `Xvfb` and `xdotool`
//! (`apt-get install xvfb xdotool libsdl2-dev`): without them it says so and passes,
//! except under `CI=true`, where they are required.

#![cfg(feature = "window")]

mod common;

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use common::{run, scratch, stderr};

fn found(tool: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {tool}")])
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Kills a child when dropped, so a failing test leaves no process behind.
struct Killed(Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// Waits for `ready`, up to 90 s: under load (both cores busy with QEMU and compiles) the
/// window once took longer than 30.
fn wait_for(what: &str, mut ready: impl FnMut() -> bool) {
    let started = Instant::now();
    while !ready() {
        assert!(
            started.elapsed() < Duration::from_secs(90),
            "timed out waiting for {what}"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
}

fn xdotool(display: &str, args: &[&str]) -> String {
    let output = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", display)
        .output()
        .unwrap();
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn pixels(path: &Path) -> Vec<u8> {
    image::open(path).unwrap().into_rgb8().into_raw()
}

#[test]
fn a_click_in_the_window_zooms_and_the_saved_picture_is_the_headless_render() {
    if !(found("Xvfb") && found("xdotool")) {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI needs Xvfb and xdotool"
        );
        eprintln!("skipped: needs Xvfb and xdotool (apt-get install xvfb xdotool)");
        return;
    }
    let dir = scratch("window");
    // Xvfb picks a free display itself and writes its number once it takes connections,
    // so no display of another run (or a stale socket) is ever taken for ours.
    let mut server = Killed(
        Command::new("Xvfb")
            .args(["-displayfd", "1", "-screen", "0", "320x240x24"])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    let mut number = String::new();
    let stdout = server.0.stdout.take().unwrap();
    std::io::BufRead::read_line(&mut std::io::BufReader::new(stdout), &mut number).unwrap();
    assert!(!number.trim().is_empty(), "Xvfb did not start");
    let display = format!(":{}", number.trim());
    let mut explorer = Killed(
        Command::new(env!("CARGO_BIN_EXE_tinyfractal"))
            .args(["explore", "--size", "64x48"])
            .env("DISPLAY", &display)
            .current_dir(&dir)
            .spawn()
            .unwrap(),
    );
    let mut window = String::new();
    wait_for("the window", || {
        // An explorer that stopped will never show one: say how it ended.
        if let Ok(Some(status)) = explorer.0.try_wait() {
            panic!("the explorer exited before its window showed: {status}");
        }
        window = xdotool(
            &display,
            &["search", "--onlyvisible", "--name", "tinyfractal explore"],
        );
        !window.trim().is_empty()
    });
    let window = window.lines().next().unwrap().trim().to_string();
    // Let the window come up and draw its first picture before it is clicked.
    std::thread::sleep(Duration::from_millis(2000));
    xdotool(
        &display,
        &["mousemove", "--window", &window, "16", "12", "click", "1"],
    );
    std::thread::sleep(Duration::from_millis(500));
    // `s` saves the picture once it is complete.
    xdotool(&display, &["key", "--window", &window, "s"]);
    let saved = dir.join("explore-000.png");
    wait_for("the saved picture", || saved.exists());
    std::thread::sleep(Duration::from_millis(200));
    // The view a click at (16, 12) gives: zoomed twice about that pixel's point.
    let spacing = 3.5 / 64.0;
    let point = (-0.75 + (16.5 - 32.0) * spacing, -(12.5 - 24.0) * spacing);
    let centre = (
        point.0 + (-0.75 - point.0) / 2.0,
        point.1 + (0.0 - point.1) / 2.0,
    );
    let expected = dir.join("expected.png");
    let output = run(&[
        "render",
        "mandelbrot",
        "--center",
        &format!("{:e},{:e}", centre.0, centre.1),
        "--width",
        &format!("{:e}", 1.75),
        "--size",
        "64x48",
        "--out",
        expected.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(pixels(&saved), pixels(&expected));
}
