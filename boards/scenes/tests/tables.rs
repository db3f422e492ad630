//! The performance tables in `docs/performance.md`, `docs/families.md` and the README are
//! generated from the measurements (`boards/measurements.json`, written by `boards/measure`,
//! and `benches/results.json`, written by `benches/record`), never typed by hand. This test
//! regenerates every table and fails when a document's copy is stale; `TINYFRACTAL_BLESS=1` (or
//! `boards/tables`) writes them instead.
//!
//! A table sits between `<!-- generated: NAME -->` and `<!-- end: NAME -->`.

use std::path::{Path, PathBuf};

use serde_json::Value;

fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn read_json(path: &str) -> Value {
    let path = repository().join(path);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// 1234567 as "1,234,567".
fn thousands(value: u64) -> String {
    let digits = value.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

fn number(record: &Value, key: &str) -> Option<u64> {
    record.get(key).and_then(Value::as_u64)
}

fn text<'a>(record: &'a Value, key: &str) -> &'a str {
    record.get(key).and_then(Value::as_str).unwrap_or("?")
}

/// Every Cortex-M record: instructions per frame and per unit of work, against the baselines.
fn cortex_m_table(records: &[Value]) -> String {
    let mut table = String::from(
        "| core | scene | frame | instructions per frame | per unit | f32 baseline | fixed20 baseline | stack (bytes) |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for record in records {
        let instructions = number(record, "instructions").unwrap_or(0);
        let work = number(record, "work").unwrap_or(1).max(1);
        let baseline = |key: &str| {
            number(record, key).map_or("—".to_string(), |b| {
                format!("{} ({:.1}×)", thousands(b), b as f64 / instructions as f64)
            })
        };
        table.push_str(&format!(
            "| {} | {} | {} | {} | {} per {} | {} | {} | {} |\n",
            text(record, "core"),
            text(record, "scene"),
            text(record, "size"),
            thousands(instructions),
            thousands((instructions as f64 / work as f64).round() as u64),
            text(record, "work_unit"),
            baseline("baseline_f32"),
            baseline("baseline_fixed20"),
            thousands(number(record, "stack").unwrap_or(0)),
        ));
    }
    table
}

/// Flash of the measuring firmware per core, and the deepest stack.
fn footprint_table(records: &[Value]) -> String {
    let mut table = String::from(
        "| core | `.text` (bytes) | `.data` | `.bss` | deepest stack (bytes) |\n|---|---|---|---|---|\n",
    );
    let mut cores: Vec<&str> = records.iter().map(|r| text(r, "core")).collect();
    cores.dedup();
    for core in cores {
        let of_core: Vec<&Value> = records.iter().filter(|r| text(r, "core") == core).collect();
        let first = of_core[0];
        let stack = of_core
            .iter()
            .filter_map(|r| number(r, "stack"))
            .max()
            .unwrap_or(0);
        table.push_str(&format!(
            "| {core} | {} | {} | {} | {} |\n",
            thousands(number(first, "text").unwrap_or(0)),
            number(first, "data").unwrap_or(0),
            number(first, "bss").unwrap_or(0),
            thousands(stack),
        ));
    }
    table
}

/// The README's short table: the full Mandelbrot view and the Julia set on each core, at
/// the OLED's frame and a real display's, against the better of the two naive loops.
fn summary_table(records: &[Value]) -> String {
    let mut table = String::from(
        "| core | view | frame | ours | naive f32 loop | naive fixed-point loop | fewer instructions than the better one |\n|---|---|---|---|---|---|---|\n",
    );
    let views = [
        ("mandelbrot", "Mandelbrot full view"),
        ("julia", "Julia k = −0.8 + 0.156i"),
    ];
    for (scene, what) in views {
        for record in records.iter().filter(|r| text(r, "scene") == scene) {
            let ours = number(record, "instructions").unwrap_or(1).max(1);
            let f32_loop = number(record, "baseline_f32").unwrap_or(0);
            let fixed = number(record, "baseline_fixed20").unwrap_or(0);
            let better = f32_loop.min(fixed);
            table.push_str(&format!(
                "| {} | {what}, max-iter {} | {} | {} | {} | {} | {:.1}× |\n",
                text(record, "core"),
                max_iterations(scene, text(record, "size")),
                text(record, "size").replace('x', "×"),
                thousands(ours),
                thousands(f32_loop),
                thousands(fixed),
                better as f64 / ours as f64,
            ));
        }
    }
    table
}

