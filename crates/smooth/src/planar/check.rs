//! The checker of a smoothed polygon set: what 2D smoothing guarantees,
//! tested directly (exact predicates for crossings, the broad phase for
//! pairs), for tests, `xtask` and fuzz targets.

use super::broad::{edge_pairs, segment_box, VertexIndex};
use super::geom::{cracks_at, dist2, edges_conflict};
use super::work::WEdge;
use crate::merge_vertices;
use std::fmt;
use topology::{PolygonSet2, TopologyError};

/// A way in which a polygon set is not as smoothing leaves it.
#[derive(Clone, Debug, PartialEq)]
pub enum PlanarDefect {
    /// A closure constraint, an index or a coordinate is invalid.
    Topology(TopologyError),
    /// Two entries join the same vertex pair, or an entry's multiplicity
    /// is not 1 (a smoothed set has unit edges, one per vertex pair).
    Multiplicity {
        /// The edge index.
        edge: usize,
    },
    /// An edge not longer than the tolerance (or from a vertex to itself).
    ShortEdge {
        /// The edge index.
        edge: usize,
    },
    /// Two vertices within the tolerance of each other.
    CloseVertices {
        /// The earlier vertex.
        a: u32,
        /// The later vertex.
        b: u32,
    },
    /// A vertex within the tolerance of an edge's interior (or exactly on
    /// it) where cracking would make both parts shorter (Appendix A).
    VertexNearEdge {
        /// The vertex.
        vertex: u32,
        /// The edge index.
        edge: usize,
    },
    /// Two edges meet other than at a vertex they share.
    Crossing {
        /// One edge index.
        a: usize,
        /// The other edge index.
        b: usize,
    },
    /// The simplification sweep failed on the set (a bug there).
    Sweep(String),
    /// An edge does not separate winding number 1 from 0 (an inside-out
    /// or multiply enclosed region), by the sweep's cell structure.
    Winding {
        /// The edge index.
        edge: usize,
        /// The winding number on its left.
        left: i32,
        /// The winding number on its right.
        right: i32,
    },
}

impl fmt::Display for PlanarDefect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlanarDefect::Topology(e) => write!(f, "invalid set: {e}"),
            PlanarDefect::Multiplicity { edge } => {
                write!(
                    f,
                    "edge {edge} repeats a vertex pair or has multiplicity other than 1"
                )
            }
            PlanarDefect::ShortEdge { edge } => {
                write!(f, "edge {edge} is not longer than the tolerance")
            }
            PlanarDefect::CloseVertices { a, b } => {
                write!(f, "vertices {a} and {b} lie within the tolerance")
            }
            PlanarDefect::VertexNearEdge { vertex, edge } => {
                write!(
                    f,
                    "vertex {vertex} lies within the tolerance of edge {edge}'s interior"
                )
            }
            PlanarDefect::Crossing { a, b } => {
                write!(f, "edges {a} and {b} cross, touch or overlap")
            }
            PlanarDefect::Sweep(m) => write!(f, "the winding check failed: {m}"),
            PlanarDefect::Winding { edge, left, right } => write!(
                f,
                "edge {edge} has winding number {left} on its left and {right} on its right, not 1 and 0"
            ),
        }
    }
}

impl std::error::Error for PlanarDefect {}

/// Checks that `set` is as 2D smoothing with `tolerance` leaves it:
/// topologically valid, unit edges (one per vertex pair), no edge of
/// length at most `tolerance`, no two vertices within `tolerance`, no
/// vertex within `tolerance` of an edge's interior that Appendix A's rule
/// would crack it at (both parts strictly shorter), no two edges that
/// cross, touch or overlap (exact), and every edge with winding number 1
/// on its left and 0 on its right (the cell structure of the
/// simplification sweep, exact on a set without crossings). Cost
/// `O(n log n)` plus the pairs of the broad phase.
pub fn sanity_check_polygon_set(set: &PolygonSet2, tolerance: f64) -> Result<(), PlanarDefect> {
    set.validate_coordinates().map_err(PlanarDefect::Topology)?;
    set.check_topology().map_err(PlanarDefect::Topology)?;
    let pts = set.vertices();
    let mut seen = std::collections::HashSet::new();
    let mut edges = Vec::with_capacity(set.edge_count());
    for (i, e) in set.edges().iter().enumerate() {
        if e.mult != 1 || !seen.insert((e.start.min(e.end), e.start.max(e.end))) {
            return Err(PlanarDefect::Multiplicity { edge: i });
        }
        let (p, q) = set.edge_points(e);
        if e.start == e.end || dist2(&p, &q) <= tolerance * tolerance {
            return Err(PlanarDefect::ShortEdge { edge: i });
        }
        edges.push(WEdge::directed(e.start, e.end, 1));
    }
    let m = merge_vertices(pts, tolerance);
    if let Some(b) = (0..pts.len()).find(|&v| m.representative[v] as usize != v) {
        return Err(PlanarDefect::CloseVertices {
            a: m.representative[b],
            b: b as u32,
        });
    }
    let index = VertexIndex::new(pts);
    let tol2 = tolerance * tolerance;
    for (i, e) in edges.iter().enumerate() {
        let (pa, pb) = (pts[e.a as usize], pts[e.b as usize]);
        let (lo, hi) = segment_box(pa, pb, tolerance);
        // The least such vertex, whatever order the index gives them in.
        let mut near: Option<u32> = None;
        index.visit(lo, hi, |v| {
            if v != e.a && v != e.b && cracks_at(pts[v as usize], pa, pb, tol2) {
                near = Some(near.map_or(v, |u| u.min(v)));
            }
        });
        if let Some(v) = near {
            return Err(PlanarDefect::VertexNearEdge { vertex: v, edge: i });
        }
    }
    let crossing = edge_pairs(pts, &edges, 0.0, |i, j| {
        let (e, f) = (edges[i], edges[j]);
        edges_conflict([e.a, e.b], [f.a, f.b], pts)
    });
    if let Some(&(a, b)) = crossing.first() {
        return Err(PlanarDefect::Crossing { a, b });
    }
    let cells = simplify_2d::cell_structure(set).map_err(|e| match e {
        simplify_2d::SimplifyError::InvalidInput { source, .. } => PlanarDefect::Topology(source),
        other => PlanarDefect::Sweep(other.to_string()),
    })?;
    for e in cells.edges() {
        if e.mult != 0 && !(e.left.max(e.right) == 1 && e.left.min(e.right) == 0) {
            return Err(PlanarDefect::Winding {
                edge: e.origin as usize,
                left: e.left,
                right: e.right,
            });
        }
    }
    Ok(())
}
