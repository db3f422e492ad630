//! IFS by the chaos game, against an f64 chaos game written here; Fractint's `.ifs`
//! reader; and the gingerbread man against a plain integer model.

mod common;

use std::collections::{HashMap, HashSet};

use common::Bitmap;
use embedded_graphics::{pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
use tinyfractal::{
    error::{Location, ReadError},
    ifs::IfsPicture,
    ChaosGame, Error, Gingerbread, IfsFile, Real,
};

/// Fractint's fern (its file's entry, byte for byte).
const FERN: &str = "fern {\n    0\t 0    0  .16 0\t 0 .01\n   .85\t.04 -.04 .85 0 1.6 .85\n   .2  -.26  .23 .22 0 1.6 .07\n  -.15\t.28  .26 .24 0 .44 .07\n  }\n";

/// The lecture's table of the fern, in its own naming: x' = a·x + b·y + e,
/// y' = c·x + d·y + f, the rows f1..f4 with their probabilities.
const LECTURE_FERN: [[f64; 7]; 4] = [
    [0.0, 0.0, 0.0, 0.16, 0.0, 0.0, 0.01],
    [0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85],
    [0.2, -0.26, 0.23, 0.22, 0.0, 1.6, 0.07],
    [-0.15, 0.28, 0.26, 0.24, 0.0, 0.44, 0.07],
];

/// The box of the lit pixels.
fn lit_box(bitmap: &Bitmap) -> Option<Rectangle> {
    let (w, h) = (bitmap.size().width as i32, bitmap.size().height as i32);
    let lit: Vec<Point> = (0..h)
        .flat_map(|y| (0..w).map(move |x| Point::new(x, y)))
        .filter(|p| bitmap.get(p.x, p.y))
        .collect();
    let min = Point::new(
        lit.iter().map(|p| p.x).min()?,
        lit.iter().map(|p| p.y).min()?,
    );
    let max = Point::new(
        lit.iter().map(|p| p.x).max()?,
        lit.iter().map(|p| p.y).max()?,
    );
    Some(Rectangle::with_corners(min, max))
}

#[test]
fn fractints_fern_is_the_lecture_fern() {
    let ifs = IfsFile::new(FERN).entry("FERN").unwrap().ifs().unwrap();
    assert!(!ifs.is_3d());
    assert_eq!(ifs.len(), 4);
    for (map, row) in ifs.maps().zip(LECTURE_FERN) {
        let [a, b, c, d, e, f, _] = row;
        let got = [
            map.matrix[0][0],
            map.matrix[0][1],
            map.matrix[1][0],
            map.matrix[1][1],
            map.translation[0],
            map.translation[1],
        ];
        for (g, want) in got.iter().zip([a, b, c, d, e, f]) {
            assert!((g.to_f64() - want).abs() < 1e-9, "{g:?} vs {want}");
        }
    }
}

/// A small generator for the f64 model, unrelated to the engine's PCG.
struct Lcg(u64);

impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Every plotted point of the fern lies on the attractor as an f64 chaos game finds it
/// (a cell of a 100×100 grid it reached, or one next to it), and the points cover it:
/// they reach 95 % of the cells the model reaches often.
#[test]
fn fern_points_lie_on_and_cover_the_attractor() {
    let ifs = IfsFile::new(FERN).entry("fern").unwrap().ifs().unwrap();
    // The f64 model.
    let (mut x, mut y) = (0.0f64, 0.0f64);
    let mut rng = Lcg(7);
    let mut model = Vec::new();
    for i in 0..2_000_000 {
        let r = rng.unit();
        let mut acc = 0.0;
        let mut chosen = LECTURE_FERN[3];
        for row in LECTURE_FERN {
            acc += row[6];
            if r < acc {
                chosen = row;
                break;
            }
        }
        let [a, b, c, d, e, f, _] = chosen;
        (x, y) = (a * x + b * y + e, c * x + d * y + f);
        if i > 100 {
            model.push((x, y));
        }
    }
    let (x0, x1) = (-3.0, 3.0);
    let (y0, y1) = (0.0, 10.0);
    let cell = |x: f64, y: f64| {
        (
            (((x - x0) / (x1 - x0)) * 100.0).floor() as i32,
            (((y - y0) / (y1 - y0)) * 100.0).floor() as i32,
        )
    };
    let mut counts: HashMap<(i32, i32), u32> = HashMap::new();
    for &(x, y) in &model {
        *counts.entry(cell(x, y)).or_default() += 1;
    }
    let ours: Vec<(i32, i32)> = ChaosGame::new(&ifs, 3, 400_000)
        .map(|p| {
            let p = p.unwrap().position;
            cell(p[0].to_f64(), p[1].to_f64())
        })
        .collect();
    for &(cx, cy) in &ours {
        let near = (-1..=1).any(|dx| (-1..=1).any(|dy| counts.contains_key(&(cx + dx, cy + dy))));
        assert!(near, "a point off the attractor in cell ({cx}, {cy})");
    }
    let reached: HashSet<&(i32, i32)> = ours.iter().collect();
    let often: Vec<&(i32, i32)> = counts
        .iter()
        .filter(|(_, &n)| n >= 100)
        .map(|(c, _)| c)
        .collect();
    let covered = often.iter().filter(|c| reached.contains(**c)).count();
    assert!(
        covered as f64 >= 0.95 * often.len() as f64,
        "{covered} of {} cells covered",
        often.len()
    );
}

/// The same seed plots the same points; another seed other points; the drawing is fitted
/// to a sample of its game (the first `FIT_POINTS` and the maps' fixed points): it fills
/// its bounding box to within a pixel on every side, inside the area's margin.
#[test]
fn games_are_seeded_and_fitted() {
    let ifs = IfsFile::new(FERN).entry("fern").unwrap().ifs().unwrap();
    let points = |seed| -> Vec<[Real; 3]> {
        ChaosGame::new(&ifs, seed, 1000)
            .map(|p| p.unwrap().position)
            .collect()
    };
    assert_eq!(points(1), points(1));
    assert_ne!(points(1), points(2));
    let drawing = IfsPicture::new(&ifs, 20_000)
        .fit(
            Rectangle::new(Point::zero(), Size::new(64, 96)),
            &[BinaryColor::On],
        )
        .unwrap();
    let mut bitmap = Bitmap::new(64, 96);
    assert_eq!(drawing.draw(&mut bitmap).unwrap(), 20_000);
    let lit = lit_box(&bitmap).unwrap();
    let fitted = drawing.bounding_box();
    let (a, b) = (lit.bottom_right().unwrap(), fitted.bottom_right().unwrap());
    for (got, want) in [
        (lit.top_left.x, fitted.top_left.x),
        (lit.top_left.y, fitted.top_left.y),
        (a.x, b.x),
        (a.y, b.y),
    ] {
        assert!((got - want).abs() <= 1, "{lit:?} against {fitted:?}");
    }
}

#[test]
fn malformed_ifs_files_are_typed_errors() {
    let error = |text: &str| {
        IfsFile::new(text)
            .entries()
            .next()
            .unwrap()
            .unwrap()
            .ifs()
            .unwrap_err()
    };
    assert_eq!(
        error("a {\n  .5 0 0 .5 0 0\n}\n"),
        Error::Read(ReadError::WrongColumnCount {
            expected: 7,
            found: 6,
            at: Location { line: 2, column: 3 },
        })
    );
    assert_eq!(
        error("a (3D) {\n  .5 0 0 .5 0 0 .5\n}\n"),
        Error::Read(ReadError::WrongColumnCount {
            expected: 13,
            found: 7,
            at: Location { line: 2, column: 3 },
        })
    );
    let sum = error("a {\n  .5 0 0 .5 0 0 .5\n  .5 0 0 .5 1 1 .3\n}\n");
    assert!(sum.to_string().contains("sum to 0.8,"), "{sum}");
    assert!(matches!(
        error("a {\n  .5 0 0 .5 0 x .5\n}\n"),
        Error::Read(ReadError::NotANumber { .. })
    ));
    assert!(matches!(
        IfsFile::new("a {\n  .5 0 0 .5 0 0 1\n")
            .entries()
            .next()
            .unwrap(),
        Err(Error::Read(ReadError::UnterminatedEntry { .. }))
    ));
}

/// All 20 entries of Fractint's `fractint.ifs` read (2D and 3D) and draw.
#[test]
#[cfg_attr(
    not(tinyfractal_corpus),
    ignore = "needs Fractint's corpus: shared/ beside the repository, or TINYFRACTAL_CORPUS"
)]
fn every_corpus_ifs_reads_and_draws() {
    let path =
        std::path::PathBuf::from(env!("TINYFRACTAL_CORPUS_DIR")).join("fractint/fractint.ifs");
    let text = std::fs::read_to_string(path).unwrap();
    let file = IfsFile::new(&text);
    let mut count = 0;
    let mut three_d = 0;
    for entry in file.entries() {
        let entry = entry.unwrap();
        let ifs = entry
            .ifs()
            .unwrap_or_else(|e| panic!("{}: {e}", entry.name()));
        three_d += usize::from(ifs.is_3d());
        let drawing = IfsPicture::new(&ifs, 5_000)
            .fit(
                Rectangle::new(Point::zero(), Size::new(64, 48)),
                &[BinaryColor::On],
            )
            .unwrap_or_else(|e| panic!("{}: {e}", entry.name()));
        let mut bitmap = Bitmap::new(64, 48);
        assert_eq!(
            drawing.draw(&mut bitmap).unwrap(),
            5_000,
            "{}",
            entry.name()
        );
        assert!(lit_box(&bitmap).is_some(), "{} draws", entry.name());
        count += 1;
    }
    assert_eq!(count, 20);
    assert!(three_d >= 2, "{three_d} 3D entries");
}

