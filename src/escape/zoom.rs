//! A zoom that reuses its frames, as XaoS does: each column and row of a new frame takes
//! a column or row of the previous frame that lies within a stated fraction of the new
//! pixel spacing (one old line for at most one new line, as many as can be matched), and
//! only the pixels on neither are computed.
//!
//! A frame keeps the point each of its columns and rows was computed at, and a new pixel
//! on a reused column or row is computed at that point, not at its nominal one: every
//! value is the exact value of a grid point, and the grid never strays from the nominal
//! one by more than the tolerance, however many frames reuse it (it does not drift). A
//! frame with no tolerance, such as a zoom's last, takes only lines at exactly its own
//! points, so it equals a full render (tested).
//!
//! Measured in `tests/zoom.rs` (100 frames at 1.05×, 320×240): with a tolerance of one
//! pixel, 9.2 % of each frame's pixels are computed on average (10.7 % at worst; a zoom
//! by 1.05 must compute at least 1 − 1/1.05² ≈ 9.3 % of nominal lines, a little less
//! here because lines just outside the old frame's edge are within reach); with half a
//! pixel, 30.6 %, because old lines kept at their own points bunch up and two of them
//! then reach for one new line. Which lines are taken decides the next frame: the most
//! lines, earliest first, then each moved to the free line nearest its point. Earliest
//! first alone (11.6 %) left every line at the low end of its reach and the grid
//! bunched; nearest first alone loses lines (14 %, modelled). Matching nominal lines
//! instead (taking a line's values to the new line nearest its nominal point, as a first
//! design did) computes 9.75 %, but a pixel's point then drifts a little further with
//! every frame: by frame 100 only 72 % of the pixels had the nominal point's dwell,
//! against 78 % here.
//!
//! RAM: the caller holds each frame: W×H×2 bytes of values and 8 bytes a column and a row;
//! this module keeps nothing.

use super::kernel::{Kernel, Periodicity};
use super::view::View;
use crate::error::{Error, FitError};

/// What a reusing frame did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ReuseStats {
    /// Pixels computed.
    pub computed: u32,
    /// Pixels taken from the previous frame.
    pub reused: u32,
    /// z ← z² + c steps.
    pub iterations: u64,
}

/// One frame of a zoom, in the caller's storage: its view, its values row by row, and the
/// point (Q60 bits) each column and row was computed at.
#[derive(Debug)]
pub struct ZoomFrame<'a> {
    view: View,
    values: &'a mut [u16],
    columns: &'a mut [i64],
    rows: &'a mut [i64],
}

impl<'a> ZoomFrame<'a> {
    /// A frame of `view` over `values` (W×H of them), `columns` (W) and `rows` (H); nothing
    /// computed yet. [`FitError::BufferTooSmall`] if a slice is too short.
    pub fn new(
        view: View,
        values: &'a mut [u16],
        columns: &'a mut [i64],
        rows: &'a mut [i64],
    ) -> Result<Self, Error> {
        let size = view.size();
        let pixels = size.width as usize * size.height as usize;
        for (needed, given) in [
            (pixels, values.len()),
            (size.width as usize, columns.len()),
            (size.height as usize, rows.len()),
        ] {
            if given < needed {
                return Err(Error::Fit(FitError::BufferTooSmall { needed, given }));
            }
        }
        Ok(Self {
            view,
            values,
            columns,
            rows,
        })
    }

    /// The frame's view.
    pub const fn view(&self) -> &View {
        &self.view
    }

    /// The values, row by row.
    pub fn values(&self) -> &[u16] {
        self.values
    }

