//! The collision ledger: the last impacts, newest last, each with the
//! velocities and spins before and after, so a lesson can show momentum and
//! kinetic energy per disc and in total across one impact, and the normal
//! and tangential components the collision law acts on. An impact is
//! either a collision between two discs ([`Collision`]) or a disc hitting
//! a wall ([`WallHit`]); the ledger keeps both, as [`Impact`]s, in the
//! order they were recorded.
//!
//! Only impacts go in: contacts closing faster than
//! [`crate::impact::threshold`], the same ones the step counters count
//! (`StepStats::pair_collisions` and `StepStats::wall_hits`). A disc
//! resting on the floor, or a pile resting on itself, records nothing.
//! With the ledger on from the start, [`Ledger::recorded`] and
//! [`Ledger::recorded_walls`] equal the world's `total_pair_collisions`
//! and `total_wall_hits`, in every method but `verlet`, whose pair
//! collisions are counted but not recorded: its projection moves positions
//! and the velocities come out of the whole substep, so there is no
//! before and after of one collision to show. Its wall hits are recorded:
//! the wall stage reflects a velocity as in the other methods. Periodic and
//! open edges have no walls, and so no wall impacts.
//!
//! Off by default (a lab run does not pay for it); the window turns it on.

use glam::DVec2;
use std::collections::VecDeque;

/// One pair collision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// When (s, world time).
    pub time: f64,
    /// The two discs (indices into the world's particles at that moment).
    pub discs: [usize; 2],
    /// Unit normal from the first disc to the second.
    pub normal: DVec2,
    /// Their masses (kg).
    pub masses: [f64; 2],
    /// Velocities just before (m/s).
    pub before: [DVec2; 2],
    /// Velocities just after (m/s).
    pub after: [DVec2; 2],
    /// Their radii (m).
    pub radii: [f64; 2],
    /// Spins just before (rad/s, counter-clockwise).
    pub spins_before: [f64; 2],
    /// Spins just after: they differ only where contacts are rough.
    pub spins_after: [f64; 2],
}

impl Collision {
    /// The two discs, the lower number first, as a person names the pair
    /// ("discs 0 and 1"), whichever way round the search met them.
    pub fn discs_in_order(&self) -> [usize; 2] {
        let [a, b] = self.discs;
        [a.min(b), a.max(b)]
    }

    /// Momentum of disc `k` (0 or 1) before and after.
    pub fn momentum(&self, k: usize) -> (DVec2, DVec2) {
        (
            self.masses[k] * self.before[k],
            self.masses[k] * self.after[k],
        )
    }

    /// Kinetic energy of disc `k` before and after.
    pub fn kinetic_energy(&self, k: usize) -> (f64, f64) {
        let e = |v: DVec2| 0.5 * self.masses[k] * v.length_squared();
        (e(self.before[k]), e(self.after[k]))
    }

    /// Rotational energy ½·I·ω² of disc `k` before and after.
    pub fn rotational_energy(&self, k: usize) -> (f64, f64) {
        let inertia = 0.5 * self.masses[k] * self.radii[k] * self.radii[k];
        let e = |w: f64| 0.5 * inertia * w * w;
        (e(self.spins_before[k]), e(self.spins_after[k]))
    }

    /// Change of the pair's total momentum and kinetic energy.
    pub fn total_change(&self) -> (DVec2, f64) {
        let mut dp = DVec2::ZERO;
        let mut dke = 0.0;
        for k in 0..2 {
            let (p0, p1) = self.momentum(k);
            let (e0, e1) = self.kinetic_energy(k);
            dp += p1 - p0;
            dke += e1 - e0;
        }
        (dp, dke)
    }

    /// The unit normal from the lower-numbered disc to the other: the
    /// direction a person reading "discs 1 and 2" takes as positive.
    /// (`normal` goes from `discs[0]`, whichever of the two the search met
    /// first, so its sign alone changes from one collision to the next.)
    pub fn normal_in_order(&self) -> DVec2 {
        if self.discs[0] <= self.discs[1] {
            self.normal
        } else {
            -self.normal
        }
    }

    /// Disc `k`'s velocity split along [`Self::normal_in_order`] and the
    /// tangent (the normal turned a quarter counter-clockwise), before and
    /// after: ((normal, tangent) before, (normal, tangent) after).
    pub fn components(&self, k: usize) -> ((f64, f64), (f64, f64)) {
        let n = self.normal_in_order();
        let t = n.perp();
        let split = |v: DVec2| (v.dot(n), v.dot(t));
        (split(self.before[k]), split(self.after[k]))
    }
}

/// One side of the box (the same names as `Walls`: y is up, so the bottom
/// is the floor).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Wall {
    /// The side x = 0.
    Left,
    /// The side x = width.
    Right,
    /// The side y = 0.
    Bottom,
    /// The side y = height.
    Top,
}

