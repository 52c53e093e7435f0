//! Standard output that never panics: a write error is an error of the
//! command (exit 1, one line naming standard output), and a closed pipe
//! (the reader went away, as `umbra check x.wkt --json | head -1` does) is
//! not an error at all: output stops quietly and the command finishes with
//! the exit code it would have had, like the usual Unix filters. Standard
//! error is best effort: a message that cannot be written is dropped.

use std::io::{ErrorKind, Write};
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once a write met a closed pipe: later output is dropped.
static CLOSED: AtomicBool = AtomicBool::new(false);

/// Standard output could not be written.
#[derive(Debug)]
pub struct StdoutError(pub std::io::Error);

impl std::fmt::Display for StdoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "standard output: cannot write: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

/// Writes `text` to standard output and flushes it.
pub fn print(text: &str) -> Result<(), StdoutError> {
    if CLOSED.load(Ordering::Relaxed) {
        return Ok(());
    }
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == ErrorKind::BrokenPipe => {
            CLOSED.store(true, Ordering::Relaxed);
            Ok(())
        }
        Err(e) => Err(StdoutError(e)),
    }
}

/// Writes one line to standard error, prefixed with `umbra: ` and with
/// any line breaks of `text` replaced by spaces; never fails.
pub fn error_line(text: &str) {
    let line = format!("umbra: {}\n", text.replace(['\n', '\r'], " "));
    let _ = std::io::stderr().lock().write_all(line.as_bytes());
}

/// `println!` to [`print()`]: evaluates to `Result<(), StdoutError>`.
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::stdout::print(&format!("{}\n", format_args!($($arg)*)))
    };
}
pub(crate) use outln;
