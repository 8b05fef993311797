//! A spinner on stderr for long work, shown only when stderr is a terminal (never in pipes,
//! files or tests) and the work is large.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal as _;
use std::time::Duration;

/// Inputs at least this large are expected to take around a second or more.
pub const LARGE_INPUT: usize = 1_000_000;

/// A spinner that clears itself when dropped.
pub struct Spinner(ProgressBar);

impl Spinner {
    /// Show `message` with a spinner when `large` and stderr is a terminal; otherwise nothing.
    pub fn start(message: &str, large: bool) -> Spinner {
        if !large || !std::io::stderr().is_terminal() {
            return Spinner(ProgressBar::hidden());
        }
        let bar = ProgressBar::new_spinner();
        if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} ({elapsed})") {
            bar.set_style(style);
        }
        bar.set_message(message.to_string());
        bar.enable_steady_tick(Duration::from_millis(120));
        Spinner(bar)
    }
}

impl Drop for Spinner {
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}
