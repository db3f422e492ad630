//! Lines to pixels, in runs: each horizontal or vertical run of a line is one `fill_solid`.
//!
//! On SPI displays a `draw_iter` pixel costs a whole address-window command, while a run
//! costs one window for all its pixels, so runs are what make lines cheap there.
//! The pixel at major-axis step `t` of a line from `(x0, y0)` to `(x1, y1)` (x-major) is
//! `y0 + round(t·dy/dx)` with halves rounded up: the nearest pixel to the ideal line.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// The runs of a line, clipped on its major axis to `clip` (rows or columns outside it are
/// never visited, so a segment far off-screen costs nothing). In `i64` for any line, in
/// `i32` for one that lies inside a clip of at most 2²⁹ a side (two instructions fewer a
/// step and half the set-up on 32-bit cores: the lines a drawing mostly has).
#[derive(Debug, Clone)]
pub(crate) struct Runs<T = i64> {
    /// Start on the major axis, and its direction (+1 or -1).
    major: T,
    major_dir: T,
    minor: T,
    minor_dir: T,
    /// Steps left, including the current one.
    remaining: T,
    /// Twice the minor and major lengths, and the Bresenham remainder.
    twice_minor: T,
    twice_major: T,
    remainder: T,
    x_major: bool,
}

/// What a run's arithmetic needs of its integer type.
pub(crate) trait RunInt:
    Copy
    + Ord
    + From<i32>
    + core::ops::Add<Output = Self>
    + core::ops::Sub<Output = Self>
    + core::ops::Mul<Output = Self>
    + core::ops::AddAssign
    + core::ops::SubAssign
{
    const ZERO: Self;
    const ONE: Self;
    fn abs(self) -> Self;
    /// To i32 (a run's ends are inside the clip: always exact).
    fn to_i32(self) -> i32;
    /// A run's length as a rectangle's side.
    fn to_u32(self) -> u32;
}

impl RunInt for i32 {
    const ZERO: Self = 0;
    const ONE: Self = 1;
    fn abs(self) -> Self {
        i32::abs(self)
    }
    fn to_i32(self) -> i32 {
        self
    }
    fn to_u32(self) -> u32 {
        u32::try_from(self).unwrap_or(0)
    }
}

impl RunInt for i64 {
    const ZERO: Self = 0;
    const ONE: Self = 1;
    fn abs(self) -> Self {
        i64::abs(self)
    }
    fn to_i32(self) -> i32 {
        i32::try_from(self).unwrap_or(i32::MAX)
    }
    fn to_u32(self) -> u32 {
        u32::try_from(self).unwrap_or(0)
    }
}

/// Largest side of a clip whose lines run in `i32`: twice a length and a remainder stay
/// below 2³¹.
const SHORT_CLIP: u32 = 1 << 29;

/// A line seen along its major axis: where it starts on both axes, its directions, its
/// length in major steps and twice its extents (the Bresenham quantities).
struct Line<T> {
    x_major: bool,
    major0: T,
    minor0: T,
    major_dir: T,
    minor_dir: T,
    length: T,
    twice_major: T,
    twice_minor: T,
}

impl<T: RunInt> Line<T> {
    fn of(from: Point, to: Point) -> Self {
        let (x0, y0, x1, y1) = (
            T::from(from.x),
            T::from(from.y),
            T::from(to.x),
            T::from(to.y),
        );
        let (dx, dy) = (x1 - x0, y1 - y0);
        let x_major = dx.abs() >= dy.abs();
        let (major0, minor0, d_major, d_minor) = if x_major {
            (x0, y0, dx, dy)
        } else {
            (y0, x0, dy, dx)
        };
        let direction = |d: T| T::from(if d < T::ZERO { -1 } else { 1 });
        let length = d_major.abs();
        Self {
            x_major,
            major0,
            minor0,
            major_dir: direction(d_major),
            minor_dir: direction(d_minor),
            length,
            twice_major: T::from(2) * length.max(T::ONE),
            twice_minor: T::from(2) * d_minor.abs(),
        }
    }

