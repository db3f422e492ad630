//! A zoom that reuses its frames, as XaoS does: each column and row of a new frame takes
//! a column or row of the previous frame that lies within a stated fraction of the new
//! pixel spacing (one old line for at most one new line, as many as can be matched), and
//! only the pixels on neither are computed. One frame is enough: [`ZoomFrame::advance`]
//! moves the old values to their new places in the same storage, in an order that reads
//! every old value before it is overwritten (a board holds one frame, not two).
//!
//! A frame keeps the point each of its columns and rows was computed at, and a new pixel
//! on a reused column or row is computed at that point, not at its nominal one: every
//! value is the value of a grid point (in the tier of the frame that computed it: a zoom
//! crossing into a finer tier keeps the coarser tier's values where it reuses them), and
//! the grid never strays from the nominal
//! one by more than the tolerance, however many frames reuse it (it does not drift). A
//! frame with no tolerance, such as a zoom's last, takes only lines at exactly its own
//! points and only from a frame of its own tier, so it equals a full render (tested, and
//! fuzzed: the tier rule came from the fuzzer).
//!
//! Which lines are taken decides the next frame: the most lines, earliest first, then
//! each moved to the free line nearest its point, which computes about the least a zoom
//! must and keeps the grid even (the alternatives measured: docs/performance.md).
//!
//! RAM: the caller holds the frame: W×H cells of values (`u16`, or `u8` where RAM is short)
//! and 12 bytes a column and a row ([`ZoomLine`]); this module keeps nothing. A 128×64
//! frame of `u8` takes 10,496 bytes.

use embedded_graphics::{prelude::*, primitives::Rectangle};

use super::kernel::{Kernel, Orbit, Part, Periodicity};
use super::view::{Tier, View};
use crate::error::{Error, FitError, ViewError};
use crate::render::palette::Palette;

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

mod sealed {
    pub trait Sealed {}
    impl Sealed for u8 {}
    impl Sealed for u16 {}
}

/// A frame's cell: `u16`, or `u8` to halve a frame's RAM for views whose values stay at or
/// below 255 (dwells with a cap of at most 255).
pub trait ZoomValue: Copy + Default + sealed::Sealed {
    /// The largest value a cell holds.
    const MAX: u16;

    /// A cell holding `value` (at most [`MAX`](Self::MAX): views are checked).
    fn from_value(value: u16) -> Self;

    /// The value held.
    fn value(self) -> u16;
}

impl ZoomValue for u8 {
    const MAX: u16 = u8::MAX as u16;

    fn from_value(value: u16) -> Self {
        u8::try_from(value).unwrap_or(u8::MAX)
    }

    fn value(self) -> u16 {
        u16::from(self)
    }
}

impl ZoomValue for u16 {
    const MAX: u16 = u16::MAX;

    fn from_value(value: u16) -> Self {
        value
    }

    fn value(self) -> u16 {
        self
    }
}

/// A column or row of a frame.
///
/// The point it was computed at (Q60 bits, not always its nominal one), and while a frame is computed, the old line it takes. 12 bytes: the
/// point is kept as two 32-bit halves so that a line is aligned to 4, not 8.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ZoomLine {
    high: i32,
    low: u32,
    /// The old line taken, or [`NONE`].
    source: u16,
}

/// A line that takes no old line.
const NONE: u16 = u16::MAX;

impl ZoomLine {
    fn point(self) -> i64 {
        i64::from(self.high) << 32 | i64::from(self.low)
    }

    fn set_point(&mut self, point: i64) {
        self.high = (point >> 32) as i32;
        self.low = point as u32;
    }

    fn source(self) -> Option<usize> {
        (self.source != NONE).then_some(usize::from(self.source))
    }
}

/// One frame of a zoom, in the caller's storage: its view, its values row by row, and the
/// point each column and row was computed at.
#[derive(Debug)]
pub struct ZoomFrame<'a, V: ZoomValue = u16> {
    view: View,
    values: &'a mut [V],
    columns: &'a mut [ZoomLine],
    rows: &'a mut [ZoomLine],
    /// Whether the values and lines hold `view`'s picture.
    computed: bool,
}

