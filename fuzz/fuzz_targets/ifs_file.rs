//! Fractint `.ifs` text: read every entry and play its chaos game into a strict target,
//! as points and as a density picture.

#![no_main]

use embedded_graphics::prelude::*;
use libfuzzer_sys::fuzz_target;
use tinyfractal::{ifs::IfsPicture, IfsFile};
use tinyfractal_fuzz::{StrictTarget, PALETTE};

fuzz_target!(|data: &[u8]| {
    let Some((&seed, text)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(text);
    for entry in IfsFile::new(&text).entries().take(8) {
        let Ok(entry) = entry else { continue };
        let Ok(ifs) = entry.ifs() else { continue };
        let picture = IfsPicture::new(&ifs, 2_000).with_seed(u64::from(seed));
        let mut target = StrictTarget::new(64, 48);
        if let Ok(drawing) = picture.fit(target.bounding_box(), &PALETTE) {
            let _ = drawing.draw(&mut target);
        }
    }
});
