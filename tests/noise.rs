//! Perlin noise against his published values and an f64 model of his 2002 code written
//! here: exact where f64 computes exactly, within 2⁻²⁰ elsewhere; the fractal sums against
//! f64 sums of the model.

use tinyfractal::{
    error::ParameterError,
    noise::{Octaves, Perlin, Sum, MAX_OCTAVES},
    Error, Real,
};

/// Perlin's improved noise as he wrote it (Java, 2002), in f64, over a permutation `p`.
fn model(p: &[u8; 256], x: f64, y: f64, z: f64) -> f64 {
    let perm = |i: i64| i64::from(p[(i & 255) as usize]);
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
    let grad = |hash: i64, x: f64, y: f64, z: f64| {
        let h = hash & 15;
        let u = if h < 8 { x } else { y };
        let v = if h < 4 {
            y
        } else if h == 12 || h == 14 {
            x
        } else {
            z
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    };
    let (fx, fy, fz) = (x.floor(), y.floor(), z.floor());
    let (xi, yi, zi) = (fx as i64, fy as i64, fz as i64);
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let a = perm(xi) + yi;
    let (aa, ab) = (perm(a) + zi, perm(a + 1) + zi);
    let b = perm(xi + 1) + yi;
    let (ba, bb) = (perm(b) + zi, perm(b + 1) + zi);
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(perm(aa), x, y, z), grad(perm(ba), x - 1.0, y, z)),
            lerp(
                u,
                grad(perm(ab), x, y - 1.0, z),
                grad(perm(bb), x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                grad(perm(aa + 1), x, y, z - 1.0),
                grad(perm(ba + 1), x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                grad(perm(ab + 1), x, y - 1.0, z - 1.0),
                grad(perm(bb + 1), x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}

fn real(value: f64) -> Real {
    Real::from_f64(value).unwrap()
}

/// How far from the model a sample may be where f64 rounds: 2⁻²⁰.
const TOLERANCE: f64 = 1.0 / (1u32 << 20) as f64;

/// A small deterministic stream of points (xorshift64), independent of the crate's.
fn points(count: usize, span: f64) -> impl Iterator<Item = (f64, f64, f64)> {
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 * span - span
    };
    (0..count).map(move |_| (next(), next(), next()))
}

#[test]
fn the_published_values() {
    let noise = Perlin::reference();
    let close = |got: f64, published: f64| {
        assert!(
            (got - published).abs() <= TOLERANCE,
            "{got} is not {published}"
        )
    };
    // 3.14 as Perlin's example writes it, not π.
    let x = Real::parse_signed("3.14").unwrap();
    close(
        noise.noise3(x, real(42.0), real(7.0)).to_f64(),
        0.136_919_958_784_000_12,
    );
    close(
        noise.noise3(real(-4.2), real(10.0), real(6.0)).to_f64(),
        0.142_08,
    );
    assert_eq!(
        noise.noise3(real(0.5), real(0.5), real(0.5)).to_f64(),
        -0.25
    );
}

#[test]
fn exact_where_f64_is_exact() {
    let noise = Perlin::reference();
    let p = noise.permutation();
    // 2D at multiples of ¼ and 3D at multiples of ½, across cells and signs.
    for i in -40..40 {
        for j in -40..40 {
            let (x, y) = (f64::from(i) / 4.0, f64::from(j) / 4.0);
            assert_eq!(
                noise.noise2(real(x), real(y)).to_f64(),
                model(p, x, y, 0.0),
                "({x}, {y})"
            );
        }
    }
    for i in -12..12 {
        for j in -12..12 {
            for k in -12..12 {
                let (x, y, z) = (f64::from(i) / 2.0, f64::from(j) / 2.0, f64::from(k) / 2.0);
                assert_eq!(
                    noise.noise3(real(x), real(y), real(z)).to_f64(),
                    model(p, x, y, z),
                    "({x}, {y}, {z})"
                );
            }
        }
    }
}

#[test]
fn within_two_to_the_minus_twenty_everywhere() {
    for seed in [0, 1, 7] {
        let noise = Perlin::seeded(seed);
        let p = noise.permutation();
        let mut worst: f64 = 0.0;
        for (x, y, z) in points(20_000, 300.0) {
            let three = noise.noise3(real(x), real(y), real(z)).to_f64();
            let two = noise.noise2(real(x), real(y)).to_f64();
            worst = worst
                .max((three - model(p, x, y, z)).abs())
                .max((two - model(p, x, y, 0.0)).abs());
        }
        assert!(worst <= TOLERANCE, "seed {seed}: off by {worst}");
    }
}

/// Noise repeats every 256 cells (the permutation sees a cell modulo 256), so the ends of
/// `Real`'s range sample as cells 255 and 0 do, with no overflow on the way.
#[test]
fn the_ends_of_the_range_wrap_as_the_lattice_does() {
    let noise = Perlin::seeded(9);
    let (top, bottom) = (real(2_147_483_647.5), real(-2_147_483_647.75));
    let (y, z) = (real(0.3), real(0.6));
    assert_eq!(noise.noise2(top, y), noise.noise2(real(255.5), y));
    assert_eq!(noise.noise3(y, top, z), noise.noise3(y, real(255.5), z));
    assert_eq!(noise.noise3(y, z, bottom), noise.noise3(y, z, real(0.25)));
    // Rounding to 2⁻²⁴ past the largest coordinate wraps to cell 0 (2³¹ is 0 modulo 256).
    let last = Real::from_bits(i64::MAX);
    assert_eq!(noise.noise2(last, y), noise.noise2(Real::ZERO, y));
}

#[test]
fn seeds_shuffle_perlins_permutation() {
    assert_eq!(Perlin::seeded(0), Perlin::reference());
    let mut seen = [false; 256];
    for &value in Perlin::reference().permutation() {
        seen[usize::from(value)] = true;
    }
    assert!(
        seen.iter().all(|&seen| seen),
        "the reference is a permutation"
    );
    for seed in [1, 2, 0xFFFF_FFFF] {
        let shuffled = Perlin::seeded(seed);
        let mut sorted = *shuffled.permutation();
        sorted.sort_unstable();
        assert!(sorted.iter().enumerate().all(|(i, &v)| usize::from(v) == i));
        assert_ne!(shuffled, Perlin::reference(), "seed {seed}");
        assert_eq!(
            shuffled,
            Perlin::seeded(seed),
            "seed {seed} is deterministic"
        );
    }
    assert_ne!(Perlin::seeded(1), Perlin::seeded(2));
}

/// The f64 sum of the model's octaves, as `Octaves::sum` documents it.
fn model_sum(p: &[u8; 256], octaves: &Octaves, sum: Sum, (x, y, z): (f64, f64, f64)) -> f64 {
    let (persistence, lacunarity) = (octaves.persistence.to_f64(), octaves.lacunarity.to_f64());
    let (mut total, mut amplitude, mut frequency, mut weight) = (0.0, 1.0, 1.0, 1.0);
    for _ in 0..octaves.octaves {
        let value = model(p, x * frequency, y * frequency, z * frequency);
        total += amplitude
            * match sum {
                Sum::Fbm => value,
                Sum::Turbulence => value.abs(),
                Sum::Ridged => {
                    let signal = (1.0 - value.abs()).powi(2);
                    let term = signal * weight;
                    weight = (signal * 2.0).clamp(0.0, 1.0);
                    term
                }
            };
        amplitude *= persistence;
        frequency *= lacunarity;
    }
    total
}

#[test]
fn fractal_sums_follow_an_f64_sum() {
    let noise = Perlin::seeded(3);
    let p = noise.permutation();
    // The usual octaves (summed in 64-bit integers in the plane), and others (the general
    // path, in `Real`).
    let other = Octaves {
        octaves: 5,
        persistence: real(0.625),
        lacunarity: real(1.875),
    };
    for (octaves, sum) in [Octaves::default(), other]
        .into_iter()
        .flat_map(|o| [Sum::Fbm, Sum::Turbulence, Sum::Ridged].map(|s| (o, s)))
    {
        for (x, y, z) in points(2_000, 4.0) {
            let got = octaves
                .sum(&noise, sum, (real(x), real(y), Some(real(z))))
                .unwrap()
                .to_f64();
            let flat = octaves
                .sum(&noise, sum, (real(x), real(y), None))
                .unwrap()
                .to_f64();
            let want = model_sum(p, &octaves, sum, (x, y, z));
            let want_flat = model_sum(p, &octaves, sum, (x, y, 0.0));
            // Six octaves of 2⁻²⁰ each (the ridge squares: twice), and Real's rounding.
            let tolerance = 16.0 * TOLERANCE;
            assert!(
                (got - want).abs() <= tolerance,
                "{sum:?} at ({x}, {y}, {z})"
            );
            assert!(
                (flat - want_flat).abs() <= tolerance,
                "{sum:?} at ({x}, {y})"
            );
        }
    }
}

#[test]
fn octaves_out_of_range_are_typed_errors() {
    let noise = Perlin::reference();
    let at = (Real::ZERO, Real::ZERO, None);
    let with = |octaves: u32, persistence: f64, lacunarity: f64| {
        Octaves {
            octaves,
            persistence: real(persistence),
            lacunarity: real(lacunarity),
        }
        .sum(&noise, Sum::Fbm, at)
    };
    assert_eq!(
        with(0, 0.5, 2.0),
        Err(Error::Parameter(ParameterError::OctavesOutOfRange {
            octaves: 0,
            max: MAX_OCTAVES
        }))
    );
    assert!(matches!(
        with(MAX_OCTAVES + 1, 0.5, 2.0),
        Err(Error::Parameter(ParameterError::OctavesOutOfRange { .. }))
    ));
    assert!(matches!(
        with(4, 1.5, 2.0),
        Err(Error::Parameter(
            ParameterError::PersistenceOutOfRange { .. }
        ))
    ));
    assert!(matches!(
        with(4, 0.5, 0.5),
        Err(Error::Parameter(
            ParameterError::LacunarityOutOfRange { .. }
        ))
    ));
    assert!(with(MAX_OCTAVES, 1.0, 4.0).is_ok());
    // Coordinates a fine octave takes past Real's range: an overflow, not a wrapped value.
    let far = Octaves {
        octaves: MAX_OCTAVES,
        persistence: real(0.5),
        lacunarity: real(4.0),
    };
    assert!(matches!(
        far.sum(&noise, Sum::Fbm, (real(1.0e6), Real::ZERO, None)),
        Err(Error::Parameter(ParameterError::NoiseOutOfRange))
    ));
}

mod textures {
    use super::{model, model_sum, points, real};
    use embedded_graphics::{
        mock_display::MockDisplay, pixelcolor::Gray8, prelude::*, primitives::Rectangle,
    };
    use tinyfractal::{
        error::{FitError, ParameterError},
        noise::{NoiseTexture, Octaves, Perlin, Sum, Texture},
        render::Palette,
        Error, Real,
    };

    /// Every texture.
    const TEXTURES: [Texture; 7] = [
        Texture::Perlin,
        Texture::Fbm,
        Texture::Clouds,
        Texture::Turbulence,
        Texture::Ridged,
        Texture::Marble,
        Texture::Wood,
    ];

    /// Each texture's value in [0, 1] as its documentation states it, from the f64 model.
    fn model_value(p: &[u8; 256], texture: Texture, octaves: &Octaves, (x, y): (f64, f64)) -> f64 {
        let amplitudes: f64 = (0..octaves.octaves)
            .map(|i| octaves.persistence.to_f64().powi(i as i32))
            .sum();
        let sum = |sum: Sum| model_sum(p, octaves, sum, (x, y, 0.0)) / amplitudes;
        let centred = |value: f64| ((value + 1.0) / 2.0).clamp(0.0, 1.0);
        match texture {
            Texture::Perlin => centred(model(p, x, y, 0.0)),
            Texture::Fbm | Texture::Clouds => centred(sum(Sum::Fbm)),
            Texture::Turbulence => sum(Sum::Turbulence).clamp(0.0, 1.0),
            Texture::Ridged => sum(Sum::Ridged).clamp(0.0, 1.0),
            Texture::Marble => {
                let turbulence = model_sum(p, octaves, Sum::Turbulence, (x, y, 0.0));
                (1.0 + (2.0 * std::f64::consts::PI * (x + turbulence / 4.0)).sin()) / 2.0
            }
            Texture::Wood => (8.0 * (model(p, x, y, 0.0) + 1.0)).fract(),
        }
    }

    #[test]
    fn values_follow_the_documented_formulas() {
        let noise = Perlin::seeded(11);
        let p = noise.permutation();
        let octaves = Octaves::default();
        for texture in TEXTURES {
            for (x, y, _) in points(1_000, 6.0) {
                let got = texture
                    .value(&noise, &octaves, (real(x), real(y), None))
                    .unwrap()
                    .to_f64();
                let want = model_value(p, texture, &octaves, (x, y));
                // Wood's fraction wraps: compare around the circle.
                let off = (got - want).abs();
                let off = if texture == Texture::Wood {
                    off.min(1.0 - off)
                } else {
                    off
                };
                assert!(
                    off < 1e-5,
                    "{texture:?} at ({x}, {y}): {got} against {want}"
                );
                assert!((0.0..=1.0).contains(&got), "{texture:?}: {got}");
            }
        }
    }

    /// Level `l` in grey `l`.
    struct Levels;

    impl Palette for Levels {
        type Color = Gray8;

        fn color(&self, value: u16, _max: u16) -> Gray8 {
            Gray8::new(value as u8)
        }
    }

    #[test]
    fn a_drawing_covers_its_area_once_with_each_pixels_level() {
        let noise = Perlin::reference();
        let p = noise.permutation();
        // Every texture: those a drawing sums a block of columns at a time (the plane at
        // lacunarity 2, two blocks and a part of one across) and those it takes point by
        // point (ridged), each pixel the level its point has.
        for kind in TEXTURES {
            let texture = NoiseTexture::new(&noise, kind).with_scale(real(3.0));
            let area = Rectangle::new(Point::zero(), Size::new(48, 32));
            let drawing = texture.fit(area, Levels).unwrap();
            let mut display = MockDisplay::<Gray8>::new();
            drawing.draw(&mut display).unwrap();
            for y in 0..32 {
                for x in 0..48 {
                    let level = drawing.level_at(x, y);
                    assert_eq!(
                        display.get_pixel(Point::new(x as i32, y as i32)),
                        Some(Gray8::new(level)),
                        "{kind:?} ({x}, {y})"
                    );
                    // Pixel (x, y) samples its top-left corner, scale / width units a pixel.
                    let at = (3.0 * f64::from(x) / 48.0, 3.0 * f64::from(y) / 48.0);
                    let want = model_value(p, kind, &Octaves::default(), at) * 255.0;
                    assert!(
                        (f64::from(level) - want).abs() <= 0.51,
                        "{kind:?} ({x}, {y})"
                    );
                }
            }
        }
    }

    /// Octaves of every weight (eighths, powers of two, others), 3D and an area away from
    /// the origin: the drawing is its points' levels.
    #[test]
    fn drawings_of_any_octaves_are_their_points_levels() {
        let noise = Perlin::seeded(3);
        let settings = [
            (6, 0.5, 2.0, None),
            (9, 0.37, 2.0, None),
            (3, 1.0, 2.0, None),
            (4, 0.5, 2.5, None),
            (5, 0.5, 2.0, Some(0.75)),
        ];
        for (octaves, persistence, lacunarity, z) in settings {
            let octaves = Octaves {
                octaves,
                persistence: real(persistence),
                lacunarity: real(lacunarity),
            };
            for kind in [Texture::Fbm, Texture::Turbulence, Texture::Marble] {
                let mut texture = NoiseTexture::new(&noise, kind)
                    .with_octaves(octaves)
                    .with_scale(real(5.5));
                if let Some(z) = z {
                    texture = texture.with_z(real(z));
                }
                let area = Rectangle::new(Point::new(3, 5), Size::new(57, 20));
                let drawing = texture.fit(area, Levels).unwrap();
                let mut display = MockDisplay::<Gray8>::new();
                drawing.draw(&mut display).unwrap();
                for y in 0..20 {
                    for x in 0..57 {
                        assert_eq!(
                            display.get_pixel(Point::new(3 + x as i32, 5 + y as i32)),
                            Some(Gray8::new(drawing.level_at(x, y))),
                            "{kind:?} {octaves:?} {z:?} ({x}, {y})"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn bad_textures_are_typed_errors() {
        let noise = Perlin::reference();
        let area = Rectangle::new(Point::zero(), Size::new(16, 16));
        let texture = NoiseTexture::new(&noise, Texture::Fbm);
        assert!(matches!(
            texture.clone().with_scale(Real::ZERO).fit(area, Levels),
            Err(Error::Parameter(ParameterError::ScaleNotPositive { .. }))
        ));
        assert!(matches!(
            texture.clone().fit(Rectangle::zero(), Levels),
            Err(Error::Fit(FitError::ZeroSizeTarget))
        ));
        let too_many = Octaves {
            octaves: 40,
            ..Octaves::default()
        };
        assert!(matches!(
            texture.clone().with_octaves(too_many).fit(area, Levels),
            Err(Error::Parameter(ParameterError::OctavesOutOfRange { .. }))
        ));
        // A picture whose finest octave leaves Real's range is refused before drawing.
        let fine = Octaves {
            octaves: 16,
            persistence: real(0.5),
            lacunarity: real(4.0),
        };
        assert!(matches!(
            texture
                .with_octaves(fine)
                .with_scale(real(1000.0))
                .fit(area, Levels),
            Err(Error::Parameter(ParameterError::NoiseOutOfRange))
        ));
    }
}

/// A noise landscape's heights are the fBm of the model at its grid points, (scale·i/n,
/// scale·j/n), in Q16.16 rounded down.
#[test]
fn noise_terrain_heights_are_the_model_fbm() {
    use tinyfractal::noise::NoiseTerrain;
    let noise = Perlin::seeded(5);
    let p = noise.permutation();
    let n = 33;
    let terrain = NoiseTerrain::new(&noise, n).with_scale(real(3.0));
    let mut heights = vec![0i32; terrain.cells()];
    terrain.generate(&mut heights).unwrap();
    for j in 0..n {
        for i in 0..n {
            let at = |k: u32| f64::from(k) * 3.0 / f64::from(n);
            let want = model_sum(p, &Octaves::default(), Sum::Fbm, (at(i), at(j), 0.0));
            let got = f64::from(heights[(j * n + i) as usize]) / 65536.0;
            assert!(
                (got - want).abs() <= 2.0 / 65536.0,
                "({i}, {j}): {got} against {want}"
            );
        }
    }
    // Too small a buffer, a side out of range, a scale not positive: typed errors.
    assert!(matches!(
        terrain.generate(&mut heights[..10]),
        Err(Error::Fit(tinyfractal::error::FitError::BufferTooSmall {
            needed: 1089,
            given: 10
        }))
    ));
    assert!(matches!(
        NoiseTerrain::new(&noise, 1).generate(&mut heights),
        Err(Error::Parameter(ParameterError::GridOutOfRange { .. }))
    ));
    assert!(matches!(
        terrain.with_scale(Real::ZERO).generate(&mut heights),
        Err(Error::Parameter(ParameterError::ScaleNotPositive { .. }))
    ));
    // A landscape whose finest octave leaves the range, at its far corner only or
    // everywhere: the range's error, not a wrapped height.
    let fine = Octaves {
        octaves: 16,
        ..Octaves::default()
    };
    for scale in [2.0e5, 1.0e9] {
        assert!(matches!(
            terrain
                .with_octaves(fine)
                .with_scale(real(scale))
                .generate(&mut heights),
            Err(Error::Parameter(ParameterError::NoiseOutOfRange))
        ));
    }
}
