//! The host's colours: Fractint's 16 VGA colours, with index 0 (the turtle's first colour)
//! white instead of black so that uncoloured systems show on the black background.

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
        }
    }
}
