//! `render lsystem --colormap FILE.map`: the colour modules index a Fractint map, `.lsys`
//! systems default to the book's browns and greens, and a bad map names its line.

mod common;

use std::collections::HashSet;

use common::{run, scratch, stderr};

/// A plant whose stem is colour 0 and whose leaves, after `'`, colour 1.
const PLANT: &str = "Plant {\n  axiom: F\n  angle: 30\n  F --> F[+'F][-'F]\n}\n";

fn colours(png: &std::path::Path) -> HashSet<[u8; 3]> {
    image::open(png)
        .unwrap()
        .to_rgb8()
        .pixels()
        .map(|p| p.0)
        .filter(|&p| p != [0, 0, 0])
        .collect()
}

#[test]
fn a_map_colours_the_modules() {
    let dir = scratch("colormap");
    let (file, map, png) = (
        dir.join("plant.lsys"),
        dir.join("two.map"),
        dir.join("plant.png"),
    );
    std::fs::write(&file, PLANT).unwrap();
    std::fs::write(&map, "255 0 0 the stem\n\n0 0 255 leaves\n").unwrap();
    let render = |extra: &[&str]| {
        let mut args = vec![
            "render",
            "lsystem",
            "--file",
            file.to_str().unwrap(),
            "--name",
            "Plant",
            "--order",
            "3",
            "--size",
            "64x64",
            "--out",
            png.to_str().unwrap(),
        ];
        args.extend(extra);
        let output = run(&args);
        assert!(output.status.success(), "{}", stderr(&output));
        colours(&png)
    };
    assert_eq!(
        render(&["--colormap", map.to_str().unwrap()]),
        HashSet::from([[255, 0, 0], [0, 0, 255]])
    );
    // Without a map: the book's bark brown and the next three (at order 3 a leaf is up to
    // three `'` in); with the two-colour map above, the indices wrapped to its two.
    assert_eq!(
        render(&[]),
        HashSet::from([
            [0x8B, 0x5A, 0x2B],
            [0x7A, 0x4E, 0x24],
            [0x6B, 0x5A, 0x2A],
            [0x5C, 0x6B, 0x2E]
        ])
    );
}

#[test]
fn a_bad_map_names_its_line() {
    let dir = scratch("colormap-bad");
    let (map, png) = (dir.join("bad.map"), dir.join("x.png"));
    for (text, expected) in [
        ("0 0 0\n1 2\n", ":2:"),
        ("0 0 256\n", ":1:"),
        ("\n\n", "no colours"),
        (&"1 2 3\n".repeat(257)[..], ":257: more than 256"),
    ] {
        std::fs::write(&map, text).unwrap();
        let output = run(&[
            "render",
            "lsystem",
            "--axiom",
            "F",
            "--rule",
            "F=F+F",
            "--angle",
            "4",
            "--order",
            "2",
            "--colormap",
            map.to_str().unwrap(),
            "--out",
            png.to_str().unwrap(),
        ]);
        assert_eq!(output.status.code(), Some(1), "{text}");
        assert!(stderr(&output).contains(expected), "{}", stderr(&output));
        assert!(!png.exists());
    }
}

/// `--palette-file` colours an escape-time picture by its map: each pixel's dwell d (from
/// `--dwell`) takes colour d mod the map's length, the set black; the shipped maps read.
#[test]
fn a_map_colours_the_dwells() {
    let dir = scratch("colormap-dwells");
    let (map, png, dwells) = (dir.join("three.map"), dir.join("m.png"), dir.join("d.txt"));
    std::fs::write(&map, "255 0 0\n0 255 0 green\n0 0 255\n").unwrap();
    let output = run(&[
        "render",
        "mandelbrot",
        "--size",
        "64x48",
        "--max-iter",
        "50",
        "--palette-file",
        map.to_str().unwrap(),
        "--dwell",
        dwells.to_str().unwrap(),
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let picture = image::open(&png).unwrap().to_rgb8();
    let text = std::fs::read_to_string(&dwells).unwrap();
    let colours = [[255, 0, 0], [0, 255, 0], [0, 0, 255]];
    for (y, line) in text.lines().skip(1).enumerate() {
        for (x, dwell) in line.split_whitespace().enumerate() {
            let dwell: usize = dwell.parse().unwrap();
            let expected = if dwell >= 50 {
                [0, 0, 0]
            } else {
                colours[dwell % 3]
            };
            assert_eq!(
                picture.get_pixel(x as u32, y as u32).0,
                expected,
                "({x}, {y}) dwell {dwell}"
            );
        }
    }
    for shipped in ["glow", "earth", "neon"] {
        let path = common::shipped(&format!("maps/{shipped}.map"));
        let output = run(&[
            "render",
            "mandelbrot",
            "--size",
            "32x24",
            "--palette-file",
            &path,
            "--out",
            png.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{shipped}: {}", stderr(&output));
    }
}

/// `--palette histogram` spreads the picture over the gradient: far more of its colours
/// than the plain gradient shows at a high cap, where the dwells crowd low.
#[test]
fn histogram_colouring_spreads_the_colours() {
    let dir = scratch("histogram");
    let png = dir.join("h.png");
    let distinct = |palette: &str| {
        let output = run(&[
            "render",
            "mandelbrot",
            "--size",
            "96x64",
            "--max-iter",
            "2000",
            "--width",
            "0.02",
            "--center=-0.745,0.11",
            "--palette",
            palette,
            "--out",
            png.to_str().unwrap(),
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        let picture = image::open(&png).unwrap().to_rgb8();
        picture.pixels().map(|p| p.0).collect::<HashSet<_>>().len()
    };
    let (plain, equalised) = (distinct("classic"), distinct("histogram"));
    assert!(equalised >= 32, "{equalised} colours");
    assert!(equalised != plain);
}
