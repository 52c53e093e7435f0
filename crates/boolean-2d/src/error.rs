//! The error type of the 2D Boolean.

use std::fmt;
use topology::{Operand, TopologyError};

/// Errors of the 2D Boolean.
#[derive(Clone, Debug, PartialEq)]
pub enum BooleanError {
    /// An operand is not topologically valid or has a bad coordinate.
    InvalidInput {
        /// Which operand.
        operand: Operand,
        /// The violated constraint.
        source: TopologyError,
    },
    /// The proximity asked of [`crate::PlanarContacts`] is not a finite
    /// number at least 0.
    InvalidProximity(f64),
    /// An invariant that the theorems of section 4.9 guarantee failed: this
    /// is a bug, please report it with the input.
    Internal(String),
}

impl fmt::Display for BooleanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BooleanError::InvalidInput { operand, source } => {
                write!(f, "operand {operand:?}: {source}")
            }
            BooleanError::InvalidProximity(p) => {
                write!(
                    f,
                    "the contact proximity must be finite and at least 0, not {p}"
                )
            }
            BooleanError::Internal(msg) => {
                write!(f, "internal error (a bug, please report): {msg}")
            }
        }
    }
}

impl std::error::Error for BooleanError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BooleanError::InvalidInput { source, .. } => Some(source),
            BooleanError::InvalidProximity(_) | BooleanError::Internal(_) => None,
        }
    }
}
