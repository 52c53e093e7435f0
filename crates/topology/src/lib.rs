//! Shape representations and the topological constraints of section 4.2.
//!
//! - [`PolygonSet2`]: a 2D polygonal set as a collection of directed edges
//!   between vertices, each with an integer multiplicity (a negative
//!   multiplicity means the edge runs the other way).
//! - [`PolygonMesh`]: a polyhedral shape whose facets are collections of
//!   half-edges (so a facet may have holes or several regions); non-manifold
//!   and disconnected shapes are allowed.
//! - [`TriangleMesh`]: a polyhedral shape of triangular facets.
//! - [`BooleanOp`] and [`Operand`]: the one operation type (eq. 4.11-4.13,
//!   4.20) and operand name that every Boolean of the workspace takes.
//! - [`triangulate_facet`] and [`triangulate_mesh`]: the triangulation of
//!   facets by internal edges (section 4.8).
//! - Inspection: [`check_mesh`] ([`MeshCheckReport`]: 2-manifoldness,
//!   exact self-intersecting facet pairs, signed volume, bounding box),
//!   also as methods (`mesh.check()`, `mesh.signed_volume()`,
//!   `mesh.bounding_box()`, `mesh.self_intersections()`,
//!   `mesh.manifold_report()`), and [`check_polygon_set`]
//!   ([`CheckReport`]: exact crossing edge pairs), on the exact predicates
//!   of `robust_arith`. With the feature `serde` the reports are
//!   `serde::Serialize`.
//!
//! Each structure has `check_topology()`, which returns a [`TopologyError`]
//! naming the violated constraint and the entity, and
//! `validate_coordinates()`, which rejects non-finite coordinates and those
//! beyond `f64::MAX / 4` (section 8.5). Coincident vertices and zero-length
//! edges are topologically valid (section 4.2) and accepted.
//!
//! # Example
//!
//! ```
//! use topology::PolygonSet2;
//!
//! let mut square = PolygonSet2::new();
//! square.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
//! assert!(square.check_topology().is_ok());
//! assert_eq!(square.signed_area(), 1.0);
//!
//! // An edge whose end vertex starts nothing breaks shape boundary closure.
//! let mut open = PolygonSet2::new();
//! let a = open.add_vertex([0.0, 0.0]);
//! let b = open.add_vertex([1.0, 0.0]);
//! open.add_edge(a, b);
//! assert!(open.check_topology().is_err());
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod error;
mod inspect;
mod mesh;
mod op;
mod polygon_set;
mod triangle_mesh;
mod triangulate;
mod unit_scale;

pub use error::TopologyError;
pub use inspect::*;
pub use mesh::{Facet, HalfEdge, PolygonMesh};
pub use op::{BooleanOp, Operand};
pub use polygon_set::{Edge2, PolygonSet2};
pub use robust_arith::{Point2, Point3};
pub use triangle_mesh::TriangleMesh;
pub use triangulate::{triangulate_facet, triangulate_mesh, FacetProjection};

/// Checks every coordinate of every point (shared by the three structures).
fn validate_points<const N: usize>(points: &[[f64; N]]) -> Result<(), TopologyError> {
    for (vertex, p) in points.iter().enumerate() {
        for (axis, &value) in p.iter().enumerate() {
            if let Err(source) = robust_arith::validate_coordinate(value) {
                return Err(TopologyError::BadCoordinate {
                    vertex: vertex as u32,
                    axis: axis as u8,
                    source,
                });
            }
        }
    }
    Ok(())
}
