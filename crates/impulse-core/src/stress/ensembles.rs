//! Scenarios with many discs: a settling pile, inelastic collapse, a dense
//! start, a long run and relaxation to the Maxwell–Boltzmann law.

use super::{finite_and_inside, load, max_relative_overlap, run_for, Outcome, Scenario, Size};
use crate::method::{Method, Setting};
use crate::metrics::Metrics;
use crate::World;

const PILE_PATH: &str = crate::catalogue::STRESS_PILE.path;
const PILE_TEXT: &str = crate::catalogue::STRESS_PILE.text;

/// 4. A pile settling under gravity.
pub(super) const PILE: Scenario = Scenario {
    key: "pile",
    title: "4. Pile under gravity (e = 0.5)",
    quick_title: None,
    figure: "max overlap (radii)",
    criterion: "after settling (6 s; 10 s in the full suite): overlap under 0.05 radius (about a pixel at classroom zoom), mean jitter energy under 0.01·m·g·r per disc, and no step gains more than 0.01·m·g·r per disc (push-apart restores height that sinking lost)",
    threshold: "pass if < 0.05, jitter < 0.01·m·g·r, no step gains energy",
    scene_path: PILE_PATH,
    scene: PILE_TEXT,
    run: pile,
};

fn pile(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    let mut world = load(PILE_TEXT, PILE_PATH, method)?;
    let n = world.particles.len() as f64;
    let mean = |f: fn(&crate::Particle) -> f64| world.particles.iter().map(f).sum::<f64>() / n;
    let (m, r) = (mean(|p| p.mass), mean(|p| p.radius));
    let unit = m * world.laws.gravity.length() * r; // lifting a disc by its radius
    let mut energy = world.total_energy();
    let mut worst_gain = 0.0f64;
    let duration = if size == Size::Quick { 6.0 } else { 10.0 };
    let run = run_for(&mut world, crate::scene::DEFAULT_DT, duration, |w, _| {
        let e = w.total_energy();
        worst_gain = worst_gain.max(e - energy);
        energy = e;
    });
    if let Err(stall) = run {
        return Ok(stall.outcome());
    }
    let overlap = max_relative_overlap(&world);
    let jitter = world.metrics().kinetic_energy / n / unit;
    let gain = worst_gain / n / unit;
    let inside = finite_and_inside(&world, 1e-6);
    Ok(Outcome {
        figure: overlap,
        summary: format!(
            "overlap {overlap:.3} r, jitter {jitter:.1e} mgr, worst step gain {gain:.1e} mgr per disc"
        ),
        pass: inside && overlap < 0.05 && jitter < 0.01 && gain < 1e-2,
    })
}

const COLLAPSE_PATH: &str = crate::catalogue::STRESS_COLLAPSE.path;
const COLLAPSE_TEXT: &str = crate::catalogue::STRESS_COLLAPSE.text;

/// 5. Inelastic collapse.
pub(super) const COLLAPSE: Scenario = Scenario {
    key: "collapse",
    title: "5. Inelastic collapse (e = 0.2)",
    quick_title: None,
    figure: "most work in a frame (contacts or events per disc)",
    criterion: "no NaN, no stall (event cap never hit), kinetic energy never rises, while the gas cools for 10 s",
    threshold: "no threshold: pass if no stall and the energy never rises",
    scene_path: COLLAPSE_PATH,
    scene: COLLAPSE_TEXT,
    run: collapse,
};

fn collapse(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    let mut world = load(COLLAPSE_TEXT, COLLAPSE_PATH, method)?;
    let n = world.particles.len() as f64;
    let ke0 = world.metrics().kinetic_energy;
    let mut ke = ke0;
    let (mut rose, mut work) = (false, 0.0f64);
    let duration = if size == Size::Quick { 5.0 } else { 10.0 };
    let run = run_for(&mut world, 1.0 / 60.0, duration, |w, stats| {
        let now = w.metrics().kinetic_energy;
        rose |= now > ke * (1.0 + 1e-12);
        ke = now;
        let per_frame = stats.events.max(stats.contacts * stats.substeps as usize);
        work = work.max(per_frame as f64 / n);
    });
    if let Err(stall) = run {
        return Ok(stall.outcome());
    }
    let finite = finite_and_inside(&world, 1e-6);
    Ok(Outcome {
        figure: work,
        summary: format!(
            "{work:.2} per disc at most; energy left {:.1e}{}",
            ke / ke0,
            if rose { ", energy rose" } else { "" }
        ),
        pass: finite && !rose,
    })
}

