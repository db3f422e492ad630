//! Every scene, described once: the L-systems as the books give them, and the entries (a
//! system at an order, or an escape-time view, with a size and a palette) that the gallery,
//! every firmware and the measuring firmware read.

use embedded_graphics::{geometry::Size, pixelcolor::Rgb888};
use tinyfractal::{
    attractor::Kind,
    escape::{Shading, Tier},
    lsystem::Wind,
    math::DeepCoord,
    noise::{Octaves, Texture},
    particles::Preset as ParticlePreset,
    reaction::Preset,
    render::{Dither, Orientation},
    subdivision::CubeVariant,
    terrain::Displacement,
    Angle, Coord, Dialect, Error, Fractal, Grammar, Real, View,
};

/// An L-system in ABOP notation: axiom, rules, angle, and the symbols besides `F` that draw.
#[derive(Debug, Clone, Copy)]
pub struct System {
    /// The axiom.
    pub axiom: &'static str,
    /// The rules, symbol and body.
    pub rules: &'static [(char, &'static str)],
    /// How far `+` and `-` turn.
    pub angle: Angle,
    /// Symbols besides `F` that draw a line (edge-rewriting systems).
    pub draw_symbols: &'static str,
    /// Stochastic productions: symbol, body, probability.
    pub alternatives: &'static [(char, &'static str, Real)],
    /// The seed of the stochastic choices.
    pub seed: u32,
}

impl System {
    /// The checked grammar. Built out of line, with the draw symbols added only when there
    /// are some: every by-value builder step can cost a grammar-sized copy on an MCU's
    /// stack, and the frame of a caller that draws both families should not hold them.
    #[inline(never)]
    pub fn grammar(&self) -> Result<Grammar<'static>, Error> {
        // Built in place: a grammar is a few KiB, and every move is a copy on an MCU stack.
        let mut grammar = Grammar::new(Dialect::Abop, self.axiom, self.angle)?;
        grammar.add_draw_symbols(self.draw_symbols)?;
        for &(symbol, body) in self.rules {
            grammar.add_rule(symbol, body)?;
        }
        for &(symbol, body, probability) in self.alternatives {
            grammar.add_alternative(symbol, body, probability)?;
        }
        grammar.set_seed(self.seed);
        Ok(grammar)
    }
}

/// A subdivision fractal of the Sierpiński family.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// The carpet.
    Carpet,
    /// The gasket.
    Gasket,
    /// The cube, seen isometrically.
    Cube(CubeVariant),
}

/// The colour of the Sierpiński cube's faces, before shading.
pub const CUBE_COLOUR: Rgb888 = Rgb888::new(0xC8, 0xB4, 0x78);

/// What to draw.
#[derive(Debug, Clone, Copy)]
pub enum Scene {
    /// An L-system at an order.
    LSystem {
        /// The system.
        system: &'static System,
        /// Order.
        order: u32,
        /// Which way the first heading points.
        orientation: Orientation,
    },
    /// An IFS of a `.ifs` text by the chaos game.
    Ifs {
        /// The `.ifs` text.
        source: &'static str,
        /// The entry in it.
        system: &'static str,
        /// Points plotted.
        points: u64,
        /// The game's seed.
        seed: u64,
        /// Drawn by density (each pixel by how many points hit it, through the look's
        /// gradient) instead of each point in ink.
        density: bool,
    },
    /// A subdivision fractal at an order.
    Subdivision {
        /// Which.
        shape: Shape,
        /// Order.
        order: u32,
    },
    /// Midpoint-displacement terrain: a profile, or a landscape (`map`) of `samples`²
    /// heights.
    Terrain {
        /// Roughness, σ and seed.
        displacement: Displacement,
        /// Heights (along a side, for a landscape): 2ᵏ + 1.
        samples: u32,
        /// A 2D landscape rather than a profile.
        map: bool,
    },
    /// The lecture's articulated figure walking: `frames` frames of one stride, fitted
    /// once, each erasing the last.
    Walk {
        /// Frames in the cycle.
        frames: u32,
    },
    /// A Mandelbrot or Julia view.
    Escape(EscapeScene),
    /// Cubic Bézier curves given in a 320×240 design, scaled uniformly and centred on the
    /// picture, one pixel wide in the look's ink over its background.
    Bezier {
        /// Each curve's four control points, in the design's pixels.
        curves: &'static [[(i16, i16); 4]],
    },
    /// A particle system from its start, `frames` ticks (a thirtieth of a second each), each
    /// frame erasing the last one's particles (an animation on a board).
    Particles {
        /// Which system.
        preset: ParticlePreset,
        /// Frames drawn, a tick each.
        frames: u32,
    },
    /// A strange attractor with its kind's defaults, `points` points after the default
    /// transient, by density (hit counts a byte a pixel) over the picture.
    Attractor {
        /// Which attractor.
        kind: Kind,
        /// Points plotted.
        points: u64,
    },
    /// One of Perlin's textures over the picture, `scale` lattice cells across it.
    Noise {
        /// Which texture.
        texture: Texture,
        /// The octaves of its sums.
        octaves: Octaves,
        /// Lattice cells across the picture's width.
        scale: Real,
        /// The permutation's seed (0: Perlin's own).
        seed: u32,
    },
    /// One of Perlin's textures moving through 3D noise: `frames` frames, frame k at depth
    /// k·`z_step`, each drawn over the last (an animation on a board).
    NoiseFlight {
        /// Which texture.
        texture: Texture,
        /// The octaves of its sums.
        octaves: Octaves,
        /// Lattice cells across the picture's width.
        scale: Real,
        /// The permutation's seed.
        seed: u32,
        /// Frames drawn.
        frames: u32,
        /// How much deeper each frame is, in lattice cells.
        z_step: Real,
    },
    /// A landscape of noise: `samples`² heights of fBm, `scale` lattice cells across,
    /// drawn as a relief (like a midpoint-displacement landscape).
    NoiseTerrain {
        /// The octaves of its fBm.
        octaves: Octaves,
        /// Lattice cells across.
        scale: Real,
        /// The permutation's seed.
        seed: u32,
        /// Heights along a side.
        samples: u32,
    },
    /// Reaction–diffusion: `preset` on a `grid` of cells from Sims's square start, after
    /// `steps` steps, stretched over the picture.
    Reaction {
        /// The (f, k) pair.
        preset: Preset,
        /// Cells across and down.
        grid: (u32, u32),
        /// Steps of the model.
        steps: u32,
    },
    /// A zoom into the Mandelbrot set, `frames` frames in one frame of storage: each frame
    /// takes the last one's columns and rows within `tolerance_percent` % of a pixel
    /// (`ZoomFrame::advance`) and computes the rest; the last is exact.
    Zoom {
        /// Centre.
        centre: (&'static str, &'static str),
        /// The first frame's width.
        width: &'static str,
        /// Iteration cap: at most 255 (a board keeps a byte a pixel).
        max_iterations: u32,
        /// Frames drawn.
        frames: u32,
        /// Each frame's width is the last one's times this ratio (numerator, denominator).
        shrink: (u32, u32),
        /// How far (in % of a pixel) a line may be from the one it takes.
        tolerance_percent: u32,
        /// XaoS's autopilot with this seed steers each frame instead (`escape::Autopilot`,
        /// from `centre` and `width`; `shrink` unused), with the scenes' `panels` feature;
        /// without it such a scene draws the background and does no work.
        pilot: Option<u64>,
    },
}

