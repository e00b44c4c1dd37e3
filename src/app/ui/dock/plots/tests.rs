//! The plots' axes and ranges, laid out by egui without a window.
use super::{
    bar_hover, from_start, numbered_range, padded_range, steps_of_one_five_ten, still_plot, tick,
    value_steps, x_axis,
};
use crate::app::ui::widgets::headless;
use egui_plot::{Bar, GridInput};

#[test]
fn the_grid_steps_are_a_power_of_ten_then_five_and_ten_of_it() {
    let steps = |base_step_size| {
        steps_of_one_five_ten(GridInput {
            bounds: (0.0, 10.0),
            base_step_size,
        })
    };
    assert_eq!(steps(0.3), [1.0, 5.0, 10.0]);
    assert_eq!(steps(1.0), [1.0, 5.0, 10.0]);
    assert_eq!(steps(1.5), [10.0, 50.0, 100.0]);
    let tiny = steps(0.0);
    assert!(tiny.iter().all(|s| s.is_finite() && *s > 0.0), "{tiny:?}");
}

/// The time axis's numbers a plot `width` points wide over 0 to `end`
/// seconds shows, drawn by egui without a window.
fn time_numbers(width: f32, end: f64) -> Vec<String> {
    let out = headless(egui::vec2(width, 60.0), |ui| {
        let plot = from_start(still_plot("time"), 0.0).include_x(end);
        x_axis(plot, 60.0, String::new(), "s")
            .height(60.0)
            .show(ui, |_| {});
    });
    drawn_text(&out)
        .filter(|text| text.ends_with(" s"))
        .collect()
}

/// The text a frame drew.
fn drawn_text(out: &egui::FullOutput) -> impl Iterator<Item = String> + '_ {
    out.shapes
        .iter()
        .filter_map(|clipped| match &clipped.shape {
            egui::Shape::Text(text) => Some(text.galley.text().to_string()),
            _ => None,
        })
}

/// The value axis's numbers of a plot `height` points high showing a
/// constant total `v` (padded as the Totals tab pads it).
fn value_numbers(height: f32, v: f64) -> Vec<String> {
    let (lo, hi) = numbered_range(padded_range([v, v].into_iter()), height);
    let out = headless(egui::vec2(230.0, height), |ui| {
        let plot = from_start(still_plot("value"), 0.0).include_x(3.0);
        x_axis(plot, height, String::new(), "s")
            .include_y(lo)
            .include_y(hi)
            .height(height)
            .show(ui, |plot| {
                plot.line(egui_plot::Line::new(vec![[0.0, v], [3.0, v]]));
            });
    });
    drawn_text(&out)
        .filter(|text| !text.is_empty() && !text.ends_with(" s"))
        .collect()
}

/// The value axis's numbers stand clear of the plot's frame (egui_plot
/// set them flush against it: "−200" touched it).
#[test]
fn a_value_axis_number_stands_clear_of_the_frame() {
    for v in [-200.0, 3.0, 750.0, -0.37] {
        let (lo, hi) = padded_range([v, v].into_iter());
        let out = headless(egui::vec2(230.0, 80.0), |ui| {
            let plot = from_start(still_plot("value"), 0.0).include_x(3.0);
            x_axis(plot, 80.0, String::new(), "s")
                .include_y(lo)
                .include_y(hi)
                .height(80.0)
                .show(ui, |plot| {
                    plot.line(egui_plot::Line::new(vec![[0.0, v], [3.0, v]]));
                });
        });
        // The frame: the rectangle drawn inside the window.
        let frame = out
            .shapes
            .iter()
            .filter_map(|c| match &c.shape {
                egui::Shape::Rect(r) if r.rect.width() < 230.0 => Some(r.rect),
                _ => None,
            })
            .next()
            .expect("a frame");
        let mut numbers = 0;
        for c in &out.shapes {
            let egui::Shape::Text(t) = &c.shape else {
                continue;
            };
            let text = t.galley.text();
            if text.trim().is_empty() || text.ends_with(" s") {
                continue;
            }
            // Where the last letter's ink ends.
            let ink = t
                .galley
                .rows
                .iter()
                .flat_map(|row| row.glyphs.iter())
                .filter(|g| !g.chr.is_whitespace() && g.chr != '\u{a0}')
                .map(|g| g.pos.x + g.advance_width)
                .fold(f32::MIN, f32::max);
            let right = t.pos.x + ink;
            assert!(
                right <= frame.left() - 3.0,
                "{v}: \"{text}\" ends at {right}, the frame starts at {}",
                frame.left()
            );
            numbers += 1;
        }
        assert!(numbers > 0, "{v}: no number");
    }
}

