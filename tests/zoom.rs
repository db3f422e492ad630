//! The zoom that reuses its frames: how much it computes, how close its frames stay to
//! fully computed ones, and that a frame with no tolerance is exact.

use embedded_graphics::geometry::Size;
use tinyfractal::{
    escape::{Algorithm, Render, ReuseStats, ZoomFrame, ZoomLine},
    render::DwellBuffer,
    Coord, Fractal, View,
};

const CENTRE: (f64, f64) = (-0.743_5, 0.131_4);

fn view(width: f64, size: Size) -> View {
    capped(width, size, 256)
}

fn capped(width: f64, size: Size, cap: u32) -> View {
    let c = |v: f64| Coord::from_f64(v).unwrap();
    View::new(
        Fractal::Mandelbrot,
        (c(CENTRE.0), c(CENTRE.1)),
        c(width),
        size,
        cap,
    )
    .unwrap()
}

fn computed(view: View) -> Vec<u16> {
    let size = view.size();
    let mut values = vec![0; (size.width * size.height) as usize];
    let Ok(_) =
        Render::new(view, Algorithm::Exact).run(&mut DwellBuffer::new(&mut values, size.width));
    values
}

/// Storage for one frame of `size`.
struct Storage {
    values: Vec<u16>,
    columns: Vec<ZoomLine>,
    rows: Vec<ZoomLine>,
}

impl Storage {
    fn new(size: Size) -> Self {
        Self {
            values: vec![0; (size.width * size.height) as usize],
            columns: vec![ZoomLine::default(); size.width as usize],
            rows: vec![ZoomLine::default(); size.height as usize],
        }
    }

    fn frame(&mut self, view: View) -> ZoomFrame<'_> {
        ZoomFrame::new(view, &mut self.values, &mut self.columns, &mut self.rows).unwrap()
    }
}

/// Computes `next` from `previous` (a frame of `previous_view`) in the two storages.
fn step(
    previous: &mut Storage,
    previous_view: View,
    next: &mut Storage,
    view: View,
    tolerance: u32,
) -> ReuseStats {
    let old = previous.frame(previous_view);
    let mut new = next.frame(view);
    new.compute(Some(&old), tolerance)
}

#[test]
fn a_zoom_by_1_05_computes_a_tenth_of_each_frame() {
    let size = Size::new(320, 240);
    let (mut previous, mut next) = (Storage::new(size), Storage::new(size));
    let mut previous_view = view(3.0, size);
    let first = previous.frame(previous_view).compute(None, 100);
    assert_eq!(first.computed, 320 * 240);
    let (mut shares, mut agreement) = (Vec::new(), Vec::new());
    for frame in 1..=100 {
        let next_view = view(3.0 / 1.05f64.powi(frame), size);
        let stats = step(&mut previous, previous_view, &mut next, next_view, 100);
        assert_eq!(stats.computed + stats.reused, 320 * 240);
        shares.push(f64::from(stats.computed) / f64::from(320 * 240));
        if frame % 25 == 0 {
            let exact = computed(next_view);
            let same = exact
                .iter()
                .zip(&next.values)
                .filter(|(a, b)| a == b)
                .count();
            agreement.push(same as f64 / exact.len() as f64);
        }
        std::mem::swap(&mut previous, &mut next);
        previous_view = next_view;
    }
    let mean = shares.iter().sum::<f64>() / shares.len() as f64;
    let worst = shares.iter().copied().fold(0.0, f64::max);
    eprintln!("computed per frame: mean {mean:.4}, worst {worst:.4}; agreement {agreement:?}");
    // Measured: 9.2 % on average, 10.7 % at worst (the goal is 10 %; a zoom by 1.05 must
    // compute about 1 - 1/1.05^2 = 9.3 % of the nominal lines; taking lines earliest
    // first without moving them on computed 11.6 %; at half a pixel's tolerance 30.6 %).
    assert!(mean <= 0.10, "mean share computed {mean}");
    assert!(worst <= 0.12, "worst share computed {worst}");
    // Reused pixels show a grid point up to a pixel from the nominal one, and the grid
    // does not drift: most pixels keep the nominal point's dwell (the share falls as the
    // zoom reaches finer detail: 93 % at frame 25, 78 % at frame 100).
    assert!(agreement.iter().all(|&a| a >= 0.75), "{agreement:?}");
}