/// The iteration cap of the catalogue's escape-time entry `scene` at `size` (`WxH`).
fn max_iterations(scene: &str, size: &str) -> u32 {
    tinyfractal_scenes::SCENES
        .iter()
        .chain(&tinyfractal_scenes::DISPLAY_SCENES)
        .filter(|entry| entry.name == scene)
        .filter(|entry| format!("{}x{}", entry.size.width, entry.size.height) == size)
        .find_map(|entry| match entry.scene {
            tinyfractal_scenes::Scene::Escape(escape) => Some(escape.max_iterations),
            _ => None,
        })
        .unwrap_or(0)
}

fn milliseconds(ns: u64) -> String {
    let ms = ns as f64 / 1e6;
    if ms < 10.0 {
        format!("{ms:.2} ms")
    } else {
        format!("{ms:.1} ms")
    }
}

/// The L-system benches: the Koch snowflake at order 8.
fn lsystem_table(results: &Value) -> String {
    const SEGMENTS: u64 = 3 * 4u64.pow(8);
    let mut table = String::from("| what | time | segments per second |\n|---|---|---|\n");
    let times = &results["times_ns"];
    let time = |key: &str| number(times, &format!("koch-snowflake-order-8 / {key}")).unwrap_or(0);
    const PEER: &str = "peer: lindenmayer + f32 turtle, two walks + Bresenham";
    const CLI: &str = "fit + draw (expansion table, as the CLI)";
    for (key, what) in [
        ("segments (walk + turtle)", "walk + turtle (`Segments`)"),
        (
            "fit (walk: sizing pass, box predicted)",
            "fit by walking (a sizing pass; the box predicted from it)",
        ),
        (
            "draw (walk + rasterise)",
            "draw by walking, rasterised into a 320×240 RGB565 framebuffer",
        ),
        (
            "fit (expansion table)",
            "fit from the expansion table (`fit_in`)",
        ),
        (
            "draw (expansion table: culling, one pixel per sub-pixel subtree)",
            "draw through the table: culling, one pixel per sub-pixel subtree",
        ),
        (CLI, "**fit + draw through the table, as the CLI**"),
        (
            PEER,
            "peer: `lindenmayer` crate + `f32` turtle, two walks + Bresenham",
        ),
    ] {
        let ns = time(key);
        let per_second = SEGMENTS as f64 / (ns.max(1) as f64 / 1e9);
        table.push_str(&format!(
            "| {what} | {} | {:.0} M |\n",
            milliseconds(ns),
            per_second / 1e6
        ));
    }
    table.push_str(&format!(
        "\nFit and draw through the table take {:.1}× less time than the peer.\n",
        time(PEER) as f64 / time(CLI).max(1) as f64
    ));
    table
}

