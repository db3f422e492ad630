//! The explorer's state and inputs, headless: every input changes the view as stated,
//! cancels the stale render, and the finished picture equals the headless render of the
//! same view.

use embedded_graphics::{pixelcolor::Rgb888, prelude::*, primitives::Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::{
    escape::{Algorithm, Painter, Render},
    Coord,
};
use tinyfractal_simulator::escape_scene;
use tinyfractal_simulator::explore::{
    EscapeState, Explorer, Input, Subject, PALETTES, STATUS_HEIGHT,
};

const SIZE: Size = Size::new(64, 48);

fn window() -> SimulatorDisplay<Rgb888> {
    SimulatorDisplay::new(Size::new(SIZE.width, SIZE.height + STATUS_HEIGHT))
}

fn state(explorer: &Explorer) -> EscapeState {
    match &explorer.subject {
        Subject::Escape(state) => state.clone(),
        Subject::LSystems { .. } | Subject::Gallery { .. } => panic!("not an escape-time view"),
    }
}

/// Ticks until the picture is complete; how many ticks it took.
fn finish(explorer: &mut Explorer, display: &mut SimulatorDisplay<Rgb888>, budget: u64) -> u32 {
    let mut ticks = 0;
    loop {
        explorer.tick(display, budget);
        ticks += 1;
        if explorer.is_complete() {
            return ticks;
        }
        assert!(ticks < 100_000, "the render never finishes");
    }
}

/// The headless render of an explorer's state, as `render mandelbrot` paints it.
fn headless(state: &EscapeState) -> SimulatorDisplay<Rgb888> {
    let text = |v: f64| format!("{v:e}");
    let julia = state.julia.map(|(re, im)| (re.to_string(), im.to_string()));
    let (centre, width) = (
        (text(state.centre.0), text(state.centre.1)),
        text(state.width),
    );
    let request = escape_scene::Request {
        julia: julia.as_ref().map(|(re, im)| (re.as_str(), im.as_str())),
        centre: (&centre.0, &centre.1),
        width: &width,
        size: SIZE,
        max_iterations: state.max_iterations,
        algorithm: Algorithm::Fast,
        tier: None,
        palette: PALETTES[state.palette],
        palette_file: None,
        modes: escape_scene::Modes::default(),
    };
    let (view, palette) = escape_scene::view_at(&request, &width).unwrap();
    let mut display = SimulatorDisplay::new(SIZE);
    let Ok(_) =
        Render::new(view, Algorithm::Fast).run(&mut Painter::new(&mut display, &palette, &view));
    display
}

fn assert_picture(display: &SimulatorDisplay<Rgb888>, expected: &SimulatorDisplay<Rgb888>) {
    for p in Rectangle::new(Point::zero(), SIZE).points() {
        assert_eq!(display.get_pixel(p), expected.get_pixel(p), "pixel {p:?}");
    }
}

#[test]
fn clicks_zoom_about_the_mouse_and_the_picture_is_the_headless_render() {
    let mut display = window();
    let mut explorer = Explorer::escape(EscapeState::default(), SIZE);
    finish(&mut explorer, &mut display, 1 << 40);
    assert_picture(&display, &headless(&state(&explorer)));
    assert!(
        explorer
            .status()
            .starts_with("mandelbrot -0.750000,0.000000 w=3.500e0 it=256"),
        "{}",
        explorer.status()
    );
    // A click zooms in twice about the point under the mouse, which stays put.
    let click = Point::new(16, 12);
    explorer.input(Input::ZoomIn(click));
    let zoomed = state(&explorer);
    assert_eq!(zoomed.width, 1.75);
    let spacing = 3.5 / 64.0;
    let before = (-0.75 + (16.5 - 32.0) * spacing, -(12.5 - 24.0) * spacing);
    let after = (
        zoomed.centre.0 + (16.5 - 32.0) * spacing / 2.0,
        zoomed.centre.1 - (12.5 - 24.0) * spacing / 2.0,
    );
    assert!((before.0 - after.0).abs() < 1e-12 && (before.1 - after.1).abs() < 1e-12);
    finish(&mut explorer, &mut display, 1 << 40);
    assert_picture(&display, &headless(&zoomed));
    explorer.input(Input::ZoomOut(click));
    assert_eq!(state(&explorer).width, 3.5);
    explorer.input(Input::Wheel(click, 2));
    assert!((state(&explorer).width - 3.5 / 1.5625).abs() < 1e-12);
}

#[test]
fn an_input_cancels_the_stale_render() {
    let mut display = window();
    let deep = EscapeState {
        centre: (-0.743_643_887, 0.131_825_904),
        width: 1e-6,
        max_iterations: 2000,
        ..EscapeState::default()
    };
    let mut explorer = Explorer::escape(deep, SIZE);
    // A small budget: the preview, then a little of the render.
    explorer.tick(&mut display, 10_000);
    assert!(
        !explorer.is_complete(),
        "a deep view takes more than one tick"
    );
    assert!(
        explorer.status().ends_with("ms") && explorer.status().contains("..."),
        "{}",
        explorer.status()
    );
    explorer.input(Input::Pan(8, 0));
    let moved = state(&explorer);
    assert!((moved.centre.0 - (-0.743_643_887 - 8.0 * 1e-6 / 64.0)).abs() < 1e-15);
    let ticks = finish(&mut explorer, &mut display, 100_000);
    assert!(ticks >= 2, "rendered progressively ({ticks} ticks)");
    assert_picture(&display, &headless(&moved));
}

#[test]
fn keys_change_iterations_palette_julia_and_reset() {
    let mut display = window();
    let mut explorer = Explorer::escape(EscapeState::default(), SIZE);
    explorer.input(Input::More);
    assert_eq!(state(&explorer).max_iterations, 512);
    explorer.input(Input::Fewer);
    explorer.input(Input::Fewer);
    assert_eq!(state(&explorer).max_iterations, 128);
    explorer.input(Input::NextPalette);
    assert_eq!(PALETTES[state(&explorer).palette], "fire");
    // j: the Julia set of the point under the mouse, framed at the origin.
    explorer.input(Input::JuliaAt(Point::new(32, 24)));
    let julia = state(&explorer);
    let k = julia.julia.expect("a Julia set");
    assert!((k.0.to_f64() - (-0.75 + 0.5 * 3.5 / 64.0)).abs() < 1e-9);
    assert_eq!((julia.centre, julia.width), ((0.0, 0.0), 3.2));
    finish(&mut explorer, &mut display, 1 << 40);
    assert_picture(&display, &headless(&julia));
    assert!(
        explorer.status().starts_with("julia"),
        "{}",
        explorer.status()
    );
    explorer.input(Input::JuliaAt(Point::zero()));
    assert_eq!(state(&explorer).julia, None);
    explorer.input(Input::Reset);
    assert_eq!(state(&explorer), EscapeState::default());
    // Colour cycling turns the finished picture's colours without recomputing it.
    finish(&mut explorer, &mut display, 1 << 40);
    let still = headless(&state(&explorer));
    explorer.input(Input::ToggleCycling);
    explorer.tick(&mut display, 1 << 40);
    let changed = Rectangle::new(Point::zero(), SIZE)
        .points()
        .filter(|&p| display.get_pixel(p) != still.get_pixel(p))
        .count();
    assert!(changed > 100, "{changed} pixels changed colour");
    let _ = Coord::default();
}

#[test]
fn lsystem_files_page_through_their_systems() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../data/classics.l"))
        .unwrap();
    let names: Vec<String> = tinyfractal::LFile::new(&text)
        .entries()
        .filter_map(|e| e.ok().map(|e| e.name().to_string()))
        .collect();
    let mut display = window();
    let mut explorer = Explorer::lsystems(text.clone(), names.clone(), false, SIZE);
    explorer.tick(&mut display, 1);
    let expected = |name: &str, order: u32| {
        let grammar = tinyfractal::LFile::new(&text).find(name).unwrap();
        tinyfractal_simulator::scene::render(&grammar, order, SIZE.width, SIZE.height, None)
            .unwrap()
            .display
    };
    assert_picture(&display, &expected(&names[0], 3));
    explorer.input(Input::NextSystem);
    explorer.input(Input::More);
    explorer.tick(&mut display, 1);
    assert_picture(&display, &expected(&names[1], 4));
    assert!(
        explorer
            .status()
            .starts_with(&format!("{} order 4 (2/", names[1])),
        "{}",
        explorer.status()
    );
    explorer.input(Input::PreviousSystem);
    explorer.input(Input::PreviousSystem);
    explorer.tick(&mut display, 1);
    assert_picture(&display, &expected(names.last().unwrap(), 4));
}

