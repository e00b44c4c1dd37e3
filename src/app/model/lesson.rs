//! The classroom's numbers: how much of the ledger the sandbox keeps, how
//! far "next collision" looks, and the π blocks' count ("31 collisions:
//! π ≈ 3.1") once it is final; the core's warnings in the window's words.

use crate::app::lang::tr;
use crate::app::numbers::plain;

/// Collisions the window keeps in the ledger.
pub const LEDGER_KEEP: usize = 50;
/// How far "run to the next collision" looks ahead (simulated seconds).
pub const NEXT_COLLISION_LIMIT: f64 = 60.0;

/// The impacts counted, the one count the top bar, the Collisions tab and
/// the dump all give: "collisions: 1 between discs · 13 with walls" (walls
/// only where there are any).
pub fn count_line(world: &impulse::World) -> String {
    let pairs = world.total_pair_collisions;
    let walls = world.total_wall_hits;
    let with_walls =
        world.laws.boundary == impulse::Boundary::Box && !world.laws.walls.names().is_empty();
    if with_walls {
        tr!("count-line-walls", pairs = pairs, walls = walls)
    } else {
        tr!("count-line", pairs = pairs)
    }
}

/// For the π blocks (two discs, one wall, a mass ratio of 100^k): k, the
/// number of decimals of π their collision count spells (31 for k = 1).
pub fn pi_decimals(world: &impulse::World) -> Option<u32> {
    let [a, b] = world.particles.as_slice() else {
        return None;
    };
    let one_wall =
        world.laws.boundary == impulse::Boundary::Box && world.laws.walls.names().len() == 1;
    let k = (a.mass.max(b.mass) / a.mass.min(b.mass)).log10() / 2.0;
    let round = k.round();
    (one_wall && (k - round).abs() < 1e-9 && (0.0..=8.0).contains(&round)).then_some(round as u32)
}

/// "31 collisions: π ≈ 3.1" once the π blocks can collide no more.
pub fn pi_result(world: &impulse::World) -> Option<String> {
    let k = pi_decimals(world)?;
    if !world.collisions_over() {
        return None;
    }
    let count = world.total_pair_collisions + world.total_wall_hits;
    let digits = count.to_string();
    let (whole, decimals) = digits.split_at(1.min(digits.len()));
    let point = if crate::app::lang::decimal_comma() {
        ','
    } else {
        '.'
    };
    let pi = if k == 0 || decimals.is_empty() {
        whole.to_string()
    } else {
        format!("{whole}{point}{decimals}")
    };
    Some(tr!("pi-result", count = count, pi = pi))
}

/// A warning of the core's ([`impulse::warnings`]) in the window's words.
pub fn warning_text(warning: &impulse::warnings::Warning, method: &str) -> String {
    let value = |name: &str| {
        warning
            .values
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(0.0, |(_, v)| *v)
    };
    match warning.code {
        impulse::warnings::VERLET => tr!(
            "warning-verlet",
            restitution = crate::app::numbers::field(value("restitution"))
        ),
        impulse::warnings::SEED => tr!("warning-seed"),
        impulse::warnings::SUBSTEPS => tr!(
            "warning-substeps",
            substeps = value("substeps") as u64,
            radii = plain(value("radii"), 1)
        ),
        impulse::warnings::STALL => tr!("warning-stall", method = method),
        _ => warning.text.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use impulse::Scene;

    fn pi_world(file: &str) -> impulse::World {
        let path = format!("{}/assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
        Scene::load(std::path::Path::new(&path))
            .and_then(|s| s.build(&path))
            .unwrap()
    }

    #[test]
    fn the_pi_blocks_say_their_count_once_it_is_final_and_not_before() {
        for (file, k, line) in [
            ("pi-blocks-1.toml", 0, "3 collisions: π ≈ 3"),
            ("preset-7-pi-blocks.toml", 1, "31 collisions: π ≈ 3.1"),
            ("pi-blocks-10000.toml", 2, "314 collisions: π ≈ 3.14"),
            ("pi-blocks-1000000.toml", 3, "3141 collisions: π ≈ 3.141"),
        ] {
            let mut world = pi_world(file);
            assert_eq!(pi_decimals(&world), Some(k), "{file}");
            assert_eq!(pi_result(&world), None, "{file}: nothing counted yet");
            let mut said_at = None;
            for _ in 0..40 * 240 {
                world.step(1.0 / 240.0);
                if said_at.is_none() && pi_result(&world).is_some() {
                    said_at = Some(world.total_pair_collisions + world.total_wall_hits);
                }
            }
            // Said exactly when the last collision was over, and true.
            assert_eq!(pi_result(&world).as_deref(), Some(line), "{file}");
            assert_eq!(
                said_at,
                Some(line.split(' ').next().unwrap().parse().unwrap())
            );
        }
    }

    #[test]
    fn other_scenes_are_not_pi_blocks() {
        let mut world = pi_world("preset-7-pi-blocks.toml");
        world.laws.walls = impulse::Walls::ALL;
        assert_eq!(pi_decimals(&world), None, "four walls never end the count");
        let mut world = pi_world("preset-7-pi-blocks.toml");
        world.particles[1].mass = 50.0;
        assert_eq!(pi_decimals(&world), None, "50 is not a power of 100");
        assert_eq!(pi_decimals(&pi_world("preset-1-head-on.toml")), None);
    }
}
