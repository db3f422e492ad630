//! Cost on Cortex-M0, M3 and M4, by instruction counts under QEMU (`-icount shift=0`):
//! builds `boards/qemu-measure` for each core, runs it on `microbit`, `mps2-an385` and
//! `mps2-an386`, and checks that every scene's checksum equals the host's (the same picture,
//! bit for bit, on every core). Also reads flash and RAM sizes from the ELF's section
//! headers (as `size` reports them) and checks the budgets.
//!
//! Built as ignored, saying what to install, where QEMU or the Cortex-M targets are missing
//! and cannot be added (see `boards/tools/detect.rs`); under `CI=true` it always runs.
//!
//! With `TINYFRACTAL_MEASUREMENTS=PATH` it writes the records to PATH as JSON:
//! `boards/measure` does that for `boards/measurements.json`.

use tinyfractal_test_support::qemu as tools;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::mem::size_of;
use std::path::{Path, PathBuf};
use std::process::Command;

use embedded_graphics::prelude::Size;
use tinyfractal::escape::{Render, REFERENCE_POINT_BYTES};
use tinyfractal_scenes::measure::Checksum;
use tinyfractal_scenes::{
    Entry, Work, DEEP_SCENES, DISPLAY_SCENES, DYNAMICS_SCENES, GENERAL_SCENES, GREY,
    MAX_BOARD_REFERENCE_POINTS, PANEL_SCENES, SCENES, TEXTURE_SCENES, ZOOM_SCENES,
};

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
        machine: "mps2-an385",
        cpu: "cortex-m3",
        flash: 4 << 20,
        ram: 4 << 20,
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

