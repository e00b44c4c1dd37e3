//! The browser build's bridge to the page (`web/impulse.js`, a miniquad
//! plugin): the state report the page and its tests read, file downloads,
//! the browser's local storage, the address's fragment for shared links,
//! and the clicks of impacts (Web Audio). Only compiled for `wasm32`; the
//! desktop has files instead.

use std::fmt;

extern "C" {
    fn impulse_report_state(ptr: *const u8, len: usize);
    fn impulse_download(name: *const u8, name_len: usize, data: *const u8, data_len: usize);
    fn impulse_storage_set(key: *const u8, key_len: usize, value: *const u8, len: usize) -> i32;
    fn impulse_storage_get(key: *const u8, key_len: usize) -> i32;
    fn impulse_storage_remove(key: *const u8, key_len: usize);
    fn impulse_fragment_get() -> i32;
    fn impulse_fragment_set(ptr: *const u8, len: usize);
    fn impulse_take(ptr: *mut u8, len: usize);
    fn impulse_now() -> f64;
    fn impulse_report_fingerprints(ptr: *const u8, len: usize);
    fn impulse_click(hz: f32, amplitude: f32, attack: f32, decay: f32, seconds: f32, delay: f64);
    fn impulse_browser_language() -> i32;
    fn impulse_mirror(ptr: *const u8, len: usize);
    fn impulse_say(ptr: *const u8, len: usize);
    fn impulse_world_keys(on: i32);
    fn impulse_set_page_language(
        tag: *const u8,
        tag_len: usize,
        title: *const u8,
        title_len: usize,
    );
}

/// Builds (or updates) the page's accessible mirror from its description
/// (`model::mirror::Mirror` as JSON).
pub fn set_mirror(json: &str) {
    // SAFETY: the page reads the string during the call.
    unsafe { impulse_mirror(json.as_ptr(), json.len()) }
}

/// A line for the page's `aria-live` region.
pub fn say(line: &str) {
    // SAFETY: the page reads the string during the call.
    unsafe { impulse_say(line.as_ptr(), line.len()) }
}

/// Whether the world has the keys (no control of the canvas has them):
/// then Shift+Tab leaves the canvas for the mirror.
pub fn set_world_keys(on: bool) {
    // SAFETY: a number.
    unsafe { impulse_world_keys(i32::from(on)) }
}

