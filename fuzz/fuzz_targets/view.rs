//! Escape-time views from arbitrary numbers and decimal text: every view is either a
//! typed error or renders, in every tier, algorithm, shading and preview, into a sink that
//! checks every area and value.

#![no_main]

use arbitrary::Arbitrary;
use embedded_graphics::prelude::*;
use libfuzzer_sys::fuzz_target;
use tinyfractal::{
    escape::{Algorithm, Render, Shading, Tier},
    Coord, Fractal, View,
};
use tinyfractal_fuzz::StrictDwells;

#[derive(Debug, Arbitrary)]
enum Number<'a> {
    Bits(i64),
    Text(&'a str),
}

impl Number<'_> {
    fn coord(&self) -> Option<Coord> {
        match *self {
            Number::Bits(bits) => Some(Coord::from_bits(bits)),
            Number::Text(text) => Coord::parse(text),
        }
    }
}

#[derive(Debug, Arbitrary)]
struct Input<'a> {
    julia: Option<(Number<'a>, Number<'a>)>,
    centre: (Number<'a>, Number<'a>),
    width: Number<'a>,
    size: (u8, u8),
    max_iterations: u16,
    tier: Option<u8>,
    fast: bool,
    smooth: bool,
    preview: u8,
}

fuzz_target!(|input: Input<'_>| {
    let fractal = match &input.julia {
        None => Fractal::Mandelbrot,
        Some((re, im)) => {
            let (Some(re), Some(im)) = (re.coord(), im.coord()) else {
                return;
            };
            Fractal::Julia { re, im }
        }
    };
    let (Some(re), Some(im), Some(width)) = (
        input.centre.0.coord(),
        input.centre.1.coord(),
        input.width.coord(),
    ) else {
        return;
    };
    // At most 48×32 pixels and 2,000 iterations: a few million steps at most.
    let size = Size::new(u32::from(input.size.0 % 49), u32::from(input.size.1 % 33));
    let max = u32::from(input.max_iterations % 2001);
    let Ok(mut view) = View::new(fractal, (re, im), width, size, max) else {
        return;
    };
    if let Some(tier) = input.tier {
        view = view.with_tier(Tier::ALL[usize::from(tier) % Tier::ALL.len()]);
    }
    if input.smooth {
        let Ok(smooth) = view.with_shading(Shading::Smooth) else {
            return;
        };
        view = smooth;
    }
    let algorithm = if input.fast {
        Algorithm::Fast
    } else {
        Algorithm::Exact
    };
    let mut sink = StrictDwells {
        size,
        inside: view.inside_value(),
    };
    let mut render = Render::new(view, algorithm).with_preview(u32::from(input.preview % 12));
    let Ok(stats) = render.run(&mut sink);
    assert!(stats.iterations <= u64::from(max) * u64::from(size.width * size.height) * 2);
    assert!(render.progress().is_complete());
});
