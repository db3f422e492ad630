//! Midpoint-displacement terrain as a careful fixed-point sketch makes and draws it.
//!
//! Heights in Q16.16; a normal deviate as the sum of four of C's `rand` values, centred
//! and scaled (Irwin and Hall's approximation, no logarithm or root); the fit's divisions
//! done once, as reciprocals.

use embedded_graphics::{pixelcolor::Gray4, prelude::*};

use embedded_graphics::primitives::Rectangle;

use super::shared::{c_rand, mul_q16, q16, NAIVE_LANDSCAPE_SIDE, NAIVE_PROFILE};

/// A normal deviate in Q16: four `rand` values summed, centred and scaled to σ = 1 (their
/// sum's σ is 32,768/√3 of `rand`'s units).
fn normal_q16(state: &mut u32) -> i32 {
    let sum: i64 = (0..4).map(|_| i64::from(c_rand(state))).sum();
    // (sum − 65,534)·√3/32,768 in Q16 is (2·sum − 131,068)·√3 in Q16 >> 16.
    (((2 * sum - 131_068) * 113_512) >> 16) as i32
}

/// A mountain profile as a careful sketch makes it, in Q16.16.
///
/// [`terrain_f32`]'s midpoint displacement and drawing with Irwin and Hall's deviates;
/// each column's height scaled by a reciprocal found once, its sky and ground each one
/// `fill_solid` of the target (a careful user's way to a filled rectangle). Returns the heights made, or 0
/// for more than [`NAIVE_PROFILE`].
///
/// [`terrain_f32`]: super::terrain_f32
pub fn terrain_fixed<D: DrawTarget<Color = Gray4>>(
    (roughness, sigma, seed): (f32, f32, u32),
    samples: usize,
    target: &mut D,
) -> u64 {
    if !(2..=NAIVE_PROFILE).contains(&samples) {
        return 0;
    }
    let roughness = q16(roughness);
    let mut heights = [0i32; NAIVE_PROFILE];
    let mut state = seed;
    let mut step = samples - 1;
    let mut scale = q16(sigma);
    while step > 1 {
        let half = step / 2;
        let mut left = 0;
        while left + step < samples {
            let normal = normal_q16(&mut state);
            heights[left + half] =
                ((heights[left] + heights[left + step]) >> 1) + mul_q16(normal, scale);
            left += step;
        }
        step = half;
        scale = mul_q16(scale, roughness);
    }
    let (low, high) = heights[..samples]
        .iter()
        .fold((i32::MAX, i32::MIN), |(l, h), &v| (l.min(v), h.max(v)));
    let size = target.bounding_box().size;
    let (w, h) = (size.width as i32, size.height as i32);
    // Pixels a height unit in Q32: (h − 1)/(high − low).
    let per_unit = (i64::from(h - 1) << 32) / i64::from((high - low).max(1));
    for x in 0..w {
        let sample = heights[x as usize * (samples - 1) / (w.max(2) - 1) as usize];
        let ground = ((i64::from(sample - low) * per_unit) >> 32) as i32 + 1;
        let column = |top: i32, height: i32| {
            Rectangle::new(Point::new(x, top), Size::new(1, height.max(0) as u32))
        };
        let _ = target.fill_solid(&column(0, h - ground), Gray4::BLACK);
        let _ = target.fill_solid(&column(h - ground, ground), Gray4::WHITE);
    }
    samples as u64
}

