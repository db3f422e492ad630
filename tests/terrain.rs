//! Midpoint displacement: reproducible per seed, each level's displacement N(0, σrʲ) as
//! measured from the heights, and the roughness's meaning (the variance of differences at
//! lag 2ʲ) against the lecture's algorithm run in f64 with its own normal variates; the
//! pictures; bad input.

#![allow(clippy::needless_range_loop)]

mod common;

use std::f64::consts::FRAC_1_SQRT_2;

use common::{Counting, Frame};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use tinyfractal::{
    error::{FitError, ParameterError},
    terrain::Displacement,
    Error, Real, Terrain, TerrainMap,
};

fn real(value: f64) -> Real {
    Real::from_f64(value).unwrap()
}

fn displacement(roughness: f64, sigma: f64, seed: u64) -> Displacement {
    Displacement {
        roughness: real(roughness),
        sigma: real(sigma),
        seed,
    }
}

fn profile(samples: u32, roughness: f64, sigma: f64, seed: u64) -> Vec<f64> {
    Terrain::new(samples, displacement(roughness, sigma, seed))
        .heights()
        .unwrap()
        .map(Real::to_f64)
        .collect()
}

/// SplitMix64 and Box–Muller: the test's own normal variates.
struct Normals(u64);

impl Normals {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform().max(1e-300), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// The lecture's algorithm in f64: a[mid] = (a[0] + a[last])/2 + N(0, σ), σ *= r.
fn lecture_profile(levels: u32, roughness: f64, sigma: f64, normals: &mut Normals) -> Vec<f64> {
    let n = (1usize << levels) + 1;
    let mut a = vec![0.0; n];
    let mut step = n - 1;
    let mut s = sigma;
    while step > 1 {
        for left in (0..n - 1).step_by(step) {
            a[left + step / 2] = (a[left] + a[left + step]) / 2.0 + s * normals.normal();
        }
        s *= roughness;
        step /= 2;
    }
    a
}

/// Mean squared difference at each lag 2^j, j = 0..levels.
fn structure(profiles: &[Vec<f64>], levels: u32) -> Vec<f64> {
    (0..levels)
        .map(|j| {
            let lag = 1 << j;
            let (mut sum, mut count) = (0.0, 0.0);
            for p in profiles {
                for i in 0..p.len() - lag {
                    sum += (p[i + lag] - p[i]).powi(2);
                    count += 1.0;
                }
            }
            sum / count
        })
        .collect()
}

#[test]
fn profiles_are_reproducible_per_seed_with_fixed_ends() {
    let a = profile(1025, 0.7, 10.0, 42);
    assert_eq!(a, profile(1025, 0.7, 10.0, 42));
    assert_ne!(a, profile(1025, 0.7, 10.0, 43));
    assert_eq!(a.len(), 1025);
    assert_eq!((a[0], a[1024]), (0.0, 0.0));
    let ends = Terrain::new(9, displacement(0.5, 1.0, 1))
        .with_ends(Real::from_int(-3), Real::from_int(5))
        .heights()
        .unwrap()
        .map(Real::to_f64)
        .collect::<Vec<_>>();
    assert_eq!((ends[0], ends[8]), (-3.0, 5.0));
    // σ = 0: the straight line between the ends.
    let line: Vec<f64> = Terrain::new(9, displacement(0.5, 0.0, 1))
        .with_ends(Real::ZERO, Real::from_int(8))
        .heights()
        .unwrap()
        .map(Real::to_f64)
        .collect();
    assert_eq!(line, (0..9).map(f64::from).collect::<Vec<_>>());
}

#[test]
fn each_level_displaces_its_midpoints_by_sigma_r_to_the_level() {
    // From the heights alone: a midpoint of level j minus the mean of its interval's ends
    // is N(0, σ·r^j): its variance over many seeds.
    let (levels, roughness, sigma) = (6u32, 0.6, 4.0);
    let mut sums = vec![(0.0, 0.0); levels as usize];
    for seed in 0..400 {
        let p = profile((1 << levels) + 1, roughness, sigma, seed);
        for j in 0..levels as usize {
            let step = 1usize << (levels as usize - j);
            for left in (0..p.len() - 1).step_by(step) {
                let d = p[left + step / 2] - (p[left] + p[left + step]) / 2.0;
                sums[j].0 += d * d;
                sums[j].1 += 1.0;
            }
        }
    }
    for (j, (sum, count)) in sums.iter().enumerate() {
        let expected = (sigma * roughness.powi(j as i32)).powi(2);
        let measured = sum / count;
        // 400 draws at the first level: about ±7 % (2 standard errors); more below.
        assert!(
            (measured / expected - 1.0).abs() < 0.15,
            "level {j}: variance {measured}, expected {expected}"
        );
    }
}

#[test]
fn roughness_means_what_the_lecture_says() {
    // The variance of height differences at lag 2^j, ours against the lecture's
    // algorithm in f64 with Box–Muller normals, over 300 seeds of 1025 samples each.
    let levels = 10;
    for roughness in [0.5, 0.6, FRAC_1_SQRT_2, 0.8, 1.0] {
        let ours: Vec<Vec<f64>> = (0..300)
            .map(|seed| profile((1 << levels) + 1, roughness, 8.0, seed))
            .collect();
        let mut normals = Normals(roughness.to_bits());
        let model: Vec<Vec<f64>> = (0..300)
            .map(|_| lecture_profile(levels, roughness, 8.0, &mut normals))
            .collect();
        let (s_ours, s_model) = (structure(&ours, levels), structure(&model, levels));
        for j in 0..levels as usize - 1 {
            let ratio = s_ours[j] / s_model[j];
            assert!(
                (ratio - 1.0).abs() < 0.12,
                "r = {roughness}, lag 2^{j}: {} vs model {}",
                s_ours[j],
                s_model[j]
            );
        }
        // And at r = 1/√2 the slope of log2 S against j is 2H = 1 (Brownian motion) over
        // the lags the recursion has refined many times.
        if roughness == FRAC_1_SQRT_2 {
            let slope = (s_ours[6].log2() - s_ours[1].log2()) / 5.0;
            assert!((slope - 1.0).abs() < 0.1, "Brownian slope {slope}");
        }
    }
}

#[test]
fn the_profile_fills_its_area_once_from_lowest_to_highest() {
    // More samples than columns, fewer, and one a column (a loop of its own), at σ = 10
    // (a row's numerator in 32 bits) and 200 (in 64); each profile fitted with its
    // heights generated twice and kept in a buffer.
    let cases = [
        (1025, 300, 10.0),
        (33, 300, 10.0),
        (257, 257, 10.0),
        (129, 128, 10.0),
        (65, 64, 10.0),
        (3, 2, 10.0),
        (257, 100, 200.0),
        (129, 128, 200.0),
    ];
    let both = |case| [(case, false), (case, true)];
    for ((samples, width, sigma), stored) in cases.into_iter().flat_map(both) {
        let size = Size::new(width, 120);
        let mut frame = Counting::new(Frame::filled(size, Rgb888::RED));
        let terrain = Terrain::new(samples, displacement(0.7, sigma, 5));
        let mut buffer = vec![0; samples as usize + 3];
        let area = frame.bounding_box();
        let drawing = if stored {
            terrain.fit_with_heights(area, Rgb888::GREEN, Rgb888::BLUE, &mut buffer)
        } else {
            terrain.fit(area, Rgb888::GREEN, Rgb888::BLUE)
        }
        .unwrap();
        assert_eq!(drawing.draw(&mut frame).unwrap(), u64::from(samples));
        assert_eq!(frame.run_pixels, (width * 120) as usize);
        assert_eq!(frame.fill_solid_calls, 2 * width as usize);
        let frame = frame.inner;
        assert!(!frame.pixels.contains(&Rgb888::RED));
        // The highest sample reaches the top row, the lowest leaves ground on the bottom
        // row everywhere.
        assert!((0..width as i32).any(|x| frame.pixel(x, 0) == Some(Rgb888::GREEN)));
        assert!((0..width as i32).all(|x| frame.pixel(x, 119) == Some(Rgb888::GREEN)));
        // Each column: sky, then ground, no sky below ground, from the row of the highest
        // point of the piecewise-linear profile over the column (heights as Q16.16
        // integers in f64, quotients truncated, the row rounded half up).
        let q16 = |h: Real| h.to_f64() * 65536.0;
        let heights: Vec<f64> = terrain.heights().unwrap().map(q16).collect();
        let (low, high) = (q16(drawing.range().0), q16(drawing.range().1));
        let (w, last) = (f64::from(width), f64::from(samples - 2));
        let at = |p: f64| {
            let k = (p / w).floor().min(last);
            let (a, b) = (heights[k as usize], heights[k as usize + 1]);
            a + ((b - a) * (p - k * w) / w).trunc()
        };
        let rows = 119.0;
        let row = |h: f64| ((high - h) * rows + ((high - low) / 2.0).floor()) / (high - low);
        for x in 0..width as i32 {
            let column: Vec<_> = (0..120).map(|y| frame.pixel(x, y).unwrap()).collect();
            let ground = column.iter().position(|&c| c == Rgb888::GREEN).unwrap();
            assert!(column[ground..].iter().all(|&c| c == Rgb888::GREEN));
            let intervals = f64::from(samples - 1);
            let (from, to) = (f64::from(x) * intervals, f64::from(x + 1) * intervals);
            let inside = (0..samples as usize)
                .filter(|&i| i as f64 * w > from && i as f64 * w <= to)
                .map(|i| heights[i]);
            let highest = inside.fold(at(from).max(at(to)), f64::max);
            assert_eq!(
                ground,
                row(highest).floor() as usize,
                "{samples} {width} {stored}: {x}"
            );
        }
    }
}

/// Diamond-square in f64, as the crate documents it (square step averaging the 3 or 4
/// neighbours there are), with the test's own normals.
fn lecture_map(levels: u32, roughness: f64, sigma: f64, normals: &mut Normals) -> Vec<Vec<f64>> {
    let n = (1usize << levels) + 1;
    let last = n - 1;
    let mut a = vec![vec![0.0; n]; n];
    for (x, y) in [(0, 0), (last, 0), (0, last), (last, last)] {
        a[y][x] = sigma * normals.normal();
    }
    let (mut step, mut s) = (last, sigma);
    while step > 1 {
        let half = step / 2;
        for y in (half..last).step_by(step) {
            for x in (half..last).step_by(step) {
                let mean = (a[y - half][x - half]
                    + a[y - half][x + half]
                    + a[y + half][x - half]
                    + a[y + half][x + half])
                    / 4.0;
                a[y][x] = mean + s * normals.normal();
            }
        }
        for y in (0..n).step_by(half) {
            let start = if (y / half) % 2 == 0 { half } else { 0 };
            for x in (start..n).step_by(step) {
                let mut values = Vec::new();
                if x >= half {
                    values.push(a[y][x - half]);
                }
                if x + half < n {
                    values.push(a[y][x + half]);
                }
                if y >= half {
                    values.push(a[y - half][x]);
                }
                if y + half < n {
                    values.push(a[y + half][x]);
                }
                a[y][x] = values.iter().sum::<f64>() / values.len() as f64 + s * normals.normal();
            }
        }
        s *= roughness;
        step = half;
    }
    a
}

fn map(samples: u32, roughness: f64, seed: u64, wrap: bool) -> Vec<Vec<f64>> {
    let terrain = TerrainMap::new(samples, displacement(roughness, 8.0, seed)).wrapped(wrap);
    let mut heights = vec![0; terrain.cells()];
    terrain.generate(&mut heights).unwrap();
    heights
        .chunks(samples as usize)
        .map(|row| row.iter().map(|&h| f64::from(h) / 65536.0).collect())
        .collect()
}

#[test]
fn landscapes_match_diamond_square_in_f64_statistically() {
    let levels = 6;
    let samples = (1 << levels) + 1;
    for roughness in [0.5, FRAC_1_SQRT_2, 0.9] {
        let ours: Vec<Vec<f64>> = (0..150)
            .flat_map(|seed| map(samples, roughness, seed, false))
            .collect();
        let mut normals = Normals(7 + roughness.to_bits());
        let model: Vec<Vec<f64>> = (0..150)
            .flat_map(|_| lecture_map(levels, roughness, 8.0, &mut normals))
            .collect();
        // Along rows: differences at lag 2^j.
        let (s_ours, s_model) = (structure(&ours, levels), structure(&model, levels));
        for j in 0..levels as usize - 1 {
            let ratio = s_ours[j] / s_model[j];
            assert!(
                (ratio - 1.0).abs() < 0.15,
                "r = {roughness}, lag 2^{j}: ratio {ratio}"
            );
        }
    }
}

#[test]
fn landscapes_reproduce_and_wrapped_ones_tile() {
    assert_eq!(map(33, 0.7, 3, false), map(33, 0.7, 3, false));
    assert_ne!(map(33, 0.7, 3, false), map(33, 0.7, 4, false));
    let tiled = map(33, 0.7, 3, true);
    for i in 0..33 {
        assert_eq!(tiled[0][i], tiled[32][i]);
        assert_eq!(tiled[i][0], tiled[i][32]);
    }
    // Drawn: one fill_contiguous for the whole area.
    let terrain = TerrainMap::new(65, displacement(0.6, 20.0, 9));
    let mut heights = vec![0; terrain.cells()];
    let mut frame = Counting::new(Frame::filled(Size::new(160, 100), Rgb888::RED));
    let drawing = terrain.fit(frame.bounding_box(), &mut heights).unwrap();
    assert_eq!(drawing.draw(&mut frame).unwrap(), 65 * 65);
    assert_eq!(
        (
            frame.fill_contiguous_calls,
            frame.fill_solid_calls,
            frame.draw_iter_pixels
        ),
        (1, 0, 0)
    );
    assert!(!frame.inner.pixels.contains(&Rgb888::RED));
}

/// Heights generated into a buffer a level at a time are the iterator's, generated depth
/// first, for any seed, size, roughness and ends; the buffer past them is untouched.
#[test]
fn stored_heights_are_the_iterators() {
    let mut random = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        random ^= random << 13;
        random ^= random >> 7;
        random ^= random << 17;
        random
    };
    for _ in 0..200 {
        let samples = (1 << (1 + next() % 11)) + 1;
        let roughness = 0.05 + (next() % 95) as f64 / 100.0;
        let sigma = (next() % 2000) as f64 / 10.0;
        let ends = [0, 1].map(|_| Real::from_int((next() % 2001) as i32 - 1000));
        let terrain = Terrain::new(samples as u32, displacement(roughness, sigma, next()))
            .with_ends(ends[0], ends[1]);
        let mut buffer = vec![7; samples + 5];
        let area = Rectangle::new(Point::zero(), Size::new(100, 50));
        let drawing = terrain
            .fit_with_heights(area, Rgb888::GREEN, Rgb888::BLUE, &mut buffer)
            .unwrap();
        let range = drawing.range();
        let expected: Vec<i32> = terrain.heights().unwrap().raw().collect();
        assert_eq!(buffer[..samples], expected[..]);
        assert!(buffer[samples..].iter().all(|&h| h == 7));
        let real = |h: i32| Real::from_bits(i64::from(h) << 16);
        let low = expected.iter().copied().min().map(real);
        let high = expected.iter().copied().max().map(real);
        assert_eq!((Some(range.0), Some(range.1)), (low, high));
    }
}