impl<'a, V: ZoomValue> ZoomFrame<'a, V> {
    /// A frame of `view` over `values` (W×H of them), `columns` (W) and `rows` (H); nothing
    /// computed yet. [`FitError::BufferTooSmall`] if a slice is too short,
    /// [`FitError::CellTooNarrow`] if the view's values do not fit a `V`,
    /// [`ViewError::ZoomNeedsFixedTier`] if the view's tier is perturbation (a frame would
    /// compute it in `Deep`: render it with [`Render::perturbed`](crate::escape::Render::perturbed)).
    pub fn new(
        view: View,
        values: &'a mut [V],
        columns: &'a mut [ZoomLine],
        rows: &'a mut [ZoomLine],
    ) -> Result<Self, Error> {
        let frame = Self {
            view,
            values,
            columns,
            rows,
            computed: false,
        };
        frame.check(&view)?;
        Ok(frame)
    }

    /// Whether this frame's storage holds `view`, and `view` is computed in a fixed tier.
    fn check(&self, view: &View) -> Result<(), Error> {
        if view.tier() == Tier::Perturbation {
            return Err(Error::View(ViewError::ZoomNeedsFixedTier));
        }
        let size = view.size();
        let pixels = size.width as usize * size.height as usize;
        for (needed, given) in [
            (pixels, self.values.len()),
            (size.width as usize, self.columns.len()),
            (size.height as usize, self.rows.len()),
        ] {
            if given < needed {
                return Err(Error::Fit(FitError::BufferTooSmall { needed, given }));
            }
        }
        // Distance estimation draws the pixels near the set one above the inside value.
        let largest = view
            .inside_value()
            .saturating_add(u16::from(view.distance != 0));
        if largest > V::MAX {
            return Err(Error::Fit(FitError::CellTooNarrow {
                largest: largest.into(),
                cell_max: V::MAX.into(),
            }));
        }
        Ok(())
    }

    /// The frame's view.
    pub const fn view(&self) -> &View {
        &self.view
    }

    /// The values, row by row.
    pub fn values(&self) -> &[V] {
        self.values
    }

    /// The point (real, imaginary; Q60 bits as [`Coord`](crate::Coord) holds them) that
    /// pixel (`column`, `row`) was computed at, once the frame is computed.
    pub fn point(&self, column: u32, row: u32) -> Option<(i64, i64)> {
        let re = self.columns.get(column as usize)?.point();
        let im = self.rows.get(row as usize)?.point();
        Some((re, im))
    }

    /// Computes this frame, taking from `previous` every pixel whose column and row both
    /// lie within `tolerance_percent` % of this view's pixel spacing of one of its columns
    /// and rows (`None`, or a frame of another size, fractal, cap or shading, or with no
    /// tolerance one of another tier: nothing is taken). `previous` is trusted to hold what its own `compute` or `advance` left, even
    /// if it was wrapped again since (its storage is the frame). Tolerances above 100 %
    /// count as 100 %.
    pub fn compute(
        &mut self,
        previous: Option<&ZoomFrame<'_, V>>,
        tolerance_percent: u32,
    ) -> ReuseStats {
        let view = self.view;
        self.computed = false;
        if let Some(previous) = previous.filter(|p| compatible(&p.view, &view)) {
            let size = view.size();
            let pixels = size.width as usize * size.height as usize;
            copy(self.values, previous.values, pixels);
            copy(self.columns, previous.columns, size.width as usize);
            copy(self.rows, previous.rows, size.height as usize);
            (self.view, self.computed) = (previous.view, true);
        }
        self.step(view, Some(tolerance_percent))
    }

    /// Moves this frame to `view` in place: pixels whose column and row both lie within
    /// `tolerance_percent` % of the new pixel spacing of this frame's are taken (as
    /// [`compute`](Self::compute) takes them from a previous frame), the rest computed;
    /// `None`, or a frame not yet computed (by this value: a frame wrapped anew holds
    /// nothing it knows of) or of another size, fractal, cap or shading, computes every
    /// pixel. The storage's errors are [`new`](Self::new)'s.
    pub fn advance(
        &mut self,
        view: View,
        tolerance_percent: Option<u32>,
    ) -> Result<ReuseStats, Error> {
        self.check(&view)?;
        self.computed &= compatible(&self.view, &view);
        Ok(self.step(view, tolerance_percent))
    }