/// The lecture's gingerbread man: the orbit equals a plain integer model of the map, and
/// its period is the one a set of seen points finds.
#[test]
fn gingerbread_orbit_and_period() {
    let map = Gingerbread::default();
    let (m, l) = (40i64, 3i64);
    let (mut x, mut y) = (115i64, 121i64);
    let mut seen = HashMap::new();
    let mut first_repeat = None;
    let ours: Vec<(i64, i64)> = Gingerbread {
        iterations: 20_000,
        ..map
    }
    .points()
    .map(Result::unwrap)
    .collect();
    for (i, &point) in ours.iter().enumerate() {
        assert_eq!(point, (x, y), "point {i}");
        if first_repeat.is_none() {
            if let Some(&j) = seen.get(&(x, y)) {
                first_repeat = Some((j as u64, (i - j) as u64));
            }
            seen.insert((x, y), i);
        }
        (x, y) = (m * (1 + 2 * l) - y + (x - l * m).abs(), x);
    }
    let (tail, period) = first_repeat.expect("a repeat within 20,000 points");
    let cycle = map.cycle(1 << 20).unwrap().unwrap();
    assert_eq!((cycle.tail, cycle.period), (tail, period));
    // A start off the lecture's has a tail before its cycle, found the same way.
    let other = Gingerbread {
        start: (0, 1000),
        ..map
    };
    let cycle = other.cycle(1 << 22).unwrap().unwrap();
    let mut seen = HashMap::new();
    let mut p = other.start;
    for i in 0u64.. {
        if let Some(&j) = seen.get(&p) {
            assert_eq!((cycle.tail, cycle.period), (j, i - j));
            break;
        }
        seen.insert(p, i);
        p = other.step(p).unwrap();
    }
}