#[test]
fn no_tolerance_gives_the_exact_frame() {
    let size = Size::new(96, 72);
    let first = view(0.5, size);
    let mut previous = Storage::new(size);
    previous.frame(first).compute(None, 0);
    assert_eq!(previous.values, computed(first));
    for width in [0.5, 0.5 / 1.05, 0.25, 0.49] {
        let next_view = view(width, size);
        let mut next = Storage::new(size);
        let stats = step(&mut previous, first, &mut next, next_view, 0);
        assert_eq!(next.values, computed(next_view), "width {width}");
        if width == 0.5 {
            assert_eq!(stats.computed, 0, "the same view is taken whole");
        }
    }
}

#[test]
fn nothing_is_taken_from_a_different_fractal_or_cap() {
    let size = Size::new(40, 30);
    let first = view(1.0, size);
    let mut previous = Storage::new(size);
    previous.frame(first).compute(None, 50);
    let c = |v: f64| Coord::from_f64(v).unwrap();
    let other_cap = View::new(Fractal::Mandelbrot, first.centre(), c(1.0), size, 100).unwrap();
    let mut next = Storage::new(size);
    let stats = step(&mut previous, first, &mut next, other_cap, 50);
    assert_eq!((stats.reused, &next.values), (0, &computed(other_cap)));
}

#[test]
fn short_storage_is_a_typed_error() {
    let size = Size::new(40, 30);
    let (mut values, mut columns, mut rows) = (
        vec![0u16; 1199],
        vec![ZoomLine::default(); 40],
        vec![ZoomLine::default(); 30],
    );
    let error = ZoomFrame::new(view(1.0, size), &mut values, &mut columns, &mut rows).unwrap_err();
    assert_eq!(
        error,
        tinyfractal::Error::Fit(tinyfractal::error::FitError::BufferTooSmall {
            needed: 1200,
            given: 1199
        })
    );
}

/// The dwell at one point, as a 1×1 view of `tier` computes it.
fn dwell_at(frame_view: &View, (re, im): (i64, i64)) -> u16 {
    let one = Size::new(1, 1);
    let view = View::new(
        frame_view.fractal(),
        (Coord::from_bits(re), Coord::from_bits(im)),
        frame_view.spacing(),
        one,
        frame_view.max_iterations(),
    )
    .unwrap()
    .with_tier(frame_view.tier());
    computed(view)[0]
}

#[test]
fn one_frame_moved_in_place_holds_each_pixels_own_dwell() {
    // Zooming in, out and panning move lines both ways: whatever the order the values are
    // moved in, every pixel must hold the dwell at the point its column and row stand for
    // (a value overwritten before it was read would not), and those points stay within
    // the tolerance of the nominal ones.
    let size = Size::new(48, 36);
    let mut storage = Storage::new(size);
    let mut frame = storage.frame(view(0.02, size));
    let first = frame.advance(view(0.02, size), Some(100)).unwrap();
    assert_eq!(first.computed, 48 * 36, "a new frame computes everything");
    let c = |v: f64| Coord::from_f64(v).unwrap();
    let panned = |dx: f64, width: f64| {
        View::new(
            Fractal::Mandelbrot,
            (
                c(CENTRE.0 + dx * width / 48.0),
                c(CENTRE.1 - dx * width / 96.0),
            ),
            c(width),
            size,
            256,
        )
        .unwrap()
    };
    let mut reused = 0;
    let mut width = 0.02;
    for step in 0..24 {
        let next = match step % 4 {
            0 | 1 => {
                width /= 1.05;
                view(width, size)
            }
            2 => {
                width *= 1.1;
                view(width, size)
            }
            _ => panned(if step % 8 == 3 { 5.0 } else { -7.0 }, width),
        };
        let stats = frame.advance(next, Some(100)).unwrap();
        reused += stats.reused;
        let spacing = next.spacing().to_bits() as i128;
        for row in 0..size.height {
            for column in 0..size.width {
                let point = frame.point(column, row).unwrap();
                let value = frame.values()[(row * size.width + column) as usize];
                assert_eq!(
                    value,
                    dwell_at(&next, point),
                    "step {step} at ({column}, {row})"
                );
                let nominal = (
                    i128::from(next.centre().0.to_bits())
                        + spacing * (2 * i128::from(column) + 1 - 48) / 2,
                    i128::from(next.centre().1.to_bits())
                        - spacing * (2 * i128::from(row) + 1 - 36) / 2,
                );
                assert!(
                    (i128::from(point.0) - nominal.0).abs() <= spacing + 2,
                    "step {step}"
                );
                assert!(
                    (i128::from(point.1) - nominal.1).abs() <= spacing + 2,
                    "step {step}"
                );
            }
        }
    }
    assert!(
        reused > 24 * 48 * 36 / 2,
        "most pixels are moved, not computed: {reused}"
    );
}