impl Wall {
    /// The four sides, in the order of `Walls::NAMES`.
    pub const ALL: [Wall; 4] = [Wall::Left, Wall::Right, Wall::Bottom, Wall::Top];

    /// The wall at the lower (`upper = false`) or upper end of an axis
    /// (0: x, 1: y).
    pub fn at(axis: usize, upper: bool) -> Wall {
        match (axis, upper) {
            (0, false) => Wall::Left,
            (0, true) => Wall::Right,
            (_, false) => Wall::Bottom,
            (_, true) => Wall::Top,
        }
    }

    /// The axis it stands across (0: x, 1: y).
    pub fn axis(self) -> usize {
        match self {
            Wall::Left | Wall::Right => 0,
            Wall::Bottom | Wall::Top => 1,
        }
    }

    /// Whether it is at the upper end of its axis (right or top).
    pub fn is_upper(self) -> bool {
        matches!(self, Wall::Right | Wall::Top)
    }

    /// "left", "right", "bottom" or "top", as in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Wall::Left => "left",
            Wall::Right => "right",
            Wall::Bottom => "bottom",
            Wall::Top => "top",
        }
    }

    /// The unit normal from the wall into the box: the direction the wall
    /// pushes a disc that hits it.
    pub fn normal(self) -> DVec2 {
        let mut n = DVec2::ZERO;
        n[self.axis()] = if self.is_upper() { -1.0 } else { 1.0 };
        n
    }
}

/// One disc hitting a wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallHit {
    /// When (s, world time).
    pub time: f64,
    /// The disc (its index into the world's particles at that moment).
    pub disc: usize,
    /// The wall it hit.
    pub wall: Wall,
    /// Its mass (kg).
    pub mass: f64,
    /// Its radius (m).
    pub radius: f64,
    /// Velocity just before (m/s).
    pub before: DVec2,
    /// Velocity just after (m/s).
    pub after: DVec2,
    /// Spin just before (rad/s, counter-clockwise).
    pub spin_before: f64,
    /// Spin just after: it differs only where the wall is rough.
    pub spin_after: f64,
}

impl WallHit {
    /// The unit normal from the wall into the box.
    pub fn normal(&self) -> DVec2 {
        self.wall.normal()
    }

    /// How fast the disc came in towards the wall (m/s, positive).
    pub fn closing_speed(&self) -> f64 {
        let v = self.before[self.wall.axis()];
        if self.wall.is_upper() {
            v
        } else {
            -v
        }
    }

    /// Momentum before and after.
    pub fn momentum(&self) -> (DVec2, DVec2) {
        (self.mass * self.before, self.mass * self.after)
    }

    /// Kinetic energy before and after.
    pub fn kinetic_energy(&self) -> (f64, f64) {
        let e = |v: DVec2| 0.5 * self.mass * v.length_squared();
        (e(self.before), e(self.after))
    }

    /// Rotational energy ½·I·ω² before and after.
    pub fn rotational_energy(&self) -> (f64, f64) {
        let inertia = 0.5 * self.mass * self.radius * self.radius;
        let e = |w: f64| 0.5 * inertia * w * w;
        (e(self.spin_before), e(self.spin_after))
    }

    /// The impulse the wall gave the disc, m·(v′ − v) (kg·m/s): along the
    /// normal −(1 + e)·m·vₙ, plus along the wall what a rough wall took.
    pub fn wall_impulse(&self) -> DVec2 {
        self.mass * (self.after - self.before)
    }

    /// Change of the disc's momentum (the wall's impulse) and kinetic
    /// energy.
    pub fn total_change(&self) -> (DVec2, f64) {
        let (e0, e1) = self.kinetic_energy();
        (self.wall_impulse(), e1 - e0)
    }

    /// The velocity split along the normal (into the box) and the tangent,
    /// before and after: ((normal, tangent) before, (normal, tangent)
    /// after).
    pub fn components(&self) -> ((f64, f64), (f64, f64)) {
        let n = self.normal();
        let t = n.perp();
        let split = |v: DVec2| (v.dot(n), v.dot(t));
        (split(self.before), split(self.after))
    }
}

/// One entry of the ledger: a collision between discs or a wall hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Impact {
    /// Two discs collided.
    Pair(Collision),
    /// A disc hit a wall.
    Wall(WallHit),
}

// History snapshots clone the ledger: a wall entry must not make an entry
// larger than a pair collision already was (the enum's tag aside).
const _: () = assert!(std::mem::size_of::<Impact>() <= std::mem::size_of::<Collision>() + 8);

impl From<Collision> for Impact {
    fn from(c: Collision) -> Self {
        Impact::Pair(c)
    }
}

