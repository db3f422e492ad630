//! The playground's WebAssembly module: the gallery's renderers and the core behind a few
//! exports, so a browser draws the same pixels as the gallery's PNGs and the boards.
//!
//! The page talks to it through memory, with no bindings generator: it asks for an input
//! buffer ([`input_buffer`]), writes a request there as UTF-8 text and calls [`run`]; the
//! answer is a text ([`output_pointer`], [`output_length`]) and, for a picture, RGBA
//! pixels ([`pixels_pointer`], [`picture_width`], [`picture_height`]). A request is a
//! command on its first line, `key=value` lines, and for an L-system a blank line and the
//! file's text (see [`respond`]).

// The exports' `#[no_mangle]` names are the page's interface; nothing else is unsafe.
#![allow(unsafe_code)]

mod picture;
mod request;
mod session;

use std::cell::RefCell;

pub use picture::Picture;
pub use request::{respond, respond_in, Response};
pub use session::{Session, STEP_ITERATIONS};

/// What the module holds between the page's calls.
#[derive(Debug, Default)]
struct State {
    input: Vec<u8>,
    output: String,
    picture: Option<Picture>,
    session: Option<Session>,
}

thread_local! {
    static STATE: RefCell<State> = RefCell::new(State::default());
}

/// A buffer of `length` bytes for the next request: the page writes it, then calls [`run`].
#[no_mangle]
pub extern "C" fn input_buffer(length: usize) -> *mut u8 {
    STATE.with_borrow_mut(|state| {
        state.input = vec![0; length];
        state.input.as_mut_ptr()
    })
}

/// Answers the request in the input buffer: 0 for a picture (and a text), 1 for a text
/// alone, 2 for an error (its message the text), 3 for a partial picture (ask `more`).
#[no_mangle]
pub extern "C" fn run() -> u32 {
    STATE.with_borrow_mut(|state| {
        let request = String::from_utf8_lossy(&state.input).into_owned();
        let response = respond_in(&request, &mut state.session);
        let status = match (&response.picture, response.error, response.more) {
            (_, true, _) => 2,
            (Some(_), false, true) => 3,
            (Some(_), false, false) => 0,
            (None, false, _) => 1,
        };
        state.output = response.text;
        state.picture = response.picture;
        status
    })
}

/// Where the last answer's text starts.
#[no_mangle]
pub extern "C" fn output_pointer() -> *const u8 {
    STATE.with_borrow(|state| state.output.as_ptr())
}

/// The last answer's text's length in bytes.
#[no_mangle]
pub extern "C" fn output_length() -> usize {
    STATE.with_borrow(|state| state.output.len())
}

/// Where the last picture's RGBA pixels start (row by row), or null without one.
#[no_mangle]
pub extern "C" fn pixels_pointer() -> *const u8 {
    STATE.with_borrow(|state| {
        state
            .picture
            .as_ref()
            .map_or(std::ptr::null(), |picture| picture.rgba.as_ptr())
    })
}

/// The last picture's width in pixels (0 without one).
#[no_mangle]
pub extern "C" fn picture_width() -> u32 {
    STATE.with_borrow(|state| state.picture.as_ref().map_or(0, |p| p.width))
}

/// The last picture's height in pixels (0 without one).
#[no_mangle]
pub extern "C" fn picture_height() -> u32 {
    STATE.with_borrow(|state| state.picture.as_ref().map_or(0, |p| p.height))
}
