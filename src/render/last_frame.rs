//! What an animation's last frame drew, kept as the runs it sent, so that the next frame
//! erases it by filling those runs in the background instead of drawing it again.
//!
//! An animation on a display that cannot be cleared every frame (an SPI panel: a clear is
//! every pixel on the wire) erases the last frame by drawing it again in the background
//! colour. That costs the whole drawing a second time: the walk, the lines' stepping, the
//! circles' edges. [`LastFrame`] keeps the rectangles a frame sent (its `fill_solid` and
//! `fill_contiguous` areas, a pixel of `draw_iter` each), 8 bytes a run, and erases them by
//! sending the same rectangles again in one colour: the same pixels, with none of the
//! drawing's work. Where the frame sent more runs than it holds, it says so and the caller
//! erases the old way.

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// A run as kept: its top-left corner and size, in 16 bits each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Run {
    x: i16,
    y: i16,
    width: u16,
    height: u16,
}

impl Run {
    /// `area` in 16 bits, or `None` where it does not fit them.
    fn of(area: &Rectangle) -> Option<Self> {
        Some(Self {
            x: i16::try_from(area.top_left.x).ok()?,
            y: i16::try_from(area.top_left.y).ok()?,
            width: u16::try_from(area.size.width).ok()?,
            height: u16::try_from(area.size.height).ok()?,
        })
    }

    fn area(self) -> Rectangle {
        Rectangle::new(
            Point::new(i32::from(self.x), i32::from(self.y)),
            Size::new(u32::from(self.width), u32::from(self.height)),
        )
    }
}

/// The runs a frame sent, up to `N` of them (8 bytes each, [`LastFrame::BYTES`] in all),
/// to erase that frame from the next.
///
/// Draw a frame through [`recording`](Self::recording), and before the next,
/// [`erase`](Self::erase) it:
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use embedded_graphics::primitives::{Line, PrimitiveStyle};
/// use tinyfractal::render::LastFrame;
///
/// let mut display = MockDisplay::<BinaryColor>::new();
/// display.set_allow_overdraw(true);
/// let mut last = LastFrame::<64>::new();
/// let ink = PrimitiveStyle::with_stroke(BinaryColor::On, 1);
/// for x in [10, 20] {
///     // Nothing to erase before the first frame; then the last frame's runs, in Off.
///     assert!(last.erase(&mut display, BinaryColor::Off)?);
///     Line::new(Point::new(x, 0), Point::new(x, 30))
///         .into_styled(ink)
///         .draw(&mut last.recording(&mut display))?;
/// }
/// // Only the second line is left lit.
/// assert_eq!(display.get_pixel(Point::new(10, 5)), Some(BinaryColor::Off));
/// assert_eq!(display.get_pixel(Point::new(20, 5)), Some(BinaryColor::On));
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Debug, Clone)]
pub struct LastFrame<const N: usize> {
    runs: [Run; N],
    kept: usize,
    /// Whether the frame sent a run that could not be kept (more than `N`, or beyond 16
    /// bits).
    lost: bool,
}

impl<const N: usize> Default for LastFrame<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> LastFrame<N> {
    /// The memory it takes: 8 bytes a run and two words.
    pub const BYTES: usize = size_of::<Self>();

    /// No frame yet: nothing to erase.
    pub const fn new() -> Self {
        Self {
            runs: [Run {
                x: 0,
                y: 0,
                width: 0,
                height: 0,
            }; N],
            kept: 0,
            lost: false,
        }
    }

    /// `target`, keeping every area drawn on it as this frame's (the last frame's runs
    /// are forgotten: erase them first).
    pub fn recording<'a, D: DrawTarget>(&'a mut self, target: &'a mut D) -> Recording<'a, D, N> {
        self.kept = 0;
        self.lost = false;
        Recording { target, last: self }
    }

    /// Fills every run the last frame sent with `background`, in the order it sent them,
    /// and forgets them: true. False, erasing nothing, where the frame sent more than it
    /// kept: the caller erases it another way (by drawing it again in the background).
    pub fn erase<D: DrawTarget>(
        &mut self,
        target: &mut D,
        background: D::Color,
    ) -> Result<bool, D::Error> {
        if self.lost {
            self.forget();
            return Ok(false);
        }
        for run in self.runs.get(..self.kept).unwrap_or_default() {
            target.fill_solid(&run.area(), background)?;
        }
        self.forget();
        Ok(true)
    }

    /// Whether every run of the last frame is kept (what [`erase`](Self::erase) would
    /// answer).
    pub const fn is_complete(&self) -> bool {
        !self.lost
    }

    /// Runs kept.
    pub const fn len(&self) -> usize {
        self.kept
    }

    /// Whether no run is kept.
    pub const fn is_empty(&self) -> bool {
        self.kept == 0
    }

    fn forget(&mut self) {
        self.kept = 0;
        self.lost = false;
    }

