//! Exact self-intersection of a polygon mesh. Section 4.2 requires of a geometrically valid shape
//! that its boundary components do not intersect. Every facet is
//! triangulated by internal edges only (section 4.8,
//! [`crate::triangulate_facet`]; a big convex facet by the balanced
//! triangulation below); vertices with exactly equal
//! coordinates are taken as one point (coincident vertices and zero-length
//! edges are features a topologically valid mesh may have, section 4.1);
//! the triangles of different facets whose closed boxes overlap (a
//! bounding-volume hierarchy, pairs streamed to the exact test, never
//! stored) are then tested exactly with `robust_arith::orient3d` and
//! `orient2d`. Two triangles meet where
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

//!
//! Big facets. Ear clipping a convex facet of `n` vertices gives a fan: its
//! triangles' boxes reach across the facet and meet the boxes of the
//! `O(n)` facets around its rim each, `O(n^2)` candidate pairs (a
//! 30,000-sided cylinder took minutes and gigabytes). A facet of more than
//! [`BIG_FACET`] half-edges forming one loop that is strictly convex in its
//! projection (exact) is therefore triangulated by halving: the triangle
//! `(0, n/2, n-1)`, then each half recursively, so the triangles of one
//! level span disjoint arcs of the rim and meet `O(n)` rim boxes in all,
//! `O(n log n)` over the `log n` levels. Any triangulation of a planar
//! convex facet covers the same region, and the rule below does not
//! depend on which. Other facets keep the triangulation of section 4.8.

use super::bvh::Bvh;
use crate::{triangulate_facet, PolygonMesh};
use rayon::prelude::*;
use robust_arith::{orient2d, orient3d, Point3};
use std::cmp::Ordering;
use std::collections::HashMap;

