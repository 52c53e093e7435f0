//! The error type: which constraint of section 4.2 is violated, and where.

use robust_arith::ArithError;
use std::fmt;

/// A violated data definition, topological constraint (section 4.2) or
/// coordinate requirement (section 8.5).
#[derive(Clone, Debug, PartialEq)]
pub enum TopologyError {
    /// An edge, half-edge or triangle refers to a vertex that does not exist.
    DanglingIndex {
        /// The kind of entity holding the reference ("edge", "facet", "triangle").
        entity: &'static str,
        /// The index of that entity.
        entity_index: u32,
        /// The out-of-range vertex index.
        vertex: u32,
        /// The number of vertices.
        vertex_count: u32,
    },
    /// 2D shape boundary closure: the (multiplicity-weighted) number of
    /// edges ending at a vertex differs from the number starting there.
    ShapeClosure2 {
        /// The vertex.
        vertex: u32,
        /// Weighted number of edges ending at the vertex.
        ending: i64,
        /// Weighted number of edges starting at the vertex.
        starting: i64,
    },
    /// Facet boundary closure: within one facet, the number of half-edges
    /// ending at a vertex differs from the number starting there.
    FacetClosure {
        /// The facet.
        facet: u32,
        /// The vertex.
        vertex: u32,
        /// Half-edges of the facet ending at the vertex.
        ending: u32,
        /// Half-edges of the facet starting at the vertex.
        starting: u32,
    },
    /// Triangular facet loop: a triangle's half-edges do not form one loop.
    /// (Only reachable through future representations; a `[u32; 3]` always
    /// forms a loop.)
    TriangleLoop {
        /// The triangle.
        triangle: u32,
    },
    /// 3D shape boundary closure: the number of half-edges from `start` to
    /// `end` differs from the number from `end` to `start`.
    ShapeClosure3 {
        /// Start vertex of the forward half-edges.
        start: u32,
        /// End vertex of the forward half-edges.
        end: u32,
        /// Half-edges from `start` to `end`.
        forward: u32,
        /// Half-edges from `end` to `start`.
        backward: u32,
    },
    /// A coordinate is NaN, infinite or beyond `f64::MAX / 4`.
    BadCoordinate {
        /// The vertex.
        vertex: u32,
        /// The axis (0 = x, 1 = y, 2 = z).
        axis: u8,
        /// What is wrong with the value.
        source: ArithError,
    },
}

impl fmt::Display for TopologyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TopologyError::DanglingIndex {
                entity,
                entity_index,
                vertex,
                vertex_count,
            } => write!(
                f,
                "dangling index: {entity} {entity_index} refers to vertex {vertex}, but there are only {vertex_count} vertices"
            ),
            TopologyError::ShapeClosure2 {
                vertex,
                ending,
                starting,
            } => write!(
                f,
                "shape boundary closure violated at vertex {vertex}: {ending} edge(s) end there but {starting} start there"
            ),
            TopologyError::FacetClosure {
                facet,
                vertex,
                ending,
                starting,
            } => write!(
                f,
                "facet boundary closure violated in facet {facet} at vertex {vertex}: {ending} half-edge(s) end there but {starting} start there"
            ),
            TopologyError::TriangleLoop { triangle } => {
                write!(f, "triangle {triangle} does not form a single loop")
            }
            TopologyError::ShapeClosure3 {
                start,
                end,
                forward,
                backward,
            } => write!(
                f,
                "shape boundary closure violated on edge {start}-{end}: {forward} half-edge(s) {start}->{end} but {backward} half-edge(s) {end}->{start} (open or inconsistently oriented mesh)"
            ),
            TopologyError::BadCoordinate {
                vertex,
                axis,
                source,
            } => {
                let name = ["x", "y", "z"].get(*axis as usize).copied().unwrap_or("?");
                write!(f, "vertex {vertex}: {name} {source}")
            }
        }
    }
}

impl std::error::Error for TopologyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            TopologyError::BadCoordinate { source, .. } => Some(source),
            _ => None,
        }
    }
}
