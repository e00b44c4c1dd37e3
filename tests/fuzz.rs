//! Fuzzing under proptest: the scene parser and the step.
//!
//! - Any byte string given to the parser gives a scene or a one-line error
//!   naming its origin, never a panic; a scene it accepts builds (or is
//!   refused with one line) and steps without NaN.
//! - The shipped scenes, mutated (numbers swapped for extreme values, lines
//!   dropped, duplicated or cut, bytes flipped), likewise.
//! - Any valid scene stepped for many steps under every method keeps every
//!   value finite, every disc inside a closed box (or a periodic one), and the
//!   total momentum where the boundary conserves it (periodic or open: it
//!   changes only by M·g·t).
//!
//! `PROPTEST_CASES=N cargo test --test fuzz` runs more cases; the defaults are
//! modest so `cargo test` stays fast.

use impulse::method::{Method, Setting};
use impulse::scene::{fuzz_scene_bytes, FuzzOutcome};
use impulse::{Boundary, Color, DVec2, Metrics, Particle, World};
use proptest::prelude::*;

/// Cases per property unless `PROPTEST_CASES` says otherwise.
fn cases(default: u32) -> ProptestConfig {
    let n = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    ProptestConfig {
        cases: n,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// The shipped scenes, the seeds the mutations start from.
fn shipped() -> Vec<String> {
    let texts: Vec<String> = impulse::catalogue::ALL
        .iter()
        .map(|f| f.text.to_string())
        .collect();
    assert!(texts.len() >= 10, "found {} scenes", texts.len());
    texts
}

/// Values a mutation writes in place of a number.
const EXTREMES: &[&str] = &[
    "0",
    "-0.0",
    "-1",
    "1e-300",
    "1e300",
    "1.7976931348623157e308",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "1e9",
    "1e-9",
    "9223372036854775807",
    "-9223372036854775808",
    "18446744073709551616",
    "2000000",
    "2000001",
    "1e400",
    "0.5",
    "\"x\"",
    "[]",
    "[1.0]",
    "[1.0, 2.0, 3.0]",
    "true",
];

/// Checks one outcome of the parser fuzz body: errors are one line naming
/// the origin; accepted scenes build into finite worlds.
fn check(outcome: &FuzzOutcome) -> Result<(), TestCaseError> {
    match outcome {
        FuzzOutcome::Refused(message) | FuzzOutcome::NotBuilt(message) => {
            prop_assert!(!message.contains('\n'), "not one line: {message}");
            prop_assert!(message.starts_with("fuzz"), "no origin: {message}");
        }
        FuzzOutcome::Built(world) => {
            prop_assert!(world
                .particles
                .iter()
                .all(|p| p.pos.is_finite() && p.vel.is_finite() && p.mass > 0.0 && p.radius > 0.0));
            // Three steps of it keep the laws' promises (step_checked).
            step_checked((**world).clone(), 3, 1.0 / 240.0)?;
        }
    }
    Ok(())
}

/// Whether two discs overlap (across the edges of a periodic box too).
fn any_overlap(w: &World) -> bool {
    let ps = &w.particles;
    ps.iter().enumerate().any(|(i, p)| {
        ps[i + 1..].iter().any(|q| {
            w.laws
                .boundary
                .separation(p.pos, q.pos, w.laws.size)
                .length()
                < p.radius + q.radius
        })
    })
}

/// Total energy (kinetic, rotational and potential) and the scale it is
/// compared with: each disc's kinetic energies plus |potential|.
fn energy(w: &World) -> (f64, f64) {
    let g = w.laws.gravity;
    let pe = |p: &Particle| -p.mass * g.dot(p.pos);
    let total = w
        .particles
        .iter()
        .map(|p| p.kinetic_energy() + p.rotational_energy() + pe(p))
        .sum();
    let scale = w
        .particles
        .iter()
        .map(|p| p.kinetic_energy() + p.rotational_energy() + pe(p).abs())
        .sum();
    (total, scale)
}

/// Total angular momentum about the origin (orbital plus spin) and its
/// scale, Σ|L_i|.
fn angular_momentum(w: &World) -> (f64, f64) {
    let total = w.particles.iter().map(|p| p.angular_momentum()).sum();
    let scale = w.particles.iter().map(|p| p.angular_momentum().abs()).sum();
    (total, scale)
}

/// Steps `world` `steps` times by `dt` and checks what physics promises:
///
/// - every value finite;
/// - energy: with restitutions e ≤ 1 and |β| ≤ 1 no impact gains energy
///   (an impulse that turns the normal relative velocity g_n into −e·g_n
///   changes the kinetic energy by −(1 − e²)/2·m*·g_n², whatever the
///   normal). So the total energy may not rise by more than rounding,
///   1e-9 of its scale (each of at most a few thousand impacts rounds it
///   by a few ε = 2.2e-16 relative: ~1e-12; 1e-9 leaves room for the
///   scale's cancellation between kinetic and potential energy) under
///   `exact`, which moves discs on their exact parabolas and never lets
///   them overlap, and, without gravity, under `seed` and `impulse`
///   (straight flight is exact; their push-apart moves positions only,
///   which without gravity costs no energy). Not promised: in a periodic
///   box under gravity (a disc wrapping through the floor reappears at
///   the ceiling); under gravity
///   the fixed-step methods' push-apart lifts discs (potential energy from
///   nowhere, bounded but not rounding); `verlet` reads velocities off
///   projected positions and ignores restitution; and discs overlapping
///   from the start are pushed apart by every method.
/// - angular momentum, in open space without gravity (nothing exerts a
///   torque about the origin): kept to rounding (1e-9 of Σ|L_i|) under
///   `exact`, whose impulses act along the line of centres at the touch
///   (tangentially at the contact point for rough discs) and which never
///   pushes discs apart. Not asserted for the fixed-step methods: `seed`
///   takes the normal where the discs overlap and pushes them apart across
///   their velocities, `verlet` projects positions, and `impulse`, which
///   keeps L at each impact it resolves at the touch, falls back to
///   push-apart where a pair is found overlapping without closing: the
///   fuzz's steps (up to 0.05 s at up to 30 m/s) carry discs several radii
///   a substep, through one another and into several at once, and there
///   push-apart moved L by up to 4e-2 of Σ|L| (3000 cases; 1e-14 in the
///   cases without such a step). impulse's angular momentum is asserted
///   where its rule holds: tests/at_touch.rs (isolated impacts) and
///   tests/rough.rs (an open rough gas).
fn step_checked(mut world: World, steps: usize, dt: f64) -> Result<World, TestCaseError> {
    let laws = world.laws;
    let elastic_at_most = laws.restitution <= 1.0
        && laws.wall_restitution <= 1.0
        && laws.tangential_restitution.abs() <= 1.0
        && laws.wall_tangential_restitution.abs() <= 1.0;
    let overlapping = any_overlap(&world);
    let (e0, e_scale) = energy(&world);
    let (l0, l_scale) = angular_momentum(&world);
    let mut methods = Vec::new();
    // What the contacts `impulse` did not resolve cleanly at the touch may
    // move the angular momentum by (see tests/rough.rs): push-apart by
    // depth d along n, m*·d·|g|; a disc met twice in one pass, rewound
    // along a velocity the first contact changed, τ·J·|Δg| ≤ 4·m*·|g|²·h.
    // |g| is at most twice the fastest disc's speed (its spin's rim speed
    // included), m* at most half the heaviest mass.
    let heaviest = world.particles.iter().map(|p| p.mass).fold(0.0, f64::max);
    let mut fallback_allowance = 0.0;
    for _ in 0..steps {
        let fastest = world
            .particles
            .iter()
            .map(|p| p.vel.length() + p.spin.abs() * p.radius)
            .fold(0.0, f64::max);
        let stats = world.step(dt);
        let changed = stats.at_touch_changed;
        let pushed = stats.contacts.saturating_sub(stats.at_touch + changed) as f64;
        let (g, h) = (2.0 * fastest, dt / f64::from(stats.substeps.max(1)));
        let reduced = 0.5 * heaviest;
        fallback_allowance +=
            reduced * g * (pushed * stats.max_overlap + changed as f64 * 4.0 * g * h);
        if let Some(plan) = world.plan() {
            if !methods.contains(&plan.method) {
                methods.push(plan.method);
            }
        }
    }
    for (i, p) in world.particles.iter().enumerate() {
        prop_assert!(
            p.pos.is_finite() && p.vel.is_finite() && p.spin.is_finite(),
            "disc {i} not finite: {p:?}"
        );
    }
    let weightless = laws.gravity == DVec2::ZERO;
    // (In a periodic box under gravity a disc leaving through the floor
    // comes back at the ceiling: its potential energy is not a function of
    // where it is, and there is no energy to keep.)
    let wraps_under_gravity = laws.boundary == Boundary::Periodic && !weightless;
    let keeps_energy = elastic_at_most
        && !overlapping
        && !wraps_under_gravity
        && methods.iter().all(|m| match m {
            Method::Exact => true,
            Method::Seed | Method::Impulse => weightless,
            Method::Verlet => false,
        });
    let (e1, _) = energy(&world);
    let (l1, _) = angular_momentum(&world);
    let open_space = laws.boundary == Boundary::Open && weightless && !overlapping;
    if keeps_energy {
        prop_assert!(
            e1 - e0 <= 1e-9 * e_scale,
            "energy rose from {e0:e} to {e1:e} J (scale {e_scale:e}) under {methods:?}"
        );
    }
    if open_space && methods.iter().all(|m| matches!(m, Method::Exact)) {
        prop_assert!(
            (l1 - l0).abs() <= 1e-9 * l_scale,
            "angular momentum moved from {l0:e} to {l1:e} (Σ|L| {l_scale:e}) under {methods:?}"
        );
    }
    // `impulse` resolves impacts at the touch, which keeps L; only its
    // fallback contacts may move it, by the allowance above.
    if open_space
        && methods
            .iter()
            .all(|m| matches!(m, Method::Impulse | Method::Exact))
    {
        prop_assert!(
            (l1 - l0).abs() <= fallback_allowance + 1e-9 * l_scale,
            "angular momentum moved from {l0:e} to {l1:e} (Σ|L| {l_scale:e}, fallbacks allow \
             {fallback_allowance:e}) under {methods:?}"
        );
    }
    Ok(world)
}

/// Applies one mutation, chosen by `kind`, at a place chosen by `at`.
fn mutate(text: &str, kind: u8, at: usize, value: &str, byte: u8) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let k = at % lines.len().max(1);
    match kind % 5 {
        // A number (or the first value on the line) swapped for an extreme.
        0 => {
            let mut out = lines.clone();
            let line = lines.get(k).copied().unwrap_or("");
            let replaced;
            if let Some((key, _)) = line.split_once('=') {
                replaced = format!("{key}= {value}");
                if let Some(slot) = out.get_mut(k) {
                    *slot = &replaced;
                }
                return out.join("\n");
            }
            out.join("\n")
        }
        // An element inside a [x, y] pair swapped for an extreme.
        1 => {
            let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
            if let Some(line) = out.get_mut(k) {
                if let (Some(a), Some(b)) = (line.find('['), line.find(',')) {
                    if a < b && !line.trim_start().starts_with('[') {
                        line.replace_range(a + 1..b, value);
                    }
                }
            }
            out.join("\n")
        }
        // A line dropped or duplicated.
        2 => {
            let mut out = lines.clone();
            if byte % 2 == 0 && !out.is_empty() {
                out.remove(k);
            } else if let Some(line) = lines.get(k) {
                out.insert(k, line);
            }
            out.join("\n")
        }
        // Cut short.
        3 => {
            let cut = at % text.len().max(1);
            let mut end = cut;
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            text[..end].to_string()
        }
        // One byte overwritten (the result may not be UTF-8).
        _ => {
            let mut bytes = text.as_bytes().to_vec();
            if !bytes.is_empty() {
                let i = at % bytes.len();
                bytes[i] = byte;
            }
            String::from_utf8_lossy(&bytes).into_owned()
        }
    }
}

proptest! {
    #![proptest_config(cases(256))]

    #[test]
    fn any_bytes_give_a_scene_or_a_one_line_error(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        check(&fuzz_scene_bytes(&bytes, "fuzz"))?;
    }

    #[test]
    fn toml_shaped_noise_gives_a_scene_or_a_one_line_error(
        lines in proptest::collection::vec(
            (
                prop::sample::select(vec!["[world]", "[[particles]]", "[fill]", "[simulation]", "size", "pos", "vel", "mass", "radius", "count", "seed", "density", "speed", "overlap", "gravity", "restitution", "wall_restitution", "boundary", "method", "broad_phase", "substeps", "dt", "color"]),
                prop::sample::select(EXTREMES.to_vec()),
                prop::sample::select(EXTREMES.to_vec()),
            ),
            0..24,
        )
    ) {
        let text: String = lines
            .iter()
            .map(|(key, a, b)| if key.starts_with('[') {
                format!("{key}\n")
            } else if matches!(*key, "size" | "pos" | "vel" | "gravity" | "radius" | "speed") {
                format!("{key} = [{a}, {b}]\n")
            } else {
                format!("{key} = {a}\n")
            })
            .collect();
        check(&fuzz_scene_bytes(text.as_bytes(), "fuzz"))?;
    }

    #[test]
    fn mutated_shipped_scenes_give_a_scene_or_a_one_line_error(
        which in any::<prop::sample::Index>(),
        mutations in proptest::collection::vec(
            (any::<u8>(), any::<usize>(), prop::sample::select(EXTREMES.to_vec()), any::<u8>()),
            1..4,
        ),
    ) {
        let scenes = shipped();
        let mut text = scenes[which.index(scenes.len())].clone();
        for (kind, at, value, byte) in &mutations {
            text = mutate(&text, *kind, *at, value, *byte);
        }
        if std::env::var_os("FUZZ_TRACE").is_some() {
            let _ = std::fs::write("/tmp/robust_last_case.toml", &text);
        }
        let outcome = fuzz_scene_bytes(text.as_bytes(), "fuzz");
        check(&outcome)?;
        // check() steps a built world three times, with the energy and
        // angular momentum checks of step_checked.
    }
}

/// A valid world: discs placed at random, the ones that would overlap or
/// stick out of the box dropped.
#[allow(clippy::too_many_arguments)]
fn world_from(
    size: (f64, f64),
    discs: &[(f64, f64, f64, f64, f64, f64)],
    boundary: Boundary,
    gravity: f64,
    restitution: (f64, f64),
    method: Setting<Method>,
) -> World {
    let mut world = World::new(DVec2::new(size.0, size.1));
    world.laws.boundary = boundary;
    world.laws.gravity = DVec2::new(0.0, -gravity);
    world.laws.restitution = restitution.0;
    world.laws.wall_restitution = restitution.1;
    world.method = method;
    for (k, &(fx, fy, vx, vy, radius, mass)) in discs.iter().enumerate() {
        let r = radius.min(size.0 / 2.0).min(size.1 / 2.0) * 0.999;
        let pos = DVec2::new(r + fx * (size.0 - 2.0 * r), r + fy * (size.1 - 2.0 * r));
        if world.is_free(pos, r) {
            world.particles.push(Particle::new(
                pos,
                DVec2::new(vx, vy),
                mass,
                r,
                Color::palette(k),
            ));
        }
    }
    world
}

/// The discrete methods; `exact` and `auto` (which often picks it) run in
/// the twin below.
fn methods() -> impl Strategy<Value = Setting<Method>> {
    prop::sample::select(vec![
        Setting::Fixed(Method::Seed),
        Setting::Fixed(Method::Impulse),
        Setting::Fixed(Method::Verlet),
    ])
}

fn exact_or_auto() -> impl Strategy<Value = Setting<Method>> {
    prop::sample::select(vec![Setting::Auto, Setting::Fixed(Method::Exact)])
}

proptest! {
    #![proptest_config(cases(48))]

    #[test]
    fn stepping_any_valid_scene_keeps_values_finite_discs_inside_and_momentum(
        scene in scenes(methods()),
    ) {
        step_and_check(scene)?;
    }

    #[test]
    fn stepping_any_valid_scene_under_exact_and_auto(scene in scenes(exact_or_auto())) {
        step_and_check(scene)?;
    }
}

type Discs = Vec<(f64, f64, f64, f64, f64, f64)>;

/// A random valid scene: size, discs, boundary, gravity, restitutions,
/// method, step.
type SceneCase = (
    (f64, f64),
    Discs,
    Boundary,
    f64,
    (f64, f64),
    Setting<Method>,
    f64,
);

fn scenes(method: impl Strategy<Value = Setting<Method>>) -> impl Strategy<Value = SceneCase> {
    (
        (1.0f64..40.0, 1.0f64..40.0),
        proptest::collection::vec(
            (
                0.0f64..1.0,
                0.0f64..1.0,
                -30.0f64..30.0,
                -30.0f64..30.0,
                0.02f64..2.0,
                1e-3f64..1e3,
            ),
            1..40,
        ),
        prop::sample::select(Boundary::ALL.to_vec()),
        prop_oneof![Just(0.0), 0.0f64..20.0],
        (0.0f64..=1.0, 0.0f64..=1.0),
        method,
        prop_oneof![Just(1.0 / 240.0), 1e-4f64..0.05],
    )
}

/// Steps the scene 300 times; checks finiteness, energy and angular
/// momentum (step_checked), containment and momentum.
fn step_and_check(scene: SceneCase) -> Result<(), TestCaseError> {
    let (size, discs, boundary, gravity, restitution, method, dt) = scene;
    let world = world_from(size, &discs, boundary, gravity, restitution, method);
    let before = Metrics::measure(&world.particles);
    let scale = Metrics::momentum_scale(&world.particles).max(1e-300);
    let world = step_checked(world, 300, dt)?;
    for (i, p) in world.particles.iter().enumerate() {
        match boundary {
            Boundary::Box => {
                let slack = 1e-9 * size.0.max(size.1);
                prop_assert!(
                    p.pos.x >= p.radius - slack
                        && p.pos.x <= size.0 - p.radius + slack
                        && p.pos.y >= p.radius - slack
                        && p.pos.y <= size.1 - p.radius + slack,
                    "disc {i} outside the box: {p:?}"
                );
            }
            Boundary::Periodic => {
                prop_assert!(
                    p.pos.x >= 0.0 && p.pos.x <= size.0 && p.pos.y >= 0.0 && p.pos.y <= size.1,
                    "disc {i} outside the periodic cell: {p:?}"
                );
            }
            Boundary::Open => {}
        }
    }
    if boundary != Boundary::Box {
        let after = Metrics::measure(&world.particles);
        let expected = before.momentum + before.mass * world.laws.gravity * world.time;
        let kicks = before.mass * gravity * world.time;
        let drift = (after.momentum - expected).length();
        // Rounding: of the sums, and of positions, which `verlet` turns
        // into velocities by dividing by the step.
        let n = world.particles.len() as f64;
        let rounding = 4.0 * n * before.mass * f64::EPSILON * size.0.max(size.1) / dt;
        prop_assert!(
            drift <= 1e-9 * (scale + kicks) * (1.0 + n) + rounding,
            "momentum drifted by {drift:e} (scale {scale:e}) under {:?}",
            world.plan().map(|p| p.method)
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(cases(48))]

    /// The fill looks up its neighbours in a hash grid: it must still never
    /// place two discs closer than it allows, on any boundary, beside listed
    /// discs of any size.
    #[test]
    fn a_fill_never_overlaps_beyond_what_it_allows(
        size in (2.0f64..60.0, 2.0f64..60.0),
        count in 1usize..300,
        seed in 0..=i64::MAX as u64,
        radius in (0.05f64..1.0, 1.0f64..3.0),
        overlap in prop_oneof![Just(0.0), 0.0f64..0.5],
        boundary in prop::sample::select(Boundary::ALL.to_vec()),
        big in proptest::option::of(0.1f64..0.45),
    ) {
        let (r0, r1) = (radius.0.min(size.0 / 4.0), (radius.0 * radius.1).min(size.0.min(size.1) / 2.0));
        let r0 = r0.min(r1);
        let listed = big.map(|f| {
            let r = f * size.0.min(size.1);
            format!("[[particles]]\npos = [{}, {}]\nmass = 1.0\nradius = {r}\n", size.0 / 2.0, size.1 / 2.0)
        }).unwrap_or_default();
        let boundary_name = match boundary {
            Boundary::Box => "box",
            Boundary::Open => "open",
            Boundary::Periodic => "periodic",
        };
        let text = format!(
            "[world]\nsize = [{}, {}]\nboundary = \"{boundary_name}\"\n{listed}[fill]\ncount = {count}\nseed = {seed}\nradius = [{r0}, {r1}]\noverlap = {overlap}\n",
            size.0, size.1
        );
        let world = match fuzz_scene_bytes(text.as_bytes(), "fuzz") {
            FuzzOutcome::Built(world) => world,
            FuzzOutcome::NotBuilt(message) => {
                prop_assert!(message.contains("too full"), "{message}");
                return Ok(());
            }
            FuzzOutcome::Refused(message) => return Err(TestCaseError::fail(message)),
        };
        let first_fill = usize::from(big.is_some());
        for (i, p) in world.particles.iter().enumerate().skip(first_fill) {
            for (j, q) in world.particles[..i].iter().enumerate() {
                let gap = if overlap > 0.0 {
                    (p.pos - q.pos).length()
                } else {
                    boundary.separation(p.pos, q.pos, world.laws.size).length()
                };
                let allowed = overlap * 2.0 * p.radius.min(q.radius);
                prop_assert!(
                    gap >= p.radius + q.radius - allowed - 1e-12,
                    "discs {j} and {i} overlap: gap {gap}, radii {} {}", q.radius, p.radius
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(cases(128))]

    /// The loader's overlap check (a hash grid) finds exactly what testing
    /// every pair finds: the first disc that overlaps an earlier one, and
    /// the earliest such partner.
    #[test]
    fn the_overlap_check_agrees_with_testing_every_pair(
        size in (2.0f64..30.0, 2.0f64..30.0),
        discs in proptest::collection::vec((0.0f64..1.0, 0.0f64..1.0, 0.05f64..1.5), 1..60),
        boundary in prop::sample::select(Boundary::ALL.to_vec()),
    ) {
        let placed: Vec<(DVec2, f64)> = discs
            .iter()
            .map(|&(fx, fy, r)| {
                let r = r.min(size.0 / 2.0).min(size.1 / 2.0);
                (DVec2::new(r + fx * (size.0 - 2.0 * r), r + fy * (size.1 - 2.0 * r)), r)
            })
            .collect();
        let boundary_name = match boundary {
            Boundary::Box => "box",
            Boundary::Open => "open",
            Boundary::Periodic => "periodic",
        };
        let mut text = format!("[world]\nsize = [{:?}, {:?}]\nboundary = \"{boundary_name}\"\n", size.0, size.1);
        for (pos, r) in &placed {
            text += &format!("[[particles]]\npos = [{:?}, {:?}]\nmass = 1.0\nradius = {r:?}\n", pos.x, pos.y);
        }
        let size = DVec2::new(size.0, size.1);
        let expected = placed.iter().enumerate().find_map(|(k, (p, rp))| {
            placed[..k]
                .iter()
                .position(|(q, rq)| boundary.separation(*q, *p, size).length() < rp + rq)
                .map(|other| format!("particles[{k}].pos: overlaps particles[{other}]"))
        });
        match (impulse::Scene::parse(&text, "fuzz"), expected) {
            (Ok(_), None) => {}
            (Err(e), Some(wanted)) => prop_assert!(e.to_string().contains(&wanted), "{e} / {wanted}"),
            (got, wanted) => return Err(TestCaseError::fail(format!("{got:?} but expected {wanted:?}"))),
        }
    }
}
