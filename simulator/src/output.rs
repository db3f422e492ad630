//! Writing a run's outputs: all of them or none, and nothing destroyed on the way.
//!
//! Every output of a run is planned first ([`Plan`]): two outputs naming one file are
//! refused, as is a folder or a missing folder, before anything is written. Then each
//! output streams into a uniquely named temporary file beside its target (`tempfile`), and
//! only when all of them are complete are they renamed over their targets. A target that
//! is not a regular file (a FIFO, a device such as `/dev/null`) is written directly, after
//! every temporary file is complete, and never replaced; a symlink is followed, and its
//! target written (atomically, when that is a regular file). Nothing the program did not
//! create is ever removed, and a failure removes the temporary files it made; so does an
//! interrupt (Ctrl-C, SIGTERM: [`remove_temporaries_on_interrupt`]).

use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use image::ImageEncoder;

/// The temporary files being written now: what an interrupt removes.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Makes Ctrl-C (SIGINT), SIGTERM and SIGHUP remove the temporary files of the outputs being
/// written, then end the run with status 130.
///
/// A run stopped half way leaves the folder as it was. Called once, as the run starts.
pub fn remove_temporaries_on_interrupt() {
    // A browser's page (the playground's build) has no signals to handle.
    #[cfg(not(target_arch = "wasm32"))]
    // A second handler cannot be set (tests call `run` once a process): nothing to do.
    let _ = ctrlc::set_handler(|| {
        let paths = TEMPORARIES
            .lock()
            .map(|paths| paths.clone())
            .unwrap_or_default();
        for path in paths {
            let _ = fs::remove_file(path);
        }
        crate::console::complain("tinyfractal: interrupted: nothing was written\n");
        std::process::exit(130);
    });
}

/// A temporary file's place in [`TEMPORARIES`] while it lives.
struct Registered(PathBuf);

impl Registered {
    fn new(path: &Path) -> Self {
        if let Ok(mut paths) = TEMPORARIES.lock() {
            paths.push(path.to_path_buf());
        }
        Self(path.to_path_buf())
    }
}

impl Drop for Registered {
    fn drop(&mut self) {
        if let Ok(mut paths) = TEMPORARIES.lock() {
            paths.retain(|path| path != &self.0);
        }
    }
}

/// Produces an output's bytes into a writer (it may be called once).
type Producer<'a> = Box<dyn FnOnce(&mut dyn Write) -> io::Result<()> + 'a>;

/// One output: where it goes, what names it (for messages), and how its bytes are made.
struct Output<'a> {
    option: &'static str,
    path: PathBuf,
    produce: Producer<'a>,
}

/// The outputs of one run, written all together by [`Plan::write`].
#[derive(Default)]
pub struct Plan<'a> {
    outputs: Vec<Output<'a>>,
    /// Text for standard output, printed before the outputs are put in place.
    printed: String,
    /// More of it, made once every output is complete.
    printed_after: Option<Box<dyn FnOnce() -> Result<String, String> + 'a>>,
}

/// Where an output's bytes go: through a temporary file renamed over `target` (a regular
/// file, or none yet), or, for anything else (a FIFO, a device), into `target` in place.
struct Destination {
    target: PathBuf,
    in_place: bool,
}

impl<'a> Plan<'a> {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds an output named by `option` (e.g. `--out`) at `path`.
    pub fn add(
        &mut self,
        option: &'static str,
        path: &Path,
        produce: impl FnOnce(&mut dyn Write) -> io::Result<()> + 'a,
    ) {
        self.outputs.push(Output {
            option,
            path: path.to_path_buf(),
            produce: Box::new(produce),
        });
    }

