//! Reaction–diffusion against theory and an f64 model of the same equations written here.

use proptest::prelude::*;
use tinyfractal::error::{Error, FitError, ParameterError};
use tinyfractal::reaction::{Cell, GrayScott, Preset, Reaction, Start, ONE};
use tinyfractal::Real;

fn real(text: &str) -> Real {
    Real::parse_signed(text).unwrap()
}

/// A grid of `w × h` cells and its ring, owned together for a test.
struct Grid {
    size: (u32, u32),
    cells: Vec<Cell>,
    ring: Vec<Cell>,
}

impl Grid {
    fn new(w: u32, h: u32) -> Self {
        Self {
            size: (w, h),
            cells: vec![Cell::REST; (w * h) as usize],
            ring: vec![Cell::REST; Reaction::ring_len(w)],
        }
    }

    fn reaction(&mut self, model: &GrayScott) -> Reaction<'_> {
        Reaction::new(model, self.size, &mut self.cells, &mut self.ring).unwrap()
    }
}

/// The f64 model: Sims's equations, the 3×3 kernel, edges wrapping, concentrations
/// clamped to [0, 1].
fn model_step(a: &mut [f64], b: &mut [f64], (w, h): (usize, usize), m: &GrayScott) {
    let (f, k) = (m.feed.to_f64(), m.kill.to_f64());
    let (da, db, dt) = (
        m.diffusion_a.to_f64(),
        m.diffusion_b.to_f64(),
        m.dt.to_f64(),
    );
    let laplacian = |v: &[f64], x: usize, y: usize| {
        let at = |dx: isize, dy: isize| {
            let xx = (x as isize + dx).rem_euclid(w as isize) as usize;
            let yy = (y as isize + dy).rem_euclid(h as isize) as usize;
            v[yy * w + xx]
        };
        -at(0, 0)
            + 0.2 * (at(-1, 0) + at(1, 0) + at(0, -1) + at(0, 1))
            + 0.05 * (at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1))
    };
    let (old_a, old_b) = (a.to_vec(), b.to_vec());
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            let (ai, bi) = (old_a[i], old_b[i]);
            let abb = ai * bi * bi;
            a[i] =
                (ai + (da * laplacian(&old_a, x, y) - abb + f * (1.0 - ai)) * dt).clamp(0.0, 1.0);
            b[i] = (bi + (db * laplacian(&old_b, x, y) + abb - (k + f) * bi) * dt).clamp(0.0, 1.0);
        }
    }
}

fn to_f64(cells: &[Cell]) -> (Vec<f64>, Vec<f64>) {
    let unit = f64::from(ONE);
    (
        cells.iter().map(|c| f64::from(c.a) / unit).collect(),
        cells.iter().map(|c| f64::from(c.b) / unit).collect(),
    )
}

#[test]
fn the_rest_state_is_a_fixed_point_exactly() {
    for preset in Preset::ALL {
        let mut grid = Grid::new(7, 5);
        let mut reaction = grid.reaction(&preset.model());
        reaction.step(50);
        assert!(
            reaction.cells().iter().all(|&c| c == Cell::REST),
            "{preset:?}"
        );
    }
}

/// A grid of random cells in [0, 1) from a seed (a small LCG, independent of the crate).
fn random_cells(n: usize, seed: u64) -> Vec<u16> {
    let mut state = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % u64::from(ONE)) as u16
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// With no feed, no kill and one chemical absent, a step is diffusion alone, and the
    /// carried remainders keep each total exactly.
    #[test]
    fn pure_diffusion_conserves_the_totals_exactly(
        w in 3u32..24,
        h in 3u32..24,
        seed in any::<u64>(),
        steps in 1u32..20,
        d in 0u32..=100,
        dt in 1u32..=100,
        diffusing_b in any::<bool>(),
    ) {
        let mut grid = Grid::new(w, h);
        let values = random_cells((w * h) as usize, seed);
        let model = GrayScott {
            feed: Real::ZERO,
            kill: Real::ZERO,
            diffusion_a: Real::from_ratio(d.into(), 100).unwrap(),
            diffusion_b: Real::from_ratio(d.into(), 100).unwrap(),
            dt: Real::from_ratio(dt.into(), 100).unwrap(),
        };
        let mut reaction = grid.reaction(&model);
        for (cell, &v) in reaction.cells_mut().iter_mut().zip(&values) {
            *cell = if diffusing_b { Cell { a: 0, b: v } } else { Cell { a: v, b: 0 } };
        }
        let total = |r: &Reaction| -> i64 {
            r.cells().iter().map(|c| i64::from(c.a) + i64::from(c.b)).sum()
        };
        let before = total(&reaction);
        reaction.step(steps);
        prop_assert_eq!(total(&reaction), before);
        // The other chemical stays absent.
        let absent = |c: &Cell| if diffusing_b { c.a == 0 } else { c.b == 0 };
        prop_assert!(reaction.cells().iter().all(absent), "the other chemical appeared");
    }
}

