//! `PolygonMesh`: a polyhedral shape whose facets are collections of
//! half-edges (section 4.2, "Polygon mesh").

use crate::{validate_points, TopologyError};
use robust_arith::Point3;
use std::collections::HashMap;

/// A half-edge: a directed link from vertex `start` to vertex `end`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct HalfEdge {
    /// The start-vertex index.
    pub start: u32,
    /// The end-vertex index.
    pub end: u32,
}

/// A facet: a collection of half-edges. Facet boundary closure (section 4.2)
/// requires every vertex to start as many of the facet's half-edges as it
/// ends, so the half-edges form loops: an outer boundary and holes, or
/// several regions. The facet faces the side from which its outer loops run
/// anticlockwise.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Facet {
    /// The half-edges, in no required order.
    pub half_edges: Vec<HalfEdge>,
}

impl Facet {
    /// A facet bounded by one loop through the given vertices.
    pub fn from_loop(vertices: &[u32]) -> Facet {
        let mut f = Facet::default();
        f.push_loop(vertices);
        f
    }

    /// A facet bounded by several loops (e.g. an outer loop and holes).
    pub fn from_loops(loops: &[Vec<u32>]) -> Facet {
        let mut f = Facet::default();
        for l in loops {
            f.push_loop(l);
        }
        f
    }

    /// Adds the half-edges of one closed loop.
    pub fn push_loop(&mut self, vertices: &[u32]) {
        let n = vertices.len();
        for i in 0..n {
            self.half_edges.push(HalfEdge {
                start: vertices[i],
                end: vertices[(i + 1) % n],
            });
        }
    }

    /// Chains the half-edges into closed loops of vertex indices. Valid only
    /// when the facet satisfies facet boundary closure; half-edges that
    /// cannot be chained are returned as open chains.
    pub fn loops(&self) -> Vec<Vec<u32>> {
        let mut outgoing: HashMap<u32, Vec<usize>> = HashMap::new();
        for (i, h) in self.half_edges.iter().enumerate().rev() {
            outgoing.entry(h.start).or_default().push(i);
        }
        let mut used = vec![false; self.half_edges.len()];
        let mut loops = Vec::new();
        for first in 0..self.half_edges.len() {
            if used[first] {
                continue;
            }
            used[first] = true;
            let start = self.half_edges[first].start;
            let mut ring = vec![start];
            let mut at = self.half_edges[first].end;
            while at != start {
                let next = outgoing.get_mut(&at).and_then(|l| {
                    while let Some(&i) = l.last() {
                        if used[i] {
                            l.pop();
                        } else {
                            return Some(i);
                        }
                    }
                    None
                });
                match next {
                    Some(i) => {
                        used[i] = true;
                        ring.push(at);
                        at = self.half_edges[i].end;
                    }
                    None => break,
                }
            }
            loops.push(ring);
        }
        loops
    }
}

/// A polyhedral shape as vertices and facets (section 4.2). Non-manifold
/// edges (several half-edge pairs), several shells, coincident vertices and
/// zero-length edges are all topologically valid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonMesh {
    /// The vertex positions.
    pub vertices: Vec<Point3>,
    /// The facets.
    pub facets: Vec<Facet>,
}

impl PolygonMesh {
    /// A mesh from vertices and facets (unchecked).
    pub fn new(vertices: Vec<Point3>, facets: Vec<Facet>) -> Self {
        PolygonMesh { vertices, facets }
    }

    /// The total number of half-edges.
    pub fn half_edge_count(&self) -> usize {
        self.facets.iter().map(|f| f.half_edges.len()).sum()
    }

