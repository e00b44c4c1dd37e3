//! What is drawn over the discs, as the person chose it: arrows, readouts,
//! the centre of mass, the contact at an impact, the palette. Pure data:
//! the world's drawing reads it.

use glam::DVec2;
use impulse::World;

/// Arrows show where a disc will be this many seconds from now.
pub const ARROW_SECONDS: f64 = 0.5;

/// Δp arrows are drawn in scenes of up to this many discs: in a gas they
/// would hide the discs (the checkbox says so).
pub const DELTA_P_MAX_DISCS: usize = 40;

/// Which discs carry a text readout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadoutScope {
    /// None.
    Off,
    /// Only the selected disc.
    Selected,
    /// Every disc on screen.
    All,
}

impl ReadoutScope {
    /// Off → Selected → All → Off.
    pub fn next(self) -> Self {
        match self {
            ReadoutScope::Off => ReadoutScope::Selected,
            ReadoutScope::Selected => ReadoutScope::All,
            ReadoutScope::All => ReadoutScope::Off,
        }
    }

    /// "off", "selected" or "all".
    pub fn name(self) -> &'static str {
        match self {
            ReadoutScope::Off => "off",
            ReadoutScope::Selected => "selected",
            ReadoutScope::All => "all",
        }
    }
}

/// The overlay toggles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overlays {
    /// Velocity arrows.
    pub velocity: bool,
    /// Momentum arrows.
    pub momentum: bool,
    /// For a moment after each collision, each disc's change of momentum.
    pub delta_p: bool,
    /// Text readouts.
    pub readouts: ReadoutScope,
    /// Colour discs by the colour-blind-safe palette, not the scene's colours.
    pub safe_palette: bool,
    /// The centre of mass and its velocity.
    pub center_of_mass: bool,
    /// The contact's normal and tangent at the instant of impact.
    pub contact: bool,
    /// The centre-of-mass view, with the camera's offset from the centre
    /// of mass when it was turned on.
    pub com_view: Option<DVec2>,
}

impl Default for Overlays {
    fn default() -> Self {
        Overlays {
            velocity: true,
            momentum: false,
            delta_p: true,
            readouts: ReadoutScope::Selected,
            safe_palette: false,
            center_of_mass: false,
            contact: false,
            com_view: None,
        }
    }
}

impl Overlays {
    /// The colour disc `i` of `world` is drawn in: its own, or with the
    /// colour-blind-safe palette on, the palette's by its number. The
    /// world, the readouts, the ledger, the Discs table and the Momenta
    /// diagram all ask here: with the palette on, the ledger's dots and the
    /// table's had kept the scene's colours, no longer the discs'.
    pub fn disc_color(&self, world: &World, i: usize) -> impulse::Color {
        match world.particles.get(i) {
            Some(p) if !self.safe_palette => p.color,
            _ => impulse::Color::palette(i),
        }
    }
}

/// How long a collision's Δp arrows stay (simulated seconds).
pub const DELTA_P_SECONDS: f64 = 1.0;

/// A disc's change of momentum m·(v′ − v) in a recent collision between
/// discs, to be drawn as an arrow on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MomentumChange {
    /// The disc, by its index in the world's list.
    pub disc: usize,
    /// Its change of momentum (kg·m/s).
    pub change: DVec2,
    /// How much of the arrow's colour is left: 1 at the collision, 0.3
    /// after [`DELTA_P_SECONDS`].
    pub fade: f32,
}

/// The changes of momentum of the collisions between discs in the last
/// [`DELTA_P_SECONDS`], but only those after `edited_at`: a disc the person
/// has since changed (a mass typed, a velocity aimed) no longer carries the
/// change a collision made to what it was. A wall's push, twice the
/// momentum, would cross the box: the lesson is that the two are equal and
/// opposite.
pub fn momentum_changes(world: &World, edited_at: Option<f64>) -> Vec<MomentumChange> {
    let mut changes = Vec::new();
    for impact in world.ledger.impacts() {
        let age = world.time - impact.time();
        let fresh = edited_at.is_none_or(|at| impact.time() > at);
        let impulse::ledger::Impact::Pair(c) = impact else {
            continue;
        };
        if !fresh || !(0.0..=DELTA_P_SECONDS).contains(&age) {
            continue;
        }
        let fade = (1.0 - 0.7 * age / DELTA_P_SECONDS) as f32;
        changes.extend((0..2).map(|k| MomentumChange {
            disc: c.discs[k],
            change: c.masses[k] * (c.after[k] - c.before[k]),
            fade,
        }));
    }
    changes
}

/// Whether spin is worth showing: a disc spins, or the laws can make one
/// spin (a roughness β above −1 between discs or at the walls, or friction,
/// which rubs resting discs). Only then do discs carry their spin line and
/// the readouts, the Discs table, the top bar and the Speeds tab their spin
/// values, so the smooth presets look as they always did.
pub fn spin_shown(world: &World) -> bool {
    let laws = &world.laws;
    laws.tangential_restitution > -1.0
        || laws.wall_tangential_restitution > -1.0
        || laws.friction.is_some()
        || world.particles.iter().any(|p| p.spin != 0.0)
}