/// The model's rates as the engine takes them: D·Δt/20, f·Δt and (k + f)·Δt each rounded
/// to the nearest multiple of 2⁻¹⁵ (Δt is 1 here).
fn as_the_engine_rounds(m: &GrayScott) -> GrayScott {
    let q15 = |x: f64| (x * 32768.0).round();
    let real = |units: f64| Real::from_ratio(units as i64, 32768).unwrap();
    let (f, k) = (m.feed.to_f64(), m.kill.to_f64());
    GrayScott {
        feed: real(q15(f)),
        kill: real(q15(f + k) - q15(f)),
        diffusion_a: real(20.0 * q15(m.diffusion_a.to_f64() / 20.0)),
        diffusion_b: real(20.0 * q15(m.diffusion_b.to_f64() / 20.0)),
        dt: m.dt,
    }
}

/// The largest difference between the engine and the f64 model over `steps` steps.
fn worst_difference(preset: Preset, start: Start, (w, h): (u32, u32), steps: u32) -> f64 {
    let model = preset.model();
    let mut grid = Grid::new(w, h);
    let mut reaction = grid.reaction(&model);
    reaction.start(start);
    let (mut a, mut b) = to_f64(reaction.cells());
    let rounded = as_the_engine_rounds(&model);
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        reaction.step(1);
        model_step(&mut a, &mut b, (w as usize, h as usize), &rounded);
        let (ea, eb) = to_f64(reaction.cells());
        for i in 0..a.len() {
            worst = worst.max((ea[i] - a[i]).abs()).max((eb[i] - b[i]).abs());
        }
    }
    worst
}

/// The first 200 steps follow the f64 model, with the rates as the engine rounds them,
/// within 2⁻¹⁰ in every cell (the worst seen is 2⁻¹¹·⁰): each step rounds AB to 2⁻¹⁵ and
/// each cell to 2⁻¹⁵ (with the remainder carried).
#[test]
fn the_first_200_steps_follow_an_f64_model() {
    for preset in [Preset::Coral, Preset::Mitosis, Preset::Worms, Preset::Waves] {
        for start in [Start::Square, Start::Spots { seed: 7 }] {
            let worst = worst_difference(preset, start, (64, 48), 200);
            assert!(
                worst < 1.0 / 1024.0,
                "{preset:?} {start:?}: differs by {worst} = 2^{:.1}",
                worst.log2()
            );
        }
    }
}

#[test]
fn the_square_start_is_centred_with_side_an_eighth() {
    let mut grid = Grid::new(80, 48);
    let mut reaction = grid.reaction(&GrayScott::default());
    reaction.start(Start::Square);
    // ⌊48/8⌋ = 6 cells, from column (80 − 6)/2 = 37 and row (48 − 6)/2 = 21.
    for y in 0..48 {
        for x in 0..80 {
            let inside = (37..43).contains(&x) && (21..27).contains(&y);
            let cell = reaction.cell(x, y).unwrap();
            assert_eq!(
                cell,
                Cell {
                    a: ONE,
                    b: if inside { ONE } else { 0 }
                },
                "({x}, {y})"
            );
        }
    }
}

#[test]
fn spots_follow_the_seed() {
    let spots = |seed| {
        let mut grid = Grid::new(128, 128);
        let mut reaction = grid.reaction(&GrayScott::default());
        reaction.start(Start::Spots { seed });
        reaction.cells().to_vec()
    };
    assert_eq!(spots(1), spots(1));
    assert_ne!(spots(1), spots(2));
    // 128·128/2048 = 8 squares of side 8: at most 512 cells, fewer where they overlap.
    let seeded = spots(1).iter().filter(|c| c.b == ONE).count();
    assert!(seeded > 64 && seeded <= 512, "{seeded}");
}

