//! `render figure`: the lecture's articulated body in a pose, or frames of its walk cycle.

use std::io::Write;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    figure::{FigureDrawing, Pose, BODY},
    render::Colors,
    Figure, Real,
};

use crate::common::Common;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PoseName {
    /// Standing
    Stand,
    /// The walk cycle (at --time)
    Walk,
    /// Waving the right arm (at --time)
    Wave,
}

#[derive(Debug, Clone, PartialEq, Args)]
pub struct FigureOptions {
    /// The pose
    #[arg(long, value_enum, default_value = "walk")]
    pose: PoseName,
    /// Where in the cycle, in cycles (0 to 1 is one stride or wave)
    #[arg(
        long,
        value_name = "T",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    time: f64,
    /// Write N frames of one cycle, NAME-000.png to NAME-(N-1).png, instead of one picture
    /// (without --segments or --dimension, which are of one picture)
    #[arg(long, value_name = "N", conflicts_with_all = ["segments", "dimension"])]
    frames: Option<u32>,
    /// Write every drawn line, `x0 y0 x1 y1 part` a line, in world units
    #[arg(long, value_name = "TXT")]
    segments: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
}

fn pose(name: PoseName, time: f64) -> Result<Pose, String> {
    let time = Real::from_f64(time).ok_or_else(|| format!("--time {time}: out of range"))?;
    Ok(match name {
        PoseName::Stand => Pose::default(),
        PoseName::Walk => tinyfractal::figure::walk(time),
        PoseName::Wave => tinyfractal::figure::wave(time),
    })
}

/// The figure's colours: body, skin, hair, clothes.
const PALETTE: [Rgb888; 4] = [
    Rgb888::new(0xE0, 0xE0, 0xE0),
    Rgb888::new(0xF4, 0xA4, 0x60),
    Rgb888::new(0xFF, 0xD7, 0x00),
    Rgb888::new(0x46, 0x82, 0xB4),
];

/// Draws a fitted figure into a fresh target of the requested size.
fn render(
    drawing: &FigureDrawing<Colors<'_, Rgb888>>,
    size: Size,
) -> Result<(SimulatorDisplay<Rgb888>, u64), String> {
    let mut display = SimulatorDisplay::new(size);
    let drawn = drawing
        .try_draw(&mut display)
        .map_err(crate::scene::engine_error)
        .map_err(|e| format!("figure: {e}"))?;
    Ok((display, drawn))
}

/// Fits `figure` to a target of the requested size so that it also fits in `poses`.
fn fit(
    figure: &Figure,
    size: Size,
    poses: impl IntoIterator<Item = Pose>,
) -> Result<(FigureDrawing<Colors<'static, Rgb888>>, Size), String> {
    let drawing = figure
        .fit_poses(Rectangle::new(Point::zero(), size), &PALETTE, poses)
        .map_err(|e| format!("figure: {e}"))?;
    Ok((drawing, size))
}

/// `frames` pictures of one cycle of `movement` at `size`, each into `emit` as it is drawn,
/// fitted once over all of them so the figure walks in place instead of jumping.
pub fn cycle(
    movement: PoseName,
    frames: u32,
    size: Size,
    mut emit: impl FnMut(SimulatorDisplay<Rgb888>) -> Result<(), String>,
) -> Result<(), String> {
    let poses = (0..frames)
        .map(|index| pose(movement, f64::from(index) / f64::from(frames)))
        .collect::<Result<Vec<_>, _>>()?;
    let Some(&first) = poses.first() else {
        return Ok(());
    };
    let (drawing, size) = fit(&Figure::new(&BODY, first), size, poses.iter().copied())?;
    for &pose in &poses {
        emit(render(&drawing.with_pose(pose), size)?.0)?;
    }
    Ok(())
}

/// `render figure`.
pub fn render_figure(options: &FigureOptions) -> Result<(), String> {
    crate::delivery::window_available(options.common.window)?;
    let started = crate::clock::Instant::now();
    if let Some(frames) = options.frames {
        if frames == 0 {
            return Err("--frames 0: give at least one frame".into());
        }
        let out = options
            .common
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("figure.png"));
        let stem = out.with_extension("");
        let size = Size::new(options.common.width(), options.common.height());
        // Every frame and the stats line, all or nothing.
        let mut pictures = Vec::new();
        cycle(options.pose, frames, size, |picture| {
            pictures.push(picture);
            Ok(())
        })?;
        let paths: Vec<PathBuf> = (0..pictures.len())
            .map(|index| PathBuf::from(format!("{}-{index:03}.png", stem.display())))
            .collect();
        let mut plan = crate::output::Plan::new();
        for (display, path) in pictures.iter().zip(&paths) {
            plan.add("--frames", path, move |w| crate::output::png(display, w));
        }
        if options.common.stats {
            plan.print(format!(
                "frames={frames} elapsed_ms={:.3}\n",
                started.elapsed().as_secs_f64() * 1e3
            ));
        }
        return plan.write();
    }
    let figure = Figure::new(&BODY, pose(options.pose, options.time)?);
    let size = Size::new(options.common.width(), options.common.height());
    let (drawing, size) = fit(&figure, size, [])?;
    let (display, drawn) = render(&drawing, size)?;
    let stats = format!(
        "lines={drawn} elapsed_ms={:.3}",
        started.elapsed().as_secs_f64() * 1e3
    );
    crate::delivery::deliver(
        &options.common,
        "figure",
        &display,
        |plan| {
            if let Some(path) = &options.segments {
                plan.add("--segments", path, move |w: &mut dyn Write| {
                    let mut result = Ok(());
                    figure
                        .for_each_line(|line| {
                            let s = line.segment;
                            if result.is_ok() {
                                result = writeln!(
                                    w,
                                    "{} {} {} {} {}",
                                    s.start[0], s.start[1], s.end[0], s.end[1], line.part
                                );
                            }
                            Ok(())
                        })
                        .map_err(std::io::Error::other)?;
                    result
                });
            }
        },
        &stats,
    )
}
