//! The gallery: the catalogue's gallery scenes rendered to PNG files, with a table of what
//! each took.

use std::path::Path;
use std::time::Duration;

use rayon::prelude::*;
use tinyfractal_scenes::{
    Entry, EscapeScene, GeneralEntry, IfsEntry, Scene, GALLERY, GENERAL_GALLERY, IFS_GALLERY,
};

fn row(scene: &str, detail: &str, work: &str, elapsed: Duration, file: &Path) -> String {
    format!(
        "| {:<22} | {:<14} | {:>18} | {:>9.3} | {}\n",
        scene,
        detail,
        work,
        elapsed.as_secs_f64() * 1e3,
        file.display()
    )
}

/// Whether the gallery's folder must be made; one message if it is a file.
fn folder_missing(out: &Path) -> Result<bool, String> {
    if out.exists() && !out.is_dir() {
        return Err(format!(
            "gallery --out {}: is a file, not a folder",
            out.display()
        ));
    }
    Ok(!out.exists())
}

/// A scene's picture and what the table says of it: detail, work, time.
pub type Rendered = (Picture, String, String, Duration);

/// Renders every scene, then writes them all into `out` with the table on standard output, or
/// nothing.
///
/// A scene that fails, a full disk or a closed standard output leaves the folder as it was (a
/// folder made for the gallery is removed again).
pub fn run(out: &Path) -> Result<(), String> {
    let make_folder = folder_missing(out)?;
    let scenes = GALLERY.len() + GENERAL_GALLERY.len() + IFS_GALLERY.len();
    let bar = crate::progress::bar(scenes as u64, "gallery");
    let mut rendered: Vec<(&str, Rendered)> = Vec::with_capacity(scenes);
    let mut failed = 0;
    for (name, result) in pictures(|| bar.inc(1)) {
        match result {
            Ok(scene) => rendered.push((name, scene)),
            Err(error) => {
                bar.suspend(|| {
                    crate::console::complain(&format!("tinyfractal: error: {name}: {error}\n"));
                });
                failed += 1;
            }
        }
    }
    bar.finish_and_clear();
    if failed > 0 {
        return Err(format!(
            "the gallery is incomplete ({failed} scenes failed, above): nothing was written"
        ));
    }
    let mut table = format!(
        "| {:<22} | {:<14} | {:>18} | {:>9} | file\n|{:-<24}|{:-<16}|{:->20}|{:->11}|-----\n",
        "scene", "detail", "work", "ms", "", "", "", ""
    );
    let paths: Vec<_> = rendered
        .iter()
        .map(|(name, _)| out.join(format!("{name}.png")))
        .collect();
    let mut plan = crate::output::Plan::new();
    for ((name, (picture, detail, work, elapsed)), path) in rendered.iter().zip(&paths) {
        table.push_str(&row(name, detail, work, *elapsed, path));
        plan.add("gallery --out", path, move |w| {
            crate::output::png(picture, w)
        });
    }
    plan.print(table);
    if make_folder {
        std::fs::create_dir_all(out).map_err(|e| {
            format!(
                "gallery --out {}: cannot make the folder: {e}",
                out.display()
            )
        })?;
    }
    plan.write().inspect_err(|_| {
        if make_folder {
            // Only if empty: nothing of anyone else's is removed.
            let _ = std::fs::remove_dir(out);
        }
    })
}

/// Every scene of the gallery rendered on the pool's threads (`--threads`), in the
/// catalogue's order, `done` called as each is finished: the pictures are the same
/// whatever the number of threads.
pub fn pictures(done: impl Fn() + Sync) -> Vec<(&'static str, Result<Rendered, String>)> {
    jobs()
        .into_par_iter()
        .map(|(name, job)| {
            let result = job.render();
            done();
            (name, result)
        })
        .collect()
}

/// The gallery's scenes by name, in the catalogue's order (its PNG files' names).
pub fn names() -> Vec<&'static str> {
    jobs().into_iter().map(|(name, _)| name).collect()
}

/// The gallery's scene `name` as its PNG shows it, or `None` if the gallery has no such
/// scene (the playground draws it by name).
pub fn render_named(name: &str) -> Option<Result<Rendered, String>> {
    jobs()
        .into_iter()
        .find(|(scene, _)| *scene == name)
        .map(|(_, job)| job.render())
}

/// Every scene of the gallery, from the catalogue's three lists.
fn jobs() -> Vec<(&'static str, Job)> {
    GALLERY
        .iter()
        .map(|entry| (entry.name, Job::Scene(entry)))
        .chain(
            GENERAL_GALLERY
                .iter()
                .map(|entry| (entry.name, Job::General(entry))),
        )
        .chain(
            IFS_GALLERY
                .iter()
                .map(|entry| (entry.name, Job::Ifs(entry))),
        )
        .collect()
}

