//! A failed run leaves the folder as it was and never panics: standard output closed or
//! full, a `--dimension` that fails, an interrupt while outputs stream, counts without a
//! bound, an animation run again with fewer frames.

mod common;

use common::{run, scratch, stderr, stdout};
use std::fs::File;
use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

fn command(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_tinyfractal"));
    command.args(args).stdin(Stdio::null());
    command
}

/// Waits for `child` at most `limit`; kills it and fails past that.
fn wait_within(child: &mut Child, limit: Duration, what: &str) -> ExitStatus {
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            panic!("{what} did not end within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Runs `args` with stdout closed at once (`closed`) or discarded, at most `limit`: the
/// exit status and stderr.
fn finish(args: &[&str], closed: bool, limit: Duration) -> (ExitStatus, String) {
    let mut child = command(args)
        .stdout(if closed {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The reading end goes at once: every write then fails with a broken pipe.
    drop(child.stdout.take());
    let status = wait_within(&mut child, limit, &args.join(" "));
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (status, err)
}

/// A `.l` file of 20,000 systems: its list (240 KB) is longer than a pipe holds.
fn many_systems(dir: &Path) -> String {
    let path = dir.join("many.l");
    let text: String = (0..20_000)
        .map(|k| format!("System{k:05} {{\n  Angle 4\n  Axiom F\n  F=F+F\n}}\n"))
        .collect();
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Standard output closed before the command writes (a reader such as `head -1` that has
/// gone): a quiet stop with status 1, never a panic (101), and nothing on stderr. Each
/// output is longer than a pipe holds (the derivation is Fibonacci's, 2.2 million symbols),
/// so a reading end that another test's child holds for a moment, between its fork and its
/// exec, cannot let the whole output through.
#[test]
fn a_closed_standard_output_is_a_quiet_stop() {
    let dir = scratch("closed");
    let many = many_systems(&dir);
    for args in [
        vec!["list", many.as_str()],
        vec!["completions", "bash"],
        vec![
            "derive",
            "--axiom",
            "A",
            "--rule",
            "A=AB",
            "--rule",
            "B=A",
            "--order",
            "30",
            "--max-length",
            "20000000",
        ],
    ] {
        let (status, err) = finish(&args, true, Duration::from_secs(30));
        // `completions` may fit the pipe's buffer before it is closed: then it succeeds.
        assert!(
            status.code() == Some(1) || (status.success() && args[0] == "completions"),
            "{args:?}: {status:?} {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// Standard output on a full device: one line naming it, status 1, and the picture that
/// was asked for is not put in place (nor is an old one replaced).
#[test]
fn a_full_standard_output_is_one_error_and_no_picture() {
    let Ok(full) = File::options().write(true).open("/dev/full") else {
        return; // Not Linux: nothing to test with.
    };
    let dir = scratch("full");
    let out = dir.join("m.png");
    std::fs::write(&out, b"old").unwrap();
    let output = command(&[
        "render",
        "mandelbrot",
        "--size",
        "32x24",
        "--stats",
        "--out",
        out.to_str().unwrap(),
    ])
    .stdout(full.try_clone().unwrap())
    .output()
    .unwrap();
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let err = stderr(&output);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("cannot write to standard output"), "{err}");
    assert_eq!(std::fs::read(&out).unwrap(), b"old");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "a temporary was left"
    );
    // The gallery: all or nothing, its folder not even made.
    let gallery = dir.join("gallery");
    let output = command(&["gallery", "--out", gallery.to_str().unwrap()])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert!(!gallery.exists(), "the gallery left {gallery:?}");
}

/// A `--dimension` that fails (boxes that do not fit a 4×4 picture) fails before the
/// picture is put in place.
#[test]
fn a_failing_dimension_replaces_nothing() {
    let dir = scratch("dimension");
    let out = dir.join("tiny.png");
    std::fs::write(&out, b"old").unwrap();
    let output = run(&[
        "render",
        "lsystem",
        "--axiom",
        "F",
        "--angle",
        "4",
        "--order",
        "1",
        "--size",
        "4x4",
        "--dimension",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("dimension:"),
        "{}",
        stderr(&output)
    );
    assert_eq!(stdout(&output), "");
    assert_eq!(std::fs::read(&out).unwrap(), b"old");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "a temporary was left"
    );
}

/// Ctrl-C while `--segments` streams: the temporary files go, nothing is put in place.
#[cfg(unix)]
#[test]
fn an_interrupt_removes_the_temporaries() {
    let dir = scratch("interrupt");
    let (png, txt) = (dir.join("koch.png"), dir.join("koch.txt"));
    let mut child = command(&[
        "render",
        "lsystem",
        "--axiom",
        "F",
        "--rule",
        "F=F+F-F-F+F",
        "--angle",
        "4",
        "--order",
        "13",
        "--segments",
        txt.to_str().unwrap(),
        "--out",
        png.to_str().unwrap(),
    ])
    .stderr(Stdio::piped())
    .spawn()
    .unwrap();
    // Waits for the segments' temporary file to be written.
    let started = Instant::now();
    while std::fs::read_dir(&dir).unwrap().count() < 2 {
        assert!(
            started.elapsed() < Duration::from_secs(30),
            "no temporary appeared"
        );
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before the interrupt"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = wait_within(&mut child, Duration::from_secs(30), "the interrupted run");
    assert_eq!(status.code(), Some(130));
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    assert!(left.is_empty(), "left {left:?}");
}

/// Counts without a bound are refused with the bound (a usage error), and a derivation
/// with no practical limit streams: `derive ... | head` ends at once.
#[test]
fn counts_are_bounded_or_stream() {
    for args in [
        vec![
            "render",
            "ifs",
            "--map",
            "0.5,0,0,0.5,0,0,1",
            "--points-count",
            "18446744073709551615",
        ],
        vec![
            "render",
            "gingerbread",
            "--iterations",
            "18446744073709551615",
        ],
    ] {
        let (status, err) = finish(&args, false, Duration::from_secs(10));
        assert_eq!(status.code(), Some(2), "{args:?}");
        assert!(err.contains("0..=1000000000"), "{err}");
    }
    let mut child = command(&[
        "derive",
        "--axiom",
        "F",
        "--rule",
        "F=F+F",
        "--angle",
        "4",
        "--order",
        "60",
        "--max-length",
        "18446744073709551615",
    ])
    .stdout(Stdio::piped())
    .stderr(Stdio::piped())
    .spawn()
    .unwrap();
    let mut first = [0u8; 100];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    assert_eq!(&first[..6], b"F+F+F+");
    drop(child.stdout.take());
    let status = wait_within(&mut child, Duration::from_secs(10), "derive | head");
    assert_eq!(status.code(), Some(1));
}

/// An animation into a folder run again with fewer frames leaves none of the first run's.
#[test]
fn fewer_frames_leave_no_stale_frames() {
    let dir = scratch("stale");
    let frames = dir.join("frames");
    let animate = |count: &str| {
        let output = run(&[
            "animate",
            "zoom",
            "--frames",
            count,
            "--size",
            "16x12",
            "--out",
            frames.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
    };
    animate("5");
    std::fs::write(frames.join("notes.txt"), b"mine").unwrap();
    animate("2");
    let mut names: Vec<String> = std::fs::read_dir(&frames)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["frame-0000.png", "frame-0001.png", "notes.txt"]);
}

/// The peak resident memory of a run, in KiB, polled from `/proc` while it runs.
#[cfg(target_os = "linux")]
fn peak_kib(args: &[&str]) -> u64 {
    let mut child = command(args).stdout(Stdio::null()).spawn().unwrap();
    let status_file = format!("/proc/{}/status", child.id());
    let mut peak = 0;
    loop {
        if let Ok(status) = std::fs::read_to_string(&status_file) {
            if let Some(kib) = status
                .lines()
                .find_map(|line| line.strip_prefix("VmHWM:"))
                .and_then(|rest| {
                    rest.trim()
                        .trim_end_matches("kB")
                        .trim()
                        .parse::<u64>()
                        .ok()
                })
            {
                peak = peak.max(kib);
            }
        }
        if let Some(status) = child.try_wait().unwrap() {
            assert!(status.success(), "{args:?}");
            return peak;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// An animation's memory does not grow with its frames: they stream to the encoder. At
/// 768×768 a frame is 1.7 MiB and more, 24 more frames held at once some 50 MiB (at
/// 1024×1024, 24 frames took 107 MB against 17 MB for 2); streamed, the memory stops
/// growing once the pipeline (a frame being made, one waiting, one being encoded) is full.
#[cfg(target_os = "linux")]
#[test]
fn an_animations_memory_does_not_grow_with_its_frames() {
    let dir = scratch("memory");
    let run_with = |frames: &str, out: &str| {
        let out = dir.join(out);
        peak_kib(&[
            "animate",
            "palette",
            "--frames",
            frames,
            "--size",
            "768x768",
            "--max-iter",
            "32",
            "--out",
            out.to_str().unwrap(),
        ])
    };
    for out in ["frames", "cycle.png"] {
        let few = run_with("8", out);
        let many = run_with("32", out);
        assert!(
            many < few + 16 * 1024,
            "{out}: {many} KiB at 32 frames against {few} KiB at 8"
        );
    }
}

/// An animation that fails part way (Koch too fine for 64×48 at order 17) leaves nothing:
/// no folder made for it, no file, no temporary; the message is the animation's.
#[test]
fn an_animation_failing_part_way_leaves_nothing() {
    let dir = scratch("failing-animation");
    for out in ["frames", "grow.gif", "grow.png"] {
        let path = dir.join(out);
        let output = run(&[
            "animate",
            "growth",
            "--axiom",
            "F",
            "--rule",
            "F=F+F--F+F",
            "--angle",
            "6",
            "--order",
            "18",
            "--size",
            "64x48",
            "--out",
            path.to_str().unwrap(),
        ]);
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        assert!(
            stderr(&output).contains("too many steps across"),
            "{}",
            stderr(&output)
        );
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .collect();
        assert!(left.is_empty(), "{out}: left {left:?}");
    }
}
