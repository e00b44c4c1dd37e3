//! The strip under the world: a scale bar of a round number of metres on
//! the left, then one line that says what the scene shows (its caption), or,
//! for a few seconds, the latest message (opened, saved, an error). Its
//! height is fixed (one line): a long caption is cut, with the whole of it
//! on hover, so the world never moves.

use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::lesson::pi_result;
use egui::{Color32, RichText, Stroke};

/// Longest scale bar (points).
const BAR_POINTS: f64 = 120.0;

/// The strip (no state of its own).
pub struct Strip;

impl View for Strip {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let ppp = f64::from(cx.marks.ppp);
        let camera = &model.view.camera;
        let metres = nice_length(BAR_POINTS * ppp / camera.scale);
        let bar = (metres * camera.scale / ppp) as f32;
        let result = pi_result(&model.world);
        let caption = model.scene_description().map(|d| {
            if model.open.edited {
                tr!("caption-edited", caption = d)
            } else {
                d
            }
        });
        ui.horizontal_centered(|ui| {
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
            ui.separator();
            // One line whatever it says: a long one is cut with "…", the
            // whole of it on hover.
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
            let r = super::widgets::one_line(ui, text, None);
            cx.note(name, &r);
        });
    }
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
