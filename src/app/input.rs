//! Keys, the mouse, touches and dropped files, as commands. Keys go through
//! the bindings table ([`crate::app::model::bindings`]); nothing here
//! changes the model.

use super::model::bindings::{command_for, Key, Trigger};
use super::model::{Command, Sandbox};
use super::ui::Panels;
use crate::app::lang::tr;
use glam::DVec2;
use macroquad::prelude::*;

/// What input keeps between frames.
#[derive(Default)]
pub struct Input {
    last_mouse: DVec2,
    /// Two fingers down on a touch screen: where they were last frame.
    pinch: Option<[DVec2; 2]>,
    /// The left button went down in the world (not on a panel).
    pressed_in_world: bool,
    pub fullscreen: bool,
    /// macroquad's queue of this frame's input events, read for where the
    /// left button went down and came up.
    events: Option<usize>,
}

/// Where the left button went down (the first time) and came up (the last
/// time) this frame, in window pixels. A slow frame reads the pointer only
/// once, after everything queued: a press on a disc followed at once by a
/// move would otherwise count where the pointer had got to, off the disc.
#[derive(Default)]
struct LeftButton {
    down: Option<DVec2>,
    up: Option<DVec2>,
}

impl LeftButton {
    fn at(x: f32, y: f32) -> DVec2 {
        let scale = f64::from(miniquad::window::dpi_scale());
        DVec2::new(f64::from(x), f64::from(y)) / scale
    }
}

impl miniquad::EventHandler for LeftButton {
    fn update(&mut self) {}
    fn draw(&mut self) {}
    fn mouse_button_down_event(&mut self, button: miniquad::MouseButton, x: f32, y: f32) {
        if button == miniquad::MouseButton::Left && self.down.is_none() {
            self.down = Some(Self::at(x, y));
        }
    }
    fn mouse_button_up_event(&mut self, button: miniquad::MouseButton, x: f32, y: f32) {
        if button == miniquad::MouseButton::Left {
            self.up = Some(Self::at(x, y));
        }
    }
}

/// Whether a modifier was down at any moment of this frame: held, pressed
/// or released. At a low frame rate a quick Ctrl+Q can press and release
/// Ctrl, or release it together with Q, within one frame.
fn held_or_pressed(keys: [KeyCode; 2]) -> bool {
    keys.into_iter()
        .any(|k| is_key_down(k) || is_key_pressed(k) || is_key_released(k))
}

/// The key codes the bindings table's keys are read from.
fn key_codes(key: Key) -> &'static [KeyCode] {
    use KeyCode as K;
    match key {
        Key::Space => &[K::Space],
        Key::Enter => &[K::Enter, K::KpEnter],
        Key::Tab => &[K::Tab],
        Key::Escape => &[K::Escape],
        Key::Delete => &[K::Delete],
        Key::Backspace => &[K::Backspace],
        Key::Left => &[K::Left],
        Key::Right => &[K::Right],
        Key::Up => &[K::Up],
        Key::Down => &[K::Down],
        Key::PageUp => &[K::PageUp],
        Key::PageDown => &[K::PageDown],
        Key::Home => &[K::Home],
        Key::End => &[K::End],
        Key::Equal => &[K::Equal],
        Key::Minus => &[K::Minus],
        Key::KpAdd => &[K::KpAdd],
        Key::KpSubtract => &[K::KpSubtract],
        Key::LeftBracket => &[K::LeftBracket],
        Key::RightBracket => &[K::RightBracket],
        Key::Comma => &[K::Comma],
        Key::Period => &[K::Period],
        Key::Digit(d) => match d {
            0 => &[K::Key0],
            1 => &[K::Key1],
            2 => &[K::Key2],
            3 => &[K::Key3],
            4 => &[K::Key4],
            5 => &[K::Key5],
            6 => &[K::Key6],
            7 => &[K::Key7],
            8 => &[K::Key8],
            _ => &[K::Key9],
        },
        Key::F(n) => match n {
            1 => &[K::F1],
            2 => &[K::F2],
            3 => &[K::F3],
            4 => &[K::F4],
            8 => &[K::F8],
            11 => &[K::F11],
            12 => &[K::F12],
            _ => &[],
        },
        Key::Letter(c) => match c {
            'A' => &[K::A],
            'B' => &[K::B],
            'C' => &[K::C],
            'D' => &[K::D],
            'E' => &[K::E],
            'F' => &[K::F],
            'G' => &[K::G],
            'H' => &[K::H],
            'I' => &[K::I],
            'J' => &[K::J],
            'K' => &[K::K],
            'L' => &[K::L],
            'M' => &[K::M],
            'N' => &[K::N],
            'O' => &[K::O],
            'P' => &[K::P],
            'Q' => &[K::Q],
            'R' => &[K::R],
            'S' => &[K::S],
            'T' => &[K::T],
            'U' => &[K::U],
            'V' => &[K::V],
            'W' => &[K::W],
            'X' => &[K::X],
            'Y' => &[K::Y],
            'Z' => &[K::Z],
            _ => &[],
        },
    }
}

