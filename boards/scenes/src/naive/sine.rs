//! The careful sketches' sine: a quarter wave of 256 steps in Q16, read by binary angle.
//!
//! A fixed-point sketch keeps its angles as binary angles (2³² a turn, so a turn wraps by
//! itself) and reads its sines from a table, interpolating between neighbours; the table
//! is made at compile time from a Taylor series in `f64`, as a sketch pastes one in.

/// A binary angle: 2³² a turn.
pub(super) type Turns = u32;

/// A quarter turn in binary angle.
const QUARTER: u32 = 1 << 30;

/// sin(kπ/512) in Q16 for k = 0 to 256.
const TABLE: [i32; 257] = {
    let mut table = [0; 257];
    let mut k = 0;
    while k < 257 {
        let x = k as f64 * core::f64::consts::PI / 512.0;
        // Taylor's series to x¹⁷: within 10⁻¹² on [0, π/2].
        let (mut term, mut sum, mut n) = (x, x, 1);
        while n < 9 {
            term = -term * x * x / ((2 * n) as f64 * (2 * n + 1) as f64);
            sum += term;
            n += 1;
        }
        table[k] = (sum * 65536.0 + 0.5) as i32;
        k += 1;
    }
    table
};

/// The sine of `angle` in Q16, interpolated between the table's neighbours.
pub(super) fn sin_q16(angle: Turns) -> i32 {
    let within = angle & (QUARTER - 1);
    // The second and fourth quarters read the first backwards.
    let within = if angle & QUARTER == 0 {
        within
    } else {
        QUARTER - within
    };
    let index = (within >> 22) as usize;
    let fraction = ((within >> 6) & 0xFFFF) as i32;
    let low = TABLE[index];
    let high = TABLE[(index + 1).min(256)];
    let value = low + (((high - low) * fraction) >> 16);
    if angle & (2 * QUARTER) == 0 {
        value
    } else {
        -value
    }
}

/// The cosine of `angle` in Q16.
pub(super) fn cos_q16(angle: Turns) -> i32 {
    sin_q16(angle.wrapping_add(QUARTER))
}

/// The binary angle of `degrees` in Q16.16, rounded.
pub(super) fn turns_of_degrees(degrees: i32) -> Turns {
    // A Q16 degree is 2¹⁶/360 binary units: 2⁴⁰/360 in Q24.
    ((i64::from(degrees) * 3_054_198_966 + (1 << 23)) >> 24) as Turns
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_reads_the_sine_within_a_q16_unit() {
        for step in 0..4096u32 {
            let angle = step.wrapping_mul(1_048_573);
            let radians = f64::from(angle) * core::f64::consts::TAU / 4_294_967_296.0;
            let (sin, cos) = (sin_q16(angle), cos_q16(angle));
            assert!((f64::from(sin) / 65536.0 - radians.sin()).abs() < 2.0 / 65536.0);
            assert!((f64::from(cos) / 65536.0 - radians.cos()).abs() < 2.0 / 65536.0);
        }
        assert_eq!(turns_of_degrees(90 << 16), 1 << 30);
        assert_eq!(turns_of_degrees(-90 << 16), 3 << 30);
    }
}
