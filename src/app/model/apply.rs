//! Carrying a command out: the one place where a person's action changes
//! the sandbox. A command that may change the scene is checked before and
//! after; only a real change is remembered for undo.

use super::command::{Command, Dir, Law};
use super::{next_scale, scenes, Sandbox};
use crate::app::lang::tr;
use crate::app::numbers::{vector, with_unit};
use glam::DVec2;
use impulse::broad_phase::BroadPhaseKind;
use impulse::method::{Method, Setting};
use std::hash::{Hash, Hasher};

/// Zoom factor per wheel notch or key press.
pub const ZOOM_STEP: f64 = 1.15;
/// Gravity G switches on (m/s², downwards).
pub const EARTH_GRAVITY: f64 = 9.81;

pub const METHODS: [Setting<Method>; 5] = [
    Setting::Auto,
    Setting::Fixed(Method::Seed),
    Setting::Fixed(Method::Impulse),
    Setting::Fixed(Method::Verlet),
    Setting::Fixed(Method::Exact),
];
pub const BROAD_PHASES: [Setting<BroadPhaseKind>; 5] = [
    Setting::Auto,
    Setting::Fixed(BroadPhaseKind::Brute),
    Setting::Fixed(BroadPhaseKind::Grid),
    Setting::Fixed(BroadPhaseKind::Sap),
    Setting::Fixed(BroadPhaseKind::Quadtree),
];
pub const SUBSTEPS: [Setting<u32>; 6] = [
    Setting::Auto,
    Setting::Fixed(1),
    Setting::Fixed(2),
    Setting::Fixed(4),
    Setting::Fixed(8),
    Setting::Fixed(16),
];

/// The entry after `current` in `list` (the first if `current` is not in it).
fn cycle<T: PartialEq + Copy>(list: &[T], current: T) -> T {
    let next = list.iter().position(|&x| x == current).map_or(0, |k| k + 1);
    list[next % list.len()]
}

/// `e` moved by one tenth up or down, kept in `range`.
fn nudge(e: f64, dir: Dir, (lo, hi): (f64, f64)) -> f64 {
    let tenths = (e * 10.0).round() + if dir == Dir::Up { 1.0 } else { -1.0 };
    (tenths / 10.0).clamp(lo, hi)
}

/// A law's name in a message.
pub fn law_name(law: Law) -> String {
    match law {
        Law::Restitution => tr!("law-restitution"),
        Law::WallRestitution => tr!("law-wall-restitution"),
        Law::Roughness => tr!("law-roughness"),
        Law::WallRoughness => tr!("law-wall-roughness"),
    }
}

/// The totals the Totals tab plots: momentum, angular momentum, energies.
fn totals_of(world: &impulse::World) -> [f64; 5] {
    let m = world.metrics();
    [
        m.momentum.x,
        m.momentum.y,
        m.angular_momentum,
        m.kinetic_energy,
        m.rotational_energy,
    ]
}

impl Sandbox {
    /// Carries out `command`. A command that may change the scene is
    /// remembered for undo only if it did; while a modal question waits,
    /// only its answers and what changes no state go through.
    pub fn apply(&mut self, command: Command) {
        let Some(command) = self.under_modal(command) else {
            return;
        };
        let Some(kind) = command.edit_kind() else {
            return self.carry_out(command);
        };
        let now = self.session.now;
        let merge = self.undo.would_merge(kind, now);
        let before = (!merge).then(|| self.moment());
        let print = self.fingerprint();
        let totals = totals_of(&self.world);
        let voids_caption = command.voids_caption();
        self.carry_out(command);
        if self.fingerprint() == print {
            return;
        }
        // A total moved by the person (a disc launched, flung, removed or
        // edited) is no change the physics made: the Totals tab starts
        // afresh from it. A launch had read "Δp (6.000, 1.500) kg·m/s"
        // with nothing to say a disc had come.
        if totals_of(&self.world) != totals {
            self.record.totals.restart(&self.world);
        }
        match before {
            Some(moment) => self.undo.remember(move || moment, kind, now),
            None => self.undo.merge(kind, now),
        }
        // A scene opened is the person's choice, not work to keep.
        if kind != "edit-open-scene" && kind != "edit-reset" {
            self.open.unsaved = true;
            // Cleared, the box is no set-up to come back to (R after C
            // brings back what was cleared).
            if kind != "edit-clear" {
                self.open.setup = Some(self.world.clone());
            }
        }
        if voids_caption {
            self.open.edited = true;
        }
    }

