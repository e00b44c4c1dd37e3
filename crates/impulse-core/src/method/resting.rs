//! The impulse method where discs come to rest: gravity with restitution
//! below 1 (a pile, heavy discs on light ones).
//!
//! The plain impulse substep resolves each contact once, in no particular
//! order, before gravity acts. In a stack that cannot carry the weight: the
//! floor stops only the bottom disc, the discs above keep falling into each
//! other, push-apart lifts them back without touching their velocities, and
//! the lifted height falls again as kinetic energy. Measured in the stress
//! suite's pile (300 discs, e = 0.5, dt = 1/240 s): the pile never settled
//! (a jitter of about 0.2 m/s, overlaps up to 0.9 radius), and discs 100–400×
//! heavier sank through a layer of light ones to the floor.
//!
//! This substep separates impacts from resting contact, the way rigid-body
//! engines do (Guendelman, Bridson & Fedkiw 2003):
//!
//! 1. a contact (or a disc at a wall) that comes into the substep faster
//!    than the [`crate::impact::threshold`] is an *impact*: [`PASSES`] Gauss–Seidel
//!    sweeps apply the collision law with restitution e to the impacts
//!    (one made within the substep where the pair touched, as
//!    [`crate::resolution`] does it);
//! 2. then gravity acts (v ← v + g·h), and every contact that still
//!    approaches is *resting*: [`PASSES`] sweeps, bottom-up, make them
//!    stop (restitution 0), walls included, so support travels up;
//! 3. a last *shock-propagation* sweep treats the lower disc of each
//!    vertical contact as immovable, so a stack stops in one sweep whatever
//!    the mass ratio;
//! 4. push-apart leaves [`SLOP`] of the smaller radius overlapping, so a
//!    resting contact stays a contact next substep; it lifts only the upper
//!    disc of a near-vertical contact and splits the others by inverse mass;
//! 5. then positions move (x ← x + v·h) and the walls clamp as usual.
//!
//! The ledger gets the impacts of step 1, pairs and walls, at the
//! substep's start, and the wall hits step 5 catches at its end; the
//! sweeps of step 2 and the shock sweep are resting contact and record
//! nothing.
//!
//! Rough discs: impacts take the tangential law of [`crate::rough`], and
//! resting contacts (the sweeps with restitution 0, walls included) rub with
//! Coulomb friction where μ is given, so a disc sliding on the floor slows
//! at μ·g and starts to roll.
//!
//! Impacts keep the ordinary collision law with restitution e and
//! inverse-mass shares; momentum is not conserved pair by pair in step 3,
//! which only matters where the floor holds the discs anyway.

use crate::laws::Laws;
use crate::ledger::{Collision, Ledger, Wall, WallHit};
use crate::narrow_phase::Contact;
use crate::pipeline::Pipeline;
use crate::resolution::{collision_velocities, push_apart, rough_pair, rough_wall, Touch};
use crate::rough::Tangential;
use crate::stats::{Lap, StepStats};
use crate::{Boundary, Particle};
use glam::DVec2;

/// Gauss–Seidel sweeps over walls and contacts before the shock sweep.
pub const PASSES: usize = 10;
/// Overlap left in a resting contact, as a fraction of the smaller radius.
pub const SLOP: f64 = 0.005;
/// A contact is vertical enough to have a lower disc when its normal is
/// within about 84° of gravity (|n·ĝ| above this).
const VERTICAL: f64 = 0.1;
/// Push-apart lifts only the upper disc of a contact within about 32° of
/// vertical (|n·ĝ| above this), which takes in a disc sitting in the groove
/// between two below it (30°); see [`separate`].
const LIFT_ONLY: f64 = 0.85;

/// Buffers the substep reuses from step to step (no allocation per substep).
#[derive(Default)]
pub(crate) struct Scratch {
    /// Per disc and axis: did it come into the substep fast (an impact)?
    fast_at_walls: Vec<[bool; 2]>,
    /// Per contact: is it an impact?
    impacts: Vec<bool>,
    /// Per contact: when and where an impact touched, if that is defined
    /// (see [`crate::resolution`]'s "at the touch").
    touches: Vec<Option<Touch>>,
}

/// Whether a world needs this substep: gravity, and collisions that lose
/// energy so that discs come to rest.
pub(crate) fn applies(laws: &Laws) -> bool {
    laws.gravity != DVec2::ZERO && laws.restitution < 1.0
}

