//! The command line of the Sierpiński family, the terrain and the dimension: the `--stats`
//! keys, `--heights`, `dimension=`, and bad input (exit codes, messages, no file left).

mod common;

use common::{run, scratch, stderr, stdout};

/// The value of `key=` in a stats line.
fn value(line: &str, key: &str) -> String {
    line.split_whitespace()
        .find_map(|pair| pair.strip_prefix(&format!("{key}=")))
        .unwrap_or_else(|| panic!("no {key}= in {line}"))
        .to_string()
}

#[test]
fn carpet_png_is_exact_and_stats_count_squares() {
    let dir = scratch("carpet");
    let png = dir.join("c.png");
    let output = run(&[
        "render",
        "carpet",
        "--order",
        "3",
        "--size",
        "27x27",
        "--stats",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let line = stdout(&output);
    assert_eq!(value(&line, "squares"), "512");
    assert_eq!(value(&line, "holes"), "73");
    let picture = image::open(&png).unwrap().to_rgb8();
    for (x, y, pixel) in picture.enumerate_pixels() {
        let removed = (0..3).any(|d| (x / 3u32.pow(d)) % 3 == 1 && (y / 3u32.pow(d)) % 3 == 1);
        assert_eq!(pixel.0 == [0, 0, 0], removed, "({x}, {y})");
    }
}

#[test]
fn gasket_and_cube_stats() {
    let dir = scratch("cube");
    let out = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let gasket = run(&[
        "render",
        "gasket",
        "--order",
        "5",
        "--stats",
        "--out",
        &out("g.png"),
    ]);
    assert!(gasket.status.success(), "{}", stderr(&gasket));
    assert_eq!(value(&stdout(&gasket), "triangles"), "243");
    let centre = run(&[
        "render",
        "cube",
        "--order",
        "2",
        "--variant",
        "centre",
        "--stats",
        "--out",
        &out("c.png"),
    ]);
    assert!(centre.status.success(), "{}", stderr(&centre));
    // 26^2 cubes; only the outer surface shows: 3 · 9^2 faces.
    assert_eq!(value(&stdout(&centre), "cubes"), "676");
    assert_eq!(value(&stdout(&centre), "faces"), "243");
    let sponge = run(&[
        "render",
        "cube",
        "--order",
        "2",
        "--camera",
        "30,20",
        "--stats",
        "--out",
        &out("s.png"),
    ]);
    assert!(sponge.status.success(), "{}", stderr(&sponge));
    assert_eq!(value(&stdout(&sponge), "cubes"), "400");
}

#[test]
fn terrain_heights_are_written_and_reproducible() {
    let dir = scratch("terrain");
    let heights = |seed: &str, name: &str| {
        let (png, txt) = (
            dir.join(format!("{name}.png")),
            dir.join(format!("{name}.txt")),
        );
        let output = run(&[
            "render",
            "terrain",
            "--samples",
            "33",
            "--roughness",
            "0.6",
            "--sigma",
            "5",
            "--seed",
            seed,
            "--ends",
            "-2,3",
            "--heights",
            txt.to_str().unwrap(),
            "--out",
            png.to_str().unwrap(),
            "--stats",
        ]);
        assert!(output.status.success(), "{}", stderr(&output));
        assert_eq!(value(&stdout(&output), "samples"), "33");
        std::fs::read_to_string(txt).unwrap()
    };
    let (a, b, c) = (heights("4", "a"), heights("4", "b"), heights("5", "c"));
    assert_eq!(a, b);
    assert_ne!(a, c);
    let values: Vec<f64> = a.lines().map(|l| l.parse().unwrap()).collect();
    assert_eq!(values.len(), 33);
    assert_eq!((values[0], values[32]), (-2.0, 3.0));

    let grid = dir.join("grid.txt");
    let output = run(&[
        "render",
        "terrain2d",
        "--samples",
        "17",
        "--wrap",
        "--heights",
        grid.to_str().unwrap(),
        "--out",
        dir.join("grid.png").to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let rows: Vec<Vec<f64>> = std::fs::read_to_string(grid)
        .unwrap()
        .lines()
        .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 17);
    assert!(rows.iter().all(|r| r.len() == 17));
    assert_eq!(rows[0], rows[16]);
}

#[test]
fn dimension_of_a_rendered_carpet() {
    let dir = scratch("dimension");
    let png = dir.join("carpet.png");
    let output = run(&[
        "render",
        "carpet",
        "--order",
        "5",
        "--size",
        "243x243",
        "--dimension",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let from_render: f64 = value(&stdout(&output), "dimension").parse().unwrap();
    let output = run(&["dimension", png.to_str().unwrap()]);
    assert!(output.status.success(), "{}", stderr(&output));
    let line = stdout(&output);
    let from_file: f64 = value(&line, "dimension").parse().unwrap();
    assert_eq!(value(&line, "dimension").len(), 5, "three decimals: {line}");
    assert_eq!(from_render, from_file);
    let theory = 8f64.ln() / 3f64.ln();
    assert!((from_file - theory).abs() < 0.1, "{line}");
    // Against a white background the holes are what counts: at these box sizes they are
    // everywhere, so the estimate is near 2.
    let inverted = run(&["dimension", png.to_str().unwrap(), "--background", "ffffff"]);
    let holes: f64 = value(&stdout(&inverted), "dimension").parse().unwrap();
    assert!(holes > from_file + 0.03, "{}", stdout(&inverted));
}

#[test]
fn bad_input_is_refused_with_what_to_do_and_no_file() {
    let dir = scratch("bad");
    let png = dir.join("x.png");
    let out = png.to_str().unwrap();
    for (args, says) in [
        (
            vec!["render", "carpet", "--order", "9", "--out", out],
            "order 9 is too high",
        ),
        (
            vec!["render", "terrain", "--roughness", "1.5", "--out", out],
            "(0, 1]",
        ),
        (
            vec!["render", "terrain", "--roughness", "0", "--out", out],
            "(0, 1]",
        ),
        (
            vec!["render", "terrain", "--samples", "1000", "--out", out],
            "2^k + 1",
        ),
        (
            vec!["render", "terrain", "--sigma", "-1", "--out", out],
            "sigma",
        ),
        (
            vec!["render", "terrain2d", "--samples", "0", "--out", out],
            "2^k + 1",
        ),
        (
            vec![
                "render", "cube", "--order", "1", "--camera", "0,90", "--out", out,
            ],
            "elevation",
        ),
        (
            vec![
                "render", "gasket", "--order", "2", "--size", "0x10", "--out", out,
            ],
            "",
        ),
    ] {
        let output = run(&args);
        assert!(!output.status.success(), "{args:?} succeeded");
        assert!(
            stderr(&output).contains(says),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(!png.exists(), "{args:?} left a file");
    }
    for args in [
        vec!["render", "carpet"],
        vec!["render", "terrain", "--roughness", "rough"],
        vec!["render", "cube", "--order", "1", "--variant", "corners"],
        vec!["dimension", out, "--background", "white"],
    ] {
        assert_eq!(run(&args).status.code(), Some(2), "{args:?}");
    }
    let missing = run(&["dimension", dir.join("none.png").to_str().unwrap()]);
    assert_eq!(missing.status.code(), Some(1));
    assert!(stderr(&missing).contains("none.png"));
    // A small file whose header claims 30000×30000 pixels is refused as too large, before
    // any memory is taken for it.
    let huge = dir.join("huge.png");
    std::fs::write(&huge, png_claiming(30_000, 30_000)).unwrap();
    let output = run(&["dimension", huge.to_str().unwrap()]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{err}");
    assert!(err.contains("too large to read"), "{err}");
}

/// The bytes of a PNG whose header says `width`×`height` grey pixels, with one empty
/// stored zlib block as its data: a reader learns the size before it reads the data.
fn png_claiming(width: u32, height: u32) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &byte in bytes {
            crc ^= u32::from(byte);
            for _ in 0..8 {
                crc = if crc & 1 == 1 {
                    (crc >> 1) ^ 0xedb8_8320
                } else {
                    crc >> 1
                };
            }
        }
        !crc
    }
    let mut file = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        file.extend((data.len() as u32).to_be_bytes());
        let body = [kind, data].concat();
        file.extend(&body);
        file.extend(crc32(&body).to_be_bytes());
    };
    let mut header = [width.to_be_bytes(), height.to_be_bytes()].concat();
    header.extend([8, 0, 0, 0, 0]);
    chunk(b"IHDR", &header);
    chunk(
        b"IDAT",
        &[
            0x78, 0x01, 0x01, 0x00, 0x00, 0xff, 0xff, 0x00, 0x00, 0x00, 0x01,
        ],
    );
    chunk(b"IEND", &[]);
    file
}
