//! Estimates the box-counting dimension of the Koch curve and the Sierpiński carpet by
//! drawing them into a `BoxCounter` instead of a display.
//!
//! `cargo run --example dimension`

use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
use tinyfractal::dimension::Dimension;
use tinyfractal::{Angle, BoxCounter, Carpet, Dialect, Error, Grammar, LSystem};

/// The picture both fractals are drawn at: 3⁶ pixels a side.
const SIZE: Size = Size::new(729, 729);

/// The dimension of what `draw` draws into a counter of [`SIZE`].
fn estimate(
    draw: impl FnOnce(&mut BoxCounter<'_, BinaryColor>) -> Result<(), Error>,
) -> Result<Dimension, Error> {
    let mut bits = vec![0u32; BoxCounter::<BinaryColor>::words_needed(SIZE, 0)];
    let mut counter = BoxCounter::new(SIZE, 0, BinaryColor::Off, &mut bits)?;
    draw(&mut counter)?;
    counter.dimension()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let koch = Grammar::new(Dialect::Abop, "F", Angle::Divisions(6))?.with_rule('F', "F+F--F+F")?;
    let curve = estimate(|counter| {
        let area = counter.bounding_box();
        let Ok(_) = LSystem::new(&koch, 6)
            .fit(area, &[BinaryColor::On])?
            .draw(counter);
        Ok(())
    })?;
    let carpet = estimate(|counter| {
        let area = counter.bounding_box();
        let Ok(_) = Carpet::new(6)
            .fit(area, BinaryColor::On, BinaryColor::Off)?
            .draw(counter);
        Ok(())
    })?;
    for (name, estimate, theory) in [
        ("Koch curve", curve, 4f64.ln() / 3f64.ln()),
        ("Sierpiński carpet", carpet, 8f64.ln() / 3f64.ln()),
    ] {
        println!(
            "{name}: {:.3} (theory {theory:.3})",
            estimate.value.to_f64()
        );
    }
    Ok(())
}
