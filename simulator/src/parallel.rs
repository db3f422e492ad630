//! Every core of the host, the picture byte for byte the one thread's.
//!
//! An escape-time render splits into parts (rows, or columns of tiles), each part rendered
//! on one of rayon's threads into its own strip of the picture, the strips then copied in.
//!
//! A perturbed view computes its reference orbit (and series) once, in one render that each
//! part then clones: the parts share the orbit, read only, and count their units from
//! that render's own tiles.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use rayon::prelude::*;
use tinyfractal::escape::ReferencePoint;
use tinyfractal::escape::{Algorithm, ReferenceOrbit, Render, RenderStats, Tier, TILE};
use tinyfractal::render::{DwellBuffer, DwellSink};
use tinyfractal::View;

/// One part's own piece of the picture: the dwells of `area`, row by row, written as the
/// part sends them (its blocks all fall inside it).
struct Strip {
    area: Rectangle,
    values: Vec<u16>,
}

impl DwellSink for Strip {
    type Error = core::convert::Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Self::Error> {
        let within = area.translate(-self.area.top_left);
        DwellBuffer::new(&mut self.values, self.area.size.width).dwells(&within, dwells)
    }

    fn uniform(&mut self, area: &Rectangle, dwell: u16) -> Result<(), Self::Error> {
        let within = area.translate(-self.area.top_left);
        DwellBuffer::new(&mut self.values, self.area.size.width).uniform(&within, dwell)
    }
}

/// Parts a thread takes on average: more than one, so a thread that drew cheap parts
/// takes more while another works through an expensive one.
const PARTS_A_THREAD: u32 = 16;

/// The piece of the picture units `units` cover: rows for `Exact`, columns of tiles for
/// `Fast` (every row: a symmetric view's tiles are mirrored within their column).
fn area_of(
    view: &View,
    algorithm: Algorithm,
    units: core::ops::Range<u32>,
    grain: u32,
) -> Rectangle {
    let size = view.size();
    match algorithm {
        Algorithm::Exact => Rectangle::new(
            Point::new(0, units.start as i32),
            Size::new(
                size.width,
                units.end.min(size.height) - units.start.min(size.height),
            ),
        ),
        Algorithm::Fast => {
            let x0 = (units.start / grain * TILE).min(size.width);
            let x1 = (units.end / grain * TILE).min(size.width);
            Rectangle::new(Point::new(x0 as i32, 0), Size::new(x1 - x0, size.height))
        }
    }
}

/// A render split into pieces for a number of threads: the render every piece clones (a
/// perturbed one with its reference orbit computed) and how its units group.
struct Split<'r> {
    view: View,
    algorithm: Algorithm,
    base: Render<'r>,
    units: u32,
    grain: u32,
    groups: u32,
    pieces: u32,
}

impl<'r> Split<'r> {
    /// `view` split for `threads` threads, [`PARTS_A_THREAD`] pieces each; a perturbed
    /// view's reference orbit in `reference`.
    fn new(
        view: View,
        algorithm: Algorithm,
        threads: u32,
        reference: &'r mut Vec<ReferencePoint>,
    ) -> Result<Self, String> {
        let base = if view.tier() == Tier::Perturbation {
            reference.resize(
                ReferenceOrbit::points_needed(&view),
                ReferencePoint::default(),
            );
            Render::perturbed(view, algorithm, reference).map_err(|e| e.to_string())?
        } else {
            Render::new(view, algorithm)
        };
        let (units, grain) = base.parts();
        let grain = grain.max(1);
        let groups = units.div_ceil(grain);
        let pieces = (threads * PARTS_A_THREAD).clamp(1, groups.max(1));
        Ok(Self {
            view,
            algorithm,
            base,
            units,
            grain,
            groups,
            pieces,
        })
    }

    /// Renders piece `piece` into a strip of its own.
    fn run(&self, piece: u32) -> (Strip, RenderStats) {
        let (groups, pieces, grain) = (self.groups, self.pieces, self.grain);
        let (first, last) = (groups * piece / pieces, groups * (piece + 1) / pieces);
        let units = first * grain..(last * grain).min(self.units);
        let area = area_of(&self.view, self.algorithm, units.clone(), grain);
        let cells = area.size.width as usize * area.size.height as usize;
        let mut strip = Strip {
            area,
            values: vec![0; cells],
        };
        let Ok(stats) = self.base.clone().run_part(&mut strip, units);
        (strip, stats)
    }
}

