//! A plot's value axis: a range that shows a conserved total as a flat
//! line, numbered where a person reads it (each flat line with its own
//! value where there is room).

use super::{beside_frame, decimals_of, BASE_STEP_POINTS};
use crate::app::numbers::{plain, trimmed};
use egui_plot::Plot;

/// The least room between two numbers of a value axis (points): egui_plot
/// leaves out a number closer to the next than its own height (a line of
/// body text, 20.4 points).
const VALUE_LABEL_POINTS: f32 = 21.0;

/// The value axis's steps: the largest is numbered, so it is the smallest
/// of 1, 2, 2.5 or 5 × 10ᵏ at least [`VALUE_LABEL_POINTS`] apart that has a
/// mark in the plot's range; the others are a fifth and a tenth of it. A
/// short plot of a constant total (27 points of frame at a projector's
/// size) had no number at all: egui_plot's steps up by ten left the L of
/// the π blocks (750 ± 41) its marks of 50 16 points apart, too close for a
/// number, and none of 100 in range; 250 has 750.
pub(super) fn value_steps(input: egui_plot::GridInput) -> [f64; 3] {
    let base = input.base_step_size.abs().max(f64::MIN_POSITIVE);
    let least = base * f64::from(VALUE_LABEL_POINTS) / BASE_STEP_POINTS;
    let (lo, hi) = input.bounds;
    let nice =
        |k: i32| [1.0, 2.0, 2.5, 5.0][k.rem_euclid(4) as usize] * 10f64.powi(k.div_euclid(4));
    // The first of the sequence at least `least`...
    let start = 4 * least.log10().floor().clamp(-300.0, 300.0) as i32;
    let first = (start..start + 8)
        .find(|&k| nice(k) >= least * (1.0 - 1e-12))
        .unwrap_or(start);
    // ... or a larger one, where its marks miss the range.
    let marked = |k: i32| (lo / nice(k)).ceil() * nice(k) <= hi;
    let label = nice((first..first + 16).find(|&k| marked(k)).unwrap_or(first));
    [label / 10.0, label / 5.0, label]
}

/// A y range that shows a conserved total as a flat line, not its rounding
/// noise magnified: at least ±5 % of the values' size (or ±0.01) around them.
pub(super) fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let size = lo.abs().max(hi.abs());
    let pad = (0.1 * (hi - lo)).max(0.05 * size).max(0.01);
    (lo - pad, hi + pad)
}

/// What a plot's height holds besides its frame (points): the time axis's
/// numbers and the margins, 21 points measured, taken as 24 so that a
/// frame reckoned smaller than it is asks for marks no closer than egui
/// numbers (reckoned larger, a mark 21.7 points from the next was left
/// unnumbered).
const TIME_AXIS_POINTS: f32 = 24.0;

/// A value axis for a plot `height` points high (with its time axis) of
/// `series` (points of time and value): [`padded_range`]'s range, numbered
/// by [`value_steps`]. Where every series is flat (conserved totals), each
/// line is numbered with its own value instead, to four figures, level
/// with it; where none of the numbered marks falls in the range (a short
/// plot), the range is widened to hold one. The glancing hit's L, −13.25
/// kg·m²/s, had no number between −14 and −12 in a projector's 27 points
/// of frame; widened to reach −14, the range left the line off the middle,
/// read against a number it was not; its KE, 3.125 J, was read against a
/// "3.0" under it, and its p_x had no number at all.
pub fn value_axis(plot: Plot<'static>, series: &[&[[f64; 2]]], height: f32) -> Plot<'static> {
    let extent = |points: &[[f64; 2]]| {
        points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[1]), hi.max(p[1]))
            })
    };
    let extents: Vec<(f64, f64)> = series
        .iter()
        .map(|s| extent(s))
        .filter(|(lo, hi)| lo.is_finite() && hi.is_finite())
        .collect();
    let range = padded_range(extents.iter().flat_map(|&(lo, hi)| [lo, hi]));
    let ((lo, hi), own) = own_marks(range, height, &extents);
    let plot = plot.include_y(lo).include_y(hi);
    if own.is_empty() {
        return plot;
    }
    let values: Vec<f64> = own.iter().map(|(v, _)| *v).collect();
    plot.y_grid_spacer(move |input| {
        let span = input.bounds.1 - input.bounds.0;
        let mut marks = egui_plot::uniform_grid_spacer(value_steps)(input);
        marks.retain(|m| m.step_size < 0.5 * span && !values.contains(&m.value));
        let own = values.iter().map(|&value| egui_plot::GridMark {
            value,
            step_size: span,
        });
        marks.extend(own);
        marks
    })
    // The other marks are grid lines without numbers, which would crowd
    // the lines' own.
    .y_axis_formatter(move |mark, _| {
        own.iter()
            .find(|(v, _)| *v == mark.value)
            .map_or_else(String::new, |(_, label)| beside_frame(label.clone()))
    })
}

