//! # tinyfractal
//!
//! A `no_std`, heap-free, fixed-point fractal renderer for embedded-graphics displays.
//!
//! The L-system engine reads Fractint `.l` files or ABOP-style rules, walks the derivation
//! with a bounded stack (never building the derived string), moves a fixed-point turtle and
//! draws into any [`DrawTarget`](embedded_graphics::draw_target::DrawTarget).
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
//! use tinyfractal::{Angle, Dialect, Grammar, LSystem};
//!
//! // The Koch snowflake, fitted into a 64×64 display.
//! let grammar = Grammar::new(Dialect::Abop, "F--F--F", Angle::Divisions(6))?
//!     .with_rule('F', "F+F--F+F")?;
//! let mut display = MockDisplay::<BinaryColor>::new();
//! display.set_allow_overdraw(true);
//! let snowflake = LSystem::new(&grammar, 2).fit(display.bounding_box(), &[BinaryColor::On])?;
//! let stats = snowflake.draw(&mut display)?;
//! assert_eq!(stats.segments, 3 * 4 * 4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Reading a Fractint file:
//!
//! ```
//! use tinyfractal::LFile;
//!
//! let file = LFile::new(include_str!("../tests/data/small.l"));
//! let dragon = file.find("dragon")?; // names are case-insensitive
//! assert_eq!(dragon.rule_count(), 3);
//! # Ok::<(), tinyfractal::Error>(())
//! ```
//!
//! Escape-time fractals: the view picks its fixed-point tier, and the picture goes to the
//! target in tiles (`fill_solid` for uniform ones, `fill_contiguous` for the rest).
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Gray8, prelude::*};
//! use tinyfractal::{Coord, EscapeTime, Fractal, View, escape::Tier, render::TwoColor};
//!
//! let mut display = MockDisplay::<Gray8>::new();
//! let k = (Coord::parse("-0.8").unwrap(), Coord::parse("0.156").unwrap());
//! let view = View::new(
//!     Fractal::Julia { re: k.0, im: k.1 },
//!     (Coord::default(), Coord::default()),
//!     Coord::parse("3.6").unwrap(),
//!     display.size(),
//!     100,
//! )?;
//! assert_eq!(view.tier(), Tier::Standard);
//! let palette = TwoColor { inside: Gray8::BLACK, outside: Gray8::WHITE };
//! let Ok(stats) = EscapeTime::new(view, palette).draw(&mut display);
//! // A Julia set centred on the origin is computed for half its pixels, the rest by symmetry.
//! assert!(stats.pixels <= 64 * 32);
//! assert_eq!(display.get_pixel(Point::new(0, 0)), Some(Gray8::WHITE));
//! # Ok::<(), tinyfractal::Error>(())
//! ```
//!
//! ## Where things are
//! Each family is a module with its types, constants and a runnable example:
//!
//! | module | what it draws |
//! |---|---|
//! | [`lsystem`] | L-systems: Fractint `.l`, ABOP and cpfg-style `.lsys` (parametric, stochastic, context-sensitive, open, 3D) |
//! | [`escape`] | the Mandelbrot and Julia sets, in precision tiers and by perturbation |
//! | [`ifs`] | iterated function systems (the chaos game, Fractint `.ifs`) and the gingerbread man |
//! | [`figure`] | the articulated figure, a hierarchy of parts drawn with a stack of maps |
//! | [`subdivision`] | the Sierpiński carpet, gasket and cube |
//! | [`terrain`] | profiles and landscapes by midpoint displacement |
//! | [`noise`] | Perlin's improved noise, its fractal sums and textures |
//! | [`reaction`] | reaction–diffusion: the Gray–Scott model on the caller's grid |
//! | [`attractor`] | strange attractors: Hénon, Lorenz, Rössler, Clifford, de Jong and more |
//! | [`bezier`] | quadratic and cubic Bézier curves, the smooth counterpart |
//! | [`particles`] | particle systems: a fountain, fire, fireworks, snow, an explosion |
//! | [`dimension`] | the box-counting dimension of any picture |
//!
//! Beneath them, [`math`] holds the numbers (fixed-point [`Real`] and [`Coord`], angles,
//! affine maps, the seeded generator), [`render`] what every family shares on the way to
//! pixels (palettes, projections, fitting, dwell sinks), and [`error`] the one [`Error`]
//! type, grouped by stage. A family depends on these and never on another family. The
//! root re-exports the types a program starts from; [`prelude`] brings the traits and the
//! vocabulary types at once.
//!
//! ## Memory
//! Nothing is allocated. A [`Grammar`] is about 1.7 KiB (its rules compiled); a walk
//! ([`Segments`](lsystem::Segments)) is under 1 KiB with the default capacities, whatever
//! the order; an escape-time [`Render`](escape::Render) about 2.7 KiB at any size, plus
//! 0.5 KiB of stack while it runs.
//!
//! ## Numbers
//! The turtle works in [`Real`] (I32F32) with sines and cosines in Q30 computed by integer
//! maths, so a picture is bit-identical on every target.

#![no_std]
#![deny(
    missing_docs,
    missing_debug_implementations,
    missing_copy_implementations,
    trivial_casts,
    trivial_numeric_casts,
    unsafe_code,
    unstable_features,
    unused_import_braces,
    unused_qualifications,
    rustdoc::broken_intra_doc_links,
    rustdoc::private_intra_doc_links
)]
#![doc(test(attr(deny(warnings))))]
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing,
        clippy::unreachable,
        clippy::todo
    )
)]

/// The README's examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

pub mod attractor;
pub mod bezier;
pub mod dimension;
pub mod error;
pub mod escape;
pub mod figure;
pub mod ifs;
pub mod lsystem;
pub mod math;
pub mod noise;
pub mod particles;
pub mod prelude;
pub mod reaction;
pub mod render;
pub mod subdivision;
pub mod terrain;

pub use dimension::BoxCounter;
pub use error::Error;
pub use escape::{EscapeTime, Fractal, View};
pub use figure::Figure;
pub use ifs::{ChaosGame, Gingerbread, Ifs, IfsFile};
pub use lsystem::{
    Dialect, Grammar, LFile, LSystem, LsysFile, ParametricGrammar, ParametricLSystem,
};
pub use math::{Angle, Coord, Real};
pub use subdivision::{Carpet, Gasket, SierpinskiCube};
pub use terrain::{Terrain, TerrainMap};
