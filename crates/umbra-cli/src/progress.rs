//! A progress bar on standard error for long evaluations: shown only when
//! standard error is a terminal, the command is not `--quiet`, and there
//! is enough work to watch.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// Trees with fewer Booleans than this finish before a bar is worth drawing.
const MIN_STEPS: usize = 16;

/// A progress bar that may be hidden; safe to update from any thread.
pub struct Progress(Option<ProgressBar>);

impl Progress {
    /// A bar over `total` steps, hidden when `quiet`, when standard error
    /// is not a terminal, or when `total` is small.
    pub fn new(total: usize, quiet: bool) -> Progress {
        if quiet || total < MIN_STEPS || !std::io::stderr().is_terminal() {
            return Progress(None);
        }
        let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
        let style = ProgressStyle::with_template("{bar:40} {pos}/{len} Booleans, {elapsed}")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Progress(Some(bar))
    }

    /// Sets the number of steps done.
    pub fn set(&self, done: usize) {
        if let Some(bar) = &self.0 {
            bar.set_position(done as u64);
        }
    }

    /// Removes the bar from the terminal.
    pub fn finish(&self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}