impl Scene {
    /// Whether the scene is one of Sierpiński's shapes or the walking figure: the scenes'
    /// `shapes` feature, measured by the measuring firmware's build of their own beside
    /// their baselines.
    pub const fn is_shape(&self) -> bool {
        matches!(self, Self::Subdivision { .. } | Self::Walk { .. })
    }

    /// Whether the scene is a midpoint-displacement terrain: the scenes' `terrain` feature,
    /// measured by the measuring firmware's build of its own beside its baselines.
    pub const fn is_terrain(&self) -> bool {
        matches!(self, Self::Terrain { .. })
    }

    /// What the scene's [`Work`](crate::Work) counts, singular: `segment`, `point`,
    /// `iteration`, `frame`, `square`, `triangle`, `cube`, `height`, `line`, `sample` or
    /// `cell-step`.
    pub const fn work_unit(&self) -> &'static str {
        match self {
            Self::LSystem { .. } => "segment",
            Self::Ifs { .. } => "point",
            Self::Escape { .. } => "iteration",
            Self::Zoom { .. } => "frame",
            Self::Subdivision { shape, .. } => match shape {
                Shape::Carpet => "square",
                Shape::Gasket => "triangle",
                Shape::Cube(_) => "cube",
            },
            Self::Terrain { .. } => "height",
            Self::Walk { .. } => "line",
            Self::Noise { .. } => "sample",
            Self::Reaction { .. } => "cell-step",
            Self::NoiseTerrain { .. } => "height",
            Self::NoiseFlight { .. } => "sample",
            Self::Attractor { .. } => "point",
            Self::Bezier { .. } => "segment",
            Self::Particles { .. } => "particle-step",
        }
    }

    /// The family, as the CLI names it: `lsystem`, `ifs`, `carpet`, `gasket`, `cube`,
    /// `terrain`, `terrain2d`, `figure`, `mandelbrot`, `julia`, `noise`, `reaction`,
    /// `attractor`, `bezier`, `particles` or `zoom` (`animate zoom`).
    pub const fn family(&self) -> &'static str {
        match self {
            Self::LSystem { .. } => "lsystem",
            Self::Ifs { .. } => "ifs",
            Self::Subdivision { shape, .. } => match shape {
                Shape::Carpet => "carpet",
                Shape::Gasket => "gasket",
                Shape::Cube(_) => "cube",
            },
            Self::Terrain { map: false, .. } => "terrain",
            Self::Terrain { map: true, .. } => "terrain2d",
            Self::Walk { .. } => "figure",
            Self::Escape(EscapeScene { julia: None, .. }) => "mandelbrot",
            Self::Escape(EscapeScene { julia: Some(_), .. }) => "julia",
            Self::Zoom { .. } => "zoom",
            Self::Noise { .. } => "noise",
            Self::Reaction { .. } => "reaction",
            Self::NoiseTerrain { .. } => "terrain2d",
            Self::NoiseFlight { .. } => "noise",
            Self::Attractor { .. } => "attractor",
            Self::Bezier { .. } => "bezier",
            Self::Particles { .. } => "particles",
        }
    }

    /// The escape-time view of this scene at `size`; `None` for any other scene (a zoom
    /// has many).
    pub fn view(&self, size: Size) -> Option<Result<View, Error>> {
        match self {
            Self::Escape(escape) => Some(escape.view(size)),
            _ => None,
        }
    }
}

/// A Mandelbrot (`julia: None`) or Julia view, as decimal text: the catalogue's entries
/// are checked when compiled; in a scene built by hand, a number that does not parse
/// counts as 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EscapeScene {
    /// The Julia parameter, or `None` for the Mandelbrot set.
    pub julia: Option<(&'static str, &'static str)>,
    /// Centre.
    pub centre: (&'static str, &'static str),
    /// Width along the real axis.
    pub width: &'static str,
    /// Iteration cap.
    pub max_iterations: u32,
    /// Dwells or smooth values (a `smooth-*` palette on the host).
    pub shading: Shading,
    /// The tier forced on the view, or `None` for its own (the calibrated rule's).
    pub tier: Option<Tier>,
    /// Shown on a one-bit panel (an SSD1306) by this dithering, or `None` in the look's
    /// colours.
    pub one_bit: Option<Dither>,
    /// Distance estimation's width in 256ths of a pixel (`View::with_distance`), 0 for
    /// none.
    pub distance: u16,
}

