//! The board's registers: clocks, GPIO, SSI0, and the SSD0323 on it.
//!
//! Facts as QEMU 7.2 models the LM3S6965EVB: SYSCTL RCGC1 bit 4 clocks SSI0 and RCGC2 the
//! GPIO ports; SSI0 is a PL022 (CR0 = 0xC7: SPI mode 3, 8-bit frames; CPSR = 2; CR1 = 2
//! enables it), and its receive FIFO must be drained after every byte or sending stalls.
//! PC7 is the OLED's data/command line (low = command); PD0 selects the OLED (QEMU treats it
//! as active high) and stays high. The gamepad's select button reads low on PF1 while held.
//! Its release (a rising edge: GPIOIEV) is latched in GPIORIS, so a press is seen even when
//! QEMU's vCPU does not run during the 100 ms that `sendkey` holds it. The release, not the
//! press: QEMU leaves PF1 low until the first release, so a first press makes no edge.

use core::ptr::{read_volatile, write_volatile};

use tinyfractal_lm3s6965evb::Framebuffer;

const RCGC1: usize = 0x400F_E104;
const RCGC2: usize = 0x400F_E108;
const SSI0: usize = 0x4000_8000;
const GPIO_C: usize = 0x4000_6000;
const GPIO_D: usize = 0x4000_7000;
const GPIO_F: usize = 0x4002_5000;
const GPIO_DIR: usize = 0x400;
const GPIO_IEV: usize = 0x40C;
const GPIO_RIS: usize = 0x414;
const GPIO_ICR: usize = 0x41C;
const GPIO_DEN: usize = 0x51C;
const SELECT: u32 = 1 << 1;
const SSI_CR0: usize = 0x00;
const SSI_CR1: usize = 0x04;
const SSI_DR: usize = 0x08;
const SSI_SR: usize = 0x0C;
const SSI_CPSR: usize = 0x10;
const SR_RECEIVE_NOT_EMPTY: u32 = 1 << 2;

fn write(address: usize, value: u32) {
    // SAFETY: fixed, aligned MMIO register addresses of the LM3S6965.
    #[allow(unsafe_code)]
    unsafe {
        write_volatile(address as *mut u32, value)
    }
}

fn read(address: usize) -> u32 {
    // SAFETY: as above.
    #[allow(unsafe_code)]
    unsafe {
        read_volatile(address as *const u32)
    }
}

/// Writes the pins in `mask` of a GPIO port (the data register is address-masked).
fn gpio_set(port: usize, mask: u32, high: bool) {
    write(port + ((mask as usize) << 2), if high { mask } else { 0 });
}

/// The board, set up.
pub struct Board;

impl Board {
    /// Clocks SSI0 and GPIO C, D, F; PC7 and PD0 outputs; SSI0 in SPI mode 3, 8-bit.
    pub fn init() -> Self {
        write(RCGC1, read(RCGC1) | 1 << 4);
        write(RCGC2, read(RCGC2) | 1 << 2 | 1 << 3 | 1 << 5);
        for (port, pins) in [(GPIO_C, 1 << 7), (GPIO_D, 1 << 0)] {
            write(port + GPIO_DIR, read(port + GPIO_DIR) | pins);
            write(port + GPIO_DEN, read(port + GPIO_DEN) | pins);
        }
        write(GPIO_F + GPIO_DEN, read(GPIO_F + GPIO_DEN) | SELECT);
        write(GPIO_F + GPIO_IEV, read(GPIO_F + GPIO_IEV) | SELECT);
        gpio_set(GPIO_D, 1 << 0, true);
        write(SSI0 + SSI_CR1, 0);
        write(SSI0 + SSI_CPSR, 2);
        write(SSI0 + SSI_CR0, 0xC7);
        write(SSI0 + SSI_CR1, 2);
        Board
    }

    fn send(&mut self, byte: u8) {
        write(SSI0 + SSI_DR, u32::from(byte));
        while read(SSI0 + SSI_SR) & SR_RECEIVE_NOT_EMPTY == 0 {}
        let _ = read(SSI0 + SSI_DR);
    }

    fn command(&mut self, bytes: &[u8]) {
        gpio_set(GPIO_C, 1 << 7, false);
        for &byte in bytes {
            self.send(byte);
        }
    }

    /// Sends the whole framebuffer: columns 0..=63 (two pixels each), rows 0..=63.
    pub fn show(&mut self, framebuffer: &Framebuffer) {
        self.command(&[0x15, 0, 63, 0x75, 0, 63]);
        gpio_set(GPIO_C, 1 << 7, true);
        for &byte in framebuffer.bytes() {
            self.send(byte);
        }
    }

    /// Forgets any earlier release of select: call it before saying a scene is done, so the
    /// press that answers it is the one [`Board::wait_for_select`] sees.
    pub fn arm_select(&mut self) {
        write(GPIO_F + GPIO_ICR, SELECT);
    }

    /// Waits for select to be pressed and released since [`Board::arm_select`]. The release
    /// is latched as an edge, not polled as a level: a short press is not missed.
    pub fn wait_for_select(&mut self) {
        while read(GPIO_F + GPIO_RIS) & SELECT == 0 {}
        write(GPIO_F + GPIO_ICR, SELECT);
    }
}
