//! Collision methods: how a step turns contacts into motion.
//!
//! | method | idea | where it fails |
//! |---|---|---|
//! | `seed` | the presentation's: every overlapping pair gets the collision law, half-each push-apart, one step | sticky pairs, centre of mass moves, tunnelling |
//! | `impulse` | approach check, restitution, inverse-mass push-apart, K substeps; under gravity with e < 1, impacts then resting contact with shock propagation ([`resting`]) | tunnelling when travel per substep > radius; simultaneous contacts |
//! | `verlet` | position Verlet, overlap projection, velocity implied by positions, K substeps | collisions come out nearly inelastic; restitution is ignored |
//! | `exact` | event-driven hard discs: earliest impact first, no overlap ever | cost grows with the collision rate; inelastic collapse needs a rule |
//!
//! [`Setting`] lets scene files, the command line and the UI say `auto`
//! wherever they may name a method or a broad phase.

pub mod exact;
pub mod resting;
pub(crate) mod verlet;

use glam::DVec2;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use std::str::FromStr;

/// A concrete collision method.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The presentation's method, kept as the baseline.
    Seed,
    /// Impulses with approach check and restitution (the default).
    #[default]
    Impulse,
    /// Position-based Verlet with overlap projection.
    Verlet,
    /// Event-driven hard discs.
    Exact,
}

impl Method {
    /// All methods, in the order the UI cycles through them.
    pub const ALL: [Method; 4] = [Method::Seed, Method::Impulse, Method::Verlet, Method::Exact];

    /// The lowercase name used in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Method::Seed => "seed",
            Method::Impulse => "impulse",
            Method::Verlet => "verlet",
            Method::Exact => "exact",
        }
    }

    /// Whether the method uses substeps (the others ignore them).
    pub fn uses_substeps(self) -> bool {
        matches!(self, Method::Impulse | Method::Verlet)
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Method::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                format!("unknown method {s:?}: expected one of seed, impulse, verlet, exact, auto")
            })
    }
}

/// What the methods keep beside the pipeline's buffers: `exact`'s event
/// calendar from step to step, and scratch reused from substep to substep.
#[derive(Default)]
pub(crate) struct MethodState {
    /// The exact method's event calendar, carried from step to step.
    pub(crate) exact: exact::Exact,
    /// Scratch of the resting-contact substep.
    pub(crate) resting: resting::Scratch,
    /// Scratch: positions before a Verlet substep.
    pub(crate) previous_positions: Vec<DVec2>,
}

/// `auto`, or a fixed choice.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Setting<T> {
    /// Let [`crate::auto`] decide from the scene.
    #[default]
    Auto,
    /// Always this.
    Fixed(T),
}

impl<T: Copy> Setting<T> {
    /// The fixed value, or `auto_value` when automatic.
    pub fn or(self, auto_value: T) -> T {
        match self {
            Setting::Auto => auto_value,
            Setting::Fixed(v) => v,
        }
    }
}

impl<T: fmt::Display> fmt::Display for Setting<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Setting::Auto => f.write_str("auto"),
            Setting::Fixed(v) => v.fmt(f),
        }
    }
}

impl<T: FromStr> FromStr for Setting<T>
where
    T::Err: fmt::Display,
{
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        if s == "auto" {
            Ok(Setting::Auto)
        } else {
            s.parse()
                .map(Setting::Fixed)
                .map_err(|e| format!("{s:?}: {e} (or \"auto\")"))
        }
    }
}

impl<T: fmt::Display> Serialize for Setting<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de, T: FromStr> Deserialize<'de> for Setting<T>
where
    T::Err: fmt::Display,
{
    /// Accepts `"auto"`, a name, or a bare number (for substeps).
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            Text(String),
            Number(u64),
        }
        let text = match Raw::deserialize(deserializer)? {
            Raw::Text(s) => s,
            Raw::Number(n) => n.to_string(),
        };
        text.parse().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_auto_is_accepted() {
        for m in Method::ALL {
            assert_eq!(m.name().parse::<Method>(), Ok(m));
            assert_eq!(m.name().parse::<Setting<Method>>(), Ok(Setting::Fixed(m)));
        }
        assert_eq!("auto".parse::<Setting<Method>>(), Ok(Setting::Auto));
        let err = "rk4".parse::<Method>().unwrap_err();
        assert!(err.contains("rk4") && err.contains("exact"));
    }
}
