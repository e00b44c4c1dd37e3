//! The mark of what has the keyboard: a ring round a control, in a colour
//! that stands out in the theme, or a control's own mark (an edge).

/// The colour that marks what has the keyboard, one that stands out in the
/// theme (egui's own mark of focus is faint).
pub fn focus_color(theme: crate::app::model::Theme) -> egui::Color32 {
    match theme {
        crate::app::model::Theme::Dark => egui::Color32::from_rgb(255, 200, 0),
        crate::app::model::Theme::Light => egui::Color32::from_rgb(0, 80, 200),
    }
}

/// Says that control `id` marks its own focus this frame (an edge, whose
/// ring would strike through the text on either side of it).
pub fn marks_own_focus(ctx: &egui::Context, id: egui::Id) {
    ctx.data_mut(|d| d.insert_temp(egui::Id::new("marks_own_focus"), Some(id)));
}

/// A ring round the control that has the keyboard, over everything, in
/// [`focus_color`]; none round one that [`marks_own_focus`].
pub fn focus_ring(ctx: &egui::Context, id: egui::Id, theme: crate::app::model::Theme) {
    let own = ctx.data_mut(|d| d.remove_temp::<Option<egui::Id>>(egui::Id::new("marks_own_focus")));
    if own == Some(Some(id)) {
        return;
    }
    let Some(response) = ctx.read_response(id) else {
        return;
    };
    let color = focus_color(theme);
    let painter = ctx.layer_painter(egui::LayerId::new(
        egui::Order::Tooltip,
        egui::Id::new("focus_ring"),
    ));
    painter.rect_stroke(
        response.rect.expand(3.0),
        egui::CornerRadius::same(4),
        egui::Stroke::new(3.0, color),
        egui::StrokeKind::Outside,
    );
}
