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
    /// Adds the counts of a later run on this run's output.
    pub(crate) fn add(&mut self, o: &SmoothCounts) {
        let SmoothCounts {
            vertices_merged,
            edges_cracked_by_vertex,
            edges_cracked_between_edges,
            vertices_created,
            half_edges_cancelled,
            facets_cancelled,
            facets_partially_cancelled,
            zero_length_edges_removed,
            empty_facets_removed,
            unreferenced_vertices_removed,
            facets_retriangulated,
            crossings_resolved,
        } = *o;
        self.vertices_merged += vertices_merged;
        self.edges_cracked_by_vertex += edges_cracked_by_vertex;
        self.edges_cracked_between_edges += edges_cracked_between_edges;
        self.vertices_created += vertices_created;
        self.half_edges_cancelled += half_edges_cancelled;
        self.facets_cancelled += facets_cancelled;
        self.facets_partially_cancelled += facets_partially_cancelled;
        self.zero_length_edges_removed += zero_length_edges_removed;
        self.empty_facets_removed += empty_facets_removed;
        self.unreferenced_vertices_removed += unreferenced_vertices_removed;
        self.facets_retriangulated += facets_retriangulated;
        self.crossings_resolved += crossings_resolved;
    }

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
    /// Set when [`crate::SmoothOptions::guard`] undid smoothing because it
    /// would have left more defects than the input had where it changed
    /// it. Undone everywhere ([`Reverted::is_partial`] false), the input
    /// is handed back and the counts above are zero (nothing changed);
    /// undone only at the places that were worse, the counts and bounds
    /// above are smoothing's (they include the operations undone there).
    /// This says what was undone.
    pub reverted: Option<Reverted>,
}

/// Defects of a mesh near the facets smoothing changed (or would have):
/// the counts the guard compares.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct MeshDefects {
    /// Facet pairs that intersect other than in shared vertices and
    /// edges (the exact test of `topology::self_intersecting_pairs_near`).
    pub intersecting_pairs: usize,
    /// Edges used both ways but not exactly once each way.
    pub non_manifold_edges: usize,
    /// Vertices around which the facet corners form more than one fan.
    pub non_manifold_vertices: usize,
    /// Edges used in one direction only.
    pub open_edges: usize,
}

impl MeshDefects {
    /// Whether any count is above zero.
    pub fn any(&self) -> bool {
        *self != MeshDefects::default()
    }

    /// The non-manifold and open edges and non-manifold vertices
    /// together: places where the surface is not a closed 2-manifold.
    pub fn manifold_defects(&self) -> usize {
        self.non_manifold_edges + self.non_manifold_vertices + self.open_edges
    }

    /// The guard's rule: more intersecting facet pairs, or as many and
    /// more [`MeshDefects::manifold_defects`]. Pairs come first: they make
    /// the solid geometrically invalid (its surface passes through
    /// itself), while a pinch or an edge shared by four facets is a valid
    /// topology that smoothing legitimately makes where two parts lie
    /// within the tolerance of each other (and the Boolean makes where
    /// solids touch). So smoothing that removes rounding's intersecting
    /// pairs at the price of a pinch is kept.
    ///
    /// ```
    /// use smooth::MeshDefects;
    /// let clean = MeshDefects::default();
    /// let pairs = MeshDefects { intersecting_pairs: 3, ..clean };
    /// let pinch = MeshDefects { non_manifold_vertices: 1, ..clean };
    /// assert!(pairs.worse_than(&clean) && !clean.worse_than(&pairs));
    /// assert!(pinch.worse_than(&clean));
    /// assert!(pairs.worse_than(&pinch) && !pinch.worse_than(&pairs));
    /// assert!(!pairs.worse_than(&pairs));
    /// ```
    pub fn worse_than(&self, other: &MeshDefects) -> bool {
        (self.intersecting_pairs, self.manifold_defects())
            > (other.intersecting_pairs, other.manifold_defects())
    }
}

impl std::fmt::Display for MeshDefects {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} intersecting facet pairs, {} non-manifold edges, {} non-manifold vertices, {} open edges",
            self.intersecting_pairs, self.non_manifold_edges, self.non_manifold_vertices, self.open_edges
        )
    }
}

impl std::fmt::Display for Reverted {
    /// One sentence for front ends' messages.
    ///
    /// ```
    /// use smooth::{MeshDefects, Reverted};
    /// let r = Reverted {
    ///     smoothed: MeshDefects { intersecting_pairs: 15, ..MeshDefects::default() },
    ///     ..Reverted::default()
    /// };
    /// assert!(r.to_string().starts_with("smoothing undone: its 0 adjustments would have left 15 intersecting facet pairs"));
    /// // Undone at some of the places smoothing changed, kept at the others.
    /// let some = Reverted { places: 3, undone: 1, ..r };
    /// assert!(some.is_partial());
    /// assert!(some.to_string().starts_with("smoothing undone at 1 of the 3 places it changed"));
    /// assert!(some.to_string().ends_with("kept elsewhere"));
    /// ```
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.is_partial() {
            return write!(
                f,
                "smoothing undone at {} of the {} places it changed: there it would have left {} where the unsmoothed mesh has {}; kept elsewhere",
                self.undone, self.places, self.smoothed, self.input
            );
        }
        write!(
            f,
            "smoothing undone: its {} adjustments would have left {} where the unsmoothed mesh has {}; the mesh is kept as it was",
            self.counts.adjustments(),
            self.smoothed,
            self.input
        )
    }
}

/// What the guard undid ([`SmoothReport::reverted`]).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Reverted {
    /// The defects smoothing would have left near what it undid.
    pub smoothed: MeshDefects,
    /// The input's defects at the same places (kept).
    pub input: MeshDefects,
    /// The operations smoothing had made (all of them; undone where
    /// smoothing was undone).
    pub counts: SmoothCounts,
    /// The places smoothing changed: the connected patches of changed
    /// facets (joined where they share a vertex position).
    pub places: usize,
    /// The places undone: all of them, or the ones where smoothing left
    /// more defects than the input had there (the others keep smoothing).
    pub undone: usize,
}

impl Reverted {
    /// Whether smoothing was undone only at some of the places it
    /// changed (and kept at the others).
    pub fn is_partial(&self) -> bool {
        self.undone < self.places
    }
}

/// A smoothed shape and its report.
#[derive(Clone, Debug, PartialEq)]
pub struct Smoothed<T> {
    /// The smoothed shape, topologically valid whenever the input was.
    pub shape: T,
    /// What smoothing did.
    pub report: SmoothReport,
}
