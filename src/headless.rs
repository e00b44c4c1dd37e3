//! `impulse run`: simulate a scene without a window and print a summary.

use impulse::auto::Plan;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use impulse::{DVec2, Scene};
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `impulse run`.
#[derive(Clone, Debug, clap::Args)]
pub struct RunArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Simulated time in seconds.
    #[arg(long, value_parser = crate::cli::non_negative_seconds)]
    pub time: f64,
    /// Physics time step in seconds [default: the scene's, else 1/240].
    #[arg(long, value_parser = crate::cli::positive_seconds)]
    pub dt: Option<f64>,
    /// Collision method: seed, impulse, verlet, exact or auto [default: the scene's].
    #[arg(long)]
    pub method: Option<Setting<Method>>,
    /// Broad phase: brute, grid, sap, quadtree or auto [default: the scene's].
    #[arg(long)]
    pub broadphase: Option<Setting<BroadPhaseKind>>,
    /// Substeps per step (impulse, verlet), or auto [default: the scene's].
    #[arg(long, value_parser = crate::cli::substeps)]
    pub substeps: Option<Setting<u32>>,
    /// Threads for the large-scene stages [default: RAYON_NUM_THREADS, else
    /// one per core]; `auto` still runs small scenes on one.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
    /// Run even when it takes more than 10⁸ steps (many minutes).
    #[arg(long)]
    pub yes: bool,
}

/// Steps beyond which a run asks for `--yes` (at some 10⁷ steps a second
/// for a small scene, minutes of waiting).
const ASK_STEPS: f64 = 1e8;

/// Seconds between progress lines on a standard error that is not a
/// terminal (a log file, CI); `IMPULSE_PROGRESS_SECONDS` sets it (tests).
fn progress_every() -> f64 {
    std::env::var("IMPULSE_PROGRESS_SECONDS")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .filter(|s| *s > 0.0)
        .unwrap_or(5.0)
}

/// Most steps one run may take, so a typo cannot run for days.
const MAX_STEPS: f64 = 1e9;

/// What `run` prints.
#[derive(Serialize)]
struct Summary {
    scene: String,
    steps: u64,
    /// Simulated time reached (s): less than `requested_time` when steps
    /// were cut short.
    sim_time: f64,
    /// Simulated time asked for (s).
    requested_time: f64,
    /// Steps the method cut short (`exact`'s event cap): the run fell behind.
    truncated_steps: u64,
    dt: f64,
    /// Impacts in all: between discs and with walls.
    collisions: u64,
    pair_collisions: u64,
    wall_hits: u64,
    /// Whether no collision can happen any more (see `World::collisions_over`).
    collisions_over: bool,
    max_overlap: f64,
    /// The largest distance a disc moved in one substep, in its own radii
    /// (measured; 0 for `exact`): above 1 it may have passed through another.
    max_travel: f64,
    momentum: DVec2,
    /// Of translation; rotation is `rotational_energy`.
    kinetic_energy: f64,
    rotational_energy: f64,
    /// About the origin: orbital plus spin (kg·m²/s, counter-clockwise).
    angular_momentum: f64,
    wall_clock_seconds: f64,
    plan: Plan,
    /// What the method could not promise at the end of the run.
    warnings: Vec<impulse::warnings::Warning>,
    particles: Vec<impulse::Particle>,
}

/// Runs the scene and prints the summary.
pub fn run(args: &RunArgs) -> anyhow::Result<()> {
    if let Some(threads) = args.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(usize::from(threads))
            .build_global()?;
    }
    let scene = Scene::load(&args.scene)?;
    let origin = args.scene.display().to_string();
    let mut world = scene.build(&origin)?;
    if let Some(m) = args.method {
        world.method = m;
    }
    if let Some(b) = args.broadphase {
        world.broad_phase = b;
    }
    if let Some(k) = args.substeps {
        world.substeps = k;
    }
    let dt = scene.step_for(args.dt);
    let steps = (args.time / dt).round();
    if steps > MAX_STEPS {
        anyhow::bail!(
            "--time {} with --dt {} would take {steps:e} steps (limit {MAX_STEPS:e})",
            crate::cli::number(args.time),
            crate::cli::number(dt)
        );
    }
    if steps > ASK_STEPS && !args.yes {
        anyhow::bail!(
            "--time {} with --dt {} is {steps:.1e} steps, which may take many minutes: \
             add --yes to run it, or give a larger --dt",
            crate::cli::number(args.time),
            crate::cli::number(dt)
        );
    }
    let plan = world.plan_for(dt);
    let started = Instant::now();
    // Off a terminal the bar is hidden: a line every few seconds instead.
    let lines = !std::io::IsTerminal::is_terminal(&std::io::stderr());
    let every = progress_every();
    let mut said = started;
    let mut max_overlap = 0.0f64;
    let mut max_travel = 0.0f64;
    let mut truncated_steps = 0u64;
    let bar = crate::progress::bar(steps as u64, "simulating");
    for k in 0..steps as u64 {
        let stats = world.step(dt);
        max_overlap = max_overlap.max(stats.max_overlap);
        max_travel = max_travel.max(stats.max_travel);
        truncated_steps += u64::from(stats.truncated);
        if k % 256 == 0 {
            bar.set_position(k);
            if lines && said.elapsed().as_secs_f64() >= every {
                said = Instant::now();
                eprintln!(
                    "impulse: simulating: {:.0} % ({k} of {} steps), {:.0} s elapsed",
                    100.0 * k as f64 / steps.max(1.0),
                    steps as u64,
                    started.elapsed().as_secs_f64()
                );
            }
        }
    }
    bar.finish_and_clear();
    let metrics = world.metrics();
    let summary = Summary {
        scene: origin,
        steps: world.steps,
        sim_time: world.time,
        requested_time: args.time,
        truncated_steps,
        dt,
        collisions: world.total_pair_collisions + world.total_wall_hits,
        pair_collisions: world.total_pair_collisions,
        wall_hits: world.total_wall_hits,
        collisions_over: world.collisions_over(),
        max_overlap,
        max_travel,
        momentum: metrics.momentum,
        kinetic_energy: metrics.kinetic_energy,
        rotational_energy: metrics.rotational_energy,
        angular_momentum: metrics.angular_momentum,
        wall_clock_seconds: started.elapsed().as_secs_f64(),
        warnings: {
            let measured = (steps >= 1.0).then_some(max_travel);
            impulse::warnings::warnings_with_travel(&world, dt, measured)
        },
        plan,
        particles: world.particles,
    };
    let text = if args.json {
        serde_json::to_string_pretty(&summary)? + "\n"
    } else {
        summary_text(&summary)
    };
    print_quietly(&text)?;
    match fell_behind(&summary) {
        Some(warning) => Err(FellBehind(warning).into()),
        None => Ok(()),
    }
}

