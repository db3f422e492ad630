//! Every core of the host, the picture byte for byte the one thread's.
//!
//! An escape-time render splits into parts (a row, or a column of tiles, each), the parts
//! rendered on rayon's threads and their blocks put in place in order.
//!
//! A perturbed view renders on one thread: its reference orbit is computed into a render's
//! own storage, and a part a thread would compute it again (it stops scaling there).

use embedded_graphics::primitives::Rectangle;
use rayon::prelude::*;
use tinyfractal::escape::{Algorithm, Render, RenderStats};
use tinyfractal::render::{DwellBuffer, DwellSink};
use tinyfractal::View;

/// What a part sent its sink, kept until every part is done.
enum Block {
    Dwells(Rectangle, Vec<u16>),
    Uniform(Rectangle, u16),
}

/// A part's blocks, in the order it sent them.
#[derive(Default)]
struct Blocks(Vec<Block>);

impl DwellSink for Blocks {
    type Error = core::convert::Infallible;

    fn dwells<I: Iterator<Item = u16>>(
        &mut self,
        area: &Rectangle,
        dwells: I,
    ) -> Result<(), Self::Error> {
        self.0.push(Block::Dwells(*area, dwells.collect()));
        Ok(())
    }

    fn uniform(&mut self, area: &Rectangle, dwell: u16) -> Result<(), Self::Error> {
        self.0.push(Block::Uniform(*area, dwell));
        Ok(())
    }
}

/// Parts a thread takes on average: more than one, so a thread that drew cheap parts
/// takes more while another works through an expensive one.
const PARTS_A_THREAD: u32 = 4;

/// Renders `view` into `values` (row by row) on the current rayon pool's threads; the
/// stats summed over the parts.
pub(crate) fn render_parts(view: View, algorithm: Algorithm, values: &mut [u16]) -> RenderStats {
    let threads = u32::try_from(rayon::current_num_threads()).unwrap_or(1);
    let (units, grain) = Render::new(view, algorithm).parts();
    let groups = units.div_ceil(grain.max(1));
    let pieces = (threads * PARTS_A_THREAD).clamp(1, groups.max(1));
    let parts: Vec<(Blocks, RenderStats)> = (0..pieces)
        .into_par_iter()
        .map(|piece| {
            let (first, last) = (groups * piece / pieces, groups * (piece + 1) / pieces);
            let mut blocks = Blocks::default();
            let Ok(stats) =
                Render::new(view, algorithm).run_part(&mut blocks, first * grain..last * grain);
            (blocks, stats)
        })
        .collect();
    let mut sink = DwellBuffer::new(values, view.size().width);
    let mut total: Option<RenderStats> = None;
    for (blocks, stats) in parts {
        for block in blocks.0 {
            let Ok(()) = match block {
                Block::Dwells(area, dwells) => sink.dwells(&area, dwells.into_iter()),
                Block::Uniform(area, dwell) => sink.uniform(&area, dwell),
            };
        }
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
    total.unwrap_or_else(|| Render::new(view, algorithm).stats())
}

/// Runs `work` with a pool of `threads` threads (every core when `None`): what the
/// `--threads` option sets.
pub fn with_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, String> {
    match threads {
        None => Ok(work()),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| format!("--threads {n}: the threads could not start: {e}"))
            .map(|pool| pool.install(work)),
    }
}
