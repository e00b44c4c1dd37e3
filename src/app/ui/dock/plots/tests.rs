//! The plots' axes and ranges, laid out by egui without a window.
use super::readout::{bar_hover, time_readout};
use super::values::{padded_range, value_steps};
use super::{
    from_start, on_a_line, steps_of_one_two_or_five_ten, still_plot, tick, value_axis, whole_count,
    x_axis,
};
use crate::app::numbers::{plain, trimmed};
use crate::app::ui::widgets::headless;
use egui_plot::{Bar, GridInput};

#[test]
fn the_grid_steps_are_a_power_of_ten_then_two_or_five_and_ten_of_it() {
    let steps = |base_step_size| {
        steps_of_one_two_or_five_ten(GridInput {
            bounds: (0.0, 10.0),
            base_step_size,
        })
    };
    // Two of the unit where its marks are 40 points apart (5 base steps),
    // else five.
    assert_eq!(steps(0.3), [1.0, 2.0, 10.0]);
    assert_eq!(steps(0.5), [1.0, 5.0, 10.0]);
    assert_eq!(steps(1.0), [1.0, 5.0, 10.0]);
    assert_eq!(steps(1.5), [10.0, 20.0, 100.0]);
    assert_eq!(steps(5.0), [10.0, 50.0, 100.0]);
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

/// A plot's frame, the rectangle drawn inside the 230-point-wide room
/// the tests give it.
pub(super) fn frame_of(out: &egui::FullOutput) -> egui::Rect {
    out.shapes
        .iter()
        .find_map(|c| match &c.shape {
            egui::Shape::Rect(r) if r.rect.width() < 230.0 => Some(r.rect),
            _ => None,
        })
        .expect("a frame")
}

/// The value axis's numbers of a plot `height` points high showing
/// constant totals `values` (its axis as the Totals tab makes it), each
/// with the height of its middle; the heights of the lines; the frame.
fn plotted_numbers(height: f32, values: &[f64]) -> (Vec<(String, f32)>, Vec<f32>, egui::Rect) {
    let series: Vec<Vec<[f64; 2]>> = values.iter().map(|&v| vec![[0.0, v], [3.0, v]]).collect();
    let out = headless(egui::vec2(230.0, height), |ui| {
        let plot = from_start(still_plot("value"), 0.0).include_x(3.0);
        let slices: Vec<&[[f64; 2]]> = series.iter().map(Vec::as_slice).collect();
        let plot = value_axis(plot, &slices, height);
        x_axis(plot, height, String::new(), "s")
            .height(height)
            .show(ui, |plot| {
                for points in &series {
                    plot.line(egui_plot::Line::new(points.clone()));
                }
            });
    });
    let lines = out
        .shapes
        .iter()
        .filter_map(|c| match &c.shape {
            egui::Shape::Path(p) if p.points.len() == 2 && p.points[0].y == p.points[1].y => {
                Some(p.points[0].y)
            }
            _ => None,
        })
        .collect();
    let frame = frame_of(&out);
    let numbers = out
        .shapes
        .iter()
        .filter_map(|c| match &c.shape {
            egui::Shape::Text(t) => Some(t),
            _ => None,
        })
        .map(|t| {
            (
                t.galley.text().trim().to_string(),
                t.pos.x,
                t.pos.y + 0.5 * t.galley.size().y,
            )
        })
        // Left of the frame and beside it: the value axis's, not the
        // time axis's under it.
        .filter(|(text, x, middle)| {
            !text.is_empty() && *x < frame.left() && *middle <= frame.bottom()
        })
        .map(|(text, _, middle)| (text, middle))
        .collect();
    (numbers, lines, frame)
}

/// [`plotted_numbers`] of one constant total `v`: each number with how far
/// its middle is from the line (points), and how far the line is from the
/// middle of the frame.
fn value_numbers(height: f32, v: f64) -> (Vec<(String, f32)>, f32) {
    let (numbers, lines, frame) = plotted_numbers(height, &[v]);
    let line = lines[0];
    let numbers = numbers
        .into_iter()
        .map(|(t, y)| (t, (y - line).abs()))
        .collect();
    (numbers, (line - frame.center().y).abs())
}

/// Two conserved totals in one plot (the head-on hit's p_x and p_y): each
/// line numbered with its own value, level with it, where the plot has
/// room for two numbers (a projector's 27 points of frame hold one).
#[test]
fn two_constant_totals_are_numbered_each_with_its_value() {
    for height in [70.0, 120.0, 300.0] {
        let (numbers, lines, frame) = plotted_numbers(height, &[2.5, 0.0]);
        let texts: Vec<_> = numbers.iter().map(|(t, _)| t.as_str()).collect();
        assert_eq!(texts.len(), 2, "{height} points: {texts:?}");
        for (text, line) in [("2.5", lines[0]), ("0", lines[1])] {
            let (_, y) = numbers.iter().find(|(t, _)| t == text).expect(text);
            assert!(
                (y - line).abs() < 1.0,
                "{height} points: {text} at {y}, its line at {line}"
            );
            // The whole number beside the frame (at the top, a projector's
            // "2" was cut off).
            let half = 10.0;
            assert!(
                y - half >= frame.top() - 1.0 && y + half <= frame.bottom() + 1.0,
                "{height} points: {text} at {y}, the frame {frame:?}"
            );
        }
    }
}

/// Two conserved totals in a plot with room for one number (a
/// projector's): the total farther from zero is numbered, level with its
/// line, and the other has none. The head-on hit's p_y at 0 had the
/// number, and its p_x, the total the lesson is about, none.
#[test]
fn where_one_number_fits_the_total_farther_from_zero_has_it() {
    for height in [44.0, 51.0, 60.0] {
        for values in [[2.5, 0.0], [0.0, -4.0]] {
            let (numbers, lines, frame) = plotted_numbers(height, &values);
            let read = if values[0].abs() > values[1].abs() {
                0
            } else {
                1
            };
            let texts: Vec<_> = numbers.iter().map(|(t, _)| t.as_str()).collect();
            let expected = trimmed(&plain(values[read], 1)).to_string();
            assert_eq!(texts, [expected.as_str()], "{height} points");
            let y = numbers[0].1;
            assert!((y - lines[read]).abs() < 1.0, "{height}: {y}, {lines:?}");
            assert!(
                y - 10.0 >= frame.top() - 1.0 && y + 10.0 <= frame.bottom() + 1.0,
                "{height} points: at {y}, the frame {frame:?}"
            );
            let other = lines[1 - read];
            assert!(frame.top() <= other && other <= frame.bottom(), "{other}");
        }
    }
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
        let frame = frame_of(&out);
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
/// glancing hit's L, −13.25, lay between marks of 2; its range was then
/// widened to −14, which left the line off the middle, read against a
/// number it was not. Now a constant total stays in the middle, and a
/// number stands beside it: a mark of the axis, or the line's own value.
#[test]
fn a_short_plot_of_a_constant_total_numbers_its_line_in_the_middle() {
    for height in [44.0, 46.0, 50.0, 60.0, 80.0] {
        for v in [
            -12.3, -7.7, 105.0, 0.37, 20.0, -150.0, 750.0, 2.45e6, -13.25, -0.75, 0.0, 33.3,
        ] {
            let (numbers, off_middle) = value_numbers(height, v);
            assert!(!numbers.is_empty(), "{height} points, {v}: no number");
            assert!(
                off_middle < 1.0,
                "{height} points, {v}: the line is {off_middle} points off the middle"
            );
            // A number level with the line is its value, to a hundredth
            // of the range (which is ±5 % of the value, or ±0.01).
            let span = 2.0 * (0.05 * v.abs()).max(0.01);
            for (text, off) in &numbers {
                if *off < 1.5 {
                    // (As a field reads it: "2.45×10⁶" too.)
                    let read = crate::app::numbers::parse(text).unwrap_or(f64::NAN);
                    assert!(
                        (read - v).abs() <= 0.01 * span,
                        "{height} points, {v}: \"{text}\" beside the line"
                    );
                }
            }
        }
    }
}

/// A conserved total is numbered with its own value, level with its line
/// and alone: the glancing hit's L between two marks of a projector's
/// plot, its KE read against a "3.0" under the line, the π blocks' L.
#[test]
fn a_constant_total_is_numbered_with_its_own_value() {
    for (v, text) in [
        (-13.25, "−13.25"),
        (3.125, "3.125"),
        (750.0, "750"),
        (0.0, "0"),
        // A disc at 10⁷ m/s: its KE had read 50000000000000, cut.
        (5e13, "5×10¹³"),
    ] {
        for height in [50.0, 120.0, 200.0] {
            let (numbers, _) = value_numbers(height, v);
            let texts: Vec<_> = numbers.iter().map(|(t, _)| t.as_str()).collect();
            assert_eq!(texts, [text], "{height} points");
            assert!(numbers[0].1 < 1.0, "{height} points: {numbers:?}");
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
fn a_count_axis_numbers_whole_discs_only() {
    let mark = |value, step_size| egui_plot::GridMark { value, step_size };
    assert_eq!(whole_count(mark(0.5, 0.5)), "");
    assert_eq!(whole_count(mark(1.0, 0.5)).trim(), "1");
    assert_eq!(whole_count(mark(20.0, 10.0)).trim(), "20");
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

/// The first seconds of a projector's plot (a frame 118 points wide):
/// numbered every two seconds (with steps of five, "0 s" stood alone until
/// 5 s).
#[test]
fn a_short_time_axis_numbers_every_two_seconds_where_they_fit() {
    let numbers = time_numbers(150.0, 4.7);
    assert!(
        numbers.contains(&"2 s".to_string()) && numbers.contains(&"4 s".to_string()),
        "{numbers:?}"
    );
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

/// The review's "t = 0.8 / −142." with the pointer on an empty part of a
/// paused plot: a readout only on a line, with its name.
#[test]
fn a_plot_reads_out_only_on_a_line() {
    let at = egui_plot::PlotPoint::new(0.8, -142.0);
    assert_eq!(time_readout("", &at, 3, "kg·m²/s"), "");
    assert_eq!(
        time_readout("L", &at, 3, "kg·m²/s"),
        "L\nt = 0.80 s\n−142.000 kg·m²/s"
    );
    assert_eq!(on_a_line("", || "(1, 2)".into()), "");
}

/// The curve's points drawn by the Speeds plot of `n` discs, all moving
/// at 1 m/s but one at rest (so the speeds spread).
fn curve_points(n: usize) -> usize {
    let mut world = impulse::World::new(glam::DVec2::new(100.0, 100.0));
    for k in 0..n {
        let vel = if k == 0 {
            glam::DVec2::ZERO
        } else {
            glam::DVec2::X
        };
        world.particles.push(impulse::Particle::new(
            glam::DVec2::new(2.0 + 3.0 * k as f64, 50.0),
            vel,
            1.0,
            0.5,
            impulse::Color::rgb(0, 0, 0),
        ));
    }
    let h = crate::app::model::totals::SpeedHistogram::of(&world).expect("a histogram");
    let out = headless(egui::vec2(400.0, 200.0), |ui| {
        super::speed_plot(ui, &h, None, 180.0, false);
    });
    out.shapes
        .iter()
        .filter_map(|c| match &c.shape {
            egui::Shape::Path(p) if p.points.len() > 50 => Some(p.points.len()),
            _ => None,
        })
        .sum()
}

/// Maxwell–Boltzmann over a head-on hit's two bars read as something they
/// should follow: the curve is drawn from a gas's number of discs only.
#[test]
fn the_speeds_curve_is_drawn_for_a_gas_only() {
    use crate::app::model::totals::GAS_AT_LEAST;
    assert_eq!(curve_points(2), 0, "two discs");
    assert_eq!(curve_points(GAS_AT_LEAST - 1), 0);
    assert!(curve_points(GAS_AT_LEAST) > 50, "a gas");
}
