//! `impulse accuracy`: speed against accuracy, one curve per method.
//!
//! Every discrete method is swept over time steps and substeps and compared
//! with `exact` on the same scene. x is the cost (wall-clock seconds per
//! simulated second), y an error against the `exact` reference:
//!
//! - trajectory: RMS distance from the reference after a short horizon
//!   ([`TRAJECTORY_HORIZON`]), in disc radii (before chaos takes over);
//! - collisions: relative error of the pair-collision count over [`HORIZON`];
//! - energy drift with gravity: |E(T) − E(0)| / E(0) for an elastic gas
//!   falling under gravity (the reference conserves it to rounding);
//! - wall pressure: relative error of the momentum the walls transfer.
//!
//! The scene is a 100-disc elastic gas at 30 % area fraction in a closed box.
//! In the charts each method has its colour (as in every lab chart), each
//! substep count its marker and line style, a method's points are joined in
//! order of step size and each carries its step ("1/240"), and each line is
//! named at its end. Points on the Pareto front of cost against |error| (no
//! other point is both cheaper and more accurate) are ringed, where they lie
//! above the noise floor and below an error of 1 (a run that gains 40× its
//! energy is not on it, however cheap). Errors of exactly zero are drawn at
//! 1e-16.
//!
//! After a few collisions a gas is chaotic: two runs that differ only in
//! rounding part ways, and counts over [`HORIZON`] then differ by sampling
//! noise. `exact` run at other step sizes measures that noise floor (it
//! differs from the reference only in rounding), drawn as a labelled dashed
//! line with the band under it shaded: errors below it are not the method's.

use super::chart::{method_colour, write_chart, Chart, Series};
use crate::progress;
use impulse::boundary::Boundary;
use impulse::method::{Method, Setting};
use impulse::presets::Gas;
use impulse::{DVec2, World};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `impulse accuracy`.
#[derive(Clone, Debug, clap::Args)]
pub struct AccuracyArgs {
    /// Fewer time steps and substeps (well under a minute).
    #[arg(long)]
    pub quick: bool,
    /// Folder for accuracy.csv and the charts.
    #[arg(long, default_value = "lab-out")]
    pub out: PathBuf,
}

/// Simulated time for collision, energy and pressure errors (s): long
/// enough that the counts' sampling noise (the discrete runs and the
/// reference part ways chaotically) stays around a percent.
pub const HORIZON: f64 = 10.0;
/// Simulated time for the trajectory error (s).
pub const TRAJECTORY_HORIZON: f64 = 0.25;
/// Step of the `exact` reference run (s).
pub const REFERENCE_DT: f64 = 0.01;
/// Floor for drawing zero errors on a log axis.
const ZERO_ERROR: f64 = 1e-16;

/// One point of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Point {
    /// Method.
    pub method: Method,
    /// Time step (s).
    pub dt: f64,
    /// Substeps per step.
    pub substeps: u32,
    /// Wall-clock seconds per simulated second.
    pub cost: f64,
    /// RMS position error after the short horizon (radii).
    pub trajectory_error: f64,
    /// Relative error of the collision count.
    pub collision_error: f64,
    /// Relative energy drift under gravity.
    pub energy_drift: f64,
    /// Relative error of the wall pressure.
    pub pressure_error: f64,
}

/// An error measure: short name, axis label, and how to read it off a point.
type Metric = (&'static str, &'static str, fn(&Point) -> f64);

/// The errors, by name, for tables and charts.
const METRICS: [Metric; 4] = [
    (
        "trajectory",
        "RMS position error after 0.25 s (radii)",
        |p| p.trajectory_error,
    ),
    (
        "collisions",
        "relative error of the collision count over 10 s",
        |p| p.collision_error,
    ),
    (
        "energy",
        "relative energy drift over 10 s, falling under gravity",
        |p| p.energy_drift,
    ),
    ("pressure", "relative error of the wall pressure", |p| {
        p.pressure_error
    }),
];

fn gas(gravity: bool) -> World {
    let mut world = Gas {
        count: 100,
        boundary: Boundary::Box,
        speed: 2.0,
        seed: 4,
        ..Gas::default()
    }
    .build();
    if gravity {
        world.laws.gravity = DVec2::new(0.0, -9.81);
    }
    world
}

fn configure(world: &mut World, method: Method, substeps: u32) {
    world.method = Setting::Fixed(method);
    world.substeps = Setting::Fixed(substeps);
    world.broad_phase = Setting::Auto;
}

