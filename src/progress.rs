//! Progress bars for the long commands (`run` and the lab).
//!
//! [`bar`] draws on stderr with an ETA when stderr is a terminal and is hidden
//! otherwise, so output piped to a file or another program stays quiet (and a
//! test harness sees nothing).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// What a visible bar shows: message, bar, count, elapsed time and ETA.
const TEMPLATE: &str =
    "{msg} [{bar:40.cyan/blue}] {pos}/{len} ({percent}%), {elapsed} elapsed, ETA {eta}";

/// A progress bar of `len` steps labelled `message`: drawn on stderr with an
/// ETA when stderr is a terminal, hidden ([`ProgressDrawTarget::hidden`]) when
/// it is not. Call `inc` as work completes and `finish_and_clear` (or
/// `finish`) at the end.
pub fn bar(len: u64, message: &str) -> ProgressBar {
    bar_on(len, message, std::io::stderr().is_terminal())
}

/// [`bar`] with the terminal check made by the caller.
fn bar_on(len: u64, message: &str, terminal: bool) -> ProgressBar {
    let target = if terminal {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let style = ProgressStyle::with_template(TEMPLATE)
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
    ProgressBar::with_draw_target(Some(len), target)
        .with_style(style)
        .with_message(message.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn template_parses() {
        assert!(ProgressStyle::with_template(TEMPLATE).is_ok());
    }

    #[test]
    fn hidden_off_a_terminal_and_still_counts() {
        let pb = bar_on(10, "stepping", false);
        assert!(pb.is_hidden());
        assert_eq!(pb.length(), Some(10));
        assert_eq!(pb.message(), "stepping");
        pb.inc(3);
        assert_eq!(pb.position(), 3);
        pb.finish_and_clear();
        assert!(pb.is_finished());
    }

    #[test]
    fn follows_stderr() {
        // Under `cargo test` stderr is usually captured (not a terminal), but
        // whichever it is, the bar must agree.
        let pb = bar(5, "x");
        if !std::io::stderr().is_terminal() {
            assert!(pb.is_hidden());
        }
        pb.finish_and_clear();
    }
}