/// The exact sign of `orient3d(a, b, c, d)`.
fn o3(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> i8 {
    orient3d(*a, *b, *c, *d) as i8
}

/// The exact sign of the 2D orientation of the projections onto axes
/// `(i, j)`.
fn o2(a: &Point3, b: &Point3, c: &Point3, (i, j): (usize, usize)) -> i8 {
    let p = |q: &Point3| [q[i], q[j]];
    orient2d(p(a), p(b), p(c)) as i8
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

/// Facets with more half-edges than this are triangulated by halving when
/// they are one strictly convex loop (module docs).
pub(super) const BIG_FACET: usize = 64;

/// The loop of a facet whose half-edges form one simple cycle (every
/// vertex starts exactly one half-edge, no zero-length half-edge), in
/// order; `None` otherwise.
fn single_loop(half_edges: &[(u32, u32)]) -> Option<Vec<u32>> {
    let mut next: HashMap<u32, u32> = HashMap::with_capacity(half_edges.len());
    for &(s, e) in half_edges {
        if s == e || next.insert(s, e).is_some() {
            return None;
        }
    }
    let start = half_edges.first()?.0;
    let mut ring = Vec::with_capacity(half_edges.len());
    let mut at = start;
    loop {
        ring.push(at);
        at = *next.get(&at)?;
        if at == start {
            break;
        }
        if ring.len() > half_edges.len() {
            return None;
        }
    }
    (ring.len() == half_edges.len()).then_some(ring)
}

/// Whether the loop, projected onto the coordinate plane `ax`, is a
/// strictly convex polygon of either orientation, exactly: every corner
/// turns the same way (exact `orient2d`) and the edge directions go round
/// once (the sign of the first projected coordinate's change flips exactly
/// twice around the loop; a loop winding twice flips it four times).
fn strictly_convex(ring: &[u32], positions: &[Point3], ax: (usize, usize)) -> bool {
    let n = ring.len();
    if n < 3 {
        return false;
    }
    let p = |i: usize| {
        let q = positions[ring[i % n] as usize];
        [q[ax.0], q[ax.1]]
    };
    let turn = orient2d(p(n - 1), p(0), p(1));
    if turn == Ordering::Equal {
        return false;
    }
    if (1..n).any(|i| orient2d(p(i - 1), p(i), p(i + 1)) != turn) {
        return false;
    }
    let dirs: Vec<Ordering> = (0..n)
        .filter(|&i| p(i + 1)[0] != p(i)[0])
        .map(|i| p(i + 1)[0].total_cmp(&p(i)[0]))
        .collect();
    let cyclic = (0..dirs.len())
        .filter(|&i| dirs[i] != dirs[(i + 1) % dirs.len()])
        .count();
    cyclic == 2
}

/// The balanced triangulation of a convex loop (module docs): triangles
/// `(i, (i + j) / 2, j)` over the loop positions, starting with `(0, n-1)`,
/// each keeping the loop's orientation.
fn halving_triangulation(ring: &[u32], out: &mut Vec<[u32; 3]>) {
    let n = ring.len();
    if n < 3 {
        return;
    }
    let mut stack = vec![(0usize, n - 1)];
    while let Some((i, j)) = stack.pop() {
        if j - i < 2 {
            continue;
        }
        let k = i + (j - i) / 2;
        out.push([ring[i], ring[k], ring[j]]);
        stack.push((i, k));
        stack.push((k, j));
    }
}

/// Triangulates one facet for the test: a big strictly convex loop by
/// halving, anything else by section 4.8's triangulation.
fn triangulate_for_test(positions: &[Point3], hes: &[(u32, u32)], out: &mut Vec<[u32; 3]>) {
    if hes.len() > BIG_FACET {
        if let Some(ring) = single_loop(hes) {
            if PLANES
                .into_iter()
                .any(|ax| strictly_convex(&ring, positions, ax))
            {
                halving_triangulation(&ring, out);
                return;
            }
        }
    }
    triangulate_facet(positions, hes, out);
}

/// The facet pairs that intersect improperly (module docs), sorted, each
/// `[smaller, larger]`. Requires every index in range and every coordinate
/// finite (the caller checks).
pub(super) fn self_intersecting_pairs(mesh: &PolygonMesh) -> Vec<[u32; 2]> {
    pairs_with(mesh, true, None)
}

/// The facet pairs of `self_intersecting_pairs` that hold at least one
/// facet `f` with `focus[f]`, found without testing the whole mesh: only
/// the facets whose boxes meet a focus facet's box (the only ones that can
/// meet it) and the facets whose boxes meet theirs (which hold every
/// zero-area triangle that splits their edges, so their triangles are cut
/// exactly as in the whole test) are triangulated and tested. The cost is
/// a linear pass over the facets' boxes plus the test of that
/// neighbourhood. `None` when an index is out of range or a coordinate is
/// not finite (the whole test's precondition).
///
/// ```
/// use topology::{check_mesh, self_intersecting_pairs_near, Facet, PolygonMesh};
/// // Two tetrahedra, the second poking into the first.
/// let mut v = vec![[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]];
/// v.extend(v.clone().iter().map(|p| [p[0] + 1.0, p[1] + 1.0, p[2] + 1.0]));
/// let t = |o: u32| vec![[o, o + 2, o + 1], [o, o + 1, o + 3], [o + 1, o + 2, o + 3], [o, o + 3, o + 2]];
/// let facets = t(0).into_iter().chain(t(4)).map(|f| Facet::from_loop(&f)).collect();
/// let m = PolygonMesh::new(v, facets);
/// let all = check_mesh(&m).self_intersecting_facet_pairs.unwrap();
/// let every = self_intersecting_pairs_near(&m, &[true; 8]).unwrap();
/// assert_eq!(every.len(), all);
/// assert!(all > 0);
/// let mut focus = [false; 8];
/// focus[7] = true;
/// let near = self_intersecting_pairs_near(&m, &focus).unwrap();
/// assert!(near.iter().all(|p| p.contains(&7)));
/// assert_eq!(near, every.iter().copied().filter(|p| p.contains(&7)).collect::<Vec<_>>());
/// ```
pub fn self_intersecting_pairs_near(mesh: &PolygonMesh, focus: &[bool]) -> Option<Vec<[u32; 2]>> {
    if !super::report::indices_in_range(mesh) {
        return None;
    }
    pairs_near_with(
        &mesh.vertices,
        mesh.facets.len(),
        |f, out| out.extend(mesh.facets[f].half_edges.iter().map(|h| h.start)),
        |f| mesh.facets[f].clone(),
        focus,
    )
}

/// [`self_intersecting_pairs_near`] on a triangle mesh (each triangle a
/// facet), without building its polygon mesh.
pub fn self_intersecting_triangle_pairs_near(
    mesh: &crate::TriangleMesh,
    focus: &[bool],
) -> Option<Vec<[u32; 2]>> {
    let n = mesh.vertices.len() as u32;
    if !mesh.triangles.par_iter().all(|t| t.iter().all(|&v| v < n)) {
        return None;
    }
    pairs_near_with(
        &mesh.vertices,
        mesh.triangles.len(),
        |f, out| out.extend(mesh.triangles[f]),
        |f| crate::Facet::from_loop(&mesh.triangles[f]),
        focus,
    )
}

/// The pairs near a focus over `count` facets given by their corner
/// indices (`corners`, every index in range) and as facets (`facet`).
fn pairs_near_with(
    vertices: &[Point3],
    count: usize,
    corners: impl Fn(usize, &mut Vec<u32>) + Sync,
    facet: impl Fn(usize) -> crate::Facet,
    focus: &[bool],
) -> Option<Vec<[u32; 2]>> {
    let focus: Vec<bool> = (0..count)
        .map(|f| focus.get(f).copied().unwrap_or(false))
        .collect();
    if !focus.contains(&true) {
        return Some(Vec::new());
    }
    if !vertices.par_iter().all(|p| p.iter().all(|x| x.is_finite())) {
        return None;
    }
    // Facet boxes are computed where they are needed, not kept for the
    // whole mesh: the focus is usually a few facets of a large mesh, and
    // a box per facet of a 2M-triangle mesh is 96 MB to fill.
    let box_of = |f: usize, buf: &mut Vec<u32>| {
        buf.clear();
        corners(f, buf);
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for &v in buf.iter() {
            let p = vertices[v as usize];
            for k in 0..3 {
                b[0][k] = b[0][k].min(p[k]);
                b[1][k] = b[1][k].max(p[k]);
            }
        }
        b
    };
    // The facets whose boxes meet a box of `ring` (a facet mask); a ring
    // of every facet is its own growth (no hierarchy to build: the case of
    // a mesh whose every vertex moved). Most facets of a large mesh are
    // found apart from the ring's bounding box by their corners' codes
    // alone (`sides`).
    let grow = |ring: &[bool]| -> Vec<bool> {
        if ring.iter().all(|&r| r) {
            return ring.to_vec();
        }
        let mut buf = Vec::new();
        let inner: Vec<[Point3; 2]> = (0..count)
            .filter(|&f| ring[f])
            .map(|f| box_of(f, &mut buf))
            .collect();
        let bvh = Bvh::new(&inner);
        let (lo, hi) = inner.iter().fold(
            ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]),
            |(lo, hi), b| {
                (
                    [0, 1, 2].map(|k| lo[k].min(b[0][k])),
                    [0, 1, 2].map(|k| hi[k].max(b[1][k])),
                )
            },
        );
        let all = [lo, hi];
        let codes = super::sides::sides_beyond(vertices, &all);
        ring.par_iter()
            .enumerate()
            .map_init(Vec::new, |buf, (f, &r)| {
                r || {
                    buf.clear();
                    corners(f, buf);
                    !super::sides::facet_apart(&codes, buf.iter().copied()) && {
                        let b = box_of(f, buf);
                        super::bvh::overlap(&b, &all) && bvh.any_overlap(&inner, &b)
                    }
                }
            })
            .collect()
    };
    let near = grow(&focus);
    let kept = grow(&near);
    let ids: Vec<u32> = (0..count as u32).filter(|&f| kept[f as usize]).collect();
    // The neighbourhood as a mesh of its own vertices only (the new index
    // of every vertex, `u32::MAX` until a kept facet uses it).
    let mut index = vec![u32::MAX; vertices.len()];
    let mut sub = PolygonMesh::default();
    for &f in &ids {
        let mut facet = facet(f as usize);
        for h in &mut facet.half_edges {
            for v in [&mut h.start, &mut h.end] {
                let at = &mut index[*v as usize];
                if *at == u32::MAX {
                    *at = sub.vertices.len() as u32;
                    sub.vertices.push(vertices[*v as usize]);
                }
                *v = *at;
            }
        }
        sub.facets.push(facet);
    }
    // Only pairs holding a focus facet are wanted: the others are not
    // tested at all (the neighbourhood is there to cut the focus facets'
    // triangles as the whole test does, not to be tested itself).
    let sub_focus: Vec<bool> = ids.iter().map(|&f| focus[f as usize]).collect();
    let mut pairs: Vec<[u32; 2]> = pairs_with(&sub, true, Some(&sub_focus))
        .into_iter()
        .map(|[a, b]| [ids[a as usize], ids[b as usize]])
        .filter(|[a, b]| focus[*a as usize] || focus[*b as usize])
        .collect();
    pairs.sort_unstable();
    Some(pairs)
}