/// A model of `view` on `threads` threads: the speedup over one thread of its pieces.
///
/// Each piece takes time in proportion to its work (its iterations plus its pixels), the
/// pieces are handed in order to whichever thread is free first (as rayon's work stealing
/// does at best), and nothing else runs. What it leaves out is one thread's: a perturbed
/// view's reference orbit, the painting and the encoder (docs/performance.md).
pub fn modelled_speedup(view: View, algorithm: Algorithm, threads: u32) -> Result<f64, String> {
    let mut reference = Vec::new();
    let split = Split::new(view, algorithm, threads.max(1), &mut reference)?;
    let mut loads = vec![0u64; threads.max(1) as usize];
    let mut total = 0;
    for piece in 0..split.pieces {
        let (_, stats) = split.run(piece);
        let work = stats.iterations + u64::from(stats.pixels);
        total += work;
        if let Some(least) = loads.iter_mut().min() {
            *least += work;
        }
    }
    let longest = loads.iter().copied().max().unwrap_or(0).max(1);
    Ok(total as f64 / longest as f64)
}

/// Renders `view` into `values` (row by row) on the current rayon pool's threads; the
/// stats summed over the parts.
pub(crate) fn render_parts(
    view: View,
    algorithm: Algorithm,
    values: &mut [u16],
) -> Result<RenderStats, String> {
    let threads = u32::try_from(rayon::current_num_threads()).unwrap_or(1);
    let mut reference = Vec::new();
    let split = Split::new(view, algorithm, threads, &mut reference)?;
    let parts: Vec<(Strip, RenderStats)> = (0..split.pieces)
        .into_par_iter()
        .map(|piece| split.run(piece))
        .collect();
    // The strips copied in a row of the picture at a time, the rows on every thread.
    let width = view.size().width as usize;
    if width > 0 {
        values
            .par_chunks_mut(width)
            .enumerate()
            .for_each(|(y, row)| {
                for (strip, _) in &parts {
                    let (x0, y0) = (
                        strip.area.top_left.x as usize,
                        strip.area.top_left.y as usize,
                    );
                    let (w, h) = (
                        strip.area.size.width as usize,
                        strip.area.size.height as usize,
                    );
                    if w == 0 || y < y0 || y >= y0 + h {
                        continue;
                    }
                    let from = strip.values.get((y - y0) * w..(y - y0 + 1) * w);
                    if let (Some(to), Some(from)) = (row.get_mut(x0..x0 + w), from) {
                        to.copy_from_slice(from);
                    }
                }
            });
    }
    let mut total: Option<RenderStats> = None;
    for (_, stats) in parts {
        total = Some(match total {
            None => stats,
            Some(sum) => RenderStats {
                iterations: sum.iterations + stats.iterations,
                pixels: sum.pixels + stats.pixels,
                draw_calls: sum.draw_calls + stats.draw_calls,
                rebases: sum.rebases + stats.rebases,
                skipped: sum.skipped + stats.skipped,
                ..sum
            },
        });
    }
    Ok(total.unwrap_or_else(|| Render::new(view, algorithm).stats()))
}

/// Makes frames `0..count` on the current pool's threads and hands them to `emit` in
/// order: the frames one thread makes, in its order.
///
/// As many frames are made at a time as the pool has threads, so at most a batch is held.
/// The first error (of `make`, in frame order, or of `emit`) stops it, after the frames
/// before it were emitted.
pub fn frames_in_order<P: Send>(
    count: u32,
    make: impl Fn(u32) -> Result<P, String> + Sync,
    mut emit: impl FnMut(P) -> Result<(), String>,
) -> Result<(), String> {
    let batch = u32::try_from(rayon::current_num_threads())
        .unwrap_or(1)
        .max(1);
    let mut start = 0;
    while start < count {
        let end = start.saturating_add(batch).min(count);
        let made: Vec<Result<P, String>> = (start..end).into_par_iter().map(&make).collect();
        for frame in made {
            emit(frame?)?;
        }
        start = end;
    }
    Ok(())
}

/// Each of the pool's threads' stack.
///
/// The host's L-system walkers keep 1,024 levels by value, and an unoptimised build
/// copies them from frame to frame: the deepest scene's frames then need several times
/// a thread's default 2 MiB (docs/memory.md). Only what a thread touches is committed.
pub const WORKER_STACK: usize = 32 << 20;