    /// A hash of everything undo brings back: the discs, the laws and the
    /// choices, the time, and which scene is open.
    pub fn fingerprint(&self) -> u64 {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        let w = &self.world;
        w.time.to_bits().hash(&mut h);
        w.particles.len().hash(&mut h);
        for p in &w.particles {
            let numbers = [p.pos.x, p.pos.y, p.vel.x, p.vel.y, p.mass, p.radius, p.spin];
            for x in numbers {
                x.to_bits().hash(&mut h);
            }
            p.color.hash(&mut h);
        }
        format!("{:?} {:?}", w.laws, w.choices()).hash(&mut h);
        self.open.origin.hash(&mut h);
        self.open.scene.name.hash(&mut h);
        h.finish()
    }

    fn carry_out(&mut self, command: Command) {
        use Command::*;
        match command {
            TogglePause => self.clock.paused = !self.clock.paused,
            Step => self.clock.single_step(),
            Slower | Faster => {
                self.clock
                    .change_time_scale(if command == Slower { -1 } else { 1 });
                self.steps.realtime.clear();
                let scale = crate::app::numbers::field(self.clock.time_scale());
                self.toast(tr!("time-scale", scale = scale));
            }
            SetTimeScale(k) => {
                self.clock.set_time_scale_index(k);
                self.steps.realtime.clear();
            }
            NextCollision => self.run_to_next_collision(),
            Scrub(k) => self.scrub(k),
            OpenPreset(k) => self.open_preset_from_menu(k),
            OpenEmpty => self.open_preset_from_menu(scenes::PRESETS.len() - 1),
            OpenFile(path) => self.open_file(&path),
            RenameScene(name) => self.rename_scene(&name),
            OpenText { name, text } => self.open_text(&name, &text),
            Reset => self.say_reset(),
            Clear => self.clear_discs(),
            Save => {
                let _ = self.save_scene(); // said in the window and on the terminal
            }
            Share => self.share_link(),
            Export => self.export_data(),
            Screenshot => self.request_screenshot(),
            Undo => self.undo_change(),
            Redo => self.redo_change(),
            RestoreRecovery => self.restore_recovery(),
            SetRecoveryAside => self.set_recovery_aside(),
            ShowStart => {
                self.panels.start_open = true;
                self.pause_for_modal();
            }
            StartWith(tile) => self.start_with(tile),
            CloseStart => {
                self.panels.start_open = false;
                self.resume_after_modal();
            }
            ShowAllControls => self.panels.focus = super::start::Tile::FreePlay,
            ReopenKept => self.reopen_kept(),
            SetLaw(law, v) => {
                let (lo, hi) = law.range().control;
                *law.of_mut(&mut self.world.laws) = ((v * 100.0).round() / 100.0).clamp(lo, hi);
            }
            NudgeLaw(law, dir) => {
                let value = law.of_mut(&mut self.world.laws);
                *value = nudge(*value, dir, law.range().control);
                let v = *value;
                self.toast(format!(
                    "{} = {}",
                    law_name(law),
                    crate::app::numbers::plain(v, 1)
                ));
            }
            SetFriction(mu) => {
                let (lo, hi) = impulse::laws::FRICTION_RANGE.control;
                self.world.laws.friction = mu.map(|m| ((m * 100.0).round() / 100.0).clamp(lo, hi));
            }
            SetGravity(g) => {
                let (lo, hi) = impulse::laws::GRAVITY_RANGE.control;
                self.world.laws.gravity = DVec2::new(0.0, -g.abs().clamp(lo, hi));
            }
            ToggleGravity => {
                let on = self.world.laws.gravity == DVec2::ZERO;
                self.world.laws.gravity = DVec2::new(0.0, if on { -EARTH_GRAVITY } else { 0.0 });
                let g = self.world.laws.gravity.length();
                self.toast(tr!("gravity-now", gravity = with_unit(g, 2, "m/s²")));
            }
            SetBoundary(b) => {
                self.world.laws.boundary = b;
                // Only a box has walls (a scene file refuses them otherwise).
                if b != impulse::Boundary::Box {
                    self.world.laws.walls = impulse::Walls::ALL;
                }
            }
            SetMethod(m) => self.world.method = m,
            SetBroadPhase(b) => self.world.broad_phase = b,
            SetSubsteps(k) => self.world.substeps = k,
            CycleMethod => {
                self.world.method = cycle(&METHODS, self.world.method);
                self.toast(tr!("method-now", method = self.world.method.to_string()));
            }
            CycleBroadPhase => {
                self.world.broad_phase = cycle(&BROAD_PHASES, self.world.broad_phase);
                self.toast(tr!(
                    "broad-phase-now",
                    broad = self.world.broad_phase.to_string()
                ));
            }
            CycleSubsteps => {
                self.world.substeps = cycle(&SUBSTEPS, self.world.substeps);
                self.toast(tr!(
                    "substeps-now",
                    substeps = self.world.substeps.to_string()
                ));
            }
            SetNewRadius(r) => self.new_discs.disc.radius = self.radius_within(r),
            SetNewMass(m) => self.new_discs.disc.mass = m.clamp(1e-3, 1e6),
            StepNewRadius(dir) => {
                let factor = if dir == Dir::Up { 1.25 } else { 0.8 };
                let r = self.new_discs.disc.radius * factor;
                self.new_discs.disc.radius = self.radius_within(r);
                let r = self.new_discs.disc.radius;
                self.toast(tr!("new-disc-radius", radius = with_unit(r, 2, "m")));
            }
            StepNewMass(dir) => {
                let factor = if dir == Dir::Up { 2.0 } else { 0.5 };
                let m = (self.new_discs.disc.mass * factor).clamp(1e-3, 1e6);
                self.new_discs.disc.mass = m;
                self.toast(tr!("new-disc-mass", mass = with_unit(m, 3, "kg")));
            }
            SizeFollowsMass(on) => self.new_discs.size_follows_mass = on,
            Select(i) => {
                self.selected = i.filter(|&i| i < self.world.particles.len());
                if self.selected.is_some() {
                    self.panels.picks = self.panels.picks.wrapping_add(1);
                }
            }
            SelectNext(step) => self.select_next(step),
            AimSelected(dv) => self.aim_selected(dv),
            // Enter, the key that opened the lesson from its tile, plays it
            // (a disc at the centre had landed on the lesson's discs).
            LaunchAtCentre if self.lesson_waiting() => self.clock.paused = false,
            LaunchAtCentre => self.launch_at_centre(),
            Describe => {
                let words = self.describe();
                self.announce(words);
            }
            EditDisc { disc, text, from } => self.edit_disc(disc, &text, from),
            DeleteSelected => self.delete_selected(),
            PointerDown(at) => self.pointer_down(at),
            PointerMove(at) => self.pointer_move(at),
            PointerUp(at) => self.pointer_up(at),
            ToggleVelocity => self.overlays.velocity = !self.overlays.velocity,
            ToggleMomentum => self.overlays.momentum = !self.overlays.momentum,
            ToggleDeltaP => self.overlays.delta_p = !self.overlays.delta_p,
            CycleReadouts => self.overlays.readouts = self.overlays.readouts.next(),
            SetReadouts(scope) => self.overlays.readouts = scope,
            ToggleCenterOfMass => {
                self.overlays.center_of_mass = !self.overlays.center_of_mass;
            }
            ToggleTrails => self.record.trails.on = !self.record.trails.on,
            TogglePalette => {
                self.overlays.safe_palette = !self.overlays.safe_palette;
                self.toast(if self.overlays.safe_palette {
                    tr!("palette-safe")
                } else {
                    tr!("palette-scene")
                });
            }
            ToggleCenterOfMassView => self.toggle_center_of_mass_view(),
            ToggleSound => self.toggle_sound(),
            ZoomIn | ZoomOut => {
                let factor = if command == ZoomIn {
                    ZOOM_STEP
                } else {
                    1.0 / ZOOM_STEP
                };
                let centre = self.view.camera.screen_center();
                self.zoom_at(centre, factor);
            }
            ZoomAt { at, factor } => self.zoom_at(at, factor),
            Pan(pixels) => {
                self.view.camera.pan_pixels(pixels);
                self.view.fitted = false;
            }
            Pinch { before, after } => {
                self.view.camera.pinch(before, after);
                self.view.fitted = false;
                self.pointer.cancel();
            }
            Fit => self.fit_camera(),
            ShowTab(tab) => self.panels.show_tab(tab),
            ClickTab(tab) => {
                let p = &mut self.panels;
                if p.tab == tab && p.dock_expanded {
                    p.dock_expanded = false;
                } else {
                    p.tab = tab;
                    p.dock_expanded = true;
                }
            }
            SayNoRoomForTab { side_docked } => self.toast(super::no_room_for_tab(side_docked)),
            ToggleDockExpanded => self.panels.dock_expanded = !self.panels.dock_expanded,
            SetTabHeight(h) => self.panels.tab_height = h.filter(|h| h.is_finite()),
            KeepTabHeight => {
                let height = self.panels.tab_height;
                self.remember(|r| r.tab_height = height);
            }
            ToggleDocks => self.panels.docks_open = !self.panels.docks_open,
            ToggleSide => self.panels.side_open = !self.panels.side_open,
            ToggleDrawer => self.panels.drawer_open = !self.panels.drawer_open,
            CloseDrawer => self.panels.drawer_open = false,
            ToggleHelp => {
                self.panels.help_open = !self.panels.help_open;
                // A drag begun in the world does not finish behind it.
                self.pointer.cancel();
            }
            TogglePresets => self.panels.presets_open = !self.panels.presets_open,
            Escape => {
                let p = &mut self.panels;
                if p.presets_open {
                    p.presets_open = false;
                } else if p.help_open {
                    p.help_open = false;
                } else if p.drawer_open {
                    p.drawer_open = false;
                } else {
                    self.selected = None;
                    self.pointer.cancel();
                }
            }
            SetScale(s) => {
                self.panels.set_scale(s);
                let scale = self.panels.scale;
                self.remember(|r| r.text_size = Some(scale));
            }
            NextScale => {
                self.panels.set_scale(next_scale(self.panels.scale));
                let scale = self.panels.scale;
                let shown = crate::app::numbers::field(f64::from(scale));
                self.toast(tr!("text-size", scale = shown));
                self.remember(|r| r.text_size = Some(scale));
            }
            SetTheme(t) => {
                self.panels.theme = t;
                self.remember(|r| r.theme = Some(t));
            }
            SetLanguage(lang) => {
                crate::app::lang::set_language(lang);
                // Shown and said in the new language, so that the last
                // message (the strip, the page's live region) is not left
                // in the old one.
                self.toast(tr!("language-now"));
                self.remember(|r| r.language = Some(lang.code().to_string()));
            }
            Fullscreen => self.session.requests.fullscreen = true,
            Quit => self.session.requests.quit = true,
        }
    }

