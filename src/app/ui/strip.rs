//! The strip under the world: a scale bar of a round number of metres on
//! the left, its length under it, then what the scene shows (its caption),
//! or, for a few seconds, the latest message (opened, saved, an error). It
//! always holds two lines, whatever the caption: a strip of one line or two
//! as the caption needed had moved the world when a caption changed (a
//! first edit's "Before the edits:", a scene named, another scene). The
//! text's width is fixed by the window's, so a message or a zoom never
//! moves the world either. What two lines cannot hold is cut, whole on
//! hover: so every caption says its answer first ("The heavy disc keeps
//! 9/11 of its speed…"), then the set-up, and a projector's narrow strip
//! cuts the set-up. The text stops short of the drawer open over the
//! strip's end. A lesson paused has its Play button at the strip's end.

use super::{Cx, Keys, View};
use crate::app::lang::tr;
use crate::app::layout::MAX_CAPTION_LINES;
use crate::app::model::lesson::pi_result;
use egui::{Color32, RichText, Stroke};

/// Longest scale bar (points).
const BAR_POINTS: f64 = 60.0;
/// What the scale bar, its length ("500 mm") under it and the separator
/// take at most (points): the caption is laid out in what this leaves, so
/// a zoom does not change its lines.
const BAR_ROOM: f32 = 84.0;

/// The strip (no state of its own).
pub struct Strip;

impl Strip {
    /// Lines of caption the layout gives the strip room for: always the
    /// most it holds.
    pub fn lines(&self) -> u8 {
        MAX_CAPTION_LINES
    }
}

impl View for Strip {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ppp = f64::from(cx.marks.ppp);
        let camera = &model.view.camera;
        let result = pi_result(&model.world);
        let caption = model.shown_caption();
        // The text's width is fixed by what the bar may take at most, not
        // what it takes: a zoom changes the bar's length ("1 m", "10 m")
        // and moved words from line to line.
        let text_width = (ui.available_width() - BAR_ROOM).max(1.0);
        let longest = BAR_POINTS;
        let metres = nice_length(longest * ppp / camera.scale);
        let bar = (metres * camera.scale / ppp) as f32;
        ui.horizontal_centered(|ui| {
            let scale_bar = |ui: &mut egui::Ui| {
                let height = ui.text_style_height(&egui::TextStyle::Body);
                let (rect, _) =
                    ui.allocate_exact_size(egui::vec2(bar + 4.0, height), egui::Sense::hover());
                let color = ui.visuals().strong_text_color();
                let stroke = Stroke::new(2.0, color);
                let (l, r, y) = (rect.left() + 2.0, rect.left() + 2.0 + bar, rect.center().y);
                ui.painter()
                    .line_segment([egui::pos2(l, y), egui::pos2(r, y)], stroke);
                for x in [l, r] {
                    ui.painter()
                        .line_segment([egui::pos2(x, y - 6.0), egui::pos2(x, y + 6.0)], stroke);
                }
                ui.label(format_metres(metres));
            };
            // The length under the bar: the caption's lines get the room.
            ui.vertical(scale_bar);
            ui.separator();
            // In the rows the caption wants, whatever it says: a longer
            // text is cut with "…", the whole of it on hover. A message (the
            // J's long report among them) may use the second row a long
            // caption gave the strip.
            let most = usize::from(self.lines());
            let mut width = text_width.min(ui.available_width());
            // The drawer open over the strip's right end hides what runs
            // under it: the text stops short of it, cut there (whole on
            // hover), in the same lines.
            let strip = ui.max_rect();
            let over = cx.open_drawer.filter(|d| d.intersects(strip));
            if let Some(drawer) = over {
                let left = drawer.left() - ui.spacing().item_spacing.x - ui.cursor().left();
                width = width.min(left.max(1.0));
            }
            // A lesson paused has its Play at the strip's end, beside its
            // question (or what paused it), whether or not the side panel's
            // is in sight (at a projector's size it is in the drawer): one
            // sign, as a player has, so that no language's word for "play"
            // takes the question's room. Running, the answer has the whole
            // width (with the button, the head-on answer lost its end at a
            // projector's size).
            let play = (model.lesson().is_some() && model.clock.paused).then(|| {
                let sign = "▶";
                let button = super::widgets::button_text_width(ui, sign)
                    + 2.0 * ui.spacing().button_padding.x;
                (sign, button)
            });
            if let Some((_, button)) = play {
                width = (width - button - 2.0 * ui.spacing().item_spacing.x).max(1.0);
            }
            // The short hint has the full one on hover.
            let mut full_hint = None;
            // A lesson waiting keeps its question in sight, its Play button
            // the control the keys most likely reached.
            let caption = if cx.keys == Keys::World || model.lesson_waiting() {
                caption
            } else {
                let hint = keys_in_panels(ui, width, most, cx.keys);
                let full = tr!(full_hint_id(cx.keys));
                full_hint = (hint != full).then_some(full);
                Some(hint)
            };
            let (text, name) = match (result, model.message(), caption) {
                (Some(result), _, _) => (RichText::new(result).strong(), "pi_result"),
                (None, Some(message), _) => {
                    let color = if ui.visuals().dark_mode {
                        Color32::from_rgb(255, 215, 120)
                    } else {
                        Color32::from_rgb(120, 60, 0)
                    };
                    (RichText::new(message).color(color), "message")
                }
                (None, None, Some(caption)) => (RichText::new(caption), "caption"),
                (None, None, None) => (RichText::new(tr!("caption-none")), "caption"),
            };
            let (galley, whole) = caption_shown(ui, text.into(), width, most);
            if whole.is_some() {
                cx.marks.cut.insert(name.into());
            }
            let more = match name {
                "caption" => full_hint.or(whole),
                _ => whole,
            };
            let r = super::widgets::cut_label(ui, egui::Label::new(galley), more);
            cx.note(name, &r);
            if let Some((sign, button)) = play {
                ui.add_space((width - r.rect.width()).max(0.0) + ui.spacing().item_spacing.x);
                let command = crate::app::model::Command::TogglePause;
                super::widgets::wide_labelled_button(
                    ui,
                    cx,
                    (sign, button),
                    command,
                    Some("lesson_play"),
                );
            }
        });
    }
}

