//! The error type of the substratum: a coordinate no kernel may be given.

use std::fmt;

/// Why a coordinate was rejected by [`crate::validate_coordinate`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ArithError {
    /// The value is NaN or infinite.
    NonFinite {
        /// The offending value.
        value: f64,
    },
    /// The magnitude exceeds `f64::MAX / 4`, beyond which a coordinate
    /// difference may overflow (section 8.5).
    OutOfRange {
        /// The offending value.
        value: f64,
    },
}

impl fmt::Display for ArithError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ArithError::NonFinite { value } => write!(f, "coordinate {value} is not finite"),
            ArithError::OutOfRange { value } => write!(
                f,
                "coordinate {value:e} exceeds the supported magnitude f64::MAX/4 (section 8.5)"
            ),
        }
    }
}

impl std::error::Error for ArithError {}
