//! A progress indicator on stderr for long runs: an indicatif spinner with the
//! subcommand and the elapsed time, shown only when stderr is a terminal and
//! only once the run has lasted a second (so short runs, pipes, CI logs and
//! `--json` consumers never see it). Cleared when the run ends.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// Delay before the spinner appears.
const DELAY: Duration = Duration::from_secs(1);

/// A spinner that may appear after [`DELAY`]; [`Progress::finish`] clears it.
pub struct Progress {
    bar: ProgressBar,
    /// `true` once finished: the delayed thread must not show the bar then.
    done: Arc<Mutex<bool>>,
}

impl Progress {
    /// Starts the delayed spinner for `what` (e.g. `offset`).
    pub fn start(what: &str) -> Progress {
        Self::start_on(what, std::io::stderr().is_terminal())
    }

    fn start_on(what: &str, terminal: bool) -> Progress {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        if let Ok(style) =
            ProgressStyle::with_template("{spinner} lncert {msg}: working, {elapsed}")
        {
            bar.set_style(style);
        }
        bar.set_message(what.to_string());
        let done = Arc::new(Mutex::new(false));
        if terminal {
            let (bar, done) = (bar.clone(), done.clone());
            std::thread::spawn(move || {
                std::thread::sleep(DELAY);
                // shown under the lock: `finish` cannot run in between
                if let Ok(done) = done.lock() {
                    if !*done {
                        bar.set_draw_target(ProgressDrawTarget::stderr());
                        bar.enable_steady_tick(Duration::from_millis(120));
                    }
                }
            });
        }
        Progress { bar, done }
    }

    /// Ends the run: the spinner is cleared (or never shown).
    pub fn finish(self) {
        if let Ok(mut done) = self.done.lock() {
            *done = true;
        }
        self.bar.finish_and_clear();
    }

    /// Whether the spinner is currently drawn.
    #[cfg(test)]
    fn visible(&self) -> bool {
        !self.bar.is_hidden()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hidden_when_not_a_terminal_and_before_the_delay() {
        let p = Progress::start_on("test", false);
        std::thread::sleep(DELAY + Duration::from_millis(300));
        assert!(!p.visible(), "not a terminal: never drawn");
        p.finish();
        let q = Progress::start_on("test", true);
        assert!(!q.visible(), "drawn only after the delay");
        q.finish();
    }
}
