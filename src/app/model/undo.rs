//! Undo and redo of every change to the scene (Ctrl+Z, Ctrl+Shift+Z or
//! Ctrl+Y): before a change the sandbox remembers the whole scene as it was,
//! discs, laws and time included, and undo puts it back. Many levels are
//! kept within a memory budget (fewer for huge scenes, always one).

use impulse::{Particle, Scene, World};

/// Levels kept at most.
pub const MAX_LEVELS: usize = 100;
/// Memory the remembered scenes may take (bytes).
pub const BUDGET_BYTES: usize = 256 << 20;
/// Changes of the same kind closer together than this (s of wall clock)
/// are one change: a slider dragged, a key held.
const COALESCE_SECONDS: f64 = 0.75;

/// The scene at one moment: what undo brings back.
#[derive(Clone)]
pub struct Moment {
    /// The discs, laws, clock and counters.
    pub world: World,
    /// The scene file it came from (name, caption).
    pub scene: Scene,
    /// Where that came from.
    pub origin: String,
    /// Whether its discs had been edited since it opened.
    pub edited: bool,
}

impl Moment {
    fn bytes(&self) -> usize {
        let discs = self.world.particles.len() * std::mem::size_of::<Particle>();
        let listed =
            self.scene.particles.len() * std::mem::size_of::<impulse::scene::ParticleSpec>();
        std::mem::size_of::<Moment>() + discs + listed
    }
}

/// The remembered past and the undone future.
#[derive(Default)]
pub struct Undo {
    past: Vec<(Moment, &'static str)>,
    future: Vec<(Moment, &'static str)>,
    /// The last change remembered: its kind and when (s).
    last: Option<(&'static str, f64)>,
}

impl Undo {
    /// Remembers `moment` before a change of kind `what` at time `now` (s);
    /// a change of the same kind right after the last is the same change.
    /// Forgets the undone future.
    pub fn remember(&mut self, moment: impl FnOnce() -> Moment, what: &'static str, now: f64) {
        let same = self.would_merge(what, now);
        self.last = Some((what, now));
        if same {
            return;
        }
        self.future.clear();
        self.past.push((moment(), what));
        self.trim();
    }

    /// Whether a change of kind `what` at `now` would be part of the last
    /// one (so the moment before it need not be kept).
    pub fn would_merge(&self, what: &'static str, now: f64) -> bool {
        !self.past.is_empty()
            && self
                .last
                .is_some_and(|(kind, at)| kind == what && now - at < COALESCE_SECONDS)
    }

    /// A change of kind `what` at `now` that [`Undo::would_merge`] into the
    /// last: it only extends it.
    pub fn merge(&mut self, what: &'static str, now: f64) {
        self.last = Some((what, now));
    }

    /// The moment before the last change, in exchange for the present.
    pub fn undo(&mut self, present: Moment) -> Option<(Moment, &'static str)> {
        let (moment, what) = self.past.pop()?;
        self.future.push((present, what));
        self.last = None;
        Some((moment, what))
    }

    /// The moment the last undo left, in exchange for the present.
    pub fn redo(&mut self, present: Moment) -> Option<(Moment, &'static str)> {
        let (moment, what) = self.future.pop()?;
        self.past.push((present, what));
        self.last = None;
        Some((moment, what))
    }

    /// Levels that can be undone and redone.
    pub fn levels(&self) -> (usize, usize) {
        (self.past.len(), self.future.len())
    }

    /// Drops the oldest levels beyond the count or the budget (keeps one).
    fn trim(&mut self) {
        let bytes = |list: &[(Moment, &str)]| list.iter().map(|(m, _)| m.bytes()).sum::<usize>();
        while self.past.len() > 1
            && (self.past.len() > MAX_LEVELS
                || bytes(&self.past) + bytes(&self.future) > BUDGET_BYTES)
        {
            self.past.remove(0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    fn moment(discs: usize) -> Moment {
        let mut world = World::new(DVec2::new(10.0, 10.0));
        for k in 0..discs {
            world.particles.push(Particle::new(
                DVec2::new(1.0 + k as f64, 1.0),
                DVec2::ZERO,
                1.0,
                0.4,
                impulse::Color::palette(k),
            ));
        }
        let scene = Scene::from_world(&world, None, None);
        Moment {
            world,
            scene,
            origin: String::new(),
            edited: false,
        }
    }

    #[test]
    fn undo_and_redo_walk_back_and_forth_and_a_new_change_drops_the_future() {
        let mut u = Undo::default();
        u.remember(|| moment(1), "launch", 0.0);
        u.remember(|| moment(2), "launch", 10.0);
        let (back, _) = u.undo(moment(3)).unwrap();
        assert_eq!(back.world.particles.len(), 2);
        let (back, _) = u.undo(back).unwrap();
        assert_eq!(back.world.particles.len(), 1);
        assert!(u.undo(back.clone()).is_none());
        let (fwd, _) = u.redo(back).unwrap();
        assert_eq!(fwd.world.particles.len(), 2);
        u.remember(|| fwd.clone(), "clear", 20.0);
        assert_eq!(u.levels(), (2, 0), "a new change forgets the undone future");
    }

    #[test]
    fn a_drag_is_one_change_and_two_kinds_are_two() {
        let mut u = Undo::default();
        for k in 0..10 {
            u.remember(|| moment(k), "restitution", 0.1 * k as f64);
        }
        assert_eq!(u.levels(), (1, 0));
        let (first, _) = u.undo(moment(9)).unwrap();
        assert_eq!(first.world.particles.len(), 0, "the state before the drag");
        u.remember(|| moment(1), "restitution", 5.0);
        u.remember(|| moment(1), "gravity", 5.1);
        assert_eq!(u.levels(), (2, 0));
    }

    #[test]
    fn at_least_fifty_levels_and_the_budget_keeps_huge_scenes_few() {
        let mut u = Undo::default();
        for k in 0..60 {
            u.remember(|| moment(3), "launch", k as f64);
        }
        assert!(u.levels().0 >= 50);
        let huge = moment(100_000);
        let per = huge.bytes();
        let mut u = Undo::default();
        for k in 0..60 {
            u.remember(|| huge.clone(), "launch", k as f64);
        }
        let (kept, _) = u.levels();
        assert!(
            kept * per <= BUDGET_BYTES && kept >= 1,
            "{kept} levels of {per} B"
        );
        assert!(kept < 60);
    }
}