    /// Paints the frame into `target` at its origin, in one run (`fill_contiguous`).
    pub fn draw<D, P>(&self, target: &mut D, palette: &P) -> Result<(), D::Error>
    where
        D: DrawTarget,
        P: Palette<Color = D::Color>,
    {
        let size = self.view.size();
        let max = self.view.inside_value();
        let pixels = size.width as usize * size.height as usize;
        let colours = self.values.iter().take(pixels);
        target.fill_contiguous(
            &Rectangle::new(Point::zero(), size),
            colours.map(|v| palette.color(v.value(), max)),
        )
    }

    /// Computes `view` over this frame's storage, taking what lies within the tolerance of
    /// the picture held (if any). The storage is checked.
    fn step(&mut self, view: View, tolerance_percent: Option<u32>) -> ReuseStats {
        // A value from another tier can differ at the very same point: a frame with no
        // tolerance, which must be exact, takes lines only from its own tier. With a
        // tolerance, values are already those of points up to the tolerance away, and the
        // old tier was good enough for the old view, so a zoom crossing into a finer tier
        // does not compute a whole frame again.
        let same_tier = self.view.tier() == view.tier();
        let reach = tolerance_percent
            .filter(|&percent| self.computed && (percent > 0 || same_tier))
            .map(|percent| i128::from(view.spacing) * i128::from(percent.min(100)) / 100);
        self.view = view;
        let (width, height) = (view.size.width as usize, view.size.height as usize);
        let columns = self.columns.get_mut(..width).unwrap_or_default();
        let rows = self.rows.get_mut(..height).unwrap_or_default();
        assign(columns, &view, Axis::Columns, reach);
        assign(rows, &view, Axis::Rows, reach);
        let mut stats = ReuseStats::default();
        let kernel = Kernel::new(&view, Periodicity::Exact);
        let values = &mut *self.values;
        for row_pass in PASSES {
            for i in 0..height {
                let r = row_pass.line(i, height);
                let Some(&row_line) = rows.get(r).filter(|line| row_pass.takes(r, **line)) else {
                    continue;
                };
                let im = kernel.part(point(rows, r, &view, Axis::Rows));
                for pass in PASSES {
                    for i in 0..width {
                        let c = pass.line(i, width);
                        let Some(&line) = columns.get(c).filter(|line| pass.takes(c, **line))
                        else {
                            continue;
                        };
                        let taken = row_line.source().zip(line.source()).and_then(
                            |(old_row, old_column)| values.get(old_row * width + old_column),
                        );
                        let value = match taken {
                            Some(&value) => {
                                stats.reused += 1;
                                value
                            }
                            None => {
                                let re = point(columns, c, &view, Axis::Columns);
                                let orbit = dwell(&kernel, re, im);
                                stats.computed += 1;
                                stats.iterations += u64::from(orbit.iterations);
                                V::from_value(orbit.value())
                            }
                        };
                        if let Some(cell) = values.get_mut(r * width + c) {
                            *cell = value;
                        }
                    }
                }
            }
        }
        move_points(columns, &view, Axis::Columns);
        move_points(rows, &view, Axis::Rows);
        self.computed = true;
        stats
    }
}

/// The dwell at (`re`, `im`), out of line: the kernel's orbits once, not inlined into every
/// frame's loop (a frame computes a tenth of its pixels; flash is what a board lacks).
#[inline(never)]
fn dwell(kernel: &Kernel, re: i64, im: Part) -> Orbit {
    kernel.dwell(kernel.part(re), im)
}

/// Whether a frame of `old` holds values `new` may take: the same picture's kind and size.
fn compatible(old: &View, new: &View) -> bool {
    old.fractal == new.fractal
        && old.max_iterations == new.max_iterations
        && old.shading == new.shading
        && old.inside == new.inside
        && old.outside == new.outside
        && old.distance == new.distance
        && old.size == new.size
}

/// The first `count` of `from` into `to`.
fn copy<T: Copy>(to: &mut [T], from: &[T], count: usize) {
    if let (Some(to), Some(from)) = (to.get_mut(..count), from.get(..count)) {
        to.copy_from_slice(from);
    }
}

/// A frame's columns or rows.
#[derive(Debug, Clone, Copy)]
enum Axis {
    Columns,
    Rows,
}

/// Line `k`'s nominal point part (Q60) in `view`, out of line (128-bit products: a call
/// costs less flash than a copy at each of its uses).
#[inline(never)]
fn nominal(view: &View, axis: Axis, k: usize) -> i128 {
    match axis {
        Axis::Columns => view.column(k as i64),
        Axis::Rows => view.row(k as i64),
    }
}

