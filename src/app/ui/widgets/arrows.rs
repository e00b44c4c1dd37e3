//! A slider's arrow keys: a twentieth of its range a press.

use egui::Ui;

/// Presses of ← and → a slider takes to cross its range; with Shift,
/// [`FINE_STEPS`].
const ARROW_STEPS: f64 = 20.0;
const FINE_STEPS: f64 = 100.0;

/// The arrows on the slider `id` that has the keyboard, taken before egui's
/// slider sees them: a twentieth of the range a press (a hundredth with
/// Shift), on that grid, where egui moves the knob a point a press (three
/// presses took a restitution from 1.00 to 0.95). On a logarithmic track,
/// a twentieth of its decades. Returns whether the value changed.
pub fn arrow_steps(
    ui: &mut Ui,
    id: egui::Id,
    value: &mut f64,
    range: &std::ops::RangeInclusive<f64>,
    log: bool,
) -> bool {
    if !ui.memory(|m| m.has_focus(id)) {
        return false;
    }
    let presses = |modifiers| {
        let count = |key| ui.input_mut(|i| i.count_and_consume_key(modifiers, key)) as f64;
        count(egui::Key::ArrowRight) - count(egui::Key::ArrowLeft)
    };
    // Shift first: egui's match of no modifiers lets Shift through.
    let fine = presses(egui::Modifiers::SHIFT);
    let coarse = presses(egui::Modifiers::NONE);
    let (presses, grid) = if fine != 0.0 {
        (coarse * FINE_STEPS / ARROW_STEPS + fine, FINE_STEPS)
    } else {
        (coarse, ARROW_STEPS)
    };
    if presses == 0.0 {
        return false;
    }
    let (low, high) = (*range.start(), *range.end());
    let was = *value;
    // Where it is along the track (0 to 1: of the decades on a logarithmic
    // one), moved to the next point of the grid that way and on.
    let decades = (high / low).log10();
    let log = log && low > 0.0;
    let at = if log {
        (was.max(low) / low).log10() / decades
    } else {
        (was - low) / (high - low)
    };
    let from = if presses > 0.0 {
        (at * grid + 1e-9).floor()
    } else {
        (at * grid - 1e-9).ceil()
    };
    let to = (from + presses) / grid;
    *value = if log {
        low * 10f64.powf(to * decades)
    } else {
        low + to * (high - low)
    }
    .clamp(low, high);
    *value != was
}
