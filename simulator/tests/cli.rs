//! The command-line contract: outputs, formats, exit codes, and no partial files on error.

mod common;

use common::{run, scratch, stderr, stdout};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn small_l() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data/small.l")
        .display()
        .to_string()
}

/// `render lsystem` of the Koch snowflake given inline (ABOP dialect unless `extra` says
/// otherwise), with `extra` arguments.
fn koch(extra: &[&str]) -> Output {
    let mut args = vec![
        "render",
        "lsystem",
        "--axiom",
        "F--F--F",
        "--rule",
        "F=F+F--F+F",
        "--angle",
        "6",
    ];
    args.extend_from_slice(extra);
    run(&args)
}

#[test]
fn renders_an_inline_system_with_segments_and_stats() {
    let dir = scratch("inline");
    let (png, txt) = (dir.join("koch.png"), dir.join("koch.txt"));
    let output = koch(&[
        "--order",
        "2",
        "--out",
        png.to_str().unwrap(),
        "--segments",
        txt.to_str().unwrap(),
        "--stats",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let stats = stdout(&output);
    for key in [
        "segments=48 ",
        "max_stack=0 ",
        "fit_ms=",
        "draw_ms=",
        "elapsed_ms=",
    ] {
        assert!(stats.contains(key), "{stats}");
    }
    let text = std::fs::read_to_string(&txt).unwrap();
    let segments: Vec<[f64; 4]> = text
        .lines()
        .map(|line| {
            let v: Vec<f64> = line.split(' ').map(|n| n.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect();
    assert_eq!(segments.len(), 3 * 4 * 4);
    // Turtle units: from the origin along +x with step 1, `+` counter-clockwise (y up).
    let h = 3f64.sqrt() / 2.0;
    let expected_start = [
        [0.0, 0.0, 1.0, 0.0],
        [1.0, 0.0, 1.5, h],
        [1.5, h, 2.0, 0.0],
        [2.0, 0.0, 3.0, 0.0],
    ];
    for (got, want) in segments.iter().zip(expected_start) {
        for k in 0..4 {
            assert!((got[k] - want[k]).abs() < 1e-9, "{got:?} vs {want:?}");
        }
    }
    // The snowflake closes.
    let last = segments[segments.len() - 1];
    assert!(last[2].abs() < 1e-9 && last[3].abs() < 1e-9, "{last:?}");
    let image = std::fs::read(&png).unwrap();
    assert_eq!(&image[1..4], b"PNG");
    // Width and height in the IHDR chunk: the default size.
    assert_eq!(u32::from_be_bytes(image[16..20].try_into().unwrap()), 320);
    assert_eq!(u32::from_be_bytes(image[20..24].try_into().unwrap()), 240);
}

#[test]
fn renders_from_a_file_by_case_insensitive_name() {
    let dir = scratch("file");
    let png = dir.join("dragon.png");
    let output = run(&[
        "render",
        "lsystem",
        "--file",
        &small_l(),
        "--name",
        "DRAGON",
        "--order",
        "6",
        "--size",
        "64x48",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let image = std::fs::read(&png).unwrap();
    assert_eq!(u32::from_be_bytes(image[16..20].try_into().unwrap()), 64);
    assert_eq!(u32::from_be_bytes(image[20..24].try_into().unwrap()), 48);
}

#[test]
fn lists_the_systems_in_a_file() {
    let output = run(&["list", &small_l()]);
    assert!(output.status.success());
    assert_eq!(stdout(&output), "Koch1\nDragon\n");
}

#[test]
fn errors_name_the_system_and_leave_no_file() {
    let dir = scratch("errors");
    let out = dir.join("never.png");
    let segments = dir.join("never.txt");
    let out_arg = out.to_str().unwrap().to_string();
    let seg_arg = segments.to_str().unwrap().to_string();
    let small = small_l();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--file", &small, "--name", "nope", "--order", "2"],
            "nope in",
        ),
        (
            vec!["--axiom", "F]", "--angle", "4", "--order", "2"],
            "unbalanced `]` at column 2",
        ),
        (
            vec![
                "--axiom",
                "F",
                "--rule",
                "F=[[[[[F]]]]]",
                "--angle",
                "4",
                "--order",
                "210",
            ],
            "deeper than the turtle stack (1024 levels)",
        ),
        (
            vec!["--axiom", "F", "--angle", "0", "--order", "1"],
            "angle 0",
        ),
        (
            vec![
                "--axiom",
                "F",
                "--rule",
                "F=FC999F",
                "--dialect",
                "fractint",
                "--angle",
                "4",
                "--order",
                "1",
            ],
            "`c` at column 2",
        ),
        (
            vec!["--file", "/no/such/file.l", "--name", "x", "--order", "1"],
            "cannot read /no/such/file.l",
        ),
    ];
    for (args, message) in cases {
        let mut full = vec!["render", "lsystem"];
        full.extend(args.iter().copied());
        full.extend(["--out", &out_arg, "--segments", &seg_arg]);
        let output = run(&full);
        assert_eq!(output.status.code(), Some(1), "{full:?}");
        let err = stderr(&output);
        assert!(
            err.starts_with("tinyfractal: error: ") && err.contains(message),
            "{full:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
        assert!(!out.exists() && !segments.exists(), "{full:?} left a file");
        assert!(
            std::fs::read_dir(&dir).unwrap().next().is_none(),
            "{full:?} left a partial file"
        );
    }
}

#[test]
fn usage_mistakes_exit_with_2() {
    for args in [
        vec!["render"],
        vec!["render", "lsystem", "--axiom", "F"],
        vec!["bogus"],
    ] {
        let output = run(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(stderr(&output).contains("tinyfractal help"));
    }
}

#[test]
fn gallery_renders_every_scene() {
    let dir = scratch("gallery");
    let output = run(&["gallery", "--out", dir.to_str().unwrap()]);
    assert!(output.status.success(), "{}", stderr(&output));
    let table = stdout(&output);
    for scene in [
        "koch-snowflake",
        "dragon",
        "hilbert",
        "sierpinski-arrowhead",
        "plant",
        "sierpinski-carpet",
        "sierpinski-gasket",
        "menger-sponge",
        "terrain",
        "terrain2d",
        "noise-clouds",
        "noise-terrain",
        "reaction-mitosis",
        "reaction-maze",
        "attractor-henon",
        "attractor-lorenz",
        "attractor-clifford",
        "attractor-dejong",
        "bezier-figure",
        "particles-fireworks",
    ] {
        assert!(table.contains(scene), "{table}");
        assert!(dir.join(format!("{scene}.png")).exists(), "{scene}.png");
    }
    // The deep zoom (10⁻⁹ at 4000 iterations) goes by `Wide`, which keeps the dwells
    // `Deep`'s 60 bits and perturbation lose (measured in docs/tiers.md); past `Deep`'s
    // spacing, perturbation.
    for (deep, tier) in [
        ("deep-zoom", "wide tier"),
        ("deep-minibrot", "perturbation tier"),
        ("deep-spiral", "perturbation tier"),
    ] {
        assert!(
            table.lines().any(|l| l.contains(deep) && l.contains(tier)),
            "{table}"
        );
    }
}

/// The spiral around the Misiurewicz point M₄,₁, to 40 digits.
const M41: &str =
    "--center=-0.1010963638456221610257854457386225654638,0.9562865108091415007710960577299774358098";

#[test]
fn a_centre_with_forty_digits_zooms_to_ten_to_the_minus_thirty() {
    let dir = scratch("deep-render");
    let (out, dwell) = (dir.join("deep.png"), dir.join("deep.txt"));
    let output = run(&[
        "render",
        "mandelbrot",
        M41,
        "--width",
        "1e-30",
        "--max-iter",
        "600",
        "--size",
        "64x48",
        "--out",
        out.to_str().unwrap(),
        "--dwell",
        dwell.to_str().unwrap(),
        "--stats",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("tier=perturbation"),
        "{}",
        stdout(&output)
    );
    let (_, rows) = read_dwell(&dwell);
    let mut dwells: Vec<u32> = rows.concat();
    dwells.sort_unstable();
    dwells.dedup();
    // The spiral's arms, not one flat colour: dwells from about 240 to 290.
    assert!(dwells.len() > 20, "{dwells:?}");
    assert!(
        dwells[0] > 200 && dwells[dwells.len() - 1] < 600,
        "{dwells:?}"
    );
}

#[test]
fn perturbation_by_hand_draws_the_deep_tiers_dwells() {
    let dir = scratch("deep-by-hand");
    let mut dwells = Vec::new();
    for precision in ["deep", "perturbation"] {
        let path = dir.join(format!("{precision}.txt"));
        let output = run(&[
            "render",
            "mandelbrot",
            "--center=-0.743643887037151,0.131825904205330",
            "--width",
            "1e-7",
            "--max-iter",
            "1000",
            "--size",
            "64x32",
            "--precision",
            precision,
            "--out",
            dir.join(format!("{precision}.png")).to_str().unwrap(),
            "--dwell",
            path.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        dwells.push(read_dwell(&path).1.concat());
    }
    let same = dwells[0]
        .iter()
        .zip(&dwells[1])
        .filter(|(a, b)| a == b)
        .count();
    assert!(
        same * 1000 >= dwells[0].len() * 999,
        "{same} of {}",
        dwells[0].len()
    );
}

#[test]
fn deep_input_beyond_the_limits_is_refused_with_the_limit() {
    let dir = scratch("deep-limits");
    let out = dir.join("x.png");
    let cases = [
        ("--width=1e-45".to_string(), M41.to_string(), "2^-148"),
        (
            "--width=1e-30".to_string(),
            format!("--center=0.{}1,0", "0".repeat(60)),
            "tells apart at most 56",
        ),
    ];
    for (width, centre, message) in cases {
        let output = run(&[
            "render",
            "mandelbrot",
            &centre,
            &width,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(output.status.code(), Some(1), "{width} {centre}");
        let err = stderr(&output);
        assert!(err.contains(message), "{err}");
        assert!(!out.exists());
    }
    let output = run(&[
        "render",
        "julia",
        "--c=-0.8,0.156",
        "--width=1e-30",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr(&output).contains("Mandelbrot set only"),
        "{}",
        stderr(&output)
    );
}

fn read_dwell(path: &Path) -> (Vec<u32>, Vec<Vec<u32>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(' ')
        .map(|n| n.parse().unwrap())
        .collect();
    let rows = lines
        .map(|l| l.split(' ').map(|n| n.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

#[test]
fn mandelbrot_dwell_file_and_stats() {
    let dir = scratch("mandelbrot");
    let (png, txt) = (dir.join("m.png"), dir.join("m.txt"));
    let output = run(&[
        "render",
        "mandelbrot",
        "--size",
        "40x30",
        "--max-iter",
        "100",
        "--algorithm",
        "exact",
        "--out",
        png.to_str().unwrap(),
        "--dwell",
        txt.to_str().unwrap(),
        "--stats",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let stats = stdout(&output);
    for key in [
        "iterations=",
        "pixels=1200 ",
        "draw_calls=30 ",
        "tier=medium",
        "elapsed_ms=",
    ] {
        assert!(stats.contains(key), "{stats}");
    }
    let (header, rows) = read_dwell(&txt);
    assert_eq!(header, vec![40, 30, 100]);
    assert_eq!(rows.len(), 30);
    assert!(rows.iter().all(|r| r.len() == 40));
    // Default view: centre -0.75,0, width 3.5. Independent spot checks with f64:
    // pixel (20, 15) samples c = (-0.75 + 0.5·3.5/40, -0.5·3.5/40), inside the cardioid.
    assert_eq!(rows[15][20], 100);
    // Pixel (0, 0) samples c = (-2.456.., 1.269..), outside radius 2: dwell 1.
    assert_eq!(rows[0][0], 1);
    // Symmetric about the real axis.
    for j in 0..15 {
        assert_eq!(rows[j], rows[29 - j], "row {j}");
    }
}

#[test]
fn julia_needs_its_parameter_and_mirrors_through_the_origin() {
    let dir = scratch("julia");
    let txt = dir.join("j.txt");
    let output = run(&["render", "julia", "--size", "30x20"]);
    assert_eq!(output.status.code(), Some(2));
    let output = run(&[
        "render",
        "julia",
        "--c",
        "-0.8,0.156",
        "--center",
        "0,0",
        "--width",
        "3.2",
        "--size",
        "31x21",
        "--max-iter",
        "200",
        "--out",
        dir.join("j.png").to_str().unwrap(),
        "--dwell",
        txt.to_str().unwrap(),
        "--palette",
        "bands",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let (_, rows) = read_dwell(&txt);
    for j in 0..21 {
        for i in 0..31 {
            assert_eq!(rows[j][i], rows[20 - j][30 - i], "({i}, {j})");
        }
    }
}

#[test]
fn escape_time_errors() {
    let dir = scratch("escape-errors");
    let out = dir.join("never.png");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["mandelbrot", "--width", "0"],
            "the width 0 is not positive",
        ),
        (
            vec!["mandelbrot", "--width", "7.9"],
            "reaches 4.68766 from 0 on an axis, beyond ±3.5",
        ),
        (
            vec!["julia", "--c", "-0.8,0.156", "--width", "0.00000000000001"],
            "a Julia view is limited to the deep tier's spacing of 2^-54",
        ),
        (
            vec!["mandelbrot", "--width", "1e-45"],
            "pixel spacing of 3.1250e-48",
        ),
        (
            vec!["mandelbrot", "--center", "x,0"],
            "--center: `x` is not a number between -8 and 8 (write e.g. -0.75, 1e-9 or 2.5E-3)",
        ),
        (
            vec!["julia", "--c", "3,3"],
            "the Julia parameter (3, 3) is more than 2 from 0",
        ),
    ];
    for (args, message) in cases {
        let mut full = vec!["render"];
        full.extend(args.iter().copied());
        full.extend(["--out", out.to_str().unwrap()]);
        let output = run(&full);
        assert_eq!(output.status.code(), Some(1), "{full:?}");
        let err = stderr(&output);
        assert!(err.contains(message), "{full:?}: {err}");
        assert!(!out.exists(), "{full:?} left a file");
    }
}

/// A forced tier that cannot tell the pixels apart still draws (it was asked for), but
/// says so on stderr and in `--stats`, naming the automatic tier; one that can, says nothing.
#[test]
fn a_forced_tier_too_coarse_for_the_view_warns() {
    let dir = scratch("coarse-tier");
    let out = dir.join("flat.png");
    let render = |width: &str, tier: &str| {
        run(&[
            "render",
            "mandelbrot",
            "--width",
            width,
            "--precision",
            tier,
            "--size",
            "64x48",
            "--max-iter",
            "200",
            "--stats",
            "--out",
            out.to_str().unwrap(),
        ])
    };
    for (width, tier, automatic) in [
        ("0.0001", "narrow", "deep"),
        ("0.000000005", "medium", "deep"),
        ("0.000000005", "standard", "deep"),
    ] {
        let output = render(width, tier);
        assert!(output.status.success(), "{}", stderr(&output));
        let err = stderr(&output);
        assert!(
            err.contains(&format!(
                "tinyfractal: warning: --precision {tier} cannot tell"
            )) && err.contains(&format!("the automatic tier for this view is {automatic}")),
            "{err}"
        );
        let stats = stdout(&output);
        assert!(
            stats.contains(&format!("tier={tier} elapsed_ms="))
                && stats.trim_end().ends_with(&format!(
                    "warning=tier_cannot_resolve automatic_tier={automatic}"
                )),
            "{stats}"
        );
    }
    for (width, tier) in [("3.5", "narrow"), ("0.0001", "medium")] {
        let output = render(width, tier);
        assert!(output.status.success(), "{}", stderr(&output));
        assert_eq!(stderr(&output), "");
        assert!(!stdout(&output).contains("warning"));
    }
}

/// A forced tier that cannot hold says so: `deep` past its spacing (it cannot tell the
/// pixels apart), and `deep` or perturbation where the cap is longer than its rounding
/// carries (the rule picks `wide` or perturbation); the automatic tier is quiet.
#[test]
fn forced_tiers_that_cannot_hold_warn_and_the_automatic_tier_is_quiet() {
    let dir = scratch("deep-warnings");
    let out = dir.join("view.png");
    let render = |centre: &str, width: &str, max: &str, tier: Option<&str>| {
        let mut args = vec![
            "render",
            "mandelbrot",
            "--center",
            centre,
            "--width",
            width,
            "--max-iter",
            max,
            "--size",
            "64x48",
            "--stats",
            "--out",
            out.to_str().unwrap(),
        ];
        if let Some(tier) = tier {
            args.extend_from_slice(&["--precision", tier]);
        }
        let output = run(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        (stderr(&output), stdout(&output))
    };
    let spiral = "-0.743643887037151,0.131825904205330";
    let cusp = "0.2818,0.0108";
    // Past its spacing, and where the cap is longer than its rounding carries.
    for (centre, width, max, tier, said, kind, automatic) in [
        (
            spiral,
            "1e-15",
            "1000",
            "deep",
            "cannot tell this view's pixels apart",
            "tier_cannot_resolve",
            "perturbation",
        ),
        (
            spiral,
            "1e-12",
            "4000",
            "deep",
            "cannot carry this view's rounding",
            "tier_cannot_carry",
            "wide",
        ),
        (
            spiral,
            "1e-12",
            "2000",
            "deep",
            "cannot carry this view's rounding",
            "tier_cannot_carry",
            "perturbation",
        ),
        (
            cusp,
            "1e-6",
            "1000",
            "deep",
            "cannot carry this view's rounding",
            "tier_cannot_carry",
            "wide",
        ),
        (
            cusp,
            "1e-6",
            "1000",
            "perturbation",
            "cannot carry this view's rounding",
            "tier_cannot_carry",
            "wide",
        ),
    ] {
        let (err, stats) = render(centre, width, max, Some(tier));
        assert!(
            err.contains(&format!("--precision {tier} {said}"))
                && err.contains(&format!("automatic tier for this view is {automatic}")),
            "{err}"
        );
        let expected = format!("warning={kind} automatic_tier={automatic}");
        assert!(stats.trim_end().ends_with(&expected), "{stats}");
    }
    // The same views by the automatic tier, and `wide` where the rule picks perturbation
    // (it keeps those dwells too): exact, no warning.
    for (centre, width, max, tier, chosen) in [
        (spiral, "1e-12", "4000", None, "wide"),
        (spiral, "1e-12", "2000", None, "perturbation"),
        (spiral, "1e-12", "2000", Some("wide"), "wide"),
        (cusp, "1e-6", "1000", None, "wide"),
    ] {
        let (err, stats) = render(centre, width, max, tier);
        assert_eq!(err, "");
        assert!(
            stats.contains(&format!("tier={chosen} ")) && !stats.contains("warning"),
            "{stats}"
        );
    }
    // At a cap of 256 the same view is exact and quiet.
    let (err, stats) = render("0.2818,0.0108", "1e-6", "256", None);
    assert_eq!(err, "");
    assert!(!stats.contains("warning"), "{stats}");
}

#[test]
fn help_version_and_completions() {
    for (args, expected) in [
        (vec!["--help"], "Usage: tinyfractal"),
        (vec!["render", "lsystem", "--help"], "--segments <TXT>"),
        (vec!["render", "mandelbrot", "--help"], "--max-iter <N>"),
        (vec!["render", "julia", "--help"], "--c <RE,IM>"),
        (vec!["help", "render"], "Usage: tinyfractal render"),
        (vec!["animate", "--help"], "zoom"),
        (vec!["animate", "zoom", "--help"], "--end-width <W>"),
        (vec!["render", "mandelbrot", "--help"], "smooth-classic"),
        (vec!["--version"], "tinyfractal 0.1.0"),
        (vec!["completions", "bash"], "_tinyfractal()"),
    ] {
        let output = run(&args);
        assert_eq!(
            output.status.code(),
            Some(0),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(
            stdout(&output).contains(expected),
            "{args:?}: {}",
            stdout(&output)
        );
    }
    // Every accepted --precision is listed when one is not.
    let output = run(&["render", "mandelbrot", "--precision", "huge"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("auto, narrow, medium, standard, deep"),
        "{}",
        stderr(&output)
    );
}

/// Every file in `dir` with its bytes, to compare a folder before and after a run.
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let path = e.unwrap().path();
            let bytes = std::fs::read(&path).unwrap_or_default();
            (path, bytes)
        })
        .collect();
    files.sort();
    files
}

#[test]
fn a_failing_run_leaves_the_folder_exactly_as_it_was() {
    let dir = scratch("untouched");
    // A user's own files, among them one named like the old temporary file.
    std::fs::write(dir.join("old.png"), b"not a png, but mine").unwrap();
    std::fs::write(dir.join("old.png.partial"), b"mine too").unwrap();
    std::fs::create_dir(dir.join("folder")).unwrap();
    let before = snapshot(&dir);
    let out = dir.join("old.png");
    let out = out.to_str().unwrap();
    let folder = dir.join("folder");
    let folder = folder.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        // The picture would be fine; the second output cannot be written.
        vec![
            "mandelbrot",
            "--size",
            "8x8",
            "--out",
            out,
            "--dwell",
            folder,
        ],
        vec![
            "mandelbrot",
            "--size",
            "8x8",
            "--out",
            out,
            "--dwell",
            "/no/such/folder/d.txt",
        ],
        // Two outputs, one file.
        vec!["mandelbrot", "--size", "8x8", "--out", out, "--dwell", out],
        // The window is not built in.
        vec!["mandelbrot", "--size", "8x8", "--out", out, "--window"],
        // The picture fails.
        vec![
            "mandelbrot",
            "--size",
            "8x8",
            "--out",
            out,
            "--width",
            "1e-45",
        ],
    ];
    for args in cases {
        if args.contains(&"--window") && cfg!(feature = "window") {
            continue;
        }
        let mut full = vec!["render"];
        full.extend(args.iter().copied());
        let output = run(&full);
        assert_eq!(
            output.status.code(),
            Some(1),
            "{full:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).starts_with("tinyfractal: error: "),
            "{}",
            stderr(&output)
        );
        assert_eq!(snapshot(&dir), before, "{full:?} changed the folder");
    }
    let output = run(&[
        "render",
        "mandelbrot",
        "--size",
        "8x8",
        "--out",
        out,
        "--dwell",
        out,
    ]);
    assert!(
        stderr(&output).contains("--out and --dwell both name"),
        "{}",
        stderr(&output)
    );
    // A successful run replaces the picture and leaves the user's other files alone.
    let output = run(&["render", "mandelbrot", "--size", "8x8", "--out", out]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_ne!(std::fs::read(out).unwrap(), b"not a png, but mine");
    assert_eq!(
        std::fs::read(dir.join("old.png.partial")).unwrap(),
        b"mine too"
    );
    assert_eq!(snapshot(&dir).len(), before.len());
}

#[cfg(unix)]
#[test]
fn special_files_and_symlinks_are_written_not_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let dir = scratch("special");
    // /dev/null stays a device.
    let output = run(&[
        "render",
        "mandelbrot",
        "--size",
        "8x8",
        "--out",
        "/dev/null",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // A symlink stays a symlink; its target gets the picture.
    let target = dir.join("real.png");
    let link = dir.join("link.png");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let output = run(&[
        "render",
        "mandelbrot",
        "--size",
        "8x8",
        "--out",
        link.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read(&target).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn limits_are_typed_errors_not_aborts() {
    let dir = scratch("limits");
    for size in ["100000x100000", "65536x65536", "16385x1", "9000x9000"] {
        let output = run(&["render", "mandelbrot", "--size", size]);
        assert_eq!(output.status.code(), Some(2), "{size}");
        assert!(
            stderr(&output).contains("largest picture"),
            "{}",
            stderr(&output)
        );
    }
    // An endless input is read only up to its limit.
    let output = run(&[
        "render",
        "lsystem",
        "--file",
        "/dev/zero",
        "--name",
        "x",
        "--order",
        "1",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("16 MiB"), "{}", stderr(&output));
    // An output folder that is a file: said once.
    let file = dir.join("file");
    std::fs::write(&file, b"").unwrap();
    let output = run(&["gallery", "--out", file.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        stderr(&output).matches("error").count(),
        1,
        "{}",
        stderr(&output)
    );
    assert!(
        stderr(&output).contains("not a folder"),
        "{}",
        stderr(&output)
    );
}

#[cfg(unix)]
#[test]
fn paths_need_not_be_utf8() {
    use std::os::unix::ffi::OsStrExt;
    let dir = scratch("utf8");
    let out = dir.join(std::ffi::OsStr::from_bytes(b"caf\xe9.png"));
    let output = Command::new(env!("CARGO_BIN_EXE_tinyfractal"))
        .args(["render", "mandelbrot", "--size", "8x8", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(out.exists());
}

#[test]
fn segments_are_streamed() {
    let dir = scratch("stream");
    let txt = dir.join("koch.txt");
    let output = koch(&[
        "--order",
        "7",
        "--size",
        "64x64",
        "--out",
        dir.join("k.png").to_str().unwrap(),
        "--segments",
        txt.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let lines = std::fs::read_to_string(&txt).unwrap().lines().count();
    assert_eq!(lines, 3 * 4usize.pow(7));
}

#[test]
fn every_usage_mistake_exits_2_and_names_the_accepted_values() {
    for (args, expected) in [
        (
            vec!["render", "mandelbrot", "--palette", "neon"],
            "classic, fire, gray, bands, two-color",
        ),
        (
            vec!["render", "mandelbrot", "--algorithm", "slow"],
            "exact, fast",
        ),
        (
            vec!["render", "lsystem", "--dialect", "x", "--axiom", "F"],
            "fractint, abop",
        ),
        (
            vec![
                "render", "lsystem", "--file", "x.l", "--name", "", "--order", "1",
            ],
            "a value is required for '--name <NAME>'",
        ),
    ] {
        let output = run(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&output).contains(expected),
            "{args:?}: {}",
            stderr(&output)
        );
    }
    for args in [
        vec!["render", "lsystem", "--help"],
        vec!["list", "--help"],
        vec!["gallery", "--help"],
    ] {
        assert_eq!(run(&args).status.code(), Some(0), "{args:?}");
    }
}

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data")
        .join(name)
        .display()
        .to_string()
}

/// The reader's warnings reach stderr and the picture is drawn (exit 0); its errors about
/// a missing `}`, a fraction for an angle, an IFS file or old Mac line endings exit 1
/// naming the cause, with no file left.
#[test]
fn reader_warnings_and_errors_reach_the_user() {
    let dir = scratch("reader");
    let out = dir.join("bad.png");
    let render = |file: &str, name: &str| {
        run(&[
            "render",
            "lsystem",
            "--file",
            &data(file),
            "--name",
            name,
            "--order",
            "2",
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let output = render("warn-missing-brace.l", "bad");
    assert!(output.status.success(), "{}", stderr(&output));
    let err = stderr(&output);
    assert_eq!(
        err.matches("tinyfractal: warning: bad in ").count(),
        4,
        "{err}"
    );
    assert!(
        err.contains("line 9 is a second `Axiom` (the first is on line 4)"),
        "{err}"
    );
    assert!(out.exists());
    std::fs::remove_file(&out).unwrap();
    for (file, name, expected) in [
        (
            "error-missing-brace.l",
            "bad",
            "on line 1 runs into another entry's `NAME {` on line 6",
        ),
        ("error-angle-fraction.l", "bad", "not a whole number"),
        ("error-ifs.l", "bad", "IFS file"),
        ("error-old-mac.l", "bad", "carriage return alone"),
    ] {
        let output = render(file, name);
        assert_eq!(output.status.code(), Some(1), "{file}");
        assert!(
            stderr(&output).contains(expected),
            "{file}: {}",
            stderr(&output)
        );
        assert!(!out.exists(), "{file} left a file");
    }
    // The entry after the missing `}` is listed and draws.
    let listed = run(&["list", &data("error-missing-brace.l")]);
    assert_eq!(stdout(&listed), "Bad\nNext\n");
    assert!(render("error-missing-brace.l", "next").status.success());
}

/// A high order draws from the expansion table with the true statistics; a system that
/// draws nothing writes an empty picture, says so, and exits 0; the walk holds desktop
/// depths (hundreds of levels and saved turtles), not the MCU defaults.
#[test]
fn any_order_and_empty_pictures_and_desktop_capacities() {
    let dir = scratch("orders");
    let out = dir.join("koch.png");
    let output = koch(&[
        "--dialect",
        "fractint",
        "--order",
        "16",
        "--stats",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let stats = stdout(&output);
    assert!(
        stats.starts_with(&format!("segments={} ", 3 * 4u64.pow(16))),
        "{stats}"
    );
    assert!(stats.contains(" max_depth=17 "), "{stats}");

    let empty = dir.join("empty.png");
    let output = run(&[
        "render",
        "lsystem",
        "--file",
        &data("draws-nothing.l"),
        "--name",
        "erased",
        "--order",
        "3",
        "--out",
        empty.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(stderr(&output).contains("tinyfractal: note: erased draws nothing at order 3"));
    assert!(empty.exists());

    // Brackets nested 100 deep at order 1, and order 40 of a system that grows slowly.
    let deep = format!("X={}F{}", "[+".repeat(100), "]".repeat(100));
    let cases: [(&[&str], &str); 2] = [
        (
            &["--axiom", "X", "--rule", &deep, "--order", "1"],
            " max_stack=100 ",
        ),
        (
            &[
                "--axiom", "A", "--rule", "A=F+B", "--rule", "B=A", "--order", "40",
            ],
            " max_depth=41 ",
        ),
    ];
    for (system, expected) in cases {
        let mut args = vec!["render", "lsystem", "--angle", "8", "--stats", "--out"];
        args.push(out.to_str().unwrap());
        args.extend_from_slice(system);
        let output = run(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        assert!(stdout(&output).contains(expected), "{}", stdout(&output));
    }
}

/// `--view` draws a window of the fitted picture: the top-left quarter at W×H is the
/// top-left W×H of the whole picture drawn at 2W×2H, pixel for pixel; `0,0,1,1` is the
/// picture itself; a malformed window is a usage error.
#[test]
fn view_draws_a_window_of_the_picture() {
    let dir = scratch("view");
    let render = |file: &str, size: &str, view: Option<&str>| {
        let out = dir.join(file);
        let mut args = vec![
            "--dialect",
            "fractint",
            "--order",
            "6",
            "--size",
            size,
            "--out",
            out.to_str().unwrap(),
        ];
        if let Some(view) = view {
            args.extend(["--view", view]);
        }
        let output = koch(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        image::open(&out).unwrap().to_rgb8()
    };
    let whole = render("whole.png", "160x120", None);
    let same = render("same.png", "160x120", Some("0,0,1,1"));
    assert_eq!(whole, same);
    let double = render("double.png", "320x240", None);
    let quarter = render("quarter.png", "160x120", Some("0,0,0.5,0.5"));
    for y in 0..120 {
        for x in 0..160 {
            assert_eq!(
                quarter.get_pixel(x, y),
                double.get_pixel(x, y),
                "({x}, {y})"
            );
        }
    }
    assert!(
        quarter.pixels().any(|p| p.0 != [0, 0, 0]),
        "something is drawn"
    );
    for bad in ["0,0,1", "0.5,0,0.5,1", "0,0,2,1", "a,b,c,d", "-0.1,0,1,1"] {
        let output = run(&[
            "render", "lsystem", "--axiom", "F", "--angle", "4", "--order", "1", "--view", bad,
        ]);
        assert_eq!(output.status.code(), Some(2), "{bad}");
        assert!(stderr(&output).contains("X0,Y0,X1,Y1"), "{bad}");
    }
}

/// Real files that nest deeper than an MCU's 20 saved turtles draw in the CLI.
#[test]
fn deep_files_draw_with_desktop_capacities() {
    let out = scratch("deep").join("deep.png");
    let output = run(&[
        "render",
        "lsystem",
        "--file",
        &data("deep-nesting.l"),
        "--name",
        "DeepTree",
        "--order",
        "3",
        "--stats",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stdout(&output).contains(" max_stack=90 "),
        "{}",
        stdout(&output)
    );
}

/// `derive` prints the derived string on one line: Lindenmayer's algae as the lecture
/// writes them, a Fractint file's numeric commands with their numbers, and a typed error
/// (exit 1, nothing on stdout) past `--max-length`.
#[test]
fn derive_prints_the_derived_string() {
    let algae = ["A", "AB", "ABA", "ABAAB", "ABAABABA", "ABAABABAABAAB"];
    for (order, expected) in algae.iter().enumerate() {
        let output = run(&[
            "derive",
            "--axiom",
            "A",
            "--rule",
            "A=AB",
            "--rule",
            "B=A",
            "--order",
            &order.to_string(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        assert_eq!(stdout(&output), format!("{expected}\n"));
    }
    let dir = scratch("derive");
    let file = dir.join("numbers.l");
    std::fs::write(
        &file,
        "T {\n Angle 4\n Axiom F@.5F\\30/22.5C12<3>1@IQ3@2\n F=FF\n}\n",
    )
    .unwrap();
    let output = run(&[
        "derive",
        "--file",
        file.to_str().unwrap(),
        "--name",
        "t",
        "--order",
        "1",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    // 1/sqrt(3) = 0.57735 shows as 0.5774; 2 as 2; Fractint's symbols lower-cased.
    assert_eq!(stdout(&output), "ff@0.5ff\\30/22.5c12<3>1@0.5774@2\n");
    let output = run(&[
        "derive",
        "--axiom",
        "A",
        "--rule",
        "A=AA",
        "--order",
        "10",
        "--max-length",
        "1000",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(stdout(&output), "");
    assert!(
        stderr(&output).contains("longer than 1000 symbols"),
        "{}",
        stderr(&output)
    );
    let output = run(&[
        "derive",
        "--axiom",
        "A",
        "--rule",
        "A=AA",
        "--order",
        "10",
        "--max-length",
        "1024",
    ]);
    assert_eq!(stdout(&output).trim_end().len(), 1024);
}

/// Every CLI number takes scientific notation, as people write it.
#[test]
fn numbers_in_scientific_notation() {
    let dir = scratch("scientific");
    let (a, b) = (dir.join("a.txt"), dir.join("b.txt"));
    for (width, centre, dwell) in [
        ("1e-9", "-7.43643887e-1,1.31825904e-1", &a),
        ("0.000000001", "-0.743643887,0.131825904", &b),
    ] {
        let output = run(&[
            "render",
            "mandelbrot",
            "--width",
            width,
            "--center",
            centre,
            "--size",
            "16x12",
            "--max-iter",
            "500",
            "--stats",
            "--out",
            dir.join("m.png").to_str().unwrap(),
            "--dwell",
            dwell.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        // z + i = 34 + 9 with a cap over 256: `Wide`.
        assert!(stdout(&output).contains("tier=wide"), "{}", stdout(&output));
    }
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
}

/// `.lsys` files (by extension) work with `list`, `derive` and `render lsystem` as `.l`
/// files do; notation not derived yet is an error naming it.
#[test]
fn lsys_files_list_derive_and_render() {
    let abop = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../data/abop.lsys")
        .display()
        .to_string();
    let listed = run(&["list", &abop]);
    assert!(
        stdout(&listed).starts_with("Fig1.24a\nFig1.24b\n"),
        "{}",
        stdout(&listed)
    );
    let derived = run(&["derive", "--file", &abop, "--name", "algae", "--order", "4"]);
    assert_eq!(stdout(&derived), "ABAABABA\n");
    let out = scratch("lsys").join("f.png");
    let rendered = run(&[
        "render",
        "lsystem",
        "--file",
        &abop,
        "--name",
        "Fig1.24f",
        "--order",
        "5",
        "--stats",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(rendered.status.success(), "{}", stderr(&rendered));
    assert!(
        stdout(&rendered).starts_with("segments=1488 "),
        "{}",
        stdout(&rendered)
    );
    // Context-sensitive: ABOP's signal propagation (p. 30), one symbol a step.
    let context = scratch("lsys").join("c.lsys");
    std::fs::write(
        &context,
        "c {\n  axiom: baaaaaaaa\n  angle: 30\n  b < a --> b\n  b --> a\n}\n",
    )
    .unwrap();
    let signal = run(&[
        "derive",
        "--file",
        context.to_str().unwrap(),
        "--name",
        "c",
        "--order",
        "3",
    ]);
    assert_eq!(signal.status.code(), Some(0), "{}", stderr(&signal));
    assert_eq!(stdout(&signal), "aaabaaaaa\n");
    // Parametric: derived as the book prints it, and drawn.
    let book = run(&[
        "derive",
        "--file",
        &abop,
        "--name",
        "Parametric1.10",
        "--order",
        "5",
    ]);
    assert_eq!(stdout(&book), "CB(0)B(8)A(1.1429,0)\n");
    let trees = scratch("lsys").join("trees.png");
    let drawn = run(&[
        "render",
        "lsystem",
        "--file",
        &abop,
        "--name",
        "RowOfTrees",
        "--order",
        "4",
        "--stats",
        "--out",
        trees.to_str().unwrap(),
    ]);
    assert!(drawn.status.success(), "{}", stderr(&drawn));
    assert!(
        stdout(&drawn).starts_with("segments=256 "),
        "{}",
        stdout(&drawn)
    );
    assert!(trees.exists());
    // Stochastic: the file's seed, repeatable; --seed overrides it.
    let plant = |seed: Option<&str>| {
        let mut args = vec![
            "derive", "--file", &abop, "--name", "Fig1.27", "--order", "3",
        ];
        if let Some(seed) = seed {
            args.extend(["--seed", seed]);
        }
        stdout(&run(&args))
    };
    assert_eq!(plant(None), plant(None));
    assert_eq!(plant(None), plant(Some("1")));
    assert_ne!(plant(None), plant(Some("2")));
}

/// 3D systems: drawn with the 3D turtle; `--segments` writes `x0 y0 z0 x1 y1 z1`, and the
/// 3D Hilbert curve's are unit steps on its grid; `--projection` takes three views.
#[test]
fn three_d_systems_render_and_write_segments() {
    let abop = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../data/abop.lsys")
        .to_string_lossy()
        .into_owned();
    let dir = scratch("space");
    let segments = dir.join("hilbert.txt");
    for projection in ["front", "iso", "perspective"] {
        let out = dir.join(format!("{projection}.png"));
        let rendered = run(&[
            "render",
            "lsystem",
            "--file",
            &abop,
            "--name",
            "Hilbert3D",
            "--order",
            "2",
            "--projection",
            projection,
            "--depth-cue",
            "--size",
            "64x64",
            "--out",
            out.to_str().unwrap(),
            "--segments",
            segments.to_str().unwrap(),
            "--stats",
        ]);
        assert_eq!(rendered.status.code(), Some(0), "{}", stderr(&rendered));
        assert!(
            stdout(&rendered).starts_with("segments=63 "),
            "{}",
            stdout(&rendered)
        );
        assert!(out.exists());
    }
    let text = std::fs::read_to_string(&segments).unwrap();
    assert_eq!(text.lines().count(), 63);
    for line in text.lines() {
        let v: Vec<f64> = line.split(' ').map(|n| n.parse().unwrap()).collect();
        assert_eq!(v.len(), 6, "{line}");
        let length = ((v[3] - v[0]).powi(2) + (v[4] - v[1]).powi(2) + (v[5] - v[2]).powi(2)).sqrt();
        assert!((length - 1.0).abs() < 1e-6, "{line}");
    }
    let refused = run(&[
        "render",
        "lsystem",
        "--file",
        &abop,
        "--name",
        "Hilbert3D",
        "--order",
        "2",
        "--projection",
        "sideways",
    ]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        stderr(&refused).contains("give front, iso or perspective"),
        "{}",
        stderr(&refused)
    );
}

/// Open systems: `--environment` gives the world; without one the error says so; a bad
/// shape is a usage error.
#[test]
fn open_systems_grow_in_an_environment() {
    let abop = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../data/abop.lsys")
        .to_string_lossy()
        .into_owned();
    let out = scratch("open").join("topiary.png");
    let args = |extra: &[&'static str]| {
        let mut args = vec![
            "render", "lsystem", "--file", &abop, "--name", "Topiary", "--order", "6", "--size",
            "64x64", "--stats", "--out",
        ];
        args.push(out.to_str().unwrap());
        args.extend_from_slice(extra);
        args
    };
    let grown = run(&args(&["--environment", "heart:1.5"]));
    assert_eq!(grown.status.code(), Some(0), "{}", stderr(&grown));
    let wide = run(&args(&["--environment", "circle:50"]));
    let count = |o: &Output| -> u64 {
        stdout(o).split_whitespace().next().unwrap()["segments=".len()..]
            .parse()
            .unwrap()
    };
    // Pruned by the heart, it grows fewer shoots than in a circle it never leaves (3^6
    // apices at order 6: 1 + 3 + ... + 3^5 = 364 segments).
    assert_eq!(count(&wide), 364);
    assert!(count(&grown) < 364, "{}", stdout(&grown));
    let bare = run(&args(&[]));
    assert_eq!(bare.status.code(), Some(1));
    assert!(stderr(&bare).contains("--environment"), "{}", stderr(&bare));
    let bad = run(&args(&["--environment", "square:3"]));
    assert_eq!(bad.status.code(), Some(2));
    assert!(
        stderr(&bad).contains("give circle or heart"),
        "{}",
        stderr(&bad)
    );
}

/// `render ifs`: a file's entry or inline maps; `--points` writes every plotted point
/// (`x y`), all inside the attractor's box; malformed maps are errors with their place.
#[test]
fn ifs_renders_and_writes_points() {
    let lecture = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../data/lecture.ifs")
        .to_string_lossy()
        .into_owned();
    let dir = scratch("ifs");
    let points = dir.join("fern.txt");
    let out = dir.join("fern.png");
    let rendered = run(&[
        "render",
        "ifs",
        "--file",
        &lecture,
        "--name",
        "FERN",
        "--points-count",
        "2000",
        "--points",
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert_eq!(rendered.status.code(), Some(0), "{}", stderr(&rendered));
    assert!(
        stdout(&rendered).starts_with("points=2000 maps=4 "),
        "{}",
        stdout(&rendered)
    );
    let text = std::fs::read_to_string(&points).unwrap();
    assert_eq!(text.lines().count(), 2000);
    for line in text.lines() {
        let v: Vec<f64> = line.split(' ').map(|n| n.parse().unwrap()).collect();
        // The fern lies within x in [-2.2, 2.7], y in [0, 10].
        assert!(
            v.len() == 2 && (-2.2..2.7).contains(&v[0]) && (0.0..10.0).contains(&v[1]),
            "{line}"
        );
    }
    let inline = run(&[
        "render",
        "ifs",
        "--map",
        "0.5,0,0,0.5,0,0,0.5",
        "--map",
        "0.5,0,0,0.5,1,0,0.5",
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert_eq!(inline.status.code(), Some(0), "{}", stderr(&inline));
    let density = run(&[
        "render",
        "ifs",
        "--file",
        &lecture,
        "--name",
        "fern",
        "--density",
        "--size",
        "64x48",
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert_eq!(density.status.code(), Some(0), "{}", stderr(&density));
    let bad = run(&[
        "render",
        "ifs",
        "--map",
        "0.5,0,0,0.5,0,0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(stderr(&bad).contains("has 6 numbers"), "{}", stderr(&bad));
    let sum = run(&[
        "render",
        "ifs",
        "--map",
        "0.5,0,0,0.5,0,0,0.4",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(stderr(&sum).contains("sum to 0.4,"), "{}", stderr(&sum));
}

/// `render gingerbread`: the lecture's orbit, its period in `--stats`, `--points` in map
/// coordinates.
#[test]
fn gingerbread_renders_with_its_period() {
    let dir = scratch("gingerbread");
    let points = dir.join("points.txt");
    let out = dir.join("g.png");
    let rendered = run(&[
        "render",
        "gingerbread",
        "--iterations",
        "5",
        "--points",
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert_eq!(rendered.status.code(), Some(0), "{}", stderr(&rendered));
    assert!(
        stdout(&rendered).starts_with("points=5 period=3810 tail=0 "),
        "{}",
        stdout(&rendered)
    );
    // (115,121) -> (280 - 121 + |115 - 120|, 115) = (164, 115) -> (280 - 115 + 44, 164) = (209, 164)
    let text = std::fs::read_to_string(&points).unwrap();
    assert!(text.starts_with("115 121\n164 115\n209 164\n"), "{text}");
    let bad = run(&["render", "gingerbread", "--start", "1;2"]);
    assert_eq!(bad.status.code(), Some(2));
}

/// `render figure`: a pose with `--segments` (world units, the part's name last), and
/// `--frames` of the walk cycle.
#[test]
fn figure_renders_poses_and_frames() {
    let dir = scratch("figure");
    let segments = dir.join("lines.txt");
    let out = dir.join("figure.png");
    let rendered = run(&[
        "render",
        "figure",
        "--pose",
        "stand",
        "--segments",
        segments.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert_eq!(rendered.status.code(), Some(0), "{}", stderr(&rendered));
    let text = std::fs::read_to_string(&segments).unwrap();
    let thigh: Vec<f64> = text
        .lines()
        .find(|l| l.ends_with(" left thigh"))
        .unwrap()
        .split(' ')
        .take(4)
        .map(|n| n.parse().unwrap())
        .collect();
    // Standing, the thigh hangs straight down 1.8 units.
    assert!(
        (thigh[1] - thigh[3] - 1.8).abs() < 1e-6 && (thigh[0] - thigh[2]).abs() < 1e-6,
        "{thigh:?}"
    );
    let frames = run(&[
        "render",
        "figure",
        "--frames",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(frames.status.code(), Some(0), "{}", stderr(&frames));
    for index in 0..3 {
        assert!(dir.join(format!("figure-{index:03}.png")).exists());
    }
}

/// The distinct colours of a PNG.
fn colours(path: &Path) -> usize {
    let image = image::open(path).unwrap().into_rgb8();
    let mut seen: Vec<[u8; 3]> = image.pixels().map(|p| p.0).collect();
    seen.sort_unstable();
    seen.dedup();
    seen.len()
}

#[test]
fn smooth_palettes_shade_between_the_bands() {
    let dir = scratch("smooth");
    let render = |palette: &str, max: &str| {
        let (png, txt) = (
            dir.join(format!("{palette}.png")),
            dir.join(format!("{palette}.txt")),
        );
        let output = run(&[
            "render",
            "mandelbrot",
            "--size",
            "160x120",
            "--max-iter",
            max,
            "--palette",
            palette,
            "--out",
            png.to_str().unwrap(),
            "--dwell",
            txt.to_str().unwrap(),
        ]);
        (output, png, txt)
    };
    let (plain, plain_png, plain_txt) = render("classic", "100");
    assert!(plain.status.success(), "{}", stderr(&plain));
    for palette in ["smooth-gray", "smooth-classic", "smooth-fire"] {
        let (smooth, png, txt) = render(palette, "100");
        assert!(smooth.status.success(), "{}", stderr(&smooth));
        // --dwell writes dwells whatever the palette.
        assert_eq!(
            std::fs::read(&txt).unwrap(),
            std::fs::read(&plain_txt).unwrap()
        );
        if palette == "smooth-classic" {
            let (banded, shaded) = (colours(&plain_png), colours(&png));
            assert!(shaded > 2 * banded, "{shaded} colours against {banded}");
        }
    }
    std::fs::remove_file(dir.join("smooth-fire.png")).unwrap();
    let (refused, png, _) = render("smooth-fire", "5000");
    assert_eq!(refused.status.code(), Some(1));
    assert!(
        stderr(&refused).contains("max-iter 5000 is too high for smooth colouring"),
        "{}",
        stderr(&refused)
    );
    assert!(!png.exists());
}

fn frame_bytes(dir: &Path, count: usize) -> Vec<Vec<u8>> {
    (0..count)
        .map(|k| std::fs::read(dir.join(format!("frame-{k:04}.png"))).unwrap())
        .collect()
}

/// A zoom whose frames pass into perturbation (past `Deep`'s spacing, or deep with a long
/// orbit) computes those frames as `render` does: each frame equals `render mandelbrot
/// --algorithm exact` of its view, pixel for pixel.
#[test]
fn a_zoom_into_perturbation_draws_each_frame_as_render_does() {
    let dir = scratch("animate-deep");
    let centre = "-0.743643887037151,0.131825904205330";
    for (start, end, max, frames) in [
        // Deep at 10⁻⁹ and 256, perturbation from 10⁻¹³ (z + i ≥ 54).
        ("1e-9", "1e-13", "256", 3),
        // Past Deep's spacing at 10⁻¹⁵, and deep with a long orbit before it.
        ("1e-14", "1e-15", "4000", 2),
    ] {
        let zoom = dir.join(format!("zoom-{start}"));
        let output = run(&[
            "animate",
            "zoom",
            "--frames",
            &frames.to_string(),
            "--center",
            centre,
            "--width",
            start,
            "--end-width",
            end,
            "--max-iter",
            max,
            "--size",
            "64x48",
            "--out",
            zoom.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        let got = frame_bytes(&zoom, frames);
        for (frame, width) in [(0, start), (frames - 1, end)] {
            let still = dir.join(format!("still-{width}.png"));
            let output = run(&[
                "render",
                "mandelbrot",
                "--algorithm",
                "exact",
                "--center",
                centre,
                "--width",
                width,
                "--max-iter",
                max,
                "--size",
                "64x48",
                "--out",
                still.to_str().unwrap(),
            ]);
            assert!(output.status.success(), "{}", stderr(&output));
            assert!(
                got[frame] == std::fs::read(&still).unwrap(),
                "frame {frame} of the zoom from {start} differs from render at {width}"
            );
        }
    }
}

#[test]
fn animate_writes_its_frames_first_and_last_as_headless_renders() {
    let dir = scratch("animate");
    let render = |args: &[&str], out: &Path| {
        let mut args = args.to_vec();
        args.extend_from_slice(&["--size", "64x48", "--out", out.to_str().unwrap()]);
        let output = run(&args);
        assert!(output.status.success(), "{args:?}: {}", stderr(&output));
        std::fs::read(out).unwrap()
    };
    let still = |width: &str, name: &str| {
        let args = [
            "render",
            "mandelbrot",
            "--algorithm",
            "exact",
            "--center",
            "-0.7435,0.1314",
        ];
        let mut args = args.to_vec();
        args.extend_from_slice(&["--width", width]);
        render(&args, &dir.join(name))
    };
    let zoom = dir.join("zoom");
    let output = run(&[
        "animate",
        "zoom",
        "--frames",
        "6",
        "--center",
        "-0.7435,0.1314",
        "--width",
        "3",
        "--end-width",
        "0.05",
        "--size",
        "64x48",
        "--out",
        zoom.to_str().unwrap(),
        "--stats",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("frames=6 computed_share="),
        "{}",
        stdout(&output)
    );
    let frames = frame_bytes(&zoom, 6);
    assert!(!zoom.join("frame-0006.png").exists());
    assert_eq!(frames[0], still("3", "start.png"));
    assert_eq!(frames[5], still("0.05", "end.png"));
    // An animated GIF and an APNG of the same frames.
    for (name, count) in [("zoom.gif", 6), ("zoom.png", 6)] {
        let path = dir.join(name);
        let output = run(&[
            "animate",
            "zoom",
            "--frames",
            "6",
            "--width",
            "3",
            "--end-width",
            "0.05",
            "--size",
            "64x48",
            "--out",
            path.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        let bytes = std::fs::read(&path).unwrap();
        if name.ends_with(".gif") {
            use image::AnimationDecoder;
            let decoder = image::codecs::gif::GifDecoder::new(std::io::Cursor::new(bytes)).unwrap();
            assert_eq!(decoder.into_frames().count(), count);
        } else {
            let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
            let reader = decoder.read_info().unwrap();
            let control = reader.info().animation_control().unwrap();
            assert_eq!(control.num_frames, count as u32);
        }
    }
    // Colour cycling starts at the still picture.
    let cycle = dir.join("cycle");
    let output = run(&[
        "animate",
        "palette",
        "--frames",
        "3",
        "--center",
        "-0.7435,0.1314",
        "--width",
        "3",
        "--size",
        "64x48",
        "--out",
        cycle.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let frames = frame_bytes(&cycle, 3);
    assert_eq!(frames[0], std::fs::read(dir.join("start.png")).unwrap());
    assert_ne!(frames[1], frames[0]);
    let bands = run(&[
        "animate",
        "palette",
        "--palette",
        "bands",
        "--out",
        cycle.to_str().unwrap(),
    ]);
    assert_eq!(bands.status.code(), Some(1));
    assert!(
        stderr(&bands).contains("colour cycling needs a gradient"),
        "{}",
        stderr(&bands)
    );
    // Growth: order k is `render lsystem --order k`.
    let growth = dir.join("growth");
    let system = ["--axiom", "F", "--rule", "F=F+F-F-F+F", "--angle", "4"];
    let mut args = vec![
        "animate",
        "growth",
        "--order",
        "3",
        "--size",
        "64x48",
        "--out",
        growth.to_str().unwrap(),
    ];
    args.extend_from_slice(&system);
    let output = run(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    let frames = frame_bytes(&growth, 4);
    for (order, frame) in frames.iter().enumerate() {
        let order = order.to_string();
        let mut args = vec!["render", "lsystem", "--order", order.as_str()];
        args.extend_from_slice(&system);
        assert_eq!(
            *frame,
            render(&args, &dir.join(format!("order-{order}.png"))),
            "order {order}"
        );
    }
    let zero = run(&["animate", "figure", "--frames", "0"]);
    assert_eq!(zero.status.code(), Some(2));
}

/// `noise --at` prints Perlin's published values, one a line in the order given, with every
/// digit of the engine's value (his exact one where f64 has it).
#[test]
fn noise_prints_perlins_values_at_each_point() {
    let output = run(&[
        "noise",
        "--at",
        "3.14,42,7",
        "--at",
        "-4.2,10,6",
        "--at",
        "0.5,0.5,0.5",
        "--at",
        "0.5,0.5",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    let value = |line: &str| line.parse::<f64>().unwrap();
    assert!(
        (value(lines[0]) - 0.136_919_958_784_000_12).abs() < 1e-6,
        "{text}"
    );
    assert!((value(lines[1]) - 0.142_08).abs() < 1e-6, "{text}");
    assert_eq!(lines[2], "-0.25");
    // 2D is Perlin's noise at z = 0.
    let flat = stdout(&run(&["noise", "--at", "0.5,0.5,0"]));
    assert_eq!(format!("{}\n", lines[3]), flat);
    // A seed changes the permutation, and so the values (at a point inside a cell: on its
    // edges few gradients count, and two permutations often agree there).
    let inside = |seed: &str| stdout(&run(&["noise", "--at", "0.3,0.7,0.1", "--seed", seed]));
    assert_ne!(inside("5"), inside("0"));
    assert_eq!(inside("5"), inside("5"));
    for bad in [["--at", "1,2,3,4"], ["--at", "x,1"]] {
        let mut args = vec!["noise"];
        args.extend(bad);
        let output = run(&args);
        assert_eq!(output.status.code(), Some(2), "{bad:?}");
        assert!(stderr(&output).contains("--at"), "{bad:?}");
    }
}

/// `render noise` draws a texture and writes each pixel's value: Perlin noise is 0 at every
/// lattice point, so where each pixel's corner is one (a lattice cell a pixel), fBm is ½
/// everywhere.
#[test]
fn render_noise_writes_the_picture_and_its_values() {
    let dir = scratch("render-noise");
    let (png, values) = (dir.join("clouds.png"), dir.join("values.txt"));
    let output = run(&[
        "render",
        "noise",
        "--texture",
        "clouds",
        "--size",
        "16x8",
        "--scale",
        "16",
        "--out",
        png.to_str().unwrap(),
        "--values",
        values.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let picture = image::open(&png).unwrap();
    assert_eq!((picture.width(), picture.height()), (16, 8));
    let text = std::fs::read_to_string(&values).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("16 8"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(' ').collect()).collect();
    assert_eq!(rows.len(), 8);
    assert!(rows
        .iter()
        .all(|row| row.len() == 16 && row.iter().all(|v| *v == "0.5")));
    // Off the lattice, values spread over [0, 1].
    let spread = dir.join("spread.txt");
    let output = run(&[
        "render",
        "noise",
        "--texture",
        "marble",
        "--size",
        "32x16",
        "--out",
        png.to_str().unwrap(),
        "--values",
        spread.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let values: Vec<f64> = std::fs::read_to_string(&spread)
        .unwrap()
        .lines()
        .skip(1)
        .flat_map(|l| {
            l.split(' ')
                .map(|v| v.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .collect();
    assert_eq!(values.len(), 32 * 16);
    assert!(values.iter().all(|v| (0.0..=1.0).contains(v)));
    assert!(values.iter().any(|&v| v < 0.2) && values.iter().any(|&v| v > 0.8));
    // Bad parameters are refused, and nothing is written.
    let never = dir.join("never.png");
    for bad in [
        ["--scale", "0"],
        ["--persistence", "2"],
        ["--lacunarity", "0.5"],
    ] {
        let mut args = vec!["render", "noise", "--out", never.to_str().unwrap()];
        args.extend(bad);
        let output = run(&args);
        assert!(!output.status.success(), "{bad:?}");
        assert!(
            stderr(&output).contains(&bad[0][2..]),
            "{bad:?}: {}",
            stderr(&output)
        );
    }
    assert!(!never.exists());
}

/// `animate noise` moves through 3D noise: frame k is the texture `render noise` draws at
/// depth z + k·z-step.
#[test]
fn animate_noise_steps_through_the_third_dimension() {
    let dir = scratch("animate-noise");
    let frames = dir.join("frames");
    let output = run(&[
        "animate",
        "noise",
        "--texture",
        "marble",
        "--z",
        "0.25",
        "--z-step",
        "0.5",
        "--frames",
        "3",
        "--size",
        "40x30",
        "--out",
        frames.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    for (frame, depth) in [(0, "0.25"), (2, "1.25")] {
        let still = dir.join(format!("still-{frame}.png"));
        let output = run(&[
            "render",
            "noise",
            "--texture",
            "marble",
            "--z",
            depth,
            "--size",
            "40x30",
            "--out",
            still.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        let animated = image::open(frames.join(format!("frame-{frame:04}.png")))
            .unwrap()
            .to_rgb8();
        assert_eq!(
            animated,
            image::open(&still).unwrap().to_rgb8(),
            "frame {frame}"
        );
    }
    let first = image::open(frames.join("frame-0000.png"))
        .unwrap()
        .to_rgb8();
    let second = image::open(frames.join("frame-0001.png"))
        .unwrap()
        .to_rgb8();
    assert_ne!(first, second, "the texture moves");
}

/// `render reaction`: the grid after `--steps` steps, its B field in `--values` (`W H`, then
/// H rows of W values, each a multiple of 2⁻¹⁵ in [0, 1]), the same whatever `--size`.
#[test]
fn render_reaction_writes_the_b_field() {
    let dir = scratch("render-reaction");
    let png = dir.join("reaction.png");
    let values = dir.join("values.txt");
    let render = |steps: &str, size: &str, values: &Path| {
        run(&[
            "render",
            "reaction",
            "--preset",
            "mitosis",
            "--grid",
            "24x16",
            "--steps",
            steps,
            "--size",
            size,
            "--out",
            png.to_str().unwrap(),
            "--values",
            values.to_str().unwrap(),
            "--stats",
        ])
    };
    // Step 0 is Sims's start: B = 1 in the centred 2×2 square (⌊16/8⌋ = 2), 0 elsewhere.
    let output = render("0", "48x32", &values);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stdout(&output).starts_with("cells=384 steps=0 cell_steps=0 "),
        "{}",
        stdout(&output)
    );
    let text = std::fs::read_to_string(&values).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("24 16"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 16);
    for (y, row) in rows.iter().enumerate() {
        assert_eq!(row.len(), 24);
        for (x, &b) in row.iter().enumerate() {
            let seeded = (11..13).contains(&x) && (7..9).contains(&y);
            assert_eq!(b, if seeded { 1.0 } else { 0.0 }, "({x}, {y})");
        }
    }
    assert_eq!(image::open(&png).unwrap().to_rgb8().dimensions(), (48, 32));
    // After 50 steps, B has spread and every value is a multiple of 2⁻¹⁵ in [0, 1]; the
    // picture's size does not change the grid.
    let later = dir.join("later.txt");
    assert!(render("50", "48x32", &later).status.success());
    let other = dir.join("other.txt");
    assert!(render("50", "100x70", &other).status.success());
    let text = std::fs::read_to_string(&later).unwrap();
    assert_eq!(text, std::fs::read_to_string(&other).unwrap());
    let values: Vec<f64> = text
        .lines()
        .skip(1)
        .flat_map(|l| {
            l.split(' ')
                .map(|v| v.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .collect();
    assert!(values
        .iter()
        .all(|&b| (0.0..=1.0).contains(&b) && (b * 32768.0).fract() == 0.0));
    assert!(values.iter().filter(|&&b| b > 0.0).count() > 4);
}

/// Bad rates, grids and presets are refused with the cause, and nothing is written.
#[test]
fn render_reaction_refuses_bad_parameters() {
    let dir = scratch("reaction-bad");
    let never = dir.join("never.png");
    for (bad, says) in [
        (&["--feed", "0.5", "--kill", "0.6"][..], "feed"),
        (&["--dt", "2"][..], "time step"),
        (&["--diffusion-a", "1.2"][..], "unstable"),
        (&["--grid", "2x8"][..], "grid"),
        (&["--preset", "zebra"][..], "unknown preset"),
        (&["--feed", "0.05"][..], "--kill"),
        (
            &["--preset", "coral", "--feed", "0.05", "--kill", "0.06"][..],
            "cannot be used",
        ),
    ] {
        let mut args = vec![
            "render",
            "reaction",
            "--steps",
            "1",
            "--out",
            never.to_str().unwrap(),
        ];
        args.extend(bad);
        let output = run(&args);
        assert!(!output.status.success(), "{bad:?}");
        assert!(
            stderr(&output).contains(says),
            "{bad:?}: {}",
            stderr(&output)
        );
    }
    assert!(!never.exists());
}

/// `animate reaction`: frame k is the picture `render reaction` draws after k times
/// `--steps-per-frame` steps.
#[test]
fn animate_reaction_frames_are_renders_at_their_steps() {
    let dir = scratch("animate-reaction");
    let frames = dir.join("frames");
    let common = [
        "--preset", "coral", "--grid", "20x20", "--init", "spots", "--seed", "3",
    ];
    let mut args = vec!["animate", "reaction"];
    args.extend(common);
    args.extend([
        "--steps-per-frame",
        "30",
        "--frames",
        "3",
        "--size",
        "40x40",
        "--out",
    ]);
    args.push(frames.to_str().unwrap());
    let output = run(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    for (frame, steps) in [(0, "0"), (2, "60")] {
        let still = dir.join(format!("still-{frame}.png"));
        let mut args = vec![
            "render", "reaction", "--steps", steps, "--size", "40x40", "--out",
        ];
        args.push(still.to_str().unwrap());
        args.extend(common);
        let output = run(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        let animated = image::open(frames.join(format!("frame-{frame:04}.png")))
            .unwrap()
            .to_rgb8();
        assert_eq!(
            animated,
            image::open(&still).unwrap().to_rgb8(),
            "frame {frame}"
        );
    }
}

/// `render terrain2d --method noise`: each height is the fBm at its grid point, (scale·i/n,
/// scale·j/n), in 2⁻¹⁶ rounded down; with one octave, the noise `noise --at` prints there.
#[test]
fn terrain2d_of_noise_has_the_noise_commands_heights() {
    let dir = scratch("terrain2d-noise");
    let heights = dir.join("heights.txt");
    let png = dir.join("land.png");
    let output = run(&[
        "render",
        "terrain2d",
        "--method",
        "noise",
        "--octaves",
        "1",
        "--scale",
        "2",
        "--samples",
        "4",
        "--seed",
        "0",
        "--size",
        "40x30",
        "--out",
        png.to_str().unwrap(),
        "--heights",
        heights.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let grid: Vec<Vec<f64>> = std::fs::read_to_string(&heights)
        .unwrap()
        .lines()
        .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(grid.len(), 4);
    // The points 0, 0.5, 1, 1.5 along each axis: dyadic, so both commands take them exactly.
    let mut args = vec!["noise".to_string()];
    for j in 0..4 {
        for i in 0..4 {
            args.push("--at".to_string());
            args.push(format!("{},{}", f64::from(i) / 2.0, f64::from(j) / 2.0));
        }
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let values: Vec<f64> = stdout(&run(&args))
        .lines()
        .map(|l| l.parse().unwrap())
        .collect();
    for j in 0..4 {
        assert_eq!(grid[j].len(), 4);
        for i in 0..4 {
            let want = (values[j * 4 + i] * 65536.0).floor() / 65536.0;
            assert!(
                (grid[j][i] - want).abs() < 1e-9,
                "({i}, {j}): {} against {want}",
                grid[j][i]
            );
        }
    }
    assert!(values.iter().any(|&v| v != 0.0));
    // Options of the other method are refused, and nothing is written.
    let never = dir.join("never.png");
    for (bad, says) in [
        (
            &["--method", "noise", "--roughness", "0.5"][..],
            "--roughness",
        ),
        (&["--method", "noise", "--wrap"][..], "--wrap"),
        (
            &["--octaves", "3"][..],
            "--octaves applies to --method noise",
        ),
        (&["--method", "noise", "--scale", "0"][..], "scale"),
    ] {
        let mut args = vec![
            "render",
            "terrain2d",
            "--samples",
            "9",
            "--out",
            never.to_str().unwrap(),
        ];
        args.extend(bad);
        let output = run(&args);
        assert!(!output.status.success(), "{bad:?}");
        assert!(
            stderr(&output).contains(says),
            "{bad:?}: {}",
            stderr(&output)
        );
    }
    assert!(!never.exists());
}
