//! Fractint `.l` text: read every entry, its warnings and grammar, and draw it at small
//! orders into a strict target; derive it as `derive` reads it (no angle needed).

#![no_main]

use libfuzzer_sys::fuzz_target;
use tinyfractal::LFile;
use tinyfractal_fuzz::{derive_plain, draw_plain};

fuzz_target!(|data: &[u8]| {
    let Some((&orders, text)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(text);
    for entry in LFile::new(&text).entries().take(8) {
        let Ok(entry) = entry else { continue };
        for warning in entry.warnings() {
            let _ = warning.to_string();
        }
        if let Ok(grammar) = entry.grammar() {
            draw_plain(&grammar, u32::from(orders % 6));
        }
        // As `derive` reads it: no angle needed.
        if let Ok(grammar) = entry.grammar_to_derive() {
            derive_plain(&grammar, u32::from(orders % 6));
        }
    }
});
