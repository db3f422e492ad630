//! `animate autopilot`: a seeded flight whose `--stats` end with `last_width=`, narrowing by
//! the autopilot's factor a frame, the same frames for the same seed.

mod common;

use common::{run, scratch, stderr, stdout};

fn flight(name: &str, seed: &str) -> (Vec<u8>, String) {
    let dir = scratch(name);
    let gif = dir.join("a.gif");
    let output = run(&[
        "animate",
        "autopilot",
        "--seed",
        seed,
        "--frames",
        "40",
        "--size",
        "64x48",
        "--out",
        gif.to_str().unwrap(),
        "--stats",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    (std::fs::read(&gif).unwrap(), stdout(&output))
}

#[test]
fn a_seeded_flight_narrows_and_repeats() {
    let (gif, stats) = flight("autopilot-a", "5");
    let (again, _) = flight("autopilot-b", "5");
    let (other, _) = flight("autopilot-c", "6");
    assert_eq!(gif, again, "the same seed gives the same frames");
    assert_ne!(gif, other, "another seed flies elsewhere");
    let line = stats.trim_end();
    let last = line
        .split_whitespace()
        .last()
        .and_then(|word| word.strip_prefix("last_width="))
        .unwrap_or_else(|| panic!("--stats does not end with last_width=: {line}"));
    let width: f64 = last.parse().unwrap();
    assert!(line.contains("backed_out=0"), "{line}");
    // 39 steps of 15/16 from the whole set's 3.5.
    let expected = 3.5 * (15.0f64 / 16.0).powi(39);
    assert!(
        (width / expected - 1.0).abs() < 1e-3,
        "{width} against {expected}"
    );
}
