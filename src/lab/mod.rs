//! The lab commands (`impulse bench` and `impulse accuracy`): measurements of
//! the physics core written out as tables and charts, and the helpers they
//! share (charts as PNG + SVG, progress bars).

pub mod accuracy;
pub mod bench;
pub mod chart;
pub mod progress;
