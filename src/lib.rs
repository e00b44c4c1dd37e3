//! The `impulse` package's library: the physics core ([`impulse_core`],
//! in `crates/impulse-core`) under the name the binary, the tests and the
//! benchmarks use. The window and the lab commands are the binary's.

pub use impulse_core::*;