/// Colour by density: every pixel of the area written exactly once (a row at a time), the
/// hit counts add up to the points played, and a short buffer is a typed error.
#[test]
fn density_colours_count_every_point() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::Gray8;
    use tinyfractal::{error::FitError, ifs::DENSITY_LEVELS, render::Gradient};
    let ifs = IfsFile::new(FERN).entry("fern").unwrap().ifs().unwrap();
    let area = Rectangle::new(Point::zero(), Size::new(64, 64));
    let palette = Gradient::<Gray8, 16>::new(
        &[
            embedded_graphics::pixelcolor::Rgb888::BLACK,
            embedded_graphics::pixelcolor::Rgb888::WHITE,
        ],
        Gray8::BLACK,
    )
    .unwrap();
    let mut counts = vec![0u16; 64 * 64];
    let drawing = IfsPicture::new(&ifs, 30_000)
        .fit_density(area, palette, &mut counts)
        .unwrap();
    let mut display: MockDisplay<Gray8> = MockDisplay::new();
    assert_eq!(drawing.draw(&mut display).unwrap(), 30_000);
    assert_eq!(display.affected_area(), area);
    assert_eq!(counts.iter().map(|&c| u64::from(c)).sum::<u64>(), 30_000);
    assert!(
        counts.iter().any(|&c| c >= 1 << (DENSITY_LEVELS / 2)),
        "dense pixels"
    );
    let mut short = vec![0u16; 100];
    assert_eq!(
        IfsPicture::new(&ifs, 10)
            .fit_density(area, palette, &mut short)
            .err(),
        Some(Error::Fit(FitError::BufferTooSmall {
            needed: 4096,
            given: 100
        }))
    );
}

