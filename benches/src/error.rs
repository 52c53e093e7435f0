//! The error type of the bench harness.

use std::fmt;

/// Errors a peer can report instead of a result.
#[derive(Clone, Debug, PartialEq)]
pub enum BenchError {
    /// Umbra's 2D Boolean returned an error.
    Umbra(boolean_2d::BooleanError),
    /// A peer returned an error instead of a result.
    Peer(String),
    /// A peer's output could not be read back as rings (this is a bug in the
    /// harness, please report it).
    Internal(String),
}

impl fmt::Display for BenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BenchError::Umbra(e) => write!(f, "umbra: {e}"),
            BenchError::Peer(msg) => write!(f, "{msg}"),
            BenchError::Internal(msg) => write!(f, "internal error (a bug, please report): {msg}"),
        }
    }
}

impl std::error::Error for BenchError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BenchError::Umbra(e) => Some(e),
            BenchError::Peer(_) | BenchError::Internal(_) => None,
        }
    }
}
