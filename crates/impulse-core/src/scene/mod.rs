//! Scene files: TOML in, [`World`] out, with every value checked on the way.
//!
//! ```toml
//! name = "Head-on"                      # optional
//! description = "Two equal discs meet"  # optional, one line
//! edited = true                         # optional: saved after its discs were
//!                                       # edited, so the description may not hold
//! overlapping = true                    # optional: the listed discs may overlap
//!                                       # (written by saves of a running world)
//!
//! [world]
//! size = [16.0, 10.0]          # metres
//! gravity = [0.0, 0.0]         # m/s², default none
//! restitution = 1.0            # between discs, default 1
//! wall_restitution = 1.0       # at the walls, default 1
//! tangential_restitution = -1.0 # β between discs: -1 smooth (default) to 1 rough
//! wall_tangential_restitution = -1.0 # β at the walls, default -1
//! friction = 0.3               # optional Coulomb μ ≥ 0 (absent: no limit)
//! boundary = "box"             # "box", "open" or "periodic"
//! walls = ["left"]             # a box's sides that have walls; default all four
//! constrain = "x"              # optional: one dimension, motion along x only
//!
//! [simulation]                 # optional; every entry defaults to "auto"
//! method = "auto"              # "seed", "impulse", "verlet", "exact"
//! broad_phase = "auto"         # "brute", "grid", "sap", "quadtree"
//! substeps = "auto"            # or a number (impulse and verlet)
//! dt = 0.004                   # s; the window's and `run`'s default step
//!
//! [[particles]]
//! pos = [4.0, 5.0]
//! vel = [2.0, 0.0]
//! mass = 1.0
//! radius = 0.5
//! spin = 0.0                   # optional: rad/s, counter-clockwise
//! color = "#e69f00"            # optional
//!
//! [fill]                       # optional seeded random discs
//! count = 40
//! seed = 7
//! radius = [0.2, 0.4]
//! density = 1.0                # kg/m²: mass = density·π·r²
//! speed = [0.5, 2.0]
//! overlap = 0.0                # optional: overlap allowed, fraction of a diameter
//! ```

use crate::broad_phase::BroadPhaseKind;
use crate::laws::Laws;
use crate::method::{Method, Setting};
use crate::particle::{Color, Particle};
use crate::world::World;
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::path::Path;

mod errors;
mod fill;
pub use errors::MAX_MESSAGE_CHARS;
use errors::{kind_of, type_error};
use fill::DiscCells;

/// The step used when neither the command line nor the scene gives one (s).
pub const DEFAULT_DT: f64 = 1.0 / 240.0;

/// Most discs a scene may ask for, so a typo cannot exhaust memory.
pub const MAX_PARTICLES: usize = 2_000_000;

/// Largest scene file read (bytes): room for the most discs a scene may list.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// The ranges a scene's values must lie in. Inside them every product the
/// physics forms (momentum, energy, impulses, squared distances) stays far
/// from overflow and underflow in `f64`, so no method meets an infinity or a
/// NaN; outside them the loader refuses the file, naming the field.
pub mod limits {
    /// Smallest and largest box side and disc radius (m).
    pub const LENGTH: [f64; 2] = [1e-9, 1e9];
    /// Largest distance of a disc's centre from the origin (m), for the open
    /// boundary (in a box the box bounds it).
    pub const POSITION: f64 = 1e12;
    /// Smallest and largest disc mass (kg), and fill density (kg/m²).
    pub const MASS: [f64; 2] = [1e-12, 1e12];
    /// Largest speed (m/s).
    pub const SPEED: f64 = 1e8;
    /// Shortest and longest time step (s).
    pub const DT: [f64; 2] = [1e-9, 1e3];

    /// Whether `x` lies in `[lo, hi]` (false for NaN).
    pub fn within(x: f64, [lo, hi]: [f64; 2]) -> bool {
        (lo..=hi).contains(&x)
    }
}

