//! Resolution, the third stage: turn contacts into new velocities and positions.
//!
//! Velocities split along the contact normal n̂ and tangent t̂. Only the normal
//! parts change, by the one-dimensional collision law with restitution e:
//!
//! ```text
//! v'₁ₙ = ((m₁ − e·m₂)·v₁ₙ + (1 + e)·m₂·v₂ₙ) / (m₁ + m₂)
//! v'₂ₙ = ((m₂ − e·m₁)·v₂ₙ + (1 + e)·m₁·v₁ₙ) / (m₁ + m₂)
//! ```
//!
//! and only for pairs that approach (v₂ₙ − v₁ₙ < 0). A pair that already
//! separates is left alone, which is the cure for the seeds' "sticky problem"
//! (overlapping discs being bounced back into each other every frame).
//!
//! Rough discs (a tangential restitution above −1, see [`crate::rough`])
//! then take a tangential impulse at the contact point, which changes their
//! spins; a resting contact rubs with Coulomb friction if μ is given.
//!
//! Overlap is then removed by moving the discs apart along n̂, each by a share
//! proportional to its inverse mass, so the centre of mass does not move.
//!
//! **At the touch** ([`Rule::at_touch`], the impulse method): an overlap
//! found now was made by the previous substep, so the discs touched τ
//! seconds ago, τ ∈ [0, h]. For an impact the pair is rewound along the
//! velocities it had when found ([`Contact::relative_velocity`]) to where
//! |x₂ − x₁| = r₁ + r₂; the normal is taken there (and, for rough discs, the
//! contact point with it), the impulse applied, and each disc moved on by
//! τ·Δv, as if the impulse had acted at the touch. An isolated impact then
//! gives the closed form, and total angular momentum (orbital plus spin) is
//! kept, since the impulse acts along the line of centres at the touch.
//! Where τ is not defined (discs overlapping from the start, resting
//! contacts, a pair not closing when found) the contact falls back to the
//! normal where the discs overlap and push-apart.

mod bands;
mod spans;

pub use bands::{band_of, Banded, BANDED_MIN_CONTACTS, BANDS};
pub use spans::SPANS_MIN_CONTACTS;

use crate::ledger::{Collision, Ledger};
use crate::narrow_phase::Contact;
use crate::particle::Particle;
use crate::rough::{Side, Tangential};
use glam::DVec2;

/// The law a step's contacts obey.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactLaw {
    /// Restitution e between discs.
    pub restitution: f64,
    /// Closing speed above which a contact is an impact ([`crate::impact`]).
    pub impact_speed: f64,
    /// What impacts do along the contact.
    pub tangential: Tangential,
    /// Length of the substep that made the overlaps (s): how far back a
    /// [`Rule::at_touch`] resolution may rewind a pair (0: not at all).
    pub substep: f64,
}

impl ContactLaw {
    /// Smooth discs with restitution `e`, impacts above `impact_speed`,
    /// resolved where they overlap (no substep to rewind).
    pub fn smooth(restitution: f64, impact_speed: f64) -> ContactLaw {
        ContactLaw {
            restitution,
            impact_speed,
            tangential: Tangential::SMOOTH,
            substep: 0.0,
        }
    }
}

/// What resolving one step's contacts did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ResolutionReport {
    /// Impacts: pairs approaching faster than the impact speed, whose
    /// velocities were changed.
    pub collisions: usize,
    /// Resting contacts: approaching pairs slower than that (resolved too,
    /// but not counted or recorded as collisions).
    pub resting: usize,
    /// Impacts resolved where the discs touched ([`Rule::at_touch`]) whose
    /// discs no earlier contact of the pass had changed: each keeps the
    /// angular momentum exactly. The others fell back to the overlap's
    /// normal and push-apart, or (a disc met twice in one pass) were
    /// rewound along velocities the earlier contact had changed.
    pub at_touch: usize,
    /// Impacts resolved at the touch along a velocity an earlier contact
    /// of the pass had changed (a disc met twice in one pass).
    pub at_touch_changed: usize,
    /// Deepest overlap found (m).
    pub max_overlap: f64,
    /// Contacts resolved on threads side by side ([`StepStats`]'s
    /// `contacts_side_by_side`).
    ///
    /// [`StepStats`]: crate::stats::StepStats
    pub side_by_side: usize,
}

