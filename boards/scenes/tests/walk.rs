//! The walking figure, a board's animation: each frame erases the last one's lines instead
//! of clearing the display (by filling the runs it kept again, or where they were too many,
//! by drawing it again in the background), so what stays on the target must be the last
//! frame alone, in the fit shared by every frame; and a board gets a call between frames to
//! pace it.

use embedded_graphics::{prelude::*, primitives::Rectangle};
use tinyfractal::{
    figure::{walk as walk_pose, BODY},
    Figure, Real,
};
use tinyfractal_scenes::{Scene, Work, GREY};

use tinyfractal_test_support::frame;

use frame::Frame;

/// Counts the runs a drawing sends.
struct Runs {
    size: Size,
    runs: usize,
}

impl OriginDimensions for Runs {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Runs {
    type Color = embedded_graphics::pixelcolor::Gray4;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        self.runs += pixels.into_iter().count();
        Ok(())
    }

    fn fill_solid(&mut self, _: &Rectangle, _: Self::Color) -> Result<(), Self::Error> {
        self.runs += 1;
        Ok(())
    }
}

#[test]
fn the_last_frame_alone_stays_on_the_display() {
    // The OLED's frames keep their runs; the large ones send more than they keep, and
    // are erased by drawing them again.
    for (size, runs) in [
        (Size::new(128, 64), 40..256),
        (Size::new(1024, 768), 257..100_000),
    ] {
        the_last_frame_alone_stays_at(size, runs);
    }
}

fn the_last_frame_alone_stays_at(size: Size, runs: core::ops::Range<usize>) {
    const FRAMES: u32 = 16;
    let mut animated = Frame::filled(size, GREY.ink);
    let mut calls = 0;
    let work = Scene::Walk { frames: FRAMES }
        .draw_frames(&mut animated, &GREY, || calls += 1)
        .unwrap();
    assert_eq!(calls, FRAMES);
    assert_eq!(animated.outside, 0);

    let pose = |k: u32| walk_pose(Real::from_ratio(i64::from(k), i64::from(FRAMES)).unwrap());
    let drawing = Figure::new(&BODY, pose(0))
        .fit_poses(
            Rectangle::new(Point::zero(), size),
            &[GREY.ink],
            (0..FRAMES).map(pose),
        )
        .unwrap();
    let mut last = Frame::filled(size, GREY.background);
    drawing.with_pose(pose(FRAMES - 1)).draw(&mut last).unwrap();
    let mut counted = Runs { size, runs: 0 };
    drawing
        .with_pose(pose(FRAMES - 1))
        .draw(&mut counted)
        .unwrap();
    assert!(
        runs.contains(&counted.runs),
        "{} runs at {size:?}",
        counted.runs
    );
    assert!(
        animated.pixels == last.pixels,
        "the erased frames left pixels behind"
    );
    let drawn = animated.pixels.iter().filter(|&&p| p == GREY.ink).count();
    assert!(drawn > 100, "{drawn} pixels of the last frame");

    // Every frame draws the same number of lines.
    let Work::Segments(lines) = work else {
        panic!("{work:?}")
    };
    let mut one = Frame::filled(size, GREY.background);
    let per_frame = drawing.draw(&mut one).unwrap();
    assert_eq!(lines, per_frame * u64::from(FRAMES));
}

#[test]
fn no_frames_draw_nothing() {
    let mut target = Frame::filled(Size::new(32, 32), GREY.ink);
    let work = Scene::Walk { frames: 0 }.draw(&mut target, &GREY).unwrap();
    assert_eq!(work, Work::Segments(0));
    assert!(target.pixels.iter().all(|&p| p == GREY.background));
}
