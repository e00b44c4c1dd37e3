//! The lab commands (`impulse bench`, `impulse accuracy` and `impulse
//! stress`): measurements of the physics core written out as tables and
//! charts, and the charts they share (line and grid charts as PNG + SVG).

pub mod accuracy;
pub mod bench;
pub mod chart;
pub mod stress;

/// Creates the output folder `out` (and its parents); the error names it.
pub fn create_out_dir(out: &std::path::Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)
        .map_err(|e| anyhow::anyhow!("cannot create the output folder {}: {e}", out.display()))
}
