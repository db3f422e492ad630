//! `tinyfractal animate`: a picture that moves, as frames.
//!
//! A zoom that reuses its frames, colour cycling, an L-system growing by order, the walking
//! figure; written as numbered PNG frames, an animated GIF or an APNG, all or nothing, with a
//! progress bar on a terminal.

use std::io::{self, Write};
use std::path::Path;
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::time::Instant;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame, RgbaImage};
use indicatif::ProgressBar;
use tinyfractal::{
    escape::{Algorithm, Tier, ZoomFrame, ZoomLine},
    math::{DeepCoord, MAX_DECIMAL_PLACES},
    View,
};

use crate::args::{AnimateArgs, Animation};
use crate::escape_scene::{self, Request};

/// A finished frame, handed from the animation to the encoder as it is made.
type Picture = SimulatorDisplay<Rgb888>;

/// What the animation sends the writer: each frame as it is made, then the `--stats`
/// detail.
enum Message {
    Frame(Picture),
    Done(String),
}

/// Where an animation sends its frames: on to the writer, at most one frame ahead of it,
/// so an animation's memory does not grow with its frames.
struct Emit<'s> {
    sender: SyncSender<Message>,
    bar: &'s ProgressBar,
}

impl Emit<'_> {
    /// Sends `picture` on; an error once the writer has stopped (it says why).
    fn frame(&self, picture: Picture) -> Result<(), String> {
        self.bar.inc(1);
        self.sender
            .send(Message::Frame(picture))
            .map_err(|_| WRITER_STOPPED.to_string())
    }
}

/// The animation's error when the writer stopped first (the writer's own error is the one
/// reported).
const WRITER_STOPPED: &str = "the writer stopped";

/// `animate ...`: the frames are made on a thread of their own and written as they come
/// (numbered PNGs, a GIF or an APNG), all or nothing.
pub fn animate(arguments: &AnimateArgs) -> Result<(), String> {
    let started = Instant::now();
    let size = Size::new(arguments.size.0, arguments.size.1);
    let bar = crate::progress::bar(u64::from(arguments.frames), "frames");
    let (sender, receiver) = sync_channel(1);
    let result = std::thread::scope(|scope| {
        let maker = scope.spawn(|| {
            let emit = Emit { sender, bar: &bar };
            let detail = make(arguments, size, &emit)?;
            let _ = emit.sender.send(Message::Done(detail));
            Ok::<(), String>(())
        });
        let stats = |detail: String| {
            if arguments.stats {
                format!(
                    "frames={}{detail} elapsed_ms={:.3}\n",
                    arguments.frames,
                    started.elapsed().as_secs_f64() * 1e3
                )
            } else {
                String::new()
            }
        };
        let written = write(&receiver, arguments, stats);
        // The writer is done: a maker still sending stops at its next frame.
        drop(receiver);
        let made = maker
            .join()
            .unwrap_or_else(|_| Err("the animation stopped unexpectedly".to_string()));
        match (made, written) {
            (Err(error), _) if error != WRITER_STOPPED => Err(error),
            (_, written) => written,
        }
    });
    bar.finish_and_clear();
    result
}

/// Makes the animation's frames into `emit`; the `--stats` detail.
fn make(arguments: &AnimateArgs, size: Size, emit: &Emit<'_>) -> Result<String, String> {
    match &arguments.kind {
        Animation::Zoom {
            view,
            end_width,
            factor,
            tolerance,
            exact,
        } => {
            let request = escape_scene::request(view, size);
            let tolerance = if *exact { None } else { Some(*tolerance) };
            zoom(
                &request,
                end_width.as_deref(),
                *factor,
                tolerance,
                arguments.frames,
                emit,
            )
        }
        Animation::Palette { view, step } => palette_cycle(
            &escape_scene::request(view, size),
            *step,
            arguments.frames,
            emit,
        ),
        Animation::Growth { source, seed } => growth(source, *seed, arguments.frames, size, emit),
        Animation::Figure { pose } => {
            crate::figure_scene::cycle(*pose, arguments.frames, size, |frame| emit.frame(frame))?;
            Ok(String::new())
        }
    }
}

