//! The start screen: a tile per lesson, large, with a small picture, its
//! name and one line in plain words. It fits the window at every size and
//! scale (three tiles a row where wide, two or one where narrow, scrolling
//! where short); Esc keeps the scene that is open.

use super::dialog::{scroll, Dialog, Place};
use super::Cx;
use crate::app::lang::tr;
use crate::app::model::start::Tile;
use crate::app::model::Command;
use egui::{Align2, Color32, Pos2, RichText, Stroke};

/// The start screen (no state of its own).
pub struct StartScreen;

/// A tile's least width (points).
const TILE_WIDTH: f32 = 210.0;
/// A tile's picture height (points).
const PICTURE_HEIGHT: f32 = 56.0;

impl StartScreen {
    /// The tiles over the window below the top bar, which ends at `below`
    /// (points): the bar stays whole behind them, not cut through a line.
    pub fn show(&mut self, ctx: &egui::Context, cx: &mut Cx, below: f32) {
        if !cx.model.panels.start_open || cx.model.recovery.offered.is_some() {
            return;
        }
        let mut part = ctx.screen_rect();
        part.min.y = below.clamp(part.min.y, part.max.y - 100.0);
        let size = egui::vec2(
            (part.width() - 32.0).clamp(100.0, 1100.0),
            (part.height() - 24.0).max(80.0),
        );
        let dialog = Dialog::new("start_screen", Some(tr!("start-title")))
            .place(Place::CentreOf(part))
            .width_and_max_height(size)
            .modal(ctx);
        let shown = dialog.show(ctx, cx, |ui, cx| {
            scroll(ui, cx, egui::ScrollArea::vertical(), "tiles", |ui, cx| {
                // Room kept for the scroll bar, which floats over the content
                // (it lay over the right-hand tiles' edges).
                let scroll = &ui.spacing().scroll;
                let bar = scroll.bar_width + scroll.bar_inner_margin + scroll.bar_outer_margin;
                let room = ui.available_width() - bar;
                let per_row = ((room / (TILE_WIDTH + 12.0)) as usize).clamp(1, 3);
                let width = room / per_row as f32 - 12.0;
                for row in Tile::ALL.chunks(per_row) {
                    ui.horizontal(|ui| {
                        for &tile in row {
                            self.tile(ui, cx, tile, width);
                        }
                    });
                    ui.add_space(8.0);
                }
                // The footer ends where the tiles do (its words ran up to the
                // bar).
                ui.allocate_ui(egui::vec2(room - 16.0, 0.0), |ui| {
                    ui.add(egui::Label::new(tr!("start-footer")).wrap());
                });
                ui.add_space(8.0);
                super::side::files::language(ui, cx);
            });
        });
        cx.marks.note("start_screen", shown.rect);
    }

    fn tile(&mut self, ui: &mut egui::Ui, cx: &mut Cx, tile: Tile, width: f32) {
        let frame = egui::Frame::group(ui.style()).inner_margin(10.0);
        let r = frame
            .show(ui, |ui| {
                ui.set_width(width - 20.0);
                ui.vertical(|ui| {
                    let (rect, _) = ui.allocate_exact_size(
                        egui::vec2(width - 20.0, PICTURE_HEIGHT),
                        egui::Sense::hover(),
                    );
                    picture(ui.painter(), rect, tile, ui.visuals().strong_text_color());
                    ui.label(RichText::new(tile.title()).heading().strong());
                    ui.add(egui::Label::new(tile.blurb()).wrap());
                });
            })
            .response;
        let r = ui.interact(
            r.rect,
            egui::Id::new(("tile", tile.key())),
            egui::Sense::click(),
        );
        let r = r.on_hover_cursor(egui::CursorIcon::PointingHand);
        if r.hovered() {
            ui.painter().rect_stroke(
                r.rect,
                6.0,
                Stroke::new(2.0, ui.visuals().selection.stroke.color),
                egui::StrokeKind::Inside,
            );
        }
        cx.note(format!("tile_{}", tile.key()), &r);
        if r.clicked() {
            cx.send(Command::StartWith(tile));
        }
    }
}

