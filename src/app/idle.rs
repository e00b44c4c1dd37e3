//! An idle window costs nothing: when nothing moves and no input arrives,
//! the window stops drawing until the next input or timer.
//!
//! The window runs miniquad's blocking event loop: a frame is drawn only
//! when asked for. Input asks (macroquad's update triggers); a frame that
//! has something to show asks for the next one ([`Idle::frame_done`]). For
//! [`GRACE`] seconds after the last change or input every frame is drawn,
//! so panels finish their animations and tooltips appear. After that the
//! window sleeps, and a waker thread draws one frame a second (the clock
//! and the state dump stay current, autosave and `--exit-after` happen on
//! time) or sooner when `--exit-after` is due.
//!
//! The waker cannot ask miniquad for a frame itself (its event loop takes
//! the display lock without waiting, and would panic if another thread held
//! it). It sends the window an X event instead, a pointer motion to where
//! the pointer already is (asked of the server just before, so a press or
//! move since the last frame is not undone), which macroquad answers with a
//! frame on the main thread. It finds this process's window through the
//! X-Resource extension. Where that is missing (no X server, no such
//! extension, the browser), the window draws every frame as before.
//!
//! A second thread watches keys and button releases on its own connection
//! and nudges the window until a frame has seen them. miniquad's blocking
//! loop reads one event more than it has queued, so a key that arrives while
//! a frame is drawn (press and release both queued) would otherwise wait for
//! the next timer frame, up to a second.

use super::model::gesture::Gesture;
use glam::DVec2;
use macroquad::prelude::*;

/// Seconds of frames after the last change or input.
pub const GRACE: f64 = 1.0;
/// Seconds between frames while idle.
pub const IDLE_FRAME: f64 = 1.0;

/// When the window draws its next frame.
pub struct Idle {
    /// The last time something changed or input arrived (s, window clock).
    last_busy: f64,
    waker: Option<waker::Waker>,
    /// Frames drawn while idle (for the state dump).
    pub idle_frames: u64,
    /// The pointer at the end of the last frame.
    mouse: (f32, f32),
}

impl Idle {
    /// Starts the waker (on X11); `class` is the window's WM_CLASS.
    pub fn new(class: &str) -> Self {
        Idle {
            last_busy: 0.0,
            waker: waker::Waker::start(class),
            idle_frames: 0,
            mouse: (f32::NAN, f32::NAN),
        }
    }

    /// Whether a waker runs, so the window may sleep between frames.
    #[cfg_attr(target_arch = "wasm32", allow(dead_code))]
    pub fn wakes(&self) -> bool {
        self.waker.is_some()
    }

    /// Whether the window sleeps between frames now.
    pub fn sleeping(&self) -> bool {
        self.waker.as_ref().is_some_and(|w| w.ready()) && get_time() - self.last_busy >= GRACE
    }

    /// Called at the end of each frame: `busy` if something moved or
    /// changed on screen this frame; `mouse` is where the pointer is (a
    /// move keeps the window awake; the waker's event moves it to where the
    /// X server says it is, or here if the server does not say); `due` is
    /// the window-clock time something must happen by (`--exit-after`), if
    /// any.
    pub fn frame_done(&mut self, busy: bool, mouse: (f32, f32), due: Option<f64>) {
        let now = get_time();
        let moved = mouse != self.mouse;
        self.mouse = mouse;
        if busy || moved || self.waker.is_none() {
            self.last_busy = now;
        }
        if let Some(waker) = &self.waker {
            waker.frame_drawn();
        }
        match &self.waker {
            Some(waker) if waker.ready() && now - self.last_busy >= GRACE => {
                self.idle_frames += 1;
                let mut wait = IDLE_FRAME;
                if let Some(due) = due {
                    wait = wait.min((due - now).max(0.0));
                }
                let scale = miniquad::window::dpi_scale();
                waker.wake_in(wait, (mouse.0 * scale, mouse.1 * scale));
            }
            Some(_) => macroquad::miniquad::window::schedule_update(),
            None => {}
        }
    }
}

/// Whether frame `frame` of the sandbox `m` showed a change or took input,
/// so the next one follows at once (see this module; it also notices the
/// pointer moving): discs moving or turning, a button or key held, a
/// gesture or a message on screen. (egui's own repaint requests are not
/// asked: every input event makes one, the idle timer's too. Its animations
/// end within the grace period after the input that started them.)
pub fn busy(m: &super::model::Sandbox, was_running: bool, frame: u64) -> bool {
    {
        let moving = (was_running || !m.clock.paused)
            && m.world
                .particles
                .iter()
                .any(|p| p.vel != DVec2::ZERO || p.spin != 0.0);
        let input = mouse_wheel() != (0.0, 0.0)
            || !get_keys_down().is_empty()
            || [MouseButton::Left, MouseButton::Right, MouseButton::Middle]
                .into_iter()
                .any(is_mouse_button_down)
            || !touches().is_empty();
        moving
            || input
            || !matches!(m.pointer.gesture, Gesture::Idle)
            || m.message().is_some()
            || frame < 2
    }
}

