//! Where a frame's time goes: wall-clock time per frame, split into physics
//! steps, building the drawing (CPU) and presenting it (the GPU's work and
//! the buffer swap, inside `next_frame`). Kept for the HUD-free measurements
//! of `--frame-stats FILE` (a CSV row per frame) and for the state dump.

use serde::Serialize;

/// Recent frames the dump's medians cover.
const RECENT: usize = 240;

/// One frame's timings (ms) and what was drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct FrameTimes {
    /// Frame number.
    pub frame: u64,
    /// Discs in the world.
    pub discs: usize,
    /// Overlays on: velocity arrows, momentum arrows, readouts ("off",
    /// "selected", "all").
    pub velocity: bool,
    /// Momentum arrows on.
    pub momentum: bool,
    /// Readout scope.
    pub readouts: &'static str,
    /// Physics steps this frame.
    pub steps: u32,
    /// From the start of this frame to the start of the next.
    pub frame_ms: f64,
    /// Physics steps.
    pub step_ms: f64,
    /// Building the frame's drawing on the CPU.
    pub draw_ms: f64,
    /// `next_frame`: uploading and rendering the batches, the UI, the swap.
    pub present_ms: f64,
}

/// Medians over recent frames, for the state dump.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct TimingSummary {
    /// Frames the medians cover.
    pub frames: usize,
    /// Median frame time (ms).
    pub frame_ms: f64,
    /// Median physics time per frame (ms).
    pub step_ms: f64,
    /// Median drawing time per frame (ms).
    pub draw_ms: f64,
    /// Median present time per frame (ms).
    pub present_ms: f64,
}

/// Every frame's timings when `--frame-stats` asks for them, else only the
/// recent ones.
#[derive(Debug, Default)]
pub struct FrameStats {
    /// Keep every frame (for the CSV file), not only the recent ones.
    pub keep_all: bool,
    frames: Vec<FrameTimes>,
}

impl FrameStats {
    /// Empty; `keep_all` keeps every frame, not only the recent ones.
    pub fn new(keep_all: bool) -> Self {
        FrameStats {
            keep_all,
            frames: Vec::new(),
        }
    }

    /// Adds a finished frame.
    pub fn push(&mut self, times: FrameTimes) {
        if !self.keep_all && self.frames.len() >= 2 * RECENT {
            self.frames.drain(..RECENT);
        }
        self.frames.push(times);
    }

    /// Medians over the last [`RECENT`] frames.
    pub fn recent(&self) -> TimingSummary {
        let start = self.frames.len().saturating_sub(RECENT);
        summarize(&self.frames[start..])
    }

    /// Every kept frame as CSV, a header first.
    pub fn csv(&self) -> String {
        let mut out = String::from(
            "frame,discs,velocity,momentum,readouts,steps,frame_ms,step_ms,draw_ms,present_ms\n",
        );
        for f in &self.frames {
            out.push_str(&format!(
                "{},{},{},{},{},{},{:.4},{:.4},{:.4},{:.4}\n",
                f.frame,
                f.discs,
                u8::from(f.velocity),
                u8::from(f.momentum),
                f.readouts,
                f.steps,
                f.frame_ms,
                f.step_ms,
                f.draw_ms,
                f.present_ms
            ));
        }
        out
    }

    /// One line: medians over every kept frame.
    pub fn summary_line(&self) -> String {
        let s = summarize(&self.frames);
        format!(
            "{} frames, median frame {:.2} ms (steps {:.2}, draw {:.2}, present {:.2})",
            s.frames, s.frame_ms, s.step_ms, s.draw_ms, s.present_ms
        )
    }
}

/// Milliseconds from `start` to `end`.
pub fn ms_since(start: impulse::clock::Instant, end: impulse::clock::Instant) -> f64 {
    end.duration_since(start).as_secs_f64() * 1e3
}

/// Medians of each column.
pub fn summarize(frames: &[FrameTimes]) -> TimingSummary {
    let column = |f: fn(&FrameTimes) -> f64| median(frames.iter().map(f).collect());
    TimingSummary {
        frames: frames.len(),
        frame_ms: column(|f| f.frame_ms),
        step_ms: column(|f| f.step_ms),
        draw_ms: column(|f| f.draw_ms),
        present_ms: column(|f| f.present_ms),
    }
}

/// The median (the mean of the middle two for an even count); 0 when empty.
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(k: u64, ms: f64) -> FrameTimes {
        FrameTimes {
            frame: k,
            frame_ms: ms,
            draw_ms: ms / 2.0,
            readouts: "off",
            ..Default::default()
        }
    }

    #[test]
    fn medians_ignore_outliers() {
        assert_eq!(median(vec![]), 0.0);
        assert_eq!(median(vec![3.0, 1.0, 100.0]), 3.0);
        assert_eq!(median(vec![4.0, 1.0, 2.0, 100.0]), 3.0);
        let frames: Vec<_> = [10.0, 11.0, 500.0].iter().map(|&ms| frame(0, ms)).collect();
        let s = summarize(&frames);
        assert_eq!((s.frames, s.frame_ms, s.draw_ms), (3, 11.0, 5.5));
    }

    #[test]
    fn only_recent_frames_are_kept_unless_asked() {
        let mut stats = FrameStats::default();
        for k in 0..1000 {
            stats.push(frame(k, k as f64));
        }
        assert!(stats.frames.len() <= 2 * RECENT);
        assert_eq!(stats.recent().frames, RECENT);
        assert_eq!(stats.recent().frame_ms, 879.5, "the last 240: 760..=999");
        let mut all = FrameStats::new(true);
        for k in 0..1000 {
            all.push(frame(k, 1.0));
        }
        assert_eq!(all.csv().lines().count(), 1001, "a header and every frame");
        assert!(all
            .csv()
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("0,0,0,0,off,0,1.0000"));
    }
}
