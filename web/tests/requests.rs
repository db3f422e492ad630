//! The module's requests answered on the host, as the page makes them: lists, pictures,
//! and for bad input a message naming the cause, never a panic.

use tinyfractal_web::{respond, respond_in};

const KOCH: &str = "Koch {\n  Angle 6\n  Axiom F--F--F\n  F=F+F--F+F\n}\n";

#[test]
fn the_scenes_are_the_gallerys() {
    let answer = respond("scenes");
    assert!(!answer.error);
    let names: Vec<&str> = answer.text.lines().collect();
    assert_eq!(names, tinyfractal_simulator::gallery::names());
    assert!(names.contains(&"mandelbrot") && names.contains(&"koch-snowflake"));
}

#[test]
fn a_system_is_listed_and_drawn() {
    let listed = respond(&format!(
        "systems\n\n{KOCH}Broken {{\n  Angle 0\n  Axiom F\n}}\n"
    ));
    let lines: Vec<&str> = listed.text.lines().collect();
    assert_eq!(lines[..2], ["Koch", "Broken"]);
    assert!(
        lines[2].starts_with("error: Broken: ") && lines[2].contains("line 7, column 9"),
        "{lines:?}"
    );

    let drawn = respond(&format!("lsystem\norder=2\nsize=64x48\n\n{KOCH}"));
    assert!(!drawn.error, "{}", drawn.text);
    let picture = drawn.picture.expect("a picture");
    assert_eq!((picture.width, picture.height), (64, 48));
    assert_eq!(picture.rgba.len(), 64 * 48 * 4);
    // Order 2 of the snowflake: 3·4² segments.
    assert!(drawn.text.contains("segments=48"), "{}", drawn.text);
}

#[test]
fn bad_requests_say_what_is_wrong() {
    for (request, says) in [
        ("draw", "unknown request"),
        ("scene\nname=nope", "no scene"),
        ("escape\nsize=0x10", "WIDTHxHEIGHT"),
        ("escape\nsize=big", "WIDTHxHEIGHT"),
        ("escape\nwidth=abc", "abc"),
        ("escape\ncenter=1", "RE,IM"),
        ("escape\nmax-iter=0", "max-iter"),
        ("escape\nprecision=huge", "precision"),
        ("lsystem\norder=99\n\nKoch { Angle 6 Axiom F }", "order"),
        ("lsystem\n\n", "no system"),
        (
            "lsystem\n\nKoch {\n  Angle x6\n  Axiom F\n  F=F+F\n}",
            "line 2, column 9",
        ),
    ] {
        let answer = respond(request);
        assert!(answer.error, "{request:?} answered {}", answer.text);
        assert!(answer.picture.is_none());
        assert!(answer.text.contains(says), "{request:?}: {}", answer.text);
    }
}

#[test]
fn an_escape_view_reports_its_tier() {
    let answer = respond("escape\nsize=32x24\nmax-iter=64");
    assert!(!answer.error, "{}", answer.text);
    assert!(answer.text.starts_with("tier="), "{}", answer.text);
    let julia = respond("escape\nfractal=julia\njulia=-0.8,0.156\nsize=32x24");
    assert!(!julia.error, "{}", julia.text);
    assert_ne!(julia.picture, answer.picture);
}

/// A view drawn in steps ends as the one drawn whole, after partial pictures; a perturbed
/// view asked in steps is drawn whole; `more` without a view is an error.
#[test]
fn a_view_in_steps_ends_as_the_whole_one() {
    let view = "escape\ncenter=-0.7435,0.1314\nwidth=0.02\nmax-iter=4000\nsize=320x240";
    let whole = respond(view);
    let mut session = None;
    let mut answer = respond_in(&format!("{view}\nsteps=1"), &mut session);
    let mut partial = 0;
    while answer.more {
        assert!(!answer.error, "{}", answer.text);
        partial += 1;
        answer = respond_in("more", &mut session);
    }
    assert!(partial >= 2, "{partial} partial pictures");
    assert!(!answer.error, "{}", answer.text);
    assert_eq!(answer.picture, whole.picture);
    assert!(session.is_none());

    let deep = "escape\ncenter=-0.1010963638456221610257854457386225654638,\
                0.9562865108091415007710960577299774358098\nwidth=1e-30\nmax-iter=1000\n\
                size=48x36";
    let stepped = respond_in(&format!("{deep}\nsteps=1"), &mut session);
    assert!(!stepped.more && !stepped.error, "{}", stepped.text);
    assert_eq!(stepped.picture, respond(deep).picture);

    let nothing = respond_in("more", &mut None);
    assert!(
        nothing.error && nothing.text.contains("no view"),
        "{}",
        nothing.text
    );
}
