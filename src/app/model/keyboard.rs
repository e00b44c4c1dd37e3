//! The world from the keyboard alone: a key selects the next disc (its
//! number and velocity said in the strip), the arrow keys aim the selected
//! disc while the simulation is paused, and Enter puts a new disc at rest
//! at the centre of the view, selected, ready to be aimed.

use super::Sandbox;
use crate::app::lang::tr;
use crate::app::numbers::{disc_number, vector, with_unit};
use glam::DVec2;
use impulse::{Color, Particle};

/// How much one press of an arrow key changes the velocity (m/s); Shift:
/// ten times as much.
pub const AIM_STEP: f64 = 0.1;

impl Sandbox {
    /// Whether the arrow keys aim the selected disc (paused, a disc
    /// selected) rather than pan.
    pub fn arrows_aim(&self) -> bool {
        self.clock.paused && self.selected_disc().is_some()
    }

    /// Selects the disc `step` after the selected one (before it when
    /// negative), wrapping round; the first (or last) when none is.
    pub(super) fn select_next(&mut self, step: i32) {
        let n = self.world.particles.len();
        if n == 0 {
            self.toast(tr!("select-no-discs"));
            return;
        }
        let next = match self.selected_disc() {
            Some(i) => (i as i64 + i64::from(step)).rem_euclid(n as i64) as usize,
            None if step >= 0 => 0,
            None => n - 1,
        };
        self.selected = Some(next);
        self.panels.picks = self.panels.picks.wrapping_add(1);
        let p = &self.world.particles[next];
        self.toast(tr!(
            "selected-disc-said",
            disc = disc_number(next),
            discs = n,
            mass = with_unit(p.mass, 3, "kg"),
            velocity = vector(p.vel, 2, "m/s")
        ));
    }

    /// Changes the selected disc's velocity by `dv` while paused.
    pub(super) fn aim_selected(&mut self, dv: DVec2) {
        if !self.arrows_aim() {
            return;
        }
        let Some(i) = self.selected_disc() else {
            return;
        };
        // In a one-dimensional world only along its line: a velocity across
        // it showed in the readout, and the step then set it to 0 (the
        // kinetic energy fell with no collision).
        let dv = match self.world.laws.constrain {
            Some(axis) => {
                let along = axis.index();
                if dv[along] == 0.0 {
                    let keys = if along == 0 {
                        tr!("key-left-right")
                    } else {
                        tr!("key-up-down")
                    };
                    self.toast(tr!("aim-across-the-line", keys = keys));
                    return;
                }
                let mut only = DVec2::ZERO;
                only[along] = dv[along];
                only
            }
            None => dv,
        };
        let p = &mut self.world.particles[i];
        // Whole tenths, so that steps add up to round numbers: divided by
        // ten, not multiplied by 0.1 (−6 × 0.1 is −0.6000000000000001, which
        // a saved scene and the CSV then carried).
        let per_unit = (1.0 / AIM_STEP).round();
        p.vel = ((p.vel + dv) * per_unit).round() / per_unit;
        let v = p.vel;
        // The Totals tab starts afresh in `apply`, where the aim moved a
        // total.
        self.toast(tr!(
            "aimed",
            disc = disc_number(i),
            velocity = vector(v, 2, "m/s")
        ));
    }

