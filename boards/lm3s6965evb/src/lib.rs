//! The LM3S6965EVB's pieces that are the same on the host and on the board: the SSD0323's
//! 128×64 4-bit grey framebuffer as a `DrawTarget<Color = Gray4>`, and the scenes the
//! firmware shows. The QEMU test renders these same scenes on the host and compares them
//! pixel for pixel with QEMU's screen.
#![no_std]
#![deny(missing_docs, unsafe_code)]

pub mod framebuffer;

pub use framebuffer::Framebuffer;
/// The scenes, shared with every board (drawn here in [`scenes::GREY`]).
pub use tinyfractal_scenes as scenes;
