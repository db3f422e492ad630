//! Cost on Cortex-M0, M3 and M4, by instruction counts under QEMU (`-icount shift=0`):
//! builds `boards/qemu-measure` for each core, runs it on `microbit`, `lm3s6965evb` and
//! `mps2-an386`, and checks that every scene's checksum equals the host's (the same picture,
//! bit for bit, on every core). Also reads flash and RAM sizes with llvm-tools' `llvm-size`
//! and checks the budgets.
//!
//! With `TINYFRACTAL_MEASUREMENTS=PATH` it writes the records to PATH as JSON:
//! `boards/measure` does that for `boards/measurements.json`.

mod common;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use tinyfractal_lm3s6965evb::measure::Checksum;
use tinyfractal_lm3s6965evb::scenes::{Work, SCENES};

struct Core {
    name: &'static str,
    target: &'static str,
    machine: &'static str,
    cpu: &'static str,
    flash: u64,
    ram: u64,
}

const CORES: [Core; 3] = [
    Core {
        name: "cortex-m0",
        target: "thumbv6m-none-eabi",
        machine: "microbit",
        cpu: "cortex-m0",
        flash: 256 << 10,
        ram: 16 << 10,
    },
    Core {
        name: "cortex-m3",
        target: "thumbv7m-none-eabi",
        machine: "lm3s6965evb",
        cpu: "cortex-m3",
        flash: 256 << 10,
        ram: 64 << 10,
    },
    Core {
        name: "cortex-m4",
        target: "thumbv7em-none-eabihf",
        machine: "mps2-an386",
        cpu: "cortex-m4",
        flash: 4 << 20,
        ram: 4 << 20,
    },
];

fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

/// Builds the measuring firmware for one core, from its own folder (see its Cargo.toml).
fn build(core: &Core) -> PathBuf {
    let folder = repository().join("boards/qemu-measure");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .current_dir(&folder)
        .args(["build", "--release", "--target", core.target])
        .status()
        .expect("cargo runs");
    assert!(
        status.success(),
        "the measuring firmware builds for {}",
        core.target
    );
    repository()
        .join("target/qemu-measure")
        .join(core.target)
        .join("release/tinyfractal-measure")
}

/// `text`, `data` and `bss` of an ELF, from llvm-tools' llvm-size.
fn sizes(elf: &Path) -> (u64, u64, u64) {
    let sysroot = Command::new("rustc")
        .args(["--print", "sysroot"])
        .output()
        .unwrap();
    let sysroot = String::from_utf8(sysroot.stdout).unwrap();
    let host = std::env::consts::ARCH.to_string() + "-unknown-linux-gnu";
    let tool = Path::new(sysroot.trim())
        .join("lib/rustlib")
        .join(host)
        .join("bin/llvm-size");
    let output = Command::new(&tool).arg(elf).output().unwrap_or_else(|e| {
        panic!(
            "{}: {e} (rust-toolchain.toml installs llvm-tools)",
            tool.display()
        )
    });
    let text = String::from_utf8(output.stdout).unwrap();
    let numbers: Vec<u64> = text
        .lines()
        .nth(1)
        .unwrap()
        .split_whitespace()
        .take(3)
        .map(|n| n.parse().unwrap())
        .collect();
    (numbers[0], numbers[1], numbers[2])
}

/// Runs the firmware and returns each `measure scene=...` line as key → value.
fn run(core: &Core, elf: &Path) -> Vec<BTreeMap<String, String>> {
    let output = Command::new("qemu-system-arm")
        .args([
            "-machine",
            core.machine,
            "-cpu",
            core.cpu,
            "-display",
            "none",
            "-icount",
            "shift=0",
        ])
        .args(["-semihosting-config", "enable=on,target=native", "-kernel"])
        .arg(elf)
        .output()
        .expect("QEMU runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        stdout.contains("measure done"),
        "{}: the firmware did not finish:\n{stdout}",
        core.name
    );
    stdout
        .lines()
        .filter(|l| l.starts_with("measure scene="))
        .map(|line| {
            line.split_whitespace()
                .skip(1)
                .filter_map(|pair| pair.split_once('='))
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        })
        .collect()
}

