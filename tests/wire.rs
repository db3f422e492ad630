//! Bytes on the wire: mipidsi's ST7789 driver (320×240, RGB565) over a counting SPI device
//! and data/command pin (embedded-hal 1.0). A Mandelbrot frame should cost little more than
//! its W·H·2 bytes of pixels; drawing the same frame pixel by pixel costs an address window
//! (CASET, RASET, RAMWR: 11 bytes) per pixel.

use std::cell::RefCell;
use std::rc::Rc;

use embedded_graphics::{
    pixelcolor::{Rgb565, Rgb888},
    prelude::*,
};
use embedded_hal::{
    delay::DelayNs,
    digital::{ErrorType as PinErrorType, OutputPin},
    spi::{ErrorType, Operation, SpiDevice},
};
use mipidsi::{
    interface::SpiInterface,
    models::ST7789,
    options::{Orientation, Rotation},
    Builder,
};
use tinyfractal::{
    render::{Gradient, Orientation as Heading},
    Angle, Coord, Dialect, EscapeTime, Fractal, Grammar, LSystem, Real, View,
};

const CASET: u8 = 0x2A;
const RAMWR: u8 = 0x2C;

/// What went over the wire.
#[derive(Default, Debug, Clone, Copy)]
struct Wire {
    bytes: usize,
    pixel_bytes: usize,
    windows: usize,
    command_mode: bool,
    writing_pixels: bool,
}

#[derive(Clone)]
struct Spi(Rc<RefCell<Wire>>);
#[derive(Clone)]
struct Dc(Rc<RefCell<Wire>>);

impl ErrorType for Spi {
    type Error = core::convert::Infallible;
}

impl SpiDevice for Spi {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), Self::Error> {
        let mut wire = self.0.borrow_mut();
        for operation in operations {
            if let Operation::Write(bytes) = operation {
                wire.bytes += bytes.len();
                if wire.command_mode {
                    for &command in bytes.iter() {
                        wire.windows += usize::from(command == CASET);
                        wire.writing_pixels = command == RAMWR;
                    }
                } else if wire.writing_pixels {
                    wire.pixel_bytes += bytes.len();
                }
            }
        }
        Ok(())
    }
}

impl PinErrorType for Dc {
    type Error = core::convert::Infallible;
}

impl OutputPin for Dc {
    fn set_low(&mut self) -> Result<(), Self::Error> {
        self.0.borrow_mut().command_mode = true;
        Ok(())
    }
    fn set_high(&mut self) -> Result<(), Self::Error> {
        self.0.borrow_mut().command_mode = false;
        Ok(())
    }
}

struct NoDelay;

impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _: u32) {}
}

/// Draws with `draw` on a fresh 320×240 ST7789 and returns what crossed the wire after init.
fn on_the_wire(draw: impl FnOnce(&mut dyn DrawTargetRgb565)) -> Wire {
    let wire = Rc::new(RefCell::new(Wire::default()));
    let mut buffer = [0u8; 512];
    let interface = SpiInterface::new(Spi(wire.clone()), Dc(wire.clone()), &mut buffer);
    let mut display = Builder::new(ST7789, interface)
        .display_size(240, 320)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .init(&mut NoDelay)
        .unwrap();
    assert_eq!(display.bounding_box().size, Size::new(320, 240));
    *wire.borrow_mut() = Wire::default();
    draw(&mut Adapter(&mut display));
    let result = *wire.borrow();
    result
}

/// An object-safe view of a display, so the tests can hand it around.
trait DrawTargetRgb565 {
    fn fill(&mut self, drawing: &dyn Fn(&mut Recorder));
    fn pixel(&mut self, point: Point, color: Rgb565);
}

struct Adapter<'d, D>(&'d mut D);

impl<D: DrawTarget<Color = Rgb565>> DrawTargetRgb565 for Adapter<'_, D>
where
    D::Error: core::fmt::Debug,
{
    fn fill(&mut self, drawing: &dyn Fn(&mut Recorder)) {
        let mut recorder = Recorder { calls: Vec::new() };
        drawing(&mut recorder);
        for call in recorder.calls {
            match call {
                Call::Solid(area, color) => self.0.fill_solid(&area, color).unwrap(),
                Call::Contiguous(area, colors) => self.0.fill_contiguous(&area, colors).unwrap(),
                Call::Pixels(pixels) => self.0.draw_iter(pixels).unwrap(),
            }
        }
    }
    fn pixel(&mut self, point: Point, color: Rgb565) {
        self.0
            .draw_iter(core::iter::once(Pixel(point, color)))
            .unwrap();
    }
}

/// Records the calls a drawable makes, to replay them into the display.
struct Recorder {
    calls: Vec<Call>,
}

