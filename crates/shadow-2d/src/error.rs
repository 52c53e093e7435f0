//! The error type of level 2.

use std::fmt;

/// Errors of the level-2 functions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ShadowError {
    /// An intersection function is non-zero but no lower-level pair of one
    /// shadow type exists to interpolate from. Theorem 1 rules this out for
    /// `X11` always and for `X02`/`X20` when the facet satisfies facet
    /// boundary closure: either the facet given was not closed, or this is
    /// a bug (please report it).
    MissingPartner {
        /// The function, e.g. `"X11"`.
        function: &'static str,
    },
}

impl fmt::Display for ShadowError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShadowError::MissingPartner { function } => write!(
                f,
                "internal error: {function} is non-zero but a Theorem 1 interpolation partner is missing (facet not closed, or a bug: please report)"
            ),
        }
    }
}

impl std::error::Error for ShadowError {}
