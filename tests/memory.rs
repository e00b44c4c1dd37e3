//! Memory: what a world holds per disc, counted by a global allocator that
//! tracks live heap bytes. A gas stepped with the grid holds a few hundred
//! bytes per disc whatever n, so a million discs fit well under 1 GiB.

use impulse::alloc_count::{live_bytes, Counting};
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::Method;
use impulse::presets::Gas;

#[global_allocator]
static ALLOC: Counting = Counting;

/// Heap bytes per disc of a gas of `n` discs after a few grid steps.
fn bytes_per_disc(n: usize, method: Method) -> f64 {
    let before = live_bytes();
    let mut world = Gas {
        count: n,
        ..Gas::default()
    }
    .build_fixed(method, BroadPhaseKind::Grid);
    for _ in 0..3 {
        world.step(0.01);
    }
    let bytes = live_bytes() - before;
    drop(world);
    bytes as f64 / n as f64
}

#[test]
fn a_disc_costs_a_few_hundred_bytes_whatever_n() {
    let disc = std::mem::size_of::<impulse::Particle>() as f64;
    for method in [Method::Impulse, Method::Verlet] {
        let small = bytes_per_disc(10_000, method);
        let large = bytes_per_disc(100_000, method);
        // The discs themselves, plus the skin list and the grid's buffers:
        // a disc is held twice (the world's Vec<Particle> and the skin
        // list's copy, which the narrow phase reads), each Vec at most
        // twice as long as it needs (growth by doubling), so at most
        // 4·size_of::<Particle>(); the grid and the contacts hold indices
        // (a cell key and a slot per disc, a contact or two per disc, and
        // verlet's previous position), at most eight 8-byte words, 64
        // bytes. Anything beyond is per-disc state no buffer accounts for
        // (or per-step garbage). 1 GiB for 10⁶ discs would be 1074 bytes
        // each.
        let most = 4.0 * disc + 64.0;
        eprintln!(
            "{method}: {large:.0} bytes per disc at 10⁵ discs, {small:.0} at 10⁴ \
             (a disc {disc} bytes, at most {most})"
        );
        assert!(
            large <= most && small <= most,
            "{method}: {large:.0} and {small:.0} bytes per disc, more than {most:.0} \
             (4 × {disc} for the discs and 64 for indices)"
        );
        assert!(most < 1074.0, "a million discs would not fit in 1 GiB");
        // Flat in n (no per-step garbage, no quadratic buffer).
        assert!(
            (large / small - 1.0).abs() < 0.3,
            "{small:.0} against {large:.0}"
        );
    }
}
