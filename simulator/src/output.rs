//! Writing results: PNG pictures and text, each all-or-nothing (a temporary file renamed
//! into place), so a failed run never leaves a partial file behind.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};

fn temporary(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".partial");
    path.with_file_name(name)
}

/// Writes `contents` to `path` through a temporary file in the same folder.
pub fn write_atomically(
    path: &Path,
    write: impl FnOnce(&Path) -> io::Result<()>,
) -> io::Result<()> {
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        fs::create_dir_all(parent)?;
    }
    let partial = temporary(path);
    let result = write(&partial).and_then(|()| fs::rename(&partial, path));
    if result.is_err() {
        let _ = fs::remove_file(&partial);
    }
    result
}

/// Saves the display as a PNG, one image pixel per display pixel.
pub fn save_png(display: &SimulatorDisplay<Rgb888>, path: &Path) -> io::Result<()> {
    let image = display.to_rgb_output_image(&OutputSettingsBuilder::new().build());
    write_atomically(path, |partial| {
        image.save_png(partial).map_err(io::Error::other)
    })
}

/// Saves text.
pub fn save_text(path: &Path, text: &str) -> io::Result<()> {
    write_atomically(path, |partial| {
        let mut file = io::BufWriter::new(fs::File::create(partial)?);
        file.write_all(text.as_bytes())?;
        file.flush()
    })
}
