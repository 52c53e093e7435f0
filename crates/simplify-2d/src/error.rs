//! The error type of the simplification sweep: rejected input apart from
//! "this is a bug" conditions.

use std::fmt;
use topology::TopologyError;

/// Why a simplification or a Boolean through simplification failed.
#[derive(Clone, Debug, PartialEq)]
pub enum SimplifyError {
    /// The input violates a data definition, the shape boundary closure
    /// constraint of section 4.2, or has a coordinate that is not finite or
    /// exceeds `f64::MAX / 4` (section 8.5). The caller's data is untouched.
    InvalidInput {
        /// Which operand (0 for a single input; the index for Booleans).
        operand: usize,
        /// The violated constraint.
        source: TopologyError,
    },
    /// An internal invariant of the sweep failed. This is a bug: please
    /// report it together with the input.
    Internal(String),
}

impl fmt::Display for SimplifyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SimplifyError::InvalidInput { operand, source } => {
                write!(f, "invalid input (operand {operand}): {source}")
            }
            SimplifyError::Internal(msg) => write!(
                f,
                "internal error in the simplification sweep (this is a bug, please report it): {msg}"
            ),
        }
    }
}

impl std::error::Error for SimplifyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SimplifyError::InvalidInput { source, .. } => Some(source),
            SimplifyError::Internal(_) => None,
        }
    }
}