/// A scene as written in a file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Short title.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// One-line description shown on screen.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// The discs were edited after the scene was opened, so its name and
    /// description may no longer describe it.
    #[serde(default, skip_serializing_if = "is_false")]
    pub edited: bool,
    /// The listed discs may overlap: a saved state (discs in contact
    /// overlap a little, a dense start a lot). Hand-written scenes leave it
    /// out, so that overlapping discs there are reported as a mistake.
    #[serde(default, skip_serializing_if = "is_false")]
    pub overlapping: bool,
    /// The world's size and laws (the `[world]` table).
    pub world: Laws,
    /// How it is simulated.
    #[serde(default, skip_serializing_if = "SimulationSpec::is_default")]
    pub simulation: SimulationSpec,
    /// Discs placed one by one.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub particles: Vec<ParticleSpec>,
    /// Seeded random discs, placed after the listed ones.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fill: Option<FillSpec>,
    /// The name and description in other languages, by language tag
    /// (`[translations.es]`, `[translations.pt-BR]`).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub translations: std::collections::BTreeMap<String, SceneWords>,
}

/// A scene's name and description in one language.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneWords {
    /// The short title in this language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The one-line description in this language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
}

/// The `[simulation]` table: method, broad phase, substeps, step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimulationSpec {
    /// Collision method.
    #[serde(default)]
    pub method: Setting<Method>,
    /// Broad phase.
    #[serde(default)]
    pub broad_phase: Setting<BroadPhaseKind>,
    /// Substeps per step for `impulse` and `verlet`.
    #[serde(default)]
    pub substeps: Setting<u32>,
    /// Time step (s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
}

impl SimulationSpec {
    fn is_default(&self) -> bool {
        *self == SimulationSpec::default()
    }
}

/// One `[[particles]]` entry.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParticleSpec {
    /// Centre (m).
    pub pos: DVec2,
    /// Velocity (m/s).
    #[serde(default)]
    pub vel: DVec2,
    /// Mass (kg).
    pub mass: f64,
    /// Radius (m).
    pub radius: f64,
    /// Angular velocity (rad/s, counter-clockwise); default 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub spin: f64,
    /// How far it has turned (rad); default 0. Only drawn.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub angle: f64,
    /// Colour; a palette colour when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<Color>,
}

/// The `[fill]` table: `count` random discs that overlap nothing.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FillSpec {
    /// How many discs.
    pub count: usize,
    /// Random seed: the same seed gives the same discs.
    #[serde(default)]
    pub seed: u64,
    /// Smallest and largest radius (m).
    pub radius: [f64; 2],
    /// Areal density (kg/m²); mass = density·π·r².
    #[serde(default = "one")]
    pub density: f64,
    /// Smallest and largest speed (m/s), in random directions.
    #[serde(default)]
    pub speed: [f64; 2],
    /// Largest overlap allowed with discs already placed, as a fraction of
    /// the smaller diameter: 0 (the default) for none; up to 0.5 for a
    /// deliberately dense start.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub overlap: f64,
}

/// Whether any two discs overlap (cells of the widest diameter: O(n)).
fn any_overlap(particles: &[Particle], laws: &Laws) -> bool {
    let widest = particles.iter().map(|p| p.radius).fold(0.0, f64::max);
    if !(widest > 0.0 && widest.is_finite()) {
        return false;
    }
    let mut cells = DiscCells::new(laws.size, 2.0 * widest, laws.boundary);
    particles.iter().enumerate().any(|(k, p)| {
        let hit = cells.near(p.pos).any(|other| {
            let q = &particles[other];
            laws.boundary.separation(q.pos, p.pos, laws.size).length() < p.radius + q.radius
        });
        cells.insert(p.pos, k);
        hit
    })
}