    /// Checks the data definitions, facet boundary closure for every facet
    /// and shape boundary closure (section 4.2).
    pub fn check_topology(&self) -> Result<(), TopologyError> {
        let n = self.vertices.len() as u32;
        for (fi, f) in self.facets.iter().enumerate() {
            for h in &f.half_edges {
                for v in [h.start, h.end] {
                    if v >= n {
                        return Err(TopologyError::DanglingIndex {
                            entity: "facet",
                            entity_index: fi as u32,
                            vertex: v,
                            vertex_count: n,
                        });
                    }
                }
            }
        }
        // Facet boundary closure.
        let mut balance: HashMap<u32, (u32, u32)> = HashMap::new();
        for (fi, f) in self.facets.iter().enumerate() {
            balance.clear();
            for h in &f.half_edges {
                balance.entry(h.end).or_default().0 += 1;
                balance.entry(h.start).or_default().1 += 1;
            }
            let mut bad: Vec<_> = balance
                .iter()
                .filter(|(_, (e, s))| e != s)
                .map(|(&v, &(e, s))| (v, e, s))
                .collect();
            bad.sort_unstable();
            if let Some(&(vertex, ending, starting)) = bad.first() {
                return Err(TopologyError::FacetClosure {
                    facet: fi as u32,
                    vertex,
                    ending,
                    starting,
                });
            }
        }
        check_shape_closure(
            self.facets
                .iter()
                .flat_map(|f| f.half_edges.iter().map(|h| (h.start, h.end))),
        )
    }

    /// Checks every coordinate (finite, at most `f64::MAX / 4`).
    pub fn validate_coordinates(&self) -> Result<(), TopologyError> {
        validate_points(&self.vertices)
    }

    /// The same mesh with every facet turned over: each half-edge
    /// reversed, each loop walked backwards (winding numbers negated, so
    /// inside and outside swap). Both closure constraints hold for the
    /// result exactly when they hold for `self`.
    pub fn reversed(&self) -> PolygonMesh {
        PolygonMesh {
            vertices: self.vertices.clone(),
            facets: self
                .facets
                .iter()
                .map(|f| Facet {
                    half_edges: f
                        .half_edges
                        .iter()
                        .rev()
                        .map(|h| HalfEdge {
                            start: h.end,
                            end: h.start,
                        })
                        .collect(),
                })
                .collect(),
        }
    }
}

/// Shape boundary closure over a stream of half-edges: for every vertex pair
/// the number of half-edges `P -> Q` equals the number `Q -> P`.
pub(crate) fn check_shape_closure(
    half_edges: impl Iterator<Item = (u32, u32)>,
) -> Result<(), TopologyError> {
    // Per unordered vertex pair: (half-edges low->high, half-edges high->low).
    let mut count: HashMap<(u32, u32), (u32, u32)> = HashMap::new();
    for (s, e) in half_edges {
        if s == e {
            continue; // a zero-length half-edge is its own reverse
        }
        if s < e {
            count.entry((s, e)).or_default().0 += 1;
        } else {
            count.entry((e, s)).or_default().1 += 1;
        }
    }
    let mut bad: Vec<_> = count.into_iter().filter(|(_, (f, b))| f != b).collect();
    bad.sort_unstable();
    match bad.first() {
        Some(&((start, end), (forward, backward))) => Err(TopologyError::ShapeClosure3 {
            start,
            end,
            forward,
            backward,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit cube. A local copy of `test_support::shapes::box_mesh`:
    /// `test-support` depends on this crate, so here its meshes would be a
    /// second, foreign `PolygonMesh` type.
    fn cube() -> PolygonMesh {
        let mut v = Vec::new();
        for i in 0..8u32 {
            v.push([
                f64::from(i & 1),
                f64::from((i >> 1) & 1),
                f64::from((i >> 2) & 1),
            ]);
        }
        let faces: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        PolygonMesh::new(v, faces.iter().map(|f| Facet::from_loop(f)).collect())
    }

    #[test]
    fn cube_is_closed() {
        let c = cube();
        assert_eq!(c.check_topology(), Ok(()));
        assert_eq!(c.half_edge_count(), 24);
    }

    #[test]
    fn missing_face_breaks_shape_closure() {
        let mut c = cube();
        c.facets.pop();
        assert!(matches!(
            c.check_topology(),
            Err(TopologyError::ShapeClosure3 { .. })
        ));
    }

    #[test]
    fn open_facet_breaks_facet_closure() {
        let mut c = cube();
        c.facets[0].half_edges.pop();
        assert!(matches!(
            c.check_topology(),
            Err(TopologyError::FacetClosure { facet: 0, .. })
        ));
    }

    #[test]
    fn facet_with_hole_has_two_loops() {
        let f = Facet::from_loops(&[vec![0, 1, 2, 3], vec![4, 7, 6, 5]]);
        let loops = f.loops();
        assert_eq!(loops.len(), 2);
        assert_eq!(loops[0], vec![0, 1, 2, 3]);
    }
}
