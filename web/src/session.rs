//! An escape-time view drawn in budgeted steps (`Render::step`, a preview first), so the
//! page shows it growing and a newer request can replace it between steps: the explorer's
//! way of drawing. Views of the fixed tiers only; a perturbed view (whose render borrows
//! its reference orbit) is drawn whole.

use tinyfractal::escape::{Algorithm, Render, Tier};
use tinyfractal::render::DwellBuffer;
use tinyfractal::View;
use tinyfractal_simulator::escape_scene::{self, HostPalette};

use crate::picture::Picture;

/// Iterations a step computes: a few tens of milliseconds in a browser.
pub const STEP_ITERATIONS: u64 = 2_000_000;

/// A view being drawn: its render, palette and the pixels' values so far.
#[derive(Debug)]
pub struct Session {
    render: Render<'static>,
    view: View,
    palette: HostPalette,
    values: Vec<u16>,
}

impl Session {
    /// A session for `request`, or `None` if its view is drawn by perturbation.
    pub fn start(request: &escape_scene::Request<'_>) -> Result<Option<Self>, String> {
        let (view, palette) = escape_scene::view_at(request, request.width)?;
        if view.tier() == Tier::Perturbation {
            return Ok(None);
        }
        let size = view.size();
        Ok(Some(Self {
            render: Render::new(view, Algorithm::Fast).with_preview(8),
            view,
            palette,
            values: vec![0; (size.width * size.height) as usize],
        }))
    }

    /// Computes at most `iterations` more; whether the picture is complete.
    pub fn step(&mut self, iterations: u64) -> bool {
        let width = self.view.size().width;
        let Ok(progress) = self
            .render
            .step(&mut DwellBuffer::new(&mut self.values, width), iterations);
        progress.is_complete()
    }

    /// The picture so far.
    pub fn picture(&self) -> Picture {
        Picture::of(&escape_scene::paint(
            &self.view,
            &self.values,
            &self.palette,
        ))
    }

    /// What the page shows beside it: the tier, and the share done.
    pub fn status(&self) -> String {
        let progress = self.render.progress();
        let stats = self.render.stats();
        format!(
            "tier={} iterations={} done={}/{}",
            stats.tier.name(),
            stats.iterations,
            progress.done,
            progress.total
        )
    }
}
