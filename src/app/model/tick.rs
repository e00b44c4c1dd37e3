//! Time passing: each frame's physics steps within their budget, then what
//! is recorded of them (the totals, the trails, the rewind history) and
//! autosave; "next collision" and the rewind, which move time by command.

use super::lesson::{LEDGER_KEEP, NEXT_COLLISION_LIMIT};
use super::{scenes, totals, DockTab, Sandbox};
use crate::app::lang::tr;
use crate::app::numbers::{disc_number, plain, reads_as_zero, vector, with_unit};

/// How often (s of simulated time) a run to the next collision records the
/// totals, trails and rewind history on its way: as often as a frame at 60
/// frames a second would.
const RECORD_EVERY: f64 = 1.0 / 60.0;

/// How an impact changed the kinetic energy, as the messages select on it:
/// "same" where the change reads as 0.000 J, else "less" or "more" (the
/// amount is given apart, without its sign).
fn change_word(change: f64) -> &'static str {
    if reads_as_zero(change, 3) {
        "same"
    } else if change < 0.0 {
        "less"
    } else {
        "more"
    }
}

impl Sandbox {
    /// One frame of `frame_seconds` of real time: runs the steps the clock
    /// asks for as long as they fit in `budget` seconds of wall clock (at
    /// least one; the rest are dropped, so a machine that cannot keep up
    /// runs the simulation slower instead of dropping frames), records the
    /// totals, trails and history, keeps a fitted view fitted and autosaves.
    pub fn tick(&mut self, frame_seconds: f64, budget: f64) {
        let running = !self.clock.paused;
        // On before the first step, so the ledger's counts are the world's.
        if !self.world.ledger.is_on() {
            self.world.ledger.keep(LEDGER_KEEP);
        }
        let listened = self.listen();
        let due = self.clock.advance(frame_seconds);
        let start = impulse::clock::Instant::now();
        let mut steps = 0;
        // Small scenes: the totals just before and after each step with an
        // impact, so the plot drops at the instant of an inelastic collision.
        let sample_collisions = self.world.particles.len() <= totals::SAMPLE_COLLISIONS_MAX_DISCS;
        while steps < due {
            if steps > 0 && start.elapsed().as_secs_f64() >= budget {
                break;
            }
            let before = sample_collisions.then(|| (self.world.time, self.world.metrics()));
            let stats = self.world.step(self.clock.dt);
            if let Some((t, m)) = before.filter(|_| stats.pair_collisions + stats.wall_hits > 0) {
                let now = self.world.metrics();
                let walls = stats.wall_hits > 0;
                self.record
                    .totals
                    .around_impact((t, &m), &self.world, &now, walls);
            }
            if stats.separated_pairs > 0 {
                self.toast_separated(stats.separated_pairs, stats.separation_energy);
            }
            self.pointer.pin_held(&mut self.world);
            let micros = &mut self.steps.step_micros;
            micros.push_back(stats.timings.total().as_secs_f64() * 1e6);
            if micros.len() > 240 {
                micros.pop_front();
            }
            steps += 1;
            if stats.wall_hits > 0 && self.pause_at_first_wall() {
                break;
            }
        }
        if !running && steps > 0 {
            // N, paused: a step of 1/240 s does not show in the top bar's
            // hundredths, so the strip says where it went.
            self.toast(tr!(
                "stepped",
                steps = steps,
                dt = with_unit(self.clock.dt, 4, "s"),
                time = with_unit(self.world.time, 4, "s")
            ));
        }
        self.steps.steps_last_frame = steps;
        self.steps.steps_dropped = due - steps;
        self.after_steps(steps);
        self.hear(listened, frame_seconds);
        self.narrate();
        if self.view.fitted && self.follows_discs() {
            self.fit_camera();
        }
        if let Some(offset) = self.overlays.com_view {
            // The centre-of-mass view: the camera moves with it.
            self.view.camera.center = self.world.metrics().center_of_mass + offset;
        }
        let simulated = self.world.time;
        let now = self.session.now;
        self.steps
            .realtime
            .push(now, simulated, running && !self.clock.paused);
        self.autosave();
    }

    /// In a lesson about momentum, the run's first wall hit pauses it and
    /// says why the total changed there (the head-on discs' total had
    /// turned from (2, 0) to (−2, 0) under the answer "total momentum stays
    /// the same", a few seconds after it). Whether it paused.
    fn pause_at_first_wall(&mut self) -> bool {
        let about_momentum = self.open.lesson.is_some_and(|tile| tile.about_momentum());
        if !about_momentum || self.world.total_wall_hits != 1 {
            return false;
        }
        let newest_at_a_wall = self.world.ledger.impacts().rev().find_map(|i| match i {
            impulse::ledger::Impact::Wall(hit) => Some((hit.disc, hit.wall.name().to_string())),
            impulse::ledger::Impact::Pair(_) => None,
        });
        let Some((disc, wall)) = newest_at_a_wall else {
            return false;
        };
        self.clock.paused = true;
        let said = tr!(
            "lesson-wall-pause",
            disc = disc_number(disc),
            wall = wall,
            key = super::bindings::keys_of(&super::Command::TogglePause)
        );
        self.toast_for(said, 10.0);
        true
    }