impl EscapeScene {
    /// The view of these numbers at `size`.
    pub fn view(&self, size: Size) -> Result<View, Error> {
        // Every catalogue number parses: `escape()` asserts it when the tables compile.
        let coord = |text: &str| Coord::parse(text).unwrap_or_default();
        let deep = |text: &str| DeepCoord::parse(text).unwrap_or_default();
        let fractal = match self.julia {
            None => Fractal::Mandelbrot,
            Some((re, im)) => Fractal::Julia {
                re: coord(re),
                im: coord(im),
            },
        };
        View::deep(
            fractal,
            (deep(self.centre.0), deep(self.centre.1)),
            deep(self.width),
            size,
            self.max_iterations,
        )
        .map(|view| match self.tier {
            Some(tier) => view.with_tier(tier),
            None => view,
        })
        .and_then(|view| view.with_shading(self.shading))
        .map(|view| view.with_distance(self.distance))
    }

    /// The same view with `shading` (smooth shading keeps the cap within
    /// [`View::MAX_SMOOTH_ITERATIONS`]).
    pub const fn with_shading(self, shading: Shading) -> Self {
        if let Shading::Smooth = shading {
            assert!(self.max_iterations <= View::MAX_SMOOTH_ITERATIONS);
        }
        Self { shading, ..self }
    }

    /// The same view computed in `tier` whatever its own.
    pub const fn with_tier(self, tier: Tier) -> Self {
        Self {
            tier: Some(tier),
            ..self
        }
    }

    /// The same view with an iteration cap of `max_iterations`.
    pub const fn with_max_iterations(self, max_iterations: u32) -> Self {
        Self {
            max_iterations,
            ..self
        }
    }
}

/// A scene as a front end shows it: its name, its default size in pixels, and the host
/// palette it is painted with (boards use their display's [`Look`](crate::Look) instead).
#[derive(Debug, Clone, Copy)]
pub struct Entry {
    /// The name (file names, measurement records).
    pub name: &'static str,
    /// What to draw.
    pub scene: Scene,
    /// Default size in pixels.
    pub size: Size,
    /// The host palette: `vga` for L-systems, `classic`, `fire`, ... for escape time.
    pub palette: &'static str,
}

/// Degrees as an exact ratio, for the tables below.
const fn degrees(numerator: i64, denominator: i64) -> Angle {
    match Real::from_ratio(numerator, denominator) {
        Some(value) => Angle::Degrees(value),
        None => panic!("a degree ratio out of range"),
    }
}

/// The Koch snowflake (Fractint's Koch1).
pub const KOCH_SNOWFLAKE: System = System {
    axiom: "F--F--F",
    rules: &[('F', "F+F--F+F")],
    angle: Angle::Divisions(6),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};
/// The Heighway dragon.
pub const DRAGON: System = System {
    axiom: "FX",
    rules: &[('X', "X+YF+"), ('Y', "-FX-Y")],
    angle: Angle::Divisions(4),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};
/// The Hilbert curve.
pub const HILBERT: System = System {
    axiom: "A",
    rules: &[('A', "+BF-AFA-FB+"), ('B', "-AF+BFB+FA-")],
    angle: Angle::Divisions(4),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};
/// The Sierpiński arrowhead (edge rewriting: `A` and `B` draw).
pub const SIERPINSKI_ARROWHEAD: System = System {
    axiom: "A",
    rules: &[('A', "B-A-B"), ('B', "A+B+A")],
    angle: Angle::Divisions(6),
    draw_symbols: "AB",
    alternatives: &[],
    seed: 0,
};
/// The Gosper curve (ABOP fig. 1.11a, edge rewriting).
pub const GOSPER: System = System {
    axiom: "A",
    rules: &[('A', "A-B--B+A++AA+B-"), ('B', "+A-BB--B-A++A+B")],
    angle: Angle::Divisions(6),
    draw_symbols: "AB",
    alternatives: &[],
    seed: 0,
};
/// ABOP fig. 1.24d: a plant, 20°.
pub const PLANT: System = System {
    axiom: "X",
    rules: &[('X', "F[+X]F[-X]+X"), ('F', "FF")],
    angle: Angle::Degrees(Real::from_int(20)),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};
/// ABOP fig. 1.24f: a fern-like plant, 22.5°.
pub const FERN: System = System {
    axiom: "X",
    rules: &[('X', "F-[[X]+X]+F[+FX]-X"), ('F', "FF")],
    angle: degrees(45, 2),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};
/// ABOP fig. 1.25: a bush, 22.5°.
pub const BUSH: System = System {
    axiom: "F",
    rules: &[('F', "FF-[-F+F+F]+[+F-F-F]")],
    angle: degrees(45, 2),
    draw_symbols: "",
    alternatives: &[],
    seed: 0,
};

/// ABOP fig. 1.27: a stochastic plant, 25.7°, whose choices are the same on every walk and
/// every core (the QEMU checksums prove it).
pub const STOCHASTIC_PLANT: System = System {
    axiom: "F",
    rules: &[],
    angle: degrees(257, 10),
    draw_symbols: "",
    alternatives: &[
        ('F', "F[+F]F[-F]F", ratio(33, 100)),
        ('F', "F[+F]F", ratio(33, 100)),
        ('F', "F[-F]F", ratio(34, 100)),
    ],
    seed: 1,
};

/// A probability as a ratio.
const fn ratio(numerator: i64, denominator: i64) -> Real {
    match Real::from_ratio(numerator, denominator) {
        Some(value) => value,
        None => panic!("a probability ratio out of range"),
    }
}

