//! Bézier curves against the f64 curve: the flattened polyline within a quarter of a pixel
//! of it both ways, every drawn pixel within a pixel of it and every point of it within a
//! pixel of a drawn pixel, the pixels 8-connected, the ends exact.

use std::collections::{HashMap, HashSet, VecDeque};
use std::convert::Infallible;

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
use proptest::prelude::*;
use tinyfractal::bezier::{vertex_to_f64, Bezier};

/// A target that counts how often each pixel is drawn.
struct Counted {
    size: Size,
    pixels: HashMap<(i32, i32), u32>,
}

impl OriginDimensions for Counted {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Counted {
    type Color = BinaryColor;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Infallible> {
        for Pixel(p, _) in pixels {
            if self.bounding_box().contains(p) {
                *self.pixels.entry((p.x, p.y)).or_default() += 1;
            }
        }
        Ok(())
    }
}

/// The f64 curve at `t`, de Casteljau's definition by Bernstein polynomials.
fn at(points: &[(f64, f64)], t: f64) -> (f64, f64) {
    let s = 1.0 - t;
    match points {
        [a, b, c] => (
            s * s * a.0 + 2.0 * s * t * b.0 + t * t * c.0,
            s * s * a.1 + 2.0 * s * t * b.1 + t * t * c.1,
        ),
        [a, b, c, d] => (
            s * s * s * a.0 + 3.0 * s * s * t * b.0 + 3.0 * s * t * t * c.0 + t * t * t * d.0,
            s * s * s * a.1 + 3.0 * s * s * t * b.1 + 3.0 * s * t * t * c.1 + t * t * t * d.1,
        ),
        _ => unreachable!(),
    }
}

/// The curve sampled finely enough that neighbours are within 0.02 pixels.
fn samples(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let length: f64 = points
        .windows(2)
        .map(|w| ((w[1].0 - w[0].0).powi(2) + (w[1].1 - w[0].1).powi(2)).sqrt())
        .sum();
    let n = ((length / 0.02) as usize).max(16);
    (0..=n).map(|i| at(points, i as f64 / n as f64)).collect()
}

fn distance(a: (f64, f64), b: (f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

/// The distance from `p` to the segment `a`–`b`.
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length = dx * dx + dy * dy;
    let t = if length == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length).clamp(0.0, 1.0)
    };
    distance(p, (a.0 + t * dx, a.1 + t * dy))
}

fn curve_of(points: &[(i32, i32)]) -> Bezier {
    let p: Vec<Point> = points.iter().map(|&(x, y)| Point::new(x, y)).collect();
    match p[..] {
        [a, b, c] => Bezier::quadratic([a, b, c]),
        [a, b, c, d] => Bezier::cubic([a, b, c, d]),
        _ => unreachable!(),
    }
}

