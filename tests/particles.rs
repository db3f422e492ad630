//! Particle systems: a particle's flight against the closed-form parabola, the pool's
//! bound and its replacement rule, the seed's frames, the ground, and frames that erase
//! exactly what they drew.

use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
use tinyfractal::particles::{
    Emitter, Forces, Frames, Ground, ParticleLook, ParticleSystem, Preset, Schedule, Shape,
    PARTICLE_BITS,
};
use tinyfractal::render::TwoColor;

const ONE: f64 = (1u32 << PARTICLE_BITS) as f64;

/// One particle thrown from `start` at `degrees` and `speed` pixels a tick, under `forces`.
fn one(start: (f64, f64), degrees: f64, speed: f64, forces: Forces) -> ParticleSystem<4> {
    let fixed = |v: f64| (v * ONE).round() as i32;
    let mut emitter = Emitter::new(
        Shape::Point(fixed(start.0), fixed(start.1)),
        Schedule::Bursts {
            count: 1,
            first: 0,
            every: 0,
        },
    );
    emitter.direction = (degrees / 360.0 * 4_294_967_296.0) as u32;
    emitter.speed = fixed(speed);
    emitter.life = 1000;
    ParticleSystem::new(emitter, forces, 1)
}

/// Without drag a particle flies the parabola x = x₀ + v·cos θ·t, y = y₀ − v·sin θ·t +
/// a·t²/2 (screen y down), t in ticks: exactly in its fixed point (the position takes
/// v + a/2 a tick), within the rounding of its first velocity against the f64 model.
#[test]
fn a_particle_flies_the_parabola() {
    let a = 0.125;
    let forces = Forces {
        ay: (a * ONE) as i32,
        ..Forces::default()
    };
    let (x0, y0, theta, v) = (10.0, 200.0, 60.0f64, 3.0);
    let mut system = one((x0, y0), theta, v, forces);
    system.step(1); // emitted, and its first tick
    let first = *system.live().next().unwrap();
    for t in 1..=120u32 {
        let p = *system.live().next().unwrap();
        let t = f64::from(t);
        let (model_x, model_y) = (
            x0 + v * theta.to_radians().cos() * t,
            y0 - v * theta.to_radians().sin() * t + a * t * t / 2.0,
        );
        // The first velocity is the table's cosine and sine (within 3·10⁻⁷) rounded to
        // 2⁻¹⁶: at most 2⁻¹⁵ a tick.
        let slack = t * (1.0 / 32_768.0);
        assert!(
            (f64::from(p.x) / ONE - model_x).abs() <= slack,
            "t = {t}: x {}",
            f64::from(p.x) / ONE
        );
        assert!(
            (f64::from(p.y) / ONE - model_y).abs() <= slack,
            "t = {t}: y {}",
            f64::from(p.y) / ONE
        );
        // In its own fixed point the parabola is exact: integers all the way.
        let (vx, vy) = (
            i64::from(first.vx),
            i64::from(first.vy) - i64::from(forces.ay),
        );
        let ticks = t as i64;
        let x0_fixed = i64::from(first.x) - vx;
        let y0_fixed = i64::from(first.y) - vy - i64::from(forces.ay / 2);
        assert_eq!(i64::from(p.x), x0_fixed + ticks * vx);
        assert_eq!(
            i64::from(p.y),
            y0_fixed + ticks * vy + i64::from(forces.ay) * ticks * ticks / 2
        );
        system.step(1);
    }
}

#[test]
fn the_pool_never_holds_more_than_its_capacity() {
    let mut fountain = Preset::Fountain.system::<16>(Size::new(128, 64), 3);
    for _ in 0..300 {
        fountain.step(1);
        assert!(fountain.live().count() <= 16);
    }
    // 120 a second, lives of about two seconds: the pool was full, and replaced.
    assert!(fountain.replaced() > 0);
    assert_eq!(fountain.live().count(), 16);
}

/// A full pool gives the next particle the oldest one's slot.
#[test]
fn a_full_pool_replaces_the_oldest() {
    let mut emitter = Emitter::new(
        Shape::Point(0, 0),
        Schedule::Bursts {
            count: 3,
            first: 0,
            every: 5,
        },
    );
    emitter.life = 100;
    let mut system: ParticleSystem<4> = ParticleSystem::new(emitter, Forces::default(), 9);
    system.step(5); // three born at tick 0, aged 5
    system.step(1); // three more: one free slot, then the two oldest (slots 0 and 1)
    let ages: Vec<u16> = system.particles().iter().map(|p| p.age).collect();
    assert_eq!(ages, vec![1, 1, 6, 1]);
    assert_eq!(system.replaced(), 2);
}

#[test]
fn the_same_seed_gives_the_same_frames() {
    for preset in Preset::ALL {
        let run = |seed| {
            let mut system = preset.system::<64>(Size::new(128, 64), seed);
            let mut frames = Vec::new();
            for _ in 0..40 {
                system.step(1);
                frames.push(*system.particles());
            }
            frames
        };
        assert_eq!(run(5), run(5), "{}", preset.name());
        assert_ne!(run(5), run(6), "{}", preset.name());
    }
}

#[test]
fn the_ground_bounces_or_holds() {
    let ground = 50.0 * ONE;
    let falling = |what| Forces {
        ay: (0.25 * ONE) as i32,
        ground: Some((ground as i32, what)),
        ..Forces::default()
    };
    let mut bouncing = one((10.0, 40.0), -90.0, 1.0, falling(Ground::Bounce(1 << 15)));
    let mut resting = one((10.0, 40.0), -90.0, 1.0, falling(Ground::Rest));
    let mut bounced = false;
    for _ in 0..60 {
        bouncing.step(1);
        resting.step(1);
        let (b, r) = (
            *bouncing.live().next().unwrap(),
            *resting.live().next().unwrap(),
        );
        assert!(f64::from(b.y) <= ground && f64::from(r.y) <= ground);
        bounced |= b.vy < 0 && b.y < ground as i32;
    }
    assert!(bounced, "it came back up");
    let r = *resting.live().next().unwrap();
    assert_eq!((r.y, r.vx, r.vy), (ground as i32, 0, 0));
}

/// Each frame erases what the last drew and draws the live particles: the display shows
/// exactly what a fresh drawing of this frame alone shows.
#[test]
fn frames_erase_exactly_what_they_drew() {
    let look = ParticleLook {
        palette: TwoColor {
            inside: BinaryColor::On,
            outside: BinaryColor::On,
        },
        size_at_birth: 2,
        size_at_death: 1,
    };
    for preset in Preset::ALL {
        let mut system = preset.system::<48>(Size::new(64, 64), 11);
        let mut display = MockDisplay::<BinaryColor>::new();
        display.set_allow_overdraw(true);
        display.set_allow_out_of_bounds_drawing(true);
        let mut frames = Frames::new();
        for tick in 0..90 {
            system.step(1);
            frames
                .draw(&system, &look, BinaryColor::Off, &mut display)
                .unwrap();
            let mut fresh = MockDisplay::<BinaryColor>::new();
            fresh.set_allow_overdraw(true);
            fresh.set_allow_out_of_bounds_drawing(true);
            Frames::new()
                .draw(&system, &look, BinaryColor::Off, &mut fresh)
                .unwrap();
            let lit = |d: &MockDisplay<BinaryColor>| {
                d.bounding_box()
                    .points()
                    .filter(|&p| d.get_pixel(p) == Some(BinaryColor::On))
                    .collect::<Vec<_>>()
            };
            assert_eq!(
                lit(&display),
                lit(&fresh),
                "{} at tick {tick}",
                preset.name()
            );
        }
    }
}
