//! Histogram colouring: every level holds an equal share of the escaping pixels, give or
//! take one dwell's count (a dwell is never split), the levels rise with the dwell, and
//! the set keeps the inside colour; a short count buffer is a typed error.

use embedded_graphics::pixelcolor::{Gray8, GrayColor};
use embedded_graphics::prelude::*;
use tinyfractal::error::FitError;
use tinyfractal::escape::{Algorithm, Render};
use tinyfractal::render::{DwellBuffer, Histogram, Palette};
use tinyfractal::{Coord, Error, Fractal, View};

/// The level itself, as a grey (255 inside).
struct Levels;

impl Palette for Levels {
    type Color = Gray8;

    fn color(&self, value: u16, max: u16) -> Gray8 {
        Gray8::new(if value >= max { 255 } else { value as u8 })
    }
}

fn dwells(width: &str, centre: (&str, &str), max: u32) -> (Vec<u16>, u16) {
    let size = Size::new(160, 120);
    let view = View::new(
        Fractal::Mandelbrot,
        (
            Coord::parse(centre.0).unwrap(),
            Coord::parse(centre.1).unwrap(),
        ),
        Coord::parse(width).unwrap(),
        size,
        max,
    )
    .unwrap();
    let mut values = vec![0u16; 160 * 120];
    let mut sink = DwellBuffer::new(&mut values, 160);
    Render::new(view, Algorithm::Exact).run(&mut sink).unwrap();
    (values, view.inside_value())
}

#[test]
fn every_level_holds_an_equal_share() {
    for (width, centre, max) in [
        ("3.5", ("-0.75", "0"), 200),
        ("0.05", ("-0.745", "0.11"), 500),
    ] {
        let (values, inside) = dwells(width, centre, max);
        let mut counts = vec![0u32; usize::from(inside) + 1];
        let levels = 16u16;
        let histogram =
            Histogram::new(&mut counts, values.iter().copied(), inside, levels, Levels).unwrap();
        let mut per_level = vec![0u64; usize::from(levels)];
        let mut per_dwell = std::collections::HashMap::<u16, u64>::new();
        let mut previous: Vec<(u16, u8)> = Vec::new();
        for &dwell in &values {
            let grey = histogram.color(dwell, inside).luma();
            if dwell >= inside {
                assert_eq!(grey, 255, "the set keeps the inside colour");
                continue;
            }
            per_level[usize::from(grey)] += 1;
            *per_dwell.entry(dwell).or_default() += 1;
            previous.push((dwell, grey));
        }
        // Levels rise with the dwell.
        previous.sort();
        assert!(previous.windows(2).all(|w| w[0].1 <= w[1].1));
        let escaping: u64 = per_level.iter().sum();
        let largest = per_dwell.values().copied().max().unwrap();
        let share = escaping as f64 / f64::from(levels);
        // Each dwell's level from its first rank, computed here from the counts.
        let mut sorted: Vec<(u16, u64)> = per_dwell.iter().map(|(&d, &n)| (d, n)).collect();
        sorted.sort();
        let mut rank = 0u64;
        for (dwell, count) in sorted {
            let level = rank * u64::from(levels) / escaping;
            assert_eq!(
                u64::from(histogram.color(dwell, inside).luma()),
                level,
                "dwell {dwell}"
            );
            rank += count;
        }
        for (level, &count) in per_level.iter().enumerate() {
            assert!(
                (count as f64 - share).abs() <= largest as f64 + 1.0,
                "{width}: level {level} holds {count}, a share is {share:.0}, the largest dwell {largest}"
            );
        }
    }
    let mut short = vec![0u32; 10];
    assert_eq!(
        Histogram::new(&mut short, [1u16, 2], 100, 16, Levels).err(),
        Some(Error::Fit(FitError::BufferTooSmall {
            needed: 101,
            given: 10
        }))
    );
}
