//! The validity report of a 3D polygon mesh (`umbra check` on `.obj` and
//! `.off`): topological validity (section 4.2, naming the violated
//! constraint), coordinate validity, 2-manifoldness, the number of
//! self-intersecting facet pairs by an exact triangle-triangle test, and the
//! signed volume.
//!
//! Self-intersection: every facet is triangulated by internal edges only
//! (section 4.8, `boolean_3d::triangulate_facet`); triangles of different
//! facets that share no vertex index are tested when their boxes overlap
//! (sort-and-sweep on x), with Shewchuk's exact `orient3d`/`orient2d` (the
//! `robust` crate), closed triangles (touching counts). Facets that share a
//! vertex or an edge meet there by construction and are not tested; a
//! degenerate (zero-area) triangle is not tested either. A facet pair is
//! counted once however many of their triangles meet.

use boolean_3d::triangulate_facet;
use rayon::prelude::*;
use robust::{orient2d, orient3d, Coord, Coord3D};
use robust_arith::Point3;
use serde::Serialize;
use std::collections::HashMap;
use topology::{HalfEdge, PolygonMesh};

/// What `umbra check` reports about a mesh.
#[derive(Clone, Debug, PartialEq, Serialize)]
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
    /// facets around every vertex form one fan (a closed 2-manifold). Only
    /// computed for a topologically valid mesh.
    pub two_manifold: Option<bool>,
    /// Edges with other than one half-edge each way.
    pub non_manifold_edges: Option<usize>,
    /// Vertices whose surrounding facets form more than one fan.
    pub non_manifold_vertices: Option<usize>,
    /// Facet pairs whose triangles intersect (see the module docs). Only
    /// computed for valid coordinates and topology.
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
/// use umbra::{check_mesh, parse_off};
/// let tetra = parse_off("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n", "t.off").unwrap();
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
        non_manifold_edges: None,
        non_manifold_vertices: None,
        self_intersecting_facet_pairs: None,
        signed_volume: None,
        bounding_box: None,
    };
    let n = mesh.vertices.len() as u32;
    let in_range = mesh
        .facets
        .iter()
        .flat_map(|f| &f.half_edges)
        .all(|h| h.start < n && h.end < n);
    if in_range {
        let (edges, bad_edges) = edge_census(mesh);
        r.edges = edges;
        if r.topologically_valid {
            let bad_vertices = non_manifold_vertices(mesh);
            r.non_manifold_edges = Some(bad_edges);
            r.non_manifold_vertices = Some(bad_vertices);
            r.two_manifold = Some(bad_edges == 0 && bad_vertices == 0);
        }
    }
    if valid {
        r.signed_volume = Some(mesh_signed_volume(mesh));
        r.self_intersecting_facet_pairs = Some(self_intersecting_pairs(mesh));
    }
    if r.coordinates_valid && !mesh.vertices.is_empty() {
        let mut lo = mesh.vertices[0];
        let mut hi = lo;
        for p in &mesh.vertices {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        r.bounding_box = Some([lo, hi]);
    }
    r
}

/// The number of edges, and of edges without exactly one half-edge each
/// way.
fn edge_census(mesh: &PolygonMesh) -> (usize, usize) {
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
    let bad = count.values().filter(|&&(f, b)| (f, b) != (1, 1)).count();
    (count.len(), bad)
}

/// Vertices around which the facet corners form more than one fan: the
/// corners at `v` join the edge they come in by to the edge they leave by;
/// on a 2-manifold these links make one cycle per vertex.
fn non_manifold_vertices(mesh: &PolygonMesh) -> usize {
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
    let mut bad = 0;
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
            bad += 1;
        }
        i = j;
    }
    bad
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
    let rel = |v: u32| {
        let p = mesh.vertices.get(v as usize).copied().unwrap_or(o);
        [p[0] - o[0], p[1] - o[1], p[2] - o[2]]
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
    six / 6.0
}

fn c3(p: &Point3) -> Coord3D<f64> {
    Coord3D {
        x: p[0],
        y: p[1],
        z: p[2],
    }
}