const GALLERY_SIZE: Size = Size::new(320, 240);
/// The LM3S6965EVB's OLED, where the board scenes are checked and measured.
const OLED: Size = Size::new(128, 64);

const fn lsystem(
    name: &'static str,
    system: &'static System,
    order: u32,
    orientation: Orientation,
    size: Size,
) -> Entry {
    Entry {
        name,
        scene: Scene::LSystem {
            system,
            order,
            orientation,
        },
        size,
        palette: "vga",
    }
}

const fn escape(
    name: &'static str,
    julia: Option<(&'static str, &'static str)>,
    centre: (&'static str, &'static str),
    width: &'static str,
    max_iterations: u32,
    size: Size,
    palette: &'static str,
) -> Entry {
    // Checked when the tables are compiled: `Scene::view` can rely on it.
    if let Some((re, im)) = julia {
        assert!(Coord::parse(re).is_some() && Coord::parse(im).is_some());
    }
    assert!(Coord::parse(centre.0).is_some() && Coord::parse(centre.1).is_some());
    assert!(Coord::parse(width).is_some());
    Entry {
        name,
        scene: Scene::Escape(EscapeScene {
            julia,
            centre,
            width,
            max_iterations,
            shading: Shading::Dwell,
            tier: None,
            one_bit: None,
            distance: 0,
        }),
        size,
        palette,
    }
}

/// `entry`, an escape-time view, in smooth colour: painted with `palette` (a `smooth-*`
/// name) on the host, with 16× the gradient's entries on a board.
const fn smooth(entry: Entry, palette: &'static str) -> Entry {
    Entry {
        palette,
        ..adjusted(entry, escape_of(entry).with_shading(Shading::Smooth))
    }
}

/// `entry`, an escape-time view, by perturbation whatever its depth (the side-by-side
/// with the tier its view would take).
const fn perturbed(name: &'static str, entry: Entry) -> Entry {
    Entry {
        name,
        ..adjusted(entry, escape_of(entry).with_tier(Tier::Perturbation))
    }
}

/// `entry`, an escape-time view, shown on a one-bit panel by Bayer's 8×8 dither.
const fn one_bit(name: &'static str, entry: Entry) -> Entry {
    one_bit_by(name, entry, Dither::Bayer8)
}

/// `entry`, an escape-time view, shown on a one-bit panel by `dither`.
const fn one_bit_by(name: &'static str, entry: Entry, dither: Dither) -> Entry {
    let escape = escape_of(entry);
    Entry {
        name,
        ..adjusted(
            entry,
            EscapeScene {
                one_bit: Some(dither),
                ..escape
            },
        )
    }
}

/// `entry`, an escape-time view, with distance estimation at Fractint's width (0.71 of a
/// pixel, 182/256).
const fn estimated(name: &'static str, entry: Entry) -> Entry {
    let escape = escape_of(entry);
    Entry {
        name,
        ..adjusted(
            entry,
            EscapeScene {
                distance: 182,
                ..escape
            },
        )
    }
}

/// `entry`, an escape-time view, computed in `tier` (a cheaper tier than the rule's, where
/// it keeps the same dwells: checked in tests/tiers.rs).
const fn in_tier(tier: Tier, entry: Entry) -> Entry {
    adjusted(entry, escape_of(entry).with_tier(tier))
}

/// The escape-time view of `entry`, which must be one.
const fn escape_of(entry: Entry) -> EscapeScene {
    match entry.scene {
        Scene::Escape(escape) => escape,
        _ => panic!("only an escape-time view can be adjusted"),
    }
}

/// `entry` showing `escape` instead.
const fn adjusted(entry: Entry, escape: EscapeScene) -> Entry {
    Entry {
        scene: Scene::Escape(escape),
        ..entry
    }
}

/// The full Mandelbrot view.
const MANDELBROT_CENTRE: (&str, &str) = ("-0.75", "0");
/// The Julia set for k = −0.8 + 0.156i.
const JULIA_K: Option<(&str, &str)> = Some(("-0.8", "0.156"));
/// Seahorse valley's spiral, for the deep zooms.
const SPIRAL: (&str, &str) = ("-0.743643887037151", "0.131825904205330");
/// The Misiurewicz point M₄,₁ (z₄ a repelling fixed point, found by Newton's method):
/// spirals at every depth, and dwells that grow only with the log of the zoom.
const MISIUREWICZ_4_1: (&str, &str) = (
    "-0.1010963638456221610257854457386225654638",
    "0.9562865108091415007710960577299774358098",
);
/// The nucleus of a period-78 minibrot about 2.5·10⁻²¹ across, near M₄,₁.
const MINIBROT_78: (&str, &str) = (
    "-0.10109636410757091114366614915908574412568301067472",
    "0.95628651094936751151473189358592427640764366257311",
);

const fn subdivision(name: &'static str, shape: Shape, order: u32, size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::Subdivision { shape, order },
        size,
        palette: "vga",
    }
}

/// Midpoint displacement with roughness `percent`/100, σ and seed.
const fn terrain(
    name: &'static str,
    (percent, sigma, seed): (i64, i32, u64),
    samples: u32,
    map: bool,
    size: Size,
) -> Entry {
    Entry {
        name,
        scene: Scene::Terrain {
            displacement: Displacement {
                roughness: ratio(percent, 100),
                sigma: Real::from_int(sigma),
                seed,
            },
            samples,
            map,
        },
        size,
        palette: "vga",
    }
}

/// Perlin's `texture` of the permutation `seed`, six octaves of persistence ½ and
/// lacunarity 2, four lattice cells across.
const fn noise(name: &'static str, texture: Texture, seed: u32, size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::Noise {
            texture,
            octaves: Octaves {
                octaves: 6,
                persistence: ratio(1, 2),
                lacunarity: Real::from_int(2),
            },
            scale: Real::from_int(4),
            seed,
        },
        size,
        palette: "",
    }
}