/// The widths of a zoom's frames, as text: the first is `--width`, the last `end_width`
/// when given (both exactly as written), the rest shrink by one factor a frame.
fn widths(start: &str, end: Option<&str>, factor: f64, frames: u32) -> Result<Vec<String>, String> {
    let number = |option: &str, text: &str| {
        DeepCoord::parse(text)
            .map(DeepCoord::to_f64)
            .ok()
            .filter(|&w| w > 0.0)
            .ok_or_else(|| {
                format!("{option}: `{text}` is not a width between 0 and 8 (e.g. 3 or 1e-5)")
            })
    };
    let first = number("--width", start)?;
    let factor = match end {
        Some(end) if frames > 1 => {
            (first / number("--end-width", end)?).powf(1.0 / f64::from(frames - 1))
        }
        _ => factor,
    };
    if !(factor.is_finite() && factor > 0.0) {
        return Err(format!(
            "--factor {factor}: give a factor above 0 (e.g. 1.05)"
        ));
    }
    (0..frames)
        .map(|k| match (k, end) {
            (0, _) => Ok(start.to_string()),
            (k, Some(end)) if k + 1 == frames => Ok(end.to_string()),
            (k, _) => frame_width(first / factor.powi(k as i32)).ok_or_else(|| {
                format!(
                    "--factor {factor} over {frames} frames: frame {k} would be {:e} wide, past \
                     the deepest zoom (about 10^-42 across 320 pixels) and the widest view; \
                     use fewer --frames or a factor nearer 1",
                    first / factor.powi(k as i32)
                )
            }),
        })
        .collect()
}

/// A frame's width as decimal text a view reads: 15 significant digits, fewer where that
/// would pass the 56 decimal places a coordinate holds; `None` past that or past 8.
fn frame_width(width: f64) -> Option<String> {
    if !(width.is_normal() && width < 8.0) {
        return None;
    }
    let exponent = width.log10().floor() as i32;
    let digits = 14.min(MAX_DECIMAL_PLACES as i32 + exponent);
    (digits >= 0).then(|| format!("{width:.*e}", digits as usize))
}

/// A zoom: each frame reuses the last within `tolerance` % of a pixel (`None`: every
/// frame computed in full); the first and last frames are exact.
fn zoom(
    request: &Request<'_>,
    end_width: Option<&str>,
    factor: f64,
    tolerance: Option<u32>,
    frames: u32,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let widths = widths(request.width, end_width, factor, frames)?;
    // Every frame has the same palette: one is kept.
    let mut palette = None;
    let views = widths
        .iter()
        .enumerate()
        .map(|(index, width)| {
            escape_scene::view_at(request, width)
                .map(|(view, frame_palette)| {
                    palette.get_or_insert(frame_palette);
                    view
                })
                .map_err(|e| match index {
                    0 => e,
                    _ => format!("frame {index} of the zoom, {width} wide: {e}"),
                })
        })
        .collect::<Result<Vec<View>, String>>()?;
    let Some(palette) = palette else {
        return Ok(String::new());
    };
    // A frame that is not exact by the tier rule says so, once, before any is computed.
    if let Some((index, warning)) = views
        .iter()
        .enumerate()
        .find_map(|(index, view)| escape_scene::TierWarning::of(view).map(|w| (index, w)))
    {
        crate::console::warn(&format!(
            "the frame at width {} and those like it: {}",
            widths[index],
            warning.message(&views[index])
        ));
    }
    let pixels = (request.size.width * request.size.height) as usize;
    let mut values = vec![0u16; pixels];
    let mut columns = vec![ZoomLine::default(); request.size.width as usize];
    let mut rows = vec![ZoomLine::default(); request.size.height as usize];
    let (mut computed, mut total) = (0u64, 0u64);
    // One frame, moved in place from view to view. A frame computes in a fixed tier, so a
    // view whose tier is perturbation (past `Deep`'s spacing, or deep with a long orbit)
    // is rendered whole by perturbation, as `render` renders it; the frame's storage is
    // checked against a fixed tier's view of the same size.
    let fixed = |view: &View| match view.tier() {
        Tier::Perturbation => view.with_tier(Tier::Deep),
        _ => *view,
    };
    let mut frame = ZoomFrame::new(fixed(&views[0]), &mut values, &mut columns, &mut rows)
        .map_err(|e| e.to_string())?;
    for (index, view) in views.iter().enumerate() {
        let last = index + 1 == views.len();
        if view.tier() == Tier::Perturbation {
            let (perturbed, _) = escape_scene::compute(*view, Algorithm::Exact)?;
            computed += pixels as u64;
            total += pixels as u64;
            emit.frame(escape_scene::paint(view, &perturbed, &palette))?;
            continue;
        }
        // The last frame takes only lines at exactly its own points: it is exact.
        let tolerance = tolerance.map(|percent| if last { 0 } else { percent });
        let stats = frame.advance(*view, tolerance).map_err(|e| e.to_string())?;
        computed += u64::from(stats.computed);
        total += u64::from(stats.computed + stats.reused);
        emit.frame(escape_scene::paint(view, frame.values(), &palette))?;
    }
    let share = computed as f64 / total.max(1) as f64;
    Ok(format!(
        " computed_share={share:.4} last_width={}",
        widths.last().map_or("", String::as_str)
    ))
}

