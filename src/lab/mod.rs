//! The lab commands (`impulse bench`, `impulse accuracy` and `impulse
//! stress`): measurements of the physics core written out as tables and
//! charts, and the helpers they share (line and grid charts as PNG + SVG,
//! progress bars).

pub mod accuracy;
pub mod bench;
pub mod chart;
pub mod progress;
pub mod stress;
