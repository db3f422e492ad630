//! The texture scenes draw what the core's drawings draw: an animated texture's frames
//! are the stills at their depths, one wait between frames each.

use embedded_graphics::{pixelcolor::Gray4, prelude::*, primitives::Rectangle};
use tinyfractal::noise::{NoiseTexture, Perlin};
use tinyfractal::Real;
use tinyfractal_scenes::{Scene, GREY, TEXTURE_SCENES};
use tinyfractal_test_support::frame::Frame;

#[test]
fn a_flight_ends_on_the_still_at_its_last_depth() {
    let entry = TEXTURE_SCENES
        .iter()
        .find(|entry| matches!(entry.scene, Scene::NoiseFlight { .. }))
        .expect("the catalogue has a texture in flight");
    let Scene::NoiseFlight {
        texture,
        octaves,
        scale,
        seed,
        frames,
        z_step,
    } = entry.scene
    else {
        unreachable!()
    };
    let mut flown = Frame::filled(entry.size, Gray4::BLACK);
    let mut waits = 0;
    let work = entry
        .scene
        .draw_frames(&mut flown, &GREY, || waits += 1)
        .unwrap();
    assert_eq!(waits, frames);
    let pixels = u64::from(entry.size.width * entry.size.height);
    assert_eq!(work.count(), pixels * u64::from(frames));
    // The last frame: depth (frames − 1)·z_step, drawn alone.
    let noise = Perlin::seeded(seed);
    let depth = Real::from_bits(z_step.to_bits() * i64::from(frames - 1));
    let mut still = Frame::filled(entry.size, Gray4::BLACK);
    NoiseTexture::new(&noise, texture)
        .with_octaves(octaves)
        .with_scale(scale)
        .with_z(depth)
        .fit(
            Rectangle::new(Point::zero(), entry.size),
            GREY.gradient::<256>().unwrap(),
        )
        .unwrap()
        .draw(&mut still)
        .unwrap();
    assert_eq!(flown.pixels, still.pixels);
    // Drawn without waits (as the measuring firmware does), the same frames.
    let mut drawn = Frame::filled(entry.size, Gray4::BLACK);
    assert_eq!(entry.scene.draw(&mut drawn, &GREY).unwrap(), work);
    assert_eq!(drawn.pixels, still.pixels);
}