    /// The runs from major step `first` to `last`, the minor axis `offset` steps in there
    /// with Bresenham remainder `remainder`.
    fn runs(self, (first, last): (T, T), (offset, remainder): (T, T)) -> Runs<T> {
        Runs {
            major: self.major0 + self.major_dir * first,
            major_dir: self.major_dir,
            minor: self.minor0 + self.minor_dir * offset,
            minor_dir: self.minor_dir,
            remaining: (last - first + T::ONE).max(T::ZERO),
            twice_minor: self.twice_minor,
            twice_major: self.twice_major,
            remainder,
            x_major: self.x_major,
        }
    }

    /// The minor offset and remainder one step in: the quotient there is 0 or 1
    /// (|d_minor| ≤ |d_major|), so no division.
    fn one_step_in(&self) -> (T, T) {
        let numerator = self.twice_minor + self.length;
        if numerator >= self.twice_major {
            (T::ONE, numerator - self.twice_major)
        } else {
            (T::ZERO, numerator)
        }
    }
}

impl Runs<i32> {
    /// The runs of a line whose ends both lie inside a clip of at most [`SHORT_CLIP`] a
    /// side: nothing to clip, and every quantity fits an i32. The same runs as
    /// [`Runs::new`] gives.
    fn inside(from: Point, to: Point, skip_first: bool) -> Self {
        let line = Line::<i32>::of(from, to);
        let last = line.length;
        if skip_first {
            let start = line.one_step_in();
            line.runs((1, last), start)
        } else {
            let length = line.length;
            line.runs((0, last), (0, length))
        }
    }
}

impl Runs {
    /// The runs of the line `from`–`to` (both ends included, unless `skip_first`).
    pub(crate) fn new(from: Point, to: Point, skip_first: bool, clip: &Rectangle) -> Self {
        let line = Line::<i64>::of(from, to);
        let (low, high) = clip_range(clip, line.x_major);
        let (major0, length) = (line.major0, line.length);
        // Steps t in [first, last] keep the major coordinate inside the clip range.
        let (first, last) = if line.major_dir > 0 {
            ((low - major0).max(0), (high - major0).min(length))
        } else {
            ((major0 - high).max(0), (major0 - low).min(length))
        };
        let first = if skip_first { first.max(1) } else { first };
        let (twice_major, twice_minor) = (line.twice_major, line.twice_minor);
        // Closed form at t = first: offset = floor((t·2|d_minor| + |d_major|) / 2|d_major|).
        // An unclipped line starts at t = 0 or 1 and needs no division at all; a clipped one
        // usually fits i64 (64-bit division is much cheaper than 128-bit on Cortex-M).
        let start = if first == 0 {
            (0, length)
        } else if first == 1 {
            // A continuing line, which starts one step in.
            line.one_step_in()
        } else {
            match first
                .checked_mul(twice_minor)
                .and_then(|n| n.checked_add(length))
            {
                Some(numerator) => (numerator / twice_major, numerator % twice_major),
                None => {
                    let numerator =
                        i128::from(first) * i128::from(twice_minor) + i128::from(length);
                    let twice_major = i128::from(twice_major);
                    (
                        i64::try_from(numerator / twice_major).unwrap_or(0),
                        i64::try_from(numerator % twice_major).unwrap_or(0),
                    )
                }
            }
        };
        line.runs((first, last), start)
    }
}

/// The inclusive range of the major axis inside `clip` (empty if `clip` is).
fn clip_range(clip: &Rectangle, x_major: bool) -> (i64, i64) {
    let (start, length) = if x_major {
        (clip.top_left.x, clip.size.width)
    } else {
        (clip.top_left.y, clip.size.height)
    };
    let start = i64::from(start);
    (start, start + i64::from(length) - 1)
}

impl<T: RunInt> Iterator for Runs<T> {
    type Item = Rectangle;