/// One view, its gradient turned `step` entries a frame.
fn palette_cycle(
    request: &Request<'_>,
    step: u16,
    frames: u32,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let (view, palette) = escape_scene::view_at(request, request.width)?;
    let (values, _) = escape_scene::compute(view, Algorithm::Exact)?;
    for k in 0..frames {
        let offset = (u64::from(k) * u64::from(step) % 65_536) as u16;
        let turned = palette.turned(offset).ok_or_else(|| {
            format!(
                "--palette {}: colour cycling needs a gradient (classic, fire, gray or smooth-*)",
                request.palette
            )
        })?;
        emit.frame(escape_scene::paint(&view, &values, &turned))?;
    }
    Ok(String::new())
}

/// An L-system at orders 0 to `frames` − 1, each fitted to the picture.
fn growth(
    source: &crate::args::Source,
    seed: Option<u32>,
    frames: u32,
    size: Size,
    emit: &Emit<'_>,
) -> Result<String, String> {
    let mut text = String::new();
    let (loaded, name, _) = crate::systems::load(source, &mut text)?;
    let crate::systems::Loaded::Plain(grammar) = loaded else {
        return Err(format!(
            "{name}: growth animates plain systems; this one is parametric"
        ));
    };
    let mut grammar = *grammar;
    if let Some(seed) = seed {
        grammar.set_seed(seed);
    }
    for order in 0..frames {
        let rendered = crate::scene::render(&grammar, order, size.width, size.height, None)
            .map_err(|e| format!("{name} at order {order}: {e}"))?;
        emit.frame(rendered.display)?;
    }
    Ok(String::new())
}

/// Writes the frames `receiver` brings to `--out` (a GIF, an APNG or a folder of numbered
/// PNGs, made if missing) as they come, and the `--stats` line once the last is in,
/// all or nothing; in a folder, numbered frames past these (an earlier, longer run's)
/// are removed once these are in place.
fn write(
    receiver: &Receiver<Message>,
    arguments: &AnimateArgs,
    stats: impl FnOnce(String) -> String,
) -> Result<(), String> {
    let (out, delay_ms, count) = (&arguments.out, arguments.delay_ms, arguments.frames);
    // The next frame, or why there is none (the maker's error is reported instead).
    let next = || match receiver.recv() {
        Ok(Message::Frame(picture)) => Ok(picture),
        _ => Err(io::Error::other("the animation stopped")),
    };
    let mut plan = crate::output::Plan::new();
    let extension = out
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let paths: Vec<_>;
    let folder = !matches!(extension.as_deref(), Some("gif" | "png"));
    let made_folder = folder && !out.exists();
    match extension.as_deref() {
        Some("gif") => plan.add("--out", out, move |w| gif(count, next, delay_ms, w)),
        Some("png") => plan.add("--out", out, move |w| apng(count, next, delay_ms, w)),
        _ => {
            std::fs::create_dir_all(out).map_err(|e| format!("--out {}: {e}", out.display()))?;
            paths = (0..count)
                .map(|k| out.join(format!("frame-{k:04}.png")))
                .collect();
            for path in &paths {
                plan.add("--out", path, move |w| crate::output::png(&next()?, w));
            }
        }
    }
    plan.print_after(move || match receiver.recv() {
        Ok(Message::Done(detail)) => Ok(stats(detail)),
        _ => Err("the animation stopped".to_string()),
    });
    let written = plan.write();
    if written.is_err() && made_folder {
        // Only if empty: nothing of anyone else's is removed.
        let _ = std::fs::remove_dir(out);
    }
    written?;
    if folder {
        remove_stale_frames(out, count as usize)?;
    }
    Ok(())
}

