//! Options and files are never silently ignored or misread: an option that does not apply
//! is a usage error, files are known by content and extension in any case, and messages
//! name the real cause and the option's own limits.

mod common;

use common::{run, scratch, shipped, stderr};
use std::path::Path;

/// Exit status 2, and stderr holding each of `expected`.
fn usage_error(args: &[&str], expected: &[&str]) {
    let output = run(args);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
    for text in expected {
        assert!(err.contains(text), "{args:?}: `{text}` not in {err}");
    }
}

#[test]
fn options_that_do_not_apply_are_usage_errors() {
    let dir = scratch("not-applying");
    let out = dir.join("never.png");
    let out = out.to_str().unwrap();
    let classics = shipped("classics.l");
    let koch = [
        "render",
        "lsystem",
        "--file",
        &classics,
        "--name",
        "KochCurve",
        "--order",
        "2",
    ];
    for (option, value) in [
        ("--projection", Some("iso")),
        ("--depth-cue", None),
        ("--environment", Some("circle:1")),
        ("--seed", Some("3")),
    ] {
        let mut args = koch.to_vec();
        args.push(option);
        args.extend(value);
        args.extend(["--out", out]);
        usage_error(&args, &[&format!("{option} does not apply to KochCurve")]);
    }
    usage_error(
        &[
            "derive",
            "--file",
            &classics,
            "--name",
            "KochCurve",
            "--order",
            "1",
            "--seed",
            "2",
        ],
        &["--seed does not apply"],
    );
    for option in [["--segments", "s.txt"].as_slice(), &["--dimension"]] {
        let mut args = vec!["render", "figure", "--frames", "3", "--out", out];
        args.extend(option);
        usage_error(&args, &["cannot be used with"]);
    }
    usage_error(
        &[
            "animate", "growth", "--axiom", "F", "--angle", "4", "--order", "2", "--frames", "3",
        ],
        &["--frames does not apply to the growth of a plain system"],
    );
    // Found after parsing, by the command that draws: still a usage error, naming the fix.
    usage_error(
        &["render", "lsystem", "--axiom", "F", "--order", "2"],
        &[
            "an inline system needs --angle N or --angle-deg DEG",
            "tinyfractal help",
        ],
    );
    usage_error(
        &["animate", "zoom", "--frames", "0", "--out", out],
        &["--frames 0: give at least one frame"],
    );
    assert!(!Path::new(out).exists());
}

