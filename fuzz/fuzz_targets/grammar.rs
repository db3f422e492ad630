//! Grammars built through the API from arbitrary axioms, rules and angles, in both
//! dialects, drawn at small orders into a strict target.

#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use tinyfractal::{Angle, Dialect, Grammar};
use tinyfractal_fuzz::draw_plain;

#[derive(Debug, Arbitrary)]
struct Input<'a> {
    fractint: bool,
    axiom: &'a str,
    angle: &'a str,
    draw_symbols: &'a str,
    rules: Vec<(char, &'a str)>,
    seed: u32,
    order: u8,
}

fuzz_target!(|input: Input<'_>| {
    let dialect = if input.fractint {
        Dialect::Fractint
    } else {
        Dialect::Abop
    };
    let Some(angle) = Angle::parse_degrees(input.angle) else {
        return;
    };
    let Ok(mut grammar) = Grammar::new(dialect, input.axiom, angle) else {
        return;
    };
    if grammar.add_draw_symbols(input.draw_symbols).is_err() {
        return;
    }
    for &(symbol, body) in input.rules.iter().take(16) {
        let _ = grammar.add_rule(symbol, body);
    }
    grammar.set_seed(input.seed);
    draw_plain(&grammar, u32::from(input.order % 8));
});
