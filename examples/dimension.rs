//! Estimates the box-counting dimension of the Koch curve and the Sierpiński carpet by
//! drawing them into a `BoxCounter` instead of a display.
//!
//! `cargo run --example dimension`

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
use tinyfractal::{Angle, BoxCounter, Carpet, Dialect, Grammar, LSystem};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let size = Size::new(729, 729);
    let mut bits = vec![0u32; BoxCounter::<BinaryColor>::words_needed(size, 0)];

    let mut counter = BoxCounter::new(size, 0, BinaryColor::Off, &mut bits)?;
    let koch = Grammar::new(Dialect::Abop, "F", Angle::Divisions(6))?.with_rule('F', "F+F--F+F")?;
    LSystem::new(&koch, 6)
        .fit(counter.bounding_box(), &[BinaryColor::On])?
        .draw(&mut counter)?;
    let estimate = counter.dimension()?;
    println!(
        "Koch curve: {:.3} (theory {:.3})",
        estimate.value.to_f64(),
        4f64.ln() / 3f64.ln()
    );

    bits.fill(0);
    let mut counter = BoxCounter::new(size, 0, BinaryColor::Off, &mut bits)?;
    Carpet::new(6)
        .fit(counter.bounding_box(), BinaryColor::On, BinaryColor::Off)?
        .draw(&mut counter)?;
    let estimate = counter.dimension()?;
    println!(
        "Sierpiński carpet: {:.3} (theory {:.3})",
        estimate.value.to_f64(),
        8f64.ln() / 3f64.ln()
    );
    Ok(())
}
