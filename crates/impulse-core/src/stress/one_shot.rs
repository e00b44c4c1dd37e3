//! Scenarios with a known answer for a few discs: bullets, the blocks that
//! count π, Newton's cradle, extreme mass ratios, symmetric hits and
//! degenerate input.

use super::{
    finite_and_inside, load, max_relative_overlap, run_for, scene_dt, Outcome, Scenario, Size,
};
use crate::method::{Method, Setting};
use crate::{Boundary, DVec2, Particle, World};

const BULLET_PATH: &str = crate::catalogue::STRESS_BULLET.path;
const BULLET_TEXT: &str = crate::catalogue::STRESS_BULLET.text;

/// 1. Bullets.
pub(super) const BULLET: Scenario = Scenario {
    key: "bullet",
    title: "1. Bullet (50 radii per step)",
    quick_title: None,
    figure: "tunnellings (of 2)",
    criterion: "the disc is hit and the bullet never passes its centre; the wall bullet stays in the box and comes back",
    threshold: "pass if 0",
    scene_path: BULLET_PATH,
    scene: BULLET_TEXT,
    run: bullet,
};

fn bullet(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    let mut world = load(BULLET_TEXT, BULLET_PATH, method)?;
    let dt = scene_dt(BULLET_TEXT, BULLET_PATH);
    // Three steps: the disc bullet reaches its target in the second; the
    // wall bullet bounces in the first and is on its way back.
    let (mut passed_through, mut escaped) = (false, false);
    let mut substeps = 0;
    let stalled = run_for(&mut world, dt, 3.0 * dt, |w, stats| {
        passed_through |= w.particles[0].pos.x > w.particles[1].pos.x;
        escaped |= !finite_and_inside(w, 1e-9);
        substeps = substeps.max(stats.substeps);
    });
    if let Err(stall) = stalled {
        return Ok(stall.outcome());
    }
    let target_hit = world.particles[1].vel.x > 0.0;
    let disc_tunnelled = passed_through || !target_hit;
    let wall_tunnelled = escaped || world.particles[2].vel.x <= 0.0;
    let count = u8::from(disc_tunnelled) + u8::from(wall_tunnelled);
    let how = if method == Setting::Fixed(Method::Exact)
        || world.plan().is_some_and(|p| p.method == Method::Exact)
    {
        "events".to_string()
    } else {
        format!("{substeps} substeps")
    };
    let say = |tunnelled: bool| if tunnelled { "tunnelled" } else { "hit" };
    Ok(Outcome {
        figure: f64::from(count),
        summary: format!(
            "disc {}, wall {} ({how})",
            say(disc_tunnelled),
            say(wall_tunnelled)
        ),
        pass: count == 0,
    })
}

const PI_PATH: &str = crate::catalogue::STRESS_PI_BLOCKS.path;
const PI_TEXT: &str = crate::catalogue::STRESS_PI_BLOCKS.text;

/// 2. The blocks that count π.
pub(super) const PI_BLOCKS: Scenario = Scenario {
    key: "pi-blocks",
    title: "2. Blocks that count π",
    quick_title: None,
    figure: "largest mass ratio counted right",
    criterion: "pair plus wall collisions = ⌊π·10^k⌋ at mass ratio 100^k, k = 0…4 (3, 31, 314, 3141, 31415)",
    threshold: "pass if 1e8 (all five counts right)",
    scene_path: PI_PATH,
    scene: PI_TEXT,
    run: pi_blocks,
};

/// Longest simulated time a π-blocks run may take to finish (s); the
/// heavy disc turns round within 2·gap₀/v ≈ 40 s.
const PI_MAX_SECONDS: f64 = 120.0;

fn pi_blocks(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    let mut counts = Vec::new();
    let mut right_up_to = None;
    let mut all_right = true;
    for k in 0..5 {
        let ratio = crate::math::pow(100.0, f64::from(k));
        let mut world = load(PI_TEXT, PI_PATH, method)?;
        // The light disc must fit the gap the heavy one closes to, about
        // 2·gap₀/√ratio = 4 mm at 10⁸.
        world.particles[0].radius = 1e-5;
        world.particles[1].mass = ratio * world.particles[0].mass;
        // Done once the heavy disc moves away at least as fast as the light
        // one can ever follow: |v_light| ≤ v_heavy. A light disc still
        // heading for the wall then has exactly one collision left (the
        // wall), which is counted without waiting for it.
        let mut count = None;
        let done = |w: &World| {
            let (light, heavy) = (w.particles[0].vel.x, w.particles[1].vel.x);
            (heavy > 0.0 && light.abs() <= heavy)
                .then(|| w.total_pair_collisions + w.total_wall_hits + u64::from(light < 0.0))
        };
        let dt = crate::scene::DEFAULT_DT;
        for _ in 0..(PI_MAX_SECONDS / dt) as u64 {
            let stats = world.step(dt);
            if stats.truncated {
                break;
            }
            count = done(&world);
            if count.is_some() {
                break;
            }
        }
        let Some(count) = count else {
            counts.push("unfinished".into());
            all_right = false;
            continue;
        };
        let expected = (std::f64::consts::PI * crate::math::pow(10.0, f64::from(k))).floor() as u64;
        if count == expected && all_right {
            right_up_to = Some(ratio);
        } else {
            all_right = false;
        }
        counts.push(count.to_string());
    }
    Ok(Outcome {
        figure: right_up_to.unwrap_or(f64::NAN),
        summary: format!(
            "{} (right up to {})",
            counts.join(" / "),
            right_up_to.map_or("none".into(), |r| format!("{r:.0e}"))
        ),
        pass: all_right,
    })
}

