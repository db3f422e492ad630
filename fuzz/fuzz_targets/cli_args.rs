//! The CLI's argument parser: any argument list is a command or a clap error, never a
//! panic.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|args: Vec<String>| {
    let _ = tinyfractal_simulator::args::parse(args.iter().take(32));
});
