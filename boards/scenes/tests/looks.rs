//! The real boards draw the shared scenes in RGB565 at 320×240 (the Pico's ST7789, landscape)
//! and 240×320 (the DISCO's ILI9341, portrait); the OLED draws them in grey. A look changes
//! colours only: every scene draws at each size, stays inside the target, and marks exactly
//! the same pixels in either look.

use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
};
use tinyfractal_scenes::{
    Entry, Look, Work, COLOUR, DYNAMICS_SCENES, GREY, SCENES, TEXTURE_SCENES, ZOOM_SCENES,
};

use tinyfractal_test_support::frame;

use frame::Frame;

/// Which pixels a look left as background (L-systems) or inside colour (escape time).
fn marks<C: PixelColor + From<Rgb888>>(
    Entry { name, scene, .. }: &Entry,
    size: Size,
    look: &Look<'_, C>,
) -> (Work, Vec<bool>) {
    let mut frame = Frame::filled(size, look.background);
    let work = scene.draw(&mut frame, look).unwrap();
    assert_eq!(frame.outside, 0, "{name} drew outside {size}");
    let marked = match work {
        Work::Segments(_) | Work::Points(_) | Work::Cells(_) => {
            frame.pixels.iter().map(|&p| p != look.background).collect()
        }
        Work::Iterations(_) | Work::Frames(_) => {
            frame.pixels.iter().map(|&p| p == look.inside).collect()
        }
        // A texture's 256 levels show as gradient colours, which a 16-grey panel merges:
        // nothing to compare pixel for pixel (the core's tests check the levels).
        Work::Samples(_) | Work::CellSteps(_) | Work::ParticleSteps(_) => Vec::new(),
    };
    (work, marked)
}

#[test]
fn every_scene_marks_the_same_pixels_in_colour_and_in_grey() {
    // The deep zoom (1000 iterations at 60 bits) is left to the QEMU test at 128×64.
    let scenes = SCENES.iter().chain(&ZOOM_SCENES);
    for scene @ Entry { name, .. } in scenes.filter(|entry| entry.name != "deep-zoom") {
        for size in [Size::new(320, 240), Size::new(240, 320)] {
            // An inside colour no gradient entry has: the classic gradient's last key is
            // black in RGB565, and a smooth view's 256 entries come that close to it.
            let colour_look = Look {
                inside: Rgb565::MAGENTA,
                ..COLOUR
            };
            let (work_colour, colour) = marks(scene, size, &colour_look);
            let (work_grey, grey) = marks(scene, size, &GREY);
            assert_eq!(work_colour, work_grey, "{name}");
            let marked = colour.iter().filter(|&&m| m).count();
            assert!(
                marked > colour.len() / 100,
                "{name} at {size}: only {marked} pixels marked"
            );
            assert!(colour == grey, "{name} at {size}: looks differ");
        }
    }
}

/// The newer families' scenes draw at the real boards' display sizes in both looks, inside
/// the target, doing the same work: a board shows them full screen.
#[test]
fn the_newer_scenes_draw_at_every_display_size() {
    for Entry { name, scene, .. } in TEXTURE_SCENES.iter().chain(&DYNAMICS_SCENES) {
        for size in [Size::new(320, 240), Size::new(240, 320), Size::new(128, 64)] {
            let mut colour = Frame::filled(size, COLOUR.background);
            let mut grey = Frame::filled(size, GREY.background);
            let work_colour = scene.draw(&mut colour, &COLOUR).unwrap();
            let work_grey = scene.draw(&mut grey, &GREY).unwrap();
            assert_eq!(work_colour, work_grey, "{name} at {size}");
            assert!(work_colour.count() > 0, "{name} at {size}: no work");
            assert_eq!(
                colour.outside + grey.outside,
                0,
                "{name} drew outside {size}"
            );
        }
    }
}

/// The fern by density lights the pixels the fern in ink does: its counts' square holds
/// the whole fern (which fits its height in either), a pixel is lit where a point hit, and
/// either side of the square is the colour of a pixel never hit.
#[test]
fn the_fern_by_density_lights_the_ferns_pixels() {
    let named = |name: &str| SCENES.iter().find(|entry| entry.name == name).unwrap();
    for size in [Size::new(128, 64), Size::new(320, 240), Size::new(240, 320)] {
        let lit = |name: &str| {
            let mut frame = Frame::filled(size, GREY.background);
            let work = named(name).scene.draw(&mut frame, &GREY).unwrap();
            // A corner is never in the fern, nor in the square's middle.
            let unlit = frame.pixels[0];
            let lit: Vec<bool> = frame.pixels.iter().map(|&p| p != unlit).collect();
            (work, lit)
        };
        let ((ink_work, ink), (density_work, density)) = (lit("ifs-fern"), lit("ifs-fern-density"));
        assert_eq!(ink_work, density_work, "the same points played");
        let both = ink.iter().zip(&density).filter(|(a, b)| **a && **b).count();
        let count = |marks: &[bool]| marks.iter().filter(|&&m| m).count();
        let (lit_ink, lit_density) = (count(&ink), count(&density));
        // The fits may round a pixel apart at the fern's edges.
        assert!(both * 100 >= lit_ink * 95, "{size:?}: {both} of {lit_ink}");
        assert!(
            both * 100 >= lit_density * 95,
            "{size:?}: {both} of {lit_density}"
        );
    }
}
