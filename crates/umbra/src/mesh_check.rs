//! The validity report of a 3D polygon mesh (`umbra check` on `.obj` and
//! `.off`): topological validity (section 4.2, naming the violated
//! constraint), coordinate validity, 2-manifoldness, the number of
//! self-intersecting facet pairs by an exact triangle-triangle test, and the
//! signed volume.
//!
//! Self-intersection. Section 4.2 requires of a geometrically valid shape
//! that its boundary components do not intersect. Every facet is
//! triangulated by internal edges only (section 4.8,
//! `boolean_3d::triangulate_facet`); vertices with exactly equal
//! coordinates are taken as one point (coincident vertices and zero-length
//! edges are features a topologically valid mesh may have, section 4.1);
//! the triangles of different facets whose closed boxes overlap
//! (sort-and-sweep on x) are then tested exactly with Shewchuk's
//! `orient3d`/`orient2d` (the `robust` crate). Two triangles meet where
//! they share corners by construction, so a pair counts when the triangles
//! meet anywhere else:
//!
//! - No shared corner: the closed triangles meet (touching counts).
//! - One shared corner `s`: the edge opposite `s` in either triangle meets
//!   the other triangle (closed). This is exact: the intersection of two
//!   triangles is convex and holds `s`; if it holds another point `x`, the
//!   ray from `s` through `x` leaves each triangle through the edge
//!   opposite `s`, and the nearer of the two exit points lies in both
//!   triangles. Conversely, a point of an opposite edge is never `s`, so
//!   the shared corner itself never counts.
//! - Two shared corners (a shared edge): the triangles are coplanar with
//!   their third corners strictly on the same side of the edge, a fold-over
//!   (dihedral angle zero). Triangles in different planes meet only on the
//!   line common to both planes, which crosses each triangle in exactly the
//!   shared edge, so they never count.
//! - Three shared corners: the same triangle twice, which always overlaps
//!   itself (a double-sided sheet).
//!
//! Zero-area triangles (from zero-area facets or collinear facet corners,
//! features the Boolean produces, section 4.1) are not tested themselves,
//! for this reason: such a triangle is the segment between its two extreme
//! corners (or a point), and that segment is an edge of the triangle whose
//! opposite half-edge lies in another triangle (internal edges come in
//! opposite pairs, facet half-edges are matched by shape boundary closure,
//! section 4.2), so the segment lies on the boundary of that triangle and
//! whatever meets it meets that triangle too, which is tested against
//! every other facet. Where the
//! third corner lies strictly inside the segment, it is a vertex on that
//! neighbour's edge (a T-junction), so first every triangle having that
//! edge is split at the vertex (recursively): the neighbours on either
//! side then share the pieces' corners and their contact along the segment
//! is a shared edge, not a crossing. Only a zero-area region whose every
//! neighbour has zero area too goes untested.
//!
//! A facet pair is counted once however many of their triangles meet; a
//! facet's own triangles are not tested against each other.

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
    /// Facet pairs that meet anywhere but at the corners and edges their
    /// triangles share (see the module docs): crossing, touching or folded
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

/// A positive-area triangle of a facet: its corners as welded vertex ids
/// (module docs) and as points, its box, and a coordinate plane onto which
/// it projects without collapsing.
struct Tri {
    facet: u32,
    v: [u32; 3],
    p: [Point3; 3],
    lo: Point3,
    hi: Point3,
    ax: (usize, usize),
}

