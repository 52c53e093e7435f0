//! The error type of the 3D Boolean: bad input apart from "this is a bug".

use std::fmt;
use topology::{BooleanOp, Operand, TopologyError};

/// Errors of the 3D Boolean.
#[derive(Clone, Debug, PartialEq)]
pub enum Boolean3Error {
    /// An operand violates a data definition or topological constraint of
    /// section 4.2, or has a coordinate that is not finite or exceeds
    /// `f64::MAX / 4` (section 8.5). Nothing was computed.
    InvalidInput {
        /// Which operand.
        operand: Operand,
        /// The violated constraint and where.
        source: TopologyError,
    },
    /// The operation is not one the 3D Boolean builds (`Xor`: a half-edge
    /// has no multiplicity for the doubled intersection curves).
    UnsupportedOperation(BooleanOp),
    /// The result would have more vertices or half-edges than a `u32` index
    /// can address.
    TooLarge {
        /// What overflowed.
        what: &'static str,
    },
    /// The proximity asked of [`crate::Contacts`] is not a finite number
    /// at least 0.
    InvalidProximity(f64),
    /// An invariant guaranteed by the theorems of section 4.9 failed (for
    /// example a missing Theorem 1 interpolation partner or an unbalanced
    /// composite edge). This is a bug: please report it with the input.
    Internal(String),
}

impl fmt::Display for Boolean3Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Boolean3Error::InvalidInput { operand, source } => {
                write!(f, "operand {operand:?}: {source}")
            }
            Boolean3Error::UnsupportedOperation(op) => write!(
                f,
                "the 3D Boolean supports union, intersection and difference, not {op}"
            ),
            Boolean3Error::TooLarge { what } => {
                write!(f, "the result has too many {what} for 32-bit indices")
            }
            Boolean3Error::InvalidProximity(p) => {
                write!(
                    f,
                    "the contact proximity must be finite and at least 0, not {p}"
                )
            }
            Boolean3Error::Internal(msg) => {
                write!(f, "internal error (a bug, please report): {msg}")
            }
        }
    }
}

impl std::error::Error for Boolean3Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Boolean3Error::InvalidInput { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<shadow_2d::ShadowError> for Boolean3Error {
    fn from(e: shadow_2d::ShadowError) -> Self {
        // Operands are validated before any level-2 function runs, so every
        // facet satisfies facet boundary closure and Theorem 1 guarantees
        // the partners: a missing one is a bug.
        Boolean3Error::Internal(e.to_string())
    }
}
