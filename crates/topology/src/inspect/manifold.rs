//! 2-manifoldness of a polygon mesh: every edge with exactly one half-edge
//! each way, and the facets around every vertex forming one fan.

use crate::{PolygonMesh, TopologyError, TriangleMesh};
use std::collections::HashMap;

/// The use of one edge (an unordered vertex pair `a < b`, or `a == b` for
/// a zero-length half-edge) by the half-edges of a mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EdgeUse {
    /// The smaller vertex id.
    pub a: u32,
    /// The larger vertex id.
    pub b: u32,
    /// Half-edges `a -> b` (a zero-length half-edge counts here).
    pub forward: u32,
    /// Half-edges `b -> a`.
    pub backward: u32,
}

/// Where a mesh fails to be a closed 2-manifold
/// ([`PolygonMesh::manifold_report`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ManifoldReport {
    /// The number of edges (unordered vertex pairs joined by half-edges).
    pub edges: usize,
    /// Edges used in one direction only (a boundary of an open surface),
    /// sorted.
    pub open_edges: Vec<EdgeUse>,
    /// Edges used both ways but not exactly once each way (several sheets
    /// meet there), sorted.
    pub non_manifold_edges: Vec<EdgeUse>,
    /// Vertices around which the facet corners form more than one fan
    /// (e.g. two solids touching at a point), sorted.
    pub non_manifold_vertices: Vec<u32>,
}

impl ManifoldReport {
    /// No open or non-manifold edge and no non-manifold vertex.
    pub fn is_two_manifold(&self) -> bool {
        self.open_edges.is_empty()
            && self.non_manifold_edges.is_empty()
            && self.non_manifold_vertices.is_empty()
    }
}

impl PolygonMesh {
    /// Where the mesh fails to be a closed 2-manifold; an error when the
    /// mesh is not topologically valid ([`PolygonMesh::check_topology`]).
    ///
    /// ```
    /// use topology::{Facet, PolygonMesh};
    /// let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let loops = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    /// let tetra = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
    /// let r = tetra.manifold_report().unwrap();
    /// assert!(r.is_two_manifold());
    /// assert_eq!(r.edges, 6);
    /// ```
    pub fn manifold_report(&self) -> Result<ManifoldReport, TopologyError> {
        self.check_topology()?;
        let (edges, open_edges, non_manifold_edges) = edge_census(self);
        Ok(ManifoldReport {
            edges,
            open_edges,
            non_manifold_edges,
            non_manifold_vertices: non_manifold_vertices(self),
        })
    }
}

impl TriangleMesh {
    /// [`PolygonMesh::manifold_report`] of the same shape.
    pub fn manifold_report(&self) -> Result<ManifoldReport, TopologyError> {
        self.to_polygon_mesh().manifold_report()
    }
}

/// The number of edges, the open ones and the non-manifold ones (sorted).
/// Any indices (no vertex is looked up).
pub(super) fn edge_census(mesh: &PolygonMesh) -> (usize, Vec<EdgeUse>, Vec<EdgeUse>) {
    let mut count: HashMap<(u32, u32), (u32, u32)> = HashMap::new();
    for h in mesh.facets.iter().flat_map(|f| &f.half_edges) {
        let key = (h.start.min(h.end), h.start.max(h.end));
        let c = count.entry(key).or_default();
        if h.start <= h.end {
            c.0 += 1;
        } else {
            c.1 += 1;
        }
    }
    let mut open = Vec::new();
    let mut non_manifold = Vec::new();
    for (&(a, b), &(forward, backward)) in &count {
        if (forward, backward) == (1, 1) {
            continue;
        }
        let e = EdgeUse {
            a,
            b,
            forward,
            backward,
        };
        if forward == 0 || backward == 0 {
            open.push(e);
        } else {
            non_manifold.push(e);
        }
    }
    open.sort_unstable();
    non_manifold.sort_unstable();
    (count.len(), open, non_manifold)
}