/// Connected components (4-neighbours, wrapping) of the cells where B ≥ 0.2 (a pattern's
/// B peaks near 0.3 to 0.4), with each
/// component's cell count.
fn components(cells: &[Cell], w: usize, h: usize) -> Vec<usize> {
    let mut seen = vec![false; cells.len()];
    let mut sizes = Vec::new();
    for start in 0..cells.len() {
        if seen[start] || cells[start].b < ONE / 5 {
            continue;
        }
        let mut stack = vec![start];
        seen[start] = true;
        let mut size = 0;
        while let Some(i) = stack.pop() {
            size += 1;
            let (x, y) = (i % w, i / w);
            for (nx, ny) in [
                ((x + 1) % w, y),
                ((x + w - 1) % w, y),
                (x, (y + 1) % h),
                (x, (y + h - 1) % h),
            ] {
                let j = ny * w + nx;
                if !seen[j] && cells[j].b >= ONE / 5 {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        sizes.push(size);
    }
    sizes
}

#[test]
fn presets_reach_their_patterns() {
    let run = |preset: Preset, steps| {
        let mut grid = Grid::new(96, 96);
        let mut reaction = grid.reaction(&preset.model());
        reaction.start(Start::Square);
        reaction.step(steps);
        components(reaction.cells(), 96, 96)
    };
    // Mitosis: one square becomes many separate small spots.
    let spots = run(Preset::Mitosis, 6000);
    assert!(spots.len() >= 8, "mitosis: {} spots", spots.len());
    assert!(
        spots.iter().all(|&s| s < 200),
        "mitosis: a spot of {:?}",
        spots.iter().max()
    );
    // A maze: few components, one of them long and branching (most of the B cells).
    let maze = run(Preset::Maze, 6000);
    let total: usize = maze.iter().sum();
    let largest = maze.iter().copied().max().unwrap_or(0);
    assert!(maze.len() <= 6, "maze: {} components", maze.len());
    assert!(
        largest * 2 > total && largest > 500,
        "maze: largest {largest} of {total}"
    );
}

#[test]
fn every_bad_parameter_is_a_typed_error() {
    let mut grid = Grid::new(8, 8);
    let make = |grid: &mut Grid, model: GrayScott| {
        Reaction::new(&model, grid.size, &mut grid.cells, &mut grid.ring).map(|_| ())
    };
    let base = GrayScott::default();
    let dt = real("1.5");
    assert_eq!(
        make(&mut grid, GrayScott { dt, ..base }),
        Err(Error::Parameter(ParameterError::TimeStepOutOfRange { dt }))
    );
    assert_eq!(
        make(
            &mut grid,
            GrayScott {
                dt: Real::ZERO,
                ..base
            }
        ),
        Err(Error::Parameter(ParameterError::TimeStepOutOfRange {
            dt: Real::ZERO
        }))
    );
    let feed = real("-0.01");
    assert_eq!(
        make(&mut grid, GrayScott { feed, ..base }),
        Err(Error::Parameter(ParameterError::FeedKillOutOfRange {
            feed,
            kill: base.kill
        }))
    );
    let (feed, kill) = (real("0.6"), real("0.5"));
    assert_eq!(
        make(&mut grid, GrayScott { feed, kill, ..base }),
        Err(Error::Parameter(ParameterError::FeedKillOutOfRange {
            feed,
            kill
        }))
    );
    // D·Δt = 1.2: the explicit step overshoots (the kernel's extreme eigenvalue is −1.6).
    let diffusion = real("1.2");
    assert_eq!(
        make(
            &mut grid,
            GrayScott {
                diffusion_a: diffusion,
                ..base
            }
        ),
        Err(Error::Parameter(ParameterError::DiffusionUnstable {
            diffusion,
            dt: Real::ONE
        }))
    );
    // The same rate is accepted at a smaller time step.
    assert_eq!(
        make(
            &mut grid,
            GrayScott {
                diffusion_a: diffusion,
                dt: real("0.8"),
                ..base
            }
        ),
        Ok(())
    );
    let mut small = Grid::new(2, 8);
    assert_eq!(
        make(&mut small, base),
        Err(Error::Parameter(ParameterError::GridOutOfRange {
            width: 2,
            height: 8,
            min: 3,
            max: 4096
        }))
    );
    let mut cells = vec![Cell::REST; 63];
    let mut ring = vec![Cell::REST; 24];
    assert_eq!(
        Reaction::new(&base, (8, 8), &mut cells, &mut ring).map(|_| ()),
        Err(Error::Fit(FitError::BufferTooSmall {
            needed: 64,
            given: 63
        }))
    );
    let mut cells = vec![Cell::REST; 64];
    let mut ring = vec![Cell::REST; 23];
    assert_eq!(
        Reaction::new(&base, (8, 8), &mut cells, &mut ring).map(|_| ()),
        Err(Error::Fit(FitError::BufferTooSmall {
            needed: 24,
            given: 23
        }))
    );
}

/// The documented memory: the reaction itself is under 100 bytes; the caller's cells are 4
/// bytes and the ring 12 bytes a column.
#[test]
fn memory_is_as_documented() {
    assert!(size_of::<Reaction<'static>>() < 100);
    assert_eq!(size_of::<Cell>(), 4);
    assert_eq!(Reaction::ring_len(128) * size_of::<Cell>(), 128 * 12);
}

#[test]
fn presets_are_the_published_pairs() {
    let pair = |p: Preset| (p.model().feed.to_f64(), p.model().kill.to_f64());
    let close =
        |(f, k): (f64, f64), (ef, ek): (f64, f64)| (f - ef).abs() < 1e-9 && (k - ek).abs() < 1e-9;
    // Karl Sims's two named pairs.
    assert!(close(pair(Preset::Coral), (0.0545, 0.062)));
    assert!(close(pair(Preset::Mitosis), (0.0367, 0.0649)));
    let names: Vec<_> = Preset::ALL.iter().map(|p| p.name()).collect();
    let mut unique = names.clone();
    unique.dedup();
    assert_eq!(names.len(), unique.len());
}

/// A palette that shows a level as that grey, so a drawn pixel names its cell's level.
struct Levels;

impl tinyfractal::render::Palette for Levels {
    type Color = embedded_graphics::pixelcolor::Gray8;

    fn color(&self, level: u16, _max: u16) -> Self::Color {
        embedded_graphics::pixelcolor::Gray8::new(level as u8)
    }
}

/// Every pixel of a drawing shows the cell its documented rule names: column
/// ⌊x·W/width⌋ and row ⌊y·H/height⌋ of the grid, for grids stretched and shrunk.
#[test]
fn drawings_show_the_nearest_cell() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::GrayColor;
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;
    use tinyfractal::reaction::level_of;
    for (w, h) in [(3, 3), (5, 7), (24, 24), (64, 40)] {
        let mut grid = Grid::new(w, h);
        let mut reaction = grid.reaction(&Preset::Mitosis.model());
        // Each cell a level of its own (up to 256 of them), B = level/255 rounded.
        let cells = reaction.cells_mut();
        for (index, cell) in cells.iter_mut().enumerate() {
            let level = (index * 97 % 256) as u32;
            cell.b = ((level * u32::from(ONE) + 127) / 255) as u16;
        }
        let levels: Vec<u8> = reaction.cells().iter().map(|c| level_of(c.b)).collect();
        for (width, height) in [(1, 1), (7, 5), (63, 64), (13, 50), (20, 3), (62, 41)] {
            let area = Rectangle::new(Point::new(1, 0), Size::new(width, height));
            let mut display = MockDisplay::<embedded_graphics::pixelcolor::Gray8>::new();
            reaction
                .fit(area, Levels)
                .unwrap()
                .draw(&mut display)
                .unwrap();
            for y in 0..height {
                for x in 0..width {
                    let column = (f64::from(x) * f64::from(w) / f64::from(width)).floor();
                    let row = (f64::from(y) * f64::from(h) / f64::from(height)).floor();
                    let expected = levels[row as usize * w as usize + column as usize];
                    let pixel = display.get_pixel(Point::new(x as i32 + 1, y as i32));
                    assert_eq!(
                        pixel.map(|p| p.luma()),
                        Some(expected),
                        "grid {w}x{h}, area {width}x{height}, pixel ({x}, {y})"
                    );
                }
            }
        }
    }
}
