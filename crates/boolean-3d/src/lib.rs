//! The 3D basic Boolean (dissertation chapter 4 for polyhedra, levels
//! 3-6): union, intersection and difference of polygon meshes or triangle
//! meshes that always yields a topologically valid result, whatever the
//! coordinates.
//!
//! - Level 3 ([`Level3Data`]): `X03(v_A, B)`, `X12(e_A, f_B)`,
//!   `X21(f_A, e_B)`, `X30(A, v_B)` exactly as Table 4.1, from the level-2
//!   shadow functions of `shadow-2d`, with edge-facet intersection points
//!   interpolated by eq. 4.2-4.6. A BVH broad phase skips only pairs whose
//!   X is provably 0, and winding numbers are propagated along edges by the
//!   exact identity `X03(v_e) = X03(v_s) - sum_f X12(e, f)`, so one ray
//!   cast per connected component suffices.
//! - Level 4: inclusion values (eq. 4.7-4.13) and composite edges with the
//!   net end-vertex counts of section 4.6, paired along their direction
//!   (eq. 4.14-4.16, [`CompositeEdge3`]).
//! - Level 5: retained facets (which may gain holes); level 6: the shape.
//! - The triangle-mesh variant merges exactly coplanar, co-oriented
//!   edge-adjacent input triangles into polygon facets (and drops vertices
//!   that only subdivide a straight edge) before the Boolean, then
//!   triangulates each retained facet by adding internal edges only
//!   (section 4.8, [`triangulate_facet`]), keeping the input triangles of
//!   the regions the Boolean left untouched; a chain of operations thus
//!   keeps the shape's real complexity (`docs/algorithms/boolean-3d.md`).
//!
//! Theorems 1-4 of section 4.9 are checkable through the audit variants
//! ([`boolean_mesh_audit`], [`Audit::verify`]). Inputs are validated first
//! and any topologically valid input is accepted: non-manifold edges,
//! several shells, coincident vertices, zero-length edges, self-intersecting
//! and inside-out shapes (winding numbers outside {0, 1}, section 4.7).
//! The output is deterministic, bit for bit, whatever the thread count.
//!
//! # Example
//!
//! ```
//! use boolean_3d::{boolean_mesh, BooleanOp};
//! use topology::{Facet, PolygonMesh};
//!
//! fn cube(o: [f64; 3], s: f64) -> PolygonMesh {
//!     let v = (0..8)
//!         .map(|i| [o[0] + s * f64::from(i & 1), o[1] + s * f64::from((i >> 1) & 1),
//!                   o[2] + s * f64::from((i >> 2) & 1)])
//!         .collect();
//!     let f = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
//!     PolygonMesh::new(v, f.iter().map(|l| Facet::from_loop(l)).collect())
//! }
//!
//! let a = cube([0.0; 3], 2.0);
//! let b = cube([1.0; 3], 2.0);
//! let out = boolean_mesh(&a, &b, BooleanOp::Union).unwrap();
//! assert!(out.mesh.check_topology().is_ok());
//! let tri = boolean_3d::triangulate_mesh(&out.mesh);
//! assert_eq!(tri.signed_volume(), 15.0);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod api;
mod bvh;
mod composite;
mod construct;
mod contacts;
mod error;
mod level3;
mod merge;
mod mesh;
mod par;
mod prepared;
mod retriangulate;

pub use api::{
    boolean_mesh, boolean_mesh_audit, boolean_mesh_with_contacts, boolean_triangles,
    boolean_triangles_audit, boolean_triangles_with_contacts, level3, level3_reference, Audit,
    FacetAudit, MeshOutput, TriangleOutput,
};
pub use composite::CompositeEdge3;
pub use construct::{CompositeKind, CompositeRecord, FacetSource};
pub use contacts::Contacts;
pub use error::Boolean3Error;
pub use level3::{EdgeFacetHit, Level3Data};
pub use prepared::{boolean_prepared, PreparedTriangles};
pub use topology::{triangulate_facet, triangulate_mesh};
pub use topology::{BooleanOp, Operand};
