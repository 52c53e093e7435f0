//! Data smoothing (dissertation chapter 5 and Appendix A): a post-process
//! for the results of the basic Boolean and the simplification sweep that
//! resolves features below a length tolerance `delta` (gaps, slivers,
//! coincident facets, zero-length edges) by topological operations only,
//! so the closure constraints of section 4.2 hold after every step.
//!
//! - [`SmoothOptions`]: the tolerance and the safety budget.
//! - [`SmoothReport`]: counts per operation ([`SmoothCounts`]), whether
//!   the budget was hit, the largest number of adjustments touching one
//!   region (the k of chapter 8) and the distortion bound it gives.
//! - [`Smoothed`]: a smoothed shape with its report.
//! - [`smooth_mesh`], [`smooth_triangles`]: Appendix A on polygon and
//!   triangle meshes, in an order of phases that terminates by design;
//!   [`sanity_check_mesh`], [`sanity_check_triangles`]: their
//!   postconditions, for tests, `xtask` and fuzzing.
//!
//! The vertex adjustment of Appendix A (greedy acceptance: a vertex within
//! `delta` of an already accepted vertex is merged into it) runs on a
//! spatial hash grid, never over all pairs.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod error;
mod grid;
mod mesh;
mod options;
mod planar;
mod report;

pub use error::SmoothError;
pub use grid::{merge_vertices, VertexMerge};
pub use mesh::{
    sanity_check_mesh, sanity_check_triangles, smooth_mesh, smooth_mesh_near, smooth_triangles,
    smooth_triangles_near, MAX_GROWTHS, REACH,
};
pub use options::SmoothOptions;
pub use planar::{
    sanity_check_polygon_set, smooth_polygon_set, smooth_polygon_set_near, PlanarDefect,
    MAX_PLANAR_PASSES,
};
pub use report::{MeshDefects, Reverted, SmoothCounts, SmoothReport, Smoothed};
