//! The Sierpiński carpet, gasket and cube against independent models: base-3 digits for
//! the carpet, point-in-triangle subdivision in f64 for the gasket, ray casting in f64
//! for the cube; counts against theory (8ᴺ, 3ᴺ, 26ᴺ, 20ᴺ); bad input.

mod common;

use common::{Counting, Frame};
use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
    primitives::Rectangle,
};
use tinyfractal::{
    error::ParameterError,
    subdivision::{Camera, CubeVariant},
    Carpet, Error, Gasket, Real, SierpinskiCube,
};

const UNPAINTED: Rgb565 = Rgb565::RED;
const INK: Rgb565 = Rgb565::WHITE;
const PAPER: Rgb565 = Rgb565::BLACK;

/// Whether the carpet removes pixel (x, y) of a 3ᴺ-pixel square: both base-3 digits are
/// 1 at some position.
fn carpet_removes(mut x: u32, mut y: u32, order: u32) -> bool {
    (0..order).any(|_| {
        let hole = x % 3 == 1 && y % 3 == 1;
        (x, y) = (x / 3, y / 3);
        hole
    })
}

#[test]
fn carpet_is_exact_at_three_to_the_order_pixels() {
    for order in 0..=5 {
        let side = 3u32.pow(order);
        let mut frame = Counting::new(Frame::filled(Size::new(side, side), UNPAINTED));
        let area = frame.bounding_box();
        let stats = Carpet::new(order)
            .fit(area, INK, PAPER)
            .unwrap()
            .draw(&mut frame)
            .unwrap();
        assert_eq!(stats.squares, 8u64.pow(order));
        assert_eq!(stats.holes, (8u64.pow(order) - 1) / 7);
        // Every pixel once: a fill_solid per hole, and per last-level group of eight kept
        // squares four (its top and bottom rows whole, its middle row's two).
        let groups = if order == 0 { 1 } else { 8u64.pow(order - 1) };
        let ink_fills = if order == 0 { 1 } else { 4 * groups };
        assert_eq!(
            frame.fill_solid_calls as u64,
            ink_fills + stats.holes,
            "order {order}"
        );
        assert_eq!(frame.draw_iter_pixels, 0);
        assert_eq!(frame.run_pixels, (side * side) as usize);
        for y in 0..side {
            for x in 0..side {
                let expected = if carpet_removes(x, y, order) {
                    PAPER
                } else {
                    INK
                };
                assert_eq!(
                    frame.inner.pixel(x as i32, y as i32),
                    Some(expected),
                    "order {order}, pixel ({x}, {y})"
                );
            }
        }
    }
}

#[test]
fn carpet_at_other_sizes_keeps_eight_ninths_per_order() {
    // At 200 pixels a cell is not a whole number of pixels; the kept area is still within
    // a pixel row per hole edge of (8/9)^N.
    for order in 1..=4 {
        let mut frame = Frame::filled(Size::new(260, 200), UNPAINTED);
        let drawing = Carpet::new(order)
            .fit(frame.bounding_box(), INK, PAPER)
            .unwrap();
        assert_eq!(
            drawing.bounding_box(),
            Rectangle::new(Point::new(30, 0), Size::new(200, 200))
        );
        drawing.draw(&mut frame).unwrap();
        let ink = frame.pixels.iter().filter(|&&c| c == INK).count() as f64;
        let expected = (8.0f64 / 9.0).powi(order as i32) * 200.0 * 200.0;
        assert!(
            (ink - expected).abs() / expected < 0.02,
            "order {order}: {ink} ink pixels, theory {expected}"
        );
        // Outside the square: untouched.
        assert_eq!(frame.pixel(0, 100), Some(UNPAINTED));
        assert_eq!(frame.pixel(259, 100), Some(UNPAINTED));
    }
}

/// At sizes that are no power of 3, every pixel as the documented rule has it: cell i of
/// level k spans ⌊S·i/3ᵏ⌋ to ⌊S·(i + 1)/3ᵏ⌋, and a pixel is removed when at some level both
/// of its cells' indices are 1 modulo 3 (the model finds each cell by scanning the edges).
#[test]
fn carpet_cells_follow_the_edge_rule_at_any_size() {
    for (side, order) in [(200u32, 4u32), (100, 3), (82, 4), (250, 5), (64, 3)] {
        let mut frame = Frame::filled(Size::new(side, side), UNPAINTED);
        Carpet::new(order)
            .fit(frame.bounding_box(), INK, PAPER)
            .unwrap()
            .draw(&mut frame)
            .unwrap();
        // The index of the cell of level k that pixel p lies in.
        let cell = |p: u32, k: u32| {
            let cells = 3u64.pow(k);
            (0..cells)
                .find(|&i| {
                    let (from, to) = (
                        u64::from(side) * i / cells,
                        u64::from(side) * (i + 1) / cells,
                    );
                    (from..to).contains(&u64::from(p))
                })
                .unwrap()
        };
        for y in 0..side {
            for x in 0..side {
                let removed = (1..=order).any(|k| cell(x, k) % 3 == 1 && cell(y, k) % 3 == 1);
                let expected = if removed { PAPER } else { INK };
                let at = (x as i32, y as i32);
                assert_eq!(
                    frame.pixel(at.0, at.1),
                    Some(expected),
                    "{side} px order {order}: {at:?}"
                );
            }
        }
    }
}