/// A landscape as a careful sketch makes and draws it, in Q16.16.
///
/// [`landscape_f32`]'s diamond-square and shading with Irwin and Hall's deviates; returns
/// the heights made (0 for a side other than 2ᵏ + 1 up to [`NAIVE_LANDSCAPE_SIDE`]). Each
/// pixel's grid position is stepped along its row (no division a pixel), the bands'
/// starts are heights found once, and the slope's scale a reciprocal found once.
///
/// [`landscape_f32`]: super::landscape_f32
pub fn landscape_fixed<D: DrawTarget<Color = Gray4>>(
    (roughness, sigma, seed): (f32, f32, u32),
    side: usize,
    target: &mut D,
) -> u64 {
    if !(3..=NAIVE_LANDSCAPE_SIDE).contains(&side) || !(side - 1).is_power_of_two() {
        return 0;
    }
    let roughness = q16(roughness);
    let mut heights = [0i32; NAIVE_LANDSCAPE_SIDE * NAIVE_LANDSCAPE_SIDE];
    let mut state = seed;
    let at = |x: usize, y: usize| y * side + x;
    let (mut step, mut scale) = (side - 1, q16(sigma));
    while step > 1 {
        let half = step / 2;
        // Diamonds: each square's centre from its four corners.
        for y in (half..side).step_by(step) {
            for x in (half..side).step_by(step) {
                let sum = heights[at(x - half, y - half)]
                    + heights[at(x + half, y - half)]
                    + heights[at(x - half, y + half)]
                    + heights[at(x + half, y + half)];
                heights[at(x, y)] = (sum >> 2) + mul_q16(normal_q16(&mut state), scale);
            }
        }
        // Squares: each edge midpoint from its neighbours inside the grid.
        for y in (0..side).step_by(half) {
            let first = if (y / half) % 2 == 0 { half } else { 0 };
            for x in (first..side).step_by(step) {
                let (mut sum, mut count) = (0, 0);
                for (dx, dy) in [(-1i32, 0i32), (1, 0), (0, -1), (0, 1)] {
                    let (nx, ny) = (x as i32 + dx * half as i32, y as i32 + dy * half as i32);
                    if (0..side as i32).contains(&nx) && (0..side as i32).contains(&ny) {
                        sum += heights[at(nx as usize, ny as usize)];
                        count += 1;
                    }
                }
                let mean = if count == 4 { sum >> 2 } else { sum / count };
                heights[at(x, y)] = mean + mul_q16(normal_q16(&mut state), scale);
            }
        }
        step = half;
        scale = mul_q16(scale, roughness);
    }
    relief_fixed(&heights[..side * side], side, target);
    (side * side) as u64
}

/// A grid of Q16.16 heights drawn from above as [`relief_f32`] draws it, in fixed point.
///
/// [`relief_f32`]: super::relief_f32
fn relief_fixed<D: DrawTarget<Color = Gray4>>(heights: &[i32], side: usize, target: &mut D) {
    /// Each band's start (a share of the range, Q16) and grey (Q16).
    const BANDS: [(i32, i32); 6] = [
        (0, q16(0.2)),
        (q16(80.0 / 255.0), q16(0.4)),
        (q16(100.0 / 255.0), q16(0.75)),
        (q16(110.0 / 255.0), q16(0.5)),
        (q16(180.0 / 255.0), q16(0.45)),
        (q16(225.0 / 255.0), q16(0.95)),
    ];
    let (low, high) = heights
        .iter()
        .fold((i32::MAX, i32::MIN), |(l, h), &v| (l.min(v), h.max(v)));
    let spread = (high - low).max(1);
    // The bands' starts as heights, and the land's (where shading begins).
    let starts = BANDS.map(|(start, _)| low + mul_q16(spread, start));
    let land = starts[2];
    let size = target.bounding_box().size;
    let last = side as i32 - 1;
    // The slope in Q16 is the difference times (side − 1)/spread: that in Q32.
    let per_spread = (i64::from(last) << 32) / i64::from(spread);
    // Grid units a pixel in Q16, each axis.
    let step_x = (last << 16) / (size.width.max(2) as i32 - 1);
    let step_y = (last << 16) / (size.height.max(2) as i32 - 1);
    let height = |x: usize, y: usize| heights[y.min(side - 1) * side + x.min(side - 1)];
    let mut gy = 0;
    for py in 0..size.height {
        let (y, fy) = ((gy >> 16) as usize, gy & 0xFFFF);
        let mut gx = 0;
        for px in 0..size.width {
            let (x, fx) = ((gx >> 16) as usize, gx & 0xFFFF);
            let top = height(x, y) + mul_q16(height(x + 1, y) - height(x, y), fx);
            let bottom = height(x, y + 1) + mul_q16(height(x + 1, y + 1) - height(x, y + 1), fx);
            let value = top + mul_q16(bottom - top, fy);
            let band = starts.iter().rposition(|&start| value >= start);
            let mut grey = band.map_or(0, |band| BANDS[band].1);
            if value >= land {
                let difference =
                    height(x.saturating_sub(1), y.saturating_sub(1)) - height(x + 1, y + 1);
                let slope = ((i64::from(difference) * per_spread) >> 16) as i32;
                let light = (65_536 - slope / 8).clamp(q16(0.5), q16(1.4));
                grey = mul_q16(grey, light);
            }
            let level = ((grey.clamp(0, 65_536) * 15 + 32_768) >> 16) as u8;
            let _ = target.draw_iter(core::iter::once(Pixel(
                Point::new(px as i32, py as i32),
                Gray4::new(level),
            )));
            gx += step_x;
        }
        gy += step_y;
    }
}
