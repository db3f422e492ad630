//! Measuring firmware, five builds per core: runs every scene (and, where they apply, the
//! f32 and fixed-point baselines) into a checksum target and reports, over semihosting,
//! one line per scene: instructions, work, checksum and stack high-water mark. The build
//! with `--features newer` measures the newer families' scenes (noise, reaction–diffusion,
//! the attractors, Bézier curves, particles) and only them, the build with `--features
//! panels` the dithered panels', the build with `--features shapes` Sierpiński's shapes
//! and the walking figure with their baselines, the build with `--features terrain` the
//! terrains with theirs, the other build every other scene:
//! together they would overflow the micro:bit's 256 KiB of flash.
//!
//! Under QEMU with `-icount shift=0` each instruction is one virtual nanosecond. SysTick
//! runs from the core clock, so its ticks are proportional to instructions; the ratio is
//! calibrated against a loop of known length, and wrap-arounds are counted in its handler.
//! (DWT's cycle counter reads 0 in QEMU.)
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use core::sync::atomic::{AtomicU32, Ordering};

    use cortex_m::peripheral::{syst::SystClkSource, SYST};
    use cortex_m_rt::{entry, exception};
    use cortex_m_semihosting::{debug, hprintln};
    use embedded_graphics::prelude::Size;
    use panic_semihosting as _;
    #[cfg(feature = "newer")]
    use tinyfractal::attractor::Kind;
    #[cfg(feature = "newer")]
    use tinyfractal::noise::{Perlin, Texture};
    #[cfg(feature = "newer")]
    use tinyfractal::Real;
    use tinyfractal_scenes::measure::{baseline_f32, baseline_fixed20, BaselineView, Checksum};
    #[cfg(feature = "newer")]
    use tinyfractal_scenes::naive::{
        bezier_f32, bezier_fixed, fountain_f32, fountain_fixed, gray_scott_f32, gray_scott_fixed,
        henon_f32, henon_fixed, lorenz_f32, lorenz_fixed, noise_f32, noise_fixed,
    };
    #[cfg(feature = "shapes")]
    use tinyfractal_scenes::naive::{
        carpet_f32, carpet_fixed, figure_f32, figure_fixed, gasket_f32, gasket_fixed, sponge_f32,
        sponge_fixed,
    };
    #[cfg(measure_default)]
    use tinyfractal_scenes::naive::{fern_f32, fern_fixed, lsystem_f32, lsystem_fixed};
    #[cfg(feature = "terrain")]
    use tinyfractal_scenes::naive::{landscape_f32, landscape_fixed, terrain_f32, terrain_fixed};
    #[cfg(feature = "terrain")]
    use tinyfractal_scenes::SCENES;
    use tinyfractal_scenes::{Scene, Work, GREY};
    #[cfg(feature = "shapes")]
    use tinyfractal_scenes::{Shape, SCENES};
    #[cfg(measure_default)]
    use tinyfractal_scenes::{DISPLAY_SCENES, SCENES, ZOOM_SCENES};
    #[cfg(feature = "newer")]
    use tinyfractal_scenes::{DYNAMICS_SCENES, TEXTURE_SCENES};

    /// The loops measured beside a scene: the escape time's f32 and fixed-point ones, or
    /// a texture's naive f32 one.
    #[derive(Clone, Copy)]
    enum Baseline {
        Escape(BaselineView),
        /// The lecture's fern by the chaos game: the points.
        #[cfg(measure_default)]
        Fern(u32),
        /// A deterministic L-system: its system, its turn in degrees and (for the careful
        /// sketch) in divisions of the circle, order, and whether it grows up.
        #[cfg(measure_default)]
        LSystem(
            &'static tinyfractal_scenes::System,
            (f32, Option<u32>),
            u32,
            bool,
        ),
        /// fBm of Perlin's 2D noise: the permutation's seed, octaves, lattice cells across.
        #[cfg(feature = "newer")]
        Noise(u32, u32, f32),
        /// Gray–Scott: (f, k), the grid, the steps.
        #[cfg(feature = "newer")]
        Reaction((f32, f32), (usize, usize), u32),
        /// The Hénon map's or the Lorenz flow's points.
        #[cfg(feature = "newer")]
        Attractor(Kind, u32),
        /// A fountain's frames.
        #[cfg(feature = "newer")]
        Fountain(u32),
        /// Cubic curves of a 320×240 design.
        #[cfg(feature = "newer")]
        Bezier(&'static [[(i16, i16); 4]]),
        /// A midpoint-displacement profile (or, if the flag is set, a landscape):
        /// roughness, σ, seed; heights (along a side for a landscape).
        #[cfg(feature = "terrain")]
        Terrain((f32, f32, u32), usize, bool),
        /// Sierpiński's carpet (true) or gasket at an order.
        #[cfg(feature = "shapes")]
        Subdivision(bool, u32),
        /// The walking figure's frames.
        #[cfg(feature = "shapes")]
        Figure(u32),
        /// The Menger sponge at an order.
        #[cfg(feature = "shapes")]
        Sponge(u32),
        /// ABOP's monopodial tree at an order, its string expanded (where the RAM holds
        /// it: not the micro:bit's).
        #[cfg(all(measure_general, measure_default))]
        Tree(u32),
    }

    impl Baseline {
        /// The baseline of `scene`, if it has one: a texture's only for fBm with
        /// persistence ½ and lacunarity 2, what the naive loop computes.
        fn of(scene: &Scene) -> Option<Self> {
            #[cfg(feature = "newer")]
            let f32_of = |r: Real| r.to_f64() as f32;
            match *scene {
                #[cfg(feature = "newer")]
                Scene::Noise {
                    texture: Texture::Fbm,
                    octaves,
                    scale,
                    seed,
                } if octaves.persistence == Real::from_bits(1 << 31)
                    && octaves.lacunarity == Real::from_int(2) =>
                {
                    Some(Self::Noise(seed, octaves.octaves, f32_of(scale)))
                }
                #[cfg(feature = "newer")]
                Scene::Noise { .. } => None,
                #[cfg(feature = "newer")]
                Scene::Reaction {
                    preset,
                    grid,
                    steps,
                } => {
                    let model = preset.model();
                    let rates = (f32_of(model.feed), f32_of(model.kill));
                    Some(Self::Reaction(
                        rates,
                        (grid.0 as usize, grid.1 as usize),
                        steps,
                    ))
                }
                #[cfg(feature = "newer")]
                Scene::Bezier { curves } => Some(Self::Bezier(curves)),
                #[cfg(feature = "terrain")]
                Scene::Terrain {
                    displacement,
                    samples,
                    map,
                } => Some(Self::Terrain(
                    (
                        displacement.roughness.to_f64() as f32,
                        displacement.sigma.to_f64() as f32,
                        displacement.seed as u32,
                    ),
                    samples as usize,
                    map,
                )),
                #[cfg(feature = "newer")]
                Scene::Particles {
                    preset: tinyfractal::particles::Preset::Fountain,
                    frames,
                } => Some(Self::Fountain(frames)),
                #[cfg(feature = "newer")]
                Scene::Attractor {
                    kind: kind @ (Kind::Henon | Kind::Lorenz),
                    points,
                } => Some(Self::Attractor(kind, points as u32)),
                #[cfg(feature = "shapes")]
                Scene::Subdivision {
                    shape: shape @ (Shape::Carpet | Shape::Gasket),
                    order,
                } => Some(Self::Subdivision(shape == Shape::Carpet, order)),
                #[cfg(feature = "shapes")]
                Scene::Walk { frames } => Some(Self::Figure(frames)),
                #[cfg(feature = "shapes")]
                Scene::Subdivision {
                    shape: Shape::Cube(tinyfractal::subdivision::CubeVariant::Axes),
                    order,
                } => Some(Self::Sponge(order)),
                // A stochastic system's choices are the engine's own generator: no sketch
                // draws the same plant.
                #[cfg(measure_default)]
                Scene::LSystem {
                    system,
                    order,
                    orientation,
                } if system.alternatives.is_empty() => {
                    let degrees = tinyfractal_scenes::naive::turn_degrees(system.angle);
                    let divisions = tinyfractal_scenes::naive::turn_divisions(system.angle);
                    let up = orientation == tinyfractal::render::Orientation::Up;
                    Some(Self::LSystem(system, (degrees, divisions), order, up))
                }
                #[cfg(measure_default)]
                Scene::Ifs {
                    system: "fern",
                    points,
                    density: false,
                    ..
                } => Some(Self::Fern(points as u32)),
                _ => BaselineView::of(scene).map(Self::Escape),
            }
        }
    }

    /// Steps of t a curve's sketch takes (a common choice in Arduino sketches).
    #[cfg(feature = "newer")]
    const NAIVE_BEZIER_STEPS: u32 = 16;

    const RELOAD: u32 = 0x00FF_FFFF;
    /// Set at build time to measure one scene only, as `NAME` or `NAME:WIDTHxHEIGHT`,
    /// without its baselines (`boards/profile` uses it); every scene otherwise.
    const ONLY: Option<&str> = option_env!("TINYFRACTAL_MEASURE_ONLY");

    fn selected(name: &str, size: Size) -> bool {
        let Some(only) = ONLY else { return true };
        let (only_name, only_size) = only.split_once(':').unwrap_or((only, ""));
        let same_size = only_size
            .split_once('x')
            .is_none_or(|(w, h)| w.parse() == Ok(size.width) && h.parse() == Ok(size.height));
        only_name == name && same_size
    }

    static WRAPS: AtomicU32 = AtomicU32::new(0);

    #[exception]
    fn SysTick() {
        // Load and store only: thumbv6m has no atomic read-modify-write.
        WRAPS.store(WRAPS.load(Ordering::Relaxed) + 1, Ordering::Relaxed);
    }

    fn ticks() -> u64 {
        loop {
            let before = WRAPS.load(Ordering::Relaxed);
            let current = SYST::get_current();
            if WRAPS.load(Ordering::Relaxed) == before {
                return u64::from(before) * u64::from(RELOAD + 1) + u64::from(RELOAD - current);
            }
        }
    }

    /// Exactly 2 instructions per round (`subs`, `bne`).
    fn known_loop(rounds: u32) {
        // SAFETY: a counted loop on a scratch register.
        #[allow(unsafe_code)]
        unsafe {
            core::arch::asm!("1:", "subs {0}, #1", "bne 1b", inout(reg) rounds => _, options(nomem, nostack));
        }
    }

    extern "C" {
        static mut __sheap: u32;
        static _stack_start: u32;
    }

    const PAINT: u32 = 0xA5A5_A5A5;

    /// Paints the free stack below the current one; returns its lowest address.
    #[inline(never)]
    fn paint_stack() -> *mut u32 {
        // SAFETY: writes only between the end of static RAM and 256 bytes below the stack
        // pointer, memory nobody uses at this point.
        #[allow(unsafe_code)]
        unsafe {
            let bottom = core::ptr::addr_of_mut!(__sheap);
            let top = (cortex_m::register::msp::read() as *mut u32).wrapping_sub(64);
            let mut p = bottom;
            while p < top {
                p.write_volatile(PAINT);
                p = p.add(1);
            }
            bottom
        }
    }

    /// Bytes of stack used since `paint_stack`: from the first overwritten word to the top.
    fn stack_used(bottom: *mut u32) -> usize {
        // SAFETY: reads the painted region back.
        #[allow(unsafe_code)]
        unsafe {
            let top = core::ptr::addr_of!(_stack_start) as usize;
            let mut p = bottom;
            while (p as usize) < top && p.read_volatile() == PAINT {
                p = p.add(1);
            }
            top - p as usize
        }
    }

    struct Clock {
        /// Instructions per 2^20 ticks.
        scale: u64,
    }

    impl Clock {
        fn calibrate() -> Self {
            const ROUNDS: u32 = 1 << 20;
            let start = ticks();
            known_loop(ROUNDS);
            let elapsed = (ticks() - start).max(1);
            Clock {
                scale: ((2 * u64::from(ROUNDS)) << 20) / elapsed,
            }
        }

        fn measure(&self, f: impl FnOnce()) -> u64 {
            let start = ticks();
            f();
            ((ticks() - start) * self.scale) >> 20
        }
    }

    #[entry]
    fn main() -> ! {
        let mut core = cortex_m::Peripherals::take().unwrap();
        core.SYST.set_clock_source(SystClkSource::Core);
        core.SYST.set_reload(RELOAD);
        core.SYST.clear_current();
        core.SYST.enable_interrupt();
        core.SYST.enable_counter();
        // The counter starts at 0 and loads RELOAD on its first tick: wait for that, so
        // time only runs forward.
        while SYST::get_current() == 0 {}
        let clock = Clock::calibrate();
        hprintln!("measure calibration scale={}", clock.scale);
        // Every core's scenes, with the baselines where they apply: the newer families in
        // their own build, the rest in the other.
        #[cfg(feature = "newer")]
        let every_core = TEXTURE_SCENES.iter().chain(&DYNAMICS_SCENES);
        #[cfg(feature = "panels")]
        let every_core = tinyfractal_scenes::PANEL_SCENES.iter();
        #[cfg(feature = "shapes")]
        let every_core = SCENES.iter().filter(|entry| entry.scene.is_shape());
        #[cfg(feature = "terrain")]
        let every_core = SCENES.iter().filter(|entry| entry.scene.is_terrain());
        #[cfg(measure_default)]
        let every_core = SCENES
            .iter()
            .filter(|entry| !entry.scene.is_shape() && !entry.scene.is_terrain())
            .chain(&DISPLAY_SCENES)
            .chain(&ZOOM_SCENES);
        for entry in every_core {
            // The baseline's view (parsed from decimal text) only for a scene measured.
            if !selected(entry.name, entry.size) {
                continue;
            }
            let baseline = Baseline::of(&entry.scene);
            measure(&clock, (entry.name, entry.size), baseline, |target| {
                // The newer families' build reaches no other family's code.
                #[cfg(feature = "newer")]
                return entry
                    .scene
                    .draw_texture(target, &GREY)
                    .or_else(|| entry.scene.draw_dynamics(target, &GREY))
                    .unwrap_or(Ok(Work::Samples(0)));
                // The panels' build reaches only the panels' code.
                #[cfg(feature = "panels")]
                return entry
                    .scene
                    .draw_panel(target, &GREY)
                    .unwrap_or(Ok(Work::Samples(0)));
                // The shapes' build reaches only the shapes' code.
                #[cfg(feature = "shapes")]
                return entry
                    .scene
                    .draw_shape(target, &GREY)
                    .unwrap_or(Ok(Work::Segments(0)));
                // The terrains' build reaches only the terrains' code.
                #[cfg(feature = "terrain")]
                return entry
                    .scene
                    .draw_terrain(target, &GREY)
                    .unwrap_or(Ok(Work::Cells(0)));
                #[cfg(measure_default)]
                entry.scene.draw(target, &GREY)
            });
        }
        // The general engine's scenes, where the RAM holds them (not the micro:bit's).
        #[cfg(all(measure_general, measure_default))]
        for entry in tinyfractal_scenes::GENERAL_SCENES.iter() {
            // The parametric 3D tree beside its sketch (the sketch is of that tree only).
            let baseline = (entry.name == "monopodial-tree").then_some(Baseline::Tree(entry.order));
            measure(&clock, (entry.name, entry.size), baseline, |target| {
                entry.draw(target, &GREY)
            });
        }
        // Perturbation's views, where the RAM holds a reference orbit (not the micro:bit's).
        #[cfg(all(measure_general, measure_default))]
        for entry in tinyfractal_scenes::DEEP_SCENES.iter() {
            measure(&clock, (entry.name, entry.size), None, |target| {
                entry.scene.draw(target, &GREY)
            });
        }
        hprintln!("measure done");
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }

    /// Runs `draw` into a checksum of `size` (and the baselines of `view`, if any) and
    /// prints the record of scene `name`.
    fn measure<E>(
        clock: &Clock,
        (name, size): (&str, Size),
        baseline: Option<Baseline>,
        draw: impl FnOnce(&mut Checksum) -> Result<Work, E>,
    ) {
        if !selected(name, size) {
            return;
        }
        let bottom = paint_stack();
        let mut target = Checksum::of_size(size);
        let mut work = Work::Segments(0);
        let instructions = clock.measure(|| {
            work = draw(&mut target).unwrap_or(Work::Segments(0));
        });
        let stack = stack_used(bottom);
        let work = work.count();
        let (mut f32_cost, mut fixed_cost) = (None, None);
        // Each baseline's picture is kept (black_box), so the optimiser cannot drop a loop
        // whose picture nobody reads.
        let run = |loop_: &mut dyn FnMut(&mut Checksum)| {
            Some(clock.measure(|| {
                let mut baseline = Checksum::of_size(size);
                loop_(&mut baseline);
                core::hint::black_box(baseline.value);
            }))
        };
        match baseline.filter(|_| ONLY.is_none()) {
            Some(Baseline::Escape(view)) => {
                f32_cost = run(&mut |target| {
                    baseline_f32(view, target);
                });
                fixed_cost = run(&mut |target| {
                    baseline_fixed20(view, target);
                });
            }
            #[cfg(feature = "newer")]
            Some(Baseline::Noise(seed, octaves, scale)) => {
                let permutation = *Perlin::seeded(seed).permutation();
                f32_cost = run(&mut |target| {
                    noise_f32(&permutation, octaves, scale, target);
                });
                fixed_cost = run(&mut |target| {
                    noise_fixed(&permutation, octaves, scale, target);
                });
            }
            #[cfg(feature = "newer")]
            Some(Baseline::Reaction(rates, grid, steps)) => {
                f32_cost = run(&mut |target| {
                    gray_scott_f32(rates, grid, steps, target);
                });
                fixed_cost = run(&mut |target| {
                    gray_scott_fixed(rates, grid, steps, target);
                });
            }
            #[cfg(feature = "newer")]
            Some(Baseline::Attractor(kind, points)) => {
                f32_cost = run(&mut |target| {
                    if kind == Kind::Henon {
                        henon_f32(points, target);
                    } else {
                        lorenz_f32(points, target);
                    }
                });
                fixed_cost = run(&mut |target| {
                    if kind == Kind::Henon {
                        henon_fixed(points, target);
                    } else {
                        lorenz_fixed(points, target);
                    }
                });
            }
            #[cfg(feature = "newer")]
            Some(Baseline::Fountain(frames)) => {
                f32_cost = run(&mut |target| {
                    fountain_f32(frames, target);
                });
                fixed_cost = run(&mut |target| {
                    fountain_fixed(frames, target);
                });
            }
            #[cfg(feature = "newer")]
            Some(Baseline::Bezier(curves)) => {
                f32_cost = run(&mut |target| {
                    let area = embedded_graphics::geometry::Dimensions::bounding_box(target);
                    let place = tinyfractal_scenes::design_placement(area);
                    bezier_f32(curves, place, NAIVE_BEZIER_STEPS, target);
                });
                fixed_cost = run(&mut |target| {
                    let area = embedded_graphics::geometry::Dimensions::bounding_box(target);
                    let place = tinyfractal_scenes::design_placement(area);
                    bezier_fixed(curves, place, NAIVE_BEZIER_STEPS, target);
                });
            }
            #[cfg(feature = "terrain")]
            Some(Baseline::Terrain(displacement, samples, map)) => {
                f32_cost = run(&mut |target| {
                    if map {
                        landscape_f32(displacement, samples, target);
                    } else {
                        terrain_f32(displacement, samples, target);
                    }
                });
                fixed_cost = run(&mut |target| {
                    if map {
                        landscape_fixed(displacement, samples, target);
                    } else {
                        terrain_fixed(displacement, samples, target);
                    }
                });
            }
            #[cfg(feature = "shapes")]
            Some(Baseline::Subdivision(carpet, order)) => {
                f32_cost = run(&mut |target| {
                    if carpet {
                        carpet_f32(order, target);
                    } else {
                        gasket_f32(order, target);
                    }
                });
                fixed_cost = run(&mut |target| {
                    if carpet {
                        carpet_fixed(order, target);
                    } else {
                        gasket_fixed(order, target);
                    }
                });
            }
            #[cfg(feature = "shapes")]
            Some(Baseline::Sponge(order)) => {
                f32_cost = run(&mut |target| {
                    sponge_f32(order, target);
                });
                fixed_cost = run(&mut |target| {
                    sponge_fixed(order, target);
                });
            }
            #[cfg(feature = "shapes")]
            Some(Baseline::Figure(frames)) => {
                f32_cost = run(&mut |target| {
                    figure_f32(frames, target);
                });
                fixed_cost = run(&mut |target| {
                    figure_fixed(frames, target);
                });
            }
            #[cfg(measure_default)]
            Some(Baseline::LSystem(system, (degrees, divisions), order, up)) => {
                let rules = (system.axiom, system.rules, system.draw_symbols);
                f32_cost = run(&mut |target| {
                    lsystem_f32(rules, degrees, order, up, target);
                });
                if let Some(divisions) = divisions {
                    fixed_cost = run(&mut |target| {
                        lsystem_fixed(rules, divisions, order, up, target);
                    });
                }
            }
            #[cfg(measure_default)]
            Some(Baseline::Fern(points)) => {
                f32_cost = run(&mut |target| {
                    fern_f32(points, target);
                });
                fixed_cost = run(&mut |target| {
                    fern_fixed(points, target);
                });
            }
            #[cfg(all(measure_general, measure_default))]
            Some(Baseline::Tree(order)) => {
                f32_cost = run(&mut |target| {
                    tinyfractal_scenes::naive::monopodial_tree_f32(order, target);
                });
                fixed_cost = run(&mut |target| {
                    tinyfractal_scenes::naive::monopodial_tree_fixed(order, target);
                });
            }
            None => {}
        }
        hprintln!(
            "measure scene={} size={}x{} instructions={} work={} checksum={} pixels={} stack={} baseline_f32={} baseline_fixed20={}",
            name,
            size.width,
            size.height,
            instructions,
            work,
            target.value,
            target.pixels,
            stack,
            Optional(f32_cost),
            Optional(fixed_cost)
        );
    }

    struct Optional(Option<u64>);

    impl core::fmt::Display for Optional {
        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            match self.0 {
                Some(value) => write!(f, "{value}"),
                None => f.write_str("null"),
            }
        }
    }
}

/// On the host there is nothing to run: the firmware is built for the Cortex-M targets.
#[cfg(not(target_os = "none"))]
fn main() {}
