//! The clicks, synthesised (no audio file): a short sine burst with a
//! smooth attack (no pop) and an exponential decay, faded to zero at its
//! end; a high click between discs, a lower thud on a wall. The browser
//! plays the same [`Tone`]s with Web Audio oscillators (`web/impulse.js`).
//! The mixer places clicks at sample offsets and hands out 16-bit samples.
//!
//! Pure and free of the rest of the crate: `tests/sound_playback.rs`
//! compiles it on its own.

use std::collections::VecDeque;

/// Samples a second (mono).
pub const SAMPLE_RATE: u32 = 44_100;

/// A click's sound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tone {
    /// Pitch (Hz).
    pub hz: f32,
    /// Rise from silence to the peak (s): half a cosine.
    pub attack: f32,
    /// Time constant of the decay after the peak (s).
    pub decay: f32,
    /// The whole click (s); its last [`FADE`] seconds fade to zero.
    pub seconds: f32,
}

/// Between discs: a bright click, 25 ms.
pub const DISC: Tone = Tone {
    hz: 1800.0,
    attack: 0.001,
    decay: 0.005,
    seconds: 0.025,
};

/// On a wall: a lower thud, 35 ms.
pub const WALL: Tone = Tone {
    hz: 800.0,
    attack: 0.0015,
    decay: 0.008,
    seconds: 0.035,
};

/// The fade at a click's end (s), so it stops at zero.
pub const FADE: f32 = 0.002;

/// The amplitude of the loudest click: a few may overlap below 1.
pub const PEAK: f32 = 0.6;

/// The amplitude of a click of `loudness` (0 to 1, already a log scale of
/// the impulse): its square, so the loudness range spans about 33 dB.
pub fn amplitude(loudness: f32) -> f32 {
    let l = if loudness.is_finite() {
        loudness.clamp(0.0, 1.0)
    } else {
        0.0
    };
    PEAK * l * l
}

/// One click to play: its tone, amplitude and delay (s) after now.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Click {
    pub tone: Tone,
    pub amplitude: f32,
    pub delay: f64,
}

/// The samples of one click.
pub fn click(tone: Tone, amplitude: f32) -> Vec<f32> {
    let rate = SAMPLE_RATE as f32;
    let n = (tone.seconds * rate).round() as usize;
    (0..n)
        .map(|k| {
            let t = k as f32 / rate;
            let rise = if t < tone.attack {
                0.5 - 0.5 * (std::f32::consts::PI * t / tone.attack).cos()
            } else {
                (-(t - tone.attack) / tone.decay).exp()
            };
            let left = tone.seconds - t;
            let fade = if left < FADE {
                0.5 - 0.5 * (std::f32::consts::PI * left / FADE).cos()
            } else {
                1.0
            };
            let wave = (std::f32::consts::TAU * tone.hz * t).sin();
            amplitude * rise * fade * wave
        })
        .collect()
}

/// Clicks waiting to be played, as samples from the next one to write.
#[derive(Clone, Debug, Default)]
pub struct Mixer {
    samples: VecDeque<f32>,
}

impl Mixer {
    /// Adds `samples` starting `offset` samples from now.
    pub fn add(&mut self, offset: usize, samples: &[f32]) {
        if self.samples.len() < offset + samples.len() {
            self.samples.resize(offset + samples.len(), 0.0);
        }
        for (k, s) in samples.iter().enumerate() {
            self.samples[offset + k] += s;
        }
    }

    /// Places a click at its delay from now.
    pub fn add_click(&mut self, c: &Click) {
        let offset = (c.delay.max(0.0) * f64::from(SAMPLE_RATE)).round() as usize;
        self.add(offset, &click(c.tone, c.amplitude));
    }

    /// The next `n` samples (silence where nothing waits), kept in
    /// [-1, 1].
    pub fn take(&mut self, n: usize) -> Vec<f32> {
        (0..n)
            .map(|_| self.samples.pop_front().unwrap_or(0.0).clamp(-1.0, 1.0))
            .collect()
    }

    /// Samples still waiting.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// Whether nothing waits.
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }
}

