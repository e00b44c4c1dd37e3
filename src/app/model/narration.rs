//! The sandbox in words, for a person who cannot see the screen: what
//! happens, said as it happens (every message of the strip, the newest
//! impact at most every [`IMPACT_GAP`] seconds, the π blocks' count once it
//! is final), and the scene described on request ([`Sandbox::describe`]).
//! The browser hands each line to its `aria-live` region; the desktop shows
//! them in the *In words* tab.

use super::lesson::pi_result;
use super::Sandbox;
use crate::app::lang::tr;
use crate::app::numbers::{disc_number, plain, vector, with_unit};
use glam::DVec2;
use impulse::ledger::Impact;
use std::collections::VecDeque;

/// Least time between two impacts said (window seconds): a gas would
/// otherwise talk without end.
pub const IMPACT_GAP: f64 = 2.0;
/// Lines kept for the *In words* tab.
pub const KEEP: usize = 30;
/// Discs a description names one by one; the rest are summed up.
pub const DESCRIBED_DISCS: usize = 8;

/// What was said and what is still to be handed on.
#[derive(Clone, Debug, Default)]
pub struct Narration {
    /// Lines said, newest last, with the simulation's time t when said
    /// (the time the lines themselves speak of; the window's own clock
    /// beside them read as a second, different t).
    pub said: VecDeque<(f64, String)>,
    /// Lines not yet handed to the page's live region.
    unread: Vec<String>,
    /// The ledger's impacts counted so far.
    seen: u64,
    /// When an impact was last said (window time).
    impact_said_at: Option<f64>,
    /// Impacts came while the last one said was too recent: the newest is
    /// said once the gap is over.
    impact_waiting: bool,
    /// The π blocks' count was said.
    pi_said: bool,
    /// A lesson's question was in the strip last frame: when its answer
    /// takes its place, the answer is said.
    asking: bool,
}

impl Narration {
    /// Forgets the lines said (a new scene, a reset, a cleared box); what
    /// the page's live region has not yet read stays to be read.
    pub fn start_afresh(&mut self) {
        self.said.clear();
    }

    fn say(&mut self, t: f64, text: String) {
        if self.said.back().is_some_and(|(_, last)| *last == text) {
            return;
        }
        self.unread.push(text.clone());
        self.said.push_back((t, text));
        while self.said.len() > KEEP {
            self.said.pop_front();
        }
    }
}

/// One impact in words: who hit whom, and the momentum (or speed, at a
/// wall) before and after.
pub fn impact_words(impact: &Impact) -> String {
    match impact {
        Impact::Pair(c) => {
            let (a0, a1) = c.momentum(0);
            let (b0, b1) = c.momentum(1);
            // Lowest number first, as J and the ledger name a pair.
            let [a, b] = c.discs_in_order();
            tr!(
                "said-pair",
                a = disc_number(a),
                b = disc_number(b),
                before = with_unit((a0 + b0).length(), 2, "kg·m/s"),
                after = with_unit((a1 + b1).length(), 2, "kg·m/s")
            )
        }
        Impact::Wall(w) => tr!(
            "said-wall",
            disc = disc_number(w.disc),
            wall = w.wall.name(),
            before = with_unit(w.before.length(), 2, "m/s"),
            after = with_unit(w.after.length(), 2, "m/s")
        ),
    }
}

/// Where in the box a point is, in words: "at the left", "at the top
/// right", "in the middle".
fn place_words(at: DVec2, size: DVec2) -> String {
    let third = |v: f64, len: f64| ((v / len * 3.0).floor() as i32).clamp(0, 2);
    let (col, row) = (third(at.x, size.x), third(at.y, size.y));
    let id = match (row, col) {
        (1, 1) => "place-middle",
        (1, 0) => "place-left",
        (1, 2) => "place-right",
        (0, 1) => "place-bottom",
        (2, 1) => "place-top",
        (0, 0) => "place-bottom-left",
        (0, 2) => "place-bottom-right",
        (2, 0) => "place-top-left",
        _ => "place-top-right",
    };
    crate::app::lang::text(id, &[])
}