/// Every key the bindings table reads.
fn all_keys() -> impl Iterator<Item = Key> {
    let letters = ('A'..='Z').map(Key::Letter);
    let digits = (0..=9).map(Key::Digit);
    let f = [1, 2, 3, 4, 8, 11, 12].into_iter().map(Key::F);
    let rest = [
        Key::Space,
        Key::Enter,
        Key::Tab,
        Key::Escape,
        Key::Delete,
        Key::Backspace,
        Key::Left,
        Key::Right,
        Key::Up,
        Key::Down,
        Key::PageUp,
        Key::PageDown,
        Key::Home,
        Key::End,
        Key::Equal,
        Key::Minus,
        Key::KpAdd,
        Key::KpSubtract,
        Key::LeftBracket,
        Key::RightBracket,
        Key::Comma,
        Key::Period,
    ];
    letters.chain(digits).chain(f).chain(rest)
}

impl Input {
    /// This frame's commands from the keys, the mouse, touches and dropped
    /// files. `panels` says whether a text field has the keyboard and
    /// whether the pointer is on a panel; a click in the world or Esc gives
    /// the keyboard back to the world after Enter in a field.
    pub fn commands(&mut self, panels: &mut Panels, model: &Sandbox, mouse: DVec2) -> Vec<Command> {
        let mut out = Vec::new();
        let left = self.left_button();
        if is_key_pressed(KeyCode::F6) {
            // Between the window's parts, wherever the keyboard is.
            let shift = held_or_pressed([KeyCode::LeftShift, KeyCode::RightShift]);
            panels.jump_to_next_part(shift, model.modal_open() || model.panels.help_open);
        }
        self.keys(panels, model.arrows_aim(), &mut out);
        self.touches(&mut out);
        if self.pinch.is_none() {
            self.mouse(panels, model, (mouse, left), &mut out);
        }
        dropped_files(&mut out);
        self.last_mouse = mouse;
        out
    }

    /// This frame's left-button events (read every frame: macroquad keeps
    /// them until they are read).
    fn left_button(&mut self) -> LeftButton {
        use macroquad::input::utils;
        let events = *self
            .events
            .get_or_insert_with(utils::register_input_subscriber);
        let mut left = LeftButton::default();
        utils::repeat_all_miniquad_input(&mut left, events);
        left
    }

    /// The keys' commands; `aims`: the arrow keys aim the selected disc
    /// (paused) instead of panning.
    fn keys(&mut self, panels: &mut Panels, aims: bool, out: &mut Vec<Command>) {
        let ctrl = held_or_pressed([KeyCode::LeftControl, KeyCode::RightControl]);
        let shift = held_or_pressed([KeyCode::LeftShift, KeyCode::RightShift]);
        // "?" opens the help as H does (its button reads "? Help"), by the
        // character typed, whatever keys give it on this keyboard. The
        // characters are read every frame: macroquad keeps them until then.
        let mut question = false;
        while let Some(c) = get_char_pressed() {
            question |= c == '?';
        }
        if ctrl && is_key_pressed(KeyCode::Q) && !cfg!(target_arch = "wasm32") {
            out.push(Command::Quit);
            return;
        }
        if panels.typing {
            return; // the keys went into a text field (Ctrl+Z too: its own undo)
        }
        // After Enter in a field the keyboard stays with the panel until a
        // click in the world or Esc, all but the run's own keys: Space and J
        // act on the clock (a teacher who set a mass presses Space next),
        // and what would type on (a digit opening a preset, Backspace
        // deleting the selected disc, Enter launching one) waits.
        let after_field = panels.panel_keyboard && !ctrl;
        if after_field && is_key_pressed(KeyCode::Escape) {
            panels.panel_keyboard = false;
            return;
        }
        if question && !after_field && !ctrl {
            out.push(Command::ToggleHelp);
        }
        for key in all_keys() {
            let codes = key_codes(key);
            if codes.iter().any(|&k| is_key_pressed(k)) {
                let command = command_for(key, ctrl, shift, Trigger::Press);
                if let Some(c) = command.filter(|c| !after_field || c.runs_the_clock()) {
                    // The browser's tab is closed by the browser, never by the page.
                    let browsers = cfg!(target_arch = "wasm32") && c == Command::Quit;
                    let aim = matches!(c, Command::AimSelected(_));
                    if !browsers && (aims || !aim) {
                        out.push(c);
                    }
                }
            }
            if !ctrl && !after_field && codes.iter().any(|&k| is_key_down(k)) {
                if let Some(c) = command_for(key, false, shift, Trigger::Hold) {
                    // While the arrows aim, they do not pan.
                    if !(aims && matches!(c, Command::Pan(_))) {
                        out.push(c);
                    }
                }
            }
        }
    }