/// Perlin's `texture` moving a quarter of a lattice cell deeper a frame, `frames` frames,
/// six octaves, four lattice cells across.
const fn noise_flight(name: &'static str, texture: Texture, frames: u32, size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::NoiseFlight {
            texture,
            octaves: Octaves {
                octaves: 6,
                persistence: ratio(1, 2),
                lacunarity: Real::from_int(2),
            },
            scale: Real::from_int(4),
            seed: 0,
            frames,
            z_step: ratio(1, 4),
        },
        size,
        palette: "",
    }
}

/// A landscape of `samples`² heights of six octaves of fBm (persistence ½, lacunarity 2),
/// four lattice cells across, of the permutation `seed`.
const fn noise_terrain(name: &'static str, seed: u32, samples: u32, size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::NoiseTerrain {
            octaves: Octaves {
                octaves: 6,
                persistence: ratio(1, 2),
                lacunarity: Real::from_int(2),
            },
            scale: Real::from_int(4),
            seed,
            samples,
        },
        size,
        palette: "",
    }
}

/// `preset` on a `grid` (Sims's square start), after `steps` steps.
const fn reaction(
    name: &'static str,
    preset: Preset,
    grid: (u32, u32),
    steps: u32,
    size: Size,
) -> Entry {
    Entry {
        name,
        scene: Scene::Reaction {
            preset,
            grid,
            steps,
        },
        size,
        palette: "",
    }
}

/// `kind`'s attractor by density, `points` points.
const fn attractor(name: &'static str, kind: Kind, points: u64, size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::Attractor { kind, points },
        size,
        palette: "",
    }
}

/// A figure drawn in smooth curves, the lecture's counterpart to the articulated figure.
///
/// A head of four arcs, a spine, arms (one waving), legs and the ground, as cubic Bézier
/// curves in a 320×240 design (y down).
pub const SMOOTH_FIGURE: [[(i16, i16); 4]; 10] = [
    [(182, 50), (182, 38), (172, 28), (160, 28)],
    [(160, 28), (148, 28), (138, 38), (138, 50)],
    [(138, 50), (138, 62), (148, 72), (160, 72)],
    [(160, 72), (172, 72), (182, 62), (182, 50)],
    [(160, 72), (150, 100), (170, 125), (160, 150)],
    [(160, 90), (135, 95), (115, 120), (105, 150)],
    [(160, 90), (185, 85), (205, 70), (215, 45)],
    [(160, 150), (150, 175), (135, 195), (125, 225)],
    [(160, 150), (172, 178), (188, 198), (205, 222)],
    [(20, 230), (110, 215), (210, 245), (300, 228)],
];

/// Curves of the 320×240 design `curves`.
const fn bezier(name: &'static str, curves: &'static [[(i16, i16); 4]], size: Size) -> Entry {
    Entry {
        name,
        scene: Scene::Bezier { curves },
        size,
        palette: "",
    }
}

/// The gallery (`cargo run --release`), 320×240.
///
/// Classic L-systems, escape-time views, the Sierpiński family, midpoint-displacement
/// terrain, Perlin's textures, reaction–diffusion, strange attractors and a figure in
/// Bézier curves.
#[rustfmt::skip]
pub const GALLERY: [Entry; 32] = [
    lsystem("koch-snowflake", &KOCH_SNOWFLAKE, 5, Orientation::Right, GALLERY_SIZE),
    lsystem("dragon", &DRAGON, 12, Orientation::Right, GALLERY_SIZE),
    lsystem("hilbert", &HILBERT, 6, Orientation::Right, GALLERY_SIZE),
    lsystem("sierpinski-arrowhead", &SIERPINSKI_ARROWHEAD, 7, Orientation::Right, GALLERY_SIZE),
    lsystem("gosper", &GOSPER, 4, Orientation::Right, GALLERY_SIZE),
    lsystem("plant", &PLANT, 7, Orientation::Up, GALLERY_SIZE),
    lsystem("fern", &FERN, 6, Orientation::Up, GALLERY_SIZE),
    lsystem("bush", &BUSH, 4, Orientation::Up, GALLERY_SIZE),
    escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, GALLERY_SIZE, "classic"),
    escape("seahorse-valley", None, ("-0.7435", "0.1314"), "0.02", 512, GALLERY_SIZE, "fire"),
    escape("julia", JULIA_K, ("0", "0"), "3.2", 300, GALLERY_SIZE, "classic"),
    smooth(escape("mandelbrot-smooth", None, ("-0.7453", "0.1127"), "0.01", 500, GALLERY_SIZE, ""), "smooth-classic"),
    // Width 10^-9 at 4000 iterations: a long orbit this deep goes by `Wide`, which keeps
    // the dwells Deep's 60 bits and perturbation lose (measured in docs/tiers.md).
    escape("deep-zoom", None, SPIRAL, "0.000000001", 4000, GALLERY_SIZE, "fire"),
    // Past Deep's 2^-54: perturbation against one reference orbit.
    escape("deep-minibrot", None, MINIBROT_78, "1e-20", 2000, GALLERY_SIZE, "fire"),
    escape("deep-spiral", None, MISIUREWICZ_4_1, "1e-30", 1000, GALLERY_SIZE, "classic"),
    subdivision("sierpinski-carpet", Shape::Carpet, 4, GALLERY_SIZE),
    subdivision("sierpinski-gasket", Shape::Gasket, 7, GALLERY_SIZE),
    subdivision("sierpinski-cube", Shape::Cube(CubeVariant::Centre), 3, GALLERY_SIZE),
    subdivision("menger-sponge", Shape::Cube(CubeVariant::Axes), 3, GALLERY_SIZE),
    terrain("terrain", (70, 40, 7), 1025, false, GALLERY_SIZE),
    terrain("terrain2d", (60, 40, 3), 257, true, GALLERY_SIZE),
    noise("noise-clouds", Texture::Clouds, 0, GALLERY_SIZE),
    noise("noise-marble", Texture::Marble, 0, GALLERY_SIZE),
    noise_terrain("noise-terrain", 3, 257, GALLERY_SIZE),
    reaction("reaction-mitosis", Preset::Mitosis, (128, 96), 8000, GALLERY_SIZE),
    reaction("reaction-maze", Preset::Maze, (128, 96), 8000, GALLERY_SIZE),
    attractor("attractor-henon", Kind::Henon, 1_000_000, GALLERY_SIZE),
    attractor("attractor-lorenz", Kind::Lorenz, 1_000_000, GALLERY_SIZE),
    attractor("attractor-clifford", Kind::Clifford, 1_000_000, GALLERY_SIZE),
    attractor("attractor-dejong", Kind::DeJong, 1_000_000, GALLERY_SIZE),
    bezier("bezier-figure", &SMOOTH_FIGURE, GALLERY_SIZE),
    Entry {
        name: "particles-fireworks",
        scene: Scene::Particles { preset: ParticlePreset::Fireworks, frames: 40 },
        size: GALLERY_SIZE,
        palette: "",
    },
];