fn check(points: &[(i32, i32)]) {
    let exact: Vec<(f64, f64)> = points
        .iter()
        .map(|&(x, y)| (f64::from(x), f64::from(y)))
        .collect();
    let curve = curve_of(points);
    let along = samples(&exact);

    // The flattened polyline: its ends the control points', within ¼ pixel both ways.
    let vertices: Vec<(f64, f64)> = curve.flattened().map(vertex_to_f64).collect();
    assert_eq!(vertices.first(), exact.first(), "{points:?}");
    assert_eq!(vertices.last(), exact.last(), "{points:?}");
    let slack = 0.25 + 1e-3;
    for &p in &along {
        let nearest = vertices
            .windows(2)
            .map(|w| to_segment(p, w[0], w[1]))
            .fold(f64::MAX, f64::min);
        assert!(
            nearest <= slack,
            "{points:?}: curve point {p:?} is {nearest} from the polyline"
        );
    }
    for w in vertices.windows(2) {
        for k in 0..=8 {
            let t = f64::from(k) / 8.0;
            let p = (
                w[0].0 + t * (w[1].0 - w[0].0),
                w[0].1 + t * (w[1].1 - w[0].1),
            );
            let nearest = along
                .iter()
                .map(|&q| distance(p, q))
                .fold(f64::MAX, f64::min);
            assert!(
                nearest <= slack + 0.02,
                "{points:?}: polyline point {p:?} is {nearest} from the curve"
            );
        }
    }

    // The pixels.
    let mut target = Counted {
        size: Size::new(256, 256),
        pixels: HashMap::new(),
    };
    let stats = curve
        .into_stroked(BinaryColor::On)
        .draw(&mut target)
        .unwrap();
    let drawn: HashSet<(i32, i32)> = target.pixels.keys().copied().collect();
    assert_eq!(
        stats.pixels as usize,
        target.pixels.values().map(|&n| n as usize).sum::<usize>()
    );
    let (first, last) = (points[0], *points.last().unwrap());
    assert!(
        drawn.contains(&first) && drawn.contains(&last),
        "{points:?}: an end is missing"
    );
    for &(x, y) in &drawn {
        let centre = (f64::from(x), f64::from(y));
        let nearest = along
            .iter()
            .map(|&q| distance(centre, q))
            .fold(f64::MAX, f64::min);
        assert!(
            nearest <= 1.0,
            "{points:?}: pixel ({x}, {y}) is {nearest} from the curve"
        );
    }
    for &p in &along {
        let nearest = drawn
            .iter()
            .map(|&(x, y)| distance(p, (f64::from(x), f64::from(y))))
            .fold(f64::MAX, f64::min);
        assert!(
            nearest <= 1.0,
            "{points:?}: curve point {p:?} is {nearest} from every pixel"
        );
    }
    // 8-connected: every pixel reached from the first through neighbours.
    let mut seen = HashSet::from([first]);
    let mut queue = VecDeque::from([first]);
    while let Some((x, y)) = queue.pop_front() {
        for dx in -1..=1 {
            for dy in -1..=1 {
                let next = (x + dx, y + dy);
                if drawn.contains(&next) && seen.insert(next) {
                    queue.push_back(next);
                }
            }
        }
    }
    assert_eq!(
        seen.len(),
        drawn.len(),
        "{points:?}: the pixels are not 8-connected"
    );
}

#[test]
fn classic_curves_are_exact_by_their_rule() {
    check(&[(1, 30), (10, 0), (50, 0), (60, 30)]);
    check(&[(10, 200), (128, 10), (246, 200)]);
    // A loop, a cusp-like bend, a straight one and a point.
    check(&[(20, 20), (220, 220), (20, 220), (220, 20)]);
    check(&[(10, 10), (250, 10), (10, 10), (250, 10)]);
    check(&[(5, 5), (50, 50), (100, 100)]);
    check(&[(40, 40), (40, 40), (40, 40), (40, 40)]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    #[test]
    fn random_curves_are_exact_by_their_rule(
        points in prop::collection::vec((0i32..256, 0i32..256), 3..=4)
    ) {
        check(&points);
    }
}

/// A curve far outside the target draws nothing and costs no flattening; one crossing it
/// is clipped.
#[test]
fn curves_outside_the_target_are_clipped() {
    let mut target = Counted {
        size: Size::new(64, 64),
        pixels: HashMap::new(),
    };
    let far = Bezier::cubic([
        Point::new(1000, 1000),
        Point::new(2000, 900),
        Point::new(1500, 2000),
        Point::new(3000, 3000),
    ]);
    let stats = far.into_stroked(BinaryColor::On).draw(&mut target).unwrap();
    assert_eq!((stats.segments, stats.pixels), (0, 0));
    let crossing =
        Bezier::quadratic([Point::new(-100, 60), Point::new(32, 0), Point::new(200, 60)]);
    let stats = crossing
        .into_stroked(BinaryColor::On)
        .draw(&mut target)
        .unwrap();
    assert!(
        stats.pixels > 0
            && target
                .pixels
                .keys()
                .all(|&(x, y)| (0..64).contains(&x) && (0..64).contains(&y))
    );
    // Control points at the ends of i32 flatten within the halving limit.
    let huge = Bezier::cubic([
        Point::new(i32::MIN / 2, 0),
        Point::new(i32::MAX / 2, i32::MAX / 2),
        Point::new(i32::MIN / 2, i32::MAX / 2),
        Point::new(i32::MAX / 2, 0),
    ]);
    let stats = huge
        .into_stroked(BinaryColor::On)
        .draw(&mut target)
        .unwrap();
    assert!(stats.segments > 0);
}