#[test]
fn every_core_draws_the_host_picture_and_fits() {
    if !common::qemu_or_skip("the Cortex-M measurements") {
        return;
    }
    // The host's checksums: the same scene code into the same checksum target.
    let host: Vec<(u32, u32, u64)> = SCENES
        .iter()
        .map(|(_, scene)| {
            let mut target = Checksum::new();
            let work = match scene
                .draw(&mut target, &tinyfractal_lm3s6965evb::scenes::GREY)
                .unwrap()
            {
                Work::Segments(n) | Work::Iterations(n) => n,
            };
            (target.value, target.pixels, work)
        })
        .collect();

    let mut json = String::from("[\n");
    let mut table = String::new();
    for core in &CORES {
        let elf = build(core);
        let (text, data, bss) = sizes(&elf);
        let records = run(core, &elf);
        assert_eq!(
            records.len(),
            SCENES.len(),
            "{}: one record per scene",
            core.name
        );
        let mut deepest_stack = 0;
        for (record, ((name, _), &(checksum, pixels, work))) in
            records.iter().zip(SCENES.iter().zip(&host))
        {
            assert_eq!(record["scene"], *name);
            assert_eq!(
                record["checksum"],
                checksum.to_string(),
                "{} {name}: picture differs from the host",
                core.name
            );
            assert_eq!(record["pixels"], pixels.to_string(), "{} {name}", core.name);
            assert_eq!(record["work"], work.to_string(), "{} {name}", core.name);
            let instructions: u64 = record["instructions"].parse().unwrap();
            let stack: u64 = record["stack"].parse().unwrap();
            deepest_stack = deepest_stack.max(stack);
            let unit = if SCENES.iter().any(|(n, s)| {
                n == name && matches!(s, tinyfractal_lm3s6965evb::scenes::Scene::LSystem { .. })
            }) {
                "segment"
            } else {
                "iteration"
            };
            let _ = writeln!(
                json,
                "  {{\"core\": \"{}\", \"scene\": \"{name}\", \"instructions\": {instructions}, \"baseline_f32\": {}, \"baseline_fixed20\": {}, \"text\": {text}, \"data\": {data}, \"bss\": {bss}, \"stack\": {stack}, \"work\": {work}, \"work_unit\": \"{unit}\"}},",
                core.name, record["baseline_f32"], record["baseline_fixed20"]
            );
            let ratio = |baseline: &str| {
                baseline.parse::<f64>().map_or("-".to_string(), |b| {
                    format!("{:.1}×", b / instructions as f64)
                })
            };
            let _ = writeln!(
                table,
                "| {} | {name} | {instructions} | {:.0} per {unit} | {} | {} | {stack} |",
                core.name,
                instructions as f64 / work.max(1) as f64,
                ratio(&record["baseline_f32"]),
                ratio(&record["baseline_fixed20"]),
            );
        }
        // Budgets with room to spare: three quarters of flash, and of RAM with the deepest stack.
        assert!(
            text + data <= core.flash * 3 / 4,
            "{}: {text} + {data} bytes of flash",
            core.name
        );
        assert!(
            data + bss + deepest_stack <= core.ram * 3 / 4,
            "{}: {data} + {bss} + {deepest_stack} bytes of RAM",
            core.name
        );
        println!(
            "{}: text {text}, data {data}, bss {bss}, deepest stack {deepest_stack}",
            core.name
        );
    }
    json.truncate(json.trim_end_matches(",\n").len());
    json.push_str("\n]\n");
    println!("| core | scene | instructions | per unit | f32 baseline ÷ ours | fixed20 baseline ÷ ours | stack |\n|---|---|---|---|---|---|---|\n{table}");
    if let Some(path) = std::env::var_os("TINYFRACTAL_MEASUREMENTS") {
        std::fs::write(&path, json).unwrap();
        println!("wrote {}", PathBuf::from(path).display());
    }
}
