//! Firmware for the TI Stellaris LM3S6965 evaluation board (Cortex-M3), as QEMU emulates it:
//! draws each scene on the SSD0323 OLED (128×64, 4-bit grey, on SSI0), says so over
//! semihosting, and waits for the select button before the next one. The test harness
//! presses it through QEMU's monitor (`sendkey ctrl`, the gamepad's select) after taking a
//! screendump.
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(target_os = "none")]
mod board;

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m_rt::entry;
    use cortex_m_semihosting::{debug, hprintln};
    use panic_semihosting as _;
    use tinyfractal_lm3s6965evb::{
        scenes::{self, DEEP_SCENES, SCENES, ZOOM_SCENES},
        Framebuffer,
    };

    use tinyfractal::error::{DrawError, Error};

    use crate::board::Board;

    #[entry]
    fn main() -> ! {
        let mut board = Board::init();
        let mut framebuffer = Framebuffer::new();
        for (index, entry) in SCENES
            .iter()
            .chain(&DEEP_SCENES)
            .chain(&ZOOM_SCENES)
            .enumerate()
        {
            let (name, result) = (
                entry.name,
                entry.scene.draw(&mut framebuffer, &scenes::GREY),
            );
            board.show(&framebuffer);
            board.arm_select();
            match result {
                Ok(work) => hprintln!("scene {} {} done: {:?}", index, name, work),
                // The error's kind, not its message or fields: their printing takes
                // 30 KiB this flash does not have; the host draws the same scene and
                // says the rest (`tinyfractal gallery`).
                Err(error) => hprintln!("scene {} {} failed: {}", index, name, kind(&error)),
            }
            board.wait_for_select();
        }
        hprintln!("all scenes done");
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }

    /// What kind of error a scene failed with.
    fn kind<E>(error: &DrawError<E>) -> &'static str {
        match error {
            DrawError::Target(_) => "the display",
            DrawError::Fractal(Error::Read(_)) => "reading",
            DrawError::Fractal(Error::Walk(_)) => "walking",
            DrawError::Fractal(Error::Fit(_)) => "fitting",
            DrawError::Fractal(Error::View(_)) => "the view",
            DrawError::Fractal(Error::Parameter(_)) => "a parameter",
            DrawError::Fractal(_) => "the engine",
        }
    }
}

/// On the host there is nothing to run: the firmware is built for `thumbv7m-none-eabi`.
#[cfg(not(target_os = "none"))]
fn main() {}
