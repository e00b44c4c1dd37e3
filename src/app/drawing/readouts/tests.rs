//! The labels' placement, wrapping and notes, checked without a window.
use super::{place_over_others, wrap_words, LabelPlacer, Overlays};
use crate::app::model::camera::Camera;
use glam::DVec2;
use impulse::{Particle, World};

/// A label names its disc as the ledger does (numbered from 1): two
/// labels far from their discs had nothing to tell them apart.
#[test]
fn a_label_names_its_disc() {
    let p = Particle::new(DVec2::ZERO, DVec2::X, 1.0, 0.5, impulse::Color::palette(0));
    let lines = super::readout_lines(&p, 2, false);
    let name = crate::app::lang::tr!("disc-numbered", disc = 3);
    assert!(lines[0].starts_with(&format!("{name}:")), "{lines:?}");
    crate::app::lang::set_language(crate::app::lang::Lang::Fr);
    let french = super::readout_lines(&p, 2, false);
    crate::app::lang::set_language(crate::app::lang::Lang::En);
    assert!(french[0].starts_with("disque 3\u{a0}:"), "{french:?}");
    assert_eq!(lines.len(), 3);
    assert_eq!(super::readout_lines(&p, 2, true).len(), 5);
}

/// A crowded disc's label goes over its neighbours, but not over its
/// own velocity arrow (right of it, where a label is tried first).
#[test]
fn a_crowded_discs_label_keeps_off_its_own_arrow() {
    let mut world = World::new(DVec2::new(100.0, 100.0));
    let disc = Particle::new(
        DVec2::new(50.0, 50.0),
        DVec2::new(30.0, 0.0),
        1.0,
        2.0,
        impulse::Color::palette(0),
    );
    world.particles.push(disc);
    let camera = Camera::fitting(world.laws.size, DVec2::new(800.0, 800.0), 0.0);
    let overlays = Overlays::default();
    assert!(overlays.velocity);
    let size = DVec2::new(200.0, 60.0);
    let placer = LabelPlacer::new(size);
    let scene = (&world, &camera, &overlays);
    let room = (size, camera.screen_rect());
    let at = place_over_others(&world.particles[0], scene, room, &[6.0], &placer).expect("a place");
    // The arrow: from the centre (400, 400) px 0.5 s × 30 m/s × 8 px/m
    // to the right, 120 px.
    let [x, y, w, h] = at.rect;
    let (from, to) = (400.0, 400.0 + 120.0);
    let over = x < to && x + w > from && y < 400.0 + 10.0 && y + h > 400.0 - 10.0;
    assert!(!over, "the label {:?} over the arrow", at.rect);
}

/// Ten pixels a character.
fn measure(s: &str) -> f32 {
    10.0 * s.chars().count() as f32
}

/// "Values beside 0 of 1 discs" was no sentence: with one disc wanted
/// the note says whose values have no room.
#[test]
fn the_note_for_one_disc_says_whose_values_have_no_room() {
    use crate::app::lang::{set_language, tr, Lang};
    set_language(Lang::Es);
    let one = tr!("readouts-culled", shown = 0usize, wanted = 1usize);
    let many = tr!("readouts-culled", shown = 2usize, wanted = 5usize);
    set_language(Lang::En);
    assert!(
        one.contains("del disco elegido") && !one.contains("de 1"),
        "{one}"
    );
    assert!(many.contains("junto a 2 de 5 discos"), "{many}");
}

#[test]
fn a_long_note_is_cut_between_words_and_loses_none() {
    let note = "values beside 0 of 1 discs: no room for the rest (zoom in with the wheel)";
    for width in [60.0, 120.0, 200.0, 1e4] {
        let lines = wrap_words(note, width, measure);
        assert_eq!(lines.join(" "), note, "{width}");
        for line in &lines {
            // Only a single word may be wider (none is, above 60 px).
            assert!(measure(line) <= width, "{line:?} at {width}");
        }
        if width >= 1e4 {
            assert_eq!(lines.len(), 1);
        }
    }
    assert_eq!(wrap_words("a bb ccc", 50.0, measure), ["a bb", "ccc"]);
    assert_eq!(wrap_words("enormous x", 30.0, measure), ["enormous", "x"]);
    assert!(wrap_words("", 30.0, measure).is_empty());
}