/// Runs `world` to exactly `time` with steps of `dt` (the last one shorter
/// if `dt` does not divide `time`); returns wall-clock seconds. A method
/// that cut a step short (`exact`'s event cap) did not get there, and its
/// errors would compare two different moments: that is refused, not
/// charted.
fn simulate(world: &mut World, time: f64, dt: f64) -> f64 {
    let whole = (time / dt * (1.0 + 1e-12)).floor() as u64;
    let rest = time - whole as f64 * dt;
    let started = Instant::now();
    let mut cut_short = 0;
    for _ in 0..whole {
        cut_short += usize::from(world.step(dt).truncated);
    }
    if rest > 1e-12 * time {
        cut_short += usize::from(world.step(rest).truncated);
    }
    assert!(
        cut_short == 0,
        "{} cut {cut_short} steps short at dt = {dt} s and reached t = {} s of {time} s",
        world.plan().map_or("the method", |p| p.method.name()),
        world.time
    );
    started.elapsed().as_secs_f64()
}

/// The reference and the measured state a point is compared with.
struct Outcome {
    short: World,
    long: World,
    falling: World,
    seconds: f64,
}

fn outcome(method: Method, dt: f64, substeps: u32) -> Outcome {
    let mut short = gas(false);
    configure(&mut short, method, substeps);
    simulate(&mut short, TRAJECTORY_HORIZON, dt);
    let mut long = gas(false);
    configure(&mut long, method, substeps);
    let seconds = simulate(&mut long, HORIZON, dt);
    let mut falling = gas(true);
    configure(&mut falling, method, substeps);
    simulate(&mut falling, HORIZON, dt);
    Outcome {
        short,
        long,
        falling,
        seconds,
    }
}

fn relative(value: f64, reference: f64) -> f64 {
    ((value - reference) / reference).abs()
}

fn compare(method: Method, dt: f64, substeps: u32, got: &Outcome, reference: &Outcome) -> Point {
    let radius = got.short.particles.first().map_or(1.0, |p| p.radius);
    let squared: f64 = got
        .short
        .particles
        .iter()
        .zip(&reference.short.particles)
        .map(|(a, b)| a.pos.distance_squared(b.pos))
        .sum();
    let n = got.short.particles.len().max(1) as f64;
    let e0 = gas(true).total_energy();
    Point {
        method,
        dt,
        substeps,
        cost: got.seconds / HORIZON,
        trajectory_error: (squared / n).sqrt() / radius,
        collision_error: relative(
            got.long.total_pair_collisions as f64,
            reference.long.total_pair_collisions as f64,
        ),
        energy_drift: relative(got.falling.total_energy(), e0),
        pressure_error: relative(
            got.long.total_wall_impulse,
            reference.long.total_wall_impulse,
        ),
    }
}

/// Runs the sweep, prints the table, writes CSV and one chart per error.
pub fn run(args: &AccuracyArgs) -> anyhow::Result<()> {
    // The folder first: a bad --out is refused before minutes of measuring.
    super::create_out_dir(&args.out)?;
    let dts: &[f64] = if args.quick {
        &[1.0 / 60.0, 1.0 / 240.0, 1.0 / 960.0]
    } else {
        &[
            1.0 / 30.0,
            1.0 / 60.0,
            1.0 / 120.0,
            1.0 / 240.0,
            1.0 / 480.0,
            1.0 / 960.0,
            1.0 / 1920.0,
        ]
    };
    let substeps: &[u32] = if args.quick { &[1, 8] } else { &[1, 4, 16] };
    let mut runs: Vec<(Method, f64, u32)> = Vec::new();
    for &dt in dts {
        runs.push((Method::Seed, dt, 1));
        for &k in substeps {
            runs.push((Method::Impulse, dt, k));
            runs.push((Method::Verlet, dt, k));
        }
    }
    // Exact at other steps than the reference's: same physics, other rounding.
    for dt in [0.1, 0.03, 0.003, 0.001] {
        runs.push((Method::Exact, dt, 1));
    }
    let bar = progress::bar(runs.len() as u64 + 1, "accuracy");
    bar.set_message("reference (exact)");
    let reference = outcome(Method::Exact, REFERENCE_DT, 1);
    bar.inc(1);
    let mut points = Vec::new();
    for (method, dt, k) in runs {
        bar.set_message(format!("{method} dt {dt:.5} x{k}"));
        let got = outcome(method, dt, k);
        points.push(compare(method, dt, k, &got, &reference));
        bar.inc(1);
    }
    bar.finish_and_clear();

    let table = table(&points);
    print!("{table}");
    crate::files::write_atomically(&args.out.join("accuracy.md"), table.as_bytes())?;
    crate::files::write_atomically(&args.out.join("accuracy.csv"), csv(&points).as_bytes())?;
    write_charts(&points, &args.out)
}