/// Vertices around which the facet corners form more than one fan, sorted:
/// the corners at `v` join the edge they come in by to the edge they leave
/// by; on a 2-manifold these links make one cycle per vertex. Requires a
/// topologically valid mesh.
pub(super) fn non_manifold_vertices(mesh: &PolygonMesh) -> Vec<u32> {
    // For every vertex, its corners as (incoming neighbour, outgoing
    // neighbour).
    let mut corners: Vec<(u32, u32, u32)> = Vec::new();
    for f in &mesh.facets {
        for l in f.loops() {
            let k = l.len();
            for i in 0..k {
                corners.push((l[i], l[(i + k - 1) % k], l[(i + 1) % k]));
            }
        }
    }
    corners.sort_unstable();
    let mut bad = Vec::new();
    let mut i = 0;
    while i < corners.len() {
        let v = corners[i].0;
        let mut j = i;
        while j < corners.len() && corners[j].0 == v {
            j += 1;
        }
        // Union-find over the neighbours of v, joined by corners.
        let mut nodes: Vec<u32> = corners[i..j].iter().flat_map(|c| [c.1, c.2]).collect();
        nodes.sort_unstable();
        nodes.dedup();
        let mut parent: Vec<usize> = (0..nodes.len()).collect();
        fn find(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        let index = |u: u32| nodes.binary_search(&u).unwrap_or(0);
        for c in &corners[i..j] {
            let (a, b) = (find(&mut parent, index(c.1)), find(&mut parent, index(c.2)));
            parent[a] = b;
        }
        let roots = (0..nodes.len())
            .filter(|&x| find(&mut parent, x) == x)
            .count();
        if roots > 1 {
            bad.push(v);
        }
        i = j;
    }
    bad
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Facet;

    fn mesh(v: Vec<[f64; 3]>, loops: &[Vec<u32>]) -> PolygonMesh {
        PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect())
    }

    #[test]
    fn open_and_non_manifold_edges_are_named() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        // A tetrahedron with one face doubled: the doubled face's edges
        // carry two half-edges one way and one the other... plus the
        // reversed copy keeps closure.
        let tetra = vec![vec![0, 2, 1], vec![0, 1, 3], vec![1, 2, 3], vec![0, 3, 2]];
        let mut doubled = tetra.clone();
        doubled.push(vec![0, 1, 2]);
        doubled.push(vec![0, 2, 1]);
        let r = mesh(v.clone(), &doubled).manifold_report().unwrap();
        assert!(!r.is_two_manifold());
        assert_eq!(r.edges, 6);
        assert!(r.open_edges.is_empty());
        let named: Vec<(u32, u32)> = r.non_manifold_edges.iter().map(|e| (e.a, e.b)).collect();
        assert_eq!(named, vec![(0, 1), (0, 2), (1, 2)]);
        assert!(r
            .non_manifold_edges
            .iter()
            .all(|e| e.forward + e.backward == 4));
        // Open: the tetrahedron's topology error refuses the report; the
        // census still names the open edges.
        let open = mesh(v, &tetra[..3]);
        assert!(open.manifold_report().is_err());
        let (edges, open_edges, bad) = edge_census(&open);
        assert_eq!(edges, 6);
        assert!(bad.is_empty());
        let named: Vec<(u32, u32)> = open_edges.iter().map(|e| (e.a, e.b)).collect();
        assert_eq!(named, vec![(0, 2), (0, 3), (2, 3)]);
    }

    #[test]
    fn two_tetrahedra_touching_at_a_vertex() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, -1.0],
        ];
        let t = |a: u32, b: u32, c: u32, d: u32| {
            vec![vec![a, c, b], vec![a, b, d], vec![b, c, d], vec![a, d, c]]
        };
        let loops: Vec<Vec<u32>> = t(0, 1, 2, 3).into_iter().chain(t(0, 4, 5, 6)).collect();
        let m = mesh(v, &loops);
        let r = m.manifold_report().unwrap();
        assert_eq!(r.non_manifold_vertices, vec![0]);
        assert!(r.open_edges.is_empty() && r.non_manifold_edges.is_empty());
        let tri = TriangleMesh::new(
            m.vertices.clone(),
            loops.iter().map(|l| [l[0], l[1], l[2]]).collect(),
        );
        assert_eq!(tri.manifold_report(), Ok(r));
    }
}
