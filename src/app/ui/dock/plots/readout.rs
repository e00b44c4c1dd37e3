//! What a plot says where the pointer is: only on a line.

use crate::app::numbers::plain;

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
