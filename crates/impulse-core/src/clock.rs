//! The wall clock behind the stage timings, on every target.
//!
//! On the desktop it is `std::time::Instant`. In a browser
//! (`wasm32-unknown-unknown`) `Instant::now` panics and there is no clock
//! without the page's help, so the caller installs one (`set_clock`,
//! seconds from any fixed origin); until then every timing reads zero. The
//! core imports nothing from the page itself, so it runs under any wasm
//! host.

use std::time::Duration;

/// A moment on the wall clock.
#[derive(Clone, Copy, Debug)]
pub struct Instant(
    #[cfg(not(target_arch = "wasm32"))] std::time::Instant,
    #[cfg(target_arch = "wasm32")] f64,
);

#[cfg(target_arch = "wasm32")]
static CLOCK: std::sync::OnceLock<fn() -> f64> = std::sync::OnceLock::new();

/// Installs the clock the timings read in a browser (seconds, from any
/// fixed origin; for example the page's `performance.now() / 1000`). The
/// first one installed stays.
#[cfg(target_arch = "wasm32")]
pub fn set_clock(seconds: fn() -> f64) {
    let _ = CLOCK.set(seconds);
}

impl Instant {
    /// Now.
    pub fn now() -> Instant {
        #[cfg(not(target_arch = "wasm32"))]
        return Instant(std::time::Instant::now());
        #[cfg(target_arch = "wasm32")]
        return Instant(CLOCK.get().map_or(0.0, |seconds| seconds()));
    }

    /// Time from `earlier` to this moment (zero if `earlier` is later).
    pub fn duration_since(&self, earlier: Instant) -> Duration {
        #[cfg(not(target_arch = "wasm32"))]
        return self.0.saturating_duration_since(earlier.0);
        #[cfg(target_arch = "wasm32")]
        return Duration::from_secs_f64((self.0 - earlier.0).max(0.0));
    }

    /// Time since this moment.
    pub fn elapsed(&self) -> Duration {
        Instant::now().duration_since(*self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_moves_forward_and_never_backward() {
        let a = Instant::now();
        std::thread::sleep(Duration::from_millis(5));
        let b = Instant::now();
        assert!(b.duration_since(a) >= Duration::from_millis(5));
        assert_eq!(a.duration_since(b), Duration::ZERO);
        assert!(a.elapsed() >= b.duration_since(a));
    }
}