#[test]
fn bad_parameters_are_typed_errors() {
    let parameter = |result: Result<Vec<Real>, Error>| match result {
        Err(Error::Parameter(error)) => error,
        other => panic!("expected a parameter error, got {other:?}"),
    };
    let heights = |samples, roughness, sigma| {
        Terrain::new(samples, displacement(roughness, sigma, 1))
            .heights()
            .map(Iterator::collect)
    };
    assert!(matches!(
        parameter(heights(9, 0.0, 1.0)),
        ParameterError::RoughnessOutOfRange { .. }
    ));
    assert!(matches!(
        parameter(heights(9, 1.5, 1.0)),
        ParameterError::RoughnessOutOfRange { .. }
    ));
    assert!(matches!(
        parameter(heights(9, 0.5, -1.0)),
        ParameterError::SigmaOutOfRange { .. }
    ));
    assert!(matches!(
        parameter(heights(9, 0.5, 300.0)),
        ParameterError::SigmaOutOfRange { .. }
    ));
    assert_eq!(
        parameter(heights(1000, 0.5, 1.0)),
        ParameterError::SamplesNotPowerOfTwoPlusOne { samples: 1000 }
    );
    assert_eq!(
        parameter(heights(0, 0.5, 1.0)),
        ParameterError::SamplesNotPowerOfTwoPlusOne { samples: 0 }
    );
    assert_eq!(
        parameter(heights((1 << 17) + 1, 0.5, 1.0)),
        ParameterError::TooManySamples {
            samples: (1 << 17) + 1,
            max: (1 << 16) + 1
        }
    );
    let end =
        Terrain::new(9, displacement(0.5, 1.0, 1)).with_ends(Real::from_int(5000), Real::ZERO);
    assert!(matches!(
        end.heights().map(|_| ()),
        Err(Error::Parameter(ParameterError::EndOutOfRange { .. }))
    ));
    let message = parameter(heights(9, 1.5, 1.0)).to_string();
    assert!(message.contains("(0, 1]"), "{message}");
    // A buffer too small for the landscape, and a zero-size area.
    let terrain = TerrainMap::new(17, displacement(0.5, 1.0, 1));
    assert_eq!(
        terrain.generate(&mut [0; 100]),
        Err(Error::Fit(FitError::BufferTooSmall {
            needed: 289,
            given: 100
        }))
    );
    // A profile's buffer too small, and a bad parameter before it.
    let area = Rectangle::new(Point::zero(), Size::new(10, 5));
    assert_eq!(
        Terrain::new(33, displacement(0.5, 1.0, 1))
            .fit_with_heights(area, Rgb888::GREEN, Rgb888::BLUE, &mut [0; 32])
            .map(|_| ()),
        Err(Error::Fit(FitError::BufferTooSmall {
            needed: 33,
            given: 32
        }))
    );
    assert!(matches!(
        Terrain::new(32, displacement(0.5, 1.0, 1))
            .fit_with_heights(area, Rgb888::GREEN, Rgb888::BLUE, &mut [0; 40])
            .map(|_| ()),
        Err(Error::Parameter(
            ParameterError::SamplesNotPowerOfTwoPlusOne { samples: 32 }
        ))
    ));
    let zero = Rectangle::new(Point::zero(), Size::new(0, 5));
    assert!(Terrain::new(9, displacement(0.5, 1.0, 1))
        .fit(zero, Rgb888::GREEN, Rgb888::BLUE)
        .is_err());
}

#[test]
fn memory_is_as_the_readme_states() {
    use embedded_graphics::pixelcolor::Rgb565;
    use std::mem::size_of;
    use tinyfractal::{
        subdivision::{CarpetDrawing, CubeDrawing, GasketDrawing},
        terrain::Heights,
    };
    assert!(size_of::<Heights>() < 400, "{}", size_of::<Heights>());
    assert!(size_of::<CarpetDrawing<Rgb565>>() < 200);
    assert!(size_of::<GasketDrawing<Rgb565>>() < 200);
    assert!(
        size_of::<CubeDrawing<Rgb565>>() < 200,
        "{}",
        size_of::<CubeDrawing<Rgb565>>()
    );
}
