//! What a plot says where the pointer is: only on a line, in a box of its
//! own beside the pointer.

use crate::app::lang::tr;
use crate::app::numbers::plain;
use egui_plot::Bar;
use std::{cell::RefCell, rc::Rc};

/// `text` where the pointer is on a line (egui_plot names it), nothing away
/// from the lines: there egui_plot gives the pointer's own place as if it
/// were a value (a momentum at a time not yet run, at the plot's edge).
pub fn on_a_line(name: &str, text: impl FnOnce() -> String) -> String {
    if name.is_empty() {
        String::new()
    } else {
        text()
    }
}

/// A time plot's readout on a line ([`on_a_line`]): its name, the time and
/// the value with `decimals` and `unit`.
pub fn time_readout(name: &str, v: &egui_plot::PlotPoint, decimals: usize, unit: &str) -> String {
    on_a_line(name, || {
        format!(
            "{name}\nt = {} s\n{} {unit}",
            plain(v.x, 2),
            plain(v.y, decimals)
        )
    })
}

/// What hovering a speed bar says, on one line (egui_plot put it at the
/// bar's top, where a second line was cut off by the plot's edge): how many
/// discs it counts and the bin's speeds ("12 discs from 1.00 to 1.25 m/s"),
/// after its series where two are drawn, where egui_plot would show the
/// bare height ("12").
pub fn bar_hover(series: Option<&str>, bar: &Bar, bin_width: f64) -> String {
    let bin = (bar.argument / bin_width).floor();
    let count = bar.value.round() as i64;
    let (low, high) = (plain(bin * bin_width, 2), plain((bin + 1.0) * bin_width, 2));
    let what = tr!("speeds-bar", count = count, low = low, high = high);
    match series {
        Some(series) => format!("{series}: {what}"),
        None => what,
    }
}

/// A plot's readout drawn by us rather than by egui_plot, which writes it
/// up and to the right of the pointer inside the plot's frame: a
/// projector's plots are 27 points high, and of a readout's three lines
/// only the last was left, cut at the frame's top; near the newest
/// point, at the frame's right, nothing was left. The readout goes in a
/// box above the other layers, beside the pointer, on the screen
/// ([`beside`]).
#[derive(Clone, Default)]
pub struct Readout(Rc<RefCell<String>>);

impl Readout {
    /// egui_plot's formatter (of a line's label or a bar's hover) for
    /// `text`: what it writes is kept for [`Readout::show`], and egui_plot
    /// gets nothing to draw.
    pub fn keeping<A: ?Sized, B: ?Sized>(
        &self,
        text: impl Fn(&A, &B) -> String + 'static,
    ) -> impl Fn(&A, &B) -> String + 'static {
        let kept = Rc::clone(&self.0);
        move |a, b| {
            *kept.borrow_mut() = text(a, b);
            String::new()
        }
    }

    /// [`Readout::keeping`] a time plot's [`time_readout`].
    pub fn of_time(
        &self,
        decimals: usize,
        unit: &'static str,
    ) -> impl Fn(&str, &egui_plot::PlotPoint) -> String + 'static {
        self.keeping(move |name: &str, v: &egui_plot::PlotPoint| {
            time_readout(name, v, decimals, unit)
        })
    }

    /// Draws the readout kept this frame, if any, beside the pointer over
    /// the plot `shown`.
    pub fn show(&self, ui: &egui::Ui, shown: &egui::Response) {
        let text = std::mem::take(&mut *self.0.borrow_mut());
        let Some(pointer) = shown.hover_pos() else {
            return;
        };
        if text.is_empty() {
            return;
        }
        let visuals = ui.visuals();
        let font = egui::TextStyle::Body.resolve(ui.style());
        let galley = ui
            .painter()
            .layout_no_wrap(text, font, visuals.strong_text_color());
        let margin = egui::vec2(6.0, 4.0);
        let rect = beside(
            pointer,
            galley.size() + 2.0 * margin,
            ui.ctx().screen_rect(),
        );
        let layer = egui::LayerId::new(egui::Order::Tooltip, shown.id.with("readout"));
        let painter = ui.ctx().layer_painter(layer);
        let stroke = visuals.window_stroke();
        painter.rect(
            rect,
            4.0,
            visuals.window_fill(),
            stroke,
            egui::StrokeKind::Inside,
        );
        painter.galley(rect.min + margin, galley, visuals.strong_text_color());
    }
}

/// Where a box of `size` goes beside the `pointer`: up and to the right of
/// it, clear of it by a gap; to its left where the screen ends on the right
/// (the newest point of a time plot), below it where the screen ends at the
/// top; and always whole on the `screen`.
pub fn beside(pointer: egui::Pos2, size: egui::Vec2, screen: egui::Rect) -> egui::Rect {
    const GAP: f32 = 12.0;
    let x = if pointer.x + GAP + size.x <= screen.right() {
        pointer.x + GAP
    } else {
        pointer.x - GAP - size.x
    };
    let y = if pointer.y - GAP - size.y >= screen.top() {
        pointer.y - GAP - size.y
    } else {
        pointer.y + GAP
    };
    let min = egui::pos2(
        x.clamp(screen.left(), (screen.right() - size.x).max(screen.left())),
        y.clamp(screen.top(), (screen.bottom() - size.y).max(screen.top())),
    );
    egui::Rect::from_min_size(min, size)
}
