//! The book's plants from the command line: `--polygons`, an entry's colours in light,
//! `animate sway` and the continuous `animate growth`.

mod common;

use common::{run, scratch, shipped, stderr, stdout};
use std::path::Path;

fn ok(args: &[&str]) -> String {
    let output = run(args);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    stdout(&output)
}

fn rgb(path: &Path) -> image::RgbImage {
    image::open(path).unwrap().to_rgb8()
}

/// The unit square `{.f+.f+.f+.f}` (heading up, `+` turning left a quarter) has the
/// vertices (0,0), (0,1), (−1,1), (−1,0): one line, `x y` each.
#[test]
fn polygons_are_written_in_turtle_units() {
    let dir = scratch("square");
    let file = dir.join("square.lsys");
    std::fs::write(&file, "square {\n axiom: {.f+.f+.f+.f}\n angle: 90\n}\n").unwrap();
    let polygons = dir.join("polygons.txt");
    let out = dir.join("square.png");
    let stats = ok(&[
        "render",
        "lsystem",
        "--file",
        file.to_str().unwrap(),
        "--name",
        "square",
        "--order",
        "0",
        "--polygons",
        polygons.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    assert!(stats.contains("polygons=1"), "{stats}");
    let text = std::fs::read_to_string(&polygons).unwrap();
    let numbers: Vec<f64> = text
        .split_whitespace()
        .map(|n| n.parse().unwrap())
        .collect();
    assert_eq!(text.lines().count(), 1);
    assert_eq!(numbers, [0.0, 0.0, 0.0, 1.0, -1.0, 1.0, -1.0, 0.0]);
}

/// ABOP's bush in space: each leaf `{-f+f+f-|-f+f+f}` is its start and six moves, seven
/// vertices `x y z`; as many lines as `--stats` counts polygons.
#[test]
fn the_bushs_leaves_are_seven_vertices_in_space() {
    let dir = scratch("bush");
    let polygons = dir.join("leaves.txt");
    let out = dir.join("bush.png");
    let stats = ok(&[
        "render",
        "lsystem",
        "--file",
        &shipped("abop.lsys"),
        "--name",
        "Fig1.25",
        "--order",
        "3",
        "--polygons",
        polygons.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--stats",
    ]);
    let text = std::fs::read_to_string(&polygons).unwrap();
    let count = stats
        .split_whitespace()
        .find_map(|kv| kv.strip_prefix("polygons="))
        .unwrap();
    assert_eq!(text.lines().count().to_string(), count);
    assert!(text.lines().count() > 10);
    for line in text.lines() {
        assert_eq!(line.split_whitespace().count(), 21, "{line}");
    }
}

/// A polygon in colour 1 of the entry's `colors:` line, facing the viewer, is that colour
/// at the light's brightness for a surface square to the view: 35 % + 65 % · 2/√6 of it.
#[test]
fn an_entrys_colours_are_lit() {
    let dir = scratch("colours");
    let file = dir.join("leaf.lsys");
    std::fs::write(
        &file,
        "leaf {\n axiom: F'{.f+.f+.f+.f}\n angle: 90\n colors: 000000 c86432\n}\n",
    )
    .unwrap();
    let out = dir.join("leaf.png");
    ok(&[
        "render",
        "lsystem",
        "--file",
        file.to_str().unwrap(),
        "--name",
        "leaf",
        "--order",
        "0",
        "--size",
        "64x64",
        "--out",
        out.to_str().unwrap(),
    ]);
    let picture = rgb(&out);
    let light = 0.35 + 0.65 * 2.0 / 6f64.sqrt();
    let expected = [0xc8, 0x64, 0x32].map(|c: u8| f64::from(c) * light);
    let leaf = picture
        .pixels()
        .find(|p| p.0[0] > 100)
        .expect("the leaf is drawn");
    for (got, want) in leaf.0.iter().zip(expected) {
        assert!(
            (f64::from(*got) - want).abs() <= 1.0,
            "{leaf:?} against {expected:?}"
        );
    }
}

/// A plant swaying: every frame differs from the first somewhere (5 frames: the gust
/// sin 2πt + ½ sin(4πt + φ) takes five values), the root pixel (the trunk's lowest) is the
/// same in every frame.
#[test]
fn animate_sway_moves_the_crown_not_the_root() {
    let dir = scratch("sway");
    let frames = dir.join("frames");
    ok(&[
        "animate",
        "sway",
        "--file",
        &shipped("abop.lsys"),
        "--name",
        "Fig2.8a",
        "--order",
        "4",
        "--frames",
        "5",
        "--wind",
        "0.1",
        "--size",
        "120x120",
        "--out",
        frames.to_str().unwrap(),
    ]);
    let pictures: Vec<_> = (0..5)
        .map(|k| rgb(&frames.join(format!("frame-{k:04}.png"))))
        .collect();
    let lowest = |p: &image::RgbImage| {
        (0..p.height())
            .rev()
            .find_map(|y| {
                (0..p.width())
                    .find(|&x| p.get_pixel(x, y).0 != [0, 0, 0])
                    .map(|x| (x, y))
            })
            .unwrap()
    };
    for (k, picture) in pictures.iter().enumerate().skip(1) {
        assert!(picture != &pictures[0], "frame {k} is frame 0");
        assert_eq!(lowest(picture), lowest(&pictures[0]));
    }
}

/// A parametric plant growing continuously: its first frame is order 0 and its last is
/// the plant `render lsystem` draws at the last order, pixel for pixel (both fitted to
/// the full-grown plant); frames in between exist.
#[test]
fn animate_growth_runs_from_order_zero_to_the_plant() {
    let dir = scratch("growth");
    let file = dir.join("plant.lsys");
    std::fs::write(
        &file,
        "plant {\n axiom: X(1)\n angle: 25\n X(l) --> F(l)[+X(l)]F(l)[-X(l)]+X(l)\n F(l) --> F(l*2)\n}\n",
    )
    .unwrap();
    let frames = dir.join("frames");
    let still = dir.join("plant.png");
    let common = [
        "--file",
        file.to_str().unwrap(),
        "--name",
        "plant",
        "--order",
        "3",
        "--size",
        "100x100",
    ];
    let mut args = vec![
        "animate",
        "growth",
        "--frames",
        "7",
        "--out",
        frames.to_str().unwrap(),
    ];
    args.extend(common);
    ok(&args);
    let mut args = vec!["render", "lsystem", "--out", still.to_str().unwrap()];
    args.extend(common);
    ok(&args);
    let last = rgb(&frames.join("frame-0006.png"));
    assert!(last == rgb(&still), "the last frame is not the plant");
    let first = rgb(&frames.join("frame-0000.png"));
    assert!(
        first.pixels().all(|p| p.0 == [0, 0, 0]),
        "order 0 draws nothing"
    );
    let middle = rgb(&frames.join("frame-0003.png"));
    let lit = |p: &image::RgbImage| p.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    assert!(0 < lit(&middle) && lit(&middle) < lit(&last));
}