    #[inline]
    fn keep(&mut self, area: &Rectangle) {
        if area.size.width == 0 || area.size.height == 0 {
            return;
        }
        match (self.runs.get_mut(self.kept), Run::of(area)) {
            (Some(slot), Some(run)) => {
                *slot = run;
                self.kept += 1;
            }
            _ => self.lost = true,
        }
    }
}

/// A target that keeps every area drawn on it in a [`LastFrame`]: an embedded-graphics
/// [`DrawTarget`] in front of the display.
#[derive(Debug)]
pub struct Recording<'a, D, const N: usize> {
    target: &'a mut D,
    last: &'a mut LastFrame<N>,
}

impl<D: DrawTarget, const N: usize> Dimensions for Recording<'_, D, N> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D: DrawTarget, const N: usize> DrawTarget for Recording<'_, D, N> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        let last = &mut *self.last;
        self.target
            .draw_iter(pixels.into_iter().inspect(|Pixel(point, _)| {
                last.keep(&Rectangle::new(*point, Size::new(1, 1)));
            }))
    }

    fn fill_contiguous<I: IntoIterator<Item = Self::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.last.keep(area);
        self.target.fill_contiguous(area, colors)
    }

    #[inline]
    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        self.last.keep(area);
        self.target.fill_solid(area, color)
    }

    fn clear(&mut self, color: Self::Color) -> Result<(), Self::Error> {
        self.last.keep(&self.target.bounding_box());
        self.target.clear(color)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::BinaryColor;
    use embedded_graphics::primitives::{Circle, Line, PrimitiveStyle};

    use super::*;

    /// The lit pixels of a display.
    fn lit(display: &MockDisplay<BinaryColor>) -> Vec<Point> {
        display
            .bounding_box()
            .points()
            .filter(|&p| display.get_pixel(p) == Some(BinaryColor::On))
            .collect()
    }

    /// Erasing a frame leaves exactly what was there before it: every pixel it drew is
    /// background again, by runs, by contiguous areas and by single pixels.
    #[test]
    fn erasing_a_frame_leaves_the_background() {
        let mut display = MockDisplay::<BinaryColor>::new();
        display.set_allow_overdraw(true);
        let mut last = LastFrame::<256>::new();
        let ink = PrimitiveStyle::with_stroke(BinaryColor::On, 1);
        {
            let mut recording = last.recording(&mut display);
            Line::new(Point::new(3, 60), Point::new(50, 2))
                .into_styled(ink)
                .draw(&mut recording)
                .unwrap();
            Circle::new(Point::new(20, 20), 17)
                .into_styled(PrimitiveStyle::with_fill(BinaryColor::On))
                .draw(&mut recording)
                .unwrap();
            recording
                .fill_contiguous(
                    &Rectangle::new(Point::new(40, 40), Size::new(3, 2)),
                    [BinaryColor::On; 6],
                )
                .unwrap();
            recording
                .fill_solid(
                    &Rectangle::new(Point::new(5, 5), Size::new(4, 1)),
                    BinaryColor::On,
                )
                .unwrap();
        }
        assert!(last.is_complete() && !last.is_empty());
        assert!(lit(&display).len() > 200);
        assert!(last.erase(&mut display, BinaryColor::Off).unwrap());
        assert_eq!(lit(&display), Vec::<Point>::new());
        assert!(last.is_empty());
    }

    /// A frame of more runs than it holds is not erased: the caller is told.
    #[test]
    fn a_frame_too_large_is_not_erased() {
        let mut display = MockDisplay::<BinaryColor>::new();
        display.set_allow_overdraw(true);
        let mut last = LastFrame::<3>::new();
        let mut recording = last.recording(&mut display);
        for y in 0..4 {
            recording
                .fill_solid(
                    &Rectangle::new(Point::new(0, y), Size::new(5, 1)),
                    BinaryColor::On,
                )
                .unwrap();
        }
        assert!(!last.is_complete());
        assert!(!last.erase(&mut display, BinaryColor::Off).unwrap());
        assert_eq!(lit(&display).len(), 20);
        // Forgotten: the next frame starts afresh.
        assert!(last.is_complete() && last.is_empty());
    }

    /// A run beyond 16 bits cannot be kept: the frame is not erased.
    #[test]
    fn a_run_beyond_16_bits_is_not_kept() {
        let mut last = LastFrame::<4>::new();
        last.keep(&Rectangle::new(Point::new(40_000, 0), Size::new(1, 1)));
        assert!(!last.is_complete());
        let mut last = LastFrame::<4>::new();
        last.keep(&Rectangle::new(Point::new(-5, -7), Size::new(70_000, 1)));
        assert!(!last.is_complete());
        let mut last = LastFrame::<4>::new();
        last.keep(&Rectangle::new(Point::new(-5, -7), Size::new(0, 1)));
        assert!(last.is_complete() && last.is_empty());
    }

    /// A run is 8 bytes, as the memory the docs state.
    #[test]
    fn a_run_is_eight_bytes() {
        assert_eq!(size_of::<Run>(), 8);
        assert_eq!(LastFrame::<256>::BYTES, 8 * 256 + 2 * size_of::<usize>());
    }
}