const CRADLE_PATH: &str = crate::catalogue::STRESS_CRADLE.path;
const CRADLE_TEXT: &str = crate::catalogue::STRESS_CRADLE.text;

/// 3. Newton's cradle.
pub(super) const CRADLE: Scenario = Scenario {
    key: "cradle",
    title: "3. Newton's cradle",
    quick_title: None,
    figure: "velocity error (of the arrival speed)",
    criterion: "the last disc leaves at the arrival speed and the rest stay, to 1e-6, touching and with 1 µm gaps",
    threshold: "pass if ≤ 1e-6",
    scene_path: CRADLE_PATH,
    scene: CRADLE_TEXT,
    run: cradle,
};

fn cradle(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    let mut world = load(CRADLE_TEXT, CRADLE_PATH, method)?;
    let v0 = world.particles[0].vel;
    // Contact after 5 s; 3 s more to let the row settle into its result.
    if let Err(stall) = run_for(&mut world, crate::scene::DEFAULT_DT, 8.0, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let error_of = |row: &[Particle]| {
        row.iter()
            .enumerate()
            .map(|(k, p)| {
                let expected = if k == row.len() - 1 { v0 } else { DVec2::ZERO };
                (p.vel - expected).length() / v0.length()
            })
            .fold(0.0f64, f64::max)
    };
    let touching = error_of(&world.particles[0..5]);
    let gaps = error_of(&world.particles[5..10]);
    let error = touching.max(gaps);
    Ok(Outcome {
        figure: error,
        summary: format!("{error:.1e} (touching {touching:.1e}, gaps {gaps:.1e})"),
        pass: error <= 1e-6,
    })
}

const MASS_PATH: &str = crate::catalogue::STRESS_MASS_RATIO.path;
const MASS_TEXT: &str = crate::catalogue::STRESS_MASS_RATIO.text;

/// 6. Extreme mass ratios.
pub(super) const MASS_RATIO: Scenario = Scenario {
    key: "mass-ratio",
    title: "6. Extreme mass ratios",
    quick_title: None,
    figure: "sink of the heavy discs (radii)",
    criterion: "an overlap at mass ratio 10⁶ is cured within 1 s without moving the centre of mass (1e-9 m) or setting the light disc moving (1e-9 m/s); discs 100–400× heavier sink less than 0.1 radius into a light layer in 5 s",
    threshold: "pass if < 0.1, and the 10⁶ pair cured",
    scene_path: MASS_PATH,
    scene: MASS_TEXT,
    run: mass_ratio,
};

fn mass_ratio(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    // (a) Push-apart at 10⁶: two discs overlapping by a quarter diameter.
    let mut pair = World::new(DVec2::new(10.0, 10.0));
    pair.laws.boundary = Boundary::Open;
    pair.method = method;
    pair.particles = vec![
        Particle::new(
            DVec2::new(5.0, 5.0),
            DVec2::ZERO,
            1.0,
            0.5,
            crate::Color::rgb(0, 114, 178),
        ),
        Particle::new(
            DVec2::new(5.75, 5.0),
            DVec2::ZERO,
            1e6,
            0.5,
            crate::Color::rgb(213, 94, 0),
        ),
    ];
    let com0 = pair.metrics().center_of_mass;
    if let Err(stall) = run_for(&mut pair, crate::scene::DEFAULT_DT, 1.0, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let com_shift = (pair.metrics().center_of_mass - com0).length();
    let light_speed = pair.particles[0].vel.length();
    let overlap_left = max_relative_overlap(&pair);
    let pair_ok = com_shift <= 1e-9 && light_speed <= 1e-9 && overlap_left <= 0.01;

    // (b) Heavy discs resting on a row of light ones.
    let mut pile = load(MASS_TEXT, MASS_PATH, method)?;
    let heavy: Vec<usize> = (0..pile.particles.len())
        .filter(|&i| pile.particles[i].mass >= 100.0)
        .collect();
    let y0: Vec<f64> = heavy.iter().map(|&i| pile.particles[i].pos.y).collect();
    let duration = if size == Size::Quick { 3.0 } else { 5.0 };
    if let Err(stall) = run_for(&mut pile, crate::scene::DEFAULT_DT, duration, |_, _| {}) {
        let mut out = stall.outcome();
        out.summary = format!(
            "pair: COM {com_shift:.0e} m, light {light_speed:.0e} m/s; pile {}",
            out.summary
        );
        return Ok(out);
    }
    let sink = heavy
        .iter()
        .zip(&y0)
        .map(|(&i, &y)| (y - pile.particles[i].pos.y) / pile.particles[i].radius)
        .fold(0.0f64, f64::max);
    let inside = finite_and_inside(&pile, 1e-6);
    Ok(Outcome {
        figure: sink,
        summary: format!(
            "sink {sink:.2} r; pair at 10⁶: COM moved {com_shift:.0e} m, light disc {light_speed:.0e} m/s, overlap left {overlap_left:.2} r"
        ),
        pass: pair_ok && inside && sink < 0.1,
    })
}

const CORNER_PATH: &str = crate::catalogue::STRESS_CORNER.path;
const CORNER_TEXT: &str = crate::catalogue::STRESS_CORNER.text;
const THREE_PATH: &str = crate::catalogue::STRESS_THREE_DISCS.path;
const THREE_TEXT: &str = crate::catalogue::STRESS_THREE_DISCS.text;

/// 9. Corners and simultaneous hits.
pub(super) const SYMMETRY: Scenario = Scenario {
    key: "symmetry",
    title: "9. Corner and three-disc hit",
    quick_title: None,
    figure: "symmetry error (of the speed)",
    criterion: "into the corner at 45° and back along the diagonal; a disc hitting two touching discs at once leaves them mirror images; both to 1e-9",
    threshold: "pass if ≤ 1e-9",
    scene_path: THREE_PATH,
    scene: THREE_TEXT,
    run: symmetry,
};

fn symmetry(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    // The corner: back where it started after 9 s, moving the other way.
    let mut corner = load(CORNER_TEXT, CORNER_PATH, method)?;
    let start = corner.particles[0];
    if let Err(stall) = run_for(&mut corner, crate::scene::DEFAULT_DT, 9.0, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let p = corner.particles[0];
    let speed = start.vel.length();
    let corner_error = ((p.vel + start.vel).length() / speed)
        .max((p.vel.x - p.vel.y).abs() / speed)
        .max((p.pos.x - p.pos.y).abs() / p.radius);

    // Three discs: B and C must mirror each other across A's line.
    let mut three = load(THREE_TEXT, THREE_PATH, method)?;
    let v0 = three.particles[0].vel.length();
    if let Err(stall) = run_for(&mut three, crate::scene::DEFAULT_DT, 8.0, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let [a, b, c] = [three.particles[0], three.particles[1], three.particles[2]];
    let three_error = ((b.vel.y + c.vel.y).abs() + (b.vel.x - c.vel.x).abs() + a.vel.y.abs()) / v0;
    let error = corner_error.max(three_error);
    Ok(Outcome {
        figure: error,
        summary: format!("{error:.1e} (corner {corner_error:.1e}, three discs {three_error:.1e})"),
        pass: error <= 1e-9,
    })
}

const DEGENERATE_PATH: &str = crate::catalogue::STRESS_DEGENERATE.path;
const DEGENERATE_TEXT: &str = crate::catalogue::STRESS_DEGENERATE.text;

/// 10. Degenerate input.
pub(super) const DEGENERATE: Scenario = Scenario {
    key: "degenerate",
    title: "10. Degenerate input",
    quick_title: None,
    figure: "cases failed (of 4)",
    criterion: "no NaN, no disc outside the box, no panic, no stall",
    threshold: "pass if 0",
    scene_path: DEGENERATE_PATH,
    scene: DEGENERATE_TEXT,
    run: degenerate,
};

fn degenerate(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    let base = load(DEGENERATE_TEXT, DEGENERATE_PATH, method)?;
    let mut cases: Vec<(&str, World)> = Vec::new();
    // As written: everything at rest, no gravity, one disc wider than half the box.
    cases.push(("at rest", base.clone()));
    // Two discs on one spot, at rest.
    let mut stacked = base.clone();
    stacked.particles[2].pos = stacked.particles[1].pos;
    cases.push(("coincident at rest", stacked.clone()));
    // Two discs on one spot, moving apart and moving together.
    let mut moving = stacked;
    moving.particles[1].vel = DVec2::new(1.0, 0.5);
    moving.particles[2].vel = DVec2::new(-0.5, 1.0);
    cases.push(("coincident moving", moving));
    // The big disc thrown at a wall with the small ones pinned in corners.
    let mut thrown = base;
    thrown.particles[0].vel = DVec2::new(30.0, 20.0);
    thrown.laws.gravity = DVec2::new(0.0, -9.81);
    cases.push(("big disc thrown", thrown));
    let mut failed = Vec::new();
    for (name, mut world) in cases {
        let mut ok = true;
        let run = run_for(&mut world, crate::scene::DEFAULT_DT, 2.0, |w, _| {
            ok &= finite_and_inside(w, 1e-6);
        });
        if run.is_err() || !ok {
            failed.push(name);
        }
    }
    Ok(Outcome {
        figure: failed.len() as f64,
        summary: if failed.is_empty() {
            "all 4 sane".into()
        } else {
            format!("failed: {}", failed.join(", "))
        },
        pass: failed.is_empty(),
    })
}