    /// Resets the scene and says so: first to the person's set-up (the
    /// discs as their last change left them), then to the scene as it
    /// opened; where that dropped edits, also which key brings them back
    /// (a teacher who set 3 kg and pressed R saw the collision again at
    /// 1 kg, with no word why).
    fn say_reset(&mut self) {
        let (time, steps) = (self.world.time, self.world.steps);
        let setup = self.open.setup.as_ref();
        if let Some(setup) = setup.filter(|w| (w.time, w.steps) != (time, steps)) {
            self.world = setup.clone();
            self.back_to_setup();
            // Paused there, so that R again reaches the scene as it opened
            // (running, it left the set-up at once and R came back to it).
            self.clock.paused = true;
            let reset = super::bindings::keys_of(&Command::Reset);
            let time = crate::app::numbers::plain(self.world.time, 2);
            self.toast_for(tr!("scene-back-to-setup", time = time, reset = reset), 8.0);
            return;
        }
        match self.reset_scene() {
            Some(true) => {
                let undo = super::bindings::keys_of(&Command::Undo);
                self.toast_for(tr!("scene-reset-edits", undo = undo), 8.0);
            }
            Some(false) if self.open.lesson.is_some() => {
                // A lesson starts again as it opened: paused on its
                // question, in the strip at once (a toast had hidden it
                // while the discs closed in, and the answer came).
                self.clock.paused = true;
                self.announce(tr!("scene-reset"));
                self.ask();
            }
            Some(false) => self.toast(tr!("scene-reset")),
            None => {}
        }
    }