thread_local! {
    /// The mirror's controls used since the last frame: (list, index).
    static MIRROR_USES: std::cell::RefCell<Vec<(u32, u32)>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// The page's mirror used control `index` of `list` (0 buttons, 1 presets,
/// 2 languages); the window reads it next frame.
#[no_mangle]
pub extern "C" fn impulse_mirror_use(list: u32, index: u32) {
    MIRROR_USES.with(|u| u.borrow_mut().push((list, index)));
}

/// The mirror's controls used since the last call.
pub fn take_mirror_uses() -> Vec<(u32, u32)> {
    MIRROR_USES.with(|u| std::mem::take(&mut *u.borrow_mut()))
}

/// The browser's language (`navigator.language`, "de-DE").
pub fn browser_language() -> Option<String> {
    // SAFETY: no arguments; the page sets the bytes aside for `take`.
    take(unsafe { impulse_browser_language() })
}

/// Declares the page's language (`<html lang>`) and sets its title, in it.
pub fn set_page_language(tag: &str, title: &str) {
    // SAFETY: the page reads both strings during the call.
    unsafe { impulse_set_page_language(tag.as_ptr(), tag.len(), title.as_ptr(), title.len()) }
}

/// Seconds on the page's clock (`performance.now()`), for the core's stage
/// timings and the frame times.
pub fn now() -> f64 {
    // SAFETY: no arguments, a number back.
    unsafe { impulse_now() }
}

/// Plays a click through Web Audio, `delay` seconds from now: a sine of
/// `hz` rising over `attack` seconds to `amplitude`, decaying with time
/// constant `decay`, silent after `seconds` (the desktop's synthesis,
/// `app::audio::synth`). Silent until the page has had a click or a key
/// (browsers start sound only after a gesture).
pub fn click(hz: f32, amplitude: f32, attack: f32, decay: f32, seconds: f32, delay: f64) {
    // SAFETY: numbers only.
    unsafe { impulse_click(hz, amplitude, attack, decay, seconds, delay) }
}

/// Computes the physics fingerprints ([`impulse::fingerprint`]) and puts
/// them where the page can read them (`window.impulseFingerprints`); the
/// browser test calls it and compares them with the desktop's.
#[no_mangle]
pub extern "C" fn impulse_fingerprints() {
    let json = impulse::fingerprint::fingerprints_json();
    // SAFETY: the page reads `len` bytes of our memory during the call.
    unsafe { impulse_report_fingerprints(json.as_ptr(), json.len()) }
}

/// The plugin's version, checked by the page's loader against its own.
#[no_mangle]
pub extern "C" fn impulse_crate_version() -> u32 {
    1
}

/// Bytes the page has set aside for us (`len` from the call that did so).
fn take(len: i32) -> Option<String> {
    let len = usize::try_from(len).ok()?;
    let mut bytes = vec![0u8; len];
    // SAFETY: the page copies exactly `len` bytes into the buffer we own.
    unsafe { impulse_take(bytes.as_mut_ptr(), len) };
    String::from_utf8(bytes).ok()
}

/// Puts the app's state (JSON) where the page can read it
/// (`window.impulseState`).
pub fn report_state(json: &str) {
    // SAFETY: the page reads `len` bytes of our memory during the call.
    unsafe { impulse_report_state(json.as_ptr(), json.len()) }
}

/// Offers `data` to the user as a downloaded file named `name`.
pub fn download(name: &str, data: &[u8]) {
    // SAFETY: as above; the page copies the bytes before returning.
    unsafe { impulse_download(name.as_ptr(), name.len(), data.as_ptr(), data.len()) }
}

/// Why the browser would not keep something.
#[derive(Debug)]
pub struct StorageFull;

impl fmt::Display for StorageFull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("the browser's storage for this page is full or turned off")
    }
}

impl std::error::Error for StorageFull {}

/// Keeps `value` under `key` in the browser's local storage.
pub fn storage_set(key: &str, value: &str) -> Result<(), StorageFull> {
    // SAFETY: the page reads both strings during the call.
    let ok = unsafe { impulse_storage_set(key.as_ptr(), key.len(), value.as_ptr(), value.len()) };
    if ok == 1 {
        Ok(())
    } else {
        Err(StorageFull)
    }
}

/// What local storage holds under `key`.
pub fn storage_get(key: &str) -> Option<String> {
    // SAFETY: the page reads the key during the call.
    take(unsafe { impulse_storage_get(key.as_ptr(), key.len()) })
}

/// Forgets `key` in local storage.
pub fn storage_remove(key: &str) {
    // SAFETY: as above.
    unsafe { impulse_storage_remove(key.as_ptr(), key.len()) }
}

/// The page address's fragment, without the `#`.
pub fn fragment() -> String {
    // SAFETY: no arguments; the page sets the bytes aside for `take`.
    take(unsafe { impulse_fragment_get() }).unwrap_or_default()
}

/// Replaces the page address's fragment (no new history entry).
pub fn set_fragment(value: &str) {
    // SAFETY: the page reads the string during the call.
    unsafe { impulse_fragment_set(value.as_ptr(), value.len()) }
}

thread_local! {
    /// The sandbox as the page should keep it, refreshed by the window:
    /// (local storage key, scene text).
    static LATEST: std::cell::RefCell<Option<(String, String)>> =
        const { std::cell::RefCell::new(None) };
}

/// Sets what [`impulse_keep_now`] writes: the sandbox now, under `key`;
/// `None` when nothing is worth keeping.
pub fn keep_latest(latest: Option<(String, String)>) {
    LATEST.with(|l| *l.borrow_mut() = latest);
}

/// Called by the page when it is hidden or left (`visibilitychange`,
/// `pagehide`): writes the latest sandbox into local storage at once, so a
/// reload or a return reopens it as it was.
#[no_mangle]
pub extern "C" fn impulse_keep_now() {
    LATEST.with(|l| {
        if let Some((key, text)) = l.borrow_mut().take() {
            let _ = storage_set(&key, &text); // a full storage was reported by autosave
        }
    });
}