impl ResolutionReport {
    /// Both reports together: collisions added, the deeper overlap.
    pub fn merge(self, other: ResolutionReport) -> ResolutionReport {
        ResolutionReport {
            collisions: self.collisions + other.collisions,
            resting: self.resting + other.resting,
            at_touch: self.at_touch + other.at_touch,
            at_touch_changed: self.at_touch_changed + other.at_touch_changed,
            max_overlap: self.max_overlap.max(other.max_overlap),
            side_by_side: self.side_by_side + other.side_by_side,
        }
    }
}

/// Which velocity changes a contact gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Velocities {
    /// The collision law, only for pairs that approach (the cure for sticking).
    ApproachingOnly,
    /// The collision law for every overlapping pair (the seed's method).
    Always,
    /// None: position-based methods imply velocity from positions.
    Never,
}

/// How overlap is removed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PushApart {
    /// Shares proportional to inverse mass: the centre of mass stays put.
    InverseMass,
    /// Half each, whatever the masses (the seeds' rule; moves the centre of mass).
    HalfEach,
}

/// A resolution rule: what a contact does to velocities and positions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rule {
    /// Velocity changes.
    pub velocities: Velocities,
    /// Overlap removal.
    pub push_apart: PushApart,
    /// Resolve impacts where the discs touched, not where they overlap
    /// (see the module's doc); falls back to the overlap where that moment
    /// is not defined.
    pub at_touch: bool,
}

impl Rule {
    /// Impulse method: approaching pairs only, impacts at the touch, else
    /// inverse-mass push-apart.
    pub const IMPULSE: Rule = Rule {
        velocities: Velocities::ApproachingOnly,
        push_apart: PushApart::InverseMass,
        at_touch: true,
    };
    /// The presentation's method: every overlapping pair, half each.
    pub const SEED: Rule = Rule {
        velocities: Velocities::Always,
        push_apart: PushApart::HalfEach,
        at_touch: false,
    };
    /// Position projection (Verlet): no velocity change, inverse-mass push.
    pub const PROJECTION: Rule = Rule {
        velocities: Velocities::Never,
        push_apart: PushApart::InverseMass,
        at_touch: false,
    };
}

/// Resolves `contacts` in order with `law`; each impact goes into `ledger`
/// (if it is on) at time `time`.
pub fn resolve_contacts(
    particles: &mut [Particle],
    contacts: &[Contact],
    law: ContactLaw,
    rule: Rule,
    ledger: &mut Ledger,
    time: f64,
) -> ResolutionReport {
    let mut report = ResolutionReport::default();
    for (k, c) in contacts.iter().enumerate() {
        // The discs a few contacts on, asked for now: contacts come in order
        // of their first disc, their second anywhere, and in a large scene
        // (or after the narrow phase ran on other cores) neither is cached.
        if let Some(ahead) = contacts.get(k + PREFETCH_CONTACTS_AHEAD) {
            crate::parallel::prefetch(&particles[ahead.i as usize]);
            crate::parallel::prefetch(&particles[ahead.j as usize]);
        }
        let (a, b) = pair_mut(particles, c.i as usize, c.j as usize);
        resolve_contact(a, b, c, law, rule, (ledger, time), &mut report);
    }
    report
}

/// How many contacts ahead [`resolve_contacts`] prefetches the discs.
const PREFETCH_CONTACTS_AHEAD: usize = 8;

