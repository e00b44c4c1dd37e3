//! `cargo fuzz run scene` (nightly): any bytes as a scene file must give a
//! scene or a one-line error naming the file, never a panic. The same body
//! runs on stable under proptest in `tests/fuzz.rs`.
#![no_main]

use impulse::scene::{fuzz_scene_bytes, FuzzOutcome};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    match fuzz_scene_bytes(data, "fuzz") {
        FuzzOutcome::Refused(message) | FuzzOutcome::NotBuilt(message) => {
            assert!(!message.contains('\n'), "not one line: {message}");
        }
        FuzzOutcome::Built(mut world) => {
            world.step(1.0 / 240.0);
            assert!(world
                .particles
                .iter()
                .all(|p| p.pos.is_finite() && p.vel.is_finite()));
        }
    }
});
