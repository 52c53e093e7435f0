//! The inspection report of a polygon mesh: topological validity (section
//! 4.2, naming the violated constraint), coordinate validity (section
//! 8.5), 2-manifoldness, the number of self-intersecting facet pairs
//! (exact), the signed volume and the bounding box; and those measures as
//! methods of [`PolygonMesh`] and [`TriangleMesh`].

use super::intersect::self_intersecting_pairs;
use super::manifold::{edge_census, report_of_valid};
use crate::{HalfEdge, PolygonMesh, TopologyError, TriangleMesh};
use rayon::prelude::*;
use robust_arith::Point3;

/// What the inspection of a mesh reports ([`check_mesh`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MeshCheckReport {
    /// Every facet satisfies facet boundary closure and the mesh satisfies
    /// shape boundary closure, with no dangling index (section 4.2).
    pub topologically_valid: bool,
    /// The first violated constraint, naming the entity.
    pub topology_error: Option<String>,
    /// Every coordinate finite and at most `f64::MAX / 4` (section 8.5).
    pub coordinates_valid: bool,
    /// The first bad coordinate.
    pub coordinate_error: Option<String>,
    /// Number of vertices.
    pub vertices: usize,
    /// Number of facets.
    pub facets: usize,
    /// Number of half-edges (over all facet loops).
    pub half_edges: usize,
    /// Number of edges (unordered vertex pairs joined by half-edges).
    pub edges: usize,
    /// Every edge has exactly one half-edge in each direction and the
    /// facets around every vertex form one fan (a closed 2-manifold). This
    /// and the three counts below are those of
    /// [`PolygonMesh::manifold_report`] ([`crate::ManifoldCounts`]), only
    /// computed for a topologically valid mesh.
    pub two_manifold: Option<bool>,
    /// Edges used in one direction only (in a topologically valid mesh,
    /// only a zero-length half-edge `a -> a` makes one).
    pub open_edges: Option<usize>,
    /// Edges used both ways but not exactly once each way (several sheets
    /// meet there).
    pub non_manifold_edges: Option<usize>,
    /// Vertices whose surrounding facets form more than one fan.
    pub non_manifold_vertices: Option<usize>,
    /// Facet pairs that meet anywhere but at the corners and edges their
    /// triangles share ([`PolygonMesh::self_intersections`]): crossing, touching or folded
    /// over. Only computed for valid coordinates and topology.
    pub self_intersecting_facet_pairs: Option<usize>,
    /// The enclosed volume (positive for outward-facing facets). Only
    /// computed for valid coordinates and topology.
    pub signed_volume: Option<f64>,
    /// The bounding box `[min, max]` of the vertices, when there are any
    /// and they are valid.
    pub bounding_box: Option<[Point3; 2]>,
}

impl MeshCheckReport {
    /// Valid coordinates and topology: every Boolean accepts the mesh.
    pub fn is_valid(&self) -> bool {
        self.topologically_valid && self.coordinates_valid
    }
}

/// Checks a mesh (any data: nothing here panics or trusts the indices).
///
/// ```
/// use topology::{check_mesh, Facet, PolygonMesh};
/// let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let loops = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// let tetra = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
/// let r = check_mesh(&tetra);
/// assert!(r.is_valid());
/// assert_eq!(r.two_manifold, Some(true));
/// assert_eq!(r.self_intersecting_facet_pairs, Some(0));
/// assert_eq!(r.signed_volume, Some(1.0 / 6.0));
/// ```
pub fn check_mesh(mesh: &PolygonMesh) -> MeshCheckReport {
    let topology = mesh.check_topology();
    let coords = mesh.validate_coordinates();
    let valid = topology.is_ok() && coords.is_ok();
    let mut r = MeshCheckReport {
        topologically_valid: topology.is_ok(),
        topology_error: topology.err().map(|e| e.to_string()),
        coordinates_valid: coords.is_ok(),
        coordinate_error: coords.err().map(|e| e.to_string()),
        vertices: mesh.vertices.len(),
        facets: mesh.facets.len(),
        half_edges: mesh.half_edge_count(),
        edges: 0,
        two_manifold: None,
        open_edges: None,
        non_manifold_edges: None,
        non_manifold_vertices: None,
        self_intersecting_facet_pairs: None,
        signed_volume: None,
        bounding_box: None,
    };
    if r.topologically_valid {
        let m = report_of_valid(mesh);
        let counts = m.counts();
        r.edges = m.edges;
        r.two_manifold = Some(counts.two_manifold);
        r.open_edges = Some(counts.open_edges);
        r.non_manifold_edges = Some(counts.non_manifold_edges);
        r.non_manifold_vertices = Some(counts.non_manifold_vertices);
    } else if indices_in_range(mesh) {
        r.edges = edge_census(mesh).0;
    }
    if valid {
        r.signed_volume = Some(mesh_signed_volume(mesh));
        r.self_intersecting_facet_pairs = Some(self_intersecting_pairs(mesh).len());
    }
    if r.coordinates_valid {
        r.bounding_box = mesh.bounding_box();
    }
    r
}