/// Whether a point (u across, v down, the triangle's box being [0, 1]²) is in the gasket
/// of `order`: the triangle with apex (1/2, 0) and base v = 1, its middle removed at each
/// level, followed down in f64.
fn in_gasket(u: f64, v: f64, order: u32) -> bool {
    // Barycentric-like coordinates: depth v, offset from the left edge.
    let (mut a, mut b) = (v, u - (0.5 - v / 2.0)); // b in [0, v] inside
    if !(0.0..=1.0).contains(&a) || b < 0.0 || b > a {
        return false;
    }
    for _ in 0..order {
        // Scale the triangle by 2: top half (a < 1/2) is the top sub-triangle.
        a *= 2.0;
        b *= 2.0;
        if a < 1.0 {
            continue;
        }
        a -= 1.0;
        if b < 1.0 {
            // Lower left, unless in the middle (inverted) triangle: b > a.
            if b > a {
                return false;
            }
        } else {
            b -= 1.0;
            if b > a {
                return false;
            }
        }
    }
    true
}

#[test]
fn gasket_matches_an_f64_subdivision_pixel_for_pixel_away_from_edges() {
    for order in 0..=6 {
        let mut frame = Counting::new(Frame::filled(Size::new(300, 220), UNPAINTED));
        let drawing = Gasket::new(order)
            .fit(frame.bounding_box(), INK, PAPER)
            .unwrap();
        let stats = drawing.draw(&mut frame).unwrap();
        assert_eq!(stats.triangles, 3u64.pow(order));
        let frame_box = drawing.bounding_box();
        assert_eq!(
            frame.run_pixels,
            frame_box.size.width as usize * frame_box.size.height as usize
        );
        assert_eq!(frame.draw_iter_pixels, 0);
        let (w, h) = (frame_box.size.width as f64, frame_box.size.height as f64);
        let (mut differ, mut ink) = (0, 0);
        for y in 0..frame_box.size.height as i32 {
            for x in 0..frame_box.size.width as i32 {
                let p = frame_box.top_left + Point::new(x, y);
                let got = frame.inner.pixel(p.x, p.y).unwrap();
                assert_ne!(got, UNPAINTED, "order {order}: ({x}, {y}) not painted");
                let (u, v) = ((x as f64 + 0.5) / w, (y as f64 + 0.5) / h);
                let inside = in_gasket(u, v, order);
                ink += usize::from(got == INK);
                if inside != (got == INK) {
                    // Only pixels whose centre is within a hair of an edge may differ.
                    let near = [(-1e-6, 0.0), (1e-6, 0.0), (0.0, -1e-6), (0.0, 1e-6)]
                        .iter()
                        .any(|(du, dv)| in_gasket(u + du, v + dv, order) != inside);
                    assert!(
                        near,
                        "order {order}: pixel ({x}, {y}) differs from the model"
                    );
                    differ += 1;
                }
            }
        }
        // Centres exactly on an edge: the model's comparisons and the half-open rule may
        // break the tie differently.
        assert!(
            differ * 1000 <= (w * h) as usize,
            "order {order}: {differ} edge pixels differ"
        );
        // Area: half the box, times (3/4)^N, while the triangles are large against a
        // pixel (beyond, sampling their edges dominates; the pixels are checked above).
        if order > 4 {
            continue;
        }
        let theory = 0.5 * 0.75f64.powi(order as i32) * w * h;
        assert!(
            (ink as f64 - theory).abs() / theory < 0.03,
            "order {order}: {ink} vs {theory}"
        );
    }
}

/// The cube's picture in f64: each pixel centre cast as a ray along the view direction into
/// the kept cells (listed here, from the variant's rule), the nearest face hit giving its
/// axis; `None` for background.
struct CubeModel {
    cells: Vec<[i64; 3]>,
    side: f64,
    right: [f64; 3],
    up: [f64; 3],
    toward: [f64; 3],
    scale: f64,
    centre_offset: (f64, f64),
}