/// A velocity in words: "at rest", or "moving up and to the right at
/// 2.00 m/s".
fn motion_words(v: DVec2) -> String {
    let speed = v.length();
    if speed < 1e-3 {
        return tr!("motion-rest");
    }
    // Eight directions, counter-clockwise from "right".
    let k = ((v.y.atan2(v.x) / std::f64::consts::FRAC_PI_4).round() as i32).rem_euclid(8);
    let direction = crate::app::lang::text(
        [
            "direction-right",
            "direction-up-right",
            "direction-up",
            "direction-up-left",
            "direction-left",
            "direction-down-left",
            "direction-down",
            "direction-down-right",
        ][k as usize],
        &[],
    );
    tr!(
        "motion-moving",
        direction = direction,
        speed = with_unit(speed, 2, "m/s")
    )
}

impl Sandbox {
    /// Says `text` to a person who cannot see the screen.
    pub fn announce(&mut self, text: String) {
        self.announce_at(self.world.time, text);
    }

    /// Says `text` of something that happened at the simulation's time
    /// `t`: an impact is stamped with its own instant, as the ledger and J
    /// give it (stamped with the frame's, the head-on hit at 2.400 s read
    /// "t = 2.42 s").
    fn announce_at(&mut self, t: f64, text: String) {
        self.messages.narration.say(t, text);
    }

    /// The lines not yet handed to the page's live region.
    pub fn take_announcements(&mut self) -> Vec<String> {
        std::mem::take(&mut self.messages.narration.unread)
    }

    /// After the frame's steps: the newest impact, unless one was said a
    /// moment ago, and the π blocks' count once it is final.
    pub(super) fn narrate(&mut self) {
        let asking = self.lesson_unanswered().is_some();
        let answered = std::mem::replace(&mut self.messages.narration.asking, asking) && !asking;
        // Answered by what was just seen (not by an edit or another scene,
        // where the strip's caption is another's).
        if answered && self.open.lesson.is_some() && !self.open.edited {
            if let Some(answer) = self.shown_caption() {
                self.announce(answer);
            }
        }
        let now = self.session.now;
        let recorded = self.world.ledger.recorded_impacts();
        let narration = &mut self.messages.narration;
        if recorded < narration.seen {
            // A new scene, a reset, a rewind: counted afresh, and its first
            // impact said at once, however recently the last scene's was.
            narration.seen = recorded;
            narration.pi_said = false;
            narration.impact_said_at = None;
            narration.impact_waiting = false;
        }
        let new = recorded > narration.seen || narration.impact_waiting;
        narration.seen = recorded;
        if let (Some(result), false) = (pi_result(&self.world), narration.pi_said) {
            narration.pi_said = true;
            narration.impact_said_at = Some(now);
            return self.announce(result);
        }
        let quiet = narration
            .impact_said_at
            .is_none_or(|t| now - t >= IMPACT_GAP);
        // Paused (J stopped at an impact), the strip's report says it.
        narration.impact_waiting = new && !quiet && !self.clock.paused;
        if new && quiet && !self.clock.paused {
            let newest = self.world.ledger.impacts().next_back();
            if let Some((t, words)) = newest.map(|i| (i.time(), impact_words(i))) {
                self.messages.narration.impact_said_at = Some(now);
                self.announce_at(t, words);
            }
        }
    }

