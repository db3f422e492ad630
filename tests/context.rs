//! Context-sensitive systems (ABOP 1.8) derived without a string, against an independent
//! model that rewrites whole strings level by level, as the book defines it.

use proptest::prelude::*;
use tinyfractal::{error::ReadError, lsystem::ParametricWalker, Error, LsysFile};

/// The derived string of the system in `text` (one `.lsys` entry) at `order`.
fn derive(text: &str, order: u32) -> Result<String, Error> {
    let file = LsysFile::new(text);
    let grammar = file.entries().next().expect("one entry")?.parametric()?;
    ParametricWalker::<40>::new(&grammar, order)?
        .with_budget(50_000_000)
        .map(|module| module.map(|m| m.to_string()))
        .collect()
}

/// `lc < pred > rc --> successor`, single symbols, for the model.
#[derive(Debug, Clone)]
struct Rule {
    left: Option<char>,
    predecessor: char,
    right: Option<char>,
    successor: String,
}

/// The left context of `s[i]` as ABOP defines it: back over ignored symbols and whole
/// branches; a branch's first symbol sees the one before its `[`.
fn left_of(s: &[char], i: usize, ignore: &str) -> Option<char> {
    let mut depth = 0;
    for &c in s[..i].iter().rev() {
        match c {
            ']' => depth += 1,
            '[' => depth = (depth - 1).max(0),
            _ if depth > 0 || ignore.contains(c) => {}
            c => return Some(c),
        }
    }
    None
}

/// The right context: on over ignored symbols and whole branches, none past the `]` of
/// the symbol's own branch.
fn right_of(s: &[char], i: usize, ignore: &str) -> Option<char> {
    let mut depth = 0;
    for &c in &s[i + 1..] {
        match c {
            '[' => depth += 1,
            ']' if depth == 0 => return None,
            ']' => depth -= 1,
            _ if depth > 0 || ignore.contains(c) => {}
            c => return Some(c),
        }
    }
    None
}

/// One derivation step of the whole string: each symbol by the first rule that applies.
fn rewrite(s: &[char], rules: &[Rule], ignore: &str) -> Vec<char> {
    let mut next = Vec::new();
    for (i, &c) in s.iter().enumerate() {
        let applies = |rule: &&Rule| {
            rule.predecessor == c
                && rule.left.is_none_or(|l| left_of(s, i, ignore) == Some(l))
                && rule.right.is_none_or(|r| right_of(s, i, ignore) == Some(r))
        };
        match rules.iter().find(applies) {
            Some(rule) if !"[]".contains(c) => next.extend(rule.successor.chars()),
            _ => next.push(c),
        }
    }
    next
}

fn model(axiom: &str, rules: &[Rule], ignore: &str, order: u32) -> String {
    let mut s: Vec<char> = axiom.chars().collect();
    for _ in 0..order {
        s = rewrite(&s, rules, ignore);
    }
    s.into_iter().collect()
}

fn lsys(axiom: &str, rules: &[Rule], ignore: &str) -> String {
    let mut text = format!("s {{\n  axiom: {axiom}\n  angle: 90\n");
    if !ignore.is_empty() {
        text += &format!("  ignore: {ignore}\n");
    }
    for rule in rules {
        text += "  ";
        if let Some(l) = rule.left {
            text += &format!("{l} < ");
        }
        text.push(rule.predecessor);
        if let Some(r) = rule.right {
            text += &format!(" > {r}");
        }
        text += &format!(" --> {}\n", rule.successor);
    }
    text + "}\n"
}

fn rule(text: &str) -> Rule {
    let (left_side, successor) = text.split_once("-->").unwrap();
    let (left, rest) = match left_side.split_once('<') {
        Some((l, rest)) => (l.trim().chars().next(), rest),
        None => (None, left_side),
    };
    let (predecessor, right) = match rest.split_once('>') {
        Some((p, r)) => (p, r.trim().chars().next()),
        None => (rest, None),
    };
    Rule {
        left,
        predecessor: predecessor.trim().chars().next().unwrap(),
        right,
        successor: successor.trim().to_string(),
    }
}

/// ABOP p. 30: a signal travels along the string, one symbol a step.
#[test]
fn signal_propagation_from_the_book() {
    let text = "s {\n  axiom: baaaaaaaa\n  angle: 90\n  b < a --> b\n  b --> a\n}\n";
    let book = [
        "baaaaaaaa",
        "abaaaaaaa",
        "aabaaaaaa",
        "aaabaaaaa",
        "aaaabaaaa",
    ];
    for (order, expected) in book.iter().enumerate() {
        assert_eq!(derive(text, order as u32).unwrap(), *expected);
    }
    // And back, by a right context.
    let text = "s {\n  axiom: aaaab\n  angle: 90\n  a > b --> b\n  b --> a\n}\n";
    assert_eq!(derive(text, 1).unwrap(), "aaaba");
    assert_eq!(derive(text, 3).unwrap(), "abaaa");
}

/// Contexts across branches, as ABOP defines them (p. 32): a branch's first symbol sees
/// the symbol before it, a left context skips whole branches, a right context ends at its
/// branch's end, and ignored symbols are skipped.
#[test]
fn contexts_across_branches() {
    let text = "s {\n  axiom: a[b]c[d]e+f\n  angle: 90\n  ignore: +\n  a < b --> B\n  \
                a < c --> C\n  d > e --> D\n  c > e --> X\n  e > f --> E\n}\n";
    assert_eq!(derive(text, 1).unwrap(), "a[B]C[d]E+f");
}