/// Fractint draws entries with a probability of 0 or less (public collections use them on
/// purpose): it adds probabilities until the sum reaches a random number in [0, 1] and
/// takes the last map if it never does. The maps' shares of a long game match that loop,
/// run here in f64 over a fine grid of random numbers.
#[test]
fn maps_of_zero_or_negative_probability_are_chosen_as_fractint_chooses() {
    let probabilities = [0.3, 0.0, -0.2, 0.5, 0.1, 0.3];
    let rows: String = probabilities
        .iter()
        .enumerate()
        .map(|(k, p)| format!("  0.5 0 0 0.5 {} 0 {p}\n", k as f64 * 0.1))
        .collect();
    let text = format!("negative {{\n{rows}}}\n");
    let ifs = IfsFile::new(&text)
        .entry("negative")
        .unwrap()
        .ifs()
        .unwrap();
    // Fractint's loop, as written in its source.
    let grid = 100_000;
    let mut expected = [0usize; 6];
    for i in 0..grid {
        let r = (i as f64 + 0.5) / grid as f64;
        let (mut sum, mut k) = (probabilities[0], 0);
        while sum < r && k < probabilities.len() - 1 {
            k += 1;
            sum += probabilities[k];
        }
        expected[k] += 1;
    }
    // Maps 1 and 2 (0 and -0.2) are never chosen; map 3's sum, 0.6, passes the largest
    // before it, 0.3: chosen from 0.3 to 0.6.
    assert_eq!(expected[1] + expected[2], 0);
    assert_eq!(ifs.never_chosen(), 2);
    let points = 200_000;
    let mut counts = [0usize; 6];
    for point in ChaosGame::new(&ifs, 7, points) {
        counts[point.unwrap().map] += 1;
    }
    for k in 0..6 {
        let model = expected[k] as f64 / grid as f64;
        let ours = counts[k] as f64 / points as f64;
        assert!(
            (model - ours).abs() < 0.005,
            "map {k}: {ours} against Fractint's {model}"
        );
    }
    // And the picture draws.
    let mut bitmap = Bitmap::new(64, 64);
    IfsPicture::new(&ifs, 2000)
        .fit(bitmap.bounding_box(), &[BinaryColor::On])
        .unwrap()
        .draw(&mut bitmap)
        .unwrap();
}