/// `true` when every half-edge's vertex indices are below the vertex
/// count (the precondition of every census and test here).
pub(super) fn indices_in_range(mesh: &PolygonMesh) -> bool {
    let n = mesh.vertices.len() as u32;
    mesh.facets
        .par_iter()
        .all(|f| f.half_edges.iter().all(|h| h.start < n && h.end < n))
}

/// The signed volume of a topologically valid mesh: the sum over facets of
/// the cones from the facet's first vertex over its half-edges (facet
/// boundary closure makes the choice of apex irrelevant), taken relative to
/// the first vertex of the mesh to limit cancellation. Half-edges with
/// dangling indices are skipped.
pub fn mesh_signed_volume(mesh: &PolygonMesh) -> f64 {
    let Some(&o) = mesh.vertices.first() else {
        return 0.0;
    };
    let volume = six_times_volume(mesh, o, [1.0; 3]) / 6.0;
    if volume.is_finite() {
        return volume;
    }
    // The products overflowed (coordinates beyond about 5e102): the same
    // sum on exactly scaled coordinates, scaled back (`unit_scale.rs`).
    let rel = mesh
        .vertices
        .iter()
        .map(|p| [p[0] - o[0], p[1] - o[1], p[2] - o[2]]);
    match crate::unit_scale::axis_scales(rel) {
        Some((down, up)) => {
            crate::unit_scale::scaled_back(six_times_volume(mesh, o, down) / 6.0, &up)
        }
        None => volume,
    }
}

/// Six times the signed volume by the divergence sum over the facets, on
/// coordinates relative to `o`, axis `k` multiplied by `scale[k]` (1, or
/// powers of two).
fn six_times_volume(mesh: &PolygonMesh, o: Point3, scale: [f64; 3]) -> f64 {
    let rel = |v: u32| {
        let p = mesh.vertices.get(v as usize).copied().unwrap_or(o);
        [
            (p[0] - o[0]) * scale[0],
            (p[1] - o[1]) * scale[1],
            (p[2] - o[2]) * scale[2],
        ]
    };
    let mut six = 0.0;
    for f in &mesh.facets {
        let Some(first) = f.half_edges.first() else {
            continue;
        };
        let c = rel(first.start);
        for &HalfEdge { start, end } in &f.half_edges {
            let (a, b) = (rel(start), rel(end));
            six += c[0] * (a[1] * b[2] - a[2] * b[1]) - c[1] * (a[0] * b[2] - a[2] * b[0])
                + c[2] * (a[0] * b[1] - a[1] * b[0]);
        }
    }
    six
}

impl PolygonMesh {
    /// The inspection report ([`check_mesh`]).
    pub fn check(&self) -> MeshCheckReport {
        check_mesh(self)
    }

    /// The enclosed volume, positive for outward-facing facets
    /// ([`mesh_signed_volume`]).
    pub fn signed_volume(&self) -> f64 {
        mesh_signed_volume(self)
    }

    /// The bounding box `[min, max]` of the vertices (`None` without
    /// vertices). NaN coordinates are passed over by `f64::min`/`max`.
    pub fn bounding_box(&self) -> Option<[Point3; 2]> {
        bounding_box(&self.vertices)
    }

    /// The facet pairs that meet improperly, exactly: crossing, touching or
    /// folded over. Sorted, each `[smaller, larger]` facet index; an error
    /// for a mesh that is not topologically valid or has invalid
    /// coordinates.
    ///
    /// Every facet is triangulated by internal edges (section 4.8);
    /// vertices with equal coordinates are one point. Two triangles of
    /// different facets meet improperly when they share no corner and
    /// meet at all (touching counts); share one corner and meet anywhere
    /// else; share an edge and are coplanar with their third corners on
    /// the same side (a fold-over); or are the same triangle twice (a
    /// double-sided sheet). A facet pair counts once. Zero-area triangles
    /// are covered by their neighbours (after splitting those at
    /// T-junctions). Boxes are paired by a bounding-volume hierarchy and
    /// tested as they come, in `O((n + k) log n)` time for `n` triangles
    /// and `k` box-overlapping pairs and linear memory; a big convex facet
    /// is triangulated by halving rather than as a fan, whose triangles'
    /// boxes would meet every facet around its rim.
    ///
    /// ```
    /// use topology::{Facet, PolygonMesh};
    /// // A closed, double-sided triangle: both sides overlap everywhere.
    /// let v = vec![[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [3.0, 2.0, 0.0]];
    /// let m = PolygonMesh::new(v, vec![Facet::from_loop(&[0, 1, 2]), Facet::from_loop(&[0, 2, 1])]);
    /// assert_eq!(m.self_intersections(), Ok(vec![[0, 1]]));
    /// ```
    pub fn self_intersections(&self) -> Result<Vec<[u32; 2]>, TopologyError> {
        self.check_topology()?;
        self.validate_coordinates()?;
        Ok(self_intersecting_pairs(self))
    }
}