/// Hogeweg and Hesper's plant, ABOP figure 1.31 (a), at the book's order 30, and (b) and
/// (e): the walk gives the model's string exactly.
#[test]
fn figure_1_31_matches_the_string_model() {
    let ignore = "+-F";
    let figures: [(&[&str], u32); 3] = [
        (
            &[
                "0 < 0 > 0 --> 0",
                "0 < 0 > 1 --> 1[+F1F1]",
                "0 < 1 > 0 --> 1",
                "0 < 1 > 1 --> 1",
                "1 < 0 > 0 --> 0",
                "1 < 0 > 1 --> 1F1",
                "1 < 1 > 0 --> 0",
                "1 < 1 > 1 --> 0",
                "+ --> -",
                "- --> +",
            ],
            30,
        ),
        (
            &[
                "0 < 0 > 0 --> 1",
                "0 < 0 > 1 --> 1[-F1F1]",
                "0 < 1 > 0 --> 1",
                "0 < 1 > 1 --> 1",
                "1 < 0 > 0 --> 0",
                "1 < 0 > 1 --> 1F1",
                "1 < 1 > 0 --> 1",
                "1 < 1 > 1 --> 0",
                "+ --> -",
                "- --> +",
            ],
            30,
        ),
        (
            &[
                "0 < 0 > 0 --> 0",
                "0 < 0 > 1 --> 1[-F1F1]",
                "0 < 1 > 0 --> 1",
                "0 < 1 > 1 --> 1",
                "1 < 0 > 0 --> 0",
                "1 < 0 > 1 --> 1F1",
                "1 < 1 > 0 --> 1",
                "1 < 1 > 1 --> 0",
                "+ --> -",
                "- --> +",
            ],
            26,
        ),
    ];
    for (rules, order) in figures {
        let rules: Vec<Rule> = rules.iter().map(|r| rule(r)).collect();
        let text = lsys("F1F1F1", &rules, ignore);
        let expected = model("F1F1F1", &rules, ignore, order);
        assert!(expected.len() > 1000, "a grown plant: {}", expected.len());
        assert_eq!(derive(&text, order).unwrap(), expected);
        // The searches for right contexts stay cheap: few modules read for each derived.
        let file = LsysFile::new(&text);
        let grammar = file
            .entries()
            .next()
            .unwrap()
            .unwrap()
            .parametric()
            .unwrap();
        let mut walk = ParametricWalker::<40>::new(&grammar, order).unwrap();
        let derived = walk.by_ref().count() as u64;
        let read = walk.symbols_read();
        assert!(read <= 30 * derived, "{read} read for {derived}");
    }
}

/// A symbol, or a bracketed branch of them.
fn body(depth: u32) -> BoxedStrategy<String> {
    let symbol = proptest::sample::select(vec!["a", "b", "c", "+"]).prop_map(String::from);
    if depth == 0 {
        return proptest::collection::vec(symbol, 0..4)
            .prop_map(|parts| parts.concat())
            .boxed();
    }
    let part = prop_oneof![
        3 => symbol,
        1 => body(depth - 1).prop_map(|inner| format!("[{inner}]")),
    ];
    proptest::collection::vec(part, 0..4)
        .prop_map(|parts| parts.concat())
        .boxed()
}

fn random_rule() -> impl Strategy<Value = Rule> {
    let context = proptest::option::of(proptest::sample::select(vec!['a', 'b', 'c']));
    (
        context.clone(),
        proptest::sample::select(vec!['a', 'b', 'c', '+']),
        context,
        body(1),
    )
        .prop_map(|(left, predecessor, right, successor)| Rule {
            left,
            predecessor,
            right,
            successor,
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Random bracketed systems with left and right contexts and an ignored symbol: the
    /// walk gives exactly the model's string at every order.
    #[test]
    fn random_systems_match_the_string_model(
        axiom in body(2),
        rules in proptest::collection::vec(random_rule(), 1..6),
        order in 0u32..6,
    ) {
        let expected = model(&axiom, &rules, "+", order);
        prop_assume!(expected.len() < 200_000);
        let text = lsys(&axiom, &rules, "+");
        prop_assert_eq!(derive(&text, order).unwrap(), expected, "{}", text);
    }
}

/// Productions for brackets, unbalanced successors and probabilities that do not sum to 1
/// are typed errors with their place.
#[test]
fn bad_context_systems_are_typed_errors() {
    let error = |body: &str| derive(&format!("s {{\n  axiom: a\n  angle: 90\n{body}}}\n"), 1);
    assert!(matches!(
        error("  a < [ --> b\n"),
        Err(Error::Read(ReadError::ReservedRule { symbol: '[', .. }))
    ));
    assert!(matches!(
        error("  b < a --> [b\n"),
        Err(Error::Read(ReadError::UnclosedBracket { .. }))
    ));
    let sum = error("  a --> b : 0.5\n  a --> c : 0.3\n").unwrap_err();
    assert!(
        sum.to_string().contains("sum to 0.8,"),
        "says what they sum to: {sum}"
    );
}