/// One impulse-method substep of length `h` with resting contact.
pub(crate) fn substep(
    pipeline: &mut Pipeline,
    scratch: &mut Scratch,
    particles: &mut [Particle],
    laws: &Laws,
    h: f64,
    stats: &mut StepStats,
    (ledger, time): (&mut Ledger, f64),
) {
    pipeline.detect(particles, laws, stats);
    let mut lap = Lap::start();
    let down = laws.gravity.normalize();
    let resting_speed = crate::impact::threshold(laws.gravity, h);
    // Which wall contacts are impacts is decided before gravity acts and
    // kept through the sweeps (the sweeps themselves can make a light disc
    // under a heavy one fast, and bouncing that would pump energy in).
    let Scratch {
        fast_at_walls,
        impacts,
        touches,
    } = scratch;
    fast_at_walls.clear();
    fast_at_walls.extend(
        particles
            .iter()
            .map(|p| [0, 1].map(|axis| p.vel[axis].abs() >= resting_speed)),
    );
    let contacts = &mut pipeline.contacts;
    let height =
        |c: &Contact| -(particles[c.i as usize].pos + particles[c.j as usize].pos).dot(down);
    contacts.sort_unstable_by(|a, b| {
        height(a)
            .total_cmp(&height(b))
            .then((a.i, a.j).cmp(&(b.i, b.j)))
    });
    // Likewise for pairs.
    impacts.clear();
    impacts.extend(
        contacts
            .iter()
            .map(|c| approach(particles, c) < -resting_speed),
    );
    // An impact made within the last substep is resolved where the pair
    // touched, with the normal there, and each disc moved on by τ·Δv.
    touches.clear();
    touches.extend(contacts.iter().zip(impacts.iter()).map(|(c, &impact)| {
        let reach = particles[c.i as usize].radius + particles[c.j as usize].radius;
        impact
            .then(|| Touch::of(c, reach, (resting_speed, h)))
            .flatten()
    }));
    let walls = Walls {
        laws,
        fast: fast_at_walls,
    };

    // Impacts first, with restitution (gravity has not acted yet, so this
    // is the collision the discs brought into the substep).
    // An impact is counted (and recorded) once, in the first sweep, if the
    // pair still approaches when its turn comes.
    let mut pair_impacts = 0;
    for pass in 0..PASSES {
        walls.hold(particles, stats, Hold::Impacts, (&mut *ledger, time));
        for ((c, &impact), touch) in contacts.iter().zip(impacts.iter()).zip(touches.iter()) {
            if impact {
                let (i, j) = (c.i as usize, c.j as usize);
                let before = [particles[i].vel, particles[j].vel];
                let spins_before = [particles[i].spin, particles[j].spin];
                let at_touch = touch.map(|t| Contact {
                    normal: t.normal,
                    ..*c
                });
                let c = at_touch.as_ref().unwrap_or(c);
                let counted = pass == 0 && approach(particles, c) < 0.0;
                let untouched = before[1] - before[0] == c.relative_velocity;
                collide(particles, c, laws.restitution, None, Some(laws.rough()));
                if let Some(t) = touch {
                    particles[i].pos += (particles[i].vel - before[0]) * t.ago;
                    particles[j].pos += (particles[j].vel - before[1]) * t.ago;
                }
                pair_impacts += usize::from(counted);
                stats.at_touch += usize::from(counted && touch.is_some() && untouched);
                stats.at_touch_changed += usize::from(counted && touch.is_some() && !untouched);
                if counted && ledger.is_on() {
                    ledger.push(Collision {
                        time,
                        discs: [i, j],
                        normal: c.normal,
                        masses: [particles[i].mass, particles[j].mass],
                        before,
                        after: [particles[i].vel, particles[j].vel],
                        radii: [particles[i].radius, particles[j].radius],
                        spins_before,
                        spins_after: [particles[i].spin, particles[j].spin],
                    });
                }
            }
        }
    }
    // Then gravity, and every contact still approaching is resting.
    for p in particles.iter_mut() {
        p.vel += laws.gravity * h;
    }
    let rubbing = laws.rough().resting();
    for _ in 0..PASSES {
        walls.hold(particles, stats, Hold::Resting, (&mut *ledger, time));
        for c in contacts.iter() {
            collide(particles, c, 0.0, None, rubbing);
        }
    }
    walls.hold(particles, stats, Hold::Resting, (&mut *ledger, time));
    // The shock sweep treats the lower disc as immovable, which is right
    // only when a floor holds the stack: with open or periodic edges it
    // changed the total momentum (a falling e = 0 cluster in an open world
    // gained 2 kg·m/s in 300 steps), so there the contacts keep the law.
    let shock = (laws.boundary == Boundary::Box && laws.walls.all()).then_some(down);
    for c in contacts.iter() {
        collide(particles, c, 0.0, shock, rubbing);
    }
    stats.pair_collisions += pair_impacts;
    stats.resting_contacts += contacts.len() - pair_impacts + walls.resting(particles);

    for c in contacts.iter() {
        separate(particles, c, laws, down);
        stats.max_overlap = stats.max_overlap.max(c.depth);
    }
    stats.timings.resolution += lap.lap();
    let travel = crate::integration::integrate(particles, DVec2::ZERO, h);
    stats.max_travel = stats.max_travel.max(travel);
    stats.timings.integration += lap.elapsed();
    // The sweeps held the discs at the walls: what the wall stage still
    // catches is a disc that moved into a wall during this substep, counted
    // there as an impact if fast; its resting contacts are counted above.
    let resting = stats.resting_contacts;
    pipeline.apply_boundary(particles, laws, (h, true), (ledger, time + h), stats);
    stats.resting_contacts = resting;
}