/// Resolves one contact between `a` (disc `c.i`) and `b` (disc `c.j`),
/// adding to `report` and recording a collision in `ledger` at `time`.
fn resolve_contact(
    a: &mut Particle,
    b: &mut Particle,
    c: &Contact,
    law: ContactLaw,
    rule: Rule,
    (ledger, time): (&mut Ledger, f64),
    report: &mut ResolutionReport,
) {
    let (restitution, impact_speed) = (law.restitution, law.impact_speed);
    let before = [a.vel, b.vel];
    let spins_before = [a.spin, b.spin];
    let touch = match rule.at_touch {
        true => Touch::of(c, a.radius + b.radius, (law.impact_speed, law.substep)),
        false => None,
    };
    let normal = touch.map_or(c.normal, |t| t.normal);
    // No earlier contact of this pass changed either disc: rewound and
    // moved on along the same velocities, the pair keeps L exactly.
    let untouched = touch.is_some() && b.vel - a.vel == c.relative_velocity;
    let closing = (a.vel - b.vel).dot(normal);
    let collided = match rule.velocities {
        Velocities::ApproachingOnly => collide(a, b, normal, restitution),
        Velocities::Always => {
            apply_collision_law(a, b, normal, restitution);
            true
        }
        Velocities::Never => false,
    };
    let impact = collided && crate::impact::is_impact(closing, impact_speed);
    if collided {
        let rubs = if impact {
            Some(law.tangential)
        } else {
            law.tangential.resting()
        };
        if let Some(rubs) = rubs {
            let normal_impulse = a.mass * (a.vel - before[0]).dot(normal).abs();
            rough_pair(a, b, normal, normal_impulse, rubs);
        }
    }
    report.collisions += usize::from(impact);
    report.at_touch += usize::from(impact && untouched);
    report.at_touch_changed += usize::from(impact && touch.is_some() && !untouched);
    report.resting += usize::from(collided && !impact);
    if impact && ledger.is_on() {
        ledger.push(Collision {
            time,
            discs: [c.i as usize, c.j as usize],
            normal,
            masses: [a.mass, b.mass],
            before,
            after: [a.vel, b.vel],
            radii: [a.radius, b.radius],
            spins_before,
            spins_after: [a.spin, b.spin],
        });
    }
    match (touch, rule.push_apart) {
        // On from the touch with the new velocities: no overlap is left.
        (Some(t), _) if collided => {
            a.pos += (a.vel - before[0]) * t.ago;
            b.pos += (b.vel - before[1]) * t.ago;
        }
        (_, PushApart::InverseMass) => push_apart(a, b, c.normal, c.depth),
        (_, PushApart::HalfEach) => {
            a.pos -= c.normal * (0.5 * c.depth);
            b.pos += c.normal * (0.5 * c.depth);
        }
    }
    report.max_overlap = report.max_overlap.max(c.depth);
}

/// When and where an overlapping pair touched (see the module's doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Touch {
    /// How long ago (s), in [0, the substep].
    pub(crate) ago: f64,
    /// Unit normal from the first disc to the second at that moment.
    pub(crate) normal: DVec2,
}

impl Touch {
    /// The touch of contact `c` between discs whose radii add up to
    /// `reach`, if it was an impact (closing faster than `impact_speed`)
    /// made within the last `substep` seconds: the root τ ≥ 0 of
    /// |d − τ·u| = reach, with d the centres' separation and u the
    /// relative velocity when the contact was found.
    pub(crate) fn of(
        c: &Contact,
        reach: f64,
        (impact_speed, substep): (f64, f64),
    ) -> Option<Touch> {
        let u = c.relative_velocity;
        let distance = reach - c.depth;
        let d = c.normal * distance;
        let du = d.dot(u);
        // Closing, and fast enough to be an impact (resting contacts and
        // pairs not closing when found keep the overlap's rule).
        if !crate::impact::is_impact(-u.dot(c.normal), impact_speed) || du >= 0.0 {
            return None;
        }
        // |u|²τ² − 2(d·u)τ + (|d|² − reach²) = 0 has one root of each sign
        // (|d| < reach); the positive one, written without cancellation.
        let gap = (distance - reach) * (distance + reach);
        let root = (du * du - u.length_squared() * gap).sqrt();
        let ago = gap / (du - root);
        if !(0.0..=substep).contains(&ago) {
            return None; // overlapping from before the substep began
        }
        // |d − τ·u| = reach to rounding: a unit normal without a square root.
        Some(Touch {
            ago,
            normal: (d - u * ago) / reach,
        })
    }
}

