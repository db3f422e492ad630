//! The page's requests, answered with the gallery's own renderers: a scene by name, the
//! systems of an L-system file, one of them drawn, an escape-time view.
//!
//! A request is text: the command on the first line, then `key=value` lines, then (for
//! `systems` and `lsystem`) a blank line and the file's text:
//!
//! - `scenes`: the gallery's scene names, one a line.
//! - `scene` with `name`: that scene as its PNG shows it.
//! - `systems`: the file's systems, one a line, and `error: ...` lines for what does not
//!   read.
//! - `lsystem` with `system` (default: the first), `order` (default 4), `size` (`WxH`,
//!   default 320x240): the system drawn as `render lsystem` draws it.
//! - `escape` with `fractal` (`mandelbrot` or `julia`), `center` (`re,im`), `width`,
//!   `max-iter`, `palette`, `precision`, `size`, and for a Julia set `julia` (`re,im`):
//!   the view as `render mandelbrot` draws it (`--algorithm fast`); with `steps=1`, in
//!   budgeted steps (see [`respond_in`]).
//! - `more`: the next step of a view drawn in steps.

use std::path::Path;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use tinyfractal::escape::Tier;
use tinyfractal::{LFile, LsysFile};
use tinyfractal_simulator::escape_scene::{self, Modes};
use tinyfractal_simulator::files::FileKind;
use tinyfractal_simulator::{gallery, scene};

use crate::picture::Picture;
use crate::session::{Session, STEP_ITERATIONS};

/// The largest picture side the page may ask for.
pub const MAX_SIDE: u32 = 2048;

/// The answer to a request: a text (a list, the render's stats, or an error's message)
/// and a picture where one was drawn.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Response {
    /// What the page shows beside the picture, or the error.
    pub text: String,
    /// The picture, if the request drew one.
    pub picture: Option<Picture>,
    /// Whether the text is an error's message.
    pub error: bool,
    /// Whether the picture is partial, more to come from `more` requests.
    pub more: bool,
}

impl Response {
    fn text(text: String) -> Self {
        Self {
            text,
            picture: None,
            error: false,
            more: false,
        }
    }

    fn picture(text: String, display: &SimulatorDisplay<Rgb888>) -> Self {
        Self {
            text,
            picture: Some(Picture::of(display)),
            error: false,
            more: false,
        }
    }

    fn error(text: String) -> Self {
        Self {
            text,
            picture: None,
            error: true,
            more: false,
        }
    }
}

/// A request read: its command, fields and body.
struct Request<'a> {
    command: &'a str,
    fields: Vec<(&'a str, &'a str)>,
    body: &'a str,
}

impl<'a> Request<'a> {
    fn parse(text: &'a str) -> Self {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let (head, body) = match text.split_once("\n\n") {
            Some((head, body)) => (head, body),
            None => (text, ""),
        };
        let mut lines = head.lines().map(str::trim);
        let command = lines.next().unwrap_or_default();
        let fields = lines.filter_map(|line| line.split_once('=')).collect();
        Self {
            command,
            fields,
            body,
        }
    }

    fn field(&self, key: &str) -> Option<&'a str> {
        self.fields
            .iter()
            .find(|(k, _)| k.trim() == key)
            .map(|(_, v)| v.trim())
    }

    fn number(&self, key: &str, default: u32, range: (u32, u32)) -> Result<u32, String> {
        let Some(text) = self.field(key) else {
            return Ok(default);
        };
        match text.parse::<u32>() {
            Ok(value) if (range.0..=range.1).contains(&value) => Ok(value),
            _ => Err(format!(
                "{key} {text:?} is not a whole number from {} to {}",
                range.0, range.1
            )),
        }
    }

    fn size(&self) -> Result<Size, String> {
        let Some(text) = self.field("size") else {
            return Ok(Size::new(320, 240));
        };
        let side = |s: &str| {
            s.trim()
                .parse::<u32>()
                .ok()
                .filter(|v| (1..=MAX_SIDE).contains(v))
        };
        match text.split_once(['x', 'X']) {
            Some((w, h)) => match (side(w), side(h)) {
                (Some(w), Some(h)) => Ok(Size::new(w, h)),
                _ => Err(format!(
                    "size {text:?}: each side from 1 to {MAX_SIDE} pixels, as WIDTHxHEIGHT"
                )),
            },
            None => Err(format!(
                "size {text:?}: write it as WIDTHxHEIGHT, e.g. 320x240"
            )),
        }
    }

    fn pair(&self, key: &str, default: (&'a str, &'a str)) -> Result<(&'a str, &'a str), String> {
        match self.field(key) {
            None => Ok(default),
            Some(text) => text
                .split_once(',')
                .map(|(a, b)| (a.trim(), b.trim()))
                .ok_or_else(|| format!("{key} {text:?}: write it as RE,IM, e.g. -0.75,0")),
        }
    }
}