impl From<WallHit> for Impact {
    fn from(w: WallHit) -> Self {
        Impact::Wall(w)
    }
}

impl Impact {
    /// When (s, world time).
    pub fn time(&self) -> f64 {
        match self {
            Impact::Pair(c) => c.time,
            Impact::Wall(w) => w.time,
        }
    }

    /// The discs involved: two for a pair, one for a wall hit.
    pub fn discs(&self) -> &[usize] {
        match self {
            Impact::Pair(c) => &c.discs,
            Impact::Wall(w) => std::slice::from_ref(&w.disc),
        }
    }

    /// How fast the contact closed (m/s): the normal approach of the pair,
    /// or the disc's speed into the wall.
    pub fn closing_speed(&self) -> f64 {
        match self {
            Impact::Pair(c) => (c.before[0] - c.before[1]).dot(c.normal),
            Impact::Wall(w) => w.closing_speed(),
        }
    }

    /// Change of the involved discs' total momentum and kinetic energy:
    /// zero momentum for a pair, the wall's impulse for a wall hit.
    pub fn total_change(&self) -> (DVec2, f64) {
        match self {
            Impact::Pair(c) => c.total_change(),
            Impact::Wall(w) => w.total_change(),
        }
    }

    /// Change of the involved discs' total rotational energy (J).
    pub fn rotational_change(&self) -> f64 {
        match self {
            Impact::Pair(c) => (0..2)
                .map(|k| {
                    let (e0, e1) = c.rotational_energy(k);
                    e1 - e0
                })
                .sum(),
            Impact::Wall(w) => {
                let (e0, e1) = w.rotational_energy();
                e1 - e0
            }
        }
    }

    /// The pair collision, if it is one.
    pub fn pair(&self) -> Option<&Collision> {
        match self {
            Impact::Pair(c) => Some(c),
            Impact::Wall(_) => None,
        }
    }

    /// The wall hit, if it is one.
    pub fn wall(&self) -> Option<&WallHit> {
        match self {
            Impact::Pair(_) => None,
            Impact::Wall(w) => Some(w),
        }
    }
}

/// The last impacts, pair collisions and wall hits together, newest last.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ledger {
    impacts: VecDeque<Impact>,
    capacity: usize,
    /// Pair collisions recorded since it was turned on.
    pub recorded: u64,
    /// Wall hits recorded since it was turned on.
    pub recorded_walls: u64,
}

impl Ledger {
    /// Keeps the last `capacity` impacts from now on (0 turns it off).
    pub fn keep(&mut self, capacity: usize) {
        self.capacity = capacity;
        while self.impacts.len() > capacity {
            self.impacts.pop_front();
        }
    }

    /// How many impacts it keeps (0: off).
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Whether impacts are being recorded.
    pub fn is_on(&self) -> bool {
        self.capacity > 0
    }

    /// Records one impact, a [`Collision`] or a [`WallHit`] (nothing when
    /// off); the oldest goes when it is full.
    pub fn push(&mut self, impact: impl Into<Impact>) {
        if self.capacity == 0 {
            return;
        }
        let impact = impact.into();
        match impact {
            Impact::Pair(_) => self.recorded += 1,
            Impact::Wall(_) => self.recorded_walls += 1,
        }
        if self.impacts.len() == self.capacity {
            self.impacts.pop_front();
        }
        self.impacts.push_back(impact);
    }

    /// Pair collisions recorded since it was turned on (the same as
    /// [`Ledger::recorded`]).
    pub fn recorded_pairs(&self) -> u64 {
        self.recorded
    }

    /// Impacts of both kinds recorded since it was turned on.
    pub fn recorded_impacts(&self) -> u64 {
        self.recorded + self.recorded_walls
    }

    /// The kept impacts, oldest first.
    pub fn impacts(&self) -> impl DoubleEndedIterator<Item = &Impact> {
        self.impacts.iter()
    }

    /// The kept pair collisions, oldest first.
    pub fn entries(&self) -> impl DoubleEndedIterator<Item = &Collision> {
        self.impacts.iter().filter_map(Impact::pair)
    }

    /// The kept wall hits, oldest first.
    pub fn wall_hits(&self) -> impl DoubleEndedIterator<Item = &WallHit> {
        self.impacts.iter().filter_map(Impact::wall)
    }

    /// The newest pair collision kept.
    pub fn last(&self) -> Option<&Collision> {
        self.entries().next_back()
    }

    /// The newest impact.
    pub fn last_impact(&self) -> Option<&Impact> {
        self.impacts.back()
    }

    /// How many impacts are kept.
    pub fn len(&self) -> usize {
        self.impacts.len()
    }

    /// Whether none is kept.
    pub fn is_empty(&self) -> bool {
        self.impacts.is_empty()
    }

