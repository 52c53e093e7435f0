//! Shape inspection: what a shape is, measured exactly where it matters,
//! beside the shapes it inspects, on the exact predicates of
//! `robust_arith` ([`robust_arith::orient2d`], [`robust_arith::orient3d`]).
//!
//! - Polygon meshes and triangle meshes: 2-manifoldness with the open and
//!   non-manifold edges and vertices named ([`ManifoldReport`]), the facet
//!   pairs that intersect improperly (exact), the signed volume and the
//!   bounding box, and the whole report [`MeshCheckReport`].
//! - Boxes: the sides of a box each vertex lies beyond, one byte each
//!   ([`sides_beyond`]), and from them, exactly, whether a facet's box
//!   is apart from it ([`facet_apart`]): the first filter of the
//!   near-focus inspections and of smoothing's region search.
//! - Polygon sets: validity and the exact count of crossing and
//!   overlapping edge pairs ([`CheckReport`]); point location in a ring
//!   ([`RingIndex`], [`ring_side`]) and a ring's signed area.
//!
//! Inspection describes shapes; it never decides topology (the Booleans do
//! not call it). Nothing here panics on any input: bad indices and
//! coordinates become fields of the reports or errors.

mod bvh;
mod intersect;
mod manifold;
mod planar;
mod report;
mod ring;
mod sides;

pub use intersect::{self_intersecting_pairs_near, self_intersecting_triangle_pairs_near};
pub use manifold::{EdgeUse, ManifoldCounts, ManifoldReport};
pub use planar::{check_polygon_set, CheckReport};
pub use report::{check_mesh, mesh_signed_volume, MeshCheckReport};
pub use ring::{ring_side, ring_signed_area, RingIndex, RingSide};
pub use sides::{facet_apart, sides_beyond};