impl Tri {
    /// The triangle `v` of facet `facet`, or `None` when it has zero area.
    fn new(facet: u32, v: [u32; 3], positions: &[Point3]) -> Option<Tri> {
        let p = v.map(|i| positions[i as usize]);
        let ax = projection(&p)?;
        let mut lo = p[0];
        let mut hi = p[0];
        for q in &p[1..] {
            for k in 0..3 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        Some(Tri {
            facet,
            v,
            p,
            lo,
            hi,
            ax,
        })
    }
}

/// Every vertex's representative: the first vertex with exactly the same
/// coordinates (`-0.0` and `0.0` are one value), so that coincident
/// vertices and the ends of zero-length edges count as one point.
fn weld(vertices: &[Point3]) -> Vec<u32> {
    let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(vertices.len());
    vertices
        .iter()
        .enumerate()
        .map(|(i, p)| {
            // Adding +0.0 turns -0.0 into +0.0 and leaves every other
            // finite value unchanged.
            let key = p.map(|c| (c + 0.0).to_bits());
            *first.entry(key).or_insert(i as u32)
        })
        .collect()
}

/// For a zero-area triangle, the ends `(p, q)` of the segment it spans and
/// its third corner `r` when `r` lies strictly between them; `None` when
/// the corners are one point or `r` coincides with an end.
///
/// The corners are collinear, so along any axis on which they are not all
/// equal the line's direction has a non-zero component and that coordinate
/// orders the points of the line exactly.
fn interior_corner(v: [u32; 3], p: &[Point3; 3]) -> Option<(u32, u32, u32)> {
    let k = (0..3).find(|&k| p[0][k] != p[1][k] || p[1][k] != p[2][k])?;
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| p[a][k].total_cmp(&p[b][k]));
    let [lo, mid, hi] = order;
    if p[mid][k] == p[lo][k] || p[mid][k] == p[hi][k] {
        return None;
    }
    Some((v[lo], v[hi], v[mid]))
}

/// Splits the positive-area triangle `t` at every vertex that a zero-area
/// triangle places strictly inside one of its edges (`splits`, keyed by the
/// edge's ends in increasing order), recursively, appending the pieces to
/// `out`. Each piece keeps `t`'s orientation and has positive area (its
/// apex is off the split edge's line). Every split lowers the area of the
/// triangle it replaces and the vertex set is finite, so this terminates.
fn refine(
    t: [u32; 3],
    splits: &HashMap<(u32, u32), Vec<u32>>,
    positions: &[Point3],
    out: &mut Vec<[u32; 3]>,
) {
    let mut stack = vec![t];
    while let Some(t) = stack.pop() {
        let found = (0..3).find_map(|k| {
            let (i, j) = (t[k], t[(k + 1) % 3]);
            splits.get(&(i.min(j), i.max(j))).map(|inner| (k, inner))
        });
        let Some((k, inner)) = found else {
            out.push(t);
            continue;
        };
        let (i, j, apex) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
        let (pi, pj) = (positions[i as usize], positions[j as usize]);
        // An axis on which the edge's ends differ orders its points.
        let axis = (0..3).find(|&a| pi[a] != pj[a]).unwrap_or(0);
        let mut chain = inner.clone();
        chain.sort_by(|&a, &b| positions[a as usize][axis].total_cmp(&positions[b as usize][axis]));
        chain.dedup();
        if pi[axis] > pj[axis] {
            chain.reverse();
        }
        let mut from = i;
        for r in chain.into_iter().chain(std::iter::once(j)) {
            stack.push([from, r, apex]);
            from = r;
        }
    }
}

