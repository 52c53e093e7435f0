//! Umbra: topologically robust Boolean operations on polygons and polyhedra
//! in plain `f64` arithmetic, after the dissertation "Towards robust inexact
//! geometric computation" (see `docs/ARCHITECTURE.md` in the repository).
//!
//! This facade is the whole public API, flat: the lower crates' entry
//! points and types, file input/output (feature `io`, on by default),
//! shape checks and typed reports. The `umbra` command-line tool (package
//! `umbra-cli`) calls nothing else.
//!
//! - Shapes: [`PolygonSet2`] (2D directed edges with multiplicity),
//!   [`PolygonMesh`], [`TriangleMesh`], with `check_topology()` naming the
//!   violated constraint of section 4.2.
//! - One [`BooleanOp`] (union, intersection, difference, xor) and one
//!   [`Operand`] for every engine.
//! - 2D: the basic Boolean [`boolean`] (chapter 4, eq. 4.7-4.16; its output
//!   is always topologically valid); through simplification (chapter 6):
//!   [`simplify`] by a [`FillRule`], [`boolean_via_simplify`], and n-ary
//!   in one sweep [`boolean_sets`] (by operation, as [`boolean_solids`] in
//!   3D), [`boolean_n`] and [`union_all`]; [`Via`] names the algorithm.
//! - 3D: [`boolean_mesh`] (polygon meshes), [`boolean_triangles`]
//!   (triangle meshes; [`PreparedTriangles`] and [`boolean_prepared`] to
//!   validate and index an operand once for many Booleans),
//!   [`triangulate_mesh`], and [`boolean_solid`], which
//!   runs either [`MeshVariant`] on any valid operands; n-ary in one call,
//!   as a balanced parallel tree: [`boolean_solids`], [`union_all_solids`]
//!   and [`difference_all_solids`].
//! - Smoothing (chapter 5, Appendix A): [`smooth_mesh`],
//!   [`smooth_triangles`], [`smooth_polygon_set`] and [`smooth_solid`] (by
//!   variant) with [`SmoothOptions`]; [`default_mesh_tolerance`] is the
//!   rule the CLI uses when none is given. After a Boolean, smoothing only
//!   near the operands' contacts costs what the Boolean changed:
//!   [`boolean_with_contacts`] and [`smooth_polygon_set_near`] in 2D,
//!   [`boolean_solid_with_contacts`] and [`smooth_solid_near`] in 3D. No
//!   other call smooths.
//! - Reports: [`Boolean2Report`], [`SimplifyReport`], [`Boolean3Report`]
//!   and their parts, `serde::Serialize`, built from an operation's output.
//! - WKT: [`read_wkt_file`], [`read_wkt_str`], [`write_wkt_file`],
//!   [`write_wkt_string`]; `geo-types` conversions [`to_geo`] and
//!   [`from_geo`]. Rings are read by role by default (outer rings enclose
//!   positively, holes negatively, as GIS data intends) or exactly as
//!   written with [`RingOrientation::AsWritten`].
//! - Inspection (from the `topology` crate, on the exact predicates
//!   [`orient2d`] and [`orient3d`]): [`check_polygon_set`] (topological
//!   validity, coordinate validity, exact count of crossing edge pairs),
//!   [`check_mesh`] (2-manifoldness, exact self-intersecting facet pairs,
//!   signed volume, bounding box), also as methods of the shapes
//!   (`mesh.check()`, `mesh.signed_volume()`, `mesh.bounding_box()`,
//!   `mesh.self_intersections()`, `mesh.manifold_report()`).
//! - Pictures (feature `render`, on by default): [`render_mesh`] and
//!   [`render_polygons`] to an [`Image`] (PNG by [`Image::to_png`]),
//!   [`render_mesh_svg`] and [`render_polygons_svg`] to SVG text, with
//!   [`RenderOptions`] ([`View`], [`Style`], size, highlight).
//! - [`UmbraError`]: every error names the file and the problem on one
//!   line.
//! - Output encoded in memory before anything is written:
//!   [`encode_polygon_set`] (which also counts the rings as written) and
//!   [`encode_mesh`] ([`encode_mesh_with`] also gives the mesh the file
//!   holds, [`EncodedMesh::written`], which the reports count through
//!   [`WrittenMeshReport::written_as`]).
//!
//! # Example
//!
//! ```
//! use umbra::{boolean, read_wkt_str, write_wkt_string, BooleanOp, ReadOptions, RingOrientation};
//!
//! let a = read_wkt_str(
//!     "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))",
//!     ReadOptions::default(),
//! )?;
//! let b = read_wkt_str("POLYGON ((2 -1, 5 -1, 5 5, 2 5, 2 -1))", ReadOptions::default())?;
//!
//! let out = boolean(&a, &b, BooleanOp::Union)?;
//! assert!(out.shape.check_topology().is_ok());
//! // The 4x4 square minus its 2x2 hole, plus the 3x6 rectangle, less the
//! // overlap 2x4 of which the hole's right half (1x2) was already missing.
//! assert_eq!(out.shape.signed_area(), 12.0 + 18.0 - (8.0 - 2.0));
//!
//! let text = write_wkt_string(&out.shape, RingOrientation::ByRole)?;
//! assert!(text.starts_with("POLYGON (("));
//! let back = read_wkt_str(&text, ReadOptions::default())?;
//! assert_eq!(back.signed_area(), out.shape.signed_area());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

