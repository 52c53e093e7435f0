//! The substratum of Umbra: the floating-point kernels every level of the
//! pyramid is built on (dissertation chapters 7.1 and 8).
//!
//! Everything here is plain IEEE 754 double arithmetic in the exact operation
//! order of the dissertation's code: no `mul_add`, no reassociation, no
//! tolerance. The functions are:
//!
//! - [`y_at_x`]: the y-value of a segment at a given x (Table 7.1), and its
//!   N-dimensional form [`point_at_x`] used for level-1 intersection points;
//! - [`interpolate`]: the intersection point of two segments from the
//!   y-values at the two ends of their x-overlap (Table 7.2);
//! - [`interpolate_pair`]: the general point-pair interpolation of
//!   eq. 4.2-4.6, of which Table 7.2 is the 2D case;
//! - [`lex_cmp`]: the lexicographic point order of section 7.1.2;
//! - the error-bound constants of chapter 8 ([`UNIT_ROUNDOFF`],
//!   [`Y_AT_X_ERROR_FACTOR`], [`INTERSECTION_ERROR_FACTOR`]) and
//!   [`validate_coordinate`] for the coordinate range of section 8.5;
//! - [`orient2d`] and [`orient3d`]: the one exact orientation-predicate
//!   source of the workspace (adaptive fast path, exact integer fallback
//!   outside its provably exact range), used by shape inspection and the
//!   triangle variant's coplanar merge, never by the Booleans' own
//!   decisions; and [`coplanar`], `orient3d == Equal` behind a residue
//!   certificate (modulo `2^61 - 1`) that decides rounded coplanar points
//!   without the exact stage.
//!
//! # Example
//!
//! ```
//! use robust_arith::{interpolate, y_at_x};
//!
//! // Table 7.1: the segment (0,0)->(4,2) at x = 1.
//! assert_eq!(y_at_x([0.0, 0.0], [4.0, 2.0], 1.0), 0.5);
//!
//! // Table 7.2: segment A from (0,0) to (2,2), segment B from (0,1) to (2,1):
//! // at x = 0, A is below B; at x = 2 it is above.
//! let p = interpolate(0.0, 0.0, 1.0, 2.0, 2.0, 1.0);
//! assert_eq!(p, [1.0, 1.0]);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod bounds;
mod error;
mod exact;
mod interpolate;
mod order;
mod pair;
mod residue;
mod segment;

pub use bounds::{
    intersection_error_bound, power_of_two_bound, y_at_x_error_bound, INTERSECTION_ERROR_FACTOR,
    MAX_COORDINATE, UNIT_ROUNDOFF, Y_AT_X_ERROR_FACTOR,
};
pub use error::ArithError;
pub use exact::{orient2d, orient3d, FAST_MAX, FAST_MIN};
pub use interpolate::interpolate;
pub use order::{from_total_order_key, lex_cmp, lex_less, total_order_key};
pub use pair::interpolate_pair;
pub use residue::coplanar;
pub use segment::{point_at_x, y_at_x};

/// A point in the plane, `[x, y]`.
pub type Point2 = [f64; 2];
/// A point in space, `[x, y, z]`.
pub type Point3 = [f64; 3];

/// Checks that a coordinate can be used by every kernel of the pyramid:
/// finite and of magnitude at most [`MAX_COORDINATE`] (`f64::MAX / 4`), so
/// that no difference of two coordinates can overflow (section 8.5).
///
/// ```
/// use robust_arith::{validate_coordinate, ArithError};
/// assert!(validate_coordinate(1.0e300).is_ok());
/// assert!(matches!(validate_coordinate(f64::NAN), Err(ArithError::NonFinite { .. })));
/// assert!(matches!(validate_coordinate(f64::MAX), Err(ArithError::OutOfRange { .. })));
/// ```
pub fn validate_coordinate(value: f64) -> Result<(), ArithError> {
    if !value.is_finite() {
        Err(ArithError::NonFinite { value })
    } else if value.abs() > MAX_COORDINATE {
        Err(ArithError::OutOfRange { value })
    } else {
        Ok(())
    }
}