#[test]
fn gallery_scenes_page_and_move_their_own_parameter() {
    use tinyfractal_scenes::{Entry, Scene, GALLERY};
    let mut display = window();
    let first = GALLERY[0];
    let mut explorer = Explorer::gallery(first.name, SIZE).unwrap();
    explorer.tick(&mut display, 1);
    let at_size = |entry: Entry| Entry {
        size: SIZE,
        ..entry
    };
    let expected = |entry: Entry| {
        tinyfractal_simulator::gallery::picture(&at_size(entry))
            .unwrap()
            .0
    };
    assert_picture(&display, &expected(first));
    assert!(
        explorer.status().starts_with(first.name),
        "{}",
        explorer.status()
    );
    // `+` raises the L-system's order by one.
    explorer.input(Input::More);
    explorer.tick(&mut display, 1);
    let Scene::LSystem {
        system,
        order,
        orientation,
    } = first.scene
    else {
        panic!("the gallery starts with an L-system");
    };
    let higher = Entry {
        scene: Scene::LSystem {
            system,
            order: order + 1,
            orientation,
        },
        ..first
    };
    assert_picture(&display, &expected(higher));
    // Page down to the carpet; `-` lowers its order.
    let carpet = GALLERY
        .iter()
        .position(|e| e.name == "sierpinski-carpet")
        .unwrap();
    for _ in 0..carpet {
        explorer.input(Input::NextSystem);
    }
    explorer.input(Input::Fewer);
    explorer.tick(&mut display, 1);
    let Scene::Subdivision { shape, order } = GALLERY[carpet].scene else {
        panic!("the carpet is a subdivision");
    };
    let lower = Entry {
        scene: Scene::Subdivision {
            shape,
            order: order - 1,
        },
        ..GALLERY[carpet]
    };
    assert_picture(&display, &expected(lower));
    assert!(Explorer::gallery("no-such-scene", SIZE)
        .err()
        .unwrap()
        .contains("sierpinski-carpet"));
}

/// `a`: the autopilot steers each finished picture to the next, narrower view; `a` again
/// stops it where it is.
#[test]
fn the_autopilot_flies_and_stops() {
    let mut display = window();
    let mut explorer = Explorer::escape(EscapeState::default(), SIZE);
    let start = state(&explorer).width;
    explorer.input(Input::Autopilot);
    for _ in 0..20 {
        finish(&mut explorer, &mut display, 1 << 40);
        // The finished picture's tick steers; the next ticks render the new view.
        explorer.tick(&mut display, 1 << 40);
    }
    let flown = state(&explorer).width;
    assert!(flown < start * 0.5, "{flown} from {start}");
    explorer.input(Input::Autopilot);
    finish(&mut explorer, &mut display, 1 << 40);
    explorer.tick(&mut display, 1 << 40);
    assert_eq!(state(&explorer).width, flown, "stopped where it was");
}