/// Applies the collision law along `normal` (from `a` to `b`) if the pair
/// approaches; returns whether it did.
pub fn collide(a: &mut Particle, b: &mut Particle, normal: DVec2, restitution: f64) -> bool {
    let (v1n, v2n) = (a.vel.dot(normal), b.vel.dot(normal));
    if v2n - v1n >= 0.0 {
        return false; // separating or resting: never re-resolved
    }
    apply_collision_law(a, b, normal, restitution);
    true
}

/// The collision law along `normal`, whether or not the pair approaches.
pub fn apply_collision_law(a: &mut Particle, b: &mut Particle, normal: DVec2, restitution: f64) {
    (a.vel, b.vel) = collision_velocities(a.mass, b.mass, a.vel, b.vel, normal, restitution);
}

/// Velocities after the collision law along `normal` (from disc 1 to disc 2):
/// normal parts by the 1D law with restitution `e`, tangential parts kept.
pub fn collision_velocities(
    m1: f64,
    m2: f64,
    v1: DVec2,
    v2: DVec2,
    normal: DVec2,
    e: f64,
) -> (DVec2, DVec2) {
    let (v1n, v2n) = (v1.dot(normal), v2.dot(normal));
    let total = m1 + m2;
    let v1n_after = ((m1 - e * m2) * v1n + (1.0 + e) * m2 * v2n) / total;
    let v2n_after = ((m2 - e * m1) * v2n + (1.0 + e) * m1 * v1n) / total;
    // The tangential parts are untouched: only the normal components change.
    (
        v1 + (v1n_after - v1n) * normal,
        v2 + (v2n_after - v2n) * normal,
    )
}

/// The tangential impulse of `law` on a contact along `normal` (from `a`
/// to `b`) that took `normal_impulse`.
pub fn rough_pair(
    a: &mut Particle,
    b: &mut Particle,
    normal: DVec2,
    normal_impulse: f64,
    law: Tangential,
) {
    if let Some((sa, sb)) = law.pair(normal, normal_impulse, side(a), side(b)) {
        (a.vel, a.spin) = (sa.vel, sa.spin);
        (b.vel, b.spin) = (sb.vel, sb.spin);
    }
}

/// The tangential impulse of `law` on disc `a` against an immovable
/// support whose normal `into` points from the disc into it, after a
/// normal impulse `normal_impulse`.
pub fn rough_wall(a: &mut Particle, into: DVec2, normal_impulse: f64, law: Tangential) {
    if let Some(sa) = law.wall(into, normal_impulse, side(a)) {
        (a.vel, a.spin) = (sa.vel, sa.spin);
    }
}

/// A disc as one side of a rough contact.
pub fn side(p: &Particle) -> Side {
    Side {
        mass: p.mass,
        radius: p.radius,
        vel: p.vel,
        spin: p.spin,
    }
}

/// Moves `a` and `b` apart along `normal` by `depth` in total, split by
/// inverse mass so that m₁·Δx₁ + m₂·Δx₂ = 0.
pub fn push_apart(a: &mut Particle, b: &mut Particle, normal: DVec2, depth: f64) {
    let total = a.mass + b.mass;
    a.pos -= normal * (depth * b.mass / total);
    b.pos += normal * (depth * a.mass / total);
}

/// Two distinct mutable elements of a slice, `i < j`.
fn pair_mut(particles: &mut [Particle], i: usize, j: usize) -> (&mut Particle, &mut Particle) {
    debug_assert!(i < j, "pairs are ordered i < j");
    let (head, tail) = particles.split_at_mut(j);
    (&mut head[i], &mut tail[0])
}
