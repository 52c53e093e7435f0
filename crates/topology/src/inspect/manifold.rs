//! 2-manifoldness of a polygon mesh: every edge with exactly one half-edge
//! each way, and the facets around every vertex forming one fan.

use crate::{PolygonMesh, TopologyError, TriangleMesh};
use rayon::prelude::*;
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

    /// The numbers of this report: what [`crate::check_mesh`] states, and
    /// what every other report of a mesh's 2-manifoldness should state
    /// (one definition of an open edge, a non-manifold edge and a
    /// non-manifold vertex).
    pub fn counts(&self) -> ManifoldCounts {
        ManifoldCounts {
            two_manifold: self.is_two_manifold(),
            open_edges: self.open_edges.len(),
            non_manifold_edges: self.non_manifold_edges.len(),
            non_manifold_vertices: self.non_manifold_vertices.len(),
        }
    }
}

/// The numbers of a [`ManifoldReport`] ([`ManifoldReport::counts`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ManifoldCounts {
    /// No open or non-manifold edge and no non-manifold vertex.
    pub two_manifold: bool,
    /// Edges used in one direction only (a zero-length half-edge `a -> a`
    /// makes one).
    pub open_edges: usize,
    /// Edges used both ways but not exactly once each way.
    pub non_manifold_edges: usize,
    /// Vertices around which the facet corners form more than one fan.
    pub non_manifold_vertices: usize,
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
        Ok(report_of_valid(self))
    }
}

/// [`PolygonMesh::manifold_report`] of a mesh known to be topologically
/// valid (the one place the report is made).
pub(super) fn report_of_valid(mesh: &PolygonMesh) -> ManifoldReport {
    let (edges, open_edges, non_manifold_edges) = edge_census(mesh);
    ManifoldReport {
        edges,
        open_edges,
        non_manifold_edges,
        non_manifold_vertices: non_manifold_vertices(mesh, &mesh.vertices),
    }
}

impl TriangleMesh {
    /// [`PolygonMesh::manifold_report`] of the same shape.
    pub fn manifold_report(&self) -> Result<ManifoldReport, TopologyError> {
        self.to_polygon_mesh().manifold_report()
    }

    /// [`PolygonMesh::manifold_report_near`] of the same shape (triangle
    /// `t` is facet `t`), without building its whole polygon mesh.
    pub fn manifold_report_near(&self, focus: &[bool]) -> Option<ManifoldReport> {
        let n = self.vertices.len() as u32;
        if !self.triangles.par_iter().all(|t| t.iter().all(|&v| v < n)) {
            return None;
        }
        Some(report_near(
            &self.vertices,
            self.triangles.len(),
            |t, out| out.extend(self.triangles[t]),
            |t| crate::Facet::from_loop(&self.triangles[t]),
            focus,
        ))
    }
}

impl PolygonMesh {
    /// [`PolygonMesh::manifold_report`] restricted to the vertices of the
    /// facets `f` with `focus[f]` (a focus shorter than the facet list
    /// counts as `false` beyond its end): the edges with an end at such a
    /// vertex, and those vertices. Every facet using such an edge or
    /// vertex is looked at, so the counts are exactly the whole report's,
    /// filtered, at a cost of one pass over the facets plus the focus's
    /// neighbourhood. Closure is not checked (call
    /// [`PolygonMesh::check_topology`] for that); `None` when an index is
    /// out of range.
    ///
    /// ```
    /// use topology::{Facet, PolygonMesh};
    /// // Two tetrahedra sharing only vertex 0: a pinch.
    /// let mut v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// v.extend([[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]);
    /// let loops = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2], [0, 4, 5], [0, 6, 4], [4, 6, 5], [0, 5, 6]];
    /// let m = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
    /// let far = m.manifold_report_near(&[false, false, true]).unwrap();
    /// assert!(far.non_manifold_vertices.is_empty());
    /// let near = m.manifold_report_near(&[true]).unwrap();
    /// assert_eq!(near.non_manifold_vertices, vec![0]);
    /// assert_eq!(near.non_manifold_vertices, m.manifold_report().unwrap().non_manifold_vertices);
    /// ```
    pub fn manifold_report_near(&self, focus: &[bool]) -> Option<ManifoldReport> {
        if !super::report::indices_in_range(self) {
            return None;
        }
        Some(report_near(
            &self.vertices,
            self.facets.len(),
            |f, out| out.extend(self.facets[f].half_edges.iter().map(|h| h.start)),
            |f| self.facets[f].clone(),
            focus,
        ))
    }
}