/// Each core's record of `scene`: the core, its instructions and instructions per unit of
/// work (with thousands separators).
fn cortex_m_rows<'a>(
    records: &'a [Value],
    scene: &'a str,
) -> impl Iterator<Item = (&'a str, u64, String)> + 'a {
    records
        .iter()
        .filter(move |r| text(r, "scene") == scene)
        .map(|record| {
            let instructions = number(record, "instructions").unwrap_or(0);
            let work = number(record, "work").unwrap_or(1).max(1);
            let per_unit = thousands((instructions as f64 / work as f64).round() as u64);
            (text(record, "core"), instructions, per_unit)
        })
}

/// The L-system scenes' instructions per drawn segment on each core (128×64), against
/// the compiled engine issue's starting point (the issue's own figures, measured then) and
/// its goal of 5× fewer.
fn lsystem_goal_table(records: &[Value]) -> String {
    const START: [(&str, u64, u64); 3] = [
        ("cortex-m0", 5_299, 7_077),
        ("cortex-m3", 2_952, 4_362),
        ("cortex-m4", 2_967, 4_394),
    ];
    let per_segment = |core: &str, scene: &str| {
        let record = records
            .iter()
            .find(|r| text(r, "core") == core && text(r, "scene") == scene)
            .unwrap_or_else(|| panic!("no {core} {scene} record"));
        number(record, "instructions").unwrap_or(0) as f64
            / number(record, "work").unwrap_or(1).max(1) as f64
    };
    let mut table = String::from(
        "| core | snowflake: at the start / now | plant: at the start / now |\n|---|---|---|\n",
    );
    for (core, snowflake, plant) in START {
        let cell = |start: u64, scene: &str| {
            let now = per_segment(core, scene);
            format!(
                "{} / {} ({:.1}×)",
                thousands(start),
                thousands(now.round() as u64),
                start as f64 / now
            )
        };
        table.push_str(&format!(
            "| {core} | {} | {} |\n",
            cell(snowflake, "koch-snowflake"),
            cell(plant, "plant")
        ));
    }
    table
}

/// The general engine: ABOP's monopodial tree (figure 2.6) at order 10, on the host
/// (benches) and on Cortex-M3 and M4 (the measuring firmware, 128×64).
fn general_table(records: &[Value], results: &Value) -> String {
    const SEGMENTS: u64 = 1023;
    let mut table =
        String::from("| where | what | time or instructions | per segment |\n|---|---|---|---|\n");
    let times = &results["times_ns"];
    for (key, what) in [
        (
            "segments (walk + 3D turtle)",
            "walk + 3D turtle (`Segments3`)",
        ),
        ("fit + draw 320x240", "fit + draw into 320×240"),
        (
            "fit keeping marks + draw 320x240",
            "fit keeping its marks + draw into 320×240",
        ),
    ] {
        let ns = number(times, &format!("monopodial-tree-order-10 / {key}")).unwrap_or(0);
        table.push_str(&format!(
            "| host | {what} | {} | {:.0} k segments per second |
",
            milliseconds(ns),
            SEGMENTS as f64 / (ns.max(1) as f64 / 1e9) / 1e3
        ));
    }
    for (core, instructions, per_unit) in cortex_m_rows(records, "monopodial-tree") {
        table.push_str(&format!(
            "| {core} | read the text, fit and draw into 128×64 | {} instructions | {per_unit} instructions |\n",
            thousands(instructions),
        ));
    }
    // The sketches beside it: the string expanded in a byte buffer, a float 3D turtle or
    // a careful Q16.16 one.
    for record in records.iter().filter(|r| r["scene"] == "monopodial-tree") {
        let core = record["core"].as_str().unwrap_or("?");
        let work = record["work"].as_u64().unwrap_or(1).max(1);
        for (key, sketch) in [
            ("baseline_f32", "the naive f32 sketch (its string expanded)"),
            (
                "baseline_fixed20",
                "a careful Q16.16 sketch (its string expanded)",
            ),
        ] {
            if let Some(cost) = record[key].as_u64() {
                table.push_str(&format!(
                    "| {core} | {sketch} | {} instructions | {} instructions |\n",
                    thousands(cost),
                    thousands(cost / work),
                ));
            }
        }
    }
    table
}

/// The chaos game: the lecture's fern on the host (100,000 points into 320×240) and on
/// Cortex-M0/M3/M4 (the measuring firmware, 20,000 points into 128×64).
fn ifs_table(records: &[Value], results: &Value) -> String {
    const POINTS: u64 = 100_000;
    let mut table =
        String::from("| where | what | time or instructions | per point |\n|---|---|---|---|\n");
    let times = &results["times_ns"];
    for key in ["chaos game", "fit + draw 320x240"] {
        let ns = number(times, &format!("ifs-fern-100k / {key}")).unwrap_or(0);
        table.push_str(&format!(
            "| host | {key} | {} | {:.0} M points per second |\n",
            milliseconds(ns),
            POINTS as f64 / (ns.max(1) as f64 / 1e9) / 1e6
        ));
    }
    for (core, instructions, per_unit) in cortex_m_rows(records, "ifs-fern") {
        table.push_str(&format!(
            "| {core} | read, fit (a sample) and draw | {} instructions | {per_unit} instructions |\n",
            thousands(instructions),
        ));
    }
    for (core, instructions, per_unit) in cortex_m_rows(records, "ifs-fern-density") {
        table.push_str(&format!(
            "| {core} | read, fit (a sample), count and draw by density | {} instructions | {per_unit} instructions |\n",
            thousands(instructions),
        ));
    }
    // The sketches beside it: the lecture's table in f32, and in careful Q16.16.
    for record in records.iter().filter(|r| r["scene"] == "ifs-fern") {
        let core = record["core"].as_str().unwrap_or("?");
        let work = record["work"].as_u64().unwrap_or(1).max(1);
        for (key, what) in [
            ("baseline_f32", "the naive f32 sketch"),
            ("baseline_fixed20", "a careful Q16.16 sketch"),
        ] {
            if let Some(cost) = record[key].as_u64() {
                table.push_str(&format!(
                    "| {core} | {what} | {} instructions | {} instructions |\n",
                    thousands(cost),
                    thousands(cost / work),
                ));
            }
        }
    }
    table
}

/// The Sierpiński family and terrain: the host benches at 320×240 and the boards' scenes
/// on Cortex-M0/M3/M4 (128×64), per square, triangle, cube or height.
fn shapes_table(records: &[Value], results: &Value) -> String {
    let mut table =
        String::from("| where | what | time or instructions | per unit |\n|---|---|---|---|\n");
    let times = &results["times_ns"];
    #[rustfmt::skip]
    let benches = [
        ("carpet-order-4", "fit + draw 320x240 (squares)", "carpet, order 4, fit + draw 320×240", 8u64.pow(4), "squares"),
        ("gasket-order-7", "fit + draw 320x240 (triangles)", "gasket, order 7, fit + draw 320×240", 3u64.pow(7), "triangles"),
        ("menger-order-3", "fit + draw 320x240 (cubes)", "Menger sponge, order 3, fit + draw 320×240", 20u64.pow(3), "cubes"),
        ("terrain-65537", "heights (points)", "profile, 65,537 heights", (1 << 16) + 1, "heights"),
        ("terrain-65537", "fit + draw 320x240 (points)", "profile, 65,537 heights, fit + draw 320×240", (1 << 16) + 1, "heights"),
        ("terrain2d-257", "diamond-square (points)", "landscape, 257², diamond-square", 257 * 257, "heights"),
    ];
    for (group, function, what, count, unit) in benches {
        let Some(ns) = number(times, &format!("{group} / {function}")) else {
            continue;
        };
        table.push_str(&format!(
            "| host | {what} | {} | {:.1} M {unit} per second |\n",
            milliseconds(ns),
            count as f64 / (ns.max(1) as f64 / 1e9) / 1e6
        ));
    }
    let scenes = [
        ("sierpinski-carpet", "carpet, order 3", "square"),
        ("sierpinski-gasket", "gasket, order 6", "triangle"),
        ("menger-sponge", "Menger sponge, order 2", "cube"),
        ("terrain", "profile, 129 heights", "height"),
        ("terrain2d", "landscape, 33², shaded", "height"),
    ];
    for (scene, what, unit) in scenes {
        for (core, instructions, per_unit) in cortex_m_rows(records, scene) {
            table.push_str(&format!(
                "| {core} | {what}, fit + draw 128×64 | {} instructions | {per_unit} per {unit} |\n",
                thousands(instructions),
            ));
        }
        // The sketches beside it (naive.rs): recursive in f32, and in careful Q16.16.
        for record in records.iter().filter(|r| r["scene"] == scene) {
            let core = record["core"].as_str().unwrap_or("?");
            let work = record["work"].as_u64().unwrap_or(1).max(1);
            for (key, sketch) in [
                ("baseline_f32", "the naive f32 sketch"),
                ("baseline_fixed20", "a careful Q16.16 sketch"),
            ] {
                if let Some(cost) = record[key].as_u64() {
                    table.push_str(&format!(
                        "| {core} | {what}, {sketch} | {} instructions | {} per {unit} |\n",
                        thousands(cost),
                        thousands(cost / work),
                    ));
                }
            }
        }
    }
    table
}

/// The boards' walking figure on Cortex-M0/M3/M4: its frames into 128×64, each erasing the
/// last.
fn figure_table(records: &[Value]) -> String {
    let frames = tinyfractal_scenes::SCENES
        .iter()
        .find_map(|entry| match entry.scene {
            tinyfractal_scenes::Scene::Walk { frames } => Some(u64::from(frames)),
            _ => None,
        })
        .unwrap_or(1)
        .max(1);
    let mut table = format!(
        "| core | {frames} frames (fit once, erase and draw each) | per frame | per line drawn | a float matrix stack's frame (naive.rs) | a Q16.16 matrix stack's frame |\n|---|---|---|---|---|---|\n",
    );
    for (core, instructions, per_line) in cortex_m_rows(records, "walking-figure") {
        let sketch = |key: &str| {
            records
                .iter()
                .find(|r| r["scene"] == "walking-figure" && r["core"] == core)
                .and_then(|r| r[key].as_u64())
                .map_or("-".to_string(), |cost| thousands(cost / frames))
        };
        table.push_str(&format!(
            "| {core} | {} instructions | {} | {per_line} | {} | {} |\n",
            thousands(instructions),
            thousands(instructions / frames),
            sketch("baseline_f32"),
            sketch("baseline_fixed20"),
        ));
    }
    table
}

/// The escape-time benches: two views at 320×240, max-iter 256.
fn escape_table(results: &Value) -> String {
    let mut table = String::from(
        "| view | algorithm | tier | time | iterations (of naive) | pixels computed | draw calls |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let times = &results["times_ns"];
    let work = results["work"].as_array().cloned().unwrap_or_default();
    for view in ["full-view", "seahorse-zoom"] {
        let name = view.replace('-', " ");
        let group = format!("mandelbrot {name} 320x240 max-iter 256");
        let rows: Vec<&Value> = work.iter().filter(|w| text(w, "view") == view).collect();
        let naive = rows
            .first()
            .and_then(|w| number(w, "naive"))
            .unwrap_or(1)
            .max(1);
        table.push_str(&format!(
            "| {name} | naive f64 | — | {} | {} (100 %) | 100 % | — |\n",
            milliseconds(number(times, &format!("{group} / naive f64 per pixel")).unwrap_or(0)),
            thousands(naive)
        ));
        for row in rows {
            let algorithm = text(row, "algorithm");
            let iterations = number(row, "iterations").unwrap_or(0);
            let pixels = number(row, "pixels").unwrap_or(0);
            let of = number(row, "of").unwrap_or(1).max(1);
            table.push_str(&format!(
                "| {name} | `{algorithm}` | {} | {} | {} ({:.1} %) | {:.1} % | {} |\n",
                text(row, "tier"),
                milliseconds(number(times, &format!("{group} / {algorithm}")).unwrap_or(0)),
                thousands(iterations),
                100.0 * iterations as f64 / naive as f64,
                100.0 * pixels as f64 / of as f64,
                thousands(number(row, "draw_calls").unwrap_or(0)),
            ));
        }
    }
    table
}

/// The deep-zoom benches (320×240): perturbation against `Deep` where both draw, and alone
/// past `Deep`'s reach; then the boards' deep scenes on Cortex-M3 and M4.
fn deep_table(records: &[Value], results: &Value) -> String {
    let mut table = String::from(
        "| view | method | tier | time | iterations computed | skipped by the series | rebases |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let times = &results["times_ns"];
    let work = results["work"].as_array().cloned().unwrap_or_default();
    for row in work.iter().filter(|w| w.get("method").is_some()) {
        let name = text(row, "view").replace('_', " ");
        let method = text(row, "method");
        let group = format!("deep {name} 320x240");
        table.push_str(&format!(
            "| {name} | {method} | {} | {} | {} | {} | {} |\n",
            text(row, "tier"),
            milliseconds(number(times, &format!("{group} / {method}")).unwrap_or(0)),
            thousands(number(row, "iterations").unwrap_or(0)),
            thousands(number(row, "skipped").unwrap_or(0)),
            thousands(number(row, "rebases").unwrap_or(0)),
        ));
    }
    table.push_str(
        "\n| core | board scene (128×64) | instructions | iterations computed |\n|---|---|---|---|\n",
    );
    for scene in ["deep-zoom", "deep-zoom-perturbed", "perturbation-zoom"] {
        for record in records.iter().filter(|r| text(r, "scene") == scene) {
            if text(record, "core") == "cortex-m0" {
                continue;
            }
            table.push_str(&format!(
                "| {} | {scene} | {} | {} |\n",
                text(record, "core"),
                thousands(number(record, "instructions").unwrap_or(0)),
                thousands(number(record, "work").unwrap_or(0)),
            ));
        }
    }
    table
}

/// `document` with each named region replaced by its table.
fn regenerated(document: &str, tables: &[(&str, String)]) -> String {
    let mut out = document.to_string();
    for (name, table) in tables {
        let (open, close) = (
            format!("<!-- generated: {name} -->\n"),
            format!("<!-- end: {name} -->"),
        );
        let Some(start) = out.find(&open) else {
            continue;
        };
        let body = start + open.len();
        let end = body
            + out[body..]
                .find(&close)
                .unwrap_or_else(|| panic!("`{close}` is missing"));
        out.replace_range(body..end, table);
    }
    out
}

#[test]
fn performance_tables_are_generated_from_the_measurements() {
    let measurements = read_json("boards/measurements.json");
    let records = measurements.as_array().expect("an array of records");
    let results = read_json("benches/results.json");
    let tables = [
        ("cortex-m", cortex_m_table(records)),
        ("footprint", footprint_table(records)),
        ("summary", summary_table(records)),
        ("lsystem-bench", lsystem_table(&results)),
        ("lsystem-goal", lsystem_goal_table(records)),
        ("escape-bench", escape_table(&results)),
        ("deep-bench", deep_table(records, &results)),
        ("general-bench", general_table(records, &results)),
        ("ifs-bench", ifs_table(records, &results)),
        ("shapes-bench", shapes_table(records, &results)),
        ("figure-bench", figure_table(records)),
    ];
    let bless = std::env::var_os("TINYFRACTAL_BLESS").is_some();
    let mut stale = Vec::new();
    for document in ["README.md", "docs/performance.md", "docs/families.md"] {
        let path = repository().join(document);
        let text = std::fs::read_to_string(&path).unwrap();
        let fresh = regenerated(&text, &tables);
        if fresh != text {
            if bless {
                std::fs::write(&path, fresh).unwrap();
                println!("wrote {document}");
            } else {
                stale.push(document);
            }
        }
    }
    assert!(
        stale.is_empty(),
        "stale generated tables in {stale:?}: run boards/tables (TINYFRACTAL_BLESS=1) and commit"
    );
}

#[test]
fn regions_are_replaced_and_the_rest_kept() {
    let document = "a\n<!-- generated: t -->\nold\n<!-- end: t -->\nb\n";
    assert_eq!(
        regenerated(document, &[("t", "new\n".into())]),
        "a\n<!-- generated: t -->\nnew\n<!-- end: t -->\nb\n"
    );
    assert_eq!(thousands(1_234_567), "1,234,567");
    assert_eq!(thousands(12), "12");
}
