//! The fixed-step clock: how many physics steps each frame runs.
//!
//! Frames arrive at whatever rate the display manages; the physics always
//! steps by the same `dt`. An accumulator carries the remainder between
//! frames, and a cap on catch-up steps keeps a slow frame from triggering an
//! ever-growing backlog (the simulation slows down instead of freezing).
//!
//! The frame budget: physics may take no more of a frame than the rest of
//! the previous frame took (drawing, presenting, the panels), so it gets at
//! most half of each frame; steps beyond the budget are dropped, not owed,
//! and [`RealtimeMeter`] measures how fast simulated time then goes.

/// Time-scale presets, slowest first.
pub const TIME_SCALES: [f64; 9] = [0.01, 0.03, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0];

/// Turns frame durations into whole physics steps.
#[derive(Clone, Debug, PartialEq)]
pub struct FixedStepClock {
    /// Physics step (s).
    pub dt: f64,
    /// Most steps one frame may run.
    pub max_steps_per_frame: u32,
    /// Whether time stands still.
    pub paused: bool,
    time_scale_index: usize,
    accumulator: f64,
    pending_single_steps: u32,
}

impl FixedStepClock {
    /// A running clock at real time.
    pub fn new(dt: f64, max_steps_per_frame: u32) -> Self {
        Self {
            dt,
            max_steps_per_frame,
            paused: false,
            time_scale_index: TIME_SCALES.iter().position(|&s| s == 1.0).unwrap_or(0),
            accumulator: 0.0,
            pending_single_steps: 0,
        }
    }

    /// Simulated seconds per real second.
    pub fn time_scale(&self) -> f64 {
        TIME_SCALES[self.time_scale_index]
    }

    /// Which of [`TIME_SCALES`] is in use.
    pub fn time_scale_index(&self) -> usize {
        self.time_scale_index
    }

    /// Uses preset `index` of [`TIME_SCALES`] (the last if beyond).
    pub fn set_time_scale_index(&mut self, index: usize) {
        self.time_scale_index = index.min(TIME_SCALES.len() - 1);
    }

    /// Next slower (`-1`) or faster (`+1`) preset.
    pub fn change_time_scale(&mut self, direction: i32) {
        let last = TIME_SCALES.len() - 1;
        self.time_scale_index = match direction.signum() {
            -1 => self.time_scale_index.saturating_sub(1),
            1 => (self.time_scale_index + 1).min(last),
            _ => self.time_scale_index,
        };
    }

    /// Pauses and queues exactly one step for the next frame.
    pub fn single_step(&mut self) {
        self.paused = true;
        self.pending_single_steps += 1;
    }

    /// Steps to run for a frame that lasted `frame_seconds` of real time.
    pub fn advance(&mut self, frame_seconds: f64) -> u32 {
        if self.paused {
            self.accumulator = 0.0;
            return std::mem::take(&mut self.pending_single_steps);
        }
        // A stalled frame (window dragged, debugger) must not come back as
        // minutes of simulation.
        let real = if frame_seconds.is_finite() {
            frame_seconds.clamp(0.0, 0.25)
        } else {
            0.0
        };
        self.accumulator += real * self.time_scale();
        let due = (self.accumulator / self.dt).floor();
        if due > f64::from(self.max_steps_per_frame) {
            self.accumulator = 0.0; // drop the backlog: run slower, not later
            self.max_steps_per_frame
        } else {
            self.accumulator -= due * self.dt;
            due as u32
        }
    }
}

/// The wall-clock time (s) the physics of a frame may take: what the rest of
/// the previous frame took. A frame always runs at least one due step.
pub fn physics_budget(previous_frame: f64, previous_physics: f64) -> f64 {
    (previous_frame - previous_physics).max(0.0)
}

/// Seconds of wall clock the ratio of simulated to real time covers: two
/// autosave periods (every 5 s by default), so the window always holds two
/// autosaves' pauses. With six seconds it held one or two, and at 10⁵ discs
/// the figure shown swung by 15–40 % around the true rate as they came and
/// went.
pub const METER_WINDOW: f64 = 10.0;

/// Simulated seconds per real second over the last ten seconds of running,
/// from the wall clock and the simulated time at the end of each frame. A
/// pause, a rewind or a jump back in time starts the measurement afresh.
#[derive(Clone, Debug, Default)]
pub struct RealtimeMeter {
    /// (wall clock, simulated time) at the end of recent frames.
    frames: std::collections::VecDeque<(f64, f64)>,
}