const DENSE_PATH: &str = crate::catalogue::STRESS_DENSE_START.path;
const DENSE_TEXT: &str = crate::catalogue::STRESS_DENSE_START.text;

/// 7. A dense start.
pub(super) const DENSE_START: Scenario = Scenario {
    key: "dense-start",
    title: "7. Dense start (overlaps ≤ ¼ diameter)",
    quick_title: None,
    figure: "kinetic energy injected (J per disc)",
    criterion: "discs at rest stay at rest (under 1e-12 J per disc) while their overlaps are cured to under 0.01 radius within 2 s",
    threshold: "pass if < 1e-12",
    scene_path: DENSE_PATH,
    scene: DENSE_TEXT,
    run: dense_start,
};

fn dense_start(method: Setting<Method>, _size: Size) -> Result<Outcome, String> {
    let mut world = load(DENSE_TEXT, DENSE_PATH, method)?;
    let n = world.particles.len() as f64;
    let overlap0 = max_relative_overlap(&world);
    if let Err(stall) = run_for(&mut world, crate::scene::DEFAULT_DT, 2.0, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let injected = world.metrics().kinetic_energy / n;
    let overlap = max_relative_overlap(&world);
    Ok(Outcome {
        figure: injected,
        summary: format!("{injected:.1e} J per disc; overlap {overlap0:.2} r → {overlap:.3} r"),
        pass: injected < 1e-12 && overlap < 0.01 && finite_and_inside(&world, 1e-6),
    })
}

const LONG_PATH: &str = crate::catalogue::STRESS_LONG_RUN.path;
const LONG_TEXT: &str = crate::catalogue::STRESS_LONG_RUN.text;

/// 8. A long run.
pub(super) const LONG_RUN: Scenario = Scenario {
    key: "long-run",
    title: "8. Long run (1,000 discs, 10⁶ steps)",
    quick_title: Some("8. Long run (1,000 discs, 10⁴ steps)"),
    figure: "relative energy drift",
    criterion: "energy drifts less than 1e-9 and momentum less than 1e-12 (of Σ m|v|) over the run (10⁴ steps in the quick suite)",
    threshold: "pass if < 1e-9 (momentum < 1e-12)",
    scene_path: LONG_PATH,
    scene: LONG_TEXT,
    run: long_run,
};

fn long_run(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    let mut world = load(LONG_TEXT, LONG_PATH, method)?;
    let steps = if size == Size::Quick { 10_000.0 } else { 1e6 };
    let dt = crate::scene::DEFAULT_DT;
    let before = world.metrics();
    let scale = Metrics::momentum_scale(&world.particles);
    if let Err(stall) = run_for(&mut world, dt, steps * dt, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let after = world.metrics();
    let energy = (after.kinetic_energy - before.kinetic_energy).abs() / before.kinetic_energy;
    let momentum = (after.momentum - before.momentum).length() / scale;
    Ok(Outcome {
        figure: energy,
        summary: format!("energy {energy:.1e}, momentum {momentum:.1e} over {steps:.0e} steps"),
        pass: energy < 1e-9 && momentum < 1e-12 && finite_and_inside(&world, 1e-6),
    })
}

const RELAX_PATH: &str = crate::catalogue::STRESS_RELAXATION.path;
const RELAX_TEXT: &str = crate::catalogue::STRESS_RELAXATION.text;

/// 11. Relaxation to Maxwell–Boltzmann.
pub(super) const RELAXATION: Scenario = Scenario {
    key: "relaxation",
    title: "11. Relaxation to Maxwell–Boltzmann",
    quick_title: None,
    figure: "Kolmogorov–Smirnov distance to the Rayleigh law",
    criterion: "after about 12 collisions per disc (25 in the full suite), the speeds pass the KS test at the 1 % level: D < 1.63/√n",
    threshold: "pass if D < 1.63/√n",
    scene_path: RELAX_PATH,
    scene: RELAX_TEXT,
    run: relaxation,
};

fn relaxation(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    let mut world = load(RELAX_TEXT, RELAX_PATH, method)?;
    let duration = if size == Size::Quick { 10.0 } else { 20.0 };
    if let Err(stall) = run_for(&mut world, crate::scene::DEFAULT_DT, duration, |_, _| {}) {
        return Ok(stall.outcome());
    }
    let n = world.particles.len();
    let distance = rayleigh_ks_distance(&world);
    let critical = 1.63 / (n as f64).sqrt();
    Ok(Outcome {
        figure: distance,
        summary: format!("D = {distance:.3} (1 % critical value {critical:.3})"),
        pass: distance < critical,
    })
}

/// Kolmogorov–Smirnov distance between the discs' speeds and the 2D
/// Maxwell–Boltzmann law at the same temperature, the Rayleigh distribution
/// F(v) = 1 − exp(−v²/⟨v²⟩) (mass-weighted ⟨v²⟩ for mixed masses).
pub fn rayleigh_ks_distance(world: &World) -> f64 {
    let ps = &world.particles;
    let mass: f64 = ps.iter().map(|p| p.mass).sum();
    let mean_square = ps
        .iter()
        .map(|p| p.mass * p.vel.length_squared())
        .sum::<f64>()
        / mass;
    let mut speeds: Vec<f64> = ps.iter().map(|p| p.vel.length()).collect();
    speeds.sort_by(f64::total_cmp);
    let n = speeds.len() as f64;
    speeds
        .iter()
        .enumerate()
        .map(|(k, &v)| {
            let model = 1.0 - crate::math::exp(-v * v / mean_square);
            let (below, at) = (k as f64 / n, (k + 1) as f64 / n);
            (model - below).abs().max((at - model).abs())
        })
        .fold(0.0, f64::max)
}

const ROUGH_PATH: &str = crate::catalogue::STRESS_ROUGH.path;
const ROUGH_TEXT: &str = crate::catalogue::STRESS_ROUGH.text;

/// 12. Rough discs share energy with rotation.
pub(super) const ROUGH: Scenario = Scenario {
    key: "rough",
    title: "12. Rough gas: equipartition with rotation",
    quick_title: None,
    figure: "|rotation's share of the energy − 1/3|, averaged over the second half",
    criterion: "a perfectly rough elastic gas (β = 1) that starts without spin gives rotation one third of the energy (one of three degrees of freedom), within 0.03, while the total (translation and rotation) moves by less than 1e-9 of itself",
    threshold: "pass if < 0.03, energy kept to 1e-9",
    scene_path: ROUGH_PATH,
    scene: ROUGH_TEXT,
    run: rough,
};

fn rough(method: Setting<Method>, size: Size) -> Result<Outcome, String> {
    let mut world = load(ROUGH_TEXT, ROUGH_PATH, method)?;
    let duration = if size == Size::Quick { 10.0 } else { 20.0 };
    let energy = world.total_energy();
    let (mut share, mut samples) = (0.0, 0);
    let run = run_for(&mut world, crate::scene::DEFAULT_DT, duration, |w, _| {
        if w.time >= 0.5 * duration {
            let m = w.metrics();
            share += m.rotational_energy / (m.kinetic_energy + m.rotational_energy);
            samples += 1;
        }
    });
    if let Err(stall) = run {
        return Ok(stall.outcome());
    }
    let share = share / samples.max(1) as f64;
    let off = (share - 1.0 / 3.0).abs();
    let drift = (world.total_energy() - energy).abs() / energy;
    Ok(Outcome {
        figure: off,
        summary: format!("rotation holds {share:.3} of the energy; energy moved {drift:.1e}"),
        pass: off < 0.03 && drift < 1e-9,
    })
}