/// The report near a focus over `count` facets given by their corner
/// indices (`corners`, every index in range of `positions`) and as facets.
fn report_near(
    positions: &[crate::Point3],
    count: usize,
    corners: impl Fn(usize, &mut Vec<u32>) + Sync,
    facet: impl Fn(usize) -> crate::Facet,
    focus: &[bool],
) -> ManifoldReport {
    let mut near = vec![false; positions.len()];
    let mut buf = Vec::new();
    for f in (0..count.min(focus.len())).filter(|&f| focus[f]) {
        buf.clear();
        corners(f, &mut buf);
        for &v in &buf {
            near[v as usize] = true;
        }
    }
    // Every facet with a corner at a focus vertex: all the half-edges of
    // the edges counted and all the corners of the vertices counted.
    let star_ids: Vec<usize> = (0..count)
        .into_par_iter()
        .map_init(Vec::new, |buf, f| {
            buf.clear();
            corners(f, buf);
            buf.iter().any(|&v| near[v as usize]).then_some(f)
        })
        .flatten()
        .collect();
    let star = PolygonMesh::new(Vec::new(), star_ids.into_iter().map(facet).collect());
    let touches = |e: &EdgeUse| near[e.a as usize] || near[e.b as usize];
    let (_, open, non_manifold) = edge_census(&star);
    let mut edges = std::collections::HashSet::new();
    for h in star.facets.iter().flat_map(|f| &f.half_edges) {
        if near[h.start as usize] || near[h.end as usize] {
            edges.insert((h.start.min(h.end), h.start.max(h.end)));
        }
    }
    ManifoldReport {
        edges: edges.len(),
        open_edges: open.into_iter().filter(touches).collect(),
        non_manifold_edges: non_manifold.into_iter().filter(touches).collect(),
        non_manifold_vertices: non_manifold_vertices(&star, positions)
            .into_iter()
            .filter(|&v| near[v as usize])
            .collect(),
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
/// by; on a 2-manifold these links make one cycle per vertex. Where a
/// facet passes a vertex more than once, its corners there pair edges by
/// the facet's geometry at `positions` ([`crate::Facet::loops_in_plane`]).
/// Requires a topologically valid mesh.
pub(super) fn non_manifold_vertices(mesh: &PolygonMesh, positions: &[crate::Point3]) -> Vec<u32> {
    // For every vertex, its corners as (incoming neighbour, outgoing
    // neighbour).
    let mut corners: Vec<(u32, u32, u32)> = Vec::new();
    for f in &mesh.facets {
        for l in f.loops_in_plane(positions) {
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

    proptest::proptest! {
        /// The report near a focus is the whole report filtered to the
        /// focus facets' vertices, on random triangle soups (open,
        /// non-manifold and repeated triangles included) and for the
        /// polygon and triangle forms alike.
        #[test]
        fn report_near_is_the_whole_report_filtered(
            tris in proptest::collection::vec([0u32..9, 0u32..9, 0u32..9], 1..24),
            mask in proptest::collection::vec(proptest::bool::ANY, 0..30),
        ) {
            let tris: Vec<[u32; 3]> =
                tris.into_iter().filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]).collect();
            let v = vec![[0.0; 3]; 9];
            let loops: Vec<Vec<u32>> = tris.iter().map(|t| t.to_vec()).collect();
            let m = mesh(v.clone(), &loops);
            let (_, open_all, nm_all) = edge_census(&m);
            let nmv_all = non_manifold_vertices(&m, &m.vertices);
            let mut near = [false; 9];
            for (t, _) in tris.iter().zip(&mask).filter(|(_, &k)| k) {
                for &c in t {
                    near[c as usize] = true;
                }
            }
            let touches = |e: &&EdgeUse| near[e.a as usize] || near[e.b as usize];
            let r = m.manifold_report_near(&mask).unwrap();
            let want_open: Vec<EdgeUse> = open_all.iter().filter(touches).copied().collect();
            let want_nm: Vec<EdgeUse> = nm_all.iter().filter(touches).copied().collect();
            let want_nmv: Vec<u32> = nmv_all.into_iter().filter(|&x| near[x as usize]).collect();
            proptest::prop_assert_eq!(&r.open_edges, &want_open);
            proptest::prop_assert_eq!(&r.non_manifold_edges, &want_nm);
            proptest::prop_assert_eq!(&r.non_manifold_vertices, &want_nmv);
            let tri = TriangleMesh::new(v, tris.clone());
            proptest::prop_assert_eq!(tri.manifold_report_near(&mask), Some(r));
        }
    }

    #[test]
    fn report_near_refuses_dangling_indices() {
        let m = mesh(vec![[0.0; 3]; 3], &[vec![0, 1, 5]]);
        assert_eq!(m.manifold_report_near(&[true]), None);
        let t = TriangleMesh::new(vec![[0.0; 3]; 3], vec![[0, 1, 5]]);
        assert_eq!(t.manifold_report_near(&[true]), None);
    }
}
