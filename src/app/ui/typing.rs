//! Typing into a field, mended where egui-macroquad gets it wrong. On X11,
//! miniquad reports a key's character before the key itself, and
//! egui-macroquad passes the character on with the modifiers of the key
//! before: Ctrl+S typed "s" over a field's selected text, Ctrl+C replaced
//! it with "c" before copying, Ctrl+V put a "v" before what it pasted. A
//! character that comes just before a key pressed with Ctrl (or Cmd), or
//! before a cut, copy or paste, is dropped. AltGr, which some keyboards
//! send as Ctrl+Alt, keeps its characters.
//!
//! And Ctrl+S in a field applies what was typed, as Enter does, before the
//! window's binding saves: a number typed and saved is in the file. The
//! number pad's Enter is an Enter (egui-macroquad drops it).

use egui::{Event, Id, Key, Modifiers};

/// Where a field whose Enter does something else than apply a value (the
/// scene file's path: Enter opens it) leaves its id, so that Ctrl+S there
/// saves without an Enter.
pub const NO_ENTER_ON_SAVE: &str = "typing_no_enter_on_save";

/// Ctrl+S while a field has the keyboard: an Enter for the field first
/// (none in the scene file's path: it would open the file typed there).
/// Whether the window is to save after this frame's views (the keys that
/// leave a field belong to it, so the window's own binding rests).
pub fn enter_before_saving(ctx: &egui::Context) -> bool {
    let Some(focused) = ctx.memory(|m| m.focused()) else {
        return false;
    };
    if !ctx.wants_keyboard_input() {
        return false;
    }
    let other = ctx.data(|d| d.get_temp::<Id>(Id::new(NO_ENTER_ON_SAVE)));
    if other == Some(focused) {
        return ctx.input(|i| i.events.iter().any(is_save));
    }
    ctx.input_mut(|i| enter_after_save(&mut i.events))
}

/// Whether `event` is Ctrl+S (without Shift) pressed.
fn is_save(event: &Event) -> bool {
    matches!(event, Event::Key { key: Key::S, pressed: true, modifiers, .. }
        if commanding(*modifiers) && !modifiers.shift)
}

/// Puts an Enter after each Ctrl+S (without Shift) in `events`; whether
/// there was one.
fn enter_after_save(events: &mut Vec<Event>) -> bool {
    let saves: Vec<usize> = (0..events.len()).filter(|&k| is_save(&events[k])).collect();
    let any = !saves.is_empty();
    for k in saves.into_iter().rev() {
        let enter = Event::Key {
            key: Key::Enter,
            physical_key: None,
            pressed: true,
            repeat: false,
            modifiers: Modifiers::NONE,
        };
        events.insert(k + 1, enter);
    }
    any
}

/// The number pad's Enter, which egui-macroquad does not pass on (it
/// knows only the main Enter): given to egui as an Enter, so that a number
/// typed on the pad is applied with the pad's Enter too.
pub fn keypad_enter_as_enter(ctx: &egui::Context, keypad_enter: bool) {
    if keypad_enter {
        ctx.input_mut(|i| push_enter(&mut i.events, i.modifiers));
    }
}

/// An Enter pressed, with `modifiers`, at the end of `events`.
fn push_enter(events: &mut Vec<Event>, modifiers: Modifiers) {
    events.push(Event::Key {
        key: Key::Enter,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    });
}

/// Drops from this frame's input the characters typed with Ctrl.
pub fn drop_characters_typed_with_ctrl(ctx: &egui::Context) {
    ctx.input_mut(|i| {
        let held = i.modifiers;
        mend(&mut i.events, held);
    });
}

/// Whether `m` is Ctrl or Cmd without Alt (AltGr).
fn commanding(m: Modifiers) -> bool {
    (m.ctrl || m.command || m.mac_cmd) && !m.alt
}

/// Removes each one-character text event that is the character of the
/// event after it, when that is a key pressed with Ctrl, a cut or a copy,
/// or (with Ctrl held now) a paste's text.
fn mend(events: &mut Vec<Event>, held: Modifiers) {
    let stray = |k: usize| -> bool {
        let Some(Event::Text(t)) = events.get(k) else {
            return false;
        };
        if t.chars().count() != 1 {
            return false;
        }
        match events.get(k + 1) {
            Some(Event::Key {
                pressed: true,
                modifiers,
                ..
            }) => commanding(*modifiers),
            Some(Event::Cut | Event::Copy) => true,
            Some(Event::Text(_)) => commanding(held),
            _ => false,
        }
    };
    let drop: Vec<bool> = (0..events.len()).map(stray).collect();
    let mut k = 0;
    events.retain(|_| {
        k += 1;
        !drop[k - 1]
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::app::ui::widgets::key_press as key;

    fn text(t: &str) -> Event {
        Event::Text(t.to_string())
    }

    #[test]
    fn the_number_pads_enter_is_an_enter() {
        let ctx = egui::Context::default();
        let presses = |ctx: &egui::Context| ctx.input(|i| i.num_presses(Key::Enter));
        let _ = ctx.run(egui::RawInput::default(), |ctx| {
            keypad_enter_as_enter(ctx, false);
            assert_eq!(presses(ctx), 0);
            keypad_enter_as_enter(ctx, true);
            assert_eq!(presses(ctx), 1);
        });
    }

    #[test]
    fn ctrl_s_is_followed_by_an_enter_for_the_field() {
        let mut events = vec![text("2"), key(Key::S, Modifiers::CTRL), text("x")];
        assert!(enter_after_save(&mut events));
        assert_eq!(
            events,
            vec![
                text("2"),
                key(Key::S, Modifiers::CTRL),
                key(Key::Enter, Modifiers::NONE),
                text("x")
            ]
        );
        // Plain S, and Ctrl+Shift+S, are no save.
        let mut events = vec![
            key(Key::S, Modifiers::NONE),
            key(Key::S, Modifiers::CTRL | Modifiers::SHIFT),
        ];
        let before = events.clone();
        assert!(!enter_after_save(&mut events));
        assert_eq!(events, before);
    }

    #[test]
    fn a_character_typed_with_ctrl_is_dropped_and_typing_is_kept() {
        let ctrl = Modifiers::CTRL;
        let none = Modifiers::NONE;
        let alt_gr = Modifiers::CTRL | Modifiers::ALT;
        // Ctrl+S, Ctrl+C (a copy), Ctrl+V (the paste's text), Ctrl+A.
        let mut events = vec![
            text("s"),
            key(Key::S, ctrl),
            text("c"),
            Event::Copy,
            text("v"),
            text("2.5"),
            text("a"),
            key(Key::A, ctrl),
        ];
        mend(&mut events, ctrl);
        assert_eq!(
            events,
            vec![
                key(Key::S, ctrl),
                Event::Copy,
                text("2.5"),
                key(Key::A, ctrl)
            ]
        );
        // Plain typing, and AltGr's characters, stay.
        let typed = vec![
            text("1"),
            key(Key::Num1, none),
            text("@"),
            key(Key::Q, alt_gr),
            text("é"),
            text("x"),
        ];
        let mut events = typed.clone();
        mend(&mut events, none);
        assert_eq!(events, typed);
    }
}