/// Normal velocity of disc j relative to disc i (negative: approaching).
fn approach(particles: &[Particle], c: &Contact) -> f64 {
    (particles[c.j as usize].vel - particles[c.i as usize].vel).dot(c.normal)
}

/// The lower and upper disc of a contact, if it is vertical enough to have
/// them: (lower, upper, normal from lower to upper).
fn lower_upper(c: &Contact, down: DVec2) -> Option<(usize, usize, DVec2)> {
    let along = c.normal.dot(down); // normal points from i to j
    if along > VERTICAL {
        Some((c.j as usize, c.i as usize, -c.normal))
    } else if along < -VERTICAL {
        Some((c.i as usize, c.j as usize, c.normal))
    } else {
        None
    }
}

/// The collision law with restitution `e` on one contact if it approaches,
/// then the tangential law `rub` (if any). With `shock` (the direction of
/// gravity) the lower disc of a vertical contact does not move and the
/// upper one takes the whole change.
fn collide(
    particles: &mut [Particle],
    c: &Contact,
    e: f64,
    shock: Option<DVec2>,
    rub: Option<Tangential>,
) {
    if approach(particles, c) >= 0.0 {
        return;
    }
    match shock.and_then(|down| lower_upper(c, down)) {
        Some((lower, upper, n)) => {
            let closing = (particles[upper].vel - particles[lower].vel).dot(n);
            particles[upper].vel -= (1.0 + e) * closing * n;
            if let Some(rub) = rub {
                let impulse = particles[upper].mass * (1.0 + e) * closing.abs();
                // The lower disc's surface moves too: rub against it.
                let below = particles[lower];
                let mut upper_rel = particles[upper];
                upper_rel.vel -= below.vel;
                upper_rel.spin += below.spin * below.radius / upper_rel.radius;
                rough_wall(&mut upper_rel, -n, impulse, rub);
                particles[upper].vel = upper_rel.vel + below.vel;
                particles[upper].spin =
                    upper_rel.spin - below.spin * below.radius / upper_rel.radius;
            }
        }
        None => {
            let (i, j) = (c.i as usize, c.j as usize);
            let (a, b) = (particles[i], particles[j]);
            let (va, vb) = collision_velocities(a.mass, b.mass, a.vel, b.vel, c.normal, e);
            particles[i].vel = va;
            particles[j].vel = vb;
            if let Some(rub) = rub {
                let impulse = a.mass * (va - a.vel).dot(c.normal).abs();
                let (head, tail) = particles.split_at_mut(j);
                rough_pair(&mut head[i], &mut tail[0], c.normal, impulse, rub);
            }
        }
    }
}

/// Which wall contacts a sweep handles.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Hold {
    /// Discs that came in fast: they bounce with the wall restitution.
    Impacts,
    /// Every disc touching a wall: it stops.
    Resting,
}

/// The walls of a box as constraints in the sweeps.
struct Walls<'a> {
    laws: &'a Laws,
    /// Per disc and axis: did it come in fast (an impact, with restitution)?
    fast: &'a [[bool; 2]],
}