/// [`value_axis`]'s range and marks of its own, on `range` of a plot
/// `height` points high, its series spanning `extents`: each series' value
/// where all are flat (within a hundredth of the range) and their numbers
/// do not crowd each other, the range then widened to hold the numbers of
/// the top and bottom lines (at a projector's size the top one was cut
/// off), or where they would, the value of the line farthest from zero,
/// in the middle; else none, the range widened to hold a numbered mark of
/// [`value_steps`]. Each is rounded to a hundredth of the range
/// (so it sits on its line to within a point) and written without
/// trailing zeros.
fn own_marks((lo, hi): (f64, f64), height: f32, extents: &[(f64, f64)]) -> ((f64, f64), OwnMarks) {
    let span = hi - lo;
    if !(span > 0.0 && span.is_finite()) {
        return ((lo, hi), Vec::new());
    }
    let frame = f64::from((height - TIME_AXIS_POINTS).max(8.0));
    let mark = |v: f64, span: f64| {
        let step = 10f64.powf((span / 100.0).log10().floor());
        let value = (v / step).round() * step;
        // From a million up as the top bar writes it (5×10¹³, not
        // 50000000000000, which a narrow plot cut).
        let label = match value.abs() >= 1e6 {
            true => crate::app::numbers::field(value),
            false => trimmed(&plain(value, decimals_of(step))).to_string(),
        };
        (value, label)
    };
    let flat = extents.iter().all(|(a, b)| b - a <= 0.01 * span);
    if flat && !extents.is_empty() {
        let mut values: Vec<f64> = extents.iter().map(|(a, b)| 0.5 * (a + b)).collect();
        values.sort_by(f64::total_cmp);
        values.dedup_by(|a, b| (*a - *b).abs() <= 0.01 * span);
        if let [one] = values[..] {
            return ((lo, hi), vec![mark(one, span)]);
        }
        // Half a number's height past the outer lines, as a share of the
        // frame: a margin m on both sides of their spread d has
        // m = half · (d + 2m). Where two lines' numbers do not fit (a
        // projector's 27 points of frame hold one), the axis's own numbers.
        let half = 0.5 * f64::from(VALUE_LABEL_POINTS) / frame;
        if half < 0.5 {
            let (least, most) = (values[0], values[values.len() - 1]);
            let margin = half * (most - least) / (1.0 - 2.0 * half);
            let (lo, hi) = (lo.min(least - margin), hi.max(most + margin));
            let apart = values
                .windows(2)
                .all(|w| (w[1] - w[0]) / (hi - lo) * frame >= f64::from(VALUE_LABEL_POINTS));
            if apart {
                let marks = values.into_iter().map(|v| mark(v, hi - lo)).collect();
                return ((lo, hi), marks);
            }
        }
        // Room for one number: the line farthest from zero gets it, in the
        // middle of the range, the others under or over it. The head-on
        // hit's p_y at 0 had taken the axis's one number, and its p_x, the
        // total the lesson is about, had none.
        let read = values
            .iter()
            .copied()
            .fold(values[0], |a, v| if v.abs() > a.abs() { v } else { a });
        let reach = (read - lo).max(hi - read);
        let range = (read - reach, read + reach);
        return (range, vec![mark(read, 2.0 * reach)]);
    }
    // Lines that move: the axis's numbers (one in the middle of the range
    // instead, a KE going from 3 to 22 J read "12.7", as if a value).
    (numbered_range((lo, hi), height), Vec::new())
}

/// Marks of [`own_marks`]: each value and its number.
type OwnMarks = Vec<(f64, String)>;

/// A range widened, where it must be, to hold a numbered mark of
/// [`value_steps`] in a plot `height` points high (with its time axis):
/// a short plot's range can fall between two marks and have no number.
fn numbered_range((mut lo, mut hi): (f64, f64), height: f32) -> (f64, f64) {
    let frame = f64::from((height - TIME_AXIS_POINTS).max(8.0));
    for _ in 0..4 {
        let span = hi - lo;
        if !(span > 0.0 && span.is_finite()) {
            break;
        }
        let base = span * BASE_STEP_POINTS / frame;
        let label = value_steps(egui_plot::GridInput {
            bounds: (lo, hi),
            base_step_size: base,
        })[2];
        let below = (hi / label).floor() * label;
        if below >= lo {
            break;
        }
        // The nearer mark, and a little room past it.
        let above = (lo / label).ceil() * label;
        if lo - below < above - hi {
            lo = below - 0.05 * span;
        } else {
            hi = above + 0.05 * span;
        }
    }
    (lo, hi)
}
