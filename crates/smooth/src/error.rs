//! The error type of smoothing: bad input (apart) and internal failures.

use std::fmt;
use topology::TopologyError;

/// Why a shape could not be smoothed.
#[derive(Clone, Debug, PartialEq)]
pub enum SmoothError {
    /// The tolerance is negative, NaN or infinite.
    InvalidTolerance(f64),
    /// The input violates a closure constraint of section 4.2, has a
    /// dangling index or a non-finite or too large coordinate (section
    /// 8.5). The input is left untouched.
    InvalidInput(TopologyError),
    /// A closure constraint failed after a smoothing step: a bug, please
    /// report it with the input.
    Internal(String),
}

impl fmt::Display for SmoothError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SmoothError::InvalidTolerance(t) => {
                write!(f, "smoothing tolerance must be finite and >= 0, got {t}")
            }
            SmoothError::InvalidInput(e) => write!(f, "invalid input: {e}"),
            SmoothError::Internal(m) => {
                write!(f, "internal error in smoothing (a bug, please report): {m}")
            }
        }
    }
}

impl std::error::Error for SmoothError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SmoothError::InvalidInput(e) => Some(e),
            _ => None,
        }
    }
}

impl From<TopologyError> for SmoothError {
    fn from(e: TopologyError) -> Self {
        SmoothError::InvalidInput(e)
    }
}
