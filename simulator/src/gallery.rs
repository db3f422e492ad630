//! The gallery: the catalogue's gallery scenes rendered to PNG files, with a table of what
//! each took.

use std::path::Path;
use std::time::Duration;

use tinyfractal_scenes::{Entry, Scene, GALLERY, GENERAL_GALLERY, IFS_GALLERY};

fn row(scene: &str, detail: &str, work: &str, elapsed: std::time::Duration, file: &Path) {
    println!(
        "| {:<22} | {:<14} | {:>18} | {:>9.3} | {}",
        scene,
        detail,
        work,
        elapsed.as_secs_f64() * 1e3,
        file.display()
    );
}

/// The gallery's folder, made if it is missing; one message if it cannot be.
fn folder(out: &Path) -> Result<(), String> {
    if out.exists() && !out.is_dir() {
        return Err(format!(
            "gallery --out {}: is a file, not a folder",
            out.display()
        ));
    }
    std::fs::create_dir_all(out).map_err(|e| {
        format!(
            "gallery --out {}: cannot make the folder: {e}",
            out.display()
        )
    })
}

/// Renders every scene into `out` and prints a table.
pub fn run(out: &Path) -> Result<(), String> {
    folder(out)?;
    println!(
        "| {:<22} | {:<14} | {:>18} | {:>9} | file",
        "scene", "detail", "work", "ms"
    );
    println!("|{:-<24}|{:-<16}|{:->20}|{:->11}|-----", "", "", "", "");
    let mut ok = true;
    let scenes = GALLERY.len() + GENERAL_GALLERY.len() + IFS_GALLERY.len();
    let bar = crate::animate::progress(scenes as u64, "gallery");
    let mut report =
        |name: &str, result: Result<(String, String, std::time::Duration), String>, path: &Path| {
            bar.suspend(|| match result {
                Ok((detail, work, elapsed)) => row(name, &detail, &work, elapsed, path),
                Err(error) => {
                    eprintln!("tinyfractal: error: {name}: {error}");
                    ok = false;
                }
            });
            bar.inc(1);
        };
    for entry in &GALLERY {
        let path = out.join(format!("{}.png", entry.name));
        let result = picture(entry).and_then(|(display, detail, work, elapsed)| {
            save(&display, &path)?;
            Ok((detail, work, elapsed))
        });
        report(entry.name, result, &path);
    }
    for entry in &GENERAL_GALLERY {
        let path = out.join(format!("{}.png", entry.name));
        let result = tinyfractal::LsysFile::new(entry.source)
            .entry(entry.system)
            .and_then(|system| system.parametric())
            .and_then(|grammar| {
                crate::scene::render_general(
                    &grammar,
                    entry.order,
                    (entry.size.width, entry.size.height),
                    None,
                    &crate::scene::GeneralLook::default(),
                )
            })
            .map_err(|e| e.to_string())
            .and_then(|rendered| {
                save(&rendered.display, &path)?;
                Ok((
                    format!("order {}", entry.order),
                    format!("{} segments", rendered.stats.segments),
                    rendered.elapsed,
                ))
            });
        report(entry.name, result, &path);
    }
    for entry in &IFS_GALLERY {
        let path = out.join(format!("{}.png", entry.name));
        let result =
            crate::ifs_scene::render_entry(entry.source, entry.system, entry.points, entry.size)
                .and_then(|(display, plotted, elapsed)| {
                    save(&display, &path)?;
                    Ok((
                        "chaos game".to_string(),
                        format!("{plotted} points"),
                        elapsed,
                    ))
                });
        report(entry.name, result, &path);
    }
    bar.finish_and_clear();
    if ok {
        Ok(())
    } else {
        Err("the gallery is incomplete".to_string())
    }
}

fn save(
    display: &embedded_graphics_simulator::SimulatorDisplay<embedded_graphics::pixelcolor::Rgb888>,
    path: &Path,
) -> Result<(), String> {
    crate::output::save_png(display, "gallery --out", path)
}

/// A catalogue entry's picture at its size, with what the gallery reports: a detail (order,
/// tier, ...), the work done, and the time it took.
pub fn picture(entry: &Entry) -> Result<(Picture, String, String, Duration), String> {
    let size = entry.size;
    match entry.scene {
        Scene::LSystem {
            system,
            order,
            orientation,
        } => system
            .grammar()
            .and_then(|grammar| {
                crate::scene::render_oriented(&grammar, order, size.width, size.height, orientation)
            })
            .map_err(|e| e.to_string())
            .map(|rendered| {
                (
                    rendered.display,
                    format!("order {order}"),
                    format!("{} segments", rendered.stats.segments),
                    rendered.elapsed,
                )
            }),
        Scene::Ifs {
            source,
            system,
            points,
            ..
        } => crate::ifs_scene::render_entry(source, system, points, size).map(
            |(display, plotted, elapsed)| {
                (
                    display,
                    "chaos game".to_string(),
                    format!("{plotted} points"),
                    elapsed,
                )
            },
        ),
        Scene::Subdivision { .. }
        | Scene::Terrain { .. }
        | Scene::Walk { .. }
        | Scene::Zoom { .. } => crate::shape_scene::render_entry(&entry.scene, size),
        Scene::Escape {
            julia,
            centre,
            width,
            max_iterations,
            shading,
            tier,
        } => {
            let request = crate::escape_scene::Request {
                julia,
                centre,
                width,
                size,
                max_iterations,
                algorithm: tinyfractal::Algorithm::Fast,
                tier,
                palette: entry.palette,
            };
            crate::escape_scene::render(&request).and_then(|rendered| {
                if rendered.view.shading() != shading {
                    return Err(format!(
                        "the catalogue paints a {shading:?} view with `{}`",
                        entry.palette
                    ));
                }
                Ok((
                    rendered.display,
                    format!("{} tier", rendered.stats.tier.name()),
                    format!("{} iterations", rendered.stats.iterations),
                    rendered.elapsed,
                ))
            })
        }
    }
}

/// A rendered picture.
pub type Picture =
    embedded_graphics_simulator::SimulatorDisplay<embedded_graphics::pixelcolor::Rgb888>;
