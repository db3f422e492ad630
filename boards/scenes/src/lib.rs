//! The scene catalogue: every scene of tinyfractal described once (name, family,
//! parameters, default size, palette), read by the gallery, by every firmware and by the
//! measuring firmware, and drawn the same way on the host and on each board. The QEMU test
//! compares the LM3S6965's screen with the host's rendering, the measuring firmware folds
//! the scenes into checksums beside the naive baselines computed from the same scenes, and
//! the Pico and the STM32F429I-DISCO show them on their displays. One [`Look`] per display
//! says which colours to use.
#![no_std]
#![deny(missing_docs, unsafe_code)]

mod catalogue;
mod dynamics;
mod look;
pub mod measure;
pub mod naive;
mod shapes;
mod terrain;
mod wait;

pub use catalogue::{
    Entry, EscapeScene, GeneralEntry, IfsEntry, Scene, Shape, System, ABOP_LSYS, BOOK, BUSH,
    CUBE_COLOUR, DEEP_SCENES, DISPLAY_SCENES, DRAGON, DYNAMICS_SCENES, FERN, GALLERY,
    GENERAL_GALLERY, GENERAL_SCENES, GOSPER, HILBERT, IFS_GALLERY, KOCH_SNOWFLAKE, LECTURE_IFS,
    PANEL_SCENES, PLANT, SCENES, SIERPINSKI_ARROWHEAD, SMOOTH_FIGURE, STOCHASTIC_PLANT,
    TEXTURE_SCENES, WIND, ZOOM_SCENES,
};
pub use dynamics::{design_placement, MAX_BOARD_PARTICLES};
pub use look::{
    Look, Work, COLOUR, GREY, LSYSTEM_CELLS, MAX_BOARD_DENSITY_PIXELS, MAX_BOARD_MAP_CELLS,
    MAX_BOARD_REACTION_CELLS, MAX_BOARD_REFERENCE_POINTS,
};
pub use wait::{show_scenes, wait_for_press_or, FRAME_MS, SHOW_FOR_MS};