enum Call {
    Solid(embedded_graphics::primitives::Rectangle, Rgb565),
    Contiguous(embedded_graphics::primitives::Rectangle, Vec<Rgb565>),
    Pixels(Vec<Pixel<Rgb565>>),
}

impl OriginDimensions for Recorder {
    fn size(&self) -> Size {
        Size::new(320, 240)
    }
}

impl DrawTarget for Recorder {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        self.calls.push(Call::Pixels(pixels.into_iter().collect()));
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &embedded_graphics::primitives::Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        let n = (area.size.width * area.size.height) as usize;
        self.calls.push(Call::Contiguous(
            *area,
            colors.into_iter().take(n).collect(),
        ));
        Ok(())
    }
    fn fill_solid(
        &mut self,
        area: &embedded_graphics::primitives::Rectangle,
        color: Rgb565,
    ) -> Result<(), Self::Error> {
        self.calls.push(Call::Solid(*area, color));
        Ok(())
    }
}

impl Recorder {
    /// Every pixel the calls write, in order.
    fn pixels(&self) -> Vec<(Point, Rgb565)> {
        let mut out = Vec::new();
        for call in &self.calls {
            match call {
                Call::Solid(area, color) => out.extend(area.points().map(|p| (p, *color))),
                Call::Contiguous(area, colors) => {
                    out.extend(area.points().zip(colors.iter().copied()))
                }
                Call::Pixels(pixels) => out.extend(pixels.iter().map(|Pixel(p, c)| (*p, *c))),
            }
        }
        out
    }
}

fn mandelbrot(recorder: &mut Recorder) {
    let view = View::new(
        Fractal::Mandelbrot,
        (Coord::parse("-0.75").unwrap(), Coord::default()),
        Coord::parse("3.5").unwrap(),
        Size::new(320, 240),
        256,
    )
    .unwrap();
    let palette = Gradient::<Rgb565, 64>::new(
        &[Rgb888::BLUE, Rgb888::WHITE, Rgb888::new(255, 160, 0)],
        Rgb565::BLACK,
    )
    .unwrap();
    EscapeTime::new(view, &palette).draw(recorder).unwrap();
}

fn plant(recorder: &mut Recorder) {
    let grammar = Grammar::new(
        Dialect::Abop,
        "X",
        Angle::Degrees(Real::parse_decimal("22.5").unwrap()),
    )
    .unwrap()
    .with_rule('X', "F-[[X]+X]+F[+FX]-X")
    .unwrap()
    .with_rule('F', "FF")
    .unwrap();
    LSystem::new(&grammar, 6)
        .with_orientation(Heading::Up)
        .fit(recorder.bounding_box(), &[Rgb565::GREEN])
        .unwrap()
        .draw(recorder)
        .unwrap();
}

fn compare(name: &str, drawing: fn(&mut Recorder)) -> (Wire, Wire) {
    let runs = on_the_wire(|display| display.fill(&drawing));
    let mut recorded = Recorder { calls: Vec::new() };
    drawing(&mut recorded);
    let pixels = recorded.pixels();
    let one_by_one = on_the_wire(|display| {
        for &(p, c) in &pixels {
            display.pixel(p, c);
        }
    });
    println!(
        "{name}: in runs {} bytes ({} of pixels) in {} windows; pixel by pixel {} bytes in {} windows ({:.1}× more bytes)",
        runs.bytes, runs.pixel_bytes, runs.windows, one_by_one.bytes, one_by_one.windows,
        one_by_one.bytes as f64 / runs.bytes as f64
    );
    assert_eq!(
        one_by_one.windows,
        pixels.len(),
        "pixel by pixel: a window each"
    );
    (runs, one_by_one)
}

#[test]
fn a_mandelbrot_frame_is_within_5_percent_of_its_pixel_bytes() {
    let (runs, one_by_one) = compare("mandelbrot 320x240", mandelbrot);
    let pixel_data = 320 * 240 * 2;
    assert_eq!(runs.pixel_bytes, pixel_data, "each pixel sent exactly once");
    assert!(
        runs.bytes as f64 <= pixel_data as f64 * 1.05,
        "{} bytes",
        runs.bytes
    );
    assert!(one_by_one.bytes > 6 * runs.bytes);
}

#[test]
fn a_plant_goes_out_in_runs() {
    let (runs, one_by_one) = compare("plant order 6", plant);
    // Lines go out as horizontal and vertical runs: a window per run, not per pixel. At
    // 22.5° most runs of this plant are one or two pixels long, so the saving is modest.
    assert!(
        runs.windows < one_by_one.windows,
        "{} windows for {} pixels",
        runs.windows,
        one_by_one.windows
    );
    assert!(runs.bytes < one_by_one.bytes);
}
