//! `Affine3`, the maps of space shared by the 3D IFS and the cube's camera, against f64
//! models written here: composition, application, and the camera's rows.

use proptest::prelude::*;
use tinyfractal::{math::Affine3, Real};

fn real(v: f64) -> Real {
    Real::from_f64(v).unwrap()
}

fn f(v: Real) -> f64 {
    v.to_f64()
}

fn model_apply(map: &Affine3, p: [f64; 3]) -> [f64; 3] {
    core::array::from_fn(|i| {
        (0..3).map(|j| f(map.matrix[i][j]) * p[j]).sum::<f64>() + f(map.translation[i])
    })
}

fn map_of(entries: [f64; 12]) -> Affine3 {
    Affine3 {
        matrix: [
            [real(entries[0]), real(entries[1]), real(entries[2])],
            [real(entries[3]), real(entries[4]), real(entries[5])],
            [real(entries[6]), real(entries[7]), real(entries[8])],
        ],
        translation: [real(entries[9]), real(entries[10]), real(entries[11])],
    }
}

proptest! {
    /// `a.then(b)` maps a point where b(a(p)) does, in f64, to within the rounding of a
    /// few products (2^-32 each).
    #[test]
    fn composition_is_application_in_turn(
        a in prop::array::uniform12(-2.0f64..2.0),
        b in prop::array::uniform12(-2.0f64..2.0),
        p in prop::array::uniform3(-10.0f64..10.0),
    ) {
        let (a, b) = (map_of(a), map_of(b));
        let point = p.map(real);
        let composed = a.then(&b).unwrap().apply(point).unwrap();
        let want = model_apply(&b, model_apply(&a, point.map(f)));
        for (got, want) in composed.iter().zip(want) {
            prop_assert!((f(*got) - want).abs() < 1e-7, "{} vs {want}", f(*got));
        }
    }
}

#[test]
fn the_identity_and_planar_maps() {
    let p = [real(1.5), real(-2.25), real(3.0)];
    assert_eq!(Affine3::IDENTITY.apply(p), Some(p));
    // Fractint's fern map 2: x' = 0.2x - 0.26y, y' = 0.23x + 0.22y + 1.6.
    let map = Affine3::planar([0.2, -0.26, 0.23, 0.22, 0.0, 1.6].map(real));
    let [x, y, z] = map.apply(p).unwrap().map(f);
    assert!((x - (0.2 * 1.5 + 0.26 * 2.25)).abs() < 1e-8);
    assert!((y - (0.23 * 1.5 - 0.22 * 2.25 + 1.6)).abs() < 1e-8);
    assert_eq!(z, 0.0);
    let big = Affine3::planar([
        real(1e9),
        Real::ZERO,
        Real::ZERO,
        Real::ONE,
        Real::ZERO,
        Real::ZERO,
    ]);
    assert_eq!(
        big.apply([real(10.0), Real::ZERO, Real::ZERO]),
        None,
        "out of range"
    );
}

/// The camera's rows are screen right, up and towards the viewer: orthonormal, as the f64
/// formulas give them; at the isometric angles the three world axes land 120° apart and
/// equally long on the screen.
#[test]
fn camera_rows() {
    for (azimuth, elevation) in [(45.0, 35.264), (0.0, 0.0), (30.0, -20.0), (200.0, 60.0)] {
        let view = Affine3::camera(real(azimuth), real(elevation));
        let (a, e) = (f64::to_radians(azimuth), f64::to_radians(elevation));
        let want = [
            [-a.sin(), a.cos(), 0.0],
            [-e.sin() * a.cos(), -e.sin() * a.sin(), e.cos()],
            [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()],
        ];
        for (row, want_row) in view.matrix.iter().zip(want) {
            for (got, expected) in row.iter().zip(want_row) {
                assert!((f(*got) - expected).abs() < 1e-6, "{azimuth},{elevation}");
            }
        }
    }
    let iso = Affine3::camera(real(45.0), real(35.264));
    let screen: Vec<(f64, f64)> = (0..3)
        .map(|axis| (f(iso.matrix[0][axis]), f(iso.matrix[1][axis])))
        .collect();
    for (x, y) in &screen {
        assert!((x.hypot(*y) - (2.0f64 / 3.0).sqrt()).abs() < 1e-4);
    }
    for i in 0..3 {
        let (a, b) = (screen[i], screen[(i + 1) % 3]);
        let cos = (a.0 * b.0 + a.1 * b.1) / (a.0.hypot(a.1) * b.0.hypot(b.1));
        assert!(
            (cos - (-0.5)).abs() < 1e-4,
            "axes {i}, {}: cos {cos}",
            (i + 1) % 3
        );
    }
}
