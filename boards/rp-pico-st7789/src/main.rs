//! Firmware for the Raspberry Pi Pico (RP2040, Cortex-M0+) with an ST7789 320×240 display on
//! SPI1, driven by `mipidsi`: shows the shared scenes one after another in RGB565. The
//! button on GP15 moves on to the next scene; without a press it moves on after
//! [`SHOW_FOR_MS`](tinyfractal_scenes::SHOW_FOR_MS). The defmt log (RTT, through the probe) says what each scene cost.
//!
//! Wiring (the Waveshare Pico-LCD-2 module's, so it plugs straight on): see README.md.
#![no_std]
#![no_main]
#![deny(unsafe_code)]

use defmt::{error, info, Debug2Format, Display2Format};
use defmt_rtt as _;
use embedded_hal::digital::InputPin;
use embedded_hal_bus::spi::ExclusiveDevice;
use mipidsi::{
    interface::SpiInterface,
    models::ST7789,
    options::{ColorInversion, Orientation, Rotation},
    Builder,
};
use panic_probe as _;
use rp2040_hal::{
    self as hal,
    clocks::{init_clocks_and_plls, Clock},
    fugit::RateExtU32,
    gpio::{FunctionSpi, Pins},
    pac, Sio, Spi, Timer, Watchdog,
};
use tinyfractal_scenes::{show_scenes, COLOUR};

/// The second-stage bootloader for the Pico's W25Q080 flash, first in the image.
// SAFETY: `.boot2` is the 256 bytes memory.x reserves at the start of the flash for it.
#[allow(unsafe_code)]
#[link_section = ".boot2"]
#[used]
pub static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Pico's crystal.
const XTAL_HZ: u32 = 12_000_000;
/// The RP2040's fastest SPI clock (the peripheral clock / 2); lower it for long wires.
const SPI_HZ: u32 = 62_500_000;
/// Most IPS ST7789 panels (the Pico-LCD-2's among them) show inverted colours without this.
const INVERSION: ColorInversion = ColorInversion::Inverted;

#[hal::entry]
fn main() -> ! {
    let Some(mut pac) = pac::Peripherals::take() else {
        defmt::panic!("peripherals taken twice");
    };
    let mut watchdog = Watchdog::new(pac.WATCHDOG);
    let Ok(clocks) = init_clocks_and_plls(
        XTAL_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    ) else {
        defmt::panic!("the clocks did not start (is the 12 MHz crystal there?)");
    };
    let sio = Sio::new(pac.SIO);
    let pins = Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );
    let mut timer = Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);

    // SPI1: GP10 clock, GP11 data out. The display sends nothing back.
    let sclk = pins.gpio10.into_function::<FunctionSpi>();
    let mosi = pins.gpio11.into_function::<FunctionSpi>();
    let spi = Spi::<_, _, _, 8>::new(pac.SPI1, (mosi, sclk)).init(
        &mut pac.RESETS,
        clocks.peripheral_clock.freq(),
        SPI_HZ.Hz(),
        embedded_hal::spi::MODE_0,
    );
    let dc = pins.gpio8.into_push_pull_output();
    let cs = pins.gpio9.into_push_pull_output();
    let reset = pins.gpio12.into_push_pull_output();
    let mut backlight = pins.gpio13.into_push_pull_output();
    let mut button = pins.gpio15.into_pull_up_input();

    let Ok(device) = ExclusiveDevice::new(spi, cs, timer);
    let mut buffer = [0_u8; 512];
    let interface = SpiInterface::new(device, dc, &mut buffer);
    let mut display = match Builder::new(ST7789, interface)
        .display_size(240, 320)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .invert_colors(INVERSION)
        .reset_pin(reset)
        .init(&mut timer)
    {
        Ok(display) => display,
        Err(error) => defmt::panic!("the ST7789 did not start: {}", Debug2Format(&error)),
    };
    let Ok(()) = embedded_hal::digital::OutputPin::set_high(&mut backlight);
    info!("ST7789 320x240 ready; GP15 shows the next scene");

    show_scenes(
        &mut display,
        &COLOUR,
        || timer.get_counter().ticks() / 1000,
        || button.is_low().unwrap_or(false), // active low
        |name, result, ms| match result {
            Ok(work) => info!("{}: {} {} in {} ms", name, work.count(), work.unit(), ms),
            Err(error) => error!("{} failed: {}", name, Display2Format(&error)),
        },
    )
}