impl CubeModel {
    fn new(order: u32, variant: CubeVariant, azimuth: f64, elevation: f64, area: Size) -> Self {
        let side = 3i64.pow(order);
        let removed = |mut p: [i64; 3]| {
            (0..order).any(|_| {
                let ones = p.iter().filter(|&&c| c % 3 == 1).count();
                p = p.map(|c| c / 3);
                match variant {
                    CubeVariant::Centre => ones == 3,
                    CubeVariant::Axes => ones >= 2,
                }
            })
        };
        let mut cells = Vec::new();
        for x in 0..side {
            for y in 0..side {
                for z in 0..side {
                    if !removed([x, y, z]) {
                        cells.push([x, y, z]);
                    }
                }
            }
        }
        let (a, e) = (azimuth.to_radians(), elevation.to_radians());
        let right = [-a.sin(), a.cos(), 0.0];
        let up = [-e.sin() * a.cos(), -e.sin() * a.sin(), e.cos()];
        let toward = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let spread = |v: [f64; 3]| v.iter().map(|c| c.abs()).sum::<f64>();
        let unit = (area.width as f64 / spread(right)).min(area.height as f64 / spread(up));
        let scale = unit / side as f64;
        // Screen of a world point: (p·right, -p·up)·scale + offset; the corners' box centred.
        let corners: Vec<(f64, f64)> = (0..8)
            .map(|i| {
                let p = [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64]
                    .map(|c| c * side as f64);
                (dot(p, right) * scale, -dot(p, up) * scale)
            })
            .collect();
        let min_x = corners.iter().map(|c| c.0).fold(f64::MAX, f64::min);
        let max_x = corners.iter().map(|c| c.0).fold(f64::MIN, f64::max);
        let min_y = corners.iter().map(|c| c.1).fold(f64::MAX, f64::min);
        let max_y = corners.iter().map(|c| c.1).fold(f64::MIN, f64::max);
        let centre_offset = (
            area.width as f64 / 2.0 - (min_x + max_x) / 2.0,
            area.height as f64 / 2.0 - (min_y + max_y) / 2.0,
        );
        Self {
            cells,
            side: side as f64,
            right,
            up,
            toward,
            scale,
            centre_offset,
        }
    }