/// Exit code of a run that did not reach the time it was asked for.
pub const EXIT_FELL_BEHIND: u8 = 3;

/// A run whose method cut steps short: the summary is printed, and the
/// binary exits with [`EXIT_FELL_BEHIND`] after this one line.
#[derive(Debug)]
pub struct FellBehind(pub String);

impl std::fmt::Display for FellBehind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for FellBehind {}

/// The one-line warning for a run that fell behind, naming the method and
/// what to do instead (not `--method auto`, which chose `exact` where a
/// fixed step would have missed impacts); `None` when it reached the time asked for.
fn fell_behind(s: &Summary) -> Option<String> {
    let short = s.requested_time - s.sim_time > 0.5 * s.dt;
    (s.truncated_steps > 0 && short).then(|| {
        format!(
            "{} cut {} of {} steps short (its event cap) and reached {:.4} s of the {} s asked for: \
             more collisions per step than an event-driven method can carry; a smaller --dt \
             spreads them over more steps, or --method impulse costs the same every step (its \
             warnings say what it may miss)",
            s.plan.method.name(),
            s.truncated_steps,
            s.steps,
            s.sim_time,
            s.requested_time
        )
    })
}

/// Prints to stdout; a reader that went away (`| head`) is not an error.
fn print_quietly(text: &str) -> anyhow::Result<()> {
    use std::io::Write;
    match std::io::stdout().lock().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e.into()),
        _ => Ok(()),
    }
}

fn summary_text(s: &Summary) -> String {
    use std::fmt::Write;
    let mut out = String::new();
    // Writing to a String cannot fail.
    macro_rules! println {
        ($($arg:tt)*) => { let _ = writeln!(out, $($arg)*); };
    }
    println!("scene            {}", s.scene);
    println!("steps            {} (dt = {} s)", s.steps, s.dt);
    println!("sim time         {:.6} s", s.sim_time);
    if s.truncated_steps > 0 {
        println!(
            "cut short        {} steps (of {}), {:.6} s asked for",
            s.truncated_steps, s.steps, s.requested_time
        );
    }
    println!("pair collisions  {}", s.pair_collisions);
    println!("wall hits        {}", s.wall_hits);
    println!("max overlap      {:.3e} m", s.max_overlap);
    if s.max_travel > 0.0 {
        println!("max travel       {:.3} radii per substep", s.max_travel);
    }
    println!(
        "momentum         ({:.9}, {:.9}) kg m/s",
        s.momentum.x, s.momentum.y
    );
    println!("kinetic energy   {:.9} J", s.kinetic_energy);
    if s.rotational_energy != 0.0 {
        println!("rotational KE    {:.9} J", s.rotational_energy);
    }
    println!("angular momentum {:.9} kg m²/s", s.angular_momentum);
    println!("wall clock       {:.3} s", s.wall_clock_seconds);
    let threads = if s.plan.parallel {
        format!("{} threads", impulse::parallel::threads())
    } else {
        "1 thread".to_string()
    };
    println!(
        "method           {} / {} / {} substep(s) / {threads}",
        s.plan.method.name(),
        s.plan.broad_phase.name(),
        s.plan.substeps
    );
    if !s.plan.reason.is_empty() {
        println!("auto chose       {}", s.plan.reason);
    }
    for w in &s.warnings {
        println!("warning          {}", w.text);
    }
    println!("particles        {}", s.particles.len());
    for (i, p) in s.particles.iter().enumerate().take(20) {
        println!(
            "  {i:>4}  pos ({:.4}, {:.4})  vel ({:.4}, {:.4})  m {}  r {}",
            p.pos.x, p.pos.y, p.vel.x, p.vel.y, p.mass, p.radius
        );
    }
    if s.particles.len() > 20 {
        println!("  ... {} more (use --json for all)", s.particles.len() - 20);
    }
    out
}