/// One chart per error measure, `accuracy-<name>.png` and `.svg` in `out`.
pub(crate) fn write_charts(points: &[Point], out: &std::path::Path) -> anyhow::Result<()> {
    for (name, label, error) in METRICS {
        let series = series_by_method(points, error);
        let floor = noise_floor(points, error);
        let front = pareto_front(points, error, floor);
        let subtitle = if front.points.is_empty() {
            let at_floor = points
                .iter()
                .filter(|p| error(p).abs() <= floor)
                .min_by(|a, b| a.cost.total_cmp(&b.cost))
                .map_or("none", |p| p.method.name());
            format!("beside each point: its step dt (s) · Pareto front on |error|: none above the noise floor (cheapest at the floor: {at_floor})")
        } else {
            "beside each point: its step dt (s) · black rings: Pareto front on |error|, above the noise floor (errors ≥ 1 not on it)".to_owned()
        };
        let title = format!("Speed against accuracy: {name}");
        let chart = Chart {
            title: &title,
            subtitle: &subtitle,
            x_label: "cost: wall-clock seconds per simulated second",
            y_label: label,
            log_x: true,
            log_y: true,
            series: &series,
            highlight: Some(&front),
            direct_labels: true,
            floor: Some((floor, floor_label(name))),
        };
        let (png, _) = write_chart(&chart, &out.join(format!("accuracy-{name}")))?;
        println!("wrote {}", png.display());
    }
    Ok(())
}

/// What the shaded band under the floor is: rounding for the smooth
/// measures, chaos for the counts and the pressure over 10 s (a collision
/// moved by an ulp changes which come after it).
fn floor_label(metric: &str) -> &'static str {
    match metric {
        "collisions" | "pressure" => "noise floor (chaos): exact against exact at other steps",
        _ => "noise floor (rounding): exact against exact at other steps",
    }
}

/// An error of this size or more (100 %, or a disc radius) is no accuracy at
/// all: such a point is not on the Pareto front however cheap it is.
const NO_ACCURACY: f64 = 1.0;

/// `dt` as a reader knows it: "1/240" where it is one over a whole number,
/// else the decimal ("0.03").
pub fn dt_label(dt: f64) -> String {
    let n = 1.0 / dt;
    if n.is_finite() && n >= 1.0 && (n - n.round()).abs() < 1e-6 * n {
        format!("1/{}", n.round())
    } else {
        format!("{dt}")
    }
}

/// One series per method and substep count, its points joined in order of
/// step size (largest step, the cheapest, first: a convergence curve, no
/// zig-zag), each labelled with its step. A colour per method (as in every
/// chart); a marker and line style per substep count (circle and solid 1,
/// square and dashed up to 8, triangle and dotted more); `exact` diamonds;
/// `seed`, which lies on `impulse, 1 substep` at larger steps, hollow rings
/// on a dash-dot line so that both show. Impulse first, so seed is drawn
/// over it.
pub(crate) fn series_by_method(points: &[Point], error: fn(&Point) -> f64) -> Vec<Series> {
    let mut keys: Vec<(Method, u32)> = Vec::new();
    for p in points {
        if !keys.contains(&(p.method, p.substeps)) {
            keys.push((p.method, p.substeps));
        }
    }
    let rank = |m: Method| match m {
        Method::Impulse => 0,
        Method::Seed => 1,
        Method::Verlet => 2,
        Method::Exact => 3,
    };
    keys.sort_by_key(|&(m, k)| (rank(m), k));
    keys.into_iter()
        .map(|(method, substeps)| {
            let mut mine: Vec<&Point> = points
                .iter()
                .filter(|p| p.method == method && p.substeps == substeps)
                .collect();
            mine.sort_by(|a, b| b.dt.total_cmp(&a.dt));
            let style = match substeps {
                0..=1 => 0,
                2..=8 => 1,
                _ => 2,
            };
            Series {
                name: match (method.uses_substeps(), substeps) {
                    (false, _) => method.name().to_string(),
                    (true, 1) => format!("{method}, 1 substep"),
                    (true, k) => format!("{method}, {k} substeps"),
                },
                points: mine
                    .iter()
                    .map(|p| (p.cost, error(p).abs().max(ZERO_ERROR)))
                    .collect(),
                point_labels: mine.iter().map(|p| dt_label(p.dt)).collect(),
                colour: Some(method_colour(method)),
                marker: Some(match method {
                    Method::Exact => 3,
                    _ => style,
                }),
                line: Some(match method {
                    Method::Seed => 3,
                    Method::Exact => 0,
                    _ => style,
                }),
                hollow: method == Method::Seed,
                ..Default::default()
            }
        })
        .collect()
}