    /// Says that `exact` pushed `pairs` overlapping pairs apart as it took
    /// the discs over, and the potential energy that added (J): the energy
    /// readout jumps, and this is why.
    fn toast_separated(&mut self, pairs: usize, energy: f64) {
        let said = if energy.abs() < 1e-9 {
            tr!("separated", pairs = pairs)
        } else if energy > 0.0 {
            tr!(
                "separated-raised",
                pairs = pairs,
                energy = with_unit(energy, 3, "J")
            )
        } else {
            tr!(
                "separated-lowered",
                pairs = pairs,
                energy = with_unit(-energy, 3, "J")
            )
        };
        self.toast_for(said, 6.0);
    }

    /// After the frame's steps: keep the ledger on, sample the totals and
    /// record the moment for rewinding. A world that went back in time (a
    /// new scene, a reset) starts its history afresh.
    fn after_steps(&mut self, steps: u32) {
        if !self.world.ledger.is_on() {
            self.world.ledger.keep(LEDGER_KEEP);
        }
        let record = &mut self.record;
        let newest = record.history.span().map(|(_, t)| t);
        if record.history.cursor().is_none() && newest.is_some_and(|t| t > self.world.time) {
            record.history.clear();
        }
        let metrics = self.world.metrics();
        record.totals.push(&self.world, &metrics);
        record.trails.record(&self.world);
        if steps > 0 || record.history.is_empty() {
            record.history.record(&self.world);
        }
    }

    /// Forgets the recorded past (a new scene, a reset, a cleared box): a
    /// rewind must never bring back discs of another scene.
    pub(super) fn forget_past(&mut self) {
        self.record.history.clear();
        self.record.totals.restart(&self.world);
        self.world.ledger.clear();
        // In words too: the last scene's lines, with their times from
        // another run, read as this one's ("Disc 24 hit the right wall" in
        // a scene of two discs, 4.14 s under 2.42 s).
        self.messages.narration.start_afresh();
        // An edit's answer was about discs of the run before (a refused
        // v_y stayed red in the table after a reset).
        self.messages.table = None;
        self.messages.fields = None;
    }

    /// Runs to the next impact, between discs or on a wall, and pauses at
    /// its instant, the ledger open.
    pub(super) fn run_to_next_collision(&mut self) {
        self.clock.paused = true;
        if !self.world.ledger.is_on() {
            self.world.ledger.keep(LEDGER_KEEP);
        }
        let counted = self.world.total_pair_collisions;
        let (found, at_once) = self.run_recording(NEXT_COLLISION_LIMIT);
        let unrecorded = self.world.total_pair_collisions > counted;
        self.overlays.contact = true;
        self.panels.docks_open = true;
        self.panels.dock_expanded = true;
        self.panels.tab = DockTab::Collisions;
        // The drawer (a small window's controls) floats over the ledger J
        // opens, whose result it would hide: it closes (≡ opens it again).
        self.panels.drawer_open = false;
        let said = match found {
            Some(impulse::ledger::Impact::Pair(c)) => {
                let (dp, dke) = c.total_change();
                let [a, b] = c.discs_in_order();
                tr!(
                    "next-collision-pair",
                    a = disc_number(a),
                    b = disc_number(b),
                    time = with_unit(c.time, 3, "s"),
                    momentum_kept = if reads_as_zero(dp.x, 3) && reads_as_zero(dp.y, 3) {
                        "yes"
                    } else {
                        "no"
                    },
                    momentum = vector(dp, 3, "kg·m/s"),
                    energy_change = change_word(dke),
                    energy = with_unit(dke.abs(), 3, "J")
                )
            }
            Some(impulse::ledger::Impact::Wall(w)) => {
                let (_, dke) = w.total_change();
                tr!(
                    "next-collision-wall",
                    disc = disc_number(w.disc),
                    wall = w.wall.name(),
                    time = with_unit(w.time, 3, "s"),
                    impulse = vector(w.wall_impulse(), 3, "kg·m/s"),
                    energy_change = change_word(dke),
                    energy = with_unit(dke.abs(), 3, "J")
                )
            }
            None if unrecorded => tr!(
                "next-collision-verlet",
                time = with_unit(self.world.time, 3, "s")
            ),
            None => tr!(
                "next-collision-none",
                limit = with_unit(NEXT_COLLISION_LIMIT, 0, "s")
            ),
        };
        // The others of that moment come first, so a strip too narrow for
        // the whole report still says the stop is more than one impact (the
        // plots and totals already hold them all).
        if found.is_some() && at_once > 1 {
            self.toast(tr!(
                "next-collision-at-once",
                impacts = at_once,
                first = said
            ));
        } else {
            self.toast(said);
        }
    }