    /// Says which scene opened; over one `left` with changes, also which
    /// key brings it back (a digit key pressed when a click meant for a
    /// field missed it replaces the lesson at once). A scene with a caption
    /// (a lesson) is named only to a screen reader and in *In words*: the
    /// caption strip is the caption's at once ("Opened Head-on, equal
    /// masses" had held it through the first seconds, before the hit it
    /// tells a class to watch for), and the top bar has the name.
    pub(super) fn say_opened(&mut self, name: String, left: Option<String>) {
        match left {
            Some(previous) => {
                let undo = super::bindings::keys_of(&Command::Undo);
                let said = tr!(
                    "scene-opened-undo",
                    name = name,
                    previous = previous,
                    undo = undo
                );
                self.toast_for(said, 8.0);
            }
            None if self.scene_description().is_some() => {
                self.announce(tr!("scene-opened", name = name));
            }
            None => self.toast(tr!("scene-opened", name = name)),
        }
    }

    /// A preset opened by its key or the menu: all controls, and the start
    /// screen (if open) gives way.
    fn open_preset_from_menu(&mut self, k: usize) {
        self.open_preset(k);
        self.panels.focus = super::start::Tile::FreePlay;
        if std::mem::take(&mut self.panels.start_open) {
            self.clock.paused = false;
            self.resume_after_modal();
        }
    }

    /// A new disc's radius kept between 1 cm and the largest the box takes
    /// (a box narrower than 2.2 cm takes less than 1 cm).
    fn radius_within(&self, r: f64) -> f64 {
        let biggest = self.biggest_radius();
        r.max(0.01_f64.min(biggest)).min(biggest)
    }

    /// Z: the centre-of-mass view on or off. The camera moves with the
    /// centre of mass and arrows and readouts show velocities relative to
    /// it; the discs' velocities are never changed.
    fn toggle_center_of_mass_view(&mut self) {
        if self.overlays.com_view.take().is_some() {
            self.toast(tr!("com-view-off"));
            return;
        }
        let m = self.world.metrics();
        self.overlays.com_view = Some(self.view.camera.center - m.center_of_mass);
        self.view.fitted = false;
        self.toast(tr!(
            "com-view-on",
            velocity = vector(m.center_of_mass_velocity, 3, "m/s")
        ));
    }
}