impl RealtimeMeter {
    /// Adds the end of a frame: the wall clock `now` and the simulated time
    /// (s); `running` is false for a paused frame.
    pub fn push(&mut self, now: f64, simulated: f64, running: bool) {
        let jumped_back = self.frames.back().is_some_and(|&(_, s)| simulated < s);
        if !running || jumped_back || !(now.is_finite() && simulated.is_finite()) {
            self.frames.clear();
            if !running {
                return;
            }
        }
        self.frames.push_back((now, simulated));
        while self.frames.len() > 2 && now - self.frames[1].0 >= METER_WINDOW {
            self.frames.pop_front();
        }
    }

    /// Forgets the past (the time scale changed, a scene opened).
    pub fn clear(&mut self) {
        self.frames.clear();
    }

    /// The ratio, once half a second of running has been seen.
    pub fn ratio(&self) -> Option<f64> {
        let (&(t0, s0), &(t1, s1)) = (self.frames.front()?, self.frames.back()?);
        (t1 - t0 >= 0.5).then(|| (s1 - s0) / (t1 - t0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_follow_real_time_whatever_the_frame_rate() {
        for fps in [30.0, 60.0, 144.0, 1000.0] {
            let mut clock = FixedStepClock::new(1.0 / 240.0, 64);
            let steps: u32 = (0..(2.0 * fps) as usize)
                .map(|_| clock.advance(1.0 / fps))
                .sum();
            assert!(
                (steps as i64 - 480).abs() <= 1,
                "{fps} fps: {steps} steps in 2 s"
            );
        }
    }

    #[test]
    fn a_slow_frame_is_capped() {
        let mut clock = FixedStepClock::new(1.0 / 240.0, 8);
        assert_eq!(clock.advance(0.2), 8);
        assert_eq!(
            clock.advance(1.0 / 240.0 + 1e-9),
            1,
            "no backlog carried over"
        );
        assert_eq!(clock.advance(f64::NAN), 0);
    }

    #[test]
    fn the_budget_is_the_rest_of_the_previous_frame() {
        assert_eq!(physics_budget(0.5, 0.3), 0.2);
        assert_eq!(physics_budget(0.1, 0.2), 0.0);
    }

    #[test]
    fn the_meter_gives_simulated_over_real_time_of_running_frames() {
        let mut meter = RealtimeMeter::default();
        assert_eq!(meter.ratio(), None);
        let (mut now, mut sim) = (0.0, 0.0);
        for _ in 0..30 {
            now += 0.1;
            sim += 0.03;
            meter.push(now, sim, true);
        }
        assert!((meter.ratio().unwrap() - 0.3).abs() < 1e-9);
        for _ in 0..(10.0 * METER_WINDOW) as usize + 10 {
            now += 0.1;
            sim += 0.1;
            meter.push(now, sim, true);
        }
        assert!(
            (meter.ratio().unwrap() - 1.0).abs() < 1e-9,
            "only the last ten seconds count"
        );
        meter.push(now + 0.1, sim, false); // a pause starts afresh
        assert_eq!(meter.ratio(), None);
        for k in 1..=10 {
            meter.push(now + 0.1 * f64::from(k), 5.0 - f64::from(k), true); // going back
        }
        assert_eq!(meter.ratio(), None, "a jump back starts afresh");
        meter.clear();
        assert_eq!(meter.ratio(), None);
    }

    #[test]
    fn pause_stops_time_and_single_step_runs_one() {
        let mut clock = FixedStepClock::new(0.01, 100);
        clock.paused = true;
        assert_eq!(clock.advance(1.0), 0);
        clock.single_step();
        clock.single_step();
        assert_eq!(clock.advance(1.0), 2);
        assert_eq!(clock.advance(1.0), 0);
    }

    #[test]
    fn slow_motion_runs_fewer_steps() {
        let mut clock = FixedStepClock::new(0.01, 100);
        clock.change_time_scale(-1);
        clock.change_time_scale(-1);
        assert_eq!(clock.time_scale(), 0.25);
        let steps: u32 = (0..100).map(|_| clock.advance(0.01)).sum();
        assert_eq!(steps, 25);
        for _ in 0..20 {
            clock.change_time_scale(1);
        }
        assert_eq!(clock.time_scale(), 8.0);
        clock.set_time_scale_index(2);
        assert_eq!((clock.time_scale_index(), clock.time_scale()), (2, 0.1));
        clock.set_time_scale_index(99);
        assert_eq!(clock.time_scale(), 8.0, "clamped to the last preset");
    }
}