/// The answer to the request `text` (see the module's documentation).
pub fn respond(text: &str) -> Response {
    let request = Request::parse(text);
    let answer = match request.command {
        "scenes" => Ok(Response::text(gallery::names().join("\n"))),
        "scene" => scene_named(&request),
        "systems" => Ok(systems(&request)),
        "lsystem" => lsystem(&request),
        "escape" => escape(&request),
        other => Err(format!(
            "unknown request {other:?}: ask scenes, scene, systems, lsystem or escape"
        )),
    };
    answer.unwrap_or_else(Response::error)
}

/// The answer to the request `text`, with a view being drawn in steps.
///
/// `escape` with `steps=1` starts one (a fixed tier's view; a perturbed one is drawn
/// whole) and answers its first step, `more` the next, each a partial picture until the
/// last; any other request drops it.
pub fn respond_in(text: &str, session: &mut Option<Session>) -> Response {
    let request = Request::parse(text);
    let started = match request.command {
        "more" => Ok(()),
        "escape" if request.field("steps") == Some("1") => escape_request(&request)
            .and_then(|escape| Session::start(&escape))
            .map(|started| *session = started),
        _ => {
            *session = None;
            return respond(text);
        }
    };
    if let Err(message) = started {
        *session = None;
        return Response::error(message);
    }
    let Some(drawing) = session.as_mut() else {
        return match request.command {
            "more" => Response::error("no view is being drawn: ask `escape` first".to_string()),
            _ => respond(text),
        };
    };
    let complete = drawing.step(STEP_ITERATIONS);
    let response = Response {
        text: drawing.status(),
        picture: Some(drawing.picture()),
        error: false,
        more: !complete,
    };
    if complete {
        *session = None;
    }
    response
}

fn scene_named(request: &Request<'_>) -> Result<Response, String> {
    let name = request.field("name").unwrap_or_default();
    let (display, detail, work, _) = gallery::render_named(name)
        .ok_or_else(|| format!("the gallery has no scene {name:?}"))??;
    Ok(Response::picture(
        format!("{name}: {detail}, {work}"),
        &display,
    ))
}

/// The file's kind: `kind=l` or `kind=lsys`, or by its text.
fn kind(request: &Request<'_>) -> FileKind {
    match request.field("kind") {
        Some("l") => FileKind::Fractint,
        Some("lsys") => FileKind::Lsys,
        _ => FileKind::of(Path::new(""), request.body),
    }
}

/// The file's systems, one a line; after a system whose rules do not read, and for an
/// entry that does not read at all, a line `error: ...` with the reader's message.
fn systems(request: &Request<'_>) -> Response {
    let text = request.body;
    let mut lines = Vec::new();
    let mut entry =
        |name: Result<&str, tinyfractal::Error>, rules: Option<tinyfractal::Error>| match name {
            Ok(name) => {
                lines.push(name.to_string());
                if let Some(error) = rules {
                    lines.push(format!("error: {name}: {error}"));
                }
            }
            Err(error) => lines.push(format!("error: {error}")),
        };
    match kind(request) {
        FileKind::Lsys => {
            for read in LsysFile::new(text).entries() {
                let rules = read.as_ref().ok().and_then(|e| e.parametric().err());
                entry(read.map(|e| e.name()), rules);
            }
        }
        FileKind::Fractint => {
            for read in LFile::new(text).entries() {
                let rules = read.as_ref().ok().and_then(|e| e.grammar().err());
                entry(read.map(|e| e.name()), rules);
            }
        }
        FileKind::Ifs => lines.push("error: the text holds IFS maps, not L-systems".to_string()),
    }
    Response::text(lines.join("\n"))
}

