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
            BooleanError::Internal(_) => None,
        }
    }
}