/// One scene of the gallery, from whichever list of the catalogue.
#[derive(Clone, Copy)]
enum Job {
    Scene(&'static Entry),
    General(&'static GeneralEntry),
    Ifs(&'static IfsEntry),
}

impl Job {
    /// The scene's picture and what the table says of it.
    fn render(self) -> Result<Rendered, String> {
        match self {
            Self::Scene(entry) => picture(entry),
            Self::General(entry) => general_picture(entry),
            Self::Ifs(entry) => {
                let (source, system) = (entry.source, entry.system);
                crate::ifs_scene::render_entry(source, system, entry.points, false, entry.size).map(
                    |(display, plotted, elapsed)| {
                        let work = format!("{plotted} points");
                        (display, "chaos game".to_string(), work, elapsed)
                    },
                )
            }
        }
    }
}

/// A system of the general engine drawn in its entry's colours (or the book's).
fn general_picture(entry: &GeneralEntry) -> Result<Rendered, String> {
    tinyfractal::LsysFile::new(entry.source)
        .entry(entry.system)
        .and_then(|system| Ok((system.parametric()?, system.colors::<256>()?)))
        .and_then(|(grammar, colors)| {
            let look = crate::scene::GeneralLook {
                colormap: (!colors.is_empty()).then_some(colors.as_slice()),
                ..crate::scene::GeneralLook::default()
            };
            crate::scene::render_general(
                &grammar,
                entry.order,
                (entry.size.width, entry.size.height),
                None,
                &look,
            )
        })
        .map_err(|e| e.to_string())
        .map(|rendered| {
            (
                rendered.display,
                format!("order {}", entry.order),
                format!("{} segments", rendered.stats.segments),
                rendered.elapsed,
            )
        })
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
            density,
            ..
        } => crate::ifs_scene::render_entry(source, system, points, density, size).map(
            |(display, plotted, elapsed)| {
                let detail = if density {
                    "chaos game, by density"
                } else {
                    "chaos game"
                };
                (
                    display,
                    detail.to_string(),
                    format!("{plotted} points"),
                    elapsed,
                )
            },
        ),
        Scene::Subdivision { .. }
        | Scene::Terrain { .. }
        | Scene::Walk { .. }
        | Scene::Zoom { .. }
        | Scene::NoiseTerrain { .. }
        | Scene::NoiseFlight { .. }
        | Scene::Bezier { .. }
        | Scene::Particles { .. } => crate::shape_scene::render_entry(&entry.scene, size),
        Scene::Noise { .. } => crate::noise_scene::render_entry(&entry.scene, size),
        Scene::Reaction { .. } => crate::reaction_scene::render_entry(&entry.scene, size),
        Scene::Attractor { kind, points } => crate::attractor_scene::render_entry(
            kind, points, None, size,
        )
        .map(|(display, plotted, elapsed)| {
            (
                display,
                "density".to_string(),
                format!("{plotted} points"),
                elapsed,
            )
        }),
        Scene::Escape(EscapeScene {
            julia,
            centre,
            width,
            max_iterations,
            shading,
            tier,
            one_bit,
            distance,
        }) => {
            let request = crate::escape_scene::Request {
                julia,
                centre,
                width,
                size,
                max_iterations,
                algorithm: tinyfractal::escape::Algorithm::Fast,
                tier,
                palette: entry.palette,
                palette_file: None,
                modes: crate::escape_scene::Modes {
                    distance,
                    ..Default::default()
                },
            };
            crate::escape_scene::render(&request).and_then(|rendered| {
                if rendered.view.shading() != shading {
                    return Err(format!(
                        "the catalogue paints a {shading:?} view with `{}`",
                        entry.palette
                    ));
                }
                // A forced tier that is not exact by the rule says so in its row.
                let caveat = match crate::escape_scene::TierWarning::of(&rendered.view) {
                    Some(_) => ", not exact (a forced tier)",
                    None => "",
                };
                // A one-bit panel's scene as the panel shows it.
                let display = match one_bit.and_then(|dither| {
                    crate::common::as_panel(
                        &rendered.display,
                        crate::common::Panel::OneBit,
                        crate::common::DitherName::of(dither),
                    )
                }) {
                    Some(shown) => shown,
                    None => rendered.display,
                };
                Ok((
                    display,
                    format!("{} tier{caveat}", rendered.stats.tier.name()),
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