/// The systems of ABOP's `data/abop.lsys`, drawn by the general engine.
pub const ABOP_LSYS: &str = include_str!("../../../data/abop.lsys");

/// A system of the general engine (parameters, contexts, 3D) at an order: a host scene,
/// its grammar and walk needing tens of KiB.
#[derive(Debug, Clone, Copy)]
pub struct GeneralEntry {
    /// The name (file names).
    pub name: &'static str,
    /// The `.lsys` text.
    pub source: &'static str,
    /// The system in it.
    pub system: &'static str,
    /// Order.
    pub order: u32,
    /// Size in pixels.
    pub size: Size,
    /// Frames of a loop swaying in [`WIND`] (0: still).
    pub frames: u32,
}

/// The wind the swaying scenes blow: e·T = 0.05 towards +x at a gust's height, seed 1
/// (`animate sway`'s default).
pub const WIND: Wind = Wind {
    push: [Real::from_bits((1 << 32) / 20), Real::ZERO, Real::ZERO],
    seed: 1,
};

/// The colours the general engine's colour modules index unless an entry has a `colors:`
/// line: the book's browns to greens, then flower colours.
pub const BOOK: [Rgb888; 16] = [
    Rgb888::new(0x8B, 0x5A, 0x2B),
    Rgb888::new(0x7A, 0x4E, 0x24),
    Rgb888::new(0x6B, 0x5A, 0x2A),
    Rgb888::new(0x5C, 0x6B, 0x2E),
    Rgb888::new(0x4A, 0x7A, 0x30),
    Rgb888::new(0x3C, 0x8A, 0x34),
    Rgb888::new(0x34, 0x9A, 0x3A),
    Rgb888::new(0x3E, 0xAA, 0x44),
    Rgb888::new(0x52, 0xBA, 0x4E),
    Rgb888::new(0x6C, 0xC8, 0x5A),
    Rgb888::new(0x8A, 0xD4, 0x68),
    Rgb888::new(0xA8, 0xDE, 0x7A),
    Rgb888::new(0xF2, 0xE2, 0x5C),
    Rgb888::new(0xF0, 0x9C, 0x4C),
    Rgb888::new(0xE8, 0x6A, 0x8A),
    Rgb888::new(0xF8, 0xF4, 0xF0),
];

const fn general(name: &'static str, system: &'static str, order: u32) -> GeneralEntry {
    GeneralEntry {
        name,
        source: ABOP_LSYS,
        system,
        order,
        size: GALLERY_SIZE,
        frames: 0,
    }
}

/// A general-engine scene on the OLED.
const fn oled_plant(
    name: &'static str,
    system: &'static str,
    order: u32,
    frames: u32,
) -> GeneralEntry {
    GeneralEntry {
        name,
        source: ABOP_LSYS,
        system,
        order,
        size: OLED,
        frames,
    }
}

/// The gallery's systems of the general engine: ABOP's context-sensitive, 3D and
/// parametric plants (leaves filled, widths, tropism), and the lecture's.
#[rustfmt::skip]
pub const GENERAL_GALLERY: [GeneralEntry; 8] = [
    general("hogeweg-plant", "Fig1.31b", 30),
    general("hilbert-3d", "Hilbert3D", 3),
    general("bush-3d", "Fig1.25", 7),
    general("flowering-plant", "Fig1.26", 5),
    general("tree-tropism", "Fig2.8a", 6),
    general("monopodial-tree", "MonopodialTree", 10),
    general("sympodial-tree", "SympodialTree", 10),
    general("lecture-plant", "LectureParametric", 7),
];

/// The lecture's IFS, `data/lecture.ifs`.
pub const LECTURE_IFS: &str = include_str!("../../../data/lecture.ifs");

/// An IFS of a `.ifs` text drawn by the chaos game.
#[derive(Debug, Clone, Copy)]
pub struct IfsEntry {
    /// The name (file names).
    pub name: &'static str,
    /// The `.ifs` text.
    pub source: &'static str,
    /// The entry in it.
    pub system: &'static str,
    /// Points plotted.
    pub points: u64,
    /// Size in pixels.
    pub size: Size,
}

/// The gallery's IFS: the lecture's fern and the Sierpinski gasket.
pub const IFS_GALLERY: [IfsEntry; 2] = [
    IfsEntry {
        name: "ifs-fern",
        source: LECTURE_IFS,
        system: "fern",
        points: 100_000,
        size: GALLERY_SIZE,
    },
    IfsEntry {
        name: "ifs-gasket",
        source: LECTURE_IFS,
        system: "gasket",
        points: 50_000,
        size: GALLERY_SIZE,
    },
];

