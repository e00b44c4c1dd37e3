//! The commands that move time while paused: J, the run to the next
//! impact (what it stops at and what it says), and N, one step.

use super::*;
use crate::app::numbers::with_unit;
use impulse::method::{Method, Setting};

/// Glancing: at t ≈ 5.57 s disc 0 hits the top wall and disc 1 the
/// bottom one at the same instant. J stops once for both, and says so
/// (it stopped twice, the first stop showing the momentum half changed),
/// first of all: a strip too narrow for the report still shows it.
#[test]
fn impacts_at_one_instant_are_one_stop_of_j_and_it_says_so() {
    let dir = tempfile::tempdir().unwrap();
    for method in [Setting::Auto, Setting::Fixed(Method::Exact)] {
        let mut s = sandbox_in(dir.path(), "preset-4-glancing.toml");
        s.apply(Command::SetMethod(method));
        let mut stops: Vec<(f64, String)> = Vec::new();
        while s.world.time < 6.0 && stops.len() < 50 {
            s.apply(Command::NextCollision);
            stops.push((s.world.time, s.message().unwrap_or_default().to_owned()));
        }
        for pair in stops.windows(2) {
            assert!(pair[1].0 - pair[0].0 > 1e-9, "{method}: two stops {pair:?}");
        }
        let both = stops.iter().find(|(t, _)| (t - 5.5717).abs() < 5e-4);
        let (_, said) = both.unwrap_or_else(|| panic!("{method}: no stop at 5.57 s: {stops:?}"));
        assert!(
            said.starts_with("2 impacts at the same moment"),
            "{method}: {said}"
        );
    }
}

/// J names a pair lowest disc first, as the table numbers them: in the
/// pile and the gas (the search meets pairs either way round) it said
/// "discs 2 and 1".
#[test]
fn j_names_a_pair_lowest_disc_first() {
    let dir = tempfile::tempdir().unwrap();
    let mut pairs = 0;
    for preset in [
        "preset-0-pile.toml",
        "preset-8-gas.toml",
        "preset-6-cradle.toml",
    ] {
        let mut s = sandbox_in(dir.path(), preset);
        for _ in 0..40 {
            s.apply(Command::NextCollision);
            let said = s.message().unwrap_or_default().to_owned();
            let Some(rest) = said.split("Discs ").nth(1) else {
                continue;
            };
            let numbers: Vec<usize> = rest
                .split([' ', ','])
                .filter_map(|w| w.parse().ok())
                .take(2)
                .collect();
            assert!(numbers[0] < numbers[1], "{preset}: {said}");
            pairs += 1;
        }
    }
    assert!(pairs > 20, "{pairs} pairs");
}

/// J says in words whether the totals changed: an elastic head-on hit
/// keeps both, a perfectly inelastic one of equal masses (m, v) keeps
/// the momentum and loses half the energy, m·v²/4. The message had
/// "changed by (0.000, 0.000) kg·m/s" and the energy cut off at a
/// projector's size. The drawer, open over the ledger J shows, closes.
#[test]
fn j_says_in_words_what_the_impact_kept_and_lost() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    s.apply(Command::ToggleDrawer);
    assert!(s.panels.drawer_open);
    s.apply(Command::NextCollision);
    assert!(!s.panels.drawer_open, "the drawer hid the ledger J opens");
    let said = s.message().unwrap_or_default().to_owned();
    assert!(
        said.starts_with("Discs 1 and 2, t\u{a0}=\u{a0}2.400 s: ")
            && said.ends_with("total momentum unchanged, kinetic energy unchanged"),
        "{said}"
    );
    let mut s = sandbox_in(dir.path(), "preset-5-inelastic.toml");
    let p = &s.world.particles[0];
    let lost = p.mass * p.vel.length_squared() / 4.0;
    s.apply(Command::NextCollision);
    let said = s.message().unwrap_or_default().to_owned();
    let less = format!("kinetic energy {} less", with_unit(lost, 3, "J"));
    assert!(
        said.contains("total momentum unchanged") && said.ends_with(&less),
        "{said} (expected {less})"
    );
    // Every language picks its words and gives the amount lost.
    for lang in crate::app::lang::Lang::SHIPPED {
        crate::app::lang::set_language(lang);
        let mut s = sandbox_in(dir.path(), "preset-5-inelastic.toml");
        s.apply(Command::NextCollision);
        let said = s.message().unwrap_or_default().to_owned();
        let amount = with_unit(lost, 3, "J");
        assert!(
            said.ends_with(&amount) || said.contains(&format!("{amount} ")),
            "{lang:?}: {said}"
        );
        assert!(
            !said.contains('{') && !said.contains("energy_change"),
            "{lang:?}: {said}"
        );
    }
    crate::app::lang::set_language(crate::app::lang::Lang::En);
}

/// N, paused, steps 1/240 s: the top bar's "t = 0.00 s" did not move, and
/// nothing said the step was made. The strip says how far and to when.
#[test]
fn a_step_says_how_far_it_went() {
    let dir = tempfile::tempdir().unwrap();
    let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
    if !s.clock.paused {
        s.apply(Command::TogglePause);
    }
    s.apply(Command::Step);
    later(&mut s, 1.0 / 60.0);
    s.tick(1.0 / 60.0, 1.0);
    let dt = s.clock.dt;
    assert!(
        (s.world.time - dt).abs() < 1e-12,
        "{} after one step of {dt}",
        s.world.time
    );
    let step = with_unit(dt, 4, "s");
    assert_eq!(
        s.message(),
        Some(format!("One step of {step}: t\u{a0}=\u{a0}{step}").as_str())
    );
}