    /// The scene in words: its name and caption whole (the strip cuts a
    /// long caption, and only a pointer's hover showed the rest), the box,
    /// the laws that matter, each disc (up to [`DESCRIBED_DISCS`]: where it
    /// is and how it moves), the time and the totals.
    pub fn describe(&self) -> String {
        let w = &self.world;
        let size = w.laws.size;
        let n = w.particles.len();
        let caption = self.shown_caption();
        let heading = match caption {
            Some(caption) => format!("{}: {caption}", self.scene_name()),
            None => format!("{}.", self.scene_name()),
        };
        let mut lines = vec![heading];
        lines.push(tr!(
            "describe-box",
            discs = n,
            width = crate::app::numbers::field(size.x),
            height = crate::app::numbers::field(size.y),
            edges = match w.laws.boundary {
                impulse::Boundary::Box => "box",
                impulse::Boundary::Open => "open",
                impulse::Boundary::Periodic => "periodic",
            }
        ));
        let g = w.laws.gravity.length();
        lines.push(if g > 0.0 {
            tr!("describe-gravity", gravity = with_unit(g, 2, "m/s²"))
        } else {
            tr!("describe-no-gravity")
        });
        lines.push(tr!(
            "describe-restitution",
            restitution = plain(w.laws.restitution, 2)
        ));
        for (i, p) in w.particles.iter().enumerate().take(DESCRIBED_DISCS) {
            lines.push(tr!(
                "describe-disc",
                disc = disc_number(i),
                mass = with_unit(p.mass, 3, "kg"),
                place = place_words(p.pos, size),
                motion = motion_words(p.vel)
            ));
        }
        if n > DESCRIBED_DISCS {
            // The mean speed of the discs not named one by one.
            let rest = &w.particles[DESCRIBED_DISCS..];
            let mean = rest.iter().map(|p| p.vel.length()).sum::<f64>() / rest.len() as f64;
            lines.push(tr!(
                "describe-more",
                more = n - DESCRIBED_DISCS,
                speed = with_unit(mean, 2, "m/s")
            ));
        }
        let m = w.metrics();
        lines.push(tr!(
            "describe-totals",
            time = with_unit(w.time, 2, "s"),
            state = if self.clock.paused {
                "paused"
            } else {
                "running"
            },
            momentum = vector(m.momentum, 2, "kg·m/s"),
            energy = with_unit(m.kinetic_energy, 2, "J")
        ));
        lines.join(" ")
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::sandbox_in;
    use super::super::Command;
    use super::*;

    #[test]
    fn a_description_names_the_box_and_every_disc() {
        let dir = tempfile::tempdir().unwrap();
        let s = sandbox_in(dir.path(), "preset-1-head-on.toml");
        let text = s.describe();
        let n = s.world.particles.len();
        assert!(text.contains(&format!("{n} discs")), "{text}");
        // Counted from 1, as the tables and the ledger count them.
        for number in 1..=n {
            assert!(text.contains(&format!("Disc {number}, ")), "{text}");
        }
        assert!(!text.contains("Disc 0"), "{text}");
        assert!(text.contains("metre box"), "{text}");
        let moving = s
            .world
            .particles
            .iter()
            .filter(|p| p.vel.length() > 1e-3)
            .count();
        let discs = &text[text.find("metre box").unwrap()..];
        assert_eq!(discs.matches("moving ").count(), moving, "{text}");
        // The name and the caption first, whole: the strip cuts a long
        // caption, and a keyboard had no way to read the rest.
        let caption = s.scene_description().unwrap();
        assert!(
            text.starts_with(&format!("{}: {caption}", s.scene_name())),
            "{text}"
        );
    }

    #[test]
    fn directions_and_places_are_the_right_ones() {
        assert_eq!(
            motion_words(DVec2::new(2.0, 0.0)),
            "moving right at 2.00 m/s"
        );
        assert_eq!(
            motion_words(DVec2::new(-1.0, -1.0)).split(" at ").next(),
            Some("moving down and to the left")
        );
        assert_eq!(motion_words(DVec2::ZERO), "at rest");
        let size = DVec2::new(9.0, 9.0);
        assert_eq!(place_words(DVec2::new(1.0, 4.5), size), "at the left");
        assert_eq!(place_words(DVec2::new(8.0, 8.0), size), "at the top right");
        assert_eq!(place_words(DVec2::new(4.5, 4.5), size), "in the middle");
    }

    /// One frame of `dt` seconds of the window's clock `t`, running the
    /// sandbox: the lines said for the page's live region.
    fn frame(s: &mut Sandbox, t: &mut f64, dt: f64) -> Vec<String> {
        *t += dt;
        s.begin_frame(*t);
        s.tick(dt, 1.0);
        s.take_announcements()
    }

    #[test]
    fn impacts_are_said_at_most_every_gap_and_the_pi_count_once() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-7-pi-blocks.toml");
        s.apply(Command::TogglePause);
        let mut said_at = Vec::new();
        let mut t = 0.0;
        for _ in 0..(40 * 60) {
            for line in frame(&mut s, &mut t, 1.0 / 60.0) {
                said_at.push((t, line));
            }
        }
        let impacts: Vec<f64> = said_at
            .iter()
            .filter(|(_, l)| l.starts_with("Disc "))
            .map(|(t, _)| *t)
            .collect();
        assert!(!impacts.is_empty());
        for pair in impacts.windows(2) {
            assert!(pair[1] - pair[0] >= IMPACT_GAP - 1e-9, "{pair:?}");
        }
        let pi: Vec<&String> = said_at
            .iter()
            .map(|(_, l)| l)
            .filter(|l| l.contains("π ≈"))
            .collect();
        assert_eq!(pi, [&"31 collisions: π ≈ 3.1".to_string()]);
    }

