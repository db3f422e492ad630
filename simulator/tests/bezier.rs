//! `render bezier` from the command line: the flattened polyline in `--segments`, the
//! picture's ends at the control points, bad control points refused.

mod common;

use common::{run, scratch, stderr, stdout};

#[test]
fn the_segments_file_is_the_flattened_curve() {
    let dir = scratch("bezier");
    let (png, file) = (dir.join("bezier.png"), dir.join("bezier.txt"));
    let output = run(&[
        "render",
        "bezier",
        "--control",
        "10,100,60,0,140,0,190,100",
        "--control",
        "10,110,100,60,190,110",
        "--size",
        "200x120",
        "--stats",
        "--out",
        png.to_str().unwrap(),
        "--segments",
        file.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let stats = stdout(&output);
    assert!(stats.starts_with("curves=2 segments="), "{stats}");
    let text = std::fs::read_to_string(&file).unwrap();
    let pieces: Vec<[f64; 4]> = text
        .lines()
        .map(|line| {
            let v: Vec<f64> = line.split(' ').map(|n| n.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect();
    let segments: usize = stats
        .split_whitespace()
        .find_map(|field| field.strip_prefix("segments="))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(pieces.len(), segments);
    // The first curve from (10, 100) to (190, 100), its pieces chained, each vertex on
    // the cubic within a thousandth of a pixel of the f64 curve at some t.
    assert_eq!(pieces[0][..2], [10.0, 100.0]);
    let split = pieces.iter().position(|p| p[..2] == [10.0, 110.0]).unwrap();
    assert_eq!(pieces[split - 1][2..], [190.0, 100.0]);
    assert_eq!(pieces.last().unwrap()[2..], [190.0, 110.0]);
    for pair in pieces[..split].windows(2) {
        assert_eq!(pair[0][2..], pair[1][..2]);
    }
    let cubic = |t: f64| {
        let s = 1.0 - t;
        (
            s * s * s * 10.0 + 3.0 * s * s * t * 60.0 + 3.0 * s * t * t * 140.0 + t * t * t * 190.0,
            s * s * s * 100.0 + t * t * t * 100.0,
        )
    };
    for piece in &pieces[..split] {
        let nearest = (0..=20_000)
            .map(|i| cubic(f64::from(i) / 20_000.0))
            .map(|(x, y)| ((x - piece[2]).powi(2) + (y - piece[3]).powi(2)).sqrt())
            .fold(f64::MAX, f64::min);
        assert!(nearest < 0.01, "{piece:?} is {nearest} from the curve");
    }
    let picture = image::open(&png).unwrap().to_rgb8();
    for (x, y) in [(10, 100), (190, 100), (10, 110), (190, 110)] {
        assert_ne!(
            picture.get_pixel(x, y).0,
            [0, 0, 0],
            "({x}, {y}) is not drawn"
        );
    }
}

#[test]
fn bad_control_points_are_refused() {
    for bad in ["1,2,3", "1,2,3,4,5,6,7", "1,2,3,4,5,x", "1.5,2,3,4,5,6"] {
        let output = run(&["render", "bezier", "--control", bad]);
        assert_eq!(output.status.code(), Some(2), "{bad}");
        assert!(stderr(&output).contains("whole pixel coordinates"), "{bad}");
    }
    let output = run(&["render", "bezier"]);
    assert_eq!(output.status.code(), Some(2));
}