impl TriangleMesh {
    /// The inspection report of the same shape as a polygon mesh.
    pub fn check(&self) -> MeshCheckReport {
        check_mesh(&self.to_polygon_mesh())
    }

    /// The bounding box `[min, max]` of the vertices (`None` without
    /// vertices).
    pub fn bounding_box(&self) -> Option<[Point3; 2]> {
        bounding_box(&self.vertices)
    }

    /// [`PolygonMesh::self_intersections`], with triangle indices.
    pub fn self_intersections(&self) -> Result<Vec<[u32; 2]>, TopologyError> {
        self.to_polygon_mesh().self_intersections()
    }
}

/// The box of a point list.
fn bounding_box(points: &[Point3]) -> Option<[Point3; 2]> {
    let (&first, rest) = points.split_first()?;
    let (mut lo, mut hi) = (first, first);
    for p in rest {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Some([lo, hi])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Facet;

    #[test]
    fn cube_and_two_crossing_cubes() {
        let cube = |o: f64, off: u32| -> (Vec<Point3>, Vec<Vec<u32>>) {
            let v: Vec<Point3> = (0..8)
                .map(|i| {
                    [
                        o + f64::from(i & 1),
                        o + f64::from((i >> 1) & 1),
                        o + f64::from((i >> 2) & 1),
                    ]
                })
                .collect();
            let f = [
                [0, 2, 3, 1],
                [4, 5, 7, 6],
                [0, 1, 5, 4],
                [2, 6, 7, 3],
                [0, 4, 6, 2],
                [1, 3, 7, 5],
            ];
            (
                v,
                f.iter()
                    .map(|q| q.iter().map(|&k| k + off).collect())
                    .collect(),
            )
        };
        let (v, f) = cube(0.0, 0);
        let m = PolygonMesh::new(v.clone(), f.iter().map(|l| Facet::from_loop(l)).collect());
        let r = check_mesh(&m);
        assert!(r.is_valid(), "{r:?}");
        assert_eq!(r.two_manifold, Some(true));
        assert_eq!(r.edges, 12);
        assert_eq!(r.signed_volume, Some(1.0));
        assert_eq!(r.self_intersecting_facet_pairs, Some(0));
        // Two overlapping cubes as one mesh: valid topology and 2-manifold
        // (two shells), but their facets cross.
        let (v2, f2) = cube(0.5, 8);
        let mut vs = v;
        vs.extend(v2);
        let fs: Vec<_> = f
            .iter()
            .chain(f2.iter())
            .map(|l| Facet::from_loop(l))
            .collect();
        let r = check_mesh(&PolygonMesh::new(vs, fs));
        assert!(r.is_valid());
        assert_eq!(r.two_manifold, Some(true));
        assert_eq!(r.signed_volume, Some(2.0));
        // The faces x = 1, y = 1, z = 1 of the first cube cross the faces
        // x = 0.5, y = 0.5, z = 0.5 of the second, except the three
        // parallel pairs: 9 - 3 = 6.
        assert_eq!(r.self_intersecting_facet_pairs, Some(6));
    }

    #[test]
    fn open_and_non_manifold_edges_are_counted_apart() {
        // Two unit cubes sharing the edge x = 1, y = 1 (vertices 2 and 6
        // shared): that edge has two half-edges each way; the facet
        // z = 0 of the first cube carries a zero-length half-edge at
        // vertex 0 besides its loop (closure holds), an edge used one way.
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
            [0.0, 1.0, 1.0],
            [2.0, 1.0, 0.0],
            [2.0, 2.0, 0.0],
            [1.0, 2.0, 0.0],
            [2.0, 1.0, 1.0],
            [2.0, 2.0, 1.0],
            [1.0, 2.0, 1.0],
        ];
        let cube = |c: [u32; 8]| {
            [
                [0, 3, 2, 1],
                [4, 5, 6, 7],
                [0, 1, 5, 4],
                [1, 2, 6, 5],
                [2, 3, 7, 6],
                [3, 0, 4, 7],
            ]
            .map(|q| q.map(|k| c[k]).to_vec())
        };
        let mut facets: Vec<Facet> = cube([0, 1, 2, 3, 4, 5, 6, 7])
            .iter()
            .chain(&cube([2, 8, 9, 10, 6, 11, 12, 13]))
            .map(|l| Facet::from_loop(l))
            .collect();
        let m = PolygonMesh::new(v, facets.clone());
        let r = check_mesh(&m);
        assert!(r.is_valid(), "{r:?}");
        assert_eq!(r.edges, 23);
        assert_eq!(r.open_edges, Some(0));
        assert_eq!(r.non_manifold_edges, Some(1));
        // The fans at the shared edge's ends meet at its other end: one
        // fan each (the edge is what is not manifold there).
        assert_eq!(r.non_manifold_vertices, Some(0));
        assert_eq!(r.two_manifold, Some(false));
        facets[0].half_edges.push(HalfEdge { start: 0, end: 0 });
        let r = check_mesh(&PolygonMesh::new(m.vertices.clone(), facets));
        assert!(r.is_valid(), "{r:?}");
        assert_eq!(r.edges, 24);
        assert_eq!(r.open_edges, Some(1));
        assert_eq!(r.non_manifold_edges, Some(1));
    }

    #[test]
    fn non_manifold_and_invalid() {
        // Two tetrahedra sharing one vertex: valid, not 2-manifold at it.
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
        let m = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
        let r = check_mesh(&m);
        assert!(r.is_valid());
        assert_eq!(r.open_edges, Some(0));
        assert_eq!(r.non_manifold_edges, Some(0));
        assert_eq!(r.non_manifold_vertices, Some(1));
        assert_eq!(r.two_manifold, Some(false));
        // An open mesh: invalid, the constraint named.
        let open = PolygonMesh::new(
            vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            vec![Facet::from_loop(&[0, 1, 2])],
        );
        let r = check_mesh(&open);
        assert!(!r.topologically_valid);
        assert!(r.topology_error.unwrap().contains("closure"));
        assert_eq!(r.signed_volume, None);
        // Dangling and NaN: reported, no panic.
        let bad = PolygonMesh::new(
            vec![[f64::NAN, 0.0, 0.0]],
            vec![Facet::from_loop(&[0, 5, 9])],
        );
        let r = check_mesh(&bad);
        assert!(!r.topologically_valid && !r.coordinates_valid);
    }

    #[test]
    fn methods_agree_with_the_report() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let t = TriangleMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]);
        let r = t.check();
        assert!(r.is_valid());
        assert_eq!(r.signed_volume, Some(t.to_polygon_mesh().signed_volume()));
        assert_eq!(r.signed_volume, Some(1.0 / 6.0));
        assert_eq!(t.bounding_box(), Some([[0.0; 3], [1.0; 3]]));
        assert_eq!(r.bounding_box, t.bounding_box());
        assert_eq!(t.self_intersections(), Ok(vec![]));
        assert_eq!(PolygonMesh::default().bounding_box(), None);
        // Dangling indices: an error, no panic.
        let bad = TriangleMesh::new(vec![[0.0; 3]], vec![[0, 1, 2]]);
        assert!(bad.self_intersections().is_err());
        assert!(!bad.check().is_valid());
    }

    use proptest::prelude::*;

    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            60 => (-4i32..=4).prop_map(f64::from),
            1 => Just(f64::NAN),
            1 => Just(f64::MAX),
            1 => Just(f64::MAX / 4.0),
            1 => Just(-f64::from_bits(1)),
            1 => any::<f64>(),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(300)))]

        /// Garbage meshes (dangling indices, NaN and huge coordinates,
        /// repeated and zero-length half-edges) are reported, never a
        /// panic, and the report agrees with the methods.
        #[test]
        fn garbage_meshes_are_reported_not_panicked_on(
            v in proptest::collection::vec(proptest::array::uniform3(coordinate()), 0..8),
            loops in proptest::collection::vec(proptest::collection::vec(0u32..10, 0..6), 0..8),
            close in any::<bool>(),
        ) {
            let mut facets: Vec<Facet> = loops.iter().map(|l| Facet::from_loop(l)).collect();
            if close {
                // Each loop doubled back: closed, often degenerate.
                facets.extend(loops.iter().map(|l| {
                    let r: Vec<u32> = l.iter().rev().copied().collect();
                    Facet::from_loop(&r)
                }));
            }
            let m = PolygonMesh::new(v, facets);
            let r = check_mesh(&m);
            prop_assert_eq!(r.is_valid(), m.self_intersections().is_ok());
            if let Ok(pairs) = m.self_intersections() {
                prop_assert_eq!(r.self_intersecting_facet_pairs, Some(pairs.len()));
                prop_assert!(pairs.iter().all(|p| p[0] < p[1]));
            }
            prop_assert_eq!(r.two_manifold, m.manifold_report().ok().map(|x| x.is_two_manifold()));
        }
    }
}
