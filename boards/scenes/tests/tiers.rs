//! A scene computed in a tier other than the rule's draws what the rule's tier would: the
//! boards measure a cheaper tier only where it keeps every dwell.

use tinyfractal::{
    escape::{Algorithm, Render, Tier},
    render::DwellBuffer,
    View,
};
use tinyfractal_scenes::{Entry, DISPLAY_SCENES, GALLERY, SCENES};

/// The view's dwells, every pixel computed at its own point.
fn dwells(view: View) -> Vec<u16> {
    let size = view.size();
    let mut values = vec![0u16; (size.width * size.height) as usize];
    let Ok(_) =
        Render::new(view, Algorithm::Exact).run(&mut DwellBuffer::new(&mut values, size.width));
    values
}

#[test]
fn a_scene_in_a_tier_of_its_own_keeps_the_rules_dwells() {
    let mut checked = Vec::new();
    for entry in SCENES.iter().chain(&DISPLAY_SCENES).chain(&GALLERY) {
        let Entry {
            name, scene, size, ..
        } = *entry;
        let Some(view) = scene.view(size) else {
            continue;
        };
        let view = view.unwrap();
        let automatic = view.automatic_tier();
        // Perturbation by hand is a side-by-side of its own (tests/perturbation.rs).
        if view.tier() == automatic || view.tier() == Tier::Perturbation {
            continue;
        }
        assert!(
            automatic != Tier::Perturbation,
            "{name}: the rule draws it by perturbation"
        );
        assert!(
            dwells(view) == dwells(view.with_tier(automatic)),
            "{name} in {:?} differs from the rule's {automatic:?}",
            view.tier()
        );
        checked.push(name);
    }
    // The board's deep zoom is one: the rule gives it `Wide`, and it is measured in `Deep`.
    assert!(checked.contains(&"deep-zoom"), "{checked:?}");
}