/// Builds the measuring firmware for one core, from its own folder (see its Cargo.toml):
/// the newer families' build (textures and dynamics: `Some("newer")`), the dithered
/// panels' (`Some("panels")`), the shapes' (`Some("shapes")`), the terrains'
/// (`Some("terrain")`), or the other scenes' (`None`).
fn build(core: &Core, features: Option<&str>) -> PathBuf {
    let folder = repository().join("boards/qemu-measure");
    tools::ensure_target(&folder, core.target);
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut args = vec!["build", "--release", "--target", core.target];
    if let Some(features) = features {
        args.extend(["--features", features]);
    }
    let status = Command::new(cargo)
        .current_dir(&folder)
        .args(args)
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

/// `text`, `data` and `bss` of an ELF, as Berkeley `size` counts them: allocated sections
/// that take no file space are bss, writable ones data, and the rest (code and constants)
/// text.
fn sizes(elf: &Path) -> (u64, u64, u64) {
    use object::{Object, ObjectSection, SectionFlags};
    const SHF_WRITE: u64 = 0x1;
    const SHF_ALLOC: u64 = 0x2;
    let bytes = std::fs::read(elf).unwrap();
    let file = object::File::parse(&*bytes).unwrap();
    let (mut text, mut data, mut bss) = (0, 0, 0);
    for section in file.sections() {
        let SectionFlags::Elf { sh_flags } = section.flags() else {
            continue;
        };
        if sh_flags & SHF_ALLOC == 0 {
            continue;
        }
        let nobits = matches!(
            section.kind(),
            object::SectionKind::UninitializedData | object::SectionKind::UninitializedTls
        );
        let size = section.size();
        if nobits {
            bss += size;
        } else if sh_flags & SHF_WRITE != 0 {
            data += size;
        } else {
            text += size;
        }
    }
    (text, data, bss)
}

/// Runs the firmware and returns each `measure scene=...` line as key → value.
fn run(core: &Core, elf: &Path) -> Vec<BTreeMap<String, String>> {
    let output = tools::qemu()
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

/// docs/memory.md's RAM claims for perturbation, from the measured stacks: the largest cap
/// whose reference orbit fits the LM3S6965's 64 KiB beside the OLED board's 4 KiB
/// framebuffer, static data and the rest of the deep scene's stack (which holds a
/// reference of `MAX_BOARD_REFERENCE_POINTS`); and the micro:bit's, which runs no
/// perturbed scene: its `Deep` scene's stack plus what perturbation adds to that on
/// Cortex-M3 (the series, the reference's computation), in its 16 KiB, with a render of
/// 32-row tiles (`Render::<'_, 1024>`, smaller by the difference of their tiles).
fn reference_caps(stacks: &BTreeMap<(&str, &str), (u64, u64)>) {
    /// The LM3S6965's RAM (the OLED board's; its measuring runs are on `mps2-an385`).
    const LM3S6965_RAM: u64 = 64 << 10;
    let point = REFERENCE_POINT_BYTES as u64;
    let reference = MAX_BOARD_REFERENCE_POINTS as u64 * point;
    let [m0, _, _] = &CORES;
    let (perturbed, statics) = stacks[&("cortex-m3", "perturbation-zoom")];
    let (deep, _) = stacks[&("cortex-m3", "deep-zoom")];
    // One point more than iterations: Z0.
    let lm3s = (LM3S6965_RAM - 4096 - statics - (perturbed - reference)) / point - 1;
    let added = perturbed - reference - deep;
    let (m0_deep, m0_statics) = stacks[&("cortex-m0", "deep-zoom")];
    let small_tiles = (size_of::<Render>() - size_of::<Render<'_, 1024>>()) as u64;
    let microbit = (m0.ram + small_tiles - m0_statics - m0_deep - added) / point - 1;
    println!(
        "a reference of {lm3s} iterations fits beside the LM3S6965's OLED, about {microbit} in the micro:bit"
    );
    assert!(
        lm3s >= 1850,
        "docs/memory.md says a cap of about 1,900 fits: {lm3s}"
    );
    assert!(
        microbit >= 50,
        "docs/memory.md says a cap of about 55 (at least 50) fits the micro:bit: {microbit}"
    );
}

/// What the host drew for a scene, which every core must draw too.
struct Expected {
    name: &'static str,
    unit: &'static str,
    /// `WxH`, as the firmware prints it.
    size: String,
    checksum: u32,
    pixels: u32,
    work: u64,
}

impl Expected {
    fn new(
        name: &'static str,
        unit: &'static str,
        size: Size,
        target: Checksum,
        work: u64,
    ) -> Self {
        Self {
            name,
            unit,
            size: format!("{}x{}", size.width, size.height),
            checksum: target.value,
            pixels: target.pixels,
            work,
        }
    }
}

#[test]
#[cfg_attr(
    tinyfractal_no_qemu,
    ignore = "needs qemu-system-arm: apt-get install qemu-system-arm"
)]
#[cfg_attr(
    all(tinyfractal_no_thumb_targets, not(tinyfractal_no_qemu)),
    ignore = "needs the Cortex-M targets: rustup target add thumbv6m-none-eabi thumbv7m-none-eabi thumbv7em-none-eabihf"
)]
fn every_core_draws_the_host_picture_and_fits() {
    // The host's checksums: the same scene code into the same checksum target, for every
    // core's scenes (the OLED's, the display-size views and the zoom), then the general engine's
    // and perturbation's, measured where the RAM holds them (not on the M0).
    let expected = |entry: &Entry| {
        let mut target = Checksum::of_size(entry.size);
        let work = entry.scene.draw(&mut target, &GREY).unwrap().count();
        Expected::new(
            entry.name,
            entry.scene.work_unit(),
            entry.size,
            target,
            work,
        )
    };
    // In the order the firmware's five builds measure them: every scene but the newer
    // families', the panels', the shapes and the terrains (then, beyond the M0, the general
    // engine's and perturbation's), then the textures and the dynamics, then the panels,
    // then the shapes, then the terrains.
    let every_core_scenes = SCENES
        .iter()
        .filter(|entry| !entry.scene.is_shape() && !entry.scene.is_terrain())
        .chain(&DISPLAY_SCENES)
        .chain(&ZOOM_SCENES);
    let mut host: Vec<Expected> = every_core_scenes.map(expected).collect();
    let every_core = host.len();
    for entry in &GENERAL_SCENES {
        let mut target = Checksum::of_size(entry.size);
        let Work::Segments(work) = entry.draw(&mut target, &GREY).unwrap() else {
            unreachable!("an L-system counts segments")
        };
        host.push(Expected::new(
            entry.name, "segment", entry.size, target, work,
        ));
    }
    host.extend(DEEP_SCENES.iter().map(expected));
    let newer: Vec<Expected> = TEXTURE_SCENES
        .iter()
        .chain(&DYNAMICS_SCENES)
        .map(expected)
        .collect();
    let panels: Vec<Expected> = PANEL_SCENES.iter().map(expected).collect();
    let shapes: Vec<Expected> = SCENES
        .iter()
        .filter(|entry| entry.scene.is_shape())
        .map(expected)
        .collect();
    let terrains: Vec<Expected> = SCENES
        .iter()
        .filter(|entry| entry.scene.is_terrain())
        .map(expected)
        .collect();

    let mut json = String::from("[\n");
    let mut table = String::new();
    // (core, scene) → (stack, static RAM), for the perturbation RAM claims below.
    let mut stacks = BTreeMap::new();
    for core in &CORES {
        for features in [
            None,
            Some("newer"),
            Some("panels"),
            Some("shapes"),
            Some("terrain"),
        ] {
            let elf = build(core, features);
            let (text, data, bss) = sizes(&elf);
            let records = run(core, &elf);
            let expected: &[Expected] = match (features, core.target.starts_with("thumbv6m")) {
                (Some("newer"), _) => &newer,
                (Some("panels"), _) => &panels,
                (Some("shapes"), _) => &shapes,
                (Some(_), _) => &terrains,
                (None, true) => &host[..every_core],
                (None, false) => &host,
            };
            assert_eq!(
                records.len(),
                expected.len(),
                "{}: one record per scene",
                core.name
            );
            let mut deepest_stack = 0;
            for (record, expected) in records.iter().zip(expected) {
                let Expected {
                    name,
                    unit,
                    ref size,
                    checksum,
                    pixels,
                    work,
                } = *expected;
                assert_eq!(record["scene"], name);
                assert_eq!(record["size"], *size, "{} {name}", core.name);
                assert_eq!(
                    record["checksum"],
                    checksum.to_string(),
                    "{} {name} at {size}: picture differs from the host",
                    core.name
                );
                assert_eq!(record["pixels"], pixels.to_string(), "{} {name}", core.name);
                assert_eq!(record["work"], work.to_string(), "{} {name}", core.name);
                // A scene that did nothing (a feature left out, a path not taken) measures
                // nothing: it would pass every check above with a count of 0.
                assert!(work > 0, "{} {name}: no work done", core.name);
                let instructions: u64 = record["instructions"].parse().unwrap();
                let stack: u64 = record["stack"].parse().unwrap();
                deepest_stack = deepest_stack.max(stack);
                if *size == "128x64" {
                    stacks.insert((core.name, name), (stack, data + bss));
                }
                let _ = writeln!(
                json,
                "  {{\"core\": \"{}\", \"scene\": \"{name}\", \"size\": \"{size}\", \"instructions\": {instructions}, \"baseline_f32\": {}, \"baseline_fixed20\": {}, \"text\": {text}, \"data\": {data}, \"bss\": {bss}, \"stack\": {stack}, \"work\": {work}, \"work_unit\": \"{unit}\"}},",
                core.name, record["baseline_f32"], record["baseline_fixed20"]
            );
                let ratio = |baseline: &str| {
                    baseline.parse::<f64>().map_or("-".to_string(), |b| {
                        format!("{:.1}×", b / instructions as f64)
                    })
                };
                let _ = writeln!(
                table,
                "| {} | {name} | {size} | {instructions} | {:.0} per {unit} | {} | {} | {stack} |",
                core.name,
                instructions as f64 / work.max(1) as f64,
                ratio(&record["baseline_f32"]),
                ratio(&record["baseline_fixed20"]),
            );
            }
            // Budgets with room to spare: thirty-one thirty-seconds of flash (this firmware
            // carries every engine but the newer families', the panels', the shapes' and the
            // terrains' (builds of their own), both baselines, the perturbation's series and finish, the
            // zoom and the expansion table, which no board's firmware does: it outgrew the
            // LM3S6965's 256 KiB, so Cortex-M3 runs it on the MPS2 image's 4 MiB; the OLED
            // board's own firmware takes about 210 KiB of the LM3S6965's), seven eighths
            // of RAM with the deepest stack (the zoom's frame, 10.5 KiB of a byte a pixel and
            // its lines, is the micro:bit's deepest: 13.3 KiB of 16 with its callers).
            assert!(
                text + data <= core.flash * 31 / 32,
                "{}: {text} + {data} bytes of flash",
                core.name
            );
            assert!(
                data + bss + deepest_stack <= core.ram * 7 / 8,
                "{}: {data} + {bss} + {deepest_stack} bytes of RAM",
                core.name
            );
            println!(
                "{}{}: text {text}, data {data}, bss {bss}, deepest stack {deepest_stack}",
                core.name,
                match features {
                    Some("newer") => " (newer families)",
                    Some("panels") => " (panels)",
                    Some("shapes") => " (shapes)",
                    Some(_) => " (terrains)",
                    None => "",
                }
            );
        }
    }
    reference_caps(&stacks);
    json.truncate(json.trim_end_matches(",\n").len());
    json.push_str("\n]\n");
    println!("| core | scene | size | instructions | per unit | f32 baseline ÷ ours | fixed20 baseline ÷ ours | stack |\n|---|---|---|---|---|---|---|---|\n{table}");
    if let Some(path) = std::env::var_os("TINYFRACTAL_MEASUREMENTS") {
        std::fs::write(&path, json).unwrap();
        println!("wrote {}", PathBuf::from(path).display());
    }
}
