//! Can a window open here? Checked before macroquad tries (and panics).
//!
//! On Linux the window needs an X server (or Wayland). Without one the binary
//! prints one line naming the headless commands instead of a backtrace; a
//! panic hook catches what the probe cannot see (a missing libGL, say) until
//! the first frame is on screen. Once it is, the surface's samples per pixel
//! are asked of OpenGL (the state dump reports them).

use std::sync::atomic::{AtomicBool, Ordering};

/// The headless commands, named when no window can open.
pub const HEADLESS_HINT: &str =
    "the headless command still works: `impulse run SCENE.toml --time T` (see `impulse --help`)";

static WINDOW_OPEN: AtomicBool = AtomicBool::new(false);

/// Why no window can open here, if that can be told in advance.
pub fn problem() -> Option<String> {
    if cfg!(not(target_os = "linux")) {
        return None;
    }
    let wayland = std::env::var_os("WAYLAND_DISPLAY").is_some_and(|v| !v.is_empty());
    match std::env::var("DISPLAY") {
        Ok(display) if !display.is_empty() => x_server_problem(&display),
        _ if wayland => None,
        _ => Some("no display to open a window on (DISPLAY is not set)".into()),
    }
}

/// Tries to reach the X server named by `$DISPLAY` (`[host]:N[.S]`).
fn x_server_problem(display: &str) -> Option<String> {
    let unreachable = || Some(format!("no X server answers at DISPLAY={display}"));
    let Some((host, rest)) = display.rsplit_once(':') else {
        return unreachable();
    };
    let Ok(number) = rest.split('.').next().unwrap_or("").parse::<u16>() else {
        return unreachable();
    };
    let reachable = if host.is_empty() || host == "unix" || host.starts_with('/') {
        local_socket_answers(number)
    } else {
        use std::net::ToSocketAddrs;
        let port = 6000u16.saturating_add(number);
        (host, port)
            .to_socket_addrs()
            .ok()
            .into_iter()
            .flatten()
            .any(|addr| {
                std::net::TcpStream::connect_timeout(&addr, std::time::Duration::from_secs(1))
                    .is_ok()
            })
    };
    if reachable {
        None
    } else {
        unreachable()
    }
}

#[cfg(target_os = "linux")]
fn local_socket_answers(number: u16) -> bool {
    use std::os::linux::net::SocketAddrExt;
    use std::os::unix::net::{SocketAddr, UnixStream};
    let path = format!("/tmp/.X11-unix/X{number}");
    UnixStream::connect(&path).is_ok()
        || SocketAddr::from_abstract_name(path.as_bytes())
            .and_then(|addr| UnixStream::connect_addr(&addr))
            .is_ok()
}

#[cfg(not(target_os = "linux"))]
fn local_socket_answers(_number: u16) -> bool {
    true
}

/// Until [`mark_open`] is called, a panic (from the windowing library failing
/// to start) is reported as one line and exit code 1.
pub fn guard_window_start() {
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if WINDOW_OPEN.load(Ordering::SeqCst) {
            default_hook(info);
        } else {
            let reason = info
                .payload()
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| info.payload().downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown error".into());
            eprintln!("impulse: cannot open a window ({reason}); {HEADLESS_HINT}");
            std::process::exit(1);
        }
    }));
}

/// The window is up: from now on a panic is a bug and reported as one.
pub fn mark_open() {
    WINDOW_OPEN.store(true, Ordering::SeqCst);
}

/// Samples per pixel the window's drawing surface has, as OpenGL reports
/// it (4 with edges smoothed; 0 or 1 without). Call with the window's
/// context current, as it is inside a frame.
#[cfg(not(target_arch = "wasm32"))]
pub fn samples_per_pixel() -> i32 {
    const GL_SAMPLES: u32 = 0x80A9;
    let mut samples = 0;
    // SAFETY: a query of one integer into a local, with the context current.
    unsafe { macroquad::miniquad::gl::glGetIntegerv(GL_SAMPLES, &mut samples) };
    samples
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_display_nobody_listens_on_is_a_problem() {
        let msg = x_server_problem(":987").expect("nothing listens on display 987");
        assert!(msg.contains(":987"));
        assert!(x_server_problem("garbage").is_some());
    }
}
