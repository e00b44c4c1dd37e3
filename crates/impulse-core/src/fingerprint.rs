//! The same scene stepped the same way gives the same bits on every target:
//! the browser build must never teach other numbers than the desktop. Each
//! fingerprint is [`World::state_hash`] (time, steps, and every disc's
//! position, velocity, mass and radius) after [`STEPS`] steps of a shipped
//! scene at its own step; the desktop prints them (`impulse fingerprint`),
//! the browser build computes them on request, and the browser test
//! compares the two.

use crate::catalogue::{self, SceneFile};
use crate::scene::Scene;
use crate::World;

/// Steps each scene is run for.
pub const STEPS: u32 = 240;

/// The scenes fingerprinted: every classroom preset, and seeded fills (the
/// gas preset's and the stability suite's relaxation, 400 discs).
pub const SCENES: [SceneFile; 12] = [
    catalogue::PRESET_0_PILE,
    catalogue::PRESET_1_HEAD_ON,
    catalogue::PRESET_2_HEAVY_HITS_LIGHT,
    catalogue::PRESET_3_LIGHT_HITS_HEAVY,
    catalogue::PRESET_4_GLANCING,
    catalogue::PRESET_5_INELASTIC,
    catalogue::PRESET_6_CRADLE,
    catalogue::PRESET_7_PI_BLOCKS,
    catalogue::PRESET_8_GAS,
    catalogue::PRESET_9_BILLIARDS,
    catalogue::STRESS_RELAXATION,
    catalogue::DEFAULT,
];

/// Each scene's path and its state hash (16 hex digits) after [`STEPS`]
/// steps; a scene that does not load gives its error instead.
pub fn fingerprints() -> Vec<(&'static str, String)> {
    SCENES
        .iter()
        .map(|file| {
            let print = Scene::parse(file.text, file.path)
                .and_then(|scene| Ok((scene.build(file.path)?, scene.step_for(None))))
                .map(|(mut world, dt): (World, f64)| {
                    for _ in 0..STEPS {
                        world.step(dt);
                    }
                    format!("{:016x}", world.state_hash())
                })
                .unwrap_or_else(|e| format!("error: {e}"));
            (file.path, print)
        })
        .collect()
}

/// The fingerprints as one JSON object, path → hash.
pub fn fingerprints_json() -> String {
    let entries: Vec<String> = fingerprints()
        .into_iter()
        .map(|(path, print)| format!("{path:?}: {print:?}"))
        .collect();
    format!("{{{}}}", entries.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_scene_is_fingerprinted_and_a_step_changes_its_print() {
        let prints = fingerprints();
        assert_eq!(prints.len(), SCENES.len());
        for (path, print) in &prints {
            assert_eq!(print.len(), 16, "{path}: {print}");
        }
        // Two runs agree; a scene stepped once more does not.
        assert_eq!(prints, fingerprints());
        let file = catalogue::PRESET_1_HEAD_ON;
        let scene = Scene::parse(file.text, file.path).unwrap();
        let mut world = scene.build(file.path).unwrap();
        for _ in 0..=STEPS {
            world.step(scene.step_for(None));
        }
        assert_ne!(format!("{:016x}", world.state_hash()), prints[1].1);
    }
}