fn is_false(b: &bool) -> bool {
    !*b
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

fn one() -> f64 {
    1.0
}

/// Why a scene could not be read or built. Each names the file it came from.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("{origin}: cannot read: {cause}")]
    Io {
        /// File name.
        origin: String,
        /// The operating system's reason (in the message, not chained
        /// after it as well, so it is said once).
        cause: std::io::Error,
    },
    /// The text is not valid TOML or does not fit the scene format.
    #[error("{origin}: {message}")]
    Syntax {
        /// File name.
        origin: String,
        /// The parser's message, with line and column.
        message: String,
    },
    /// A value is out of range.
    #[error("{origin}: {field}: {reason}")]
    Invalid {
        /// File name.
        origin: String,
        /// Dotted path of the offending field, e.g. `particles[2].mass`.
        field: String,
        /// What is wrong with it.
        reason: String,
    },
}

impl Scene {
    /// The name in the language `tag` (`"es"`, `"pt-BR"`), else the
    /// scene's own.
    pub fn name_in(&self, tag: &str) -> Option<&str> {
        self.translations
            .get(tag)
            .and_then(|w| w.name.as_deref())
            .or(self.name.as_deref())
    }

    /// The description in the language `tag`, else the scene's own.
    pub fn description_in(&self, tag: &str) -> Option<&str> {
        self.translations
            .get(tag)
            .and_then(|w| w.description.as_deref())
            .or(self.description.as_deref())
    }

    /// The step to run at (s): `asked` (the command line's), else the
    /// scene's `simulation.dt`, else [`DEFAULT_DT`]. The one place this is
    /// decided, for the window, `run` and the stress suite.
    pub fn step_for(&self, asked: Option<f64>) -> f64 {
        asked.or(self.simulation.dt).unwrap_or(DEFAULT_DT)
    }

