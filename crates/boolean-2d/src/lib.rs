//! The 2D basic Boolean (dissertation chapter 4 in the plane, levels 2-4):
//! union, intersection and difference of two [`PolygonSet2`] that always
//! yields a topologically valid polygon set, whatever the coordinates.
//!
//! - Level 2: `X02(v_A, B)`, `X11(e_A, e_B)`, `X20(A, v_B)` (Table 4.1) with
//!   the intersection points of Table 7.2.
//! - Level 3 (the 2D analogue of inclusion values, eq. 4.7-4.13):
//!   `I02 = c_A + c_I X02`, `I11 = c_I X11`, `I20 = c_B + c_I X20`.
//! - Level 3 composite edges: the retained parts of each edge, from net
//!   end-vertex counts, paired along `v = sum x_e - sum x_s`
//!   (eq. 4.14-4.16).
//! - Level 4: the shape, every retained part of every edge.
//!
//! Input may be geometrically invalid (self-intersecting, inside-out,
//! multiply enclosed; section 4.7): winding numbers outside {0, 1} are
//! handled and the result still satisfies shape boundary closure.
//!
//! # Example
//!
//! ```
//! use boolean_2d::{boolean, BooleanOp};
//! use topology::PolygonSet2;
//!
//! let mut a = PolygonSet2::new();
//! a.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
//! let mut b = PolygonSet2::new();
//! b.add_loop(&[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]);
//!
//! let out = boolean(&a, &b, BooleanOp::Union).unwrap();
//! assert!(out.shape.check_topology().is_ok());
//! assert_eq!(out.shape.signed_area(), 7.0);
//! let out = boolean(&a, &b, BooleanOp::Intersection).unwrap();
//! assert_eq!(out.shape.signed_area(), 1.0);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod composite;
mod construct;
mod error;
mod op;
mod reference;

pub use composite::{pair_composite_edge, CompositeEdge};
pub use error::{BooleanError, Operand};
pub use op::BooleanOp;
pub use reference::{boolean_reference, LevelData};
use topology::PolygonSet2;

/// The result of a 2D Boolean.
#[derive(Clone, Debug)]
pub struct BooleanOutput {
    /// The resulting polygon set (always topologically valid).
    pub shape: PolygonSet2,
    /// The epsilon of section 8.4: the 2D basic Boolean is epsilon-tolerant
    /// with `epsilon = alpha = sqrt(153) u L`, `L` the power of two bounding
    /// every input coordinate.
    pub epsilon: f64,
    /// The number of edge pairs with `X11 != 0`.
    pub intersections: usize,
}

/// The Boolean `op` of `a` and `b` (eq. 4.7-4.16).
///
/// Both operands are validated first (coordinates finite and at most
/// `f64::MAX / 4`, shape boundary closure); a bad operand gives
/// [`BooleanError::InvalidInput`] and nothing else happens.
pub fn boolean(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<BooleanOutput, BooleanError> {
    boolean_reference(a, b, op).map(|(out, _)| out)
}

/// Validates one operand.
pub(crate) fn validate(set: &PolygonSet2, which: Operand) -> Result<(), BooleanError> {
    set.validate_coordinates()
        .and_then(|()| set.check_topology())
        .map_err(|source| BooleanError::InvalidInput {
            operand: which,
            source,
        })
}
