//! The strip under the world: a scale bar of a round number of metres on
//! the left, then what the scene shows (its caption), or, for a few
//! seconds, the latest message (opened, saved, an error). It is one row
//! high, or holds two lines while the scene's caption needs them; the
//! scale bar is shorter where the caption needs the room, its length under
//! it beside more than one line. The lines follow the caption and the
//! window's width alone, so a message or a zoom never moves the world.
//! What they cannot hold is cut, whole on hover: so every caption says its
//! answer first ("The heavy disc keeps 9/11 of its speed…"), then the
//! set-up, and a projector's narrow strip cuts the set-up. The text stops
//! short of the drawer open over the strip's end.

use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::layout::MAX_CAPTION_LINES;
use crate::app::model::lesson::pi_result;
use egui::{Color32, RichText, Stroke};

/// Longest scale bar (points).
const BAR_POINTS: f64 = 120.0;
/// Longest scale bar where the caption needs the room (points).
const SHORT_BAR_POINTS: f64 = 60.0;
/// What the scale bar, its length ("500 mm") and the separator take at
/// most (points): the full bar, the short one with its length beside it,
/// and the short one with its length under it (beside a caption of more
/// than one line). The caption's lines are measured in what these leave,
/// so a zoom does not change them.
const BAR_ROOM: f32 = 230.0;
const SHORT_BAR_ROOM: f32 = 160.0;
const STACKED_BAR_ROOM: f32 = 84.0;

/// The strip: the lines its caption wants, and whether the scale bar is
/// short to give the caption room.
pub struct Strip {
    lines: u8,
    short_bar: bool,
    /// The caption and the width (points) `lines` and `short_bar` were
    /// measured for: they are measured again only when these change.
    measured: Option<(String, f32)>,
}

impl Default for Strip {
    fn default() -> Self {
        Strip {
            lines: 1,
            short_bar: false,
            measured: None,
        }
    }
}

impl Strip {
    /// Lines of caption the layout gives the strip room for.
    pub fn lines(&self) -> u8 {
        self.lines
    }
}

/// Lines `caption` needs in a strip `width` points wide, and whether the
/// scale bar must be short for it: one line beside the full bar if it
/// fits, else beside the short bar, else as many as it takes beside the
/// short bar with its length under it, up to [`MAX_CAPTION_LINES`].
fn caption_lines(ui: &egui::Ui, caption: &str, width: f32) -> (u8, bool) {
    let text = || egui::WidgetText::from(caption);
    let fits = |room: f32| !caption_galley(ui, text(), width - room, 1).elided;
    if fits(BAR_ROOM) {
        return (1, false);
    }
    if fits(SHORT_BAR_ROOM) {
        return (1, true);
    }
    let most = usize::from(MAX_CAPTION_LINES);
    let rows = caption_galley(ui, text(), width - STACKED_BAR_ROOM, most)
        .rows
        .len();
    (rows.clamp(2, most) as u8, true)
}

/// What the scale bar may take beside a caption of `lines` lines, short or
/// not (points).
fn bar_room(lines: u8, short_bar: bool) -> f32 {
    match (lines, short_bar) {
        (1, false) => BAR_ROOM,
        (1, true) => SHORT_BAR_ROOM,
        _ => STACKED_BAR_ROOM,
    }
}

