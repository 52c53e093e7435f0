//! Topologically robust 2D simplification in floating-point arithmetic
//! (dissertation chapters 6 and 7), and Booleans through it.
//!
//! Simplification (section 6.1) turns a self-intersecting or multiply
//! enclosed polygon set into a valid one by selecting the cells of its
//! arrangement by winding number: the standard form keeps winding `> 0`;
//! variants keep odd, non-zero, negative or `>= 2` winding numbers, or any
//! caller's predicate ([`FillRule`]). Assembling two boundaries and tracking
//! each operand's winding number gives union, intersection, difference and
//! xor ([`boolean`]); any number of operands go through one sweep
//! ([`boolean_sets`] by operation, [`union_all`], [`boolean_n`] by any
//! predicate).
//!
//! The arrangement is computed by the modified Bentley-Ottmann sweep of
//! sections 7.4-7.6 on the *current* data: edges are split at computed
//! intersection points (Tables 7.1 and 7.2, from `robust-arith`) and at
//! vertices found on them by the exact rule of section 6.5; coincident edges
//! merge in an edge collection with multiplicity (section 7.1.2,
//! [`EdgeCollection`]); downward vertical edges (section 7.6.1) and
//! incorrectly grouped sweep-line edges (section 7.6.2) are handled as the
//! dissertation prescribes; vertical edges are merged by 1D simplification.
//! Nothing iterates to a fixed point (section 7.6.3).
//!
//! A simplification or Boolean of a large input is swept in vertical
//! strips in parallel and the strips' boundaries joined (`strips.rs`):
//! the same guarantees, with the cut points counted in `k_max`, and the
//! same result on any number of threads.
//!
//! Guarantees: for every input satisfying shape boundary closure, the cell
//! structure is valid ([`CellStructure::check_cells`]) and every simplified
//! shape satisfies shape boundary closure. Geometric accuracy: each result
//! reports `eps = (k_max + 1) sqrt(153) u L` from the adjustment counts of
//! section 8.4.
//!
//! # Example
//!
//! ```
//! use simplify_2d::{simplify, FillRule};
//! use topology::PolygonSet2;
//!
//! // A pentagram: winding 2 in the centre, 1 in the points.
//! let pts: Vec<[f64; 2]> = (0..5)
//!     .map(|i| {
//!         let a = std::f64::consts::TAU * (2 * i) as f64 / 5.0;
//!         [a.cos(), a.sin()]
//!     })
//!     .collect();
//! let mut star = PolygonSet2::new();
//! star.add_loop(&pts);
//! let out = simplify(&star, FillRule::Positive).unwrap();
//! assert!(out.shape.check_topology().is_ok());
//! assert_eq!(out.shape.vertex_count(), 10); // the outline of the star
//! let centre = simplify(&star, FillRule::AtLeast2).unwrap();
//! assert_eq!(centre.shape.vertex_count(), 5); // the inner pentagon
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod api;
mod buffer_heap;
mod cells;
mod collection;
mod end_points;
mod error;
mod point;
mod strips;
mod sweep;
mod sweep_line;
mod vertex_table;
mod winding;

pub use api::{
    boolean, boolean_cells, boolean_n, boolean_sets, cell_structure, cell_structure_n, simplify,
    union_all, Simplified,
};
pub use cells::{CellEdge, CellStructure, SweepStats};
pub use collection::EdgeCollection;
pub use error::SimplifyError;
pub use topology::BooleanOp;
pub use winding::{FillRule, Winding};
