//! What a smoothing run did: counts per operation, the safety budget, the
//! adjustment count `k` of chapter 8 and the distortion bound.

use serde::Serialize;

/// The number of times each operation of Appendix A ran.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct SmoothCounts {
    /// Vertices merged into an accepted vertex within the tolerance.
    pub vertices_merged: u64,
    /// Edges split at an existing vertex near their interior.
    pub edges_cracked_by_vertex: u64,
    /// Edge pairs passing within the tolerance, both split at one vertex.
    pub edges_cracked_between_edges: u64,
    /// New vertices created by edge-edge cracking (not snapped to an
    /// existing vertex).
    pub vertices_created: u64,
    /// Pairs of opposing half-edges (or 2D edges) cancelled.
    pub half_edges_cancelled: u64,
    /// Opposing facet pairs cancelled in full.
    pub facets_cancelled: u64,
    /// Opposing facet pairs cancelled in part (half-edges swapped).
    pub facets_partially_cancelled: u64,
    /// Edges or half-edges whose ends coincide, removed.
    pub zero_length_edges_removed: u64,
    /// Facets left with no half-edges, removed.
    pub empty_facets_removed: u64,
    /// Vertices no edge refers to, removed.
    pub unreferenced_vertices_removed: u64,
    /// Facets re-triangulated (triangle meshes only).
    pub facets_retriangulated: u64,
    /// Crossings resolved by the simplification sweep (2D only).
    pub crossings_resolved: u64,
}

impl SmoothCounts {
    /// The number of adjustments made: every count above except the
    /// bookkeeping removals and re-triangulations.
    pub fn adjustments(&self) -> u64 {
        self.vertices_merged
            + self.edges_cracked_by_vertex
            + self.edges_cracked_between_edges
            + self.half_edges_cancelled
            + self.facets_cancelled
            + self.facets_partially_cancelled
            + self.crossings_resolved
    }
}

/// The report of one smoothing run.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SmoothReport {
    /// The tolerance `delta` used.
    pub tolerance: f64,
    /// Counts per operation.
    pub counts: SmoothCounts,
    /// Passes over the shape (each pass applies the operations in the
    /// fixed order of the algorithm note).
    pub passes: u32,
    /// Whether the safety budget stopped the run early (never expected:
    /// the process terminates by design; a hit is worth a bug report).
    pub budget_hit: bool,
    /// The largest number of position adjustments that touched one vertex
    /// of the result (the k of chapter 8).
    pub max_adjustments: u32,
    /// The bound on how far any vertex of the result lies from the
    /// position it had (or, for a created vertex, from the edges it was
    /// created on): `max_adjustments * tolerance`, or as the algorithm
    /// note derives it.
    pub distortion_bound: f64,
    /// The largest vertex displacement actually made.
    pub max_displacement: f64,
    /// The epsilon smoothing adds: the distortion bound (and in 2D the
    /// sweep's epsilon, when the sweep ran). A front end adds the input's
    /// own epsilon, e.g. the Boolean's, as `Boolean2Report::smoothed` does.
    pub epsilon: f64,
}

/// A smoothed shape and its report.
#[derive(Clone, Debug, PartialEq)]
pub struct Smoothed<T> {
    /// The smoothed shape, topologically valid whenever the input was.
    pub shape: T,
    /// What smoothing did.
    pub report: SmoothReport,
}