/// [`self_intersecting_pairs`], big convex facets halved or not (the tests
/// compare the two); with `focus`, only the pairs holding a facet `f` with
/// `focus[f]` (the same pairs as the whole test's, filtered: the other
/// pairs are never tested).
fn pairs_with(mesh: &PolygonMesh, halving: bool, focus: Option<&[bool]>) -> Vec<[u32; 2]> {
    let wanted = |f: u32| focus.is_none_or(|m| m.get(f as usize).copied().unwrap_or(false));
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
        if halving {
            triangulate_for_test(&mesh.vertices, &hes, &mut buf);
        } else {
            triangulate_facet(&mesh.vertices, &hes, &mut buf);
        }
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
    // Broad phase: a box hierarchy; each triangle queries it for the
    // triangles after it whose closed boxes meet its own, and every
    // candidate goes straight to the exact test (memory stays linear plus
    // the pairs found).
    let boxes: Vec<[Point3; 2]> = tris.iter().map(|t| [t.lo, t.hi]).collect();
    let bvh = Bvh::new(&boxes);
    let mut hits: Vec<[u32; 2]> = (0..tris.len())
        .into_par_iter()
        .fold(FacetPairs::default, |mut found, pos| {
            let i = bvh.order()[pos];
            let t = &tris[i as usize];
            bvh.query_after(&boxes, pos, |j| {
                let u = &tris[j as usize];
                if u.facet != t.facet && (wanted(t.facet) || wanted(u.facet)) && improper(t, u) {
                    found.push([t.facet.min(u.facet), t.facet.max(u.facet)]);
                }
            });
            found
        })
        .reduce(FacetPairs::default, |mut a, b| {
            for p in b.pairs {
                a.push(p);
            }
            a
        })
        .pairs;
    hits.sort_unstable();
    hits.dedup();
    hits
}

