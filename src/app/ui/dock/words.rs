//! The *In words* tab: the scene described, and what the sandbox said as it
//! happened, newest first: the text a screen reader reads in the browser
//! (the page's live region), here for anyone who wants it in words.

use super::super::dialog::scroll;
use super::super::widgets::{command_button, one_line};
use super::{Cx, View};
use crate::app::lang::tr;
use crate::app::model::narration::IMPACT_GAP;
use crate::app::model::Command;

/// The tab (no state of its own).
pub struct Words;

impl View for Words {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        // One line, so that a projector's short tab keeps its room for the
        // lines said (the explanation on three lines left one); the whole
        // explanation on hover where it is cut.
        ui.horizontal(|ui| {
            command_button(ui, cx, Command::Describe, Some("describe"));
            // The page's live region is the browser's: the desktop window
            // does not say it speaks to a screen reader.
            // It says that impacts are said at most every IMPACT_GAP: a gas's
            // 52 collisions read as a miscount beside the list's three.
            let id = if cfg!(target_arch = "wasm32") {
                "words-line-web"
            } else {
                "words-line"
            };
            let gap = crate::app::numbers::plain(IMPACT_GAP, 0);
            let line = tr!(id, gap = gap);
            one_line(ui, line, None);
        });
        let area = egui::ScrollArea::vertical().auto_shrink([false, true]);
        scroll(ui, cx, area, "words", |ui, cx| {
            let said = &model.messages.narration.said;
            if said.is_empty() {
                ui.label(tr!("words-none"));
            }
            for (k, (t, line)) in said.iter().rev().enumerate() {
                let r = ui.horizontal_wrapped(|ui| {
                    // The simulation's t, as everywhere in the window.
                    ui.weak(format!(
                        "t = {}",
                        crate::app::numbers::with_unit(*t, 2, "s")
                    ));
                    ui.add(egui::Label::new(line).wrap());
                });
                if k == 0 {
                    cx.note("words_newest", &r.response);
                }
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::Words;
    use crate::app::lang::tr;
    use crate::app::model::tests::sandbox_with;
    use crate::app::ui::widgets::texts_drawn;

    /// The tab says that it gives an impact every 2 s at most and where all
    /// of them are: a review's student read the gas's 52 collisions against
    /// the tab's three lines as a miscount.
    #[test]
    fn the_tab_says_how_often_it_tells_an_impact_and_where_all_are() {
        let dir = tempfile::tempdir().unwrap();
        let model = sandbox_with(dir.path(), "preset-8-gas.toml", true, 0.0);
        let text = texts_drawn(&model, egui::vec2(1800.0, 200.0), &mut Words).concat();
        let every = format!("{} s", super::IMPACT_GAP);
        assert!(text.contains(&every), "{text}");
        assert!(text.contains(&tr!("tab-collisions")), "{text}");
    }
}
