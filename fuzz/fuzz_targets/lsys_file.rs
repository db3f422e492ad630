//! `.lsys` text: read every entry, plain or parametric, and draw it at small orders into a
//! strict target.

#![no_main]

use libfuzzer_sys::fuzz_target;
use tinyfractal::LsysFile;
use tinyfractal_fuzz::{derive_plain, draw_parametric, draw_plain};

fuzz_target!(|data: &[u8]| {
    let Some((&orders, text)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(text);
    let order = u32::from(orders % 6);
    for entry in LsysFile::new(&text).entries().take(8) {
        let Ok(entry) = entry else { continue };
        if entry.is_parametric() {
            if let Ok(grammar) = entry.parametric() {
                draw_parametric(&grammar, order);
            }
        } else {
            if let Ok(grammar) = entry.grammar() {
                draw_plain(&grammar, order);
            }
            // As `derive` reads it: no angle needed.
            if let Ok(grammar) = entry.grammar_to_derive() {
                derive_plain(&grammar, order);
            }
        }
    }
});
