//! Draws one scene into the checksum target, for profiling on the host:
//! `valgrind --tool=callgrind target/release/examples/profile_scene plant`.
use tinyfractal_lm3s6965evb::{
    measure::Checksum,
    scenes::{self, SCENES},
};

fn main() {
    let wanted = std::env::args().nth(1).unwrap_or_else(|| "plant".into());
    for (name, scene) in SCENES.iter().filter(|(n, _)| *n == wanted) {
        let mut target = Checksum::new();
        let work = scene.draw(&mut target, &scenes::GREY);
        println!("{name}: {work:?}, checksum {}", target.value);
    }
}