    fn next(&mut self) -> Option<Rectangle> {
        if self.remaining <= T::ZERO {
            return None;
        }
        let run_start = self.major;
        let minor = self.minor;
        let mut length = T::ZERO;
        while self.remaining > T::ZERO && self.minor == minor {
            length += T::ONE;
            self.remaining -= T::ONE;
            self.major += self.major_dir;
            self.remainder += self.twice_minor;
            if self.remainder >= self.twice_major {
                self.remainder -= self.twice_major;
                self.minor += self.minor_dir;
            }
        }
        let low = if self.major_dir > T::ZERO {
            run_start
        } else {
            run_start - (length - T::ONE)
        };
        let (low, minor) = (low.to_i32(), minor.to_i32());
        let length = length.to_u32();
        Some(if self.x_major {
            Rectangle::new(Point::new(low, minor), Size::new(length, 1))
        } else {
            Rectangle::new(Point::new(minor, low), Size::new(1, length))
        })
    }
}

/// Draws the line `from`–`to` in `color`, one `fill_solid` per run.
pub(crate) fn draw_line<D: DrawTarget>(
    target: &mut D,
    from: Point,
    to: Point,
    skip_first: bool,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    let short = clip.size.width <= SHORT_CLIP && clip.size.height <= SHORT_CLIP;
    if short && clip.contains(from) && clip.contains(to) {
        for run in Runs::inside(from, to, skip_first) {
            target.fill_solid(&run, color)?;
        }
    } else {
        for run in Runs::new(from, to, skip_first, clip) {
            target.fill_solid(&run, color)?;
        }
    }
    Ok(())
}

/// [`draw_line`], with a line that goes on from a neighbouring pixel (its first pixel
/// skipped) drawn in line: only its end pixel is new, and it joins `run`, the pixels such
/// steps drew before it, where it extends that run along its row or column in the same
/// colour. Pictures finer than their pixels are mostly such steps (the snowflake on the
/// OLED: two in three of its segments): each saves the line's set-up, and a joined pixel
/// an address window on a display. A longer line sends the run first, so pixels only
/// change order within a run of one colour: the picture is the same.
#[inline(always)]
pub(crate) fn draw_line_on<D: DrawTarget>(
    target: &mut D,
    run: &mut PendingRun<D::Color>,
    from: Point,
    to: Point,
    skip_first: bool,
    color: D::Color,
    clip: &Rectangle,
) -> Result<(), D::Error> {
    if skip_first && from.x.abs_diff(to.x) <= 1 && from.y.abs_diff(to.y) <= 1 {
        if from != to && clip.contains(to) {
            run.add(target, to, color)?;
        }
        return Ok(());
    }
    run.send(target)?;
    draw_line(target, from, to, skip_first, color, clip)
}

/// Pixels drawn one after another, not yet sent: a run along a row or a column, in one
/// colour. Whoever draws through it sends it ([`send`](Self::send)) before drawing
/// anything else, and at the end.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PendingRun<C> {
    pending: Option<(Rectangle, C)>,
}

impl<C> Default for PendingRun<C> {
    fn default() -> Self {
        Self { pending: None }
    }
}

impl<C: PixelColor> PendingRun<C> {
    /// Adds pixel `p`: at either end of the run, along its row or column, in its colour,
    /// it extends the run; otherwise the run is sent and `p` starts the next.
    #[inline(always)]
    pub(crate) fn add<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
        p: Point,
        color: C,
    ) -> Result<(), D::Error> {
        if let Some((run, run_color)) = &mut self.pending {
            if *run_color == color {
                if let Some(joined) = joined(*run, p) {
                    *run = joined;
                    return Ok(());
                }
            }
        }
        self.send(target)?;
        self.pending = Some((Rectangle::new(p, Size::new(1, 1)), color));
        Ok(())
    }

    /// Sends the pending run, if any.
    #[inline(always)]
    pub(crate) fn send<D: DrawTarget<Color = C>>(
        &mut self,
        target: &mut D,
    ) -> Result<(), D::Error> {
        match self.pending.take() {
            Some((run, color)) => target.fill_solid(&run, color),
            None => Ok(()),
        }
    }
}