impl View for Strip {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ppp = f64::from(cx.marks.ppp);
        let camera = &model.view.camera;
        let result = pi_result(&model.world);
        let caption = model.scene_description().map(|d| {
            if model.open.edited {
                tr!("caption-edited", caption = d)
            } else {
                d
            }
        });
        let width = ui.available_width();
        let text = caption.as_deref().unwrap_or_default();
        let same = self
            .measured
            .as_ref()
            .is_some_and(|(was, w)| was == text && *w == width);
        let (lines, short_bar) = match caption.as_deref() {
            _ if same => (self.lines, self.short_bar),
            Some(c) => caption_lines(ui, c, width),
            None => (1, false),
        };
        if !same {
            self.measured = Some((text.to_owned(), width));
        }
        if (lines, short_bar) != (self.lines, self.short_bar) {
            (self.lines, self.short_bar) = (lines, short_bar);
            ui.ctx()
                .request_discard("the caption strip changed its lines");
        }
        let longest = if self.short_bar {
            SHORT_BAR_POINTS
        } else {
            BAR_POINTS
        };
        // The text's width is fixed by what the bar may take at most, not
        // what it takes: a zoom changes the bar's length ("1 m", "10 m")
        // and moved words from line to line.
        let room = bar_room(self.lines, self.short_bar);
        let text_width = (ui.available_width() - room).max(1.0);
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
            if self.lines > 1 {
                // The length under the bar: the caption's lines get the room.
                ui.vertical(scale_bar);
            } else {
                scale_bar(ui);
            }
            ui.separator();
            // In the rows the caption wants, whatever it says: a longer
            // text is cut with "…", the whole of it on hover.
            let caption = if cx.keys_in_panels {
                Some(tr!("keys-in-panels"))
            } else {
                caption
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
            // A message (the J's long report among them) may use the
            // second row a long caption gave the strip.
            let most = usize::from(self.lines);
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
            let galley = caption_galley(ui, text.into(), width, most);
            let r = super::widgets::cut_label(ui, egui::Label::new(galley), None);
            cx.note(name, &r);
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
mod tests {
    use super::*;
    use crate::app::lang::Lang;
    use crate::app::layout::{layout, Docks};

    /// A caption in the strip of a window of `size` (px) at `scale`, with
    /// the side dock docked where it fits, as the window lays it out.
    struct Laid {
        lang: &'static str,
        scene: &'static str,
        caption: String,
        lines: u8,
        whole: bool,
        /// The text on screen, without the "…" of a cut.
        shown: String,
    }

    /// Every preset's caption (and the default scene's and the π blocks'
    /// other counts', opened from the lesson) in every language, laid out in
    /// the strip.
    fn captions_at(size: (f32, f32), scale: f32) -> Vec<Laid> {
        let docks = Docks {
            shown: true,
            side: true,
            tab_open: true,
            drawer_open: false,
            tab_height: None,
            caption_lines: MAX_CAPTION_LINES,
        };
        let strip = layout(size, scale, docks).caption;
        let ctx = egui::Context::default();
        crate::app::look::apply(&ctx, scale, crate::app::model::panels::Theme::Dark);
        use impulse::catalogue::{DEFAULT, PI_BLOCKS_1, PI_BLOCKS_10000, PI_BLOCKS_1000000};
        let others = [DEFAULT, PI_BLOCKS_1, PI_BLOCKS_10000, PI_BLOCKS_1000000];
        let scenes = crate::app::model::scenes::PRESETS
            .iter()
            .map(|p| (p.path, p.text))
            .chain(others.iter().map(|f| (f.path, f.text)));
        let mut out = Vec::new();
        for (path, text) in scenes {
            let scene = impulse::Scene::parse(text, path).unwrap();
            for lang in Lang::SHIPPED {
                let Some(caption) = scene.description_in(lang.code()) else {
                    continue;
                };
                let input = egui::RawInput {
                    screen_rect: Some(egui::Rect::from_min_size(
                        egui::Pos2::ZERO,
                        egui::vec2(strip.w, 600.0) / scale,
                    )),
                    ..Default::default()
                };
                let _ = ctx.run(input, |ctx| {
                    egui::TopBottomPanel::bottom("strip").show(ctx, |ui| {
                        let width = ui.available_width();
                        let (lines, short) = caption_lines(ui, caption, width);
                        let room = bar_room(lines, short);
                        let text = egui::WidgetText::from(caption);
                        let galley = caption_galley(ui, text, width - room, lines.into());
                        let shown: String = galley
                            .rows
                            .iter()
                            .flat_map(|row| row.glyphs.iter().map(|g| g.chr))
                            .collect();
                        let shown = match galley.elided {
                            true => shown.trim_end_matches('…').to_owned(),
                            false => shown,
                        };
                        out.push(Laid {
                            lang: lang.code(),
                            scene: path,
                            caption: caption.to_owned(),
                            lines,
                            whole: !galley.elided,
                            shown,
                        });
                    });
                });
            }
        }
        out
    }

    /// A caption's answer: its first sentence, up to the first full stop
    /// (or "…") that a capital or a digit follows, or all of it.
    fn answer(caption: &str) -> &str {
        let ends = caption
            .char_indices()
            .filter(|&(_, c)| c == '.' || c == '…');
        for (at, stop) in ends {
            let rest = &caption[at + stop.len_utf8()..];
            let mut next = rest.chars();
            if next.next() == Some(' ')
                && next
                    .next()
                    .is_some_and(|c| c.is_uppercase() || c.is_ascii_digit())
            {
                return &caption[..at + stop.len_utf8()];
            }
        }
        caption
    }

    #[test]
    fn a_captions_answer_is_its_first_sentence() {
        assert_eq!(
            answer("Count every hit: 31, as in π = 3.1… A disc 100× heavier."),
            "Count every hit: 31, as in π = 3.1…"
        );
        assert_eq!(
            answer("Restitution 0.5. Then 150 discs."),
            "Restitution 0.5."
        );
        assert_eq!(answer("One sentence, 0.5 m. "), "One sentence, 0.5 m. ");
    }

    /// The review's case: at 1280×800 "Heavy hits light" was cut before
    /// its answer ("…the light one flies off at …"). Every caption in
    /// English is whole from 1024×768 up at scale 1, and in every language
    /// from 1280×800 (at 1024×768 eight in the other languages are cut, whole on
    /// hover); no caption takes more than two lines.
    #[test]
    fn captions_are_whole_in_the_strip_from_a_laptop_up() {
        for size in [(1024.0, 768.0), (1280.0, 800.0), (1920.0, 1080.0)] {
            let all = captions_at(size, 1.0);
            assert!(all.len() > 40, "{} captions", all.len());
            for c in all {
                let (lang, scene) = (c.lang, c.scene);
                assert!(
                    (1..=2).contains(&c.lines),
                    "{size:?} {lang} {scene}: {}",
                    c.lines
                );
                if lang == "en" || size.0 >= 1280.0 {
                    assert!(c.whole, "{size:?} {lang} {scene}: cut at {:?}", c.shown);
                }
            }
        }
        let heavy = captions_at((1280.0, 800.0), 1.0)
            .into_iter()
            .find(|c| c.lang == "en" && c.scene.contains("heavy-hits-light"));
        assert_eq!(heavy.map(|c| (c.lines, c.whole)), Some((2, true)));
    }

    /// The third review's case: at 1024×768 at size 2 (a projector) most
    /// captions were cut before their answer, which came at the end; the
    /// German π blocks never showed "31". Every caption now says its
    /// answer first, and that is whole on screen there, in every language.
    #[test]
    fn a_captions_answer_is_in_sight_on_a_projector() {
        let all = captions_at((1024.0, 768.0), 2.0);
        assert!(all.len() > 40, "{} captions", all.len());
        let squeezed = |t: &str| t.split_whitespace().collect::<String>();
        let cut: Vec<String> = all
            .iter()
            .filter(|c| !squeezed(&c.shown).starts_with(&squeezed(answer(&c.caption))))
            .map(|c| format!("{} {}: {:?}", c.lang, c.scene, c.shown))
            .collect();
        assert!(cut.is_empty(), "answers cut:\n{}", cut.join("\n"));
        let pi = all
            .iter()
            .find(|c| c.lang == "de" && c.scene.ends_with("preset-7-pi-blocks.toml"));
        assert!(
            pi.is_some_and(|c| c.shown.contains("31")),
            "the German π blocks"
        );
    }

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
        assert_eq!(format_metres(0.0005), "0.500 mm");
    }
}