/// Facet pairs found, deduplicated whenever the list has doubled, so it
/// holds at most about twice the distinct pairs.
#[derive(Default)]
struct FacetPairs {
    pairs: Vec<[u32; 2]>,
    /// The length after the last deduplication.
    clean: usize,
}

impl FacetPairs {
    fn push(&mut self, p: [u32; 2]) {
        self.pairs.push(p);
        if self.pairs.len() > 2 * self.clean + 1024 {
            self.pairs.sort_unstable();
            self.pairs.dedup();
            self.clean = self.pairs.len();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check_mesh;

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

    /// A polygon mesh from coordinates and facet loops.
    fn mesh(v: &[Point3], loops: &[&[u32]]) -> PolygonMesh {
        PolygonMesh::new(
            v.to_vec(),
            loops.iter().map(|l| crate::Facet::from_loop(l)).collect(),
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
            self_intersecting_pairs(&mesh(&v, &[&[0, 1, 2], &[1, 0, 3]])).len(),
            1
        );
        // Third corners on opposite sides: they meet in the edge only.
        let w = [v[0], v[1], v[2], [1.0, -2.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[1, 0, 3]])).len(),
            0
        );
        // Third corner lifted off the plane: a dihedral angle above zero.
        let w = [v[0], v[1], v[2], [1.0, 2.0, 1e-300]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[1, 0, 3]])).len(),
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
            self_intersecting_pairs(&mesh(&v, &[&[0, 1, 2], &[0, 3, 4]])).len(),
            1
        );
        // Sharing corner 0 and touching nowhere else: none.
        let w = [v[0], v[1], v[2], [-1.0, -1.0, -1.0], [-1.0, -1.0, 1.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])).len(),
            0
        );
        // Sharing corner 0, coplanar, the second inside the first's angle
        // at 0 (its opposite edge lies inside the first): one pair.
        let w = [v[0], v[1], v[2], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])).len(),
            1
        );
        // Sharing corner 0, upright on the first, meeting it in the segment
        // from 0 to the point (2, 2, 0) of its opposite edge, closed: one
        // pair.
        let w = [v[0], v[1], v[2], [2.0, 2.0, 0.0], [2.0, 2.0, 2.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])).len(),
            1
        );
        // Sharing corner 0, coplanar, in the opposite angle: none.
        let w = [v[0], v[1], v[2], [-1.0, -1.0, 0.0], [-2.0, -1.0, 0.0]];
        assert_eq!(
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[0, 3, 4]])).len(),
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
            self_intersecting_pairs(&mesh(&w, &[&[0, 1, 2], &[5, 3, 4]])).len(),
            0
        );
    }

    /// A prism over a polygon in the plane z = 0 (loop `ring` of 2D
    /// points, anticlockwise), from z = 0 to `h`, moved by `off`.
    fn prism(ring: &[[f64; 2]], h: f64, off: Point3) -> (Vec<Point3>, Vec<Vec<u32>>) {
        let n = ring.len() as u32;
        let mut v = Vec::new();
        for z in [0.0, h] {
            v.extend(
                ring.iter()
                    .map(|p| [p[0] + off[0], p[1] + off[1], z + off[2]]),
            );
        }
        let mut f = vec![(0..n).rev().collect::<Vec<u32>>(), (n..2 * n).collect()];
        for i in 0..n {
            let j = (i + 1) % n;
            f.push(vec![i, j, n + j, n + i]);
        }
        (v, f)
    }

    #[test]
    fn convexity_is_decided_exactly() {
        let circle = |n: usize, turns: usize| -> Vec<Point3> {
            (0..n)
                .map(|i| {
                    let t = std::f64::consts::TAU * (turns * i) as f64 / n as f64;
                    [t.cos(), t.sin(), 0.0]
                })
                .collect()
        };
        let ring: Vec<u32> = (0..101).collect();
        assert!(strictly_convex(&ring, &circle(101, 1), (0, 1)));
        // Clockwise is convex too; the other projections collapse.
        let rev: Vec<u32> = ring.iter().rev().copied().collect();
        assert!(strictly_convex(&rev, &circle(101, 1), (0, 1)));
        assert!(!strictly_convex(&ring, &circle(101, 1), (1, 2)));
        // A star polygon {101/2}: every corner turns the same way, twice
        // round.
        assert!(!strictly_convex(&ring, &circle(101, 2), (0, 1)));
        // Three collinear corners: not strictly convex.
        let mut sq: Vec<Point3> = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        sq.extend([[2.0, 2.0, 0.0], [0.0, 2.0, 0.0]]);
        assert!(!strictly_convex(&[0, 1, 2, 3, 4], &sq, (0, 1)));
        assert_eq!(single_loop(&[(0, 1), (1, 2), (2, 0)]), Some(vec![0, 1, 2]));
        assert_eq!(single_loop(&[(0, 1), (1, 0), (2, 3), (3, 2)]), None);
        assert_eq!(single_loop(&[(0, 1), (1, 2), (2, 0), (0, 2)]), None);
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: test_support::cases(48),
            max_global_rejects: test_support::cases(1024),
            ..ProptestConfig::default()
        })]

        /// Big convex caps halved give the same facet pairs as section
        /// 4.8's triangulation (a fan): two prisms over random convex
        /// polygons of 65 to 140 vertices (on a grid, so degenerate
        /// contacts occur), the second shifted to cross, touch or miss
        /// the first.
        #[test]
        fn halving_big_convex_caps_changes_no_pair(
            n in 65usize..140,
            m in 65usize..140,
            dx in -12i32..=12,
            dz in -2i32..=6,
            r in 4u32..9,
        ) {
            let poly = |n: usize, r: f64| -> Vec<[f64; 2]> {
                let mut pts: Vec<[f64; 2]> = (0..n)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / n as f64;
                        [(r * t.cos() * 64.0).round() / 8.0, (r * t.sin() * 64.0).round() / 8.0]
                    })
                    .collect();
                pts.dedup();
                // Keep the strictly convex corners only (grid rounding).
                let mut hull: Vec<[f64; 2]> = Vec::new();
                for p in pts {
                    while hull.len() >= 2
                        && orient2d(hull[hull.len() - 2], hull[hull.len() - 1], p) != Ordering::Greater
                    {
                        hull.pop();
                    }
                    hull.push(p);
                }
                // Close the chain: drop corners that do not turn left
                // across the wrap.
                loop {
                    let k = hull.len();
                    if k > 3 && orient2d(hull[k - 2], hull[k - 1], hull[0]) != Ordering::Greater {
                        hull.pop();
                    } else if k > 3 && orient2d(hull[k - 1], hull[0], hull[1]) != Ordering::Greater {
                        hull.remove(0);
                    } else {
                        break;
                    }
                }
                hull
            };
            let (mut v, mut f) = prism(&poly(n, f64::from(r)), 4.0, [0.0; 3]);
            let (v2, f2) = prism(&poly(m, 5.0), 3.0, [f64::from(dx) / 2.0, 0.5, f64::from(dz) / 2.0]);
            let off = v.len() as u32;
            v.extend(v2);
            f.extend(f2.into_iter().map(|l| l.into_iter().map(|x| x + off).collect()));
            let mesh = PolygonMesh::new(v, f.iter().map(|l| crate::Facet::from_loop(l)).collect());
            prop_assume!(mesh.check_topology().is_ok());
            // The caps really are big convex loops (halved).
            let caps: Vec<u32> = (0..mesh.facets.len())
                .filter(|&i| {
                    let hes: Vec<(u32, u32)> =
                        mesh.facets[i].half_edges.iter().map(|h| (h.start, h.end)).collect();
                    hes.len() > BIG_FACET
                        && single_loop(&hes)
                            .is_some_and(|r| strictly_convex(&r, &mesh.vertices, (0, 1)))
                })
                .map(|i| i as u32)
                .collect();
            prop_assert_eq!(caps, vec![0, 1, off / 2 + 2, off / 2 + 3]);
            prop_assert_eq!(pairs_with(&mesh, true, None), pairs_with(&mesh, false, None));
        }

        /// The pairs near a focus are the whole test's pairs that hold a
        /// focus facet: random triangle soups on a small grid (coincident,
        /// touching, zero-area and T-junction triangles among them) and
        /// random focus masks.
        #[test]
        fn pairs_near_a_focus_are_the_whole_tests_restricted(
            c in proptest::collection::vec(proptest::collection::vec(0i32..6, 3), 4..40),
            t in proptest::collection::vec(proptest::collection::vec(0usize..40, 3), 1..30),
            mask in any::<u64>(),
        ) {
            let v: Vec<Point3> = c.iter().map(|q| [q[0], q[1], q[2]].map(f64::from)).collect();
            let n = v.len();
            let facets: Vec<crate::Facet> = t
                .iter()
                .filter(|x| x[0] % n != x[1] % n && x[1] % n != x[2] % n && x[0] % n != x[2] % n)
                .map(|x| crate::Facet::from_loop(&[x[0] % n, x[1] % n, x[2] % n].map(|i| i as u32)))
                .collect();
            let mesh = PolygonMesh::new(v, facets);
            let focus: Vec<bool> = (0..mesh.facets.len()).map(|f| mask >> (f % 64) & 1 == 1).collect();
            let want: Vec<[u32; 2]> = pairs_with(&mesh, true, None)
                .into_iter()
                .filter(|p| focus[p[0] as usize] || focus[p[1] as usize])
                .collect();
            prop_assert_eq!(&pairs_with(&mesh, true, Some(&focus)), &want);
            let tris = crate::TriangleMesh::new(
                mesh.vertices.clone(),
                mesh.facets
                    .iter()
                    .map(|f| [0, 1, 2].map(|k| f.half_edges[k].start))
                    .collect(),
            );
            prop_assert_eq!(self_intersecting_triangle_pairs_near(&tris, &focus), Some(want.clone()));
            prop_assert_eq!(self_intersecting_pairs_near(&mesh, &focus), Some(want));
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
        #![proptest_config(ProptestConfig {
            cases: test_support::cases(4000),
            // About 7% of the draws are rejected: scaled with the cases.
            max_global_rejects: test_support::cases(1024),
            ..ProptestConfig::default()
        })]

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
