//! The triangle-mesh variant of 3D smoothing: the triangles are smoothed
//! as a polygon mesh and every facet smoothing changed (no longer one
//! loop of three half-edges) is re-triangulated by internal edges only,
//! by the rules of section 4.8, so the output stays a triangle mesh
//! satisfying shape boundary closure: a simple loop by the exact
//! recurrence of `quality` (no fold, no internal edge a second run would
//! crack, wherever the facet allows), anything else by ear clipping
//! (`topology::triangulate_facet`); then flips.

use crate::mesh::plane::best_fit_plane;
use crate::mesh::run;
use crate::{SmoothError, SmoothOptions, SmoothReport, Smoothed};
use quality::{crackable, triangulate_loop};
use std::collections::{HashMap, HashSet};
use topology::{triangulate_facet, HalfEdge, Point3, PolygonMesh, TriangleMesh};

mod quality;

/// Twice the signed area of the 2D triangle `a b c`.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether `d` lies strictly inside the circle through the anticlockwise
/// triangle `a b c`.
fn in_circle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let r = |p: [f64; 2]| {
        let (x, y) = (p[0] - d[0], p[1] - d[1]);
        (x, y, x * x + y * y)
    };
    let (ax, ay, a2) = r(a);
    let (bx, by, b2) = r(b);
    let (cx, cy, c2) = r(c);
    let det = ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx);
    det > 0.0
}

/// Whether `p` lies within `delta` of the segment `a b` (2D).
fn near_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2], delta: f64) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (x, y) = (a[0] + t * d[0] - p[0], a[1] + t * d[1] - p[1]);
    x * x + y * y <= delta * delta
}

/// Improves the triangles of one re-triangulated facet by flipping
/// internal edges (Lawson's flips towards the Delaunay triangulation in
/// the facet's plane), which removes the thin triangles ear clipping
/// leaves beside vertices that cracking put on the facet's edges. A flip
/// replaces the internal edge of the quadrilateral `u q v p` by `p q`: the
/// quadrilateral's four half-edges stay and the internal edge is again a
/// half-edge pair, so closure holds whatever the geometry. Only strictly
/// convex quadrilaterals are flipped, never to a new internal edge that
/// passes within `delta` of a vertex of the facet (which a second run
/// would crack); the number of flips is capped (the safety net against
/// rounding cycles).
fn flip_to_delaunay(pos: &[Point3], boundary: &[HalfEdge], tris: &mut [[u32; 3]], delta: f64) {
    if tris.len() < 2 {
        return;
    }
    let Some(plane) = best_fit_plane(pos, boundary) else {
        return;
    };
    let p2 = |v: u32| plane.project(pos[v as usize]);
    let boundary_edges: HashSet<(u32, u32)> = boundary
        .iter()
        .map(|h| (h.start.min(h.end), h.start.max(h.end)))
        .collect();
    // `u < v` where it is called.
    let on_boundary = |u: u32, v: u32| boundary_edges.contains(&(u, v));
    let mut corners: Vec<u32> = boundary.iter().map(|h| h.start).collect();
    corners.sort_unstable();
    corners.dedup();
    // Whether a new internal edge `p q` would pass within `delta` of a
    // vertex of the facet (a second run would crack it there).
    let crackable_edge = |p: u32, q: u32| {
        let (a, b) = (pos[p as usize], pos[q as usize]);
        corners
            .iter()
            .any(|&w| w != p && w != q && crackable(pos[w as usize], a, b, delta))
    };
    let cap = 4 * tris.len() * tris.len();
    let mut flips = 0;
    // Directed half-edge -> (triangle, corner of its start).
    let mut at: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    let index = |at: &mut HashMap<(u32, u32), (usize, usize)>, t: usize, tri: [u32; 3]| {
        for k in 0..3 {
            at.insert((tri[k], tri[(k + 1) % 3]), (t, k));
        }
    };
    for (t, &tri) in tris.iter().enumerate() {
        index(&mut at, t, tri);
    }
    let mut changed = true;
    while changed && flips < cap {
        changed = false;
        for t1 in 0..tris.len() {
            for k1 in 0..3 {
                let (u, v) = (tris[t1][k1], tris[t1][(k1 + 1) % 3]);
                let Some(&(t2, k2)) = at.get(&(v, u)) else {
                    continue;
                };
                if t2 == t1 || u > v || on_boundary(u, v) {
                    continue;
                }
                if tris[t2][k2] != v || tris[t2][(k2 + 1) % 3] != u {
                    continue; // a repeated half-edge: the map kept another
                }
                let p = tris[t1][(k1 + 2) % 3];
                let q = tris[t2][(k2 + 2) % 3];
                if p == q {
                    continue;
                }
                let (pu, pv, pp, pq) = (p2(u), p2(v), p2(p), p2(q));
                let after = orient(pu, pq, pp) > 0.0 && orient(pv, pp, pq) > 0.0;
                let convex = orient(pu, pv, pp) > 0.0 && orient(pv, pu, pq) > 0.0 && after;
                // A sliver: `p` or `q` within `delta` of the internal
                // edge, which a later run would crack there; flipped when
                // both new triangles are properly oriented.
                let sliver =
                    after && (near_segment(pp, pu, pv, delta) || near_segment(pq, pu, pv, delta));
                if !sliver && (!convex || !in_circle(pu, pv, pp, pq)) {
                    continue;
                }
                if crackable_edge(p, q) {
                    continue; // the flip would make what it removes
                }
                for tri in [tris[t1], tris[t2]] {
                    for k in 0..3 {
                        at.remove(&(tri[k], tri[(k + 1) % 3]));
                    }
                }
                tris[t1] = [u, q, p];
                tris[t2] = [v, p, q];
                index(&mut at, t1, tris[t1]);
                index(&mut at, t2, tris[t2]);
                flips += 1;
                changed = true;
            }
        }
    }
}