    /// Runs to the next impact for at most `limit` seconds, recording the
    /// way there as playing would: the totals, trails and rewind history
    /// every [`RECORD_EVERY`] of simulated time, and in small scenes the
    /// totals just before and after each step with an impact. So the plots
    /// show a wall's push as a step at its instant, not a ramp from where
    /// J was pressed, and the rewind steps back through the approach.
    ///
    /// Returns the impact found and how many impacts the last step had:
    /// those of its instant with `exact` (see
    /// [`impulse::method::exact::SAME_INSTANT`]), those of the step with the
    /// others.
    fn run_recording(&mut self, limit: f64) -> (Option<impulse::ledger::Impact>, usize) {
        let mut at_once = 0;
        let small = self.world.particles.len() <= totals::SAMPLE_COLLISIONS_MAX_DISCS;
        let record = &mut self.record;
        let mut before = (self.world.time, self.world.metrics());
        let mut recorded = self.world.time;
        let found =
            self.world
                .run_to_next_impact_watched(self.clock.dt, limit, &mut |world, stats| {
                    at_once = stats.pair_collisions + stats.wall_hits;
                    let impacts = at_once > 0;
                    let frame = world.time - recorded >= RECORD_EVERY;
                    if !(small || impacts || frame) {
                        return;
                    }
                    let now = world.metrics();
                    if small && impacts {
                        let walls = stats.wall_hits > 0;
                        record
                            .totals
                            .around_impact((before.0, &before.1), world, &now, walls);
                    }
                    if impacts || frame {
                        record.moment(world, &now);
                        recorded = world.time;
                    }
                    before = (world.time, now);
                });
        if recorded != self.world.time {
            let now = self.world.metrics();
            self.record.moment(&self.world, &now);
        }
        (found, at_once)
    }

    /// Shows an earlier (or later) recorded moment; pauses.
    pub(super) fn scrub(&mut self, delta: isize) {
        self.clock.paused = true;
        self.pointer.cancel();
        match self.record.history.scrub(&mut self.world, delta) {
            // Forward onto the newest moment: back at the run, not rewound.
            Some(t) if delta > 0 && self.record.history.release_at_newest() => {
                self.toast(tr!("rewound-newest", time = plain(t, 3)));
            }
            Some(t) => {
                // The snapshot brought back its ledger and counters; the
                // plot keeps what led up to this moment.
                let (oldest, newest) = self.record.history.span().unwrap_or((t, t));
                self.toast(tr!(
                    "rewound-to",
                    time = plain(t, 3),
                    oldest = plain(oldest, 3),
                    newest = plain(newest, 3)
                ));
            }
            None => self.toast(tr!("nothing-recorded")),
        }
    }

    /// Saves the next frame as a PNG in the output folder (F12).
    pub(super) fn request_screenshot(&mut self) {
        let stem = self.file_stem();
        self.session.requests.screenshot = Some(scenes::free_file(&self.session.out, &stem, "png"));
    }

    /// Writes the totals, the discs and the ledger as CSV files.
    pub(super) fn export_data(&mut self) {
        let stem = self.file_stem();
        let samples: Vec<totals::Sample> = self.record.totals.samples().copied().collect();
        let dir = self.session.out.clone();
        if cfg!(target_arch = "wasm32") {
            for (name, text) in super::export::files(&stem, &samples, &self.world) {
                let (stem, _) = name.rsplit_once('.').unwrap_or((&name, ""));
                let _ = scenes::keep_file(&dir, stem, "csv", text.as_bytes()); // downloads
            }
            self.toast(tr!("exported-downloaded"));
            return;
        }
        match super::export::export_all(&dir, &stem, &samples, &self.world) {
            Ok(files) => {
                eprintln!(
                    "impulse: exported {} files to {}",
                    files.len(),
                    dir.display()
                );
                self.toast(tr!("exported", folder = crate::files::shown(&dir)));
            }
            Err(e) => self.report(tr!(
                "not-exported",
                folder = dir.display().to_string(),
                error = e.to_string()
            )),
        }
    }

