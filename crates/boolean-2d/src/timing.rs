//! Phase timings of a Boolean: the public [`Timings`] record and the
//! clock helper every phase uses. Informational only.

use std::time::Instant;

/// Wall-clock durations of the phases of one Boolean, in milliseconds.
///
/// `total` covers the whole call (validation included); the phases add up
/// to about `total`. Informational only: no decision depends on them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timings {
    /// Coordinate validation and the closure check of both operands.
    pub validate: f64,
    /// Edge boxes and the sweep-line broad phase (0 on the reference
    /// path).
    pub broad_phase: f64,
    /// `X11` on the candidate pairs (every pair on the reference path).
    pub intersections: f64,
    /// `X02` and `X20`: ray casts and propagation (brute-force sums on the
    /// reference path).
    pub winding: f64,
    /// Levels 3-4: inclusion values, composite edges, the shape.
    pub construct: f64,
    /// The whole operation.
    pub total: f64,
}

/// Milliseconds since `start`.
pub(crate) fn ms(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}