/// The triangle `t` rotated so that its smallest vertex comes first
/// (the same key for the same oriented cycle of vertices).
fn rotated(t: [u32; 3]) -> [u32; 3] {
    let k = (0..3).min_by_key(|&k| t[k]).unwrap_or(0);
    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
}

/// Facet cancellation in full on triangles: removes pairs of triangles
/// on the same three vertices in opposite orientations (each one's
/// half-edges are the other's reversed, so removing both keeps shape
/// closure) and returns the number of pairs removed. Same-oriented
/// repeats are kept; a triangle cancels at most one opposite triangle.
fn cancel_opposite_triangles(triangles: &mut Vec<[u32; 3]>) -> u64 {
    // Oriented cycle -> indices of not yet cancelled triangles with it.
    let mut open: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
    let mut dead = vec![false; triangles.len()];
    let mut pairs = 0u64;
    for (i, &t) in triangles.iter().enumerate() {
        let key = rotated(t);
        let reverse = rotated([t[0], t[2], t[1]]);
        if let Some(j) = open.get_mut(&reverse).and_then(Vec::pop) {
            dead[i] = true;
            dead[j] = true;
            pairs += 1;
        } else {
            open.entry(key).or_default().push(i);
        }
    }
    if pairs > 0 {
        let mut i = 0;
        triangles.retain(|_| {
            i += 1;
            !dead[i - 1]
        });
    }
    pairs
}

/// Smooths a triangle mesh ([`crate::smooth_mesh`] on its triangles) and
/// re-triangulates the facets smoothing changed (section 4.8), counting
/// them in `facets_retriangulated`. The input is validated first and
/// never modified; the result satisfies [`crate::sanity_check_triangles`].
pub fn smooth_triangles(
    mesh: &TriangleMesh,
    options: &SmoothOptions,
) -> Result<Smoothed<TriangleMesh>, SmoothError> {
    options.validate()?;
    mesh.check_topology()?;
    mesh.validate_coordinates()?;
    let (poly, mut report) = run(&mesh.to_polygon_mesh(), options)?;
    let mut shape = triangulate_result(&poly, &mut report, options.tolerance);
    if options.guard && report.counts != crate::SmoothCounts::default() {
        let all = |n: usize| vec![true; n];
        let verdict = crate::mesh::guard::guard(
            &report,
            (mesh, &all(mesh.triangles.len())),
            (&shape, &all(shape.triangles.len())),
        );
        (shape, report) = verdict.apply(mesh, shape, report);
    }
    // The postconditions of a smoothing result; the guard's undone
    // places (and an input handed back) keep the input's features.
    #[cfg(debug_assertions)]
    if report.reverted.is_none() {
        crate::sanity_check_triangles(&shape, options.tolerance)?;
    }
    Ok(Smoothed { shape, report })
}