    /// In the centre-of-mass view, the world as drawn: velocities relative
    /// to the centre of mass (the camera follows it, [`Sandbox::tick`]).
    pub fn world_as_seen(&self) -> Option<impulse::World> {
        self.overlays.com_view?;
        let m = self.world.metrics();
        let mut seen = self.world.clone();
        for p in &mut seen.particles {
            p.vel -= m.center_of_mass_velocity;
        }
        Some(seen)
    }
}

#[cfg(test)]
mod tests {
    use super::RECORD_EVERY;
    use crate::app::model::command::Command;
    use crate::app::model::tests::sandbox_in;
    use impulse::method::{Method, Setting};

    /// Head-on (no gravity): the totals change only at an impact. J twice,
    /// to the collision at 2.4 s and to the right wall at 5.6 s: the plot
    /// holds the totals J started from up to the impact, sampled as often
    /// as frames would, and changes there (before, the wall's push was a
    /// straight ramp from where J was pressed); the rewind steps back
    /// through the approach instead of jumping to where J was pressed.
    #[test]
    fn the_way_to_the_next_collision_is_plotted_and_kept_as_playing_would() {
        let dir = tempfile::tempdir().unwrap();
        for method in [
            Setting::Auto,
            Setting::Fixed(Method::Exact),
            Setting::Fixed(Method::Impulse),
        ] {
            let mut s = sandbox_in(dir.path(), "preset-1-head-on.toml");
            s.apply(Command::SetMethod(method));
            let frame = RECORD_EVERY + s.clock.dt + 1e-9;
            for j in 0..2 {
                let start = s.world.metrics();
                let (t0, p0, e0) = (s.world.time, start.momentum, start.kinetic_energy);
                s.apply(Command::NextCollision);
                let hit = s.world.ledger.last_impact().unwrap().time();
                let samples: Vec<_> = s
                    .record
                    .totals
                    .samples()
                    .filter(|x| x.time >= t0)
                    .copied()
                    .collect();
                let approach: Vec<_> = samples.iter().filter(|x| x.time < hit - 1e-9).collect();
                let label = format!("{method}, J number {}", j + 1);
                assert!(
                    approach.len() as f64 >= (hit - t0) / frame,
                    "{label}: {} samples over {} s",
                    approach.len(),
                    hit - t0
                );
                for x in &approach {
                    assert!(
                        (x.momentum - p0).length() < 1e-9 && (x.energy() - e0).abs() < 1e-9,
                        "{label}: at {} s the plot has p {} and E {}, not {p0} and {e0}",
                        x.time,
                        x.momentum,
                        x.energy()
                    );
                }
                let last_before = approach.last().map_or(t0, |x| x.time);
                assert!(hit - last_before <= frame, "{label}: {last_before} → {hit}");
                for pair in samples.windows(2) {
                    assert!(pair[1].time - pair[0].time <= frame, "{label}: {pair:?}");
                }
                let now = s.world.metrics();
                assert_eq!(samples.last().map(|x| x.momentum), Some(now.momentum));
                // One moment back is on the way, not where J was pressed.
                s.apply(Command::Scrub(-1));
                let back = s.world.time;
                assert!(back < hit && hit - back <= frame, "{label}: back to {back}");
                s.apply(Command::Scrub(1));
                // Forward onto the newest moment is back at the run.
                assert!(s.record.history.cursor().is_none(), "{label}");
                assert!(
                    s.message().is_some_and(|m| m.contains("newest")),
                    "{label}: {:?}",
                    s.message()
                );
                assert!(
                    (s.world.time - hit).abs() <= s.clock.dt + 1e-9,
                    "{label}: forward to {}, the impact at {hit}, dt {}",
                    s.world.time,
                    s.clock.dt
                );
            }
            assert!(s.world.time > 5.0, "{method}: reached the right wall");
        }
    }

    /// A scene running slower than asked says so, and with many discs
    /// suggests fewer.
    #[test]
    fn a_slow_scene_says_its_rate_and_with_many_discs_suggests_fewer() {
        let dir = tempfile::tempdir().unwrap();
        let mut s = sandbox_in(dir.path(), "preset-8-gas.toml");
        s.clock.paused = false;
        // 0.3 simulated seconds a real second, for two seconds.
        for k in 0..=20 {
            let now = f64::from(k) * 0.1;
            s.steps.realtime.push(now, 0.3 * now, true);
        }
        let note = s.slow_note().expect("slower than asked");
        assert_eq!(note, "running at 0.30× real time");
        let disc = s.world.particles[0];
        s.world.particles.resize(super::super::MANY_DISCS + 1, disc);
        let note = s.slow_note().expect("slower than asked");
        assert!(note.ends_with("fewer discs would run faster"), "{note}");
        s.clock.paused = true;
        assert_eq!(s.slow_note(), None, "paused: nothing to say");
    }
}