    /// Forgets the kept impacts (a new scene or a rewind); the counts stay.
    pub fn clear(&mut self) {
        self.impacts.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(time: f64) -> Collision {
        Collision {
            time,
            discs: [0, 1],
            normal: DVec2::X,
            masses: [1.0, 2.0],
            before: [DVec2::new(1.0, 0.0), DVec2::ZERO],
            after: [DVec2::new(-1.0 / 3.0, 0.0), DVec2::new(2.0 / 3.0, 0.0)],
            radii: [0.5, 0.5],
            spins_before: [0.0; 2],
            spins_after: [0.0; 2],
        }
    }

    fn wall(time: f64) -> WallHit {
        // 2 kg into the right wall at 3 m/s, e = 0.5: out at 1.5 m/s.
        WallHit {
            time,
            disc: 4,
            wall: Wall::Right,
            mass: 2.0,
            radius: 0.5,
            before: DVec2::new(3.0, 1.0),
            after: DVec2::new(-1.5, 1.0),
            spin_before: 0.0,
            spin_after: 0.0,
        }
    }

    #[test]
    fn walls_name_their_axis_side_and_normal() {
        for (k, w) in Wall::ALL.into_iter().enumerate() {
            assert_eq!(Wall::at(w.axis(), w.is_upper()), w);
            assert_eq!((w.axis(), w.is_upper()), (k / 2, k % 2 == 1));
            assert_eq!(w.normal().length(), 1.0);
        }
        assert_eq!(Wall::Bottom.normal(), DVec2::Y, "the floor pushes up");
        assert_eq!(Wall::Right.normal(), -DVec2::X);
        assert_eq!(Wall::Top.name(), "top");
    }

    #[test]
    fn a_wall_hit_gives_the_walls_impulse_and_energy() {
        let w = wall(1.0);
        assert_eq!(w.closing_speed(), 3.0);
        // −(1 + e)·m·vₙ along the normal (−x): −1.5·2·3 = −9 in x.
        assert_eq!(w.wall_impulse(), DVec2::new(-9.0, 0.0));
        let (p0, p1) = w.momentum();
        assert_eq!(p1 - p0, w.wall_impulse());
        let (dp, dke) = w.total_change();
        assert_eq!(dp, w.wall_impulse());
        assert!((dke - 0.5 * 2.0 * (1.5f64.powi(2) - 9.0)).abs() < 1e-12);
        let ((n0, t0), (n1, t1)) = w.components();
        assert_eq!((n0, n1), (-3.0, 1.5));
        assert_eq!(t0, t1);
    }

    /// The same hit recorded either way round (the search meets the pair
    /// in either order) splits the same: disc 0 comes in at +1 along the
    /// line, whichever disc the recorded normal starts from.
    #[test]
    fn a_pairs_split_is_the_same_whichever_way_round_it_was_recorded() {
        let c = pair(0.0);
        let swapped = Collision {
            discs: [1, 0],
            normal: -c.normal,
            masses: [c.masses[1], c.masses[0]],
            before: [c.before[1], c.before[0]],
            after: [c.after[1], c.after[0]],
            ..c
        };
        assert_eq!(c.components(0), ((1.0, 0.0), (-1.0 / 3.0, 0.0)));
        assert_eq!(swapped.components(1), c.components(0));
        assert_eq!(swapped.components(0), c.components(1));
        assert_eq!(swapped.normal_in_order(), DVec2::X);
    }

    #[test]
    fn the_ledger_keeps_both_kinds_in_order_and_counts_them_apart() {
        let mut ledger = Ledger::default();
        ledger.push(pair(0.0));
        assert_eq!(ledger.recorded_impacts(), 0, "off: nothing counted");
        ledger.keep(3);
        ledger.push(pair(1.0));
        ledger.push(wall(2.0));
        ledger.push(pair(3.0));
        ledger.push(wall(4.0));
        assert_eq!((ledger.recorded, ledger.recorded_walls), (2, 2));
        assert_eq!(ledger.recorded_pairs(), 2);
        assert_eq!(ledger.recorded_impacts(), 4);
        let times: Vec<f64> = ledger.impacts().map(Impact::time).collect();
        assert_eq!(times, [2.0, 3.0, 4.0], "the oldest went");
        assert_eq!(ledger.len(), 3);
        assert_eq!(ledger.entries().count(), 1);
        assert_eq!(ledger.last().map(|c| c.time), Some(3.0));
        assert_eq!(ledger.last_impact().map(Impact::time), Some(4.0));
        assert_eq!(ledger.wall_hits().next().map(|w| w.time), Some(2.0));
        assert_eq!(ledger.last_impact().unwrap().discs(), [4]);
        ledger.clear();
        assert!(ledger.is_empty() && ledger.last().is_none());
        assert_eq!(ledger.recorded_impacts(), 4, "the counts stay");
    }
}