/// A projector's Totals plots have 27 points of frame (46 with the
/// time axis): the L plot of the π blocks (750 kg·m²/s) had no number
/// on its axis. Its marks of 50 were 18 points apart, too close for
/// egui_plot's 20, and the next, 100, had none in its range. The
/// glancing hit's L, −13.25, lay between marks of 2 (its range is
/// widened to −12 now).
#[test]
fn a_short_plot_of_a_constant_total_numbers_its_axis() {
    for height in [44.0, 46.0, 50.0, 60.0, 80.0] {
        for v in [
            -12.3, -7.7, 105.0, 0.37, 20.0, -150.0, 750.0, 2.45e6, -13.25, -0.75, 0.0, 33.3,
        ] {
            let numbers = value_numbers(height, v);
            assert!(!numbers.is_empty(), "{height} points, {v}: no number");
        }
    }
}

#[test]
fn the_numbered_value_step_is_far_enough_apart_and_has_a_mark_in_range() {
    let steps = |base_step_size| {
        value_steps(GridInput {
            bounds: (0.0, 10.0),
            base_step_size,
        })
    };
    // The base step is 8 points: 21 points are 2.625 of it. On 0 to 10
    // every step has a mark (0).
    assert_eq!(steps(8.0), [2.5, 5.0, 25.0]);
    assert_eq!(steps(3.0), [1.0, 2.0, 10.0]);
    assert_eq!(steps(1.0), [0.5, 1.0, 5.0]);
    let tiny = steps(0.0);
    assert!(tiny.iter().all(|s| s.is_finite() && *s > 0.0), "{tiny:?}");
    // No mark of 100, 200 (or 2.5 of it) between 710 and 790: 250 has 750.
    let around_750 = value_steps(GridInput {
        bounds: (710.0, 790.0),
        base_step_size: 24.0,
    });
    assert_eq!(around_750, [25.0, 50.0, 250.0]);
}

#[test]
fn a_speed_bar_says_how_many_discs_it_counts_and_between_which_speeds() {
    use crate::app::lang::{set_language, Lang};
    // The third bin of 0.25 m/s, its bar drawn off its centre (beside a
    // rim-speed bar), its height a count with a rounding error.
    let bar = Bar::new(0.57, 12.000000001);
    assert_eq!(
        bar_hover(Some("speeds |v|"), &bar, 0.25),
        "speeds |v|: 12 discs from 0.50 to 0.75 m/s"
    );
    assert_eq!(
        bar_hover(None, &Bar::new(0.125, 1.0), 0.25),
        "one disc from 0.00 to 0.25 m/s"
    );
    set_language(Lang::De);
    let german = bar_hover(None, &bar, 0.25);
    set_language(Lang::En);
    assert_eq!(german, "12 Scheiben von 0,50 bis 0,75 m/s");
}

#[test]
fn an_axis_of_huge_values_numbers_them_with_a_power_of_ten() {
    let mark = |value, step_size| egui_plot::GridMark { value, step_size };
    assert_eq!(tick(mark(8e11, 2e11)), "8×10¹¹");
    assert_eq!(tick(mark(1.5e6, 5e5)), "1.5×10⁶");
    assert_eq!(tick(mark(-4e9, 1e9)), "−4×10⁹");
    assert_eq!(tick(mark(250.0, 50.0)), "250");
    assert_eq!(tick(mark(0.5, 0.1)), "0.5");
}

#[test]
fn a_short_time_axis_numbers_every_five_seconds() {
    // A projector's third of a 1024-px dock at text size 2: 120 points.
    let numbers = time_numbers(120.0, 9.0);
    assert!(numbers.contains(&"5 s".to_string()), "{numbers:?}");
    // And never so close that they run into each other.
    let numbers = time_numbers(60.0, 9.0);
    assert!(!numbers.contains(&"1 s".to_string()), "{numbers:?}");
}

#[test]
fn a_conserved_total_gets_a_range_wider_than_its_noise() {
    let (lo, hi) = padded_range([2.0, 2.0 + 1e-15, 2.0 - 1e-15].into_iter());
    assert!(hi - lo >= 0.2 - 1e-12, "{lo} {hi}");
    assert!(lo < 2.0 && hi > 2.0);
    assert_eq!(padded_range(std::iter::empty()), (-1.0, 1.0));
    let (lo, hi) = padded_range([0.0, 0.0].into_iter());
    assert!((lo + 0.01).abs() < 1e-12 && (hi - 0.01).abs() < 1e-12);
}