/// Runs `work` with a pool of `threads` threads (every core when `None`), each with a
/// stack of [`WORKER_STACK`] bytes: what the `--threads` option sets.
///
/// With `None`, `work` runs on the calling thread (the explorer's window stays on the
/// main thread, where some platforms require it) and its parallel parts on rayon's global
/// pool, made here with that stack unless the process made it before.
pub fn with_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, String> {
    let builder = rayon::ThreadPoolBuilder::new().stack_size(WORKER_STACK);
    match threads {
        None => {
            // Fails only where the global pool already exists: it is then kept as it is.
            let _ = builder.build_global();
            Ok(work())
        }
        Some(n) => builder
            .num_threads(n)
            .build()
            .map_err(|e| format!("--threads {n}: the threads could not start: {e}"))
            .map(|pool| pool.install(work)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tinyfractal::math::DeepCoord;
    use tinyfractal::Fractal;

    /// The model is exact where it must be (one thread: no speedup; a view of one column
    /// of tiles: nothing to share), and holds the 4096×4096 full view's scaling that
    /// docs/performance.md states, to fewer threads in `Fast` than in `Exact` because
    /// `Fast`'s pieces are whole columns of tiles, handed out in order.
    #[test]
    fn the_model_scales_within_ten_percent_of_ideal() {
        let full = |size: Size, width: &str| {
            View::new(
                Fractal::Mandelbrot,
                (
                    tinyfractal::Coord::parse("-0.75").unwrap(),
                    tinyfractal::Coord::default(),
                ),
                tinyfractal::Coord::parse(width).unwrap(),
                size,
                256,
            )
            .unwrap()
        };
        let view = full(Size::new(4096, 4096), "3.5");
        for (algorithm, most) in [(Algorithm::Fast, 8), (Algorithm::Exact, 16)] {
            let one = modelled_speedup(view, algorithm, 1).unwrap();
            assert!((one - 1.0).abs() < 1e-12, "{one}");
            for threads in [2, 4, 8, 16].into_iter().filter(|&t| t <= most) {
                let speedup = modelled_speedup(view, algorithm, threads).unwrap();
                let efficiency = speedup / f64::from(threads);
                assert!(
                    (0.9..=1.0 + 1e-12).contains(&efficiency),
                    "{algorithm:?} on {threads}: {speedup:.2}x"
                );
            }
        }
        let speedup =
            modelled_speedup(full(Size::new(16, 512), "0.1"), Algorithm::Fast, 8).unwrap();
        assert!((speedup - 1.0).abs() < 1e-12, "{speedup}");
    }

    /// A perturbed view split into parts on several threads is the one render's picture,
    /// pixel for pixel, and its stats are that render's: the parts share one reference
    /// orbit and count their units from the perturbed render's own tiles.
    #[test]
    fn a_perturbed_view_in_parts_is_the_whole_render() {
        let deep = |text: &str| DeepCoord::parse(text).unwrap();
        let view = View::deep(
            Fractal::Mandelbrot,
            (
                deep("-0.1010963638456221610257854457386225654638"),
                deep("0.9562865108091415007710960577299774358098"),
            ),
            deep("1e-30"),
            Size::new(150, 97),
            1000,
        )
        .unwrap();
        assert_eq!(view.tier(), Tier::Perturbation);
        for algorithm in [Algorithm::Fast, Algorithm::Exact] {
            let mut whole = vec![0u16; 150 * 97];
            let mut reference =
                vec![ReferencePoint::default(); ReferenceOrbit::points_needed(&view)];
            let Ok(expected) = Render::perturbed(view, algorithm, &mut reference)
                .unwrap()
                .run(&mut DwellBuffer::new(&mut whole, 150));
            let mut parts = vec![0u16; 150 * 97];
            let stats = with_threads(Some(3), || render_parts(view, algorithm, &mut parts))
                .unwrap()
                .unwrap();
            assert!(whole == parts, "{algorithm:?}: the pictures differ");
            assert!(!whole.contains(&0), "{algorithm:?}: a pixel left unwritten");
            assert_eq!(
                (stats.iterations, stats.pixels, stats.rebases, stats.skipped),
                (
                    expected.iterations,
                    expected.pixels,
                    expected.rebases,
                    expected.skipped
                ),
                "{algorithm:?}"
            );
        }
    }

    /// Work on a pool of a chosen number of threads has the stack it is promised: a
    /// frame four times a thread's default stack holds (it would abort the test on a
    /// default thread). `tests/stack.rs` checks the global pool, in a process of its own.
    #[test]
    fn the_pool_holds_frames_beyond_a_default_stack() {
        #[inline(never)]
        fn deep() -> usize {
            let frame = std::hint::black_box([1u8; 8 << 20]);
            frame.iter().map(|&byte| usize::from(byte)).sum()
        }
        let both = with_threads(Some(2), || rayon::join(deep, deep));
        assert_eq!(both, Ok((8 << 20, 8 << 20)));
    }
}
