//! The autopilot: it zooms in by its stated factor while the picture has edges, never ends
//! on a uniform frame, repeats for a seed, and backs out of a uniform view.

use tinyfractal::{
    escape::{Algorithm, Autopilot, Render, NARROWING},
    render::DwellBuffer,
    Coord, Fractal, View,
};

fn values(view: View) -> Vec<u16> {
    let size = view.size();
    let mut values = vec![0; (size.width * size.height) as usize];
    let Ok(_) =
        Render::new(view, Algorithm::Fast).run(&mut DwellBuffer::new(&mut values, size.width));
    values
}

fn start() -> View {
    View::new(
        Fractal::Mandelbrot,
        (Coord::from_f64(-0.75).unwrap(), Coord::default()),
        Coord::from_f64(3.5).unwrap(),
        embedded_graphics::geometry::Size::new(64, 48),
        256,
    )
    .unwrap()
}

/// The views of `frames` frames from the full view with `seed`, and the last picture.
fn flight(seed: u64, frames: usize) -> (Vec<View>, Vec<u16>, u32) {
    let mut pilot = Autopilot::new(seed);
    let mut view = start();
    let mut views = vec![view];
    let mut picture = values(view);
    for _ in 0..frames {
        view = pilot.next(&view, &picture).unwrap();
        picture = values(view);
        views.push(view);
    }
    (views, picture, pilot.backed_out())
}

#[test]
fn it_zooms_by_its_factor_towards_edges() {
    let frames = 80;
    let (views, picture, backed_out) = flight(7, frames);
    assert_eq!(backed_out, 0, "the full view's boundary is never lost");
    // Each frame 15/16 of the last, to the bit: (15/16)^80 = 0.0057.
    let first = views[0].spacing().to_f64();
    let last = views[frames].spacing().to_f64();
    let factor = (NARROWING.0 as f64 / NARROWING.1 as f64).powi(frames as i32);
    assert!(
        (last / first / factor - 1.0).abs() < 1e-6,
        "{last} from {first}"
    );
    // Not uniform: both the set and the outside are in the last frame.
    let inside = views[frames].inside_value();
    let set = picture.iter().filter(|&&v| v >= inside).count();
    assert!(
        set > 0 && set < picture.len(),
        "{set} of {} pixels inside",
        picture.len()
    );
    let distinct: std::collections::HashSet<_> = picture.iter().collect();
    assert!(distinct.len() > 10, "{} values", distinct.len());
}

#[test]
fn a_seed_repeats_its_flight() {
    let (a, _, _) = flight(3, 30);
    let (b, _, _) = flight(3, 30);
    let (c, _, _) = flight(4, 30);
    assert_eq!(a, b);
    assert_ne!(a, c);
}

/// A view of the outside alone (far from the set) has no edge: the pilot backs out, wider,
/// until the set is in sight, and then zooms in again.
#[test]
fn it_backs_out_of_a_uniform_view() {
    let mut pilot = Autopilot::new(1);
    let mut view = View::new(
        Fractal::Mandelbrot,
        (Coord::from_f64(1.5).unwrap(), Coord::from_f64(1.5).unwrap()),
        Coord::from_f64(0.01).unwrap(),
        embedded_graphics::geometry::Size::new(64, 48),
        256,
    )
    .unwrap();
    let mut widths = vec![view.spacing().to_f64()];
    for _ in 0..12 {
        let picture = values(view);
        view = pilot.next(&view, &picture).unwrap();
        widths.push(view.spacing().to_f64());
    }
    assert!(
        pilot.backed_out() >= 2,
        "backed out {} times",
        pilot.backed_out()
    );
    assert!(widths[1] > widths[0] * 7.0, "{widths:?}");
    assert!(widths[12] < widths[11], "it zooms in again: {widths:?}");
}