#[cfg(target_os = "linux")]
mod waker {
    use super::IDLE_FRAME;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::{Arc, Condvar, Mutex};
    use std::time::Duration;
    use x11rb::connection::Connection;
    use x11rb::protocol::res::{ClientIdMask, ClientIdSpec, ConnectionExt as _};
    use x11rb::protocol::xproto::{
        AtomEnum, ChangeWindowAttributesAux, ConnectionExt as _, EventMask, MotionNotifyEvent,
        Window, MOTION_NOTIFY_EVENT,
    };
    use x11rb::protocol::Event;

    /// A wake-up asked for: when, and where the pointer is.
    type Alarm = Option<(std::time::Instant, (f32, f32))>;

    /// The thread that wakes the window.
    pub struct Waker {
        alarm: Arc<(Mutex<Alarm>, Condvar)>,
        /// This process's window, once found.
        window: Arc<Mutex<Option<Window>>>,
        /// Frames drawn so far (the input watcher waits for them).
        drawn: Arc<AtomicU64>,
    }

    /// How often the input watcher nudges until a frame has seen the input.
    const RETRY: Duration = Duration::from_millis(25);

    impl Waker {
        /// A waker if an X server answers (until it finds the window, or if
        /// it never does, the window draws every frame).
        pub fn start(class: &str) -> Option<Waker> {
            let (conn, screen) = x11rb::connect(None).ok()?;
            let root = conn.setup().roots.get(screen)?.root;
            let alarm: Arc<(Mutex<Alarm>, Condvar)> = Arc::default();
            let window = Arc::new(Mutex::new(None));
            let drawn = Arc::new(AtomicU64::new(0));
            let (a, w, d) = (alarm.clone(), window.clone(), drawn.clone());
            let class = class.to_string();
            std::thread::Builder::new()
                .name("idle waker".into())
                .spawn(move || run(conn, root, &class, &a, &w, d))
                .ok()?;
            Some(Waker {
                alarm,
                window,
                drawn,
            })
        }

        /// Whether the window was found (until then every frame is drawn).
        pub fn ready(&self) -> bool {
            self.window.lock().is_ok_and(|w| w.is_some())
        }

        /// Counts a frame drawn.
        pub fn frame_drawn(&self) {
            self.drawn.fetch_add(1, Ordering::Release);
        }

        /// Draws a frame in `seconds`; `mouse` (window pixels) is where the
        /// pointer was last seen.
        pub fn wake_in(&self, seconds: f64, mouse: (f32, f32)) {
            let at = std::time::Instant::now() + std::time::Duration::from_secs_f64(seconds);
            let (lock, signal) = &*self.alarm;
            if let Ok(mut alarm) = lock.lock() {
                *alarm = Some((at, mouse));
                signal.notify_one();
            }
        }
    }

    fn run(
        conn: x11rb::rust_connection::RustConnection,
        root: Window,
        class: &str,
        alarm: &(Mutex<Alarm>, Condvar),
        window: &Mutex<Option<Window>>,
        drawn: Arc<AtomicU64>,
    ) {
        // The window appears once miniquad has made it.
        let mine = loop {
            match own_window(&conn, root, class) {
                Some(w) => break w,
                None => std::thread::sleep(std::time::Duration::from_millis(100)),
            }
        };
        if let Ok(mut w) = window.lock() {
            *w = Some(mine);
        }
        let watched = drawn.clone();
        let _ = std::thread::Builder::new()
            .name("idle input watcher".into())
            .spawn(move || watch_input(mine, &watched));
        let (lock, signal) = alarm;
        let Ok(mut guard) = lock.lock() else { return };
        loop {
            match *guard {
                None => guard = signal.wait(guard).unwrap_or_else(|e| e.into_inner()),
                Some((at, mouse)) => {
                    let now = std::time::Instant::now();
                    if now < at {
                        guard = signal
                            .wait_timeout(guard, at - now)
                            .map(|(g, _)| g)
                            .unwrap_or_else(|e| e.into_inner().0);
                        continue;
                    }
                    *guard = None;
                    let seen = drawn.load(Ordering::Acquire);
                    drop(guard);
                    if wake(&conn, mine, mouse, &drawn, seen).is_err() {
                        return; // the display is gone: the window closes too
                    }
                    guard = match lock.lock() {
                        Ok(g) => g,
                        Err(_) => return,
                    };
                }
            }
        }
    }

    /// Nudges `window` until a frame is drawn after `seen` frames, every
    /// [`RETRY`], for [`IDLE_FRAME`] at most. One nudge may not be enough:
    /// one read in the batch of a frame being drawn is lost (see
    /// `watch_input`), and a window asleep asks for no other wake-up. (A
    /// review on a loaded machine saw 2 of 9 windows started at once with
    /// `--exit-after` never close; not seen again here, before or after.)
    fn wake(
        conn: &impl Connection,
        window: Window,
        mouse: (f32, f32),
        drawn: &AtomicU64,
        seen: u64,
    ) -> Result<(), ()> {
        let since = std::time::Instant::now();
        loop {
            nudge(conn, window, mouse)?;
            std::thread::sleep(RETRY);
            if drawn.load(Ordering::Acquire) > seen || since.elapsed().as_secs_f64() > IDLE_FRAME {
                return Ok(());
            }
        }
    }