/// A small picture of the lesson, drawn with lines and circles.
fn picture(p: &egui::Painter, rect: egui::Rect, tile: Tile, ink: Color32) {
    let c = rect.center();
    let h = rect.height();
    let blue = Color32::from_rgb(86, 180, 233);
    let orange = Color32::from_rgb(230, 159, 0);
    let line = Stroke::new(2.0, ink);
    let arrow = |from: Pos2, to: Pos2| p.arrow(from, to - from, line);
    match tile {
        // The lessons' discs as their scenes have them: the orange one
        // moving, the blue one at rest (the pictures had them the other
        // way round, both moving in the head-on one).
        Tile::HeadOn => {
            p.line_segment(
                [rect.left_center(), rect.right_center()],
                Stroke::new(1.0, ink),
            );
            p.circle_filled(c - egui::vec2(h * 0.9, 0.0), h * 0.22, orange);
            p.circle_filled(c + egui::vec2(h * 0.9, 0.0), h * 0.22, blue);
            arrow(c - egui::vec2(h * 0.9, 0.0), c - egui::vec2(h * 0.25, 0.0));
        }
        Tile::Glancing => {
            // Screen y grows downwards: the moving disc runs a little above.
            let a = c + egui::vec2(-h * 0.9, -h * 0.12);
            let b = c + egui::vec2(h * 0.2, h * 0.12);
            p.circle_filled(a, h * 0.2, orange);
            p.circle_filled(b, h * 0.2, blue);
            arrow(a, a + egui::vec2(h * 0.7, 0.0));
        }
        Tile::Inelastic => {
            p.circle_filled(c - egui::vec2(h * 0.19, 0.0), h * 0.2, orange);
            p.circle_filled(c + egui::vec2(h * 0.19, 0.0), h * 0.2, blue);
            arrow(c + egui::vec2(h * 0.4, 0.0), c + egui::vec2(h * 0.9, 0.0));
        }
        Tile::PiBlocks => {
            let wall = rect.left() + h * 0.3;
            p.line_segment(
                [Pos2::new(wall, rect.top()), Pos2::new(wall, rect.bottom())],
                Stroke::new(3.0, ink),
            );
            p.circle_filled(Pos2::new(wall + h * 0.6, c.y), h * 0.12, blue);
            p.circle_filled(Pos2::new(wall + h * 1.6, c.y), h * 0.34, orange);
            arrow(
                Pos2::new(wall + h * 2.3, c.y),
                Pos2::new(wall + h * 1.95, c.y),
            );
        }
        Tile::Gas => {
            for k in 0..14 {
                // Scattered evenly over the picture (a low-discrepancy
                // sequence), not at random.
                let (u, v) = (
                    (0.5 + k as f32 * 0.754_877_7).fract(),
                    (0.5 + k as f32 * 0.569_840_3).fract(),
                );
                let x = rect.left() + rect.width() * (0.1 + 0.8 * u);
                let y = rect.top() + h * (0.15 + 0.7 * v);
                let color = if k % 2 == 0 { blue } else { orange };
                p.circle_filled(Pos2::new(x, y), h * 0.08, color);
            }
        }
        Tile::FreePlay => {
            let from = c - egui::vec2(h * 0.8, -h * 0.2);
            p.circle_filled(from, h * 0.2, blue);
            p.line_segment(
                [from, c + egui::vec2(h * 0.6, -h * 0.25)],
                Stroke::new(1.5, ink),
            );
            arrow(from, c + egui::vec2(h * 0.6, -h * 0.25));
            p.text(
                c + egui::vec2(h * 0.8, h * 0.1),
                Align2::LEFT_CENTER,
                "+",
                egui::FontId::proportional(h * 0.5),
                ink,
            );
        }
    }
}
