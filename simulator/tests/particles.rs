//! `render particles` and `animate particles` from the command line: the live particles in
//! `--particles`, the seed's repeatability, an animation's frames against renders.

mod common;

use common::{run, scratch, stderr, stdout};

fn render(dir: &std::path::Path, name: &str, args: &[&str]) -> (String, String) {
    let (png, file) = (
        dir.join(format!("{name}.png")),
        dir.join(format!("{name}.txt")),
    );
    let mut all = vec![
        "render",
        "particles",
        "--size",
        "96x64",
        "--stats",
        "--out",
        png.to_str().unwrap(),
        "--particles",
        file.to_str().unwrap(),
    ];
    all.extend(args);
    let output = run(&all);
    assert!(output.status.success(), "{}", stderr(&output));
    (stdout(&output), std::fs::read_to_string(file).unwrap())
}

#[test]
fn the_particles_file_lists_the_live_particles() {
    let dir = scratch("particles");
    let (stats, text) = render(&dir, "fountain", &["--preset", "fountain", "--time", "2"]);
    let live: usize = stats
        .split_whitespace()
        .find_map(|f| f.strip_prefix("particles="))
        .unwrap()
        .parse()
        .unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), live);
    assert!(live > 100, "{stats}");
    for row in &rows {
        assert_eq!(row.len(), 5);
        let [x, y, _, _, age] = row[..] else {
            unreachable!()
        };
        // The fountain is thrown from (48, 60.8) and lands on the same ground.
        assert!(
            (0.0..=96.0).contains(&x) && y <= 64.0 * 0.95 + 1e-9,
            "{row:?}"
        );
        assert!((0.0..=2.0).contains(&age), "{row:?}");
    }
    // The same seed, the same particles; another seed, others.
    let (_, again) = render(&dir, "again", &["--preset", "fountain", "--time", "2"]);
    assert_eq!(again, text);
    let (_, other) = render(
        &dir,
        "other",
        &["--preset", "fountain", "--time", "2", "--seed", "9"],
    );
    assert_ne!(other, text);
    // At time 0 nothing has been emitted.
    let (stats, text) = render(&dir, "start", &["--preset", "snow", "--time", "0"]);
    assert!(stats.starts_with("particles=0 "), "{stats}");
    assert!(text.is_empty());
}

#[test]
fn an_animation_frame_is_the_render_at_its_tick() {
    let dir = scratch("animate-particles");
    let frames = dir.join("frames");
    let output = run(&[
        "animate",
        "particles",
        "--preset",
        "fireworks",
        "--frames",
        "3",
        "--size",
        "96x64",
        "--out",
        frames.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let still = dir.join("still.png");
    let output = run(&[
        "render",
        "particles",
        "--preset",
        "fireworks",
        "--time",
        "0.1",
        "--size",
        "96x64",
        "--out",
        still.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    // Frame k is k + 1 ticks in: frame 2 is a tenth of a second.
    let frame = image::open(frames.join("frame-0002.png"))
        .unwrap()
        .to_rgb8();
    assert_eq!(frame, image::open(&still).unwrap().to_rgb8());
}

#[test]
fn bad_presets_and_times_are_refused() {
    for args in [
        vec!["render", "particles", "--preset", "rain"],
        vec!["render", "particles", "--preset", "snow", "--time", "-1"],
        vec!["render", "particles", "--preset", "snow", "--time", "4000"],
        vec!["render", "particles"],
    ] {
        let output = run(&args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
    }
    assert!(stderr(&run(&["render", "particles", "--preset", "rain"])).contains("fountain"));
}