    /// The top-level window of this process with WM_CLASS `class`: the
    /// X-Resource extension names the process that made each window.
    fn own_window(conn: &impl Connection, root: Window, class: &str) -> Option<Window> {
        let pid = std::process::id();
        let tree = conn.query_tree(root).ok()?.reply().ok()?;
        tree.children.into_iter().find(|&w| {
            let named = conn
                .get_property(false, w, AtomEnum::WM_CLASS, AtomEnum::STRING, 0, 64)
                .ok()
                .and_then(|c| c.reply().ok())
                .is_some_and(|p| p.value.split(|&b| b == 0).any(|s| s == class.as_bytes()));
            named
                && conn
                    .res_query_client_ids(&[ClientIdSpec {
                        client: w,
                        mask: ClientIdMask::LOCAL_CLIENT_PID,
                    }])
                    .ok()
                    .and_then(|c| c.reply().ok())
                    .is_some_and(|r| r.ids.iter().any(|id| id.value.first() == Some(&pid)))
        })
    }

    /// Makes sure a frame follows each key press or release and button
    /// release on `window` (ButtonPress belongs to one client only, miniquad).
    /// Input that arrives while a frame is drawn is read by miniquad in one
    /// batch with everything else queued, and a nudge sent at once would be
    /// in that batch too; so after the input it nudges every [`RETRY`] until
    /// two frames have ended (the one being drawn when the input came, and
    /// one begun after it), or [`IDLE_FRAME`] has passed. Returns when the
    /// display or the window is gone.
    fn watch_input(window: Window, drawn: &AtomicU64) {
        let Ok((conn, _)) = x11rb::connect(None) else {
            return;
        };
        let mask = EventMask::KEY_PRESS | EventMask::KEY_RELEASE | EventMask::BUTTON_RELEASE;
        let selected = conn
            .change_window_attributes(window, &ChangeWindowAttributesAux::new().event_mask(mask))
            .ok()
            .and_then(|c| c.check().ok());
        if selected.is_none() {
            return;
        }
        let pointer = |event: &Event| match event {
            Event::KeyPress(e) | Event::KeyRelease(e) => Some((e.event_x, e.event_y)),
            Event::ButtonRelease(e) => Some((e.event_x, e.event_y)),
            _ => None,
        };
        while let Ok(event) = conn.wait_for_event() {
            let Some(mut at) = pointer(&event) else {
                continue;
            };
            let (seen, since) = (drawn.load(Ordering::Acquire), std::time::Instant::now());
            loop {
                if nudge(&conn, window, (at.0 as f32, at.1 as f32)).is_err() {
                    return;
                }
                std::thread::sleep(RETRY);
                while let Ok(Some(later)) = conn.poll_for_event() {
                    at = pointer(&later).unwrap_or(at);
                }
                if drawn.load(Ordering::Acquire) >= seen + 2
                    || since.elapsed().as_secs_f64() > IDLE_FRAME
                {
                    break;
                }
            }
        }
    }

    /// Sends `window` a pointer motion to where the pointer is now. The
    /// server is asked just before: a press or a move that reached the
    /// window since `mouse` was noted must not be followed by a motion back
    /// to `mouse` (the frame would read the press there). `mouse` (window
    /// pixels) is used only if the server does not answer.
    fn nudge(conn: &impl Connection, window: Window, mouse: (f32, f32)) -> Result<(), ()> {
        let (x, y) = match conn.query_pointer(window).ok().and_then(|c| c.reply().ok()) {
            Some(p) if p.same_screen => (p.win_x, p.win_y),
            _ => (mouse.0.round() as i16, mouse.1.round() as i16),
        };
        let event = MotionNotifyEvent {
            response_type: MOTION_NOTIFY_EVENT,
            detail: 0.into(),
            sequence: 0,
            time: x11rb::CURRENT_TIME,
            root: window,
            event: window,
            child: x11rb::NONE,
            root_x: x,
            root_y: y,
            event_x: x,
            event_y: y,
            state: 0u16.into(),
            same_screen: true,
        };
        conn.send_event(false, window, EventMask::NO_EVENT, event)
            .map_err(|_| ())?;
        conn.flush().map_err(|_| ())
    }
}

#[cfg(not(target_os = "linux"))]
mod waker {
    /// No waker: every frame is drawn.
    pub struct Waker;

    impl Waker {
        pub fn start(_class: &str) -> Option<Waker> {
            None
        }
        pub fn ready(&self) -> bool {
            false
        }
        pub fn wake_in(&self, _seconds: f64, _mouse: (f32, f32)) {}
        pub fn frame_drawn(&self) {}
    }
}