    /// Computes this frame, taking from `previous` every pixel whose column and row both
    /// lie within `tolerance_percent` % of this view's pixel spacing of one of its columns
    /// and rows (`None`, or a view of another fractal, cap or shading: nothing is taken).
    pub fn compute(
        &mut self,
        previous: Option<&ZoomFrame<'_>>,
        tolerance_percent: u32,
    ) -> ReuseStats {
        let view = self.view;
        let previous = previous.filter(|p| {
            p.view.fractal == view.fractal
                && p.view.max_iterations == view.max_iterations
                && p.view.shading == view.shading
        });
        let tolerance = i128::from(view.spacing) * i128::from(tolerance_percent) / 100;
        let (old_columns, old_rows): (&[i64], &[i64]) = match previous {
            Some(p) => (
                p.columns.get(..p.view.size.width as usize).unwrap_or(&[]),
                p.rows.get(..p.view.size.height as usize).unwrap_or(&[]),
            ),
            None => (&[], &[]),
        };
        let old_width = old_columns.len();
        let old_values: &[u16] = previous.map_or(&[], |p| &*p.values);
        let mut stats = ReuseStats::default();
        let kernel = Kernel::new(&view, Periodicity::Exact);
        let (width, height) = (view.size.width, view.size.height);
        let column = |i: u32| view.column(i64::from(i));
        let row = |j: u32| view.row(i64::from(j));
        let values = &mut *self.values;
        // Sources first (old line indices, or NONE), points once the values are in.
        let columns = self.columns.get_mut(..width as usize).unwrap_or(&mut []);
        let rows = self.rows.get_mut(..height as usize).unwrap_or(&mut []);
        assign(columns, column, old_columns, tolerance);
        assign(rows, row, old_rows, tolerance);
        for (j, row_slot) in (0..height).zip(rows.iter_mut()) {
            let old_row = line_source(*row_slot);
            let row_point = point(old_row, old_rows, row(j));
            let im = kernel.part(row_point);
            let start = j as usize * width as usize;
            for (i, &column_slot) in (0..width).zip(columns.iter()) {
                let old_column = line_source(column_slot);
                let taken = old_row.zip(old_column).and_then(|(r, c)| {
                    old_values.get(r as usize * old_width + c as usize).copied()
                });
                let value = match taken {
                    Some(value) => {
                        stats.reused += 1;
                        value
                    }
                    None => {
                        let re = kernel.part(point(old_column, old_columns, column(i)));
                        let orbit = kernel.dwell(re, im);
                        stats.computed += 1;
                        stats.iterations += u64::from(orbit.iterations);
                        u16::try_from(orbit.dwell).unwrap_or(u16::MAX)
                    }
                };
                if let Some(cell) = values.get_mut(start + i as usize) {
                    *cell = value;
                }
            }
            *row_slot = row_point;
        }
        for (i, slot) in (0..width).zip(columns.iter_mut()) {
            *slot = point(line_source(*slot), old_columns, column(i));
        }
        stats
    }
}

/// A line with no old line to take.
const NONE: i64 = -1;

/// The old line a slot names, if any.
fn line_source(slot: i64) -> Option<u32> {
    u32::try_from(slot).ok()
}

/// The point a line stands for: its old line's, or its nominal one.
fn point(source: Option<u32>, old: &[i64], nominal: i128) -> i64 {
    source
        .and_then(|j| old.get(j as usize).copied())
        .unwrap_or_else(|| in_range(nominal))
}

/// Gives old lines (points `old`, running the same way as the new lines' nominal points)
/// to new lines within `tolerance` (Q60 bits) of them, one old line for at most one new
/// line, in order, as many as can be: each old line in turn takes the first new line
/// after the last one given that lies within reach (earliest first is optimal for
/// points matched to windows on a line). `slots[i]` becomes the old line's index, or
/// [`NONE`].
fn assign(slots: &mut [i64], nominal: impl Fn(u32) -> i128, old: &[i64], tolerance: i128) {
    slots.fill(NONE);
    let count = slots.len();
    if count == 0 {
        return;
    }
    let first = nominal(0);
    let step = if count > 1 { nominal(1) - first } else { 1 };
    // Both ways of running become "up".
    let sign = if step < 0 { -1 } else { 1 };
    let at = |k: usize| sign * nominal(k as u32);
    let step = step.abs().max(1);
    let mut next_free = 0;
    for (j, &o) in old.iter().enumerate() {
        let o = sign * i128::from(o);
        // The first new line at or past o − tolerance: estimated by the nominal spacing,
        // then stepped (offsets are rounded, so the spacing is not exact).
        let low = o - tolerance;
        let estimate = (low - at(0)).div_euclid(step).clamp(0, count as i128);
        let mut k = usize::try_from(estimate).unwrap_or(count).max(next_free);
        while k > next_free && at(k - 1) >= low {
            k -= 1;
        }
        while k < count && at(k) < low {
            k += 1;
        }
        if k < count && at(k) <= o + tolerance {
            if let Some(slot) = slots.get_mut(k) {
                *slot = j as i64;
            }
            next_free = k + 1;
        }
    }
    // Earliest first leaves each old line at the low end of its reach, and the grid bunches
    // up over frames. From the last, each taken line moves up to the free new line nearest
    // its point: the same lines are taken, each as near its own point as the later ones
    // allow, and the next frame finds its lines evenly spread.
    let mut limit = count;
    for k in (0..count).rev() {
        let Some(j) = slots.get(k).copied().and_then(line_source) else {
            continue;
        };
        let o = old.get(j as usize).map_or(0, |&o| sign * i128::from(o));
        let mut nearest = k;
        while nearest + 1 < limit && (at(nearest + 1) - o).abs() < (at(nearest) - o).abs() {
            nearest += 1;
        }
        if nearest != k {
            slots.swap(k, nearest);
        }
        limit = nearest;
    }
}

/// A point part within the view (±3.5, checked by `View::new`).
fn in_range(q60: i128) -> i64 {
    i64::try_from(q60).unwrap_or(0)
}