/// Removes `frame-NNNN.png` files numbered `count` and on from `folder`: what an earlier
/// run with more frames left there.
fn remove_stale_frames(folder: &Path, count: usize) -> Result<(), String> {
    let entries =
        std::fs::read_dir(folder).map_err(|e| format!("--out {}: {e}", folder.display()))?;
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(number) = name
            .to_str()
            .and_then(|name| name.strip_prefix("frame-"))
            .and_then(|rest| rest.strip_suffix(".png"))
            .filter(|digits| digits.len() >= 4 && digits.bytes().all(|b| b.is_ascii_digit()))
            .and_then(|digits| digits.parse::<usize>().ok())
        else {
            continue;
        };
        if number >= count && entry.file_type().is_ok_and(|kind| kind.is_file()) {
            std::fs::remove_file(entry.path())
                .map_err(|e| format!("--out {}: {e}", entry.path().display()))?;
        }
    }
    Ok(())
}

/// RGB bytes of a frame, row by row.
fn rgb(frame: &SimulatorDisplay<Rgb888>) -> Vec<u8> {
    frame
        .to_rgb_output_image(&OutputSettingsBuilder::new().build())
        .as_image_buffer()
        .as_raw()
        .to_vec()
}

fn gif(
    count: u32,
    next: impl Fn() -> io::Result<Picture>,
    delay_ms: u32,
    out: &mut dyn Write,
) -> io::Result<()> {
    let mut encoder = GifEncoder::new_with_speed(out, 10);
    encoder
        .set_repeat(Repeat::Infinite)
        .map_err(io::Error::other)?;
    let delay = Delay::from_numer_denom_ms(delay_ms, 1);
    for _ in 0..count {
        let frame = next()?;
        let size = frame.size();
        let rgba = rgb(&frame)
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let image = RgbaImage::from_raw(size.width, size.height, rgba)
            .ok_or_else(|| io::Error::other("a frame of the wrong size"))?;
        encoder
            .encode_frame(Frame::from_parts(image, 0, 0, delay))
            .map_err(io::Error::other)?;
    }
    Ok(())
}

fn apng(
    count: u32,
    next: impl Fn() -> io::Result<Picture>,
    delay_ms: u32,
    out: &mut dyn Write,
) -> io::Result<()> {
    if count == 0 {
        return Ok(());
    }
    let first = next()?;
    let size = first.size();
    let mut encoder = png::Encoder::new(out, size.width, size.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_animated(count, 0).map_err(io::Error::other)?;
    let delay = u16::try_from(delay_ms).unwrap_or(u16::MAX);
    encoder
        .set_frame_delay(delay, 1000)
        .map_err(io::Error::other)?;
    let mut writer = encoder.write_header().map_err(io::Error::other)?;
    writer
        .write_image_data(&rgb(&first))
        .map_err(io::Error::other)?;
    for _ in 1..count {
        writer
            .write_image_data(&rgb(&next()?))
            .map_err(io::Error::other)?;
    }
    writer.finish().map_err(io::Error::other)
}