/// `text` laid out in at most `max_rows` rows of `width` points, broken
/// between words, the last row ending "…" when the text is longer.
fn caption_galley(
    ui: &egui::Ui,
    text: egui::WidgetText,
    width: f32,
    max_rows: usize,
) -> std::sync::Arc<egui::Galley> {
    let mut job = text.into_layout_job(
        ui.style(),
        egui::FontSelection::Default,
        egui::Align::Center,
    );
    job.wrap = egui::text::TextWrapping {
        max_width: width.max(1.0),
        max_rows,
        break_anywhere: false,
        overflow_character: Some('…'),
    };
    ui.fonts(|f| f.layout_job(job))
}

/// The message of the hint in full: the keys with a control, or with the
/// panels after Enter but the clock's.
fn full_hint_id(keys: Keys) -> &'static str {
    match keys {
        Keys::AfterField => "keys-after-field",
        Keys::TabEdge => "keys-tab-edge",
        Keys::World | Keys::Controls => "keys-in-panels",
    }
}

/// The hint that the keys act on the controls: in full where the strip's
/// `rows` of `width` points hold it, else its short form (how to give them
/// back).
fn keys_in_panels(ui: &egui::Ui, width: f32, rows: usize, keys: Keys) -> String {
    let full = tr!(full_hint_id(keys));
    match caption_galley(ui, full.as_str().into(), width, rows).elided {
        true if keys == Keys::TabEdge => tr!("keys-tab-edge-short"),
        true => tr!("keys-in-panels-short"),
        false => full,
    }
}

/// [`caption_galley`] as the strip shows it, with the whole text for the
/// tooltip where it was cut. A cut right after a full stop gives the stop
/// up to the "…" ("each other…", not "each other.…").
fn caption_shown(
    ui: &egui::Ui,
    text: egui::WidgetText,
    width: f32,
    max_rows: usize,
) -> (std::sync::Arc<egui::Galley>, Option<String>) {
    let galley = caption_galley(ui, text, width, max_rows);
    if !galley.elided {
        return (galley, None);
    }
    let whole = galley.text().to_owned();
    let shown = on_screen(&galley);
    let Some(kept) = shown
        .strip_suffix('…')
        .map(str::trim_end)
        .and_then(|s| s.strip_suffix('.'))
    else {
        return (galley, Some(whole));
    };
    // The rows drop the spaces they break at: find the end of what is kept
    // in the whole text by its letters.
    let mut letters = kept.chars().filter(|c| !c.is_whitespace()).count();
    let end = whole
        .char_indices()
        .find(|&(_, c)| {
            if !c.is_whitespace() {
                if letters == 0 {
                    return true;
                }
                letters -= 1;
            }
            false
        })
        .map_or(whole.len(), |(at, _)| at);
    let mut job = (*galley.job).clone();
    job.text = format!("{}…", whole[..end].trim_end());
    let len = job.text.len();
    for section in &mut job.sections {
        section.byte_range = section.byte_range.start.min(len)..section.byte_range.end.min(len);
    }
    job.sections.retain(|s| !s.byte_range.is_empty());
    if let Some(last) = job.sections.last_mut() {
        last.byte_range.end = len;
    }
    (ui.fonts(|f| f.layout_job(job)), Some(whole))
}

/// The characters `galley` shows, with its "…" if cut (without the spaces
/// its rows break at).
fn on_screen(galley: &egui::Galley) -> String {
    galley
        .rows
        .iter()
        .flat_map(|row| row.glyphs.iter().map(|g| g.chr))
        .collect()
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

/// "2 m", "50 cm", "5 mm", "2 km", "0.5 mm"; never in e-notation.
pub fn format_metres(m: f64) -> String {
    use crate::app::numbers::field;
    match m {
        m if m >= 1000.0 => format!("{} km", field(m / 1000.0)),
        m if m >= 1.0 => format!("{} m", field(m)),
        m if m >= 0.01 => format!("{} cm", (m * 100.0).round()),
        m if m >= 0.001 => format!("{} mm", (m * 1000.0).round()),
        m => format!("{} mm", crate::app::numbers::adaptive(m * 1000.0, 0)),
    }
}

#[cfg(test)]
mod tests;
