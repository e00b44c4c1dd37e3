//! Desktop playback through ALSA, with no -dev package at build time:
//! `libasound.so.2` (on every desktop Linux; Debian's `libasound2`) is
//! loaded when sound is first wanted, with `libloading`. Without it, or
//! without a sound card, one line says so ([`Player::start_or_say`]) and
//! the sandbox goes on without sound.
//!
//! **ALSA's messages.** Before anything else, ALSA's error handler is
//! replaced by one that says nothing: opening the default device on a
//! machine without a sound card would otherwise print ALSA's own lines
//! ("ALSA lib confmisc.c:… cannot find card '0'" and so on) over the one
//! line. ALSA declares the handler variadic, `void (*)(const char *file,
//! int line, const char *function, int err, const char *fmt, ...)`, and
//! stable Rust cannot define a variadic function; [`silent`] is declared
//! with the five fixed parameters only. On x86_64 and aarch64 Linux a
//! variadic call passes the fixed arguments exactly as a plain call does,
//! and a callee that never reads the rest is unaffected by them (the
//! caller cleans up), so the usual workaround is sound there; the handler
//! reads none of its arguments anyway.
//!
//! **Playing.** The frame loop only sends each frame's clicks down a
//! channel ([`Player::play`], never blocking); a thread mixes them
//! ([`super::synth::Mixer`]) and writes 10 ms chunks of S16 mono at
//! 44.1 kHz to a device opened with 50 ms of latency, recovering from
//! underruns. Clicks keep their spacing: each batch is placed by the
//! moment it was sent plus the click's delay, [`LEAD`] ahead of the
//! device's buffer. With nothing left to play the thread sleeps on the
//! channel.
//!
//! Pure of the rest of the crate but for `super::synth`:
//! `tests/sound_playback.rs` compiles both and plays through ALSA's `null`
//! device.

use super::synth::{pcm16, Click, Mixer, SAMPLE_RATE};
use std::ffi::{c_char, c_int, c_long, c_uint, c_ulong, c_void, CStr, CString};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::{Arc, OnceLock};
use std::time::Instant;

/// The library, by its run-time name.
pub const LIBRARY: &str = "libasound.so.2";
/// The device latency asked for (µs).
pub const LATENCY_US: u32 = 50_000;
/// Samples written at a time (10 ms).
pub const CHUNK: usize = 441;
/// How far ahead of "now" a click is placed (s): the device's buffer and
/// a chunk, so that a click sent at once still lands in the future.
pub const LEAD: f64 = 0.065;

const STREAM_PLAYBACK: c_int = 0;
const FORMAT_S16_LE: c_int = 2;
const ACCESS_RW_INTERLEAVED: c_int = 3;

/// `snd_pcm_t`, opaque.
type RawPcm = c_void;
/// ALSA's error handler as declared here: its fixed parameters, without
/// the `...` (see the module's notes).
type ErrorHandler = unsafe extern "C" fn(*const c_char, c_int, *const c_char, c_int, *const c_char);

/// The error handler that says nothing.
unsafe extern "C" fn silent(
    _file: *const c_char,
    _line: c_int,
    _function: *const c_char,
    _err: c_int,
    _fmt: *const c_char,
) {
}

/// The functions used, resolved once from the library, which stays loaded.
struct Api {
    open: unsafe extern "C" fn(*mut *mut RawPcm, *const c_char, c_int, c_int) -> c_int,
    set_params:
        unsafe extern "C" fn(*mut RawPcm, c_int, c_int, c_uint, c_uint, c_int, c_uint) -> c_int,
    writei: unsafe extern "C" fn(*mut RawPcm, *const c_void, c_ulong) -> c_long,
    recover: unsafe extern "C" fn(*mut RawPcm, c_int, c_int) -> c_int,
    close: unsafe extern "C" fn(*mut RawPcm) -> c_int,
    strerror: unsafe extern "C" fn(c_int) -> *const c_char,
    _library: libloading::Library,
}

static API: OnceLock<Result<Api, String>> = OnceLock::new();