    /// The axis of the face seen at screen point (sx, sy), or `None`.
    fn seen(&self, sx: f64, sy: f64) -> Option<usize> {
        let (r, u) = (
            (sx - self.centre_offset.0) / self.scale,
            -(sy - self.centre_offset.1) / self.scale,
        );
        // A ray from far on the viewer's side towards -toward.
        let far = 4.0 * self.side;
        let origin: [f64; 3] =
            std::array::from_fn(|i| r * self.right[i] + u * self.up[i] + far * self.toward[i]);
        let direction = self.toward.map(|c| -c);
        let mut best: Option<(f64, usize)> = None;
        for cell in &self.cells {
            // Slab test.
            let (mut enter, mut leave, mut axis) = (f64::MIN, f64::MAX, 0);
            let mut hit = true;
            for i in 0..3 {
                let (lo, hi) = (cell[i] as f64, cell[i] as f64 + 1.0);
                if direction[i].abs() < 1e-12 {
                    if origin[i] < lo || origin[i] > hi {
                        hit = false;
                        break;
                    }
                    continue;
                }
                let (t0, t1) = (
                    (lo - origin[i]) / direction[i],
                    (hi - origin[i]) / direction[i],
                );
                let (near, farther) = (t0.min(t1), t0.max(t1));
                if near > enter {
                    enter = near;
                    axis = i;
                }
                leave = leave.min(farther);
            }
            if hit && enter < leave && best.is_none_or(|(t, _)| enter < t) {
                best = Some((enter, axis));
            }
        }
        best.map(|(_, axis)| axis)
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a.iter().zip(&b).map(|(x, y)| x * y).sum()
}

fn check_cube_against_ray_casting(order: u32, variant: CubeVariant, azimuth: i32, elevation: i32) {
    let size = Size::new(150, 130);
    let mut frame = Frame::filled(size, UNPAINTED);
    let camera = Camera {
        azimuth: Real::from_int(azimuth),
        elevation: Real::from_int(elevation),
    };
    let cube = SierpinskiCube::new(order, variant).with_camera(camera);
    let stats = cube
        .fit(frame.bounding_box(), Rgb888::new(200, 180, 120), PAPER)
        .unwrap()
        .draw(&mut frame)
        .unwrap();
    assert_eq!(stats.cubes, variant.kept().pow(order));
    let model = CubeModel::new(order, variant, azimuth as f64, elevation as f64, size);
    // The colour of each axis, as the picture shows it: the most common colour where the
    // model sees that axis.
    let mut votes = vec![std::collections::HashMap::<Rgb565, usize>::new(); 3];
    let mut seen = Vec::new();
    for y in 0..size.height as i32 {
        for x in 0..size.width as i32 {
            let axis = model.seen(x as f64 + 0.5, y as f64 + 0.5);
            let got = frame.pixel(x, y).unwrap();
            assert_ne!(got, UNPAINTED);
            if let Some(axis) = axis {
                *votes[axis].entry(got).or_default() += 1;
            }
            seen.push((axis, got));
        }
    }
    let colours: Vec<Option<Rgb565>> = votes
        .iter()
        .map(|v| v.iter().max_by_key(|(_, n)| **n).map(|(c, _)| *c))
        .collect();
    let differ = seen
        .iter()
        .filter(|(axis, got)| match axis {
            None => *got != PAPER,
            Some(axis) => Some(*got) != colours[*axis],
        })
        .count();
    let cube_pixels = seen.iter().filter(|(axis, _)| axis.is_some()).count();
    assert!(cube_pixels > 1000);
    assert!(
        differ * 200 <= cube_pixels,
        "order {order} {variant:?} camera ({azimuth}, {elevation}): {differ} of {cube_pixels} pixels differ from ray casting"
    );
}

#[test]
fn cube_pictures_equal_ray_casting_in_f64() {
    check_cube_against_ray_casting(2, CubeVariant::Axes, 45, 35);
    check_cube_against_ray_casting(2, CubeVariant::Axes, 30, 20);
    check_cube_against_ray_casting(2, CubeVariant::Axes, -120, -25);
    check_cube_against_ray_casting(1, CubeVariant::Centre, 60, 40);
    check_cube_against_ray_casting(2, CubeVariant::Centre, 200, 10);
}

#[test]
fn cube_counts_and_hidden_faces() {
    for order in 0..=4 {
        for variant in [CubeVariant::Centre, CubeVariant::Axes] {
            let mut frame = Frame::filled(Size::new(200, 200), PAPER);
            let cube = SierpinskiCube::new(order, variant);
            assert_eq!(cube.cubes(), variant.kept().pow(order));
            let stats = cube
                .fit(frame.bounding_box(), Rgb888::WHITE, PAPER)
                .unwrap()
                .draw(&mut frame)
                .unwrap();
            assert_eq!(
                stats.cubes,
                variant.kept().pow(order),
                "{variant:?} order {order}"
            );
            if variant == CubeVariant::Centre {
                // Its holes are closed on every side: only the outer surface shows, 3·9ᴺ
                // faces, and no face inside is drawn.
                assert_eq!(stats.faces, 3 * 9u64.pow(order));
            } else {
                // Faces turned to the camera, against no kept cube: fewer than 3 per cube.
                assert!(stats.faces >= 3 * 9u64.pow(order) && stats.faces < 3 * stats.cubes.max(2));
            }
        }
    }
}

#[test]
fn orders_beyond_the_target_and_bad_cameras_are_typed_errors() {
    let area = Rectangle::new(Point::zero(), Size::new(100, 80));
    let too_high = |result: Result<(), Error>| match result {
        Err(Error::Parameter(ParameterError::OrderTooHigh { order, max })) => (order, max),
        other => panic!("expected OrderTooHigh, got {other:?}"),
    };
    // 80 pixels: 3^3 = 27 fits, 81 does not.
    assert_eq!(
        too_high(Carpet::new(4).fit(area, INK, PAPER).map(|_| ())),
        (4, 3)
    );
    assert_eq!(
        too_high(Gasket::new(7).fit(area, INK, PAPER).map(|_| ())),
        (7, 6)
    );
    assert_eq!(
        too_high(
            SierpinskiCube::new(4, CubeVariant::Axes)
                .fit(area, Rgb888::WHITE, PAPER)
                .map(|_| ())
        ),
        (4, 3)
    );
    assert!(Carpet::new(99)
        .fit(
            Rectangle::new(Point::zero(), Size::new(16000, 16000)),
            INK,
            PAPER
        )
        .is_err());
    let zero = Rectangle::new(Point::zero(), Size::new(0, 10));
    assert!(matches!(
        Carpet::new(1).fit(zero, INK, PAPER),
        Err(Error::Fit(tinyfractal::error::FitError::ZeroSizeTarget))
    ));
    let straight_down = Camera {
        azimuth: Real::ZERO,
        elevation: Real::from_int(-90),
    };
    let error = SierpinskiCube::new(1, CubeVariant::Centre)
        .with_camera(straight_down)
        .fit(area, Rgb888::WHITE, PAPER)
        .unwrap_err();
    assert!(matches!(
        error,
        Error::Parameter(ParameterError::CameraOutOfRange { .. })
    ));
    assert!(error.to_string().contains("elevation"));
}
