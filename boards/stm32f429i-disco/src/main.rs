//! Firmware for the STM32F429I-DISCO (Cortex-M4F at 180 MHz): shows the shared scenes on the
//! board's built-in 240×320 ILI9341, driven over SPI5 by `mipidsi` (the panel's serial
//! interface; the LTDC and the SDRAM stay off). The blue user button (B1, PA0) moves on to
//! the next scene; without a press it moves on after [`SHOW_FOR_MS`](tinyfractal_scenes::SHOW_FOR_MS). The defmt log (RTT,
//! through the on-board ST-LINK) says what each scene cost.
#![no_std]
#![no_main]
#![deny(unsafe_code)]

use defmt::{error, info, Debug2Format, Display2Format};
use defmt_rtt as _;
use embedded_hal_bus::spi::ExclusiveDevice;
use fugit::TimerDurationU32;
use mipidsi::{
    interface::{Interface, SpiInterface},
    models::ILI9341Rgb565,
    options::{ColorOrder, Orientation, Rotation},
    Builder,
};
use panic_probe as _;
use stm32f4xx_hal::{
    pac,
    prelude::*,
    rcc::Config,
    spi::{Mode, Phase, Polarity},
    timer::Counter,
};
use tinyfractal_scenes::{show_scenes, COLOUR};

/// The board's 8 MHz HSE clock.
const HSE_MHZ: u32 = 8;
/// The ILI9341's serial interface is specified to 10 MHz writes; it is commonly run faster.
const SPI_MHZ: u32 = 22;
/// The timer that measures scenes and timeouts counts at 10 kHz (a 16-bit prescaler cannot
/// reach 1 kHz from 90 MHz); TIM2 is 32 bits, so it wraps after five days.
const TICK_HZ: u32 = 10_000;

/// The panel's power and VCOM settings, from ST's board support code for this display;
/// mipidsi's generic ILI9341 start-up leaves them at their reset values.
const PANEL_POWER: [(u8, &[u8]); 10] = [
    (0xCB, &[0x39, 0x2C, 0x00, 0x34, 0x02]), // power control A
    (0xCF, &[0x00, 0xC1, 0x30]),             // power control B
    (0xE8, &[0x85, 0x00, 0x78]),             // driver timing control A
    (0xEA, &[0x00, 0x00]),                   // driver timing control B
    (0xED, &[0x64, 0x03, 0x12, 0x81]),       // power-on sequence control
    (0xF7, &[0x20]),                         // pump ratio control
    (0xC0, &[0x10]),                         // power control 1
    (0xC1, &[0x10]),                         // power control 2
    (0xC5, &[0x45, 0x15]),                   // VCOM control 1
    (0xC7, &[0x90]),                         // VCOM control 2
];

#[cortex_m_rt::entry]
fn main() -> ! {
    let (Some(dp), Some(cp)) = (pac::Peripherals::take(), cortex_m::Peripherals::take()) else {
        defmt::panic!("peripherals taken twice");
    };
    let mut rcc = dp.RCC.freeze(Config::hse(HSE_MHZ.MHz()).sysclk(180.MHz()));
    let mut delay = cp.SYST.delay(&rcc.clocks);
    let mut clock: Counter<pac::TIM2, TICK_HZ> = dp.TIM2.counter(&mut rcc);
    if clock.start(TimerDurationU32::from_ticks(u32::MAX)).is_err() {
        defmt::panic!("TIM2 did not start");
    }

    let gpioa = dp.GPIOA.split(&mut rcc);
    let gpioc = dp.GPIOC.split(&mut rcc);
    let gpiod = dp.GPIOD.split(&mut rcc);
    let gpiof = dp.GPIOF.split(&mut rcc);

    // SPI5: PF7 clock, PF8 data in (unused), PF9 data out; PC2 chip select; PD13 data/command
    // (the schematic's WRX). The panel's reset is the board's reset.
    let spi = dp.SPI5.spi(
        (Some(gpiof.pf7), Some(gpiof.pf8), Some(gpiof.pf9)),
        Mode {
            polarity: Polarity::IdleLow,
            phase: Phase::CaptureOnFirstTransition,
        },
        SPI_MHZ.MHz(),
        &mut rcc,
    );
    let cs = gpioc.pc2.into_push_pull_output();
    let dc = gpiod.pd13.into_push_pull_output();
    let button = gpioa.pa0.into_floating_input();

    let Ok(device) = ExclusiveDevice::new(spi, cs, dp.TIM5.delay_us(&mut rcc));
    let mut buffer = [0_u8; 512];
    let interface = SpiInterface::new(device, dc, &mut buffer);
    // ST's code sets MADCTL to 0xC8 (both mirrors, BGR): the panel is mounted upside down.
    let mut display = match Builder::new(ILI9341Rgb565, interface)
        .display_size(240, 320)
        .orientation(Orientation::new().rotate(Rotation::Deg180))
        .color_order(ColorOrder::Bgr)
        .init(&mut delay)
    {
        Ok(display) => display,
        Err(error) => defmt::panic!("the ILI9341 did not start: {}", Debug2Format(&error)),
    };
    // SAFETY (mipidsi's contract for raw commands): these set analogue power levels only, no
    // addressing or pixel-format state that mipidsi keeps track of.
    #[allow(unsafe_code)]
    let raw = unsafe { display.dcs() };
    for (command, arguments) in PANEL_POWER {
        if let Err(error) = raw.send_command(command, arguments) {
            error!(
                "power setting {:x} failed: {}",
                command,
                Debug2Format(&error)
            );
        }
    }
    info!("ILI9341 240x320 ready; the user button shows the next scene");

    show_scenes(
        &mut display,
        &COLOUR,
        || u64::from(clock.now().ticks()) / u64::from(TICK_HZ / 1000),
        || button.is_high(), // active high
        |name, result, ms| match result {
            Ok(work) => info!("{}: {} {} in {} ms", name, work.count(), work.unit(), ms),
            Err(error) => error!("{} failed: {}", name, Display2Format(&error)),
        },
    )
}
