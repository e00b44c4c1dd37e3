//! Screen-space panels: the totals HUD, the key list, the scale bar, toasts.

use super::camera::Camera;
use macroquad::prelude::*;

/// Draws `lines` on a translucent panel with its top-left corner at (x, y);
/// returns the panel's size.
pub fn text_panel(x: f32, y: f32, lines: &[String], font: f32, opacity: f32) -> Vec2 {
    let lines: Vec<String> = lines.iter().map(|l| screen_text(l)).collect();
    let pad = 0.4 * font;
    let line_height = 1.15 * font;
    let width = lines
        .iter()
        .map(|l| measure_text(l, None, font as u16, 1.0).width)
        .fold(0.0, f32::max);
    let size = vec2(
        width + 2.0 * pad,
        line_height * lines.len() as f32 + 2.0 * pad,
    );
    draw_rectangle(x, y, size.x, size.y, Color::new(0.05, 0.06, 0.09, opacity));
    for (k, line) in lines.iter().enumerate() {
        let baseline = y + pad + line_height * (k as f32 + 0.8);
        draw_text(line, x + pad, baseline, font, WHITE);
    }
    size
}

/// `text` in the characters the window's built-in font has: a few symbols
/// scene files use are spelt out (π → pi, en dash → hyphen, 10⁸ → 10^8), and
/// anything else outside ASCII becomes "?".
pub fn screen_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut in_power = false;
    for c in text.chars() {
        let power = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻".find(c).map(|_| c);
        if let Some(p) = power {
            if !in_power {
                out.push('^');
            }
            in_power = true;
            let digit = match p {
                '⁰' => '0',
                '¹' => '1',
                '²' => '2',
                '³' => '3',
                '⁴' => '4',
                '⁵' => '5',
                '⁶' => '6',
                '⁷' => '7',
                '⁸' => '8',
                '⁹' => '9',
                _ => '-',
            };
            out.push(digit);
            continue;
        }
        in_power = false;
        match c {
            c if c.is_ascii() => out.push(c),
            'π' => out.push_str("pi"),
            '–' | '—' | '−' => out.push('-'),
            '×' | '·' => out.push(if c == '×' { 'x' } else { '*' }),
            '≤' => out.push_str("<="),
            '≥' => out.push_str(">="),
            '≈' => out.push('~'),
            '°' => out.push_str(" deg"),
            'µ' | 'μ' => out.push('u'),
            '½' => out.push_str("1/2"),
            '¼' => out.push_str("1/4"),
            '’' | '‘' => out.push('\''),
            '“' | '”' => out.push('"'),
            '…' => out.push_str("..."),
            _ => out.push('?'),
        }
    }
    out
}

/// Every key, as the help overlay lists it.
pub const HELP: &[(&str, &str)] = &[
    (
        "Left drag on empty space",
        "launch a new disc along the drag",
    ),
    (
        "Left drag on a disc",
        "grab and fling it (it keeps the mouse's velocity)",
    ),
    ("Drag the selected disc's arrow tip", "set its velocity"),
    ("Right / middle drag, arrows", "pan"),
    ("Wheel, + / -", "zoom (at the cursor / at the centre)"),
    ("F", "fit the box to the window"),
    ("Space", "pause / resume"),
    ("N", "single step (pauses)"),
    ("[ / ]", "slower / faster (time scale)"),
    ("V", "velocity arrows"),
    ("M", "momentum arrows"),
    ("I", "readouts: off / selected / all"),
    ("Tab", "totals panel"),
    ("E / Shift+E", "restitution between discs + / -"),
    ("W / Shift+W", "wall restitution + / -"),
    ("G", "gravity on / off"),
    (
        "Y / B / K",
        "method / broad phase / substeps (auto or fixed)",
    ),
    ("PgUp / PgDn", "size of new discs"),
    ("Home / End", "mass of new discs"),
    ("Delete / Backspace", "delete the selected disc"),
    ("C", "clear all discs"),
    ("R", "reset the scene"),
    ("1 … 9, 0 / P", "open a classroom preset / the preset menu"),
    ("Ctrl+N", "new empty box"),
    ("Ctrl+S", "save the scene (reopens exactly)"),
    (
        "T / O / D",
        "totals plot / centre of mass / momentum diagram",
    ),
    ("Z", "centre-of-mass frame (total momentum 0)"),
    ("U / J", "collision ledger / run to the next collision"),
    (", / .", "rewind / forward (Shift: 10x); Space resumes"),
    ("X", "export totals, discs, collisions as CSV"),
    ("A", "trails (fading paths)"),
    (
        "F2 / F3 / F4",
        "projector mode / colour-blind palette / speed histogram",
    ),
    (
        "L",
        "side panel: sliders, settings, disc editor, open a file",
    ),
    ("F11", "full screen"),
    ("Esc", "deselect / close this help"),
    ("H or F1", "this help"),
    ("Ctrl+Q", "quit"),
];

/// The preset menu, centred: key, name and description of each preset.
pub fn draw_preset_menu(viewport: Vec2, font: f32, entries: &[(String, String, String)]) {
    let mut lines = vec![
        "Presets - press its key; P or Esc closes".to_string(),
        String::new(),
    ];
    for (key, name, description) in entries {
        lines.push(screen_text(&format!("{key:<8}{name}")));
        lines.push(screen_text(&format!("        {description}")));
    }
    let width = lines
        .iter()
        .map(|l| measure_text(l, None, font as u16, 1.0).width)
        .fold(0.0, f32::max);
    let height = 1.15 * font * lines.len() as f32;
    let x = ((viewport.x - width) * 0.5).max(0.0);
    let y = ((viewport.y - height) * 0.5).max(0.0);
    text_panel(x, y, &lines, font, 0.92);
}