/// The guide's examples (`docs/guide.md`), run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../../../docs/guide.md")]
pub struct GuideDoctests;

#[cfg(feature = "io")]
mod encode;
mod error;
#[cfg(feature = "io")]
mod io;
mod model;
mod nary;
mod ops;
#[cfg(feature = "render")]
mod render;
mod report;
mod round_f32;
mod smoothing;

pub use boolean_2d::{
    boolean, boolean_with_contacts, planar_contacts, BooleanError, BooleanOutput, PlanarContacts,
    Timings as BooleanTimings,
};
pub use boolean_3d::{
    boolean_mesh, boolean_mesh_with_contacts, boolean_prepared, boolean_triangles,
    boolean_triangles_with_contacts, triangulate_mesh, Boolean3Error, Contacts, MeshOutput,
    PreparedTriangles, TriangleOutput,
};
#[cfg(feature = "io")]
pub use encode::{encode_mesh, encode_mesh_with, encode_polygon_set, EncodedMesh, EncodedPolygons};
pub use error::UmbraError;
#[cfg(feature = "io")]
pub use io::*;
pub use model::*;
pub use nary::{
    boolean_solids, difference_all_solids, union_all_solids, SolidsError, SolidsOutput,
};
pub use ops::{
    as_triangle_mesh, boolean_solid, boolean_solid_triangles, boolean_solid_with_contacts,
    regularized_operand, regularized_operands, turned_outward, MeshVariant, SolidOutput,
    TriangleSolidOutput, Via,
};
#[cfg(feature = "render")]
pub use render::*;
pub use report::{
    fill_rule_name, Boolean2Report, Boolean3Report, DemoReport, FileReport, MeshCounts, Operands,
    SetCounts, SimplifyReport, SmoothFileReport, SweepReport, Timings, WrittenFile,
    WrittenMeshReport,
};
pub use robust_arith::{
    orient2d, orient3d, validate_coordinate, ArithError, Point2, Point3, MAX_COORDINATE,
};
pub use round_f32::{round_to_f32, F32Rounding, RoundedMesh, RoundedToF32};
pub use simplify_2d::{
    boolean as boolean_via_simplify, boolean_n, boolean_sets, simplify, union_all, FillRule,
    Simplified, SimplifyError, SweepStats,
};
pub use smooth::{
    smooth_mesh, smooth_mesh_near, smooth_polygon_set, smooth_polygon_set_near, smooth_triangles,
    smooth_triangles_near, MeshDefects, Reverted, SmoothCounts, SmoothError, SmoothOptions,
    SmoothReport, Smoothed,
};
pub use smoothing::{
    boolean_for_smoothing, default_boolean_set_tolerance, default_mesh_tolerance,
    default_set_tolerance, smooth_csg_result, smooth_set_result, smooth_solid, smooth_solid_near,
    DEFAULT_RELATIVE_TOLERANCE,
};
pub use topology::{
    check_mesh, check_polygon_set, mesh_signed_volume, ring_side, ring_signed_area, BooleanOp,
    CheckReport, Edge2, EdgeUse, Facet, HalfEdge, ManifoldReport, MeshCheckReport, Operand,
    PolygonMesh, PolygonSet2, RingIndex, RingSide, TopologyError, TriangleMesh,
};
