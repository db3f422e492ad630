//! What every render shares on the command line.
//!
//! `--size`, `--out`, `--stats`, `--window`, `--dimension`, and the window (`--view`) and
//! projection values some take. Defined once here, below the parser and the scenes that both
//! use them.

use std::path::PathBuf;

use clap::Args;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;

/// Options every render takes.
#[derive(Debug, Clone, PartialEq, Args)]
pub struct Common {
    /// Picture size in pixels, WxH (at most 16384 a side, 8192x8192 in all)
    #[arg(long = "size", value_name = "WxH", default_value = "320x240", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Write the picture there (default: NAME.png)
    #[arg(long, value_name = "PNG")]
    pub out: Option<PathBuf>,
    /// Print one line of statistics
    #[arg(long)]
    pub stats: bool,
    /// Show the picture in a window (needs the `window` feature and SDL2)
    #[arg(long)]
    pub window: bool,
    /// Print the picture's box-counting dimension (pixels not black), `dimension=D.DDD`
    #[arg(long)]
    pub dimension: bool,
    /// The panel's colours, which the picture shows: 1bit, gray2, gray4, gray8, rgb565 or
    /// rgb888 (the PNG holds what such a panel would show)
    #[arg(long, value_enum, value_name = "PANEL", default_value = "rgb888")]
    pub colors: Panel,
    /// How colours are brought to the panel's: none (the nearest), bayer4 or bayer8
    /// (ordered dithering)
    #[arg(long, value_enum, value_name = "HOW", default_value = "none")]
    pub dither: DitherName,
}

/// A panel's colours (`--colors`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Panel {
    /// One bit: black or white (an SSD1306).
    #[value(name = "1bit")]
    OneBit,
    /// Four greys.
    Gray2,
    /// Sixteen greys (an SSD1322, the LM3S6965's OLED).
    Gray4,
    /// 256 greys.
    Gray8,
    /// 16-bit colour (an ST7789, an ILI9341).
    Rgb565,
    /// 24-bit colour: the picture as drawn.
    #[default]
    Rgb888,
}

/// How colours are brought to the panel's (`--dither`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum DitherName {
    /// The nearest level.
    #[default]
    None,
    /// Bayer's 4×4 ordered dither.
    Bayer4,
    /// Bayer's 8×8 ordered dither.
    Bayer8,
}

impl DitherName {
    /// The name of the core's dither.
    pub fn of(dither: tinyfractal::render::Dither) -> Self {
        match dither {
            tinyfractal::render::Dither::Bayer4 => Self::Bayer4,
            tinyfractal::render::Dither::Bayer8 => Self::Bayer8,
            _ => Self::None,
        }
    }

    /// The core's dither.
    pub fn dither(self) -> tinyfractal::render::Dither {
        match self {
            Self::None => tinyfractal::render::Dither::None,
            Self::Bayer4 => tinyfractal::render::Dither::Bayer4,
            Self::Bayer8 => tinyfractal::render::Dither::Bayer8,
        }
    }
}

/// `picture` as a panel of `panel`'s colours would show it, dithered by `dither` (each
/// pixel by its position, as the core's `Dithered` target draws it), back in 24-bit colour
/// for the PNG; `None` when it is shown as drawn.
pub fn as_panel(
    picture: &SimulatorDisplay<Rgb888>,
    panel: Panel,
    dither: DitherName,
) -> Option<SimulatorDisplay<Rgb888>> {
    use embedded_graphics::pixelcolor::{BinaryColor, Gray2, Gray4, Gray8, Rgb565};
    use tinyfractal::render::Quantize;
    if panel == Panel::Rgb888 {
        return None;
    }
    let dither = dither.dither();
    let mut shown = SimulatorDisplay::<Rgb888>::new(picture.size());
    for point in picture.bounding_box().points() {
        let color = picture.get_pixel(point);
        let threshold = dither.threshold(point);
        let seen = match panel {
            Panel::OneBit => match BinaryColor::quantize(color, threshold) {
                BinaryColor::On => Rgb888::WHITE,
                BinaryColor::Off => Rgb888::BLACK,
            },
            Panel::Gray2 => Rgb888::from(Gray2::quantize(color, threshold)),
            Panel::Gray4 => Rgb888::from(Gray4::quantize(color, threshold)),
            Panel::Gray8 => Rgb888::from(Gray8::quantize(color, threshold)),
            Panel::Rgb565 => Rgb888::from(Rgb565::quantize(color, threshold)),
            Panel::Rgb888 => color,
        };
        let _ = Pixel(point, seen).draw(&mut shown);
    }
    Some(shown)
}