/// The library with ALSA's messages silenced, or why it cannot be loaded.
#[allow(dead_code)] // tests/sound_playback.rs
pub fn load() -> Result<(), String> {
    api().map(|_| ())
}

fn api() -> Result<&'static Api, String> {
    API.get_or_init(|| {
        // SAFETY: loading libasound runs only its initialisers; each symbol
        // is given its C prototype (the handler's as explained above).
        unsafe {
            let library = libloading::Library::new(LIBRARY).map_err(|e| e.to_string())?;
            let set_handler = *library
                .get::<unsafe extern "C" fn(Option<ErrorHandler>) -> c_int>(
                    b"snd_lib_error_set_handler\0",
                )
                .map_err(|e| e.to_string())?;
            // First, before ALSA has a chance to speak.
            set_handler(Some(silent));
            Ok(Api {
                open: *library.get(b"snd_pcm_open\0").map_err(|e| e.to_string())?,
                set_params: *library
                    .get(b"snd_pcm_set_params\0")
                    .map_err(|e| e.to_string())?,
                writei: *library
                    .get(b"snd_pcm_writei\0")
                    .map_err(|e| e.to_string())?,
                recover: *library
                    .get(b"snd_pcm_recover\0")
                    .map_err(|e| e.to_string())?,
                close: *library.get(b"snd_pcm_close\0").map_err(|e| e.to_string())?,
                strerror: *library.get(b"snd_strerror\0").map_err(|e| e.to_string())?,
                _library: library,
            })
        }
    })
    .as_ref()
    .map_err(Clone::clone)
}

impl Api {
    /// ALSA's words for error `code` (negative).
    fn error(&self, code: c_int) -> String {
        // SAFETY: snd_strerror returns a static string for any code.
        let text = unsafe { (self.strerror)(code) };
        if text.is_null() {
            return format!("error {code}"); // not words: the terminal's, from ALSA
        }
        // SAFETY: non-null, NUL-terminated, static.
        unsafe { CStr::from_ptr(text) }
            .to_string_lossy()
            .into_owned()
    }
}

/// An open playback device: S16 mono at [`SAMPLE_RATE`].
pub struct Pcm {
    api: &'static Api,
    raw: *mut RawPcm,
}

// SAFETY: the handle is used by one thread at a time (it moves to the
// player's thread); ALSA allows that.
unsafe impl Send for Pcm {}

impl Pcm {
    /// Opens `device` ("default", "null", "hw:0", …) for playback.
    pub fn open(device: &str) -> Result<Pcm, String> {
        let api = api()?;
        let name = CString::new(device).map_err(|e| e.to_string())?;
        let mut raw = std::ptr::null_mut();
        // SAFETY: a valid out-pointer and device name; blocking mode.
        let code = unsafe { (api.open)(&mut raw, name.as_ptr(), STREAM_PLAYBACK, 0) };
        if code < 0 || raw.is_null() {
            return Err(format!("{device}: {}", api.error(code)));
        }
        let pcm = Pcm { api, raw };
        // SAFETY: an open handle; S16_LE, interleaved, 1 channel, the
        // rate, resampling allowed, the latency.
        let code = unsafe {
            (api.set_params)(
                raw,
                FORMAT_S16_LE,
                ACCESS_RW_INTERLEAVED,
                1,
                SAMPLE_RATE,
                1,
                LATENCY_US,
            )
        };
        if code < 0 {
            return Err(format!("{device}: {}", api.error(code)));
        }
        Ok(pcm)
    }

    /// Writes every sample (blocking while the device's buffer is full),
    /// recovering from underruns; the frames written.
    pub fn write(&mut self, samples: &[i16]) -> Result<usize, String> {
        let mut done = 0;
        let mut failures = 0;
        while done < samples.len() {
            let rest = &samples[done..];
            // SAFETY: `rest` holds `rest.len()` frames of one channel.
            let n = unsafe { (self.api.writei)(self.raw, rest.as_ptr().cast(), rest.len() as _) };
            if n < 0 {
                failures += 1;
                // SAFETY: an open handle; silent: no message of ALSA's.
                let code = unsafe { (self.api.recover)(self.raw, n as c_int, 1) };
                if code < 0 || failures > 8 {
                    return Err(self.api.error(n as c_int));
                }
                continue;
            }
            failures = 0;
            done += n as usize;
        }
        Ok(done)
    }
}

