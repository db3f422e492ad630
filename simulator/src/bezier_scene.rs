//! `tinyfractal render bezier`: quadratic and cubic Bézier curves from their control
//! points, in the picture's pixel coordinates.

use crate::clock::Instant;
use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::bezier::{vertex_to_f64, Bezier};

use crate::common::Common;
use crate::console::Failure;

/// The colour of the curves.
const STROKE: Rgb888 = Rgb888::new(0xF0, 0xE6, 0x8C);

/// `render bezier`'s options.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct BezierOptions {
    /// A curve's control points in pixels, X0,Y0,X1,Y1,X2,Y2 (quadratic) or
    /// X0,Y0,X1,Y1,X2,Y2,X3,Y3 (cubic); repeat for more curves
    #[arg(long, value_name = "X0,Y0,X1,Y1,X2,Y2[,X3,Y3]", required = true,
          allow_hyphen_values = true, value_parser = parse_control)]
    control: Vec<Curve>,
    /// Write the flattened polyline: each straight piece `x0 y0 x1 y1` a line, in pixels,
    /// curve after curve
    #[arg(long, value_name = "TXT")]
    segments: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

/// One `--control`: a curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Curve(Bezier);

fn parse_control(text: &str) -> Result<Curve, String> {
    let bad = || {
        format!(
            "`{text}` is not 6 or 8 whole pixel coordinates X0,Y0,X1,Y1,X2,Y2[,X3,Y3], e.g. \
             10,100,160,0,310,100"
        )
    };
    let numbers: Vec<i32> = text
        .split(',')
        .map(|part| part.trim().parse::<i32>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    let point = |i: usize| Point::new(numbers[2 * i], numbers[2 * i + 1]);
    match numbers.len() {
        6 => Ok(Curve(Bezier::quadratic([point(0), point(1), point(2)]))),
        8 => Ok(Curve(Bezier::cubic([
            point(0),
            point(1),
            point(2),
            point(3),
        ]))),
        _ => Err(bad()),
    }
}

/// Draws `curves` into a display of `size`: the picture, pieces and pixels.
pub fn draw(curves: &[Bezier], size: Size) -> (SimulatorDisplay<Rgb888>, u64, u64) {
    let mut display = SimulatorDisplay::new(size);
    let (mut segments, mut pixels) = (0, 0);
    for curve in curves {
        let Ok(stats) = curve.into_stroked(STROKE).draw(&mut display);
        segments += stats.segments;
        pixels += stats.pixels;
    }
    (display, segments, pixels)
}

impl BezierOptions {
    /// `render bezier`.
    pub fn run(&self) -> Result<(), Failure> {
        let common = &self.common;
        crate::delivery::window_available(common.window)?;
        let curves: Vec<Bezier> = self.control.iter().map(|curve| curve.0).collect();
        let started = Instant::now();
        let (display, segments, pixels) = draw(&curves, common.area().size);
        let line = format!(
            "curves={} segments={segments} pixels={pixels} elapsed_ms={:.3}",
            curves.len(),
            started.elapsed().as_secs_f64() * 1e3
        );
        Ok(crate::delivery::deliver(
            common,
            "bezier",
            &display,
            |plan| {
                if let Some(path) = &self.segments {
                    plan.add("--segments", path, move |w: &mut dyn Write| {
                        for curve in &curves {
                            let vertices: Vec<(f64, f64)> =
                                curve.flattened().map(vertex_to_f64).collect();
                            for piece in vertices.windows(2) {
                                let ((x0, y0), (x1, y1)) = (piece[0], piece[1]);
                                writeln!(w, "{x0} {y0} {x1} {y1}")?;
                            }
                        }
                        Ok(())
                    });
                }
            },
            &line,
        )?)
    }
}