/// The general engine's scenes measured on Cortex-M3 and M4 (not M0: the micro:bit's 16 KiB
/// cannot hold the engine's grammar and walk), and shown by the real boards in colour.
///
/// ABOP's monopodial tree (figure 2.6, a parametric 3D system, with widths) at its order on
/// the OLED; the bush of figure 1.25 with its leaves filled and lit, and the same bush
/// without leaves (the same lines: what the leaves cost); the tree of figure 2.8 (a)
/// swaying in the wind, four frames.
#[rustfmt::skip]
pub const GENERAL_SCENES: [GeneralEntry; 4] = [
    oled_plant("monopodial-tree", "MonopodialTree", 10, 0),
    oled_plant("bush-leaves", "Fig1.25", 5, 0),
    oled_plant("bush-bare", "Fig1.25Bare", 5, 0),
    oled_plant("tree-sway", "Fig2.8a", 5, 4),
];

/// The lecture's IFS in the catalogue's notation: in ink, or by density where `density`.
const fn ifs(
    name: &'static str,
    system: &'static str,
    points: u64,
    density: bool,
    size: Size,
) -> Entry {
    Entry {
        name,
        scene: Scene::Ifs {
            source: LECTURE_IFS,
            system,
            points,
            seed: 1,
            density,
        },
        size,
        palette: "vga",
    }
}

/// The boards' scenes, in the order they are shown: drawn on the LM3S6965's OLED under
/// QEMU, on the real boards' displays, and measured on Cortex-M0/M3/M4.
#[rustfmt::skip]
pub const SCENES: [Entry; 15] = [
    lsystem("plant", &FERN, 5, Orientation::Up, OLED),
    lsystem("koch-snowflake", &KOCH_SNOWFLAKE, 4, Orientation::Right, OLED),
    lsystem("stochastic-plant", &STOCHASTIC_PLANT, 4, Orientation::Up, OLED),
    ifs("ifs-fern", "fern", 20_000, false, OLED),
    // The same game by density: each pixel by its hit count.
    ifs("ifs-fern-density", "fern", 20_000, true, OLED),
    subdivision("sierpinski-carpet", Shape::Carpet, 3, OLED),
    subdivision("sierpinski-gasket", Shape::Gasket, 6, OLED),
    subdivision("menger-sponge", Shape::Cube(CubeVariant::Axes), 2, OLED),
    // One sample a column of the OLED.
    terrain("terrain", (70, 40, 7), 129, false, OLED),
    // The largest landscape a board holds (MAX_BOARD_MAP_CELLS).
    terrain("terrain2d", (60, 40, 3), 33, true, OLED),
    Entry { name: "walking-figure", scene: Scene::Walk { frames: 16 }, size: OLED, palette: "vga" },
    escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 64, OLED, "classic"),
    escape("julia", JULIA_K, ("0", "0"), "3.6", 100, OLED, "classic"),
    smooth(escape("mandelbrot-smooth", None, ("-0.6", "0"), "3.2", 64, OLED, ""), "smooth-classic"),
    DEEP_ZOOM,
];

/// The boards' deep zoom, 10⁻⁷ wide: the 60-bit tier with 128-bit products. The rule gives
/// a view this deep with a cap over 256 to `Wide`; this one keeps every `Wide` dwell in
/// `Deep` (tests/tiers.rs), the tier a board would pick by hand. Drawn by perturbation
/// too ([`DEEP_SCENES`]).
const DEEP_ZOOM: Entry = in_tier(
    Tier::Deep,
    escape("deep-zoom", None, SPIRAL, "0.0000001", 1000, OLED, "fire"),
);

/// Perlin's textures and reaction–diffusion on the OLED, measured on every core.
///
/// Shown by the boards built with the scenes' `textures` feature (not the LM3S6965, whose
/// flash they would overflow). The reaction's grid is [`MAX_BOARD_REACTION_CELLS`] (32×32,
/// 4 KiB and a 384-byte ring on the stack), what the micro:bit's 16 KiB leaves.
///
/// [`MAX_BOARD_REACTION_CELLS`]: crate::MAX_BOARD_REACTION_CELLS
pub const TEXTURE_SCENES: [Entry; 4] = [
    noise("noise-fbm", Texture::Fbm, 0, OLED),
    // Clouds drifting: 3D noise, four frames.
    noise_flight("noise-flight", Texture::Clouds, 4, OLED),
    // The largest landscape a board holds (MAX_BOARD_MAP_CELLS).
    noise_terrain("noise-terrain", 3, 33, OLED),
    // 24×24: the naive f32 loop measured beside it keeps two grids of floats (9 KiB), all
    // the micro:bit has room for.
    reaction("reaction-mitosis", Preset::Mitosis, (24, 24), 700, OLED),
];

/// The lecture's dynamics on the OLED, measured on every core.
///
/// The Hénon and Lorenz attractors by density (counts a byte a pixel, 8 KiB on the stack),
/// the figure in Bézier curves, and a fountain of particles.
///
/// Shown by the boards built with the scenes' `dynamics` feature (not the LM3S6965, whose
/// flash they would overflow), and measured by the measuring firmware's second build with
/// the textures.
pub const DYNAMICS_SCENES: [Entry; 4] = [
    attractor("attractor-henon", Kind::Henon, 20_000, OLED),
    attractor("attractor-lorenz", Kind::Lorenz, 20_000, OLED),
    bezier("bezier-figure", &SMOOTH_FIGURE, OLED),
    // Two seconds of the fountain, a frame a tick, in a pool of MAX_BOARD_PARTICLES.
    Entry {
        name: "particles-fountain",
        scene: Scene::Particles {
            preset: ParticlePreset::Fountain,
            frames: 60,
        },
        size: OLED,
        palette: "",
    },
];