/// The largest error of `exact` against itself at other step sizes: what
/// rounding alone gives (errors of zero count as [`ZERO_ERROR`]).
pub(crate) fn noise_floor(points: &[Point], error: fn(&Point) -> f64) -> f64 {
    points
        .iter()
        .filter(|p| p.method == Method::Exact)
        .map(|p| error(p).abs())
        .fold(ZERO_ERROR, f64::max)
}

/// The Pareto front of cost against |error| (no other point both cheaper and
/// more accurate), drawn only where it says something: points above the
/// noise `floor` (at or below it the errors are rounding) and below
/// [`NO_ACCURACY`] (a run that gains 40× its energy is not accurate, even
/// if nothing is cheaper).
pub fn pareto_front(points: &[Point], error: fn(&Point) -> f64, floor: f64) -> Series {
    let xy: Vec<(f64, f64)> = points
        .iter()
        .map(|p| (p.cost, error(p).abs().max(ZERO_ERROR)))
        .collect();
    let front = super::chart::pareto_front(&xy)
        .into_iter()
        .map(|i| xy[i])
        .filter(|&(_, e)| e > floor && e < NO_ACCURACY)
        .collect();
    Series {
        name: "Pareto front on |error| (above the noise floor)".into(),
        points: front,
        ..Default::default()
    }
}

fn table(points: &[Point]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "| method | dt (s) | substeps | cost (s/s) | trajectory (radii) | collisions | energy drift | pressure |"
    );
    let _ = writeln!(out, "|---|---:|---:|---:|---:|---:|---:|---:|");
    for p in points {
        let _ = writeln!(
            out,
            "| {} | {:.5} | {} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {:.2e} |",
            p.method,
            p.dt,
            p.substeps,
            p.cost,
            p.trajectory_error,
            p.collision_error,
            p.energy_drift,
            p.pressure_error
        );
    }
    out
}