/// Whether two positive-area triangles of different facets meet anywhere
/// but where their shared corners make them meet (module docs: no shared
/// corner, one, two or three).
fn improper(t: &Tri, u: &Tri) -> bool {
    let in_u = t.v.map(|x| u.v.contains(&x));
    match in_u.iter().filter(|&&b| b).count() {
        0 => tri_tri(&t.p, &u.p, t.ax, u.ax),
        1 => {
            // The edges opposite the shared corner.
            let k = in_u.iter().position(|&b| b).unwrap_or(0);
            let m = u.v.iter().position(|&x| x == t.v[k]).unwrap_or(0);
            let (a, b) = (&t.p[(k + 1) % 3], &t.p[(k + 2) % 3]);
            let (c, d) = (&u.p[(m + 1) % 3], &u.p[(m + 2) % 3]);
            seg_tri(a, b, &u.p, u.ax) || seg_tri(c, d, &t.p, t.ax)
        }
        2 => {
            // The shared edge (s, e) and the two third corners: a fold-over
            // when they are coplanar and on the same side of the edge
            // (decided in `t`'s projection, which keeps the common plane's
            // incidences).
            let k = in_u.iter().position(|&b| !b).unwrap_or(0);
            let m = u.v.iter().position(|x| !t.v.contains(x)).unwrap_or(0);
            let (s, e) = (&t.p[(k + 1) % 3], &t.p[(k + 2) % 3]);
            let (a, c) = (&t.p[k], &u.p[m]);
            o3(s, e, a, c) == 0 && o2(s, e, a, t.ax) == o2(s, e, c, t.ax)
        }
        _ => true,
    }
}