    /// Two or more fingers on a touch screen pan and zoom (the first
    /// finger alone is a mouse: a drag launches a disc).
    fn touches(&mut self, out: &mut Vec<Command>) {
        let fingers: Vec<DVec2> = touches()
            .iter()
            .filter(|t| {
                matches!(
                    t.phase,
                    TouchPhase::Started | TouchPhase::Moved | TouchPhase::Stationary
                )
            })
            .map(|t| DVec2::new(f64::from(t.position.x), f64::from(t.position.y)))
            .collect();
        if fingers.len() >= 2 {
            let now = [fingers[0], fingers[1]];
            if let Some(before) = self.pinch {
                out.push(Command::Pinch { before, after: now });
            }
            self.pinch = Some(now);
            self.pressed_in_world = false;
        } else if self.pinch.is_some() && fingers.is_empty() {
            self.pinch = None;
        }
    }

    fn mouse(
        &mut self,
        panels: &mut Panels,
        model: &Sandbox,
        (mouse, left): (DVec2, LeftButton),
        out: &mut Vec<Command>,
    ) {
        // Over a panel or popup the mouse belongs to its widgets: no zoom,
        // pan or new gesture there (one begun in the world finishes).
        let on_panel = panels.pointer_on_ui;
        let (_, wheel) = mouse_wheel();
        if wheel != 0.0 && !on_panel {
            let notches = f64::from(wheel.clamp(-5.0, 5.0)).signum();
            out.push(Command::ZoomAt {
                at: mouse,
                factor: super::model::apply::ZOOM_STEP.powf(notches),
            });
        }
        let panning =
            is_mouse_button_down(MouseButton::Right) || is_mouse_button_down(MouseButton::Middle);
        let just_started = is_mouse_button_pressed(MouseButton::Right)
            || is_mouse_button_pressed(MouseButton::Middle);
        if panning && !just_started && !on_panel && mouse != self.last_mouse {
            out.push(Command::Pan(mouse - self.last_mouse));
        }
        if is_mouse_button_pressed(MouseButton::Left) && !on_panel {
            // A click in the world takes the keyboard back from a panel.
            panels.panel_keyboard = false;
            self.pressed_in_world = true;
            out.push(Command::PointerDown(left.down.unwrap_or(mouse)));
        } else if is_mouse_button_down(MouseButton::Left)
            && self.pressed_in_world
            && !matches!(model.pointer.gesture, super::model::gesture::Gesture::Idle)
        {
            out.push(Command::PointerMove(mouse));
        }
        if is_mouse_button_released(MouseButton::Left) && std::mem::take(&mut self.pressed_in_world)
        {
            out.push(Command::PointerUp(left.up.unwrap_or(mouse)));
        }
    }
}

/// Opens the scene files dropped on the window (bytes in the browser, a
/// path on the desktop); a bad one is reported and the scene kept.
fn dropped_files(out: &mut Vec<Command>) {
    for file in macroquad::input::get_dropped_files() {
        let name = file
            .path
            .as_ref()
            .map_or_else(|| tr!("dropped-file"), |p| p.display().to_string());
        let text = match (&file.bytes, &file.path) {
            (Some(bytes), _) => String::from_utf8(bytes.clone())
                .map_err(|_| tr!("dropped-not-text", name = name.as_str())),
            (None, Some(path)) => std::fs::read_to_string(path).map_err(|e| {
                tr!(
                    "dropped-unreadable",
                    name = name.as_str(),
                    error = e.to_string()
                )
            }),
            (None, None) => Err(tr!("dropped-empty")),
        };
        out.push(Command::OpenText { name, text });
    }
}
