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
mod contacts;
mod error;
mod fast;
mod interval_set;
mod level_data;
mod reference;
mod timing;

pub use composite::{pair_composite_edge, CompositeEdge};
pub use contacts::{boolean_with_contacts, planar_contacts, PlanarContacts};
pub use error::BooleanError;
pub use level_data::LevelData;
use std::time::Instant;
use timing::ms;
pub use timing::Timings;
use topology::PolygonSet2;
pub use topology::{BooleanOp, Operand};

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
    /// Phase timings of this call.
    pub timings: Timings,
}

/// The Boolean `op` of `a` and `b` (eq. 4.7-4.16).
///
/// Both operands are validated first (coordinates finite and at most
/// `f64::MAX / 4`, shape boundary closure); a bad operand gives
/// [`BooleanError::InvalidInput`] and nothing else happens.
///
/// Cost `O((n + k) log n)` for `n` edges and `k` candidate pairs of the
/// broad phase, whatever the input: a sweep over edge boxes (with an
/// interval set over y when many boxes share an x range) prunes every pair
/// whose `X11` is provably 0, `X11` runs on the rest in parallel, and the
/// winding numbers `X02`/`X20` come from one ray cast per connected
/// component (by a sweep in y over a Fenwick tree when many components
/// share an x range), propagated along edges. The result is bit for bit
/// that of [`boolean_reference`], whatever the thread count.
pub fn boolean(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<BooleanOutput, BooleanError> {
    // The level data is dropped: no composite counts to record.
    run(a, b, op, false, |timings, max_abs| {
        level2(a, b, timings, max_abs)
    })
    .map(|(out, _)| out)
}

/// [`boolean`], also returning the level data it built from (for audits:
/// Theorem 2 on `composite_counts`, comparison with [`boolean_reference`]).
pub fn boolean_audit(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<(BooleanOutput, LevelData), BooleanError> {
    run(a, b, op, true, |timings, max_abs| {
        level2(a, b, timings, max_abs)
    })
}

/// Level 2 by the fast path, recording its phase timings.
fn level2(
    a: &PolygonSet2,
    b: &PolygonSet2,
    timings: &mut Timings,
    max_abs: f64,
) -> Result<LevelData, BooleanError> {
    let (data, t) = fast::level2_fast(a, b, max_abs)?;
    timings.broad_phase = t.broad_phase;
    timings.intersections = t.intersections;
    timings.winding = t.winding;
    Ok(data)
}

/// The 2D Boolean with level 2 evaluated by brute force (every vertex
/// against every edge, every edge against every edge), returning the level
/// data for audit. `O(n m)`; use [`boolean`] for real work.
pub fn boolean_reference(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<(BooleanOutput, LevelData), BooleanError> {
    run(a, b, op, true, |timings, _| {
        let clock = Instant::now();
        let data = reference::level2_brute_force(a, b)?;
        timings.intersections = ms(clock);
        Ok(data)
    })
}

/// One Boolean: validation, level 2 by `level2` (which records its own
/// phase timings and gets the largest coordinate magnitude of both
/// operands), levels 3-4, the output; the level data's composite counts
/// are recorded when `record_counts`.
fn run(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
    record_counts: bool,
    level2: impl FnOnce(&mut Timings, f64) -> Result<LevelData, BooleanError>,
) -> Result<(BooleanOutput, LevelData), BooleanError> {
    let start = Instant::now();
    let mut timings = Timings::default();
    validate(a, Operand::A)?;
    validate(b, Operand::B)?;
    timings.validate = ms(start);
    let max_abs = a.max_abs_coordinate().max(b.max_abs_coordinate());
    let mut data = level2(&mut timings, max_abs)?;
    let clock = Instant::now();
    let shape = construct::construct(a, b, op, &mut data, record_counts)?;
    timings.construct = ms(clock);
    timings.total = ms(start);
    Ok((output(max_abs, shape, &data, timings), data))
}

/// Assembles a [`BooleanOutput`]; `max_abs` is the largest coordinate
/// magnitude of both operands.
pub(crate) fn output(
    max_abs: f64,
    shape: PolygonSet2,
    data: &LevelData,
    timings: Timings,
) -> BooleanOutput {
    BooleanOutput {
        shape,
        epsilon: robust_arith::intersection_error_bound(max_abs),
        intersections: data.x11.len(),
        timings,
    }
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
