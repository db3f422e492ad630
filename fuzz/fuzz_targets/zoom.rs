//! A zoom in one frame from arbitrary views: a start, then up to four moves (zoom in or
//! out by a ratio, pan by pixels, any tolerance, `u8` or `u16` cells), each moved in place
//! by `ZoomFrame::advance`. Every value stays within `1..=inside`, and a last move with no
//! tolerance must give the exact render of its view, pixel for pixel: whatever order the
//! frame was moved in, no value read was overwritten first.

#![no_main]

use arbitrary::Arbitrary;
use embedded_graphics::prelude::*;
use libfuzzer_sys::fuzz_target;
use tinyfractal::{
    escape::{Algorithm, Render, ZoomFrame, ZoomLine, ZoomValue},
    render::DwellBuffer,
    Coord, Fractal, View,
};

#[derive(Debug, Arbitrary)]
struct Move {
    /// The width is multiplied by (n + 1) / (d + 1).
    ratio: (u8, u8),
    /// The centre moves by this many pixels.
    pan: (i8, i8),
    tolerance: Option<u8>,
}

#[derive(Debug, Arbitrary)]
struct Input {
    julia: bool,
    centre: (i32, i32),
    width: u32,
    size: (u8, u8),
    max_iterations: u8,
    bytes: bool,
    moves: Vec<Move>,
}

/// The view `width` (Q60 bits) wide at `centre`, if it is one.
fn view(input: &Input, centre: (i64, i64), width: i64, size: Size) -> Option<View> {
    let fractal = if input.julia {
        Fractal::Julia {
            re: Coord::from_bits(-(4 << 57)),
            im: Coord::from_bits(1 << 57),
        }
    } else {
        Fractal::Mandelbrot
    };
    let centre = (Coord::from_bits(centre.0), Coord::from_bits(centre.1));
    let max = u32::from(input.max_iterations) + 1;
    View::new(fractal, centre, Coord::from_bits(width), size, max).ok()
}

fn run<V: ZoomValue>(input: &Input) {
    // At most 24×16 pixels, cap 256, five frames: a few hundred thousand steps at most.
    let size = Size::new(u32::from(input.size.0 % 25), u32::from(input.size.1 % 17));
    let pixels = (size.width * size.height) as usize;
    let mut centre = (
        i64::from(input.centre.0) << 30,
        i64::from(input.centre.1) << 30,
    );
    let mut width = i64::from(input.width) << 28;
    let Some(first) = view(input, centre, width, size) else {
        return;
    };
    let mut values = vec![V::default(); pixels];
    let mut columns = vec![ZoomLine::default(); size.width as usize];
    let mut rows = vec![ZoomLine::default(); size.height as usize];
    let Ok(mut frame) = ZoomFrame::new(first, &mut values, &mut columns, &mut rows) else {
        return;
    };
    let inside = first.inside_value();
    let _ = frame.advance(first, None);
    let mut last = first;
    for step in input.moves.iter().take(4) {
        let (n, d) = (i128::from(step.ratio.0) + 1, i128::from(step.ratio.1) + 1);
        width = i64::try_from(i128::from(width) * n / d).unwrap_or(width);
        let spacing = i64::from(last.spacing().to_bits());
        centre.0 = centre
            .0
            .saturating_add(spacing.saturating_mul(step.pan.0.into()));
        centre.1 = centre
            .1
            .saturating_add(spacing.saturating_mul(step.pan.1.into()));
        let Some(next) = view(input, centre, width, size) else {
            continue;
        };
        let tolerance = step.tolerance.map(u32::from);
        if frame.advance(next, tolerance).is_err() {
            continue;
        }
        last = next;
        for value in frame.values().iter().take(pixels) {
            assert!((1..=inside).contains(&value.value()), "{}", value.value());
        }
        if tolerance == Some(0) {
            let mut exact = vec![0u16; pixels];
            let Ok(_) = Render::new(next, Algorithm::Exact)
                .run(&mut DwellBuffer::new(&mut exact, size.width));
            let held: Vec<u16> = frame.values().iter().map(|v| v.value()).collect();
            assert_eq!(held, exact, "a frame with no tolerance is the exact render");
        }
    }
}

fuzz_target!(|input: Input| {
    if input.bytes {
        run::<u8>(&input);
    } else {
        run::<u16>(&input);
    }
});