/// The exact sign of `orient3d(a, b, c, d)`.
fn o3(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> i8 {
    let v = orient3d(c3(a), c3(b), c3(c), c3(d));
    (v > 0.0) as i8 - (v < 0.0) as i8
}

/// The exact sign of the 2D orientation of the projections onto axes
/// `(i, j)`.
fn o2(a: &Point3, b: &Point3, c: &Point3, (i, j): (usize, usize)) -> i8 {
    let p = |q: &Point3| Coord { x: q[i], y: q[j] };
    let v = orient2d(p(a), p(b), p(c));
    (v > 0.0) as i8 - (v < 0.0) as i8
}

const PLANES: [(usize, usize); 3] = [(0, 1), (1, 2), (0, 2)];

/// A coordinate plane onto which the triangle projects without collapsing
/// (exact), or `None` for a degenerate triangle.
fn projection(t: &[Point3; 3]) -> Option<(usize, usize)> {
    PLANES
        .into_iter()
        .find(|&ax| o2(&t[0], &t[1], &t[2], ax) != 0)
}

/// Closed 2D segment intersection in the projection `ax`.
fn seg_seg_2d(a: &Point3, b: &Point3, c: &Point3, d: &Point3, ax: (usize, usize)) -> bool {
    let (d1, d2) = (o2(a, b, c, ax), o2(a, b, d, ax));
    let (d3, d4) = (o2(c, d, a, ax), o2(c, d, b, ax));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    let within = |p: &Point3, q: &Point3, r: &Point3| {
        r[ax.0] >= p[ax.0].min(q[ax.0])
            && r[ax.0] <= p[ax.0].max(q[ax.0])
            && r[ax.1] >= p[ax.1].min(q[ax.1])
            && r[ax.1] <= p[ax.1].max(q[ax.1])
    };
    (d1 == 0 && within(a, b, c))
        || (d2 == 0 && within(a, b, d))
        || (d3 == 0 && within(c, d, a))
        || (d4 == 0 && within(c, d, b))
}

/// Closed point-in-triangle in the projection `ax`.
fn point_in_tri_2d(p: &Point3, t: &[Point3; 3], ax: (usize, usize)) -> bool {
    let s = [
        o2(&t[0], &t[1], p, ax),
        o2(&t[1], &t[2], p, ax),
        o2(&t[2], &t[0], p, ax),
    ];
    s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
}

/// Closed intersection of segment `a b` with triangle `t` (non-degenerate,
/// projecting without collapse onto `ax`).
fn seg_tri(a: &Point3, b: &Point3, t: &[Point3; 3], ax: (usize, usize)) -> bool {
    let sa = o3(&t[0], &t[1], &t[2], a);
    let sb = o3(&t[0], &t[1], &t[2], b);
    if sa == sb && sa != 0 {
        return false;
    }
    if sa == 0 && sb == 0 {
        // The segment lies in the triangle's plane: decide in a projection
        // that keeps the plane's incidences.
        return point_in_tri_2d(a, t, ax)
            || point_in_tri_2d(b, t, ax)
            || (0..3).any(|k| seg_seg_2d(a, b, &t[k], &t[(k + 1) % 3], ax));
    }
    // The segment meets the plane at one point; it is in the closed
    // triangle iff the line a b passes on the same side of all three edges.
    let s = [
        o3(a, b, &t[0], &t[1]),
        o3(a, b, &t[1], &t[2]),
        o3(a, b, &t[2], &t[0]),
    ];
    s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
}

/// Closed triangle-triangle intersection, exact. Two triangles meet iff
/// an edge of one meets the other (for crossing planes the intersection
/// segments on the common line overlap at an end point, which lies on an
/// edge; coplanar triangles meet by crossing edges or containment, which
/// the coplanar branch of `seg_tri` sees).
fn tri_tri(t: &[Point3; 3], u: &[Point3; 3], ax_t: (usize, usize), ax_u: (usize, usize)) -> bool {
    let side = |p: &[Point3; 3], q: &[Point3; 3]| {
        let s = q.map(|v| o3(&p[0], &p[1], &p[2], &v));
        (s.iter().all(|&x| x > 0)) || s.iter().all(|&x| x < 0)
    };
    if side(t, u) || side(u, t) {
        return false;
    }
    (0..3).any(|k| seg_tri(&t[k], &t[(k + 1) % 3], u, ax_u))
        || (0..3).any(|k| seg_tri(&u[k], &u[(k + 1) % 3], t, ax_t))
}

/// A triangle of a facet with its box and projection.
struct Tri {
    facet: u32,
    v: [u32; 3],
    p: [Point3; 3],
    lo: Point3,
    hi: Point3,
    ax: (usize, usize),
}

/// The number of facet pairs whose triangles intersect (module docs).
fn self_intersecting_pairs(mesh: &PolygonMesh) -> usize {
    let mut tris: Vec<Tri> = Vec::new();
    let mut buf = Vec::new();
    let mut hes = Vec::new();
    for (fi, f) in mesh.facets.iter().enumerate() {
        buf.clear();
        hes.clear();
        hes.extend(f.half_edges.iter().map(|h| (h.start, h.end)));
        triangulate_facet(&mesh.vertices, &hes, &mut buf);
        for &v in &buf {
            let p = v.map(|i| mesh.vertices[i as usize]);
            let Some(ax) = projection(&p) else {
                continue;
            };
            let mut lo = p[0];
            let mut hi = p[0];
            for q in &p[1..] {
                for k in 0..3 {
                    lo[k] = lo[k].min(q[k]);
                    hi[k] = hi[k].max(q[k]);
                }
            }
            tris.push(Tri {
                facet: fi as u32,
                v,
                p,
                lo,
                hi,
                ax,
            });
        }
    }
    tris.sort_unstable_by(|a, b| a.lo[0].total_cmp(&b.lo[0]));
    // Candidate pairs by sort-and-sweep on x, boxes closed.
    let mut candidates: Vec<(u32, u32)> = Vec::new();
    let mut active: Vec<u32> = Vec::new();
    for (i, t) in tris.iter().enumerate() {
        active.retain(|&j| tris[j as usize].hi[0] >= t.lo[0]);
        for &j in &active {
            let u = &tris[j as usize];
            if u.facet != t.facet
                && u.lo[1] <= t.hi[1]
                && t.lo[1] <= u.hi[1]
                && u.lo[2] <= t.hi[2]
                && t.lo[2] <= u.hi[2]
                && !t.v.iter().any(|x| u.v.contains(x))
            {
                candidates.push((j, i as u32));
            }
        }
        active.push(i as u32);
    }
    let mut hits: Vec<(u32, u32)> = candidates
        .par_iter()
        .filter_map(|&(i, j)| {
            let (t, u) = (&tris[i as usize], &tris[j as usize]);
            tri_tri(&t.p, &u.p, t.ax, u.ax).then(|| (t.facet.min(u.facet), t.facet.max(u.facet)))
        })
        .collect();
    hits.sort_unstable();
    hits.dedup();
    hits.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [Point3; 3] {
        [a, b, c]
    }

    fn meet(t: &[Point3; 3], u: &[Point3; 3]) -> bool {
        let (at, au) = (projection(t).unwrap(), projection(u).unwrap());
        let r = tri_tri(t, u, at, au);
        assert_eq!(r, tri_tri(u, t, au, at), "symmetric");
        r
    }

    #[test]
    fn triangle_pairs() {
        let t = tri([0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]);
        // Piercing.
        assert!(meet(
            &t,
            &tri([1.0, 1.0, -1.0], [1.0, 1.0, 1.0], [2.0, 1.0, 1.0])
        ));
        // Above.
        assert!(!meet(
            &t,
            &tri([1.0, 1.0, 0.5], [1.0, 2.0, 1.0], [2.0, 1.0, 1.0])
        ));
        // Touching at a vertex on the face.
        assert!(meet(
            &t,
            &tri([1.0, 1.0, 0.0], [1.0, 2.0, 1.0], [2.0, 1.0, 1.0])
        ));
        // Crossing the plane outside the triangle.
        assert!(!meet(
            &t,
            &tri([5.0, 5.0, -1.0], [5.0, 5.0, 1.0], [6.0, 5.0, 1.0])
        ));
        // Coplanar, overlapping edges crossing.
        assert!(meet(
            &t,
            &tri([1.0, -1.0, 0.0], [1.0, 5.0, 0.0], [-1.0, 2.0, 0.0])
        ));
        // Coplanar, contained.
        assert!(meet(
            &t,
            &tri([0.5, 0.5, 0.0], [1.0, 0.5, 0.0], [0.5, 1.0, 0.0])
        ));
        // Coplanar, disjoint.
        assert!(!meet(
            &t,
            &tri([5.0, 5.0, 0.0], [6.0, 5.0, 0.0], [5.0, 6.0, 0.0])
        ));
        // Coplanar, beyond the hypotenuse by one ulp-ish gap: exactness.
        let e = 4.0 * f64::EPSILON;
        assert!(!meet(
            &t,
            &tri(
                [2.0 + e, 2.0 + e, 0.0],
                [5.0, 5.0, 0.0],
                [2.0 + e, 5.0, 0.0]
            )
        ));
        assert!(meet(
            &t,
            &tri([2.0, 2.0, 0.0], [5.0, 5.0, 0.0], [2.0, 5.0, 0.0])
        ));
    }

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
        let m = PolygonMesh::new(
            v.clone(),
            f.iter().map(|l| topology::Facet::from_loop(l)).collect(),
        );
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
            .map(|l| topology::Facet::from_loop(l))
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
        let m = PolygonMesh::new(
            v,
            loops
                .iter()
                .map(|l| topology::Facet::from_loop(l))
                .collect(),
        );
        let r = check_mesh(&m);
        assert!(r.is_valid());
        assert_eq!(r.non_manifold_edges, Some(0));
        assert_eq!(r.non_manifold_vertices, Some(1));
        assert_eq!(r.two_manifold, Some(false));
        // An open mesh: invalid, the constraint named.
        let open = PolygonMesh::new(
            vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            vec![topology::Facet::from_loop(&[0, 1, 2])],
        );
        let r = check_mesh(&open);
        assert!(!r.topologically_valid);
        assert!(r.topology_error.unwrap().contains("closure"));
        assert_eq!(r.signed_volume, None);
        // Dangling and NaN: reported, no panic.
        let bad = PolygonMesh::new(
            vec![[f64::NAN, 0.0, 0.0]],
            vec![topology::Facet::from_loop(&[0, 5, 9])],
        );
        let r = check_mesh(&bad);
        assert!(!r.topologically_valid && !r.coordinates_valid);
    }
}