/// The point line `k` stands for while its frame is computed: its old line's, or its
/// nominal one.
fn point(lines: &[ZoomLine], k: usize, view: &View, axis: Axis) -> i64 {
    lines
        .get(k)
        .and_then(|line| line.source())
        .and_then(|old| lines.get(old))
        .map_or_else(|| in_range(nominal(view, axis, k)), |old| old.point())
}

/// Each line's point becomes the one it stands for, in place.
#[inline(never)]
fn move_points(lines: &mut [ZoomLine], view: &View, axis: Axis) {
    let count = lines.len();
    for pass in PASSES {
        for i in 0..count {
            let k = pass.line(i, count);
            if lines.get(k).is_some_and(|line| pass.takes(k, *line)) {
                let moved = point(lines, k, view, axis);
                if let Some(line) = lines.get_mut(k) {
                    line.set_point(moved);
                }
            }
        }
    }
}

/// The three passes that move lines in place. Old lines are taken in order (the map from
/// new line to old is increasing), so a line whose old line lies at or after it is written
/// before any line after it reads, and one whose old line lies before it before any line
/// before it reads: the first, going up, then the second, going down, read every old value
/// before it is overwritten. Lines that take nothing only write, last.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Pass {
    /// Lines whose old line is at or after them, going up.
    Up,
    /// Lines whose old line is before them, going down.
    Down,
    /// Lines that take no old line.
    Fresh,
}

/// The passes in their order.
const PASSES: [Pass; 3] = [Pass::Up, Pass::Down, Pass::Fresh];

impl Pass {
    /// The `i`th line of `count` this pass visits.
    const fn line(self, i: usize, count: usize) -> usize {
        match self {
            Self::Down => count - 1 - i,
            _ => i,
        }
    }

    /// Whether line `k` moves in this pass.
    fn takes(self, k: usize, line: ZoomLine) -> bool {
        match (self, line.source()) {
            (Self::Up, Some(old)) => old >= k,
            (Self::Down, Some(old)) => old < k,
            (Self::Fresh, None) => true,
            _ => false,
        }
    }
}

/// Gives the old lines (the points `lines` hold, running the same way as the new lines'
/// nominal points) to new lines within `reach` (Q60 bits) of them, one old line for at
/// most one new line, in order, as many as can be: each old line in turn takes the first
/// new line after the last one given that lies within reach (earliest first is optimal
/// for points matched to windows on a line). `None` gives none.
#[inline(never)]
fn assign(lines: &mut [ZoomLine], view: &View, axis: Axis, reach: Option<i128>) {
    let nominal = |k: usize| nominal(view, axis, k);
    for line in lines.iter_mut() {
        line.source = NONE;
    }
    let count = lines.len();
    let Some(reach) = reach.filter(|_| count > 0) else {
        return;
    };
    // Both ways of running become "up".
    let sign = if count > 1 && nominal(1) < nominal(0) {
        -1
    } else {
        1
    };
    let at = |k: usize| sign * nominal(k);
    let old_point = |lines: &[ZoomLine], j: usize| {
        lines
            .get(j)
            .map_or(0, |line| sign * i128::from(line.point()))
    };
    // The first new line at or past the last old line's o − reach (old points run up, so
    // it only moves up), and the first not given yet.
    let (mut k, mut next_free) = (0, 0);
    for j in 0..count.min(usize::from(NONE)) {
        let o = old_point(lines, j);
        k = k.max(next_free);
        while k < count && at(k) < o - reach {
            k += 1;
        }
        if k < count && at(k) <= o + reach {
            if let Some(line) = lines.get_mut(k) {
                line.source = j as u16;
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
        let Some(j) = lines.get(k).and_then(|line| line.source()) else {
            continue;
        };
        let o = old_point(lines, j);
        let mut nearest = k;
        while nearest + 1 < limit && (at(nearest + 1) - o).abs() < (at(nearest) - o).abs() {
            nearest += 1;
        }
        if nearest != k {
            if let Some(line) = lines.get_mut(k) {
                line.source = NONE;
            }
            if let Some(line) = lines.get_mut(nearest) {
                line.source = j as u16;
            }
        }
        limit = nearest;
    }
}

/// A point part within the view (±3.5, checked by `View::new`).
fn in_range(q60: i128) -> i64 {
    i64::try_from(q60).unwrap_or(0)
}