    /// Reads and checks a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let origin = path.display().to_string();
        let io = |cause| SceneError::Io {
            origin: origin.clone(),
            cause,
        };
        // Read at most one byte past the limit, so `/dev/zero` or a huge file
        // is refused instead of filling memory.
        // Only a regular file: a FIFO with no writer would block for ever,
        // a device could be endless, a folder is a mistake.
        let meta = std::fs::metadata(path).map_err(io)?;
        if !meta.is_file() {
            return Err(SceneError::Syntax {
                origin,
                message: format!("not a regular file ({}): give a scene file", kind_of(&meta)),
            });
        }
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|file| {
                use std::io::Read;
                file.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes)
            })
            .map_err(io)?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            return Err(SceneError::Syntax {
                origin,
                message: format!("larger than {} MiB", MAX_FILE_BYTES >> 20),
            });
        }
        let text = String::from_utf8(bytes).map_err(|e| SceneError::Syntax {
            origin: origin.clone(),
            message: format!("not UTF-8 text: {}", e.utf8_error()),
        })?;
        Scene::parse(&text, &origin)
    }

    /// Parses and checks scene text; `origin` names it in errors.
    pub fn parse(text: &str, origin: &str) -> Result<Scene, SceneError> {
        // Through serde_path_to_error, so that a value of the wrong type
        // is named by its field ("fill.count"), as the range checks name it.
        let scene: Scene = serde_path_to_error::deserialize(toml::Deserializer::new(text))
            .map_err(|e| type_error(text, origin, e))?;
        scene.validate(origin).map_err(|e| match e {
            SceneError::Invalid {
                origin,
                field,
                reason,
            } => SceneError::Invalid {
                origin: match line_of(text, &field) {
                    Some(line) => format!("{origin}, line {line}"),
                    None => origin,
                },
                field,
                reason,
            },
            other => other,
        })?;
        Ok(scene)
    }

    /// Checks every value; the error names the first bad field.
    pub fn validate(&self, origin: &str) -> Result<(), SceneError> {
        let bad = |field: String, reason: &str| SceneError::Invalid {
            origin: origin.to_string(),
            field,
            reason: reason.to_string(),
        };
        let w = &self.world;
        if !(w.size.is_finite() && w.size.min_element() > 0.0) {
            return Err(bad("world.size".into(), "must be two positive numbers"));
        }
        if !(limits::within(w.size.x, limits::LENGTH) && limits::within(w.size.y, limits::LENGTH)) {
            return Err(bad("world.size".into(), "must be between 1e-9 and 1e9 m"));
        }
        if !w.gravity.is_finite() {
            return Err(bad("world.gravity".into(), "must be finite"));
        }
        if !crate::laws::GRAVITY_RANGE.admits(w.gravity.length()) {
            return Err(bad("world.gravity".into(), "must be at most 1e6 m/s²"));
        }
        for law in crate::laws::Law::ALL {
            let range = law.range();
            if !range.admits(law.of(w)) {
                let (lo, hi) = range.valid;
                return Err(bad(
                    format!("world.{}", law.field()),
                    &format!("must be between {lo} and {hi}"),
                ));
            }
        }
        if w.friction
            .is_some_and(|mu| !(crate::laws::FRICTION_RANGE.admits(mu) && mu.is_finite()))
        {
            return Err(bad(
                "world.friction".into(),
                "must be a finite number of at least 0",
            ));
        }
        if w.walls != crate::Walls::ALL && w.boundary != crate::Boundary::Box {
            return Err(bad(
                "world.walls".into(),
                "only a box has walls: remove `walls`, or write boundary = \"box\"",
            ));
        }
        // The overlap test looks at the 3×3 cells around each disc (a cell
        // at least the widest diameter): O(n), where testing every earlier
        // disc took a minute for 10⁵ discs (`--gas 100000` built its scene so).
        let widest = self
            .particles
            .iter()
            .map(|p| p.radius)
            .filter(|r| *r > 0.0)
            .fold(0.0, f64::max);
        let mut cells = DiscCells::new(w.size, 2.0 * widest, w.boundary);
        for (k, p) in self.particles.iter().enumerate() {
            let field = |name: &str| format!("particles[{k}].{name}");
            if !(p.mass > 0.0 && p.mass.is_finite()) {
                return Err(bad(field("mass"), "must be a positive finite number"));
            }
            if !(p.radius > 0.0 && p.radius.is_finite()) {
                return Err(bad(field("radius"), "must be a positive finite number"));
            }
            if !p.vel.is_finite() {
                return Err(bad(field("vel"), "must be finite"));
            }
            if !p.pos.is_finite() {
                return Err(bad(field("pos"), "must be finite"));
            }
            if !p.spin.is_finite() {
                return Err(bad(field("spin"), "must be finite"));
            }
            if !p.angle.is_finite() {
                return Err(bad(field("angle"), "must be finite"));
            }
            if !limits::within(p.mass, limits::MASS) {
                return Err(bad(field("mass"), "must be between 1e-12 and 1e12 kg"));
            }
            if !limits::within(p.radius, limits::LENGTH) {
                return Err(bad(field("radius"), "must be between 1e-9 and 1e9 m"));
            }
            if p.vel.length() > limits::SPEED {
                return Err(bad(field("vel"), "must be at most 1e8 m/s"));
            }
            if p.spin.abs() * p.radius > limits::SPEED {
                return Err(bad(field("spin"), "must turn the rim at most 1e8 m/s"));
            }
            if p.pos.abs().max_element() > limits::POSITION {
                return Err(bad(field("pos"), "must be within 1e12 m of the origin"));
            }
            if let Some(axis) = w.constrain {
                // The other component would be dropped without a word.
                let across = p.vel[1 - axis.index()];
                if across != 0.0 {
                    let (along, name) = match axis {
                        crate::boundary::Axis::X => ("x", "vel = [vx, 0]"),
                        crate::boundary::Axis::Y => ("y", "vel = [0, vy]"),
                    };
                    let reason = format!(
                        "moves across the line of a world constrained to {along}: write {name}"
                    );
                    return Err(bad(field("vel"), &reason));
                }
            }
            if !w.boundary.admits(w.walls, w.size, p.pos, p.radius) {
                return Err(bad(field("pos"), "puts the disc outside the box"));
            }
            let overlapped = (!self.overlapping)
                .then(|| cells.near(p.pos))
                .into_iter()
                .flatten()
                .filter(|&other| {
                    let q = &self.particles[other];
                    w.boundary.separation(q.pos, p.pos, w.size).length() < p.radius + q.radius
                })
                .min();
            if let Some(other) = overlapped {
                let reason = format!("overlaps particles[{other}]");
                return Err(bad(field("pos"), &reason));
            }
            cells.insert(p.pos, k);
        }
        let sim = &self.simulation;
        if sim.dt.is_some_and(|dt| !limits::within(dt, limits::DT)) {
            return Err(bad(
                "simulation.dt".into(),
                "must be between 1e-9 and 1000 seconds",
            ));
        }
        if let Setting::Fixed(k) = sim.substeps {
            if !(1..=10_000).contains(&k) {
                return Err(bad(
                    "simulation.substeps".into(),
                    "must be between 1 and 10000",
                ));
            }
        }
        if self.particles.len() > MAX_PARTICLES {
            return Err(bad("particles".into(), "too many discs"));
        }
        if let Some(f) = &self.fill {
            if f.count > MAX_PARTICLES {
                return Err(bad("fill.count".into(), "too many discs"));
            }
            let [r0, r1] = f.radius;
            if !(r0 > 0.0 && r0 <= r1 && r1.is_finite()) {
                return Err(bad(
                    "fill.radius".into(),
                    "must be [min, max] with 0 < min ≤ max",
                ));
            }
            if !(limits::within(r0, limits::LENGTH) && limits::within(r1, limits::LENGTH)) {
                return Err(bad("fill.radius".into(), "must be between 1e-9 and 1e9 m"));
            }
            if !(f.density > 0.0 && f.density.is_finite()) {
                return Err(bad(
                    "fill.density".into(),
                    "must be a positive finite number",
                ));
            }
            if !limits::within(f.density, limits::MASS) {
                return Err(bad(
                    "fill.density".into(),
                    "must be between 1e-12 and 1e12 kg/m²",
                ));
            }
            let [s0, s1] = f.speed;
            if !(s0 >= 0.0 && s0 <= s1 && s1.is_finite()) {
                return Err(bad(
                    "fill.speed".into(),
                    "must be [min, max] with 0 ≤ min ≤ max",
                ));
            }
            if s1 > limits::SPEED {
                return Err(bad("fill.speed".into(), "must be at most 1e8 m/s"));
            }
            if 2.0 * r1 > w.size.min_element() {
                return Err(bad("fill.radius".into(), "discs wider than the box"));
            }
            if !(0.0..=0.5).contains(&f.overlap) {
                return Err(bad(
                    "fill.overlap".into(),
                    "must be a fraction of a diameter between 0 and 0.5",
                ));
            }
        }
        Ok(())
    }

    /// Builds the world: listed discs first, then the random fill.
    pub fn build(&self, origin: &str) -> Result<World, SceneError> {
        self.validate(origin)?;
        let w = &self.world;
        let mut world = World::new(w.size);
        world.laws = *w;
        world.method = self.simulation.method;
        world.broad_phase = self.simulation.broad_phase;
        world.substeps = self.simulation.substeps;
        world.particles = self
            .particles
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let color = p.color.unwrap_or_else(|| Color::palette(k));
                Particle {
                    spin: p.spin,
                    angle: p.angle,
                    ..Particle::new(p.pos, p.vel, p.mass, p.radius, color)
                }
            })
            .collect();
        if let Some(fill) = &self.fill {
            fill::add_fill(&mut world, fill).map_err(|reason| SceneError::Invalid {
                origin: origin.to_string(),
                field: "fill".into(),
                reason,
            })?;
        }
        Ok(world)
    }

    /// The scene that reproduces `world` exactly (listed discs, no fill).
    pub fn from_world(world: &World, name: Option<String>, description: Option<String>) -> Scene {
        Scene {
            name,
            description,
            translations: Default::default(),
            edited: false,
            overlapping: any_overlap(&world.particles, &world.laws),
            // Only a box has walls: a box's walls kept from before the edges
            // were opened would make the scene refuse to reopen.
            world: crate::laws::Laws {
                walls: if world.laws.boundary == crate::Boundary::Box {
                    world.laws.walls
                } else {
                    crate::Walls::ALL
                },
                ..world.laws
            },
            simulation: SimulationSpec {
                method: world.method,
                broad_phase: world.broad_phase,
                substeps: world.substeps,
                dt: None,
            },
            particles: world
                .particles
                .iter()
                .map(|p| ParticleSpec {
                    pos: p.pos,
                    vel: p.vel,
                    mass: p.mass,
                    radius: p.radius,
                    spin: p.spin,
                    angle: p.angle,
                    color: Some(p.color),
                })
                .collect(),
            fill: None,
        }
    }

    /// The scene as TOML text.
    pub fn to_toml(&self) -> String {
        // Serialising plain data with finite numbers cannot fail.
        toml::to_string_pretty(self).unwrap_or_default()
    }
}