fn lsystem(request: &Request<'_>) -> Result<Response, String> {
    let order = request.number("order", 4, (0, 30))?;
    let size = request.size()?;
    let text = request.body;
    let name = match request.field("system") {
        Some(name) if !name.is_empty() => name.to_string(),
        _ => tinyfractal_simulator::files::entry_names(kind(request), text)
            .into_iter()
            .next()
            .ok_or("the text holds no system: write one, e.g. Koch { Angle 6 Axiom F F=F+F--F+F }")?
            .map_err(|e| e.to_string())?
            .to_string(),
    };
    let failed = |e: tinyfractal::Error| format!("{name}: {e}");
    let (display, segments) = match kind(request) {
        FileKind::Lsys => {
            let system = LsysFile::new(text).entry(&name).map_err(failed)?;
            let grammar = system.parametric().map_err(failed)?;
            let colors = system.colors::<256>().map_err(failed)?;
            let look = scene::GeneralLook {
                colormap: (!colors.is_empty()).then_some(colors.as_slice()),
                ..scene::GeneralLook::default()
            };
            let rendered =
                scene::render_general(&grammar, order, (size.width, size.height), None, &look)
                    .map_err(failed)?;
            (rendered.display, rendered.stats.segments)
        }
        FileKind::Fractint => {
            let grammar = LFile::new(text)
                .entry(&name)
                .and_then(|entry| entry.grammar())
                .map_err(failed)?;
            let rendered =
                scene::render(&grammar, order, size.width, size.height, None).map_err(failed)?;
            (rendered.display, rendered.stats.segments)
        }
        FileKind::Ifs => {
            return Err("the text holds IFS maps, not L-systems".to_string());
        }
    };
    Ok(Response::picture(
        format!("{name} at order {order}: segments={segments}"),
        &display,
    ))
}

fn escape(request: &Request<'_>) -> Result<Response, String> {
    let rendered = escape_scene::render(&escape_request(request)?)?;
    Ok(Response::picture(
        format!(
            "tier={} iterations={}",
            rendered.stats.tier.name(),
            rendered.stats.iterations
        ),
        &rendered.display,
    ))
}

/// The `render mandelbrot` request the fields ask for.
fn escape_request<'a>(request: &Request<'a>) -> Result<escape_scene::Request<'a>, String> {
    let julia_set = match request.field("fractal").unwrap_or("mandelbrot") {
        "mandelbrot" => false,
        "julia" => true,
        other => return Err(format!("fractal {other:?}: mandelbrot or julia")),
    };
    let julia = julia_set
        .then(|| request.pair("julia", ("-0.8", "0.156")))
        .transpose()?;
    let default_centre = if julia_set {
        ("0", "0")
    } else {
        ("-0.75", "0")
    };
    let tier = match request.field("precision").unwrap_or("auto") {
        "auto" => None,
        "narrow" => Some(Tier::Narrow),
        "medium" => Some(Tier::Medium),
        "standard" => Some(Tier::Standard),
        "deep" => Some(Tier::Deep),
        "wide" => Some(Tier::Wide),
        "perturbation" => Some(Tier::Perturbation),
        other => {
            return Err(format!(
                "precision {other:?}: auto, narrow, medium, standard, deep, wide or perturbation"
            ))
        }
    };
    Ok(escape_scene::Request {
        julia,
        centre: request.pair("center", default_centre)?,
        width: request
            .field("width")
            .unwrap_or(if julia_set { "3.2" } else { "3.5" }),
        size: request.size()?,
        max_iterations: request.number("max-iter", 256, (1, 65_535))?,
        algorithm: tinyfractal::escape::Algorithm::Fast,
        tier,
        palette: request.field("palette").unwrap_or("classic"),
        palette_file: None,
        modes: Modes::default(),
    })
}
