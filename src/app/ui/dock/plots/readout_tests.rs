//! A plot's readout read whole beside the pointer, laid out by egui
//! without a window.
use super::tests::frame_of;
use super::{from_start, still_plot, x_axis};
/// A readout of a plot as low as a projector's (its frame about 20 points
/// high), hovered on its line at `x` of the frame's width (0 its left, 1
/// its right), in a 400 × 300 window: the readout's text and the rectangle
/// it is clipped to.
fn readout_hovered(x: f32) -> Option<(egui::Rect, egui::Rect)> {
    let ctx = egui::Context::default();
    crate::app::look::apply(&ctx, 1.0, crate::app::look::Theme::Dark);
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(400.0, 300.0));
    let mut frame = egui::Rect::NOTHING;
    let mut text = None;
    for pass in 0..4 {
        // The first passes lay the plot out; then the pointer is on its line.
        let events = if pass < 2 {
            vec![]
        } else {
            let at = egui::pos2(frame.lerp_inside(egui::vec2(x, 0.5)).x, frame.center().y);
            vec![egui::Event::PointerMoved(at)]
        };
        let input = egui::RawInput {
            screen_rect: Some(screen),
            events,
            ..Default::default()
        };
        let out = ctx.run(input, |ctx| {
            egui::CentralPanel::default().show(ctx, |ui| {
                ui.allocate_ui(egui::vec2(230.0, 44.0), |ui| {
                    let readout = super::Readout::default();
                    let plot = from_start(still_plot("readout"), 0.0).include_x(3.0);
                    let shown = x_axis(plot, 44.0, String::new(), "s")
                        .include_y(4.0)
                        .include_y(6.0)
                        .height(44.0)
                        .label_formatter(readout.of_time(3, "J"))
                        .show(ui, |plot| {
                            // A sample every 0.1 s: egui_plot reads out
                            // at a line's points.
                            let line: Vec<[f64; 2]> =
                                (0..=30).map(|k| [0.1 * f64::from(k), 5.0]).collect();
                            plot.line(egui_plot::Line::new(line).name("KE"));
                        });
                    readout.show(ui, &shown.response);
                });
            });
        });
        frame = frame_of(&out);
        text = out.shapes.iter().find_map(|c| match &c.shape {
            egui::Shape::Text(t) if t.galley.text().contains("t = ") => {
                Some((t.visual_bounding_rect(), c.clip_rect))
            }
            _ => None,
        });
    }
    text
}

/// A readout is read whole: egui_plot wrote it inside the frame, up and to
/// the right of the pointer, where a projector's 20-point frame cut off
/// all of its three lines but the last, and near the newest point, at the
/// frame's right, all of them.
#[test]
fn a_plot_readout_is_whole_on_the_screen_beside_the_pointer() {
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(400.0, 300.0));
    for x in [0.5, 0.98] {
        let (text, clip) = readout_hovered(x).expect("a readout on the line");
        assert!(
            clip.contains_rect(text) && screen.contains_rect(text),
            "at {x} of the frame: the readout {text:?} clipped to {clip:?}"
        );
    }
}

/// [`super::readout::beside`]: up and to the right of the pointer, to its
/// left at the screen's right, below it at the screen's top; whole on the
/// screen and clear of the pointer.
#[test]
fn a_readout_box_goes_beside_the_pointer_and_stays_on_the_screen() {
    use super::readout::beside;
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(400.0, 300.0));
    let size = egui::vec2(120.0, 60.0);
    let cases = [
        (egui::pos2(100.0, 150.0), "right", "above"),
        (egui::pos2(390.0, 150.0), "left", "above"),
        (egui::pos2(100.0, 20.0), "right", "below"),
        (egui::pos2(395.0, 5.0), "left", "below"),
    ];
    for (pointer, side, level) in cases {
        let b = beside(pointer, size, screen);
        assert!(screen.contains_rect(b), "{pointer:?}: {b:?} off the screen");
        assert!(
            !b.expand(4.0).contains(pointer),
            "{pointer:?}: {b:?} over it"
        );
        let on = if b.left() > pointer.x {
            "right"
        } else {
            "left"
        };
        let at = if b.bottom() < pointer.y {
            "above"
        } else {
            "below"
        };
        assert_eq!((on, at), (side, level), "{pointer:?}: {b:?}");
    }
}
