//! The host's colours: Fractint's 16 VGA colours, with index 0 (the turtle's first colour)
//! white instead of black so that uncoloured systems show on the black background; the
//! book's browns and greens for `.lsys` plants; and Fractint's `.map` files read.

use clap::ValueEnum;
use embedded_graphics::pixelcolor::Rgb888;

/// Depth cue: 16 greens from dim (far) to bright (near).
pub const DEPTH_GREENS: [Rgb888; 16] = {
    let mut levels = [Rgb888::new(0, 0, 0); 16];
    let mut i = 0;
    while i < 16 {
        let v = 64 + (i as u8) * 12;
        levels[i] = Rgb888::new(v / 2, v, v / 2);
        i += 1;
    }
    levels
};

/// The colour map of `.lsys` systems without `--colormap`, in the spirit of *The
/// Algorithmic Beauty of Plants*: index 0 a bark brown for stems, then browns turning to
/// greens, light greens for young leaves, and a few flower colours at the end (a plant's `;`
/// steps from wood towards leaves).
pub const BOOK: [Rgb888; 16] = tinyfractal_scenes::BOOK;

/// Reads a Fractint `.map` colour map: a line per colour, `R G B` (each 0 to 255) and
/// anything after the three numbers a comment; blank lines skipped; 1 to 256 colours.
pub fn read_map(path: &std::path::Path) -> Result<Vec<Rgb888>, String> {
    let text = crate::files::read_text(path)?;
    let mut colors = Vec::new();
    for (number, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let bad = || {
            format!(
                "{}:{}: `{}` is not a colour `R G B` (three whole numbers 0 to 255, then \
                 anything)",
                path.display(),
                number + 1,
                line.trim()
            )
        };
        let mut fields = line.split_whitespace();
        let mut channel = || -> Result<u8, String> {
            fields
                .next()
                .and_then(|f| f.parse::<u8>().ok())
                .ok_or_else(bad)
        };
        let (r, g, b) = (channel()?, channel()?, channel()?);
        if colors.len() == 256 {
            return Err(format!(
                "{}:{}: more than 256 colours: a Fractint map has at most 256 lines",
                path.display(),
                number + 1
            ));
        }
        colors.push(Rgb888::new(r, g, b));
    }
    if colors.is_empty() {
        return Err(format!(
            "{}: no colours: give lines `R G B`",
            path.display()
        ));
    }
    Ok(colors)
}

pub const VGA: [Rgb888; 16] = [
    Rgb888::new(0xFF, 0xFF, 0xFF),
    Rgb888::new(0x00, 0x00, 0xAA),
    Rgb888::new(0x00, 0xAA, 0x00),
    Rgb888::new(0x00, 0xAA, 0xAA),
    Rgb888::new(0xAA, 0x00, 0x00),
    Rgb888::new(0xAA, 0x00, 0xAA),
    Rgb888::new(0xAA, 0x55, 0x00),
    Rgb888::new(0xAA, 0xAA, 0xAA),
    Rgb888::new(0x55, 0x55, 0x55),
    Rgb888::new(0x55, 0x55, 0xFF),
    Rgb888::new(0x55, 0xFF, 0x55),
    Rgb888::new(0x55, 0xFF, 0xFF),
    Rgb888::new(0xFF, 0x55, 0x55),
    Rgb888::new(0xFF, 0x55, 0xFF),
    Rgb888::new(0xFF, 0xFF, 0x55),
    Rgb888::new(0xFF, 0xFF, 0xFF),
];

/// `--palette`: the escape-time colours by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PaletteName {
    /// Dark blue through white to gold
    Classic,
    /// Dark red through orange to pale yellow
    Fire,
    /// Dark grey to white
    Gray,
    /// Blue bands by dwell, from dark to light
    Bands,
    /// The set black, the rest white
    TwoColor,
    /// classic, by the smooth iteration count
    SmoothClassic,
    /// fire, by the smooth iteration count
    SmoothFire,
    /// gray, by the smooth iteration count
    SmoothGray,
    /// classic's 256 colours equalised: each covers an equal share of the escaping pixels
    Histogram,
    /// Black at the set through grey at a pixel to white, by the estimated distance
    DistanceGray,
    /// classic, by the estimated distance (16 colours a doubling)
    DistanceClassic,
    /// fire, by the estimated distance
    DistanceFire,
}

impl PaletteName {
    /// The name the scenes look the palette up by.
    pub fn name(self) -> &'static str {
        match self {
            Self::Classic => "classic",
            Self::Fire => "fire",
            Self::Gray => "gray",
            Self::Bands => "bands",
            Self::TwoColor => "two-color",
            Self::SmoothClassic => "smooth-classic",
            Self::SmoothFire => "smooth-fire",
            Self::SmoothGray => "smooth-gray",
            Self::Histogram => "histogram",
            Self::DistanceGray => "distance-gray",
            Self::DistanceClassic => "distance-classic",
            Self::DistanceFire => "distance-fire",
        }
    }
}
