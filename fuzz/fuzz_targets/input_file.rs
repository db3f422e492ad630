//! Input files as the CLI reads them: any bytes under any extension are decoded (or named
//! UTF-16, binary or too large), given a kind, and their entries listed; an L-system
//! file's first entry is loaded as its kind reads it. Never a panic.

#![no_main]

use std::path::PathBuf;

use libfuzzer_sys::fuzz_target;
use tinyfractal::{LFile, LsysFile};
use tinyfractal_simulator::files::{decode, entry_names, FileKind};

/// Extensions as people write them, in any case, and none.
const EXTENSIONS: [&str; 8] = ["l", "lsys", "ifs", "L", "LSYS", "Ifs", "txt", ""];

fuzz_target!(|input: (u8, &[u8])| {
    let (which, bytes) = input;
    let path = PathBuf::from(format!(
        "fuzzed.{}",
        EXTENSIONS[usize::from(which) % EXTENSIONS.len()]
    ));
    let Ok(text) = decode(&path, bytes) else {
        return;
    };
    let kind = FileKind::of(&path, &text);
    let names = entry_names(kind, &text);
    let Some(Ok(first)) = names.first() else {
        return;
    };
    match kind.lsystems(&path) {
        Ok(FileKind::Lsys) => {
            if let Ok(entry) = LsysFile::new(&text).entry(first) {
                let _ = entry.grammar_to_derive();
            }
        }
        Ok(_) => {
            if let Ok(entry) = LFile::new(&text).entry(first) {
                let _ = entry.grammar_to_derive();
            }
        }
        Err(_) => {}
    }
});