/// The number of facet pairs that intersect improperly (module docs).
fn self_intersecting_pairs(mesh: &PolygonMesh) -> usize {
    let id = weld(&mesh.vertices);
    // Every facet's triangles with welded corners; the zero-area ones only
    // record the vertices they place inside a segment.
    let mut kept: Vec<(u32, [u32; 3])> = Vec::new();
    let mut splits: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
    let mut buf = Vec::new();
    let mut hes = Vec::new();
    for (fi, f) in mesh.facets.iter().enumerate() {
        buf.clear();
        hes.clear();
        hes.extend(f.half_edges.iter().map(|h| (h.start, h.end)));
        triangulate_facet(&mesh.vertices, &hes, &mut buf);
        for &t in &buf {
            let v = t.map(|i| id[i as usize]);
            let p = v.map(|i| mesh.vertices[i as usize]);
            if projection(&p).is_some() {
                kept.push((fi as u32, v));
            } else if let Some((a, b, r)) = interior_corner(v, &p) {
                splits.entry((a.min(b), a.max(b))).or_default().push(r);
            }
        }
    }
    let mut tris: Vec<Tri> = Vec::with_capacity(kept.len());
    let mut pieces = Vec::new();
    for (facet, v) in kept {
        if splits.is_empty() {
            tris.extend(Tri::new(facet, v, &mesh.vertices));
            continue;
        }
        pieces.clear();
        refine(v, &splits, &mesh.vertices, &mut pieces);
        tris.extend(
            pieces
                .iter()
                .filter_map(|&w| Tri::new(facet, w, &mesh.vertices)),
        );
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
            improper(t, u).then(|| (t.facet.min(u.facet), t.facet.max(u.facet)))
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

    /// A polygon mesh from coordinates and facet loops.
    fn mesh(v: &[Point3], loops: &[&[u32]]) -> PolygonMesh {
        PolygonMesh::new(
            v.to_vec(),
            loops
                .iter()
                .map(|l| topology::Facet::from_loop(l))
                .collect(),
        )
    }

    /// The unit cube's corners (`i -> (i & 1, (i >> 1) & 1, (i >> 2) & 1)`)
    /// and its twelve outward triangles, two per face.
    fn cube_triangles() -> (Vec<Point3>, Vec<[u32; 3]>) {
        let v = (0..8)
            .map(|i| {
                [
                    f64::from(i & 1),
                    f64::from((i >> 1) & 1),
                    f64::from((i >> 2) & 1),
                ]
            })
            .collect();
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let t = quads
            .iter()
            .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
            .collect();
        (v, t)
    }

    fn triangle_mesh(v: &[Point3], t: &[[u32; 3]]) -> PolygonMesh {
        let loops: Vec<&[u32]> = t.iter().map(|x| &x[..]).collect();
        mesh(v, &loops)
    }

    fn pairs(m: &PolygonMesh) -> Option<usize> {
        let r = check_mesh(m);
        assert!(r.is_valid(), "{r:?}");
        r.self_intersecting_facet_pairs
    }

    #[test]
    fn valid_solids_have_no_self_intersecting_pairs() {
        // The cube as twelve triangles: coplanar neighbours across each
        // face diagonal lie on opposite sides of it, and the triangles
        // meeting at a corner meet only there.
        let (v, t) = cube_triangles();
        assert_eq!(pairs(&triangle_mesh(&v, &t)), Some(0));
        // A tetrahedron.
        let tetra = mesh(
            &[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            &[&[0, 2, 1], &[0, 1, 3], &[1, 2, 3], &[0, 3, 2]],
        );
        assert_eq!(pairs(&tetra), Some(0));
        // A tetrahedron whose edge 0-1 carries a vertex m = 4 at its
        // midpoint on one side only, closed by the zero-area facet
        // (0, 1, m): a T-junction. Facet (0, 2, 1) then touches (0, m, 3)
        // along 0-m, which only the split at m (module docs) recognises as
        // their shared edge.
        let needle = mesh(
            &[
                [0.0; 3],
                [2.0, 0.0, 0.0],
                [0.0, 2.0, 0.0],
                [0.0, 0.0, 2.0],
                [1.0, 0.0, 0.0],
            ],
            &[
                &[0, 2, 1],
                &[0, 4, 3],
                &[4, 1, 3],
                &[1, 2, 3],
                &[0, 3, 2],
                &[0, 1, 4],
            ],
        );
        assert!(check_mesh(&needle).is_valid());
        assert_eq!(pairs(&needle), Some(0));
    }

    #[test]
    fn a_vertex_pushed_through_the_opposite_face() {
        // Corner 7 = (1, 1, 1) of the triangulated cube pushed to
        // (0.7, 0.8, -0.5), through the bottom face z = 0, which it meets
        // in the triangles (0, 2, 3) (where y > x) and (0, 3, 1) (y < x).
        // Below z = 0: (4, 5, 7) crosses both; (4, 7, 6) crosses (0, 2, 3);
        // (2, 6, 7) and (1, 7, 5) share corner 2 with (0, 2, 3) and corner
        // 1 with (0, 3, 1) and cross them beyond it (their opposite edges
        // 6-7 and 7-5 pierce them), which a test skipping pairs with a
        // shared corner misses; (2, 7, 3) and (1, 3, 7) share an edge with
        // the bottom triangle they touch and are not coplanar with it.
        // Five pairs, as the independent rational clipping finds.
        let (mut v, t) = cube_triangles();
        v[7] = [0.7, 0.8, -0.5];
        let m = triangle_mesh(&v, &t);
        let r = check_mesh(&m);
        assert!(r.is_valid() && r.two_manifold == Some(true), "{r:?}");
        let n = r.self_intersecting_facet_pairs.unwrap();
        assert_eq!(oracle_pairs(&v, &t), PUSHED_PAIRS);
        assert_eq!(n, PUSHED_PAIRS);
        // The same cube as quadrilateral facets: whatever diagonals the
        // triangulation picks, the pushed corner crosses the bottom.
        let quads: Vec<[u32; 4]> = t
            .chunks(2)
            .map(|c| [c[0][0], c[0][1], c[0][2], c[1][2]])
            .collect();
        let loops: Vec<&[u32]> = quads.iter().map(|q| &q[..]).collect();
        assert!(pairs(&mesh(&v, &loops)).unwrap() > 0);
    }

    /// The number of improperly meeting triangle pairs of the pushed cube
    /// (the test checks that `oracle_pairs` finds it too).
    const PUSHED_PAIRS: usize = 5;

    #[test]
    fn fold_over_pairs_count_once() {
        // Two triangles sharing the edge 0-1 in the plane z = 0 with their
        // third corners on the same side: the dihedral angle is zero and
        // they overlap (an open pair, tested directly).
        let v = [
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [3.0, 2.0, 0.0],
            [1.0, 2.0, 0.0],
        ];
        assert_eq!(
            self_intersecting_pairs(&mesh(&v, &[&[0, 1, 2], &[1, 0, 3]])),
            1
        );
        // Third corners on opposite sides: they meet in the edge only.
        let w = [v[0], v[1], v[2], [1.0, -2.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[1, 0, 3]])),
            0
        );
        // Third corner lifted off the plane: a dihedral angle above zero.
        let w = [v[0], v[1], v[2], [1.0, 2.0, 1e-300]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[1, 0, 3]])),
            0
        );
        // A closed, double-sided sheet: a square as two facets facing
        // opposite ways, every edge folded over. One facet pair, however
        // the two squares are triangulated.
        let sq = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ];
        assert_eq!(pairs(&mesh(&sq, &[&[0, 1, 2, 3], &[0, 3, 2, 1]])), Some(1));
        assert_eq!(pairs(&mesh(&sq, &[&[0, 1, 2, 3], &[3, 2, 1, 0]])), Some(1));
        // The same sheet as four triangles split by crossing diagonals:
        // each top triangle overlaps each bottom one (sharing an edge or a
        // single corner), four pairs.
        let sheet = mesh(&sq, &[&[0, 1, 2], &[0, 2, 3], &[0, 3, 1], &[1, 3, 2]]);
        assert_eq!(pairs(&sheet), Some(4));
        // A double-sided triangle: the same three corners twice.
        let tri2 = mesh(&sq[..3], &[&[0, 1, 2], &[0, 2, 1]]);
        assert_eq!(pairs(&tri2), Some(1));
    }

    #[test]
    fn pairs_sharing_one_vertex() {
        // Sharing corner 0 and crossing along the segment from it to
        // (1, 1, 0): one pair.
        let v = [
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [0.0, 4.0, 0.0],
            [1.0, 1.0, -1.0],
            [1.0, 1.0, 1.0],
        ];
        assert_eq!(
            self_intersecting_pairs(&mesh(&v, &[&[0, 1, 2], &[0, 3, 4]])),
            1
        );
        // Sharing corner 0 and touching nowhere else: none.
        let w = [v[0], v[1], v[2], [-1.0, -1.0, -1.0], [-1.0, -1.0, 1.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])),
            0
        );
        // Sharing corner 0, coplanar, the second inside the first's angle
        // at 0 (its opposite edge lies inside the first): one pair.
        let w = [v[0], v[1], v[2], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])),
            1
        );
        // Sharing corner 0, upright on the first, meeting it in the segment
        // from 0 to the point (2, 2, 0) of its opposite edge, closed: one
        // pair.
        let w = [v[0], v[1], v[2], [2.0, 2.0, 0.0], [2.0, 2.0, 2.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])),
            1
        );
        // Sharing corner 0, coplanar, in the opposite angle: none.
        let w = [v[0], v[1], v[2], [-1.0, -1.0, 0.0], [-2.0, -1.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])),
            0
        );
        // A corner of the same point under another index is the same
        // corner (coincident vertices): no contact but at it.
        let w = [
            v[0],
            v[1],
            v[2],
            [-1.0, -1.0, -1.0],
            [-1.0, -1.0, 1.0],
            [0.0, 0.0, 0.0],
        ];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[5, 3, 4]])),
            0
        );
    }

    fn cube_at(o: f64, s: f64) -> PolygonMesh {
        let v: Vec<Point3> = (0..8)
            .map(|i| {
                [
                    o + s * f64::from(i & 1),
                    o + s * f64::from((i >> 1) & 1),
                    o + s * f64::from((i >> 2) & 1),
                ]
            })
            .collect();
        mesh(
            &v,
            &[
                &[0, 2, 3, 1],
                &[4, 5, 7, 6],
                &[0, 1, 5, 4],
                &[2, 6, 7, 3],
                &[0, 4, 6, 2],
                &[1, 3, 7, 5],
            ],
        )
    }

    #[test]
    fn boolean_results_of_overlapping_cubes_do_not_self_intersect() {
        use boolean_3d::{boolean_mesh, triangulate_mesh, BooleanOp};
        let (a, b) = (cube_at(0.0, 2.0), cube_at(1.0, 2.0));
        for (op, volume) in [
            (BooleanOp::Union, 15.0),
            (BooleanOp::Intersection, 1.0),
            (BooleanOp::Difference, 7.0),
        ] {
            let out = boolean_mesh(&a, &b, op).unwrap().mesh;
            let r = check_mesh(&out);
            assert!(r.is_valid(), "{op:?}: {r:?}");
            assert_eq!(r.signed_volume, Some(volume), "{op:?}");
            assert_eq!(r.self_intersecting_facet_pairs, Some(0), "{op:?}");
            // Every triangle of the result as a facet of its own: coplanar
            // neighbours, corners on other facets' edges.
            let tri = triangulate_mesh(&out).to_polygon_mesh();
            let r = check_mesh(&tri);
            assert!(r.is_valid(), "{op:?}: {r:?}");
            assert_eq!(r.self_intersecting_facet_pairs, Some(0), "{op:?} triangles");
        }
    }

    // An independent oracle: the intersection of two triangles by exact
    // rational clipping (no orientation predicate), and the rule of the
    // module docs stated on that set.

    use num_rational::BigRational as Q;
    use num_traits::{Signed, Zero};
    use proptest::prelude::*;

    type QPoint = [Q; 3];

    fn qp(p: &Point3) -> QPoint {
        p.map(|c| Q::from_float(c).unwrap())
    }

    fn sub(a: &QPoint, b: &QPoint) -> QPoint {
        [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
    }

    fn cross(a: &QPoint, b: &QPoint) -> QPoint {
        [
            &a[1] * &b[2] - &a[2] * &b[1],
            &a[2] * &b[0] - &a[0] * &b[2],
            &a[0] * &b[1] - &a[1] * &b[0],
        ]
    }

    fn dot(a: &QPoint, b: &QPoint) -> Q {
        &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
    }

    /// `a + (b - a) s`.
    fn lerp(a: &QPoint, b: &QPoint, s: &Q) -> QPoint {
        [0, 1, 2].map(|k| &a[k] + (&b[k] - &a[k]) * s)
    }

    /// Points whose convex hull is the closed intersection of the
    /// non-degenerate triangles `t` and `u`: the part of `t` in `u`'s plane
    /// (all of `t` when coplanar, else the segment where its edges cross
    /// the plane), clipped by `u`'s three edge half-planes
    /// (Sutherland-Hodgman).
    fn exact_meet(t: &[QPoint; 3], u: &[QPoint; 3]) -> Vec<QPoint> {
        let n = cross(&sub(&u[1], &u[0]), &sub(&u[2], &u[0]));
        let d: Vec<Q> = t.iter().map(|x| dot(&n, &sub(x, &u[0]))).collect();
        let mut poly: Vec<QPoint> = if d.iter().all(Zero::is_zero) {
            t.to_vec()
        } else {
            let mut pts = Vec::new();
            for k in 0..3 {
                let j = (k + 1) % 3;
                if d[k].is_zero() {
                    pts.push(t[k].clone());
                }
                if d[k].signum() * d[j].signum() < Q::zero() {
                    pts.push(lerp(&t[k], &t[j], &(&d[k] / (&d[k] - &d[j]))));
                }
            }
            pts
        };
        for k in 0..3 {
            let (a, b) = (&u[k], &u[(k + 1) % 3]);
            let inside = |x: &QPoint| dot(&cross(&sub(b, a), &sub(x, a)), &n);
            let mut next = Vec::new();
            for i in 0..poly.len() {
                let (p, r) = (&poly[i], &poly[(i + 1) % poly.len()]);
                let (fp, fr) = (inside(p), inside(r));
                if !fp.is_negative() {
                    next.push(p.clone());
                }
                if fp.signum() * fr.signum() < Q::zero() {
                    next.push(lerp(p, r, &(&fp / (&fp - &fr))));
                }
            }
            poly = next;
        }
        poly
    }

    /// Whether `x` lies on the closed segment `s e`.
    fn on_segment(x: &QPoint, s: &QPoint, e: &QPoint) -> bool {
        let (xs, es) = (sub(x, s), sub(e, s));
        cross(&xs, &es).iter().all(Zero::is_zero)
            && !dot(&xs, &es).is_negative()
            && dot(&xs, &es) <= dot(&es, &es)
    }

    /// The rule of the module docs on the exact intersection: two
    /// triangles sharing `k` corners meet improperly when their
    /// intersection has a point outside the shared corner (k = 1) or edge
    /// (k = 2), any point (k = 0), or always (k = 3).
    fn oracle(t: &[Point3; 3], tv: [u32; 3], u: &[Point3; 3], uv: [u32; 3]) -> bool {
        let shared: Vec<usize> = (0..3).filter(|&k| uv.contains(&tv[k])).collect();
        let meet = exact_meet(&t.map(|p| qp(&p)), &u.map(|p| qp(&p)));
        let s: Vec<QPoint> = shared.iter().map(|&k| qp(&t[k])).collect();
        match s.len() {
            0 => !meet.is_empty(),
            1 => meet.iter().any(|x| x != &s[0]),
            2 => meet.iter().any(|x| !on_segment(x, &s[0], &s[1])),
            _ => true,
        }
    }

    /// The improperly meeting pairs of a mesh of triangle facets, by the
    /// oracle on every pair (the mesh's vertices are all distinct points).
    fn oracle_pairs(v: &[Point3], t: &[[u32; 3]]) -> usize {
        let p = |x: &[u32; 3]| x.map(|i| v[i as usize]);
        let mut n = 0;
        for i in 0..t.len() {
            for j in i + 1..t.len() {
                n += usize::from(oracle(&p(&t[i]), t[i], &p(&t[j]), t[j]));
            }
        }
        n
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        /// `improper` agrees with the oracle on triangle pairs on a small
        /// integer grid (full of coplanar, collinear and touching cases)
        /// sharing 0, 1, 2 or 3 corners.
        #[test]
        fn improper_agrees_with_exact_clipping(
            c in proptest::collection::vec(proptest::collection::vec(0i32..5, 3), 6),
            shared in 0usize..4,
            rot in 0usize..3,
            flip in any::<bool>(),
        ) {
            let pts: Vec<Point3> = c.iter().map(|q| [q[0], q[1], q[2]].map(f64::from)).collect();
            // t = corners 0, 1, 2; u reuses the first `shared` of them.
            let tv = [0u32, 1, 2];
            let mut uv = [3u32, 4, 5];
            uv[..shared].copy_from_slice(&tv[..shared]);
            uv.rotate_left(rot);
            if flip {
                uv.swap(0, 1);
            }
            let p = |x: [u32; 3]| x.map(|i| pts[i as usize]);
            let (t, u) = (Tri::new(0, tv, &pts), Tri::new(1, uv, &pts));
            // Distinct corners must be distinct points (`weld` sees to it
            // in meshes), and both triangles must have area.
            let used: Vec<usize> = (0..3).chain(3 + shared..6).collect();
            let distinct = used.iter().all(|&i| used.iter().all(|&j| i == j || pts[i] != pts[j]));
            prop_assume!(distinct);
            let (Some(t), Some(u)) = (t, u) else {
                return Err(TestCaseError::reject("zero area"));
            };
            let want = oracle(&p(tv), tv, &p(uv), uv);
            prop_assert_eq!(improper(&t, &u), want, "t {:?} u {:?}", t.p, u.p);
            prop_assert_eq!(improper(&u, &t), want);
        }
    }
}