#[test]
fn limits_and_causes_are_the_options_own() {
    usage_error(
        &["render", "mandelbrot", "--max-iter", "0"],
        &["--max-iter", "1..=65535"],
    );
    usage_error(
        &["render", "mandelbrot", "--max-iter", "-1"],
        &["--max-iter", "-1"],
    );
    usage_error(
        &[
            "render", "lsystem", "--axiom", "F", "--angle", "4", "--order", "1000",
        ],
        &["--order", "0..=256"],
    );
    usage_error(
        &["animate", "zoom", "--frames", "-1"],
        &["--frames -1", "not a negative number"],
    );
    usage_error(
        &[
            "render",
            "attractor",
            "--skip",
            "99999999999",
            "--size",
            "8x8",
        ],
        &["--skip", "0..=1000000000"],
    );
    // Clap names only the first characters of a negative decimal (`'-0'`): the whole value
    // and its option are named.
    usage_error(
        &["render", "reaction", "--feed", "-0.1", "--size", "8x8"],
        &["--feed -0.1", "not a negative number"],
    );
    usage_error(
        &["render", "attractor", "--dt", "-0.01", "--size", "8x8"],
        &["--dt -0.01", "not a negative number"],
    );
    usage_error(
        &["render", "lsystem", "--axiom", "F", "--angle", "-30"],
        &["--angle -30", "not a negative number"],
    );
    // An unknown option before a negative number is still the unknown option.
    usage_error(
        &["animate", "zoom", "--frobnicate", "-1"],
        &["'--frobnicate'"],
    );
    usage_error(
        &["render", "mandelbrot", "--size", "0x0"],
        &["0x0 has no pixels"],
    );
    // A zoom whose factor runs past the deepest view names the factor and the frame, not
    // --width.
    let output = run(&[
        "animate", "zoom", "--factor", "1000", "--frames", "16", "--size", "8x6",
    ]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{err}");
    assert!(
        err.contains("frame 15 of the zoom") && !err.contains("--width:"),
        "{err}"
    );
    // Koch at order 18 is too fine for the target: said so, no `@` blamed.
    let output = run(&[
        "render",
        "lsystem",
        "--file",
        &shipped("classics.l"),
        "--name",
        "KochCurve",
        "--order",
        "18",
    ]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{err}");
    assert!(
        err.contains("too many steps across") && !err.contains('@'),
        "{err}"
    );
    // The help says the limits and each command's own defaults.
    for (args, expected) in [
        (vec!["render", "mandelbrot", "--help"], "1 to 65535"),
        (vec!["render", "lsystem", "--help"], "0 to 256"),
        (vec!["render", "julia", "--help"], "0,0 for a Julia set"),
    ] {
        let output = run(&args);
        assert!(output.status.success());
        assert!(common::stdout(&output).contains(expected), "{args:?}");
    }
    let zoom_help = common::stdout(&run(&["animate", "zoom", "--help"]));
    assert!(!zoom_help.contains("growth"), "{zoom_help}");
}

#[test]
fn files_are_known_by_content_and_extension() {
    let dir = scratch("files");
    // An upper-case extension is the same kind.
    let upper = dir.join("ABOP.LSYS");
    std::fs::copy(shipped("abop.lsys"), &upper).unwrap();
    let output = run(&["list", upper.to_str().unwrap()]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        common::stdout(&output).starts_with("Fig1.24a\n"),
        "{}",
        common::stdout(&output)
    );
    // A UTF-8 byte-order mark is skipped.
    let bom = dir.join("bom.l");
    let mut text = vec![0xef, 0xbb, 0xbf];
    text.extend(std::fs::read(shipped("classics.l")).unwrap());
    std::fs::write(&bom, text).unwrap();
    let output = run(&["list", bom.to_str().unwrap()]);
    assert!(
        common::stdout(&output).starts_with("KochCurve\n"),
        "{}",
        common::stdout(&output)
    );
    // UTF-16 and binary files are named as such.
    let utf16 = dir.join("wide.l");
    std::fs::write(&utf16, [0xff, 0xfe, b'K', 0, b'o', 0]).unwrap();
    let output = run(&["list", utf16.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("is UTF-16 text"),
        "{}",
        stderr(&output)
    );
    let binary = dir.join("image.l");
    std::fs::write(&binary, [0x89, b'P', b'N', b'G', 0, 0, 0, 13]).unwrap();
    let output = run(&["list", binary.to_str().unwrap()]);
    assert!(
        stderr(&output).contains("is a binary file"),
        "{}",
        stderr(&output)
    );
    // Too large a file is named as such, without guessing what it was meant to be: here a
    // palette (a sparse file, so nothing is written to the disk).
    let huge = dir.join("huge.map");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(17 << 20)
        .unwrap();
    let output = run(&[
        "render",
        "mandelbrot",
        "--palette-file",
        huge.to_str().unwrap(),
        "--size",
        "8x8",
    ]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{err}");
    assert!(
        err.contains("larger than 16 MiB") && err.contains(".map") && !err.contains("is it a"),
        "{err}"
    );
    // An IFS file given to the L-system reader, under any extension.
    let disguised = dir.join("fern.l");
    std::fs::copy(shipped("lecture.ifs"), &disguised).unwrap();
    for path in [shipped("lecture.ifs"), disguised.display().to_string()] {
        let output = run(&[
            "render", "lsystem", "--file", &path, "--name", "fern", "--order", "2",
        ]);
        assert_eq!(output.status.code(), Some(1));
        assert!(
            stderr(&output).contains("is an IFS file"),
            "{}",
            stderr(&output)
        );
    }
    // `--seed` goes by what the file holds: an `.lsys` file under another extension takes
    // it, and the seed picks the stochastic plant's productions.
    let plant = dir.join("plants.txt");
    std::fs::copy(shipped("abop.lsys"), &plant).unwrap();
    let derive = |seed: &str| {
        let output = run(&[
            "derive",
            "--file",
            plant.to_str().unwrap(),
            "--name",
            "Fig1.27",
            "--order",
            "3",
            "--seed",
            seed,
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        common::stdout(&output)
    };
    assert_ne!(derive("1"), derive("2"));
    // `list` lists an IFS file's entries.
    let output = run(&["list", &shipped("lecture.ifs")]);
    assert_eq!(common::stdout(&output), "fern\ngasket\n");
}

/// The lecture's algae (A → AB, B → A) has no angle: deriving it needs none, drawing it
/// says what is missing.
#[test]
fn derive_needs_no_angle() {
    let dir = scratch("algae");
    let fractint = dir.join("algae.l");
    std::fs::write(&fractint, "Algae {\n  Axiom A\n  A=AB\n  B=A\n}\n").unwrap();
    let lsys = dir.join("algae.lsys");
    std::fs::write(&lsys, "Algae {\n  axiom: A\n  A --> AB\n  B --> A\n}\n").unwrap();
    for (path, expected) in [(&fractint, "abaababa\n"), (&lsys, "ABAABABAABAAB\n")] {
        let path = path.to_str().unwrap();
        let order = if path.ends_with(".l") { "4" } else { "5" };
        let output = run(&[
            "derive", "--file", path, "--name", "algae", "--order", order,
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        assert_eq!(common::stdout(&output), expected);
        let out = dir.join("algae.png");
        let output = run(&[
            "render",
            "lsystem",
            "--file",
            path,
            "--name",
            "algae",
            "--order",
            "3",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(output.status.code(), Some(1));
        assert!(
            stderr(&output).contains("has no angle"),
            "{}",
            stderr(&output)
        );
    }
}
