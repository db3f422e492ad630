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
                // The error's variant and fields, not its message: the messages and the
                // decimal printing of their numbers take 8 KiB this flash does not have.
                Err(error) => hprintln!("scene {} {} failed: {:?}", index, name, error),
            }
            board.wait_for_select();
        }
        hprintln!("all scenes done");
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

/// On the host there is nothing to run: the firmware is built for `thumbv7m-none-eabi`.
#[cfg(not(target_os = "none"))]
fn main() {}