/// Samples in [-1, 1] as signed 16-bit.
pub fn pcm16(samples: &[f32]) -> Vec<i16> {
    samples
        .iter()
        .map(|s| (s.clamp(-1.0, 1.0) * f32::from(i16::MAX)).round() as i16)
        .collect()
}

/// `clicks` mixed from now until the last has ended.
#[cfg(test)]
pub fn render(clicks: &[Click]) -> Vec<f32> {
    let mut mixer = Mixer::default();
    for c in clicks {
        mixer.add_click(c);
    }
    let n = mixer.len();
    mixer.take(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn peak(samples: &[f32]) -> f32 {
        samples.iter().fold(0.0, |m, s| m.max(s.abs()))
    }

    /// Sign changes per second.
    fn crossings_per_second(samples: &[f32]) -> f32 {
        let changes = samples
            .windows(2)
            .filter(|w| (w[0] < 0.0) != (w[1] < 0.0) && w[0] != 0.0 && w[1] != 0.0)
            .count();
        changes as f32 * SAMPLE_RATE as f32 / samples.len() as f32
    }

    #[test]
    fn a_click_lasts_its_tone_and_starts_and_ends_quietly() {
        for tone in [DISC, WALL] {
            let s = click(tone, 1.0);
            let want = (tone.seconds * SAMPLE_RATE as f32).round() as usize;
            assert_eq!(s.len(), want);
            assert!(s.len() as f32 / SAMPLE_RATE as f32 <= 0.04, "short");
            // No pop: the first and last samples are near silence.
            assert!(s[0].abs() < 1e-6 && s[1].abs() < 0.02, "{:?}", &s[..2]);
            assert!(s[s.len() - 1].abs() < 1e-3);
            // It decays: the last quarter is far quieter than the first.
            let q = s.len() / 4;
            assert!(peak(&s[3 * q..]) < 0.1 * peak(&s[..q]));
        }
    }

    #[test]
    fn the_peak_follows_the_loudness() {
        let mut last = 0.0;
        for k in 1..=10 {
            let l = k as f32 / 10.0;
            let p = peak(&click(DISC, amplitude(l)));
            assert!(p > last, "{l}: {p}");
            last = p;
        }
        assert!(last <= PEAK && last > 0.9 * PEAK);
        assert_eq!(amplitude(2.0), PEAK);
        assert_eq!(amplitude(f32::NAN), 0.0);
    }

    #[test]
    fn a_wall_sounds_lower_than_a_disc() {
        let disc = crossings_per_second(&click(DISC, 1.0));
        let wall = crossings_per_second(&click(WALL, 1.0));
        // Two crossings a period.
        assert!((disc / 2.0 - DISC.hz).abs() < 0.1 * DISC.hz, "{disc}");
        assert!((wall / 2.0 - WALL.hz).abs() < 0.1 * WALL.hz, "{wall}");
        assert!(disc > 1.8 * wall);
    }

    #[test]
    fn the_mixer_places_clicks_at_their_delays_and_never_clips_beyond_one() {
        let at = |delay| Click {
            tone: DISC,
            amplitude: PEAK,
            delay,
        };
        let s = render(&[at(0.0), at(0.1)]);
        let offset = SAMPLE_RATE as usize / 10;
        assert_eq!(s.len(), offset + click(DISC, 1.0).len());
        let one = click(DISC, PEAK);
        assert_eq!(&s[..one.len()], &one[..]);
        assert_eq!(&s[offset..], &one[..]);
        assert!(s[one.len()..offset].iter().all(|&x| x == 0.0));
        // Ten loud clicks on top of each other: kept in [-1, 1].
        let pile = render(&[at(0.0); 10]);
        assert!(pile.iter().all(|x| (-1.0..=1.0).contains(x)));
        assert_eq!(peak(&pile), 1.0);
        let pcm = pcm16(&pile);
        assert!(pcm.contains(&i16::MAX) && pcm.iter().all(|&x| x >= -i16::MAX));
        // Taking more than waits gives silence.
        let mut m = Mixer::default();
        m.add_click(&at(0.0));
        assert_eq!(m.take(2000).len(), 2000);
        assert!(m.is_empty() && m.take(3) == [0.0; 3]);
    }
}