    /// Seen in the In words tab: a gas had just said an impact when the
    /// glancing hit opened, whose one impact came 1.8 s later, inside the
    /// gap: it was never said. A new scene's first impact
    /// is said at once, and an impact inside the gap once the gap is over.
    #[test]
    fn a_new_scenes_first_impact_is_said_however_recent_the_last_scenes_was() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-8-gas.toml");
        s.apply(Command::TogglePause);
        let mut t = 0.0;
        let mut frame = |s: &mut Sandbox| frame(s, &mut t, 1.0 / 60.0);
        let mut said = false;
        for _ in 0..(20 * 60) {
            if frame(&mut s).iter().any(|l| l.starts_with("Disc ")) {
                said = true;
                break;
            }
        }
        assert!(said, "the gas says an impact");
        s.apply(Command::OpenPreset(3));
        assert_eq!(s.scene_name(), "Glancing collision");
        if s.clock.paused {
            s.apply(Command::TogglePause);
        }
        let mut lines = Vec::new();
        for _ in 0..(3 * 60) {
            lines.extend(frame(&mut s));
        }
        assert!(
            s.world.total_pair_collisions == 1,
            "the glancing hit happened"
        );
        assert!(
            lines.iter().any(|l| l.starts_with("Disc 1 hit disc 2")),
            "{lines:?}"
        );
    }

    /// Seen in the In words tab (a review): after the sandbox's gas, the
    /// head-on hit's list went on with "Disc 23 hit the right wall" at
    /// 4.14 s under its own 2.42 s, and its impact read "t = 2.42 s" where
    /// the ledger and J give 2.400 s. A new scene starts the list afresh,
    /// and an impact is stamped with its own instant.
    #[test]
    fn a_new_scene_starts_the_list_afresh_and_an_impact_has_its_own_time() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-8-gas.toml");
        s.apply(Command::TogglePause);
        let mut t = 0.0;
        // Frames of 0.07 s: none ends at the impact's 2.400 s.
        let mut frame = |s: &mut Sandbox| {
            frame(s, &mut t, 0.07);
        };
        let said = |s: &Sandbox| {
            s.messages
                .narration
                .said
                .iter()
                .any(|(_, l)| l.starts_with("Disc "))
        };
        for _ in 0..300 {
            if said(&s) {
                break;
            }
            frame(&mut s);
        }
        assert!(said(&s), "the gas says an impact");
        s.apply(Command::OpenPreset(0));
        assert_eq!(s.scene_name(), "Head-on, equal masses");
        let lines: Vec<_> = s
            .messages
            .narration
            .said
            .iter()
            .map(|(_, l)| l.clone())
            .collect();
        assert_eq!(lines, ["Opened Head-on, equal masses"]);
        if s.clock.paused {
            s.apply(Command::TogglePause);
        }
        for _ in 0..60 {
            frame(&mut s);
        }
        let impact = s
            .world
            .ledger
            .impacts()
            .next()
            .expect("the head-on hit")
            .time();
        let stamped: Vec<f64> = s
            .messages
            .narration
            .said
            .iter()
            .filter(|(_, l)| l.starts_with("Disc "))
            .map(|(t, _)| *t)
            .collect();
        assert_eq!(stamped, [impact], "{:?}", s.messages.narration.said);
    }

    #[test]
    fn a_pair_is_said_with_its_momentum_before_and_after() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
        s.apply(Command::NextCollision);
        let newest = *s.world.ledger.impacts().next_back().unwrap();
        let words = impact_words(&newest);
        let Impact::Pair(c) = newest else {
            panic!("head-on starts with a pair")
        };
        let (a0, _) = c.momentum(0);
        let (b0, _) = c.momentum(1);
        let p = with_unit((a0 + b0).length(), 2, "kg·m/s");
        assert_eq!(
            words,
            format!(
                "Disc {} hit disc {}: their total momentum before {p}, after {p}",
                c.discs_in_order()[0] + 1,
                c.discs_in_order()[1] + 1
            )
        );
        // Stamped with the simulation's t (the window's clock stands still here).
        let (t, _) = s.messages.narration.said.back().unwrap();
        assert!(s.world.time > 0.5, "{}", s.world.time);
        assert_eq!(*t, s.world.time);
        // The toast of J is said too.
        assert!(s
            .take_announcements()
            .iter()
            .any(|l| l.starts_with("Discs 1 and 2,")));
    }
}
