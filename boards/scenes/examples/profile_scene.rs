//! Draws one board scene into the checksum target, for profiling on the host:
//! `valgrind --tool=callgrind target/release/examples/profile_scene plant`.
use tinyfractal_scenes::{measure::Checksum, GREY, SCENES};

fn main() {
    let wanted = std::env::args().nth(1).unwrap_or_else(|| "plant".into());
    for entry in SCENES.iter().filter(|entry| entry.name == wanted) {
        let mut target = Checksum::new();
        let work = entry.scene.draw(&mut target, &GREY);
        println!("{}: {work:?}, checksum {}", entry.name, target.value);
    }
}