fn csv(points: &[Point]) -> String {
    let mut out = String::from(
        "method,dt,substeps,cost,trajectory_error,collision_error,energy_drift,pressure_error\n",
    );
    for p in points {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{}",
            p.method,
            p.dt,
            p.substeps,
            p.cost,
            p.trajectory_error,
            p.collision_error,
            p.energy_drift,
            p.pressure_error
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(cost: f64, err: f64) -> Point {
        Point {
            method: Method::Impulse,
            dt: 0.01,
            substeps: 1,
            cost,
            trajectory_error: err,
            collision_error: err,
            energy_drift: err,
            pressure_error: err,
        }
    }

    #[test]
    fn the_pareto_front_keeps_only_unbeaten_points() {
        let points = [
            point(1.0, 0.5),
            point(2.0, 0.6),
            point(3.0, 0.1),
            point(0.5, 0.9),
            point(4.0, 0.1),
        ];
        let front = pareto_front(&points, |p| p.trajectory_error, 1e-3);
        assert_eq!(front.points, vec![(0.5, 0.9), (1.0, 0.5), (3.0, 0.1)]);
        // Not at or below the floor, and not at an error of 100 % or more.
        let front = pareto_front(&points, |p| p.trajectory_error, 0.1);
        assert_eq!(front.points, vec![(0.5, 0.9), (1.0, 0.5)]);
        let mut gains = points.to_vec();
        gains.push(point(0.1, 43.7));
        let front = pareto_front(&gains, |p| p.trajectory_error, 0.1);
        assert_eq!(front.points, vec![(0.5, 0.9), (1.0, 0.5)]);
    }

    /// The order p of `error ≈ C·dtᵖ`: the least-squares slope of
    /// log(error) against log(dt).
    fn fitted_order(points: &[(f64, f64)]) -> f64 {
        let xy: Vec<(f64, f64)> = points.iter().map(|&(dt, e)| (dt.ln(), e.ln())).collect();
        let n = xy.len() as f64;
        let (mx, my) = (
            xy.iter().map(|p| p.0).sum::<f64>() / n,
            xy.iter().map(|p| p.1).sum::<f64>() / n,
        );
        let sxy: f64 = xy.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
        let sxx: f64 = xy.iter().map(|&(x, _)| (x - mx) * (x - mx)).sum();
        sxy / sxx
    }

    #[test]
    fn the_order_fit_reads_the_exponent() {
        let points: Vec<(f64, f64)> = [0.1, 0.05, 0.025, 0.0125]
            .iter()
            .map(|&dt: &f64| (dt, 3.0 * dt.powf(1.7)))
            .collect();
        assert!((fitted_order(&points) - 1.7).abs() < 1e-12);
    }

    /// The trajectory error over the short horizon (before chaos takes
    /// over) of `method` at five steps from 1/240 to 1/3840 s, halving.
    fn trajectory_errors(method: Method) -> Vec<(f64, f64)> {
        let mut reference = gas(false);
        configure(&mut reference, Method::Exact, 1);
        simulate(&mut reference, TRAJECTORY_HORIZON, REFERENCE_DT);
        (0..5)
            .map(|k| {
                let dt = 1.0 / (240.0 * 2f64.powi(k));
                let mut w = gas(false);
                configure(&mut w, method, 1);
                simulate(&mut w, TRAJECTORY_HORIZON, dt);
                let squared: f64 = w
                    .particles
                    .iter()
                    .zip(&reference.particles)
                    .map(|(a, b)| a.pos.distance_squared(b.pos))
                    .sum();
                let radius = w.particles[0].radius;
                (dt, (squared / w.particles.len() as f64).sqrt() / radius)
            })
            .collect()
    }

    /// Rounding alone: each step moves a disc by a sum that rounds by
    /// about an ulp of a position in the 10 m box (2e-15 m), and the
    /// errors add up over the steps; in radii (0.1–0.3 m) at most about
    /// 1e-14 a step.
    fn rounding_bound(dt: f64) -> f64 {
        1e-14 * (TRAJECTORY_HORIZON / dt).ceil()
    }

    #[test]
    fn seed_is_first_order_in_the_step() {
        // `seed` takes the normal where the discs overlap, an error of the
        // order of one step's travel: in this asymptotic regime the
        // trajectory error falls as dt¹.
        let points = trajectory_errors(Method::Seed);
        let order = fitted_order(&points);
        assert!(
            (0.8..1.5).contains(&order),
            "order {order:.2} from {points:?}"
        );
    }

    #[test]
    fn impulse_follows_exact_to_rounding_from_a_240th_of_a_second() {
        // `impulse` resolves each impact where the discs touched: once no
        // disc meets two others within a step (this gas, from 1/240 s),
        // its trajectories are `exact`'s but for rounding.
        for (dt, error) in trajectory_errors(Method::Impulse) {
            assert!(
                error <= rounding_bound(dt),
                "dt {dt}: {error:e} radii, rounding allows {:e}",
                rounding_bound(dt)
            );
        }
    }

    #[test]
    fn impulse_reaches_exact_once_no_disc_meets_two_in_a_step() {
        let reference = outcome(Method::Exact, REFERENCE_DT, 1);
        let errors: Vec<f64> = [1.0 / 60.0, 1.0 / 240.0, 1.0 / 960.0]
            .iter()
            .map(|&dt| {
                compare(
                    Method::Impulse,
                    dt,
                    1,
                    &outcome(Method::Impulse, dt, 1),
                    &reference,
                )
                .trajectory_error
            })
            .collect();
        // At 1/60 s some discs meet a second partner within a step and
        // fall back to the overlap's rule; from 1/240 s only rounding is
        // left.
        assert!(errors[0] > 1e3 * errors[1], "{errors:?}");
        assert!(
            errors[1] <= rounding_bound(1.0 / 240.0) && errors[2] <= rounding_bound(1.0 / 960.0),
            "{errors:?}"
        );
        let again = compare(
            Method::Exact,
            0.001,
            1,
            &outcome(Method::Exact, 0.001, 1),
            &reference,
        );
        assert!(
            again.trajectory_error < 1e-9 && again.energy_drift < 1e-12,
            "{again:?}"
        );
    }
}