#[test]
fn byte_cells_hold_the_same_frames_and_refuse_larger_values() {
    let size = Size::new(40, 30);
    let (mut bytes, mut columns, mut rows) = (
        vec![0u8; 1200],
        vec![ZoomLine::default(); 40],
        vec![ZoomLine::default(); 30],
    );
    let mut words = Storage::new(size);
    let start = capped(0.1, size, 255);
    let mut small = ZoomFrame::new(start, &mut bytes, &mut columns, &mut rows).unwrap();
    let mut wide = words.frame(start);
    for width in [0.1, 0.09, 0.08] {
        small.advance(capped(width, size, 255), Some(100)).unwrap();
        wide.advance(capped(width, size, 255), Some(100)).unwrap();
        let widened: Vec<u16> = small.values().iter().map(|&v| u16::from(v)).collect();
        assert_eq!(widened, wide.values());
    }
    let c = |v: f64| Coord::from_f64(v).unwrap();
    let high_cap = View::new(Fractal::Mandelbrot, (c(-0.5), c(0.0)), c(3.0), size, 256).unwrap();
    assert_eq!(
        small.advance(high_cap, None).unwrap_err(),
        tinyfractal::Error::Fit(tinyfractal::error::FitError::CellTooNarrow {
            largest: 256,
            cell_max: 255
        })
    );
    let larger = View::new(
        Fractal::Mandelbrot,
        (c(-0.5), c(0.0)),
        c(3.0),
        Size::new(41, 30),
        100,
    );
    assert!(matches!(
        small.advance(larger.unwrap(), None),
        Err(tinyfractal::Error::Fit(
            tinyfractal::error::FitError::BufferTooSmall { .. }
        ))
    ));
}

#[test]
fn no_tolerance_takes_nothing_from_another_tier() {
    // Found by the `zoom` fuzz target: the same point computed in another tier can have
    // another dwell, so a frame that must be exact takes no line from a frame in another
    // tier. The case: a view 0.99 wide, then 31/256 of it, panned by (-1, 2) pixels.
    let size = Size::new(3, 15);
    let bits = |v: i64| Coord::from_bits(v);
    let at = |centre: (i64, i64), width: i64| {
        View::new(
            Fractal::Mandelbrot,
            (bits(centre.0), bits(centre.1)),
            bits(width),
            size,
            195,
        )
        .unwrap()
    };
    let (centre, width) = (
        (167_783_424i64 << 30, 65_561i64 << 30),
        4_243_991_296i64 << 28,
    );
    let first = at(centre, width);
    let spacing = first.spacing().to_bits();
    let next = at(
        (centre.0 - spacing, centre.1 + 2 * spacing),
        (i128::from(width) * 31 / 256) as i64,
    );
    assert_ne!(first.tier(), next.tier(), "the case crosses tiers");
    let mut storage = Storage::new(size);
    let mut frame = storage.frame(first);
    frame.advance(first, None).unwrap();
    frame.advance(next, Some(0)).unwrap();
    assert_eq!(frame.values(), computed(next));
}
