//! Draws one board scene into the checksum target, for profiling on the host:
//! `valgrind --tool=callgrind target/release/examples/profile_scene plant [320x240]` (the
//! size picks among entries of one name: the OLED's 128x64 by default).
use tinyfractal_scenes::{measure::Checksum, DEEP_SCENES, DISPLAY_SCENES, GREY, SCENES};

fn main() {
    let wanted = std::env::args().nth(1).unwrap_or_else(|| "plant".into());
    let size = std::env::args().nth(2).unwrap_or_else(|| "128x64".into());
    for entry in SCENES
        .iter()
        .chain(&DISPLAY_SCENES)
        .chain(&DEEP_SCENES)
        .filter(|entry| entry.name == wanted)
        .filter(|entry| format!("{}x{}", entry.size.width, entry.size.height) == size)
    {
        let mut target = Checksum::of_size(entry.size);
        let work = entry.scene.draw(&mut target, &GREY);
        println!("{}: {work:?}, checksum {}", entry.name, target.value);
    }
}