    /// Where each output goes, checked without writing anything: see the module docs.
    fn resolve(&self) -> Result<Vec<Destination>, String> {
        let mut destinations: Vec<Destination> = Vec::new();
        let mut identities: Vec<(&'static str, PathBuf)> = Vec::new();
        for output in &self.outputs {
            let destination = destination(output.option, &output.path)?;
            let identity = identity(&destination.target);
            if let Some((other, _)) = identities.iter().find(|(_, seen)| *seen == identity) {
                return Err(format!(
                    "{other} and {} both name {}: give each output its own file",
                    output.option,
                    output.path.display()
                ));
            }
            identities.push((output.option, identity));
            destinations.push(destination);
        }
        Ok(destinations)
    }

    /// Text for standard output (`--stats`, `--dimension`): printed once every output is
    /// complete and before any is put in place, so that a closed or full standard output
    /// leaves the folder as it was.
    pub fn print(&mut self, text: String) {
        self.printed.push_str(&text);
    }

    /// Text for standard output made once every output is complete (what only the end of
    /// the outputs' making knows), printed after [`print`](Self::print)'s.
    pub fn print_after(&mut self, text: impl FnOnce() -> Result<String, String> + 'a) {
        self.printed_after = Some(Box::new(text));
    }

    /// Writes every output, or none: see the module docs.
    pub fn write(self) -> Result<(), String> {
        let destinations = self.resolve()?;
        let mut staged = Vec::new();
        let mut in_place = Vec::new();
        for (
            output,
            Destination {
                target,
                in_place: direct,
            },
        ) in self.outputs.into_iter().zip(destinations)
        {
            if direct {
                in_place.push((output, target));
                continue;
            }
            let name = target.file_name().unwrap_or_default().to_string_lossy();
            let prefix = format!(".{name}.");
            let mut builder = tempfile::Builder::new();
            builder.prefix(&prefix).suffix(".tmp");
            #[cfg(unix)]
            builder.permissions(permissions(&target));
            let mut temporary = builder
                .tempfile_in(folder_of(&target))
                .map_err(|e| cannot_write(&output.path, &e))?;
            // Known to an interrupt until renamed or removed.
            let registered = Registered::new(temporary.path());
            stream(output.produce, temporary.as_file_mut(), &output.path)?;
            staged.push((temporary, registered, target, output.path));
        }
        // Every temporary file is complete: now the outputs that cannot be staged.
        for (output, target) in in_place {
            let file = fs::OpenOptions::new()
                .write(true)
                .open(&target)
                .map_err(|e| cannot_write(&output.path, &e))?;
            stream(output.produce, file, &output.path)?;
        }
        let mut printed = self.printed;
        if let Some(after) = self.printed_after {
            printed.push_str(&after()?);
        }
        if !printed.is_empty() {
            crate::console::print(&printed)?;
        }
        for (temporary, _registered, target, path) in staged {
            temporary
                .persist(&target)
                .map_err(|e| cannot_write(&path, &e.error))?;
        }
        Ok(())
    }
}

/// Produces an output's bytes into `file`, buffered.
fn stream(produce: Producer<'_>, file: impl Write, path: &Path) -> Result<(), String> {
    let mut writer = BufWriter::new(file);
    produce(&mut writer)
        .and_then(|()| writer.flush())
        .map_err(|e| cannot_write(path, &e))
}

fn cannot_write(path: &Path, error: &io::Error) -> String {
    format!("cannot write {}: {error}", path.display())
}

/// Where `path`'s bytes go, or why they cannot.
fn destination(option: &str, path: &Path) -> Result<Destination, String> {
    // A symlink's target is what gets written.
    let target = match fs::symlink_metadata(path) {
        Ok(meta) if meta.file_type().is_symlink() => fs::canonicalize(path).unwrap_or_else(|_| {
            fs::read_link(path)
                .map_or_else(|_| path.to_path_buf(), |link| folder_of(path).join(link))
        }),
        _ => path.to_path_buf(),
    };
    match fs::metadata(&target) {
        Ok(meta) if meta.is_dir() => Err(format!(
            "{option} {}: is a folder, not a file",
            path.display()
        )),
        Ok(meta) if meta.is_file() => Ok(Destination {
            target,
            in_place: false,
        }),
        Ok(_) => Ok(Destination {
            target,
            in_place: true,
        }),
        Err(error) if error.kind() == io::ErrorKind::NotFound => {
            let folder = folder_of(&target);
            match fs::metadata(folder) {
                Ok(meta) if meta.is_dir() => Ok(Destination {
                    target,
                    in_place: false,
                }),
                Ok(_) => Err(format!(
                    "{option} {}: {} is not a folder",
                    path.display(),
                    folder.display()
                )),
                Err(_) => Err(format!(
                    "{option} {}: the folder {} does not exist",
                    path.display(),
                    folder.display()
                )),
            }
        }
        Err(error) => Err(format!("{option} {}: {error}", path.display())),
    }
}

/// A replaced file keeps its permissions; a new one gets what `File::create` would give
/// (0o666 less the umask), not the temporary file's private 0o600.
#[cfg(unix)]
fn permissions(target: &Path) -> fs::Permissions {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(target).map_or_else(|_| fs::Permissions::from_mode(0o666), |m| m.permissions())
}

fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// A path as one file: its folder resolved, so `a.png` and `./a.png` are the same.
fn identity(target: &Path) -> PathBuf {
    let folder = fs::canonicalize(folder_of(target)).unwrap_or_else(|_| folder_of(target).into());
    folder.join(target.file_name().unwrap_or_default())
}

/// The display as PNG bytes, one image pixel per display pixel.
pub fn png(display: &SimulatorDisplay<Rgb888>, out: &mut dyn Write) -> io::Result<()> {
    let image = display.to_rgb_output_image(&OutputSettingsBuilder::new().build());
    let buffer = image.as_image_buffer();
    // The simulator's own settings, so the bytes are what `save_png` wrote.
    PngEncoder::new_with_quality(out, CompressionType::Best, FilterType::default())
        .write_image(
            buffer.as_raw(),
            buffer.width(),
            buffer.height(),
            image::ExtendedColorType::Rgb8,
        )
        .map_err(io::Error::other)
}

/// Saves the display as a PNG file at `path`, all or nothing (the gallery's pictures).
pub fn save_png(
    display: &SimulatorDisplay<Rgb888>,
    option: &'static str,
    path: &Path,
) -> Result<(), String> {
    let mut plan = Plan::new();
    plan.add(option, path, |out| png(display, out));
    plan.write()
}