    /// A new disc at rest at the centre of the view (or the nearest free
    /// place), selected; no room says so.
    pub(super) fn launch_at_centre(&mut self) {
        let disc = self.new_disc_now();
        let centre = self.view.camera.center;
        let Some(pos) = self.world.free_spot_near(centre, disc.radius) else {
            self.toast(tr!("no-room"));
            return;
        };
        let color = Color::palette(self.world.particles.len());
        self.world.particles.push(Particle::new(
            pos,
            DVec2::ZERO,
            disc.mass,
            disc.radius,
            color,
        ));
        let i = self.world.particles.len() - 1;
        self.selected = Some(i);
        // Where the centre was taken, it went beside the nearest disc: the
        // message said "at the centre" all the same.
        let moved = pos.distance(centre) > 1e-9 * disc.radius.max(1.0);
        let nearest = self.world.particles[..i]
            .iter()
            .enumerate()
            .min_by(|(_, a), (_, b)| pos.distance(a.pos).total_cmp(&pos.distance(b.pos)))
            .map(|(k, _)| k);
        self.toast(match nearest.filter(|_| moved) {
            Some(k) => tr!(
                "launched-near-centre",
                disc = disc_number(i),
                beside = disc_number(k)
            ),
            None => tr!("launched-at-centre", disc = disc_number(i)),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::sandbox_in as sandbox_on;
    use super::super::Command;
    use glam::DVec2;

    #[test]
    fn the_world_answers_the_keyboard_alone() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_on(dir.path(), "preset-4-glancing.toml");
        let n = s.world.particles.len();
        s.apply(Command::SelectNext(1));
        assert_eq!(s.selected, Some(0));
        s.apply(Command::SelectNext(-1));
        assert_eq!(s.selected, Some(n - 1), "wraps round");
        // Paused: the arrows aim; undo takes it back.
        let before = s.world.particles[n - 1].vel;
        s.apply(Command::AimSelected(DVec2::new(0.0, 0.1)));
        s.apply(Command::AimSelected(DVec2::new(0.0, 0.1)));
        let after = s.world.particles[n - 1].vel;
        assert!(
            (after.y - before.y - 0.2).abs() < 1e-9,
            "{before} → {after}"
        );
        s.apply(Command::Undo);
        assert_eq!(s.world.particles[n - 1].vel, before);
        // Tenths exactly as typed: six presses down from 0 are −0.6, not
        // −0.6000000000000001.
        s.apply(Command::EditDisc {
            disc: n - 1,
            text: [None, None, Some("0".into()), Some("0".into()), None, None],
            from: super::super::command::EditPlace::Fields,
        });
        for _ in 0..6 {
            s.apply(Command::AimSelected(DVec2::new(0.0, -0.1)));
        }
        assert_eq!(s.world.particles[n - 1].vel.y, -0.6);
        let before = s.world.particles[n - 1].vel;
        // Running: they do not (they pan).
        s.apply(Command::TogglePause);
        s.apply(Command::AimSelected(DVec2::new(1.0, 0.0)));
        assert_eq!(s.world.particles[n - 1].vel, before);
        assert!(!s.arrows_aim());
        // Enter: a new disc at rest near the view's centre, selected.
        s.apply(Command::LaunchAtCentre);
        assert_eq!(s.world.particles.len(), n + 1);
        assert_eq!(s.selected, Some(n));
        assert_eq!(s.world.particles[n].vel, DVec2::ZERO);
        s.apply(Command::Undo);
        assert_eq!(s.world.particles.len(), n);
    }

    /// In a one-dimensional world the arrows aim along its line only: Up
    /// had given a disc a v_y the readout showed and the next step took
    /// away, its kinetic energy falling with no collision.
    #[test]
    fn in_one_dimension_the_arrows_aim_along_the_line() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_on(dir.path(), "preset-1-head-on.toml");
        assert!(s.world.laws.constrain.is_some());
        s.apply(Command::SelectNext(1));
        let before = s.world.particles[0].vel;
        s.apply(Command::AimSelected(DVec2::new(0.0, 0.1)));
        assert_eq!(s.world.particles[0].vel, before, "Up changed nothing");
        let said = s.message().unwrap_or_default();
        assert!(said.contains("one line: Left and Right"), "{said}");
        s.apply(Command::AimSelected(DVec2::new(0.1, 0.1)));
        let after = s.world.particles[0].vel;
        assert_eq!(after.y, 0.0, "nothing across the line");
        assert!((after.x - before.x - 0.1).abs() < 1e-9, "{after}");
    }

    /// A second Enter finds the centre taken: the disc goes beside the
    /// first, and the message says so (it said "at the centre"); undo
    /// names it a new disc, not a launch.
    #[test]
    fn enter_says_where_the_new_disc_went() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_on(dir.path(), "preset-1-head-on.toml");
        s.apply(Command::OpenEmpty);
        s.apply(Command::LaunchAtCentre);
        let first = s.message().unwrap_or_default();
        assert!(first.contains("at the centre"), "{first}");
        s.apply(Command::LaunchAtCentre);
        let second = s.message().unwrap_or_default();
        assert!(second.contains("Disc 2 at rest beside disc 1"), "{second}");
        let [a, b] = [&s.world.particles[0], &s.world.particles[1]];
        assert!(
            a.pos.distance(b.pos) >= a.radius + b.radius - 1e-9,
            "side by side"
        );
        s.apply(Command::Undo);
        let undone = s.message().unwrap_or_default();
        assert!(undone.starts_with("Undone: a new disc"), "{undone}");
    }
}