/// The line (1-based) of `field` in scene text: `particles[2].mass` is the
/// `mass` line of the third `[[particles]]` table, `world.laws.size` the `size`
/// line of `[world]`; the table's header when the key is not written.
pub fn line_of(text: &str, field: &str) -> Option<usize> {
    let (table, key) = field.split_once('.').unwrap_or((field, ""));
    let (header, nth) = match table.split_once('[') {
        Some((name, index)) => (
            format!("[[{name}]]"),
            index.trim_end_matches(']').parse::<usize>().ok()?,
        ),
        None => (format!("[{table}]"), 0),
    };
    let lines: Vec<&str> = text.lines().collect();
    let start = lines
        .iter()
        .enumerate()
        .filter(|(_, l)| l.trim() == header)
        .nth(nth)
        .map(|(k, _)| k)?;
    let key = key.split(['.', '[']).next().unwrap_or("");
    let found = lines[start + 1..]
        .iter()
        .take_while(|l| !l.trim_start().starts_with('['))
        .position(|l| {
            let l = l.trim_start();
            !key.is_empty() && l.starts_with(key) && l[key.len()..].trim_start().starts_with('=')
        });
    Some(found.map_or(start, |k| start + 1 + k) + 1)
}

/// What [`fuzz_scene_bytes`] made of its input.
#[derive(Debug)]
pub enum FuzzOutcome {
    /// Refused while reading: not UTF-8, not TOML, or a bad value (the
    /// one-line message).
    Refused(String),
    /// Read, but refused while building (the one-line message).
    NotBuilt(String),
    /// Read and built.
    Built(Box<World>),
}

/// The body of the scene fuzz targets (`fuzz/fuzz_targets/scene.rs` and
/// `tests/fuzz.rs`): any bytes as a scene file named `origin`, read and built.
/// It must never panic, whatever the bytes.
pub fn fuzz_scene_bytes(bytes: &[u8], origin: &str) -> FuzzOutcome {
    let text = match std::str::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => return FuzzOutcome::Refused(format!("{origin}: not UTF-8 text: {e}")),
    };
    match Scene::parse(text, origin) {
        Err(e) => FuzzOutcome::Refused(e.to_string()),
        Ok(scene) => match scene.build(origin) {
            Err(e) => FuzzOutcome::NotBuilt(e.to_string()),
            Ok(world) => FuzzOutcome::Built(Box::new(world)),
        },
    }
}