/// Views past `Deep`'s spacing, drawn by perturbation with the reference orbit on the stack
/// ([`MAX_BOARD_REFERENCE_POINTS`](crate::MAX_BOARD_REFERENCE_POINTS), 24 KiB).
///
/// On the boards with the RAM for it and measured on Cortex-M3 and M4, not on the micro:bit (16
/// KiB). A minibrot 2.5·10⁻²¹ across in a view 10⁻²⁰ wide.
#[rustfmt::skip]
pub const DEEP_SCENES: [Entry; 2] = [
    escape("perturbation-zoom", None, MINIBROT_78, "1e-20", 1000, OLED, "fire"),
    // The deep-zoom view by perturbation: its series and Q60 finish, against `Deep`.
    perturbed("deep-zoom-perturbed", DEEP_ZOOM),
];

/// A zoom drawn on every board and measured on every core.
///
/// 32 frames into the spiral at 1.05× a frame, in one frame of a byte a pixel (10 KiB on the
/// stack at 128×64), each frame taking the last one's lines within a pixel; beside it the same
/// frames with no tolerance (lines only at exactly the same points: in a zoom, nearly every
/// pixel is computed), what a zoom costs without reuse.
#[rustfmt::skip]
pub const ZOOM_SCENES: [Entry; 2] = [
    zoom("zoom", SPIRAL, "0.01", 200, (32, 100)),
    zoom("zoom-every-frame", SPIRAL, "0.01", 200, (32, 0)),
];

/// A zoom toward `centre` from `width`, `frames` frames at 1.05× (20/21) a frame, at a
/// tolerance of `tolerance_percent` % of a pixel, on the OLED.
const fn zoom(
    name: &'static str,
    centre: (&'static str, &'static str),
    width: &'static str,
    max_iterations: u32,
    (frames, tolerance_percent): (u32, u32),
) -> Entry {
    assert!(Coord::parse(centre.0).is_some() && Coord::parse(centre.1).is_some());
    assert!(Coord::parse(width).is_some());
    assert!(max_iterations <= 255);
    Entry {
        name,
        scene: Scene::Zoom {
            centre,
            width,
            max_iterations,
            frames,
            shrink: (20, 21),
            tolerance_percent,
            pilot: None,
        },
        size: OLED,
        palette: "fire",
    }
}

/// XaoS's autopilot from the whole set with `seed`, `frames` frames at 200 iterations on
/// the OLED, reusing lines within a pixel.
const fn pilot(name: &'static str, seed: u64, frames: u32) -> Entry {
    Entry {
        name,
        scene: Scene::Zoom {
            centre: MANDELBROT_CENTRE,
            width: "3.5",
            max_iterations: 200,
            frames,
            shrink: (20, 21),
            tolerance_percent: 100,
            pilot: Some(seed),
        },
        size: OLED,
        palette: "fire",
    }
}

/// The ILI9488's 480×320 panel.
const ILI9488: Size = Size::new(480, 320);

/// The 800×480 panels of the larger boards (RA8875, the STM32F746's and F769's).
const PANEL_800X480: Size = Size::new(800, 480);

/// The escape-time views at real boards' display sizes (320×240, 480×320, 800×480),
/// measured on Cortex-M0/M3/M4 beside the OLED's frames.
///
/// The full Mandelbrot view at 256 iterations and the Julia set k = −0.8 + 0.156i at 100.
#[rustfmt::skip]
pub const DISPLAY_SCENES: [Entry; 6] = [
    escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, GALLERY_SIZE, "classic"),
    escape("julia", JULIA_K, ("0", "0"), "3.2", 100, GALLERY_SIZE, "classic"),
    escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, ILI9488, "classic"),
    escape("julia", JULIA_K, ("0", "0"), "3.2", 100, ILI9488, "classic"),
    escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, PANEL_800X480, "classic"),
    escape("julia", JULIA_K, ("0", "0"), "3.2", 100, PANEL_800X480, "classic"),
];

/// Panels of fewer colours, and the escape-time features made for them.
///
/// The OLED's Mandelbrot on a one-bit SSD1306 of its size, dithered and (what dithering
/// adds to) each pixel to its nearest colour; the seahorse valley there
/// without and with distance estimation (its strands held together), and the full view
/// with it at the OLED's and a display's size (what the estimate costs); XaoS's autopilot
/// flying 48 frames.
///
/// Dithered by Bayer's 8×8 matrix; measured by the newer families' firmware (the
/// dithering target is a second copy of the escape-time engine, beyond the other build's
/// flash).
#[rustfmt::skip]
pub const PANEL_SCENES: [Entry; 8] = [
    one_bit("mandelbrot-1bit", escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 64, OLED, "classic")),
    one_bit_by("mandelbrot-1bit-nearest", escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 64, OLED, "classic"), Dither::None),
    one_bit("seahorse-1bit", SEAHORSE),
    one_bit("seahorse-distance-1bit", estimated("seahorse", SEAHORSE)),
    one_bit("mandelbrot-distance-1bit", estimated("mandelbrot", escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 64, OLED, "classic"))),
    one_bit("mandelbrot-1bit", escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, GALLERY_SIZE, "classic")),
    one_bit("mandelbrot-distance-1bit", estimated("mandelbrot", escape("mandelbrot", None, MANDELBROT_CENTRE, "3.5", 256, GALLERY_SIZE, "classic"))),
    pilot("autopilot", 1, 48),
];

/// The seahorse valley on the OLED, 1,000 iterations: strands thinner than its pixels.
const SEAHORSE: Entry = escape(
    "seahorse",
    None,
    ("-0.7435", "0.1314"),
    "0.01",
    1000,
    OLED,
    "classic",
);