impl Drop for Pcm {
    fn drop(&mut self) {
        // SAFETY: closed once, here.
        unsafe { (self.api.close)(self.raw) };
    }
}

/// One frame's clicks and when they were sent.
struct Batch {
    sent: Instant,
    clicks: Vec<Click>,
}

/// Plays clicks on a device from a thread of its own.
pub struct Player {
    sender: Sender<Batch>,
    /// Frames written to the device so far (the playback test reads it).
    #[allow(dead_code)]
    pub written: Arc<AtomicU64>,
}

impl Player {
    /// Opens `device` and starts the thread that plays on it.
    pub fn start(device: &str) -> Result<Player, String> {
        let pcm = Pcm::open(device)?;
        let (sender, batches) = channel();
        let written = Arc::new(AtomicU64::new(0));
        let count = Arc::clone(&written);
        std::thread::Builder::new()
            .name("impulse-sound".into())
            .spawn(move || stream(pcm, &batches, &count))
            .map_err(|e| e.to_string())?;
        Ok(Player { sender, written })
    }

    /// [`Player::start`], or the one line that says why there is no sound.
    pub fn start_or_say(device: &str) -> Option<Player> {
        Player::start(device)
            .map_err(|why| eprintln!("impulse: no sound device ({why}); sound stays off"))
            .ok()
    }

    /// Queues `clicks`, each at its delay from now (never blocks).
    pub fn play(&self, clicks: Vec<Click>) {
        if !clicks.is_empty() {
            let _ = self.sender.send(Batch {
                sent: Instant::now(),
                clicks,
            }); // a stopped thread has said why
        }
    }
}

/// Where the clicks go: a moment, and the frame written then that plays
/// [`LEAD`] after it.
struct Timeline {
    anchor: Option<(Instant, u64)>,
    /// Frames written so far.
    position: u64,
}

impl Timeline {
    /// Places a batch's clicks (by delay) in the mixer, in time with the
    /// batches before it while the stream has not stopped.
    fn place(&mut self, mixer: &mut Mixer, batch: Batch) {
        let rate = f64::from(SAMPLE_RATE);
        for click in batch.clicks {
            let (t0, p0) = *self.anchor.get_or_insert((batch.sent, self.position));
            let since = batch.sent.saturating_duration_since(t0).as_secs_f64();
            let due = since + LEAD + click.delay;
            let ahead = p0 as f64 + due * rate - self.position as f64;
            // Late (the thread was held up) or too far ahead (the device's
            // clock drifted from ours): moved, and the clicks after it keep
            // their spacing from it.
            let latest = (LEAD + click.delay + 0.05) * rate;
            let moved = ahead.clamp(0.0, latest);
            if moved != ahead {
                let p0 = (p0 as f64 + moved - ahead).max(0.0) as u64;
                self.anchor = Some((t0, p0));
            }
            mixer.add_click(&Click {
                delay: moved / rate,
                ..click
            });
        }
    }
}

/// The player's thread: mixes what comes and writes it, chunk by chunk.
fn stream(mut pcm: Pcm, batches: &Receiver<Batch>, written: &AtomicU64) {
    let mut mixer = Mixer::default();
    let mut timeline = Timeline {
        anchor: None,
        position: 0,
    };
    loop {
        if mixer.is_empty() {
            // Nothing to play: sleep until something comes (the device
            // runs dry meanwhile; the next write recovers).
            timeline.anchor = None;
            match batches.recv() {
                Ok(batch) => timeline.place(&mut mixer, batch),
                Err(_) => return,
            }
        }
        while let Ok(batch) = batches.try_recv() {
            timeline.place(&mut mixer, batch);
        }
        match pcm.write(&pcm16(&mixer.take(CHUNK))) {
            Ok(n) => timeline.position += n as u64,
            Err(why) => {
                eprintln!("impulse: sound stopped ({why})");
                return;
            }
        }
        written.store(timeline.position, Ordering::Relaxed);
    }
}
