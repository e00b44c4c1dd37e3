//! Frames of egui without a window, for the views' tests: what a view
//! draws, and a key pressed.

/// The texts `view` draws for `model` in a headless ui `size` points
/// large ([`headless`]), in the order drawn.
pub fn texts_drawn(
    model: &crate::app::model::Sandbox,
    size: egui::Vec2,
    view: &mut dyn crate::app::ui::View,
) -> Vec<String> {
    shapes_drawn(model, size, view)
        .into_iter()
        .filter_map(|shape| match shape {
            egui::Shape::Text(t) => Some(t.galley.text().to_string()),
            _ => None,
        })
        .collect()
}

/// The shapes `view` draws for `model` in a headless ui `size` points
/// large ([`headless`]), in the order drawn.
pub fn shapes_drawn(
    model: &crate::app::model::Sandbox,
    size: egui::Vec2,
    view: &mut dyn crate::app::ui::View,
) -> Vec<egui::Shape> {
    let (mut out, mut marks) = (Vec::new(), crate::app::ui::Marks::default());
    let shown = headless(size, |ui| {
        let mut cx = crate::app::ui::Cx {
            model,
            out: &mut out,
            marks: &mut marks,
            drawer: false,
            open_drawer: None,
            keys: crate::app::ui::Keys::World,
        };
        view.ui(ui, &mut cx);
    });
    shown.shapes.into_iter().map(|c| c.shape).collect()
}

/// A key pressed with `modifiers`, as a frame's input has it (for tests).
pub fn key_press(key: egui::Key, modifiers: egui::Modifiers) -> egui::Event {
    egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    }
}

/// Runs `add` in a ui `size` points large, in an egui without a window and
/// styled as the app's, over three frames (egui settles its layout over a
/// few): the last frame's output. For tests of what a widget lays out.
pub fn headless(size: egui::Vec2, mut add: impl FnMut(&mut egui::Ui)) -> egui::FullOutput {
    let ctx = egui::Context::default();
    crate::app::look::apply(&ctx, 1.0, crate::app::look::Theme::Dark);
    // A scroll asked for arrives at once (in three frames without a clock
    // egui's animation moved a row).
    ctx.style_mut(|s| s.scroll_animation = egui::style::ScrollAnimation::none());
    let mut out = None;
    for _ in 0..3 {
        out = Some(ctx.run(Default::default(), |ctx| {
            egui::CentralPanel::default().show(ctx, |ui| {
                ui.allocate_ui(size, &mut add);
            });
        }));
    }
    out.expect("three frames")
}