impl Walls<'_> {
    /// Discs touching a wall (to the slop) that came in slowly: resting on it.
    fn resting(&self, particles: &[Particle]) -> usize {
        if self.laws.boundary != Boundary::Box {
            return 0;
        }
        let (size, walls) = (self.laws.size, self.laws.walls);
        let mut count = 0;
        for (p, fast) in particles.iter().zip(self.fast) {
            let slack = SLOP * p.radius;
            for axis in 0..2 {
                let low = walls.at(axis, false) && p.pos[axis] - p.radius <= slack;
                let high = walls.at(axis, true) && p.pos[axis] + p.radius >= size[axis] - slack;
                count += usize::from((low || high) && !fast[axis]);
            }
        }
        count
    }

    /// Stops discs that touch a wall from moving into it, as `which` says.
    /// The impulse is booked every time (it is all given by the wall), a
    /// hit only for impacts, and each hit goes into the ledger at `time`.
    fn hold(
        &self,
        particles: &mut [Particle],
        stats: &mut StepStats,
        which: Hold,
        (ledger, time): (&mut Ledger, f64),
    ) {
        if self.laws.boundary != Boundary::Box {
            return;
        }
        let size = self.laws.size;
        for (k, (p, fast)) in particles.iter_mut().zip(self.fast).enumerate() {
            let slack = SLOP * p.radius;
            for axis in 0..2 {
                let walls = self.laws.walls;
                let low =
                    walls.at(axis, false) && p.pos[axis] - p.radius <= slack && p.vel[axis] < 0.0;
                let high = walls.at(axis, true)
                    && p.pos[axis] + p.radius >= size[axis] - slack
                    && p.vel[axis] > 0.0;
                let bounce = which == Hold::Impacts && fast[axis];
                if (low || high) && (bounce || which == Hold::Resting) {
                    let e = if bounce {
                        self.laws.wall_restitution
                    } else {
                        0.0
                    };
                    let came_in = (p.vel, p.spin);
                    let before = p.vel[axis];
                    p.vel[axis] = -e * before;
                    let impulse = p.mass * (p.vel[axis] - before).abs();
                    stats.wall_impulse += impulse;
                    stats.wall_hits += usize::from(bounce);
                    let rub = if bounce {
                        Some(self.laws.wall_rough())
                    } else {
                        self.laws.wall_rough().resting()
                    };
                    if let Some(rub) = rub {
                        let mut into = DVec2::ZERO;
                        into[axis] = if low { -1.0 } else { 1.0 };
                        rough_wall(p, into, impulse, rub);
                    }
                    if bounce && ledger.is_on() {
                        ledger.push(WallHit {
                            time,
                            disc: k,
                            wall: Wall::at(axis, high),
                            mass: p.mass,
                            radius: p.radius,
                            before: came_in.0,
                            after: p.vel,
                            spin_before: came_in.1,
                            spin_after: p.spin,
                        });
                    }
                }
            }
        }
    }
}

/// Push-apart down to the slop. A contact within [`LIFT_ONLY`] of vertical
/// lifts only its upper disc (pushing the lower one down would drive it
/// into its own support: heavy discs sank into a row of light ones); any
/// other splits by inverse mass, which leaves the centre of mass and so the
/// potential energy where they were. Lifting on every contact with a lower
/// disc (within 84° of vertical) was tried and dropped: each lift adds
/// m·g·depth of potential energy that falls back as speed, and on the
/// slanted contacts of a heap that never ended: the preset pile kept 0.1 J
/// of jitter and 170 impacts a second between discs after 20 s, where it
/// now settles to 0.04 J with none.
fn separate(particles: &mut [Particle], c: &Contact, laws: &Laws, down: DVec2) {
    let (i, j) = (c.i as usize, c.j as usize);
    let d = laws
        .boundary
        .separation(particles[i].pos, particles[j].pos, laws.size);
    let dist = d.length();
    let (ri, rj) = (particles[i].radius, particles[j].radius);
    let excess = ri + rj - dist - SLOP * ri.min(rj);
    if excess <= 0.0 || dist == 0.0 {
        return;
    }
    let normal = d / dist;
    let along = normal.dot(down);
    if along.abs() > LIFT_ONLY {
        let (upper, n) = if along > 0.0 {
            (i, -normal)
        } else {
            (j, normal)
        };
        particles[upper].pos += n * excess;
    } else {
        let (head, tail) = particles.split_at_mut(j);
        push_apart(&mut head[i], &mut tail[0], normal, excess);
    }
}
