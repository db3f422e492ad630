//! The naive escape-time loop a user writes on an FPU: `f32`, separate multiply and add
//! (as on the Cortex-M4F), for the tests and the tier calibration.

/// The dwell of the point `p` in `f32`: the smallest n ≥ 1 with |zₙ|² > 4, capped at `max`.
/// For a Julia set (`julia: Some(k)`) z₀ = p and c = k; for the Mandelbrot set z₀ = 0 and
/// c = p.
pub fn f32_dwell(julia: Option<(f32, f32)>, p: (f32, f32), max: u32) -> u32 {
    let (c, mut z) = match julia {
        None => (p, (0.0f32, 0.0f32)),
        Some(k) => (k, p),
    };
    for n in 1..=max {
        let (x2, y2) = (z.0 * z.0, z.1 * z.1);
        z = (x2 - y2 + c.0, 2.0 * z.0 * z.1 + c.1);
        if z.0 * z.0 + z.1 * z.1 > 4.0 {
            return n;
        }
    }
    max
}