/// The triangle mesh of a smoothed polygon mesh: one-triangle facets
/// kept, every other facet re-triangulated (section 4.8: a simple loop of
/// at most `quality::MAX_VERTICES` vertices by `triangulate_loop`, else
/// by ear clipping) and improved by flips, then degenerate and opposite triangle pairs removed and unused
/// vertices dropped; the counts go into `report`.
pub(crate) fn triangulate_result(
    poly: &PolygonMesh,
    report: &mut SmoothReport,
    tolerance: f64,
) -> TriangleMesh {
    let mut triangles = Vec::with_capacity(poly.facets.len());
    let mut pairs = Vec::new();
    for f in &poly.facets {
        let h = &f.half_edges;
        if h.len() == 3
            && h[0].end == h[1].start
            && h[1].end == h[2].start
            && h[2].end == h[0].start
        {
            triangles.push([h[0].start, h[1].start, h[2].start]);
            continue;
        }
        pairs.clear();
        pairs.extend(h.iter().map(|h| (h.start, h.end)));
        let first = triangles.len();
        if !triangulate_loop(&poly.vertices, h, tolerance, &mut triangles) {
            triangulate_facet(&poly.vertices, &pairs, &mut triangles);
        }
        flip_to_delaunay(&poly.vertices, h, &mut triangles[first..], tolerance);
        report.counts.facets_retriangulated += 1;
    }
    // A triangle repeating a vertex holds a zero-length half-edge and a
    // half-edge with its reverse: dropping it keeps shape closure.
    triangles.retain(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    // Re-triangulating two differently bounded coincident facets can give
    // the same triangle in both orientations: facet cancellation in full
    // (Appendix A) on the triangles removes every such pair.
    report.counts.facets_cancelled += cancel_opposite_triangles(&mut triangles);
    // Vertices only such triangles used are dropped too.
    let mut used = vec![false; poly.vertices.len()];
    for &v in triangles.iter().flatten() {
        used[v as usize] = true;
    }
    let mut map = vec![0u32; poly.vertices.len()];
    let mut vertices = Vec::with_capacity(poly.vertices.len());
    for (i, &u) in used.iter().enumerate() {
        if u {
            map[i] = vertices.len() as u32;
            vertices.push(poly.vertices[i]);
        } else {
            report.counts.unreferenced_vertices_removed += 1;
        }
    }
    for t in &mut triangles {
        *t = t.map(|v| map[v as usize]);
    }
    TriangleMesh::new(vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opposite_triangles_cancel_in_pairs_and_same_oriented_repeats_stay() {
        // (0 1 2) appears twice, its reverse once (as a rotation), a
        // fourth triangle stands alone: one pair cancels.
        let mut t = vec![[0, 1, 2], [3, 4, 5], [1, 0, 2], [2, 0, 1], [5, 6, 7]];
        assert_eq!(cancel_opposite_triangles(&mut t), 1);
        assert_eq!(t, vec![[3, 4, 5], [2, 0, 1], [5, 6, 7]]);
        // Both orientations twice: everything goes; the half-edge
        // multiset of what is removed is balanced.
        let mut t = vec![[0, 1, 2], [0, 2, 1], [1, 2, 0], [2, 1, 0]];
        assert_eq!(cancel_opposite_triangles(&mut t), 2);
        assert!(t.is_empty());
        let mut t = vec![[0, 1, 2], [0, 1, 3]];
        assert_eq!(cancel_opposite_triangles(&mut t), 0);
        assert_eq!(t.len(), 2);
    }

    #[test]
    fn a_sliver_beside_a_straight_boundary_is_flipped() {
        // The quadrilateral a b c d with b on the segment a c: the
        // triangulation (a b c) + (a c d) has an internal edge a c through
        // b; the flip gives (b c d) + (b d a) (as `[u, q, p]`, `[v, p, q]`).
        let pos = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        let boundary: Vec<HalfEdge> = [(0, 1), (1, 2), (2, 3), (3, 0)]
            .iter()
            .map(|&(start, end)| HalfEdge { start, end })
            .collect();
        let mut tris = [[0, 1, 2], [0, 2, 3]];
        flip_to_delaunay(&pos, &boundary, &mut tris, 1e-9);
        for t in &tris {
            assert!(t.contains(&1) && t.contains(&3), "{tris:?}");
        }
    }
}