impl Common {
    /// The picture's width in pixels.
    pub fn width(&self) -> u32 {
        self.size.0
    }

    /// The picture's height in pixels.
    pub fn height(&self) -> u32 {
        self.size.1
    }

    /// A display of `--size`.
    pub fn display(&self) -> SimulatorDisplay<Rgb888> {
        SimulatorDisplay::new(self.area().size)
    }

    /// The whole picture, `--size` at the origin.
    pub fn area(&self) -> embedded_graphics::primitives::Rectangle {
        embedded_graphics::primitives::Rectangle::new(
            Point::zero(),
            Size::new(self.width(), self.height()),
        )
    }
}

/// A window of the fitted picture: `x0,y0,x1,y1` as fractions of the target it fills
/// (0,0 top left, 1,1 bottom right; `0,0,1,1` is the whole picture).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Left edge, a fraction of the target's width.
    pub x0: f64,
    /// Top edge, a fraction of the target's height.
    pub y0: f64,
    /// Right edge, a fraction of the target's width.
    pub x1: f64,
    /// Bottom edge, a fraction of the target's height.
    pub y1: f64,
}

/// The largest picture the CLI draws: 16384 pixels a side and 2²⁶ pixels (64 Mi, 8192×8192)
/// in all, so a picture and its buffers stay within a few hundred MB.
pub const MAX_SIDE: u32 = 16_384;
/// See [`MAX_SIDE`].
pub const MAX_PIXELS: u64 = 1 << 26;

pub(crate) fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("`{text}` is not WxH, e.g. 320x240");
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (w.parse().map_err(|_| bad())?, h.parse().map_err(|_| bad())?);
    if w == 0 || h == 0 {
        return Err(format!("{w}x{h} has no pixels: give at least 1x1"));
    }
    if w > MAX_SIDE || h > MAX_SIDE || u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(format!(
            "{w}x{h} is larger than the largest picture: at most {MAX_SIDE} pixels a side and {MAX_PIXELS} in all (8192x8192)"
        ));
    }
    Ok((w, h))
}

/// Smallest window side: a zoom of a million times keeps pixel positions in range.
const MIN_VIEW_SIDE: f64 = 1e-6;

pub(crate) fn parse_view(text: &str) -> Result<View, String> {
    let bad = || {
        format!(
            "`{text}` is not X0,Y0,X1,Y1 with 0 <= X0 < X1 <= 1 and 0 <= Y0 < Y1 <= 1 \
             (sides at least {MIN_VIEW_SIDE})"
        )
    };
    let numbers: Vec<f64> = text
        .split(',')
        .map(|part| part.trim().parse::<f64>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    let [x0, y0, x1, y1] = numbers[..] else {
        return Err(bad());
    };
    let within = |low: f64, high: f64| {
        (0.0..=1.0).contains(&low) && high <= 1.0 && high - low >= MIN_VIEW_SIDE
    };
    if !(within(x0, x1) && within(y0, y1)) {
        return Err(bad());
    }
    Ok(View { x0, y0, x1, y1 })
}

/// `front`, `iso` or `perspective`.
pub fn parse_projection(text: &str) -> Result<tinyfractal::render::Projection, String> {
    match text {
        "front" => Ok(tinyfractal::render::Projection::Front),
        "iso" | "isometric" => Ok(tinyfractal::render::Projection::Isometric),
        "perspective" => Ok(tinyfractal::render::Projection::Perspective {
            distance: tinyfractal::Real::from_int(3),
        }),
        other => Err(format!(
            "unknown projection `{other}`: give front, iso or perspective"
        )),
    }
}

/// A `RE,IM` value (`--c`, `--center`), each part as text the core checks.
pub fn parse_pair(text: &str) -> Result<(String, String), String> {
    let (re, im) = text
        .split_once(',')
        .ok_or_else(|| format!("`{text}` is not RE,IM, e.g. -0.75,0"))?;
    Ok((re.trim().to_string(), im.trim().to_string()))
}
