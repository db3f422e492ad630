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
//! use tinyfractal::{Coord, EscapeTime, Fractal, Tier, TwoColor, View};
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
//! ## Layers
//! `math` (fixed-point numbers, angles, wide products) and `render` (rasteriser, sinks,
//! palettes, fitting) are shared; each family (`lsystem`, `escape`) depends on them and
//! never on another family. Errors are grouped by stage: [`ReadError`], [`WalkError`],
//! [`FitError`], [`ViewError`], all inside [`Error`].
//!
//! ## Memory
//! Nothing is allocated. A [`Grammar`] is about 1.7 KiB (its rules compiled); a walk
//! ([`Segments`]) is under 1 KiB with the default capacities, whatever the order; an
//! escape-time [`Render`] about 2.7 KiB at any size, plus 0.5 KiB of stack while it runs.
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

mod dimension;
mod error;
mod escape;
mod figure;
mod ifs;
mod lsystem;
mod math;
mod render;
mod subdivision;
mod terrain;

pub use dimension::{BoxCounter, Dimension};
pub use error::{
    Arithmetic, DrawError, Error, FitError, Location, ParameterError, ReadError, ReadWarning,
    Unsupported, ViewError, WalkError,
};
pub use escape::drawing::{EscapeTime, Painter};
pub use escape::kernel::MAX_FAST_TOLERANCE;
pub use escape::perturbation::{ReferenceOrbit, REFERENCE_POINT_BYTES};
pub use escape::scaled::ReferencePoint;
pub use escape::schedule::{Algorithm, Progress, Render, RenderStats, TILE, TILE_CELLS, TILE_ROWS};
pub use escape::view::{
    Fractal, Shading, Tier, View, MAX_ITERATIONS, MAX_SMOOTH_ITERATIONS, SMOOTH_FRACTION_BITS,
};
pub use escape::zoom::{ReuseStats, ZoomFrame, ZoomLine, ZoomValue};
pub use figure::body::{walk as walk_pose, wave as wave_pose, Joint, BODY};
pub use figure::{
    Figure, FigureDrawing, FigureLine, Part, Pose, Shape, MAX_FIGURE_DEPTH, MAX_JOINTS,
};
pub use ifs::chaos::{
    ChaosGame, DensityDrawing, IfsDrawing, IfsPicture, IfsPoint, DENSITY_LEVELS, SKIPPED,
};
pub use ifs::file::{IfsEntry, IfsFile};
pub use ifs::gingerbread::{
    Cycle, Gingerbread, GingerbreadDrawing, MapPoint, Points as GingerbreadPoints,
};
pub use ifs::maps::{AffineMap, Ifs, MAX_MAPS};
pub use lsystem::alphabet::{DerivedSymbol, Dialect};
pub use lsystem::drawing::{Bounds, LSystem, LSystemDrawing, Placement};
pub use lsystem::fractint::{Entries, Entry, LFile, Warnings};
pub use lsystem::grammar::{Grammar, MAX_NUMERIC_COMMANDS, MAX_RULES, MAX_SYMBOLS};
pub use lsystem::lsys::{LsysEntries, LsysEntry, LsysFile};
pub use lsystem::parametric::context::MAX_CONTEXT_SLOTS;
pub use lsystem::parametric::draw::{ParametricDrawing, ParametricLSystem, ParametricSegments};
pub use lsystem::parametric::environment::{Environment, TurtleState};
pub use lsystem::parametric::grammar::{
    ParametricGrammar, MAX_ARGUMENTS, MAX_CONSTANTS, MAX_MODULES, MAX_PRODUCTIONS,
};
pub use lsystem::parametric::space::{Segment3, Segments3};
pub use lsystem::parametric::values::{DerivedModule, Values, MAX_PARAMS};
pub use lsystem::parametric::walker::ParametricWalker;
pub use lsystem::table::{cells_needed, Cell, MAX_BODY_NESTING};
pub use lsystem::turtle::{Segment, Segments, Start, TurtlePoint, WalkStats, DEFAULT_STACK};
pub use lsystem::walker::{Walker, DEFAULT_BUDGET, DEFAULT_DEPTH};
pub use math::affine::{Affine2, Affine3};
pub use math::random::Generator;
pub use math::{
    Angle, AngleOutOfRange, Coord, DeepCoord, DeepParseError, Overflow, Real, DEEP_LIMBS,
    MAX_ANGLE_DIVISIONS, MAX_DECIMAL_PLACES,
};
pub use render::fit::{Orientation, DEFAULT_MARGIN};
pub use render::palette::{Bands, Colors, Gradient, Palette, TwoColor};
pub use render::projection::Projection;
pub use render::sink::{DwellBuffer, DwellSink};
pub use render::space::DEPTH_LEVELS;
pub use subdivision::carpet::{Carpet, CarpetDrawing, CarpetStats};
pub use subdivision::cube::{Camera, CubeDrawing, CubeStats, CubeVariant, SierpinskiCube};
pub use subdivision::gasket::{Gasket, GasketDrawing, GasketStats};
pub use subdivision::MAX_SUBDIVISION_ORDER;
pub use terrain::map::{MapDrawing, TerrainMap, MAX_MAP_LEVELS};
pub use terrain::profile::{Heights, ProfileDrawing, Terrain};
pub use terrain::{Displacement, MAX_END, MAX_SIGMA, MAX_TERRAIN_LEVELS};
