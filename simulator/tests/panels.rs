//! `--colors` and `--dither`: the PNG holds what the panel shows.

mod common;

use common::{run, scratch, stderr};
use std::collections::HashSet;

fn colours(args: &[&str], name: &str) -> HashSet<[u8; 3]> {
    let dir = scratch(name);
    let out = dir.join("picture.png");
    let mut all = args.to_vec();
    all.extend(["--out", out.to_str().unwrap()]);
    let output = run(&all);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    image::open(&out)
        .unwrap()
        .to_rgb8()
        .pixels()
        .map(|p| p.0)
        .collect()
}

#[test]
fn the_png_shows_the_panels_colours() {
    let mandelbrot = ["render", "mandelbrot", "--size", "96x64"];
    let with = |extra: &[&'static str]| {
        let mut args = mandelbrot.to_vec();
        args.extend_from_slice(extra);
        args
    };
    for dither in ["none", "bayer4", "bayer8"] {
        let one_bit = colours(&with(&["--colors", "1bit", "--dither", dither]), dither);
        assert!(
            one_bit.is_subset(&HashSet::from([[0, 0, 0], [255, 255, 255]])),
            "{one_bit:?}"
        );
        let grey = colours(&with(&["--colors", "gray2", "--dither", dither]), dither);
        assert!(
            grey.len() <= 4 && grey.iter().all(|[r, g, b]| r == g && g == b),
            "{grey:?}"
        );
    }
    // RGB565 keeps 5, 6 and 5 bits: every channel one of their levels.
    let rgb565 = colours(
        &with(&["--colors", "rgb565", "--dither", "bayer8"]),
        "rgb565",
    );
    let levels = |bits: u32| -> HashSet<u8> {
        (0..1u32 << bits)
            .map(|l| ((l * 255 + ((1 << bits) - 1) / 2) / ((1 << bits) - 1)) as u8)
            .collect()
    };
    let (five, six) = (levels(5), levels(6));
    for [r, g, b] in &rgb565 {
        assert!(
            five.contains(r) && six.contains(g) && five.contains(b),
            "{r} {g} {b}"
        );
    }
    // Dithering a smooth gradient onto one bit lights a share of the pixels no rounding does.
    let dithered = colours(
        &with(&[
            "--colors",
            "1bit",
            "--dither",
            "bayer8",
            "--palette",
            "gray",
        ]),
        "gray8",
    );
    assert_eq!(dithered.len(), 2);
}