/// `run` with `p` added at one of its ends, along its row or column (either, for a single
/// pixel); `None` where `p` is not there.
#[inline(always)]
fn joined(run: Rectangle, p: Point) -> Option<Rectangle> {
    let (top_left, size) = (run.top_left, run.size);
    let along_row = size.height == 1 && p.y == top_left.y;
    let along_column = size.width == 1 && p.x == top_left.x;
    // Widths and heights are under 2^31 (a run stays inside a clip of i32 pixels).
    let (width, height) = (size.width as i32, size.height as i32);
    if along_row && p.x == top_left.x + width {
        Some(Rectangle::new(top_left, Size::new(size.width + 1, 1)))
    } else if along_row && p.x == top_left.x - 1 {
        Some(Rectangle::new(p, Size::new(size.width + 1, 1)))
    } else if along_column && p.y == top_left.y + height {
        Some(Rectangle::new(top_left, Size::new(1, size.height + 1)))
    } else if along_column && p.y == top_left.y - 1 {
        Some(Rectangle::new(p, Size::new(1, size.height + 1)))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    /// A 12×9 target that records every run sent (`fill_solid`, or a pixel drawn alone)
    /// and keeps the last colour sent to each of its pixels.
    #[derive(Default)]
    struct Recorded {
        runs: Vec<Rectangle>,
        image: [[Option<embedded_graphics::pixelcolor::BinaryColor>; 12]; 9],
    }

    impl OriginDimensions for Recorded {
        fn size(&self) -> Size {
            Size::new(12, 9)
        }
    }

    impl DrawTarget for Recorded {
        type Color = embedded_graphics::pixelcolor::BinaryColor;
        type Error = core::convert::Infallible;

        fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(
            &mut self,
            pixels: I,
        ) -> Result<(), Self::Error> {
            for Pixel(p, c) in pixels {
                self.fill_solid(&Rectangle::new(p, Size::new(1, 1)), c)?;
            }
            Ok(())
        }

        fn fill_solid(&mut self, area: &Rectangle, c: Self::Color) -> Result<(), Self::Error> {
            self.runs.push(*area);
            for p in area.intersection(&self.bounding_box()).points() {
                self.image[p.y as usize][p.x as usize] = Some(c);
            }
            Ok(())
        }
    }

    /// A step to any neighbouring pixel (or none) sends what `draw_line` sends inside the
    /// clip, run for run, and nothing outside it (`draw_line` clips the major axis only and
    /// leaves the minor one to the target), with its first pixel skipped or not, inside the
    /// clip, across its edge and out.
    #[test]
    fn steps_to_neighbours_send_what_lines_send() {
        use embedded_graphics::pixelcolor::BinaryColor;
        let clips = [
            Rectangle::new(Point::new(0, 0), Size::new(64, 64)),
            Rectangle::new(Point::new(5, 5), Size::new(1, 1)),
            Rectangle::new(Point::new(5, 5), Size::new(2, 3)),
            Rectangle::new(Point::new(-3, 4), Size::new(9, 2)),
        ];
        for clip in &clips {
            for x in 3..8 {
                for y in 3..8 {
                    let from = Point::new(x, y);
                    for to in Rectangle::new(from - Point::new(2, 2), Size::new(5, 5)).points() {
                        for skip_first in [false, true] {
                            let (mut line, mut step) = (Recorded::default(), Recorded::default());
                            let on = BinaryColor::On;
                            let _ = draw_line(&mut line, from, to, skip_first, on, clip);
                            let mut run = PendingRun::default();
                            let _ =
                                draw_line_on(&mut step, &mut run, from, to, skip_first, on, clip);
                            let _ = run.send(&mut step);
                            let inside = |calls: &Recorded| -> Vec<Rectangle> {
                                calls
                                    .runs
                                    .iter()
                                    .map(|run| run.intersection(clip))
                                    .filter(|run| !run.is_zero_sized())
                                    .collect()
                            };
                            let label = std::format!("{from:?} to {to:?}, {skip_first}, {clip:?}");
                            assert_eq!(inside(&line), inside(&step), "{label}");
                            if skip_first && (to - from).x.abs() <= 1 && (to - from).y.abs() <= 1 {
                                assert_eq!(inside(&step), step.runs, "{label}");
                            }
                        }
                    }
                }
            }
        }
    }

    /// Steps joined into runs paint the same picture as each line sent alone (the last
    /// colour sent to a pixel wins), over random walks of steps to neighbours and longer
    /// lines in two colours, some of them leaving the clip; every run is one row or one
    /// column, and there are no more of them than the lines alone send.
    #[test]
    fn joined_steps_paint_what_lines_paint() {
        use embedded_graphics::pixelcolor::BinaryColor;
        use proptest::prelude::*;
        let clip = Rectangle::new(Point::new(0, 0), Size::new(12, 9));
        let step = (-2i32..=2, -2i32..=2, any::<bool>(), any::<bool>());
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        runner
            .run(&proptest::collection::vec(step, 1..80), |steps| {
                let (mut joined, mut single) = (Recorded::default(), Recorded::default());
                let mut run = PendingRun::default();
                let mut at = Point::new(5, 4);
                for &(dx, dy, on, skip_first) in &steps {
                    let to = at + Point::new(dx, dy);
                    let color = if on {
                        BinaryColor::On
                    } else {
                        BinaryColor::Off
                    };
                    let _ = draw_line(&mut single, at, to, skip_first, color, &clip);
                    let _ = draw_line_on(&mut joined, &mut run, at, to, skip_first, color, &clip);
                    at = to;
                }
                let _ = run.send(&mut joined);
                prop_assert_eq!(joined.image, single.image);
                prop_assert!(joined.runs.len() <= single.runs.len());
                for r in &joined.runs {
                    prop_assert!(r.size.width == 1 || r.size.height == 1, "{:?}", r);
                }
                Ok(())
            })
            .unwrap();
    }

    fn pixels(from: Point, to: Point, clip: &Rectangle) -> Vec<Point> {
        Runs::new(from, to, false, clip)
            .flat_map(|run| run.points().collect::<Vec<_>>())
            .collect()
    }

    /// Every pixel is the nearest to the ideal line on its major-axis step, there is exactly
    /// one per step, and the ends are the endpoints: checked with f64 geometry.
    #[test]
    fn runs_are_the_nearest_pixels() {
        let clip = Rectangle::new(Point::new(-100, -100), Size::new(400, 400));
        let ends = [-37, -5, -1, 0, 1, 2, 7, 19, 64];
        for &x0 in &ends {
            for &y0 in &ends {
                for &(x1, y1) in &[(3, 50), (50, 3), (-20, 9), (9, -20), (64, 64), (x0, y0)] {
                    let (from, to) = (Point::new(x0, y0), Point::new(x1, y1));
                    let got = pixels(from, to, &clip);
                    let (dx, dy) = (f64::from(x1 - x0), f64::from(y1 - y0));
                    let steps = dx.abs().max(dy.abs()) as usize;
                    assert_eq!(got.len(), steps + 1, "{from:?}-{to:?}");
                    for p in &got {
                        let (major_t, minor_err) = if dx.abs() >= dy.abs() {
                            let t = if dx == 0.0 {
                                0.0
                            } else {
                                f64::from(p.x - x0) / dx
                            };
                            (t, (f64::from(y0) + t * dy - f64::from(p.y)).abs())
                        } else {
                            let t = f64::from(p.y - y0) / dy;
                            (t, (f64::from(x0) + t * dx - f64::from(p.x)).abs())
                        };
                        assert!(minor_err <= 0.5 + 1e-9, "{p:?} on {from:?}-{to:?}");
                        assert!((-1e-9..=1.0 + 1e-9).contains(&major_t));
                    }
                    assert!(got.contains(&from) && got.contains(&to));
                }
            }
        }
    }

    #[test]
    fn clipping_keeps_exactly_the_inside_pixels() {
        let everything = Rectangle::new(Point::new(-1000, -1000), Size::new(3000, 3000));
        let clip = Rectangle::new(Point::new(10, 5), Size::new(30, 20));
        for &(x0, y0, x1, y1) in &[(-500, -7, 900, 60), (25, -300, 31, 400), (0, 0, 45, 30)] {
            let (from, to) = (Point::new(x0, y0), Point::new(x1, y1));
            let inside: Vec<Point> = pixels(from, to, &everything)
                .into_iter()
                .filter(|p| clip.contains(*p))
                .collect();
            let clipped: Vec<Point> = pixels(from, to, &clip)
                .into_iter()
                .filter(|p| clip.contains(*p))
                .collect();
            assert_eq!(inside, clipped);
        }
    }

    /// A continuing line (its first pixel skipped) and lines clipped a step or more in
    /// start past the major axis's first steps: the same pixels as the whole line, which
    /// starts at step 0 and takes no quotient, less the first pixel and what lies outside.
    #[test]
    fn lines_started_steps_in_keep_the_whole_lines_pixels() {
        let everything = Rectangle::new(Point::new(-1000, -1000), Size::new(3000, 3000));
        let ends = [-9, -4, -1, 0, 1, 2, 3, 5, 8, 13];
        for &x1 in &ends {
            for &y1 in &ends {
                let (from, to) = (Point::zero(), Point::new(x1, y1));
                let whole = pixels(from, to, &everything);
                let skipped: Vec<Point> = Runs::new(from, to, true, &everything)
                    .flat_map(|run| run.points().collect::<Vec<_>>())
                    .collect();
                let expected: Vec<Point> = whole.iter().copied().filter(|&p| p != from).collect();
                assert_eq!(skipped, expected, "{from:?}-{to:?} skipping the first");
                for inset in 1..4 {
                    for clip in [
                        Rectangle::new(Point::new(inset, -20), Size::new(40, 40)),
                        Rectangle::new(Point::new(-20, inset), Size::new(40, 40)),
                        Rectangle::new(Point::new(-39, -20), Size::new(40 - inset as u32, 40)),
                        Rectangle::new(Point::new(-20, -39), Size::new(40, 40 - inset as u32)),
                    ] {
                        for skip_first in [false, true] {
                            let got: Vec<Point> = Runs::new(from, to, skip_first, &clip)
                                .flat_map(|run| run.points().collect::<Vec<_>>())
                                .filter(|p| clip.contains(*p))
                                .collect();
                            let expected: Vec<Point> = whole
                                .iter()
                                .copied()
                                .filter(|&p| clip.contains(p) && !(skip_first && p == from))
                                .collect();
                            assert_eq!(got, expected, "{from:?}-{to:?} in {clip:?}");
                        }
                    }
                }
            }
        }
    }

    /// A line with both ends inside the clip takes the same runs in i32 as in i64.
    #[test]
    fn lines_inside_run_the_same_in_32_bits() {
        let clip = Rectangle::new(Point::new(-40, -30), Size::new(90, 70));
        let ends = [-40, -30, -29, -7, -1, 0, 1, 2, 5, 13, 39, 49];
        for &(x0, y0) in &[(0, 0), (-40, -30), (49, 39), (3, -17), (-40, 39)] {
            for &x1 in &ends {
                for &y1 in &ends {
                    let (from, to) = (Point::new(x0, y0), Point::new(x1, y1));
                    if !(clip.contains(from) && clip.contains(to)) {
                        continue;
                    }
                    for skip_first in [false, true] {
                        let wide: Vec<Rectangle> = Runs::new(from, to, skip_first, &clip).collect();
                        let narrow: Vec<Rectangle> = Runs::inside(from, to, skip_first).collect();
                        assert_eq!(narrow, wide, "{from:?}-{to:?} skip {skip_first}");
                    }
                }
            }
        }
    }

    #[test]
    fn a_segment_far_away_visits_nothing() {
        let clip = Rectangle::new(Point::zero(), Size::new(320, 240));
        let runs = Runs::new(
            Point::new(i32::MIN, 5),
            Point::new(i32::MIN + 2_000_000_000, 6),
            false,
            &clip,
        );
        assert_eq!(runs.count(), 0);
    }
}
