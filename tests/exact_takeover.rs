//! When `exact` takes discs over (a scene that starts overlapping, an edit,
//! or a switch from a method that leaves overlaps), its set-up pushes
//! overlapping pairs apart before the first event. The step says how many
//! pairs and what potential energy the moves added, so the window can tell
//! why the energy readout jumps. Checked against the geometry of the push.

use impulse::method::exact::OVERLAP_TOLERANCE;
use impulse::method::{Method, Setting};
use impulse::{Boundary, DVec2, World};

mod common;
use common::{disc, world_with};

const DT: f64 = impulse::scene::DEFAULT_DT;
const G: f64 = 9.81;

fn exact_world(discs: Vec<impulse::Particle>) -> World {
    let mut w = world_with([2.0, 2.0], Boundary::Box, discs);
    w.laws.gravity = DVec2::new(0.0, -G);
    w.laws.restitution = 0.5;
    w.method = Setting::Fixed(Method::Exact);
    w
}

#[test]
fn a_disc_sunk_into_one_on_the_floor_is_lifted_and_the_energy_it_gains_is_reported() {
    let (m, r, depth) = (2.0, 0.1, 0.05);
    let lower = disc([1.0, r], [0.0, 0.0], 3.0, r);
    let upper = disc([1.0, r + 2.0 * r - depth], [0.0, 0.0], m, r);
    let mut w = exact_world(vec![lower, upper]);
    let first = w.step(DT);
    assert_eq!(first.separated_pairs, 1, "one overlapping pair");
    // The floor holds the lower disc, so the upper one rises by the depth
    // (to touching, within the tolerance, plus at most the set-up's margin
    // of 1e-3 of the two radii): m·g·depth, whatever the masses.
    let want = m * G * depth;
    let (low, high) = (
        want - m * G * OVERLAP_TOLERANCE * 2.0 * r,
        want + m * G * 1e-3 * 2.0 * r,
    );
    assert!(
        (low..=high).contains(&first.separation_energy),
        "lifting {m} kg by {depth} m adds {want} J, reported {}",
        first.separation_energy
    );
    let second = w.step(DT);
    assert_eq!(
        second.separated_pairs, 0,
        "a continuing step pushes nothing"
    );
    assert_eq!(second.separation_energy, 0.0);
}

#[test]
fn pushing_a_pair_apart_in_mid_air_keeps_its_centre_of_mass_and_its_energy() {
    let (r, depth) = (0.1, 0.04);
    let a = disc([1.0, 1.0], [0.0, 0.0], 1.0, r);
    let b = disc([1.03, 1.0 + 2.0 * r - depth], [0.0, 0.0], 3.0, r);
    let mut w = exact_world(vec![a, b]);
    let stats = w.step(DT);
    assert_eq!(stats.separated_pairs, 1);
    // Shares by inverse mass: Σ m·Δy = 0, so no potential energy.
    let scale = 4.0 * G * depth;
    assert!(
        stats.separation_energy.abs() < 1e-12 * scale,
        "a mid-air push added {} J",
        stats.separation_energy
    );
}

#[test]
fn switching_a_settled_impulse_pile_to_exact_reports_the_overlaps_it_removes() {
    let mut w = common::scene_with("preset-0-pile.toml", Method::Impulse);
    for _ in 0..(3.0 / DT) as usize {
        w.step(DT);
    }
    let before = common::deepest_pair_overlap(&w);
    assert!(
        before > OVERLAP_TOLERANCE,
        "impulse's pile overlaps ({before:e} of a radius)"
    );
    w.method = Setting::Fixed(Method::Exact);
    let first = w.step(DT);
    assert!(first.separated_pairs >= 1, "the overlaps were pushed apart");
    assert!(
        common::deepest_pair_overlap(&w) < 1e-9,
        "none left after exact's first step: {:e}",
        common::deepest_pair_overlap(&w)
    );
    assert!(
        first.separation_energy >= -1e-9,
        "a pile pushed apart on the floor does not sink: {} J",
        first.separation_energy
    );
    assert_eq!(w.step(DT).separated_pairs, 0);
}

#[test]
fn scenes_without_overlaps_report_no_pushes() {
    let mut w = common::scene_with("preset-8-gas.toml", Method::Exact);
    for _ in 0..20 {
        let stats = w.step(DT);
        assert_eq!(stats.separated_pairs, 0);
        assert_eq!(stats.separation_energy, 0.0);
    }
}
