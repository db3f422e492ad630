//! `--inside`, `--outside`, `--distance` and the `distance-*` palettes on the command line:
//! each changes the picture and not the dwells, one-bit strands hold together, and the
//! combinations the core refuses are refused with their cause.

mod common;

use common::{run, scratch, stderr};

/// Renders the Mandelbrot set with `extra`, returning its pixels and its `--dwell` text.
fn render(name: &str, extra: &[&str]) -> (image::RgbImage, String) {
    let dir = scratch(name);
    let (png, dwells) = (dir.join("m.png"), dir.join("d.txt"));
    let mut args = vec![
        "render",
        "mandelbrot",
        "--size",
        "96x72",
        "--max-iter",
        "200",
        "--dwell",
        dwells.to_str().unwrap(),
        "--out",
        png.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let output = run(&args);
    assert!(output.status.success(), "{extra:?}: {}", stderr(&output));
    (
        image::open(&png).unwrap().to_rgb8(),
        std::fs::read_to_string(&dwells).unwrap(),
    )
}

fn differing(a: &image::RgbImage, b: &image::RgbImage) -> usize {
    a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
}

#[test]
fn modes_change_the_colours_not_the_dwells() {
    let (plain, dwells) = render("modes-plain", &[]);
    for (name, extra) in [
        ("modes-real", &["--outside", "real"][..]),
        ("modes-imag", &["--outside", "imag"]),
        ("modes-mult", &["--outside", "mult"]),
        ("modes-summ", &["--outside", "summ"]),
        ("modes-atan", &["--outside", "atan"]),
        ("modes-zmag", &["--inside", "zmag"]),
        ("modes-period", &["--inside", "period"]),
        ("modes-distance", &["--distance", "0.71"]),
        ("modes-shade", &["--palette", "distance-gray"]),
    ] {
        let (picture, text) = render(name, extra);
        assert_eq!(text, dwells, "{extra:?}: --dwell writes the dwells");
        let changed = differing(&picture, &plain);
        assert!(changed > 200, "{extra:?} changed {changed} pixels");
    }
}

/// Black pixels of a one-bit seahorse valley, with and without the estimate.
#[test]
fn the_estimate_keeps_one_bit_strands() {
    let black = |extra: &[&str]| {
        let dir = scratch("modes-one-bit");
        let png = dir.join("s.png");
        let mut args = vec![
            "render",
            "mandelbrot",
            "--center=-0.7435,0.1314",
            "--width",
            "0.01",
            "--max-iter",
            "1000",
            "--size",
            "128x64",
            "--colors",
            "1bit",
            "--palette",
            "two-color",
            "--out",
            png.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let output = run(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        let picture = image::open(&png).unwrap().to_rgb8();
        picture.pixels().filter(|p| p.0 == [0, 0, 0]).count()
    };
    let (plain, estimated) = (black(&[]), black(&["--distance", "0.71"]));
    assert!(
        estimated > 10 * plain,
        "{estimated} set pixels against {plain}"
    );
}

#[test]
fn refused_combinations_name_their_cause() {
    for (extra, cause) in [
        (&["--distance", "0"][..], "out of range"),
        (&["--distance", "wide"], "not a number"),
        (
            &["--outside", "real", "--palette", "smooth-classic"],
            "outside mode",
        ),
        (
            &["--inside", "zmag", "--width", "1e-20", "--center=-0.75,0.1"],
            "perturbation",
        ),
    ] {
        let dir = scratch("modes-refused");
        let png = dir.join("r.png");
        let mut args = vec![
            "render",
            "mandelbrot",
            "--size",
            "32x24",
            "--out",
            png.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let output = run(&args);
        assert!(!output.status.success(), "{extra:?} succeeded");
        assert!(
            stderr(&output).contains(cause),
            "{extra:?}: {}",
            stderr(&output)
        );
        assert!(!png.exists(), "{extra:?} left a file");
    }
}