/// One line of text centred at the bottom of the window, on a dark band.
pub fn draw_caption(text: &str, viewport: Vec2, font: f32) {
    let text = &screen_text(text);
    // A long caption shrinks to fit (down to a still legible 12 px).
    let full = measure_text(text, None, font as u16, 1.0).width;
    let font = (font * (viewport.x - 30.0) / full.max(1.0)).clamp(12.0, font);
    let width = measure_text(text, None, font as u16, 1.0).width;
    // Clear of the scale bar (bottom left) when there is room.
    let x = ((viewport.x - width) * 0.5)
        .max((viewport.x - width - 10.0).min(SCALE_BAR_ROOM))
        .max(10.0);
    let y = viewport.y - 0.6 * font;
    draw_rectangle(
        x - 8.0,
        y - font,
        width + 16.0,
        1.3 * font,
        Color::new(0.0, 0.0, 0.0, 0.55),
    );
    draw_text(text, x, y, font, Color::new(0.95, 0.95, 0.95, 1.0));
}

/// The help overlay, centred.
pub fn draw_help(viewport: Vec2, font: f32) {
    let key_width = HELP
        .iter()
        .map(|(k, _)| measure_text(k, None, font as u16, 1.0).width)
        .fold(0.0, f32::max);
    let spaces = (key_width / measure_text(" ", None, font as u16, 1.0).width).ceil() as usize + 2;
    let mut lines = vec!["Impulse - keys and mouse".to_string(), String::new()];
    lines.extend(HELP.iter().map(|(k, what)| format!("{k:<spaces$}{what}")));
    // The default font is monospaced, so padding aligns the columns.
    let width = lines
        .iter()
        .map(|l| measure_text(l, None, font as u16, 1.0).width)
        .fold(0.0, f32::max);
    let height = 1.15 * font * lines.len() as f32;
    let x = ((viewport.x - width) * 0.5).max(0.0);
    let y = ((viewport.y - height) * 0.5).max(0.0);
    text_panel(x, y, &lines, font, 0.92);
}

/// Width the scale bar and its label take at the bottom left (px).
const SCALE_BAR_ROOM: f32 = 260.0;

/// A bar of a round number of metres, about 150 px long, bottom left.
pub fn draw_scale_bar(camera: &Camera, font: f32) {
    let metres = nice_length(150.0 / camera.scale);
    let length = (metres * camera.scale) as f32;
    let (x, y) = (20.0, camera.viewport.y as f32 - 24.0);
    let color = Color::new(0.9, 0.9, 0.9, 0.9);
    draw_line(x, y, x + length, y, 3.0, color);
    draw_line(x, y - 6.0, x, y + 6.0, 2.0, color);
    draw_line(x + length, y - 6.0, x + length, y + 6.0, 2.0, color);
    draw_text(
        format_metres(metres).as_str(),
        x + length + 10.0,
        y + 0.3 * font,
        font,
        color,
    );
}

/// The largest 1, 2 or 5 × 10^k not above `at_most` (0 when not positive).
pub fn nice_length(at_most: f64) -> f64 {
    if !(at_most > 0.0 && at_most.is_finite()) {
        return 0.0;
    }
    let decade = 10f64.powf(at_most.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&l| l <= at_most * (1.0 + 1e-12))
        .unwrap_or(decade)
}

/// "2 m", "50 cm", "5 mm", "2 km".
pub fn format_metres(m: f64) -> String {
    match m {
        m if m >= 1000.0 => format!("{} km", m / 1000.0),
        m if m >= 1.0 => format!("{m} m"),
        m if m >= 0.01 => format!("{} cm", (m * 100.0).round()),
        m if m >= 0.001 => format!("{} mm", (m * 1000.0).round()),
        m => format!("{m:e} m"),
    }
}

/// A short message at the bottom centre; a long one (an error naming a
/// file) is wrapped to the width of `viewport`.
pub fn draw_toast(message: &str, viewport: Vec2, font: f32) {
    let message = &screen_text(message);
    let char_width = measure_text("0000000000", None, font as u16, 1.0).width / 10.0;
    let chars = ((viewport.x - 2.0 * font) / char_width).max(10.0) as usize;
    let lines = super::panel::wrap(message, chars);
    let width = lines
        .iter()
        .map(|l| measure_text(l, None, font as u16, 1.0).width)
        .fold(0.0, f32::max)
        + 0.8 * font;
    let x = ((viewport.x - width) * 0.5).max(0.0);
    let y = viewport.y - (1.15 * lines.len() as f32 + 1.85) * font;
    text_panel(x, y, &lines, font, 0.85);
}

#[cfg(test)]
mod screen_text_tests {
    use super::screen_text;

    #[test]
    fn symbols_are_spelt_out_for_the_builtin_font() {
        assert_eq!(screen_text("Blocks that count π"), "Blocks that count pi");
        assert_eq!(
            screen_text("Maxwell–Boltzmann at 10⁸, 10⁻³"),
            "Maxwell-Boltzmann at 10^8, 10^-3"
        );
        assert_eq!(screen_text("a ≤ b, 90°, ✓"), "a <= b, 90 deg, ?");
        assert_eq!(screen_text("plain ASCII"), "plain ASCII");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_bar_lengths_are_round() {
        assert_eq!(nice_length(1.0), 1.0);
        assert_eq!(nice_length(1.9), 1.0);
        assert_eq!(nice_length(2.5), 2.0);
        assert_eq!(nice_length(7.0), 5.0);
        assert!((nice_length(0.07) - 0.05).abs() < 1e-15);
        assert_eq!(nice_length(0.0), 0.0);
        assert_eq!(format_metres(0.05), "5 cm");
        assert_eq!(format_metres(2000.0), "2 km");
    }
}
