//! The triangulation of a facet by internal edges (section 4.8), used by
//! the triangle-mesh variant of the 3D Boolean and by shape inspection:
//! internal edges are added between vertices of the facet, so the
//! original half-edges plus both half-edges of every internal edge form the
//! triangles. Topology holds whatever the geometry; the geometry is as good
//! as ear clipping in the facet's dominant projection plane can make it.
//!
//! Steps:
//!
//! 1. Chain the half-edges into loops (facet boundary closure makes this
//!    always possible). Loops of one or two half-edges (`v->v`, or
//!    `a->b->a`) are dropped: their half-edges balance among themselves, so
//!    facet and shape boundary closure are unaffected.
//! 2. Project onto the coordinate plane most perpendicular to the facet's
//!    Newell normal, mirrored so that the facet's outer loops run
//!    anticlockwise.
//! 3. Loops of positive area are outer boundaries; the others are holes.
//!    Each hole is bridged into the outer boundary its rightmost vertex sees
//!    first along the +u ray (the scheme of Eberly's and the `earcut`
//!    library's hole elimination), by an internal edge added as two
//!    half-edges, one each way. A hole whose rightmost vertex is not inside
//!    a region (the ray meets no boundary, or first meets one from outside)
//!    bounds an inside-out region (section 4.7): a bridge would only drag
//!    the region's triangles across the facet, so it is triangulated on its
//!    own, mirrored. Where a vertex is on the polygon more than once (a
//!    bridge reached it before), the bridge leaves from the copy whose
//!    corner opens towards the hole, so that bridges never cross.
//! 4. Each outer polygon is ear-clipped: an ear `(a, b, c)` adds the
//!    internal edge `c -> a` to the triangle and `a -> c` to the remaining
//!    polygon. A valid ear (anticlockwise, no other vertex in it) is taken
//!    first, one whose chord passes through no vertex before one that
//!    does (through its tip or a vertex of a straight side, to a turn of
//!    about 1e-9, as where the Boolean put vertices on a facet's side:
//!    the flat triangle it leaves folds against the neighbouring facets);
//!    then a degenerate (zero-area) one. When neither exists the
//!    polygon is geometrically invalid, and the ear of smallest absolute
//!    area is clipped. For a quadrilateral both diagonals are compared: a
//!    valid one (two anticlockwise triangles) is taken; of two valid ones,
//!    the one whose smaller triangle is larger (the other would pass
//!    through a corner that is straight to rounding, such as a vertex the
//!    Boolean put on a facet's side: section 4.8's ideal internal edge
//!    touches nothing but at its ends); of two invalid ones, the one whose
//!    two triangles cover the smaller total area (figure 4.10). Every triangulation of a loop has the loop's winding
//!    number everywhere (the internal edges cancel), so the covered area
//!    beyond `|winding|` is exactly the overlap the figure minimises. An
//!    ear over a vertex the polygon visits twice (a spike along a bridge,
//!    or where a hole touches the boundary) that repeats the vertex has
//!    zero area and half-edges that balance by themselves: it is dropped,
//!    so no triangle of the result repeats a vertex.
//! 5. Ear clipping is optimal when every triangle faces the polygon's way
//!    (the covered area is then the polygon's signed area, a lower bound
//!    for any triangulation). Otherwise the polygon is geometrically
//!    invalid, and a greedy choice of ears can extend the invalid region
//!    far more than necessary (a figure eight can be clipped straight
//!    across its crossing), so a polygon of at most `MAX_OPTIMAL`
//!    vertices is re-triangulated by the exact minimum of the total
//!    absolute triangle area over all its triangulations by internal edges
//!    (section 4.8: "minimises how far any geometrically invalid region is
//!    extended").
//!
//! Cost. Facets of many vertices and holes (a slab's face pierced by
//! 1,000 boxes) take `O(n log n)`-like time rather than the quadratic one
//! of plain hole elimination and ear clipping: holes are merged into
//! linked lists (`bridge`), and both the bridges' ray and triangle
//! searches and the ear tests look their candidates up in a uniform grid
//! (`grid`) instead of scanning the polygon. The grid only narrows the
//! candidates, never the tests they go through, so the indexed and the
//! linear search (kept for small polygons and non-finite coordinates)
//! build the same triangles; the property tests check it.

mod bridge;
mod ear;
mod grid;
mod optimal;
mod projection;
#[cfg(test)]
mod props;

pub use projection::FacetProjection;

use crate::{HalfEdge, PolygonMesh, TriangleMesh};
use robust_arith::Point3;

type P2 = [f64; 2];

/// How the hole bridging and the ear tests find their candidates: in a
/// spatial index (big polygons with finite coordinates) or by scanning
/// every vertex and edge. Both find the same bridges and ears; the linear
/// scan is kept for small polygons and as the tests' reference.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Search {
    Linear,
    Indexed,
}

/// Triangulates one facet given as half-edges `(start, end)` between
/// vertices of `positions` (section 4.8), appending triangles to `out`.
///
/// The triangles' half-edges are the facet's half-edges (minus loops of one
/// or two half-edges, which balance by themselves) plus both half-edges of
/// every internal edge, so a mesh of facets satisfying shape boundary
/// closure stays closed. Half-edges referring to a vertex beyond
/// `positions` make the facet invalid input: it is skipped (no triangles).
///
/// A valid facet gives non-overlapping triangles facing its way. An
/// invalid one (figure 4.10) gives, for each of its polygons of up to 160
/// vertices, the triangulation covering the least total area, i.e.
/// extending the invalid region as little as possible, and triangulates
/// inside-out loops lying outside every region on their own.
pub fn triangulate_facet(positions: &[Point3], half_edges: &[(u32, u32)], out: &mut Vec<[u32; 3]>) {
    let search = if half_edges.len() >= ear::INDEXED {
        Search::Indexed
    } else {
        Search::Linear
    };
    triangulate_facet_by(positions, half_edges, search, out);
}

/// [`triangulate_facet`] with the given candidate search.
fn triangulate_facet_by(
    positions: &[Point3],
    half_edges: &[(u32, u32)],
    search: Search,
    out: &mut Vec<[u32; 3]>,
) {
    let n = positions.len();
    if half_edges
        .iter()
        .any(|&(s, e)| s as usize >= n || e as usize >= n)
    {
        return;
    }
    if half_edges.len() == 3 {
        let [h0, h1, h2] = [half_edges[0], half_edges[1], half_edges[2]];
        if h0.1 == h1.0 && h1.1 == h2.0 && h2.1 == h0.0 {
            // A loop of three half-edges over a repeated vertex is a
            // zero-length half-edge and an opposite pair, which balance
            // themselves: nothing to triangulate (a triangle on it would
            // repeat a vertex).
            if h0.0 != h1.0 && h1.0 != h2.0 && h2.0 != h0.0 {
                out.push([h0.0, h1.0, h2.0]);
            }
            return;
        }
    }
    let Some(&(first, _)) = half_edges.iter().find(|&&(s, e)| s != e) else {
        return; // only zero-length half-edges: each balances itself
    };
    // The plane of the Newell normal (`projection.rs`), relative to one
    // vertex for accuracy.
    let plane = FacetProjection::new(positions, half_edges, first);
    let proj = |v: u32| plane.project(positions[v as usize]);
    let loops = chain_loops(half_edges, &proj);
    let rings: Vec<Vec<(u32, P2)>> = loops
        .iter()
        .filter(|l| l.len() >= 3)
        .map(|l| l.iter().map(|&v| (v, proj(v))).collect())
        .collect();
    if rings.is_empty() {
        return;
    }
    for polygon in bridge::bridge_holes(rings, search) {
        triangulate_polygon(polygon, search, out);
    }
}

/// Polygons of at most this many vertices that ear clipping leaves with a
/// reversed triangle are re-triangulated by the exact minimum-overlap
/// recurrence (`O(n^3)` time, `O(n^2)` memory; invalid polygons are rare).
const MAX_OPTIMAL: usize = 160;

/// Triangulates one polygon (an outer boundary with its holes bridged in,
/// or an inside-out loop on its own), appending triangles of vertex ids.
fn triangulate_polygon(mut poly: Vec<(u32, P2)>, search: Search, out: &mut Vec<[u32; 3]>) {
    // A polygon of negative area (an inside-out loop, section 4.7) is
    // clipped mirrored, so that its ears are valid, and flipped back:
    // reversing a ring and every triangle keeps the internal edges paired.
    let flip = ring_area(&poly) < 0.0;
    if flip {
        poly.reverse();
    }
    let mut tris = Vec::with_capacity(poly.len().saturating_sub(2));
    ear::ear_clip(&poly, search, &mut tris);
    let twice_area = |t: &[usize; 3]| orient(poly[t[0]].1, poly[t[1]].1, poly[t[2]].1);
    if poly.len() <= MAX_OPTIMAL && tris.iter().any(|t| twice_area(t) < 0.0) {
        // Figure 4.10 generalised: the triangulation covering the least
        // total area, if it beats the ears.
        let clipped: f64 = tris.iter().map(|t| twice_area(t).abs()).sum();
        let (least, optimal) = optimal::min_overlap(&poly);
        if least < clipped {
            tris = optimal;
        }
    }
    // A triangle over a repeated vertex (an ear at a vertex the polygon
    // visits twice, where a hole touches the boundary) has zero area and
    // half-edges that balance by themselves (`x->y`, `y->x`, `x->x`):
    // dropping it keeps facet and shape boundary closure, and a triangle
    // mesh never holds a triangle that repeats a vertex.
    out.extend(tris.iter().filter_map(|t| {
        let [a, b, c] = t.map(|i| poly[i].0);
        if a == b || b == c || c == a {
            None
        } else if flip {
            Some([a, c, b])
        } else {
            Some([a, b, c])
        }
    }));
}

/// Triangulates every facet of a polygon mesh (section 4.8). The result
/// satisfies shape boundary closure whenever the input does.
pub fn triangulate_mesh(mesh: &PolygonMesh) -> TriangleMesh {
    let mut tris = Vec::new();
    let mut hes = Vec::new();
    let n = mesh.vertices.len() as u32;
    for f in &mesh.facets {
        hes.clear();
        hes.extend(
            f.half_edges
                .iter()
                .filter(|h| h.start < n && h.end < n)
                .map(|&HalfEdge { start, end }| (start, end)),
        );
        triangulate_facet(&mesh.vertices, &hes, &mut tris);
    }
    TriangleMesh::new(mesh.vertices.clone(), tris)
}

/// Chains half-edges into closed loops of vertices. Where a vertex has
/// several unused outgoing half-edges (the facet touches itself there), the
/// one first clockwise from the way back along the incoming half-edge is
/// taken, which traces each region with its interior on the left without
/// crossing the other regions when the facet is valid. Every half-edge ends
/// up in exactly one loop when the facet is closed; an open chain
/// (impossible for closed facets) is returned as is.
fn chain_loops(half_edges: &[(u32, u32)], proj: &impl Fn(u32) -> P2) -> Vec<Vec<u32>> {
    let mut by_start: Vec<u32> = (0..half_edges.len() as u32).collect();
    by_start.sort_by_key(|&i| (half_edges[i as usize].0, i));
    let mut used = vec![false; half_edges.len()];
    let mut loops = Vec::new();
    for first in 0..half_edges.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let start = half_edges[first].0;
        if half_edges[first].1 == start {
            continue; // a zero-length half-edge balances itself
        }
        let mut ring = vec![start];
        let mut from = start;
        let mut at = half_edges[first].1;
        while at != start {
            let lo = by_start.partition_point(|&i| half_edges[i as usize].0 < at);
            let mut cands = by_start[lo..]
                .iter()
                .take_while(|&&i| half_edges[i as usize].0 == at)
                .filter(|&&i| !used[i as usize] && half_edges[i as usize].1 != at)
                .copied();
            let Some(mut best) = cands.next() else {
                break;
            };
            let rest: Vec<u32> = cands.collect();
            if !rest.is_empty() {
                let pa = proj(at);
                let back = proj(from);
                let back_ang = (back[1] - pa[1]).atan2(back[0] - pa[0]);
                let cw = |i: u32| {
                    let w = proj(half_edges[i as usize].1);
                    let a = (w[1] - pa[1]).atan2(w[0] - pa[0]);
                    let mut d = back_ang - a;
                    while d <= 0.0 {
                        d += std::f64::consts::TAU;
                    }
                    if d.is_finite() {
                        d
                    } else {
                        f64::INFINITY
                    }
                };
                let mut best_d = cw(best);
                for i in rest {
                    let d = cw(i);
                    if d < best_d {
                        best = i;
                        best_d = d;
                    }
                }
            }
            used[best as usize] = true;
            ring.push(at);
            from = at;
            at = half_edges[best as usize].1;
        }
        loops.push(ring);
    }
    loops
}

#[inline]
fn orient(a: P2, b: P2, c: P2) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn ring_area(r: &[(u32, P2)]) -> f64 {
    let mut s = 0.0;
    for i in 0..r.len() {
        let p = r[i].1;
        let q = r[(i + 1) % r.len()].1;
        s += p[0] * q[1] - p[1] * q[0];
    }
    s / 2.0
}

/// Whether `p` lies in the closed box and the closed triangle `(a, b, c)`
/// of either orientation. (A point in the triangle is in its box; the box
/// only rules out points that rounding puts in a thin triangle's
/// supporting lines, and lets the spatial index find every candidate.)
#[inline]
fn in_box_and_triangle(a: P2, b: P2, c: P2, p: P2) -> bool {
    if p[0] < a[0].min(b[0]).min(c[0])
        || p[0] > a[0].max(b[0]).max(c[0])
        || p[1] < a[1].min(b[1]).min(c[1])
        || p[1] > a[1].max(b[1]).max(c[1])
    {
        return false;
    }
    let d1 = orient(a, b, p);
    let d2 = orient(b, c, p);
    let d3 = orient(c, a, p);
    (d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0) || (d1 <= 0.0 && d2 <= 0.0 && d3 <= 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(n: usize) -> Vec<(u32, u32)> {
        (0..n as u32).map(|i| (i, (i + 1) % n as u32)).collect()
    }

    /// The triangles' half-edges minus the facet's must be symmetric
    /// (internal edges come in opposite pairs; zero-length ones aside).
    /// Shared with the property tests (`props.rs`).
    pub(super) fn balance(tris: &[[u32; 3]], hes: &[(u32, u32)]) -> bool {
        let mut count = std::collections::HashMap::new();
        for t in tris {
            for (s, e) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                *count.entry((s, e)).or_insert(0i32) += 1;
            }
        }
        for &(s, e) in hes {
            *count.entry((s, e)).or_insert(0) -= 1;
        }
        count
            .iter()
            .all(|(&(s, e), &c)| s == e || c == count.get(&(e, s)).copied().unwrap_or(0))
    }

    #[test]
    fn convex_and_concave_polygons_give_n_minus_2_ccw_triangles() {
        let pts: Vec<Point3> = vec![
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [4.0, 4.0, 0.0],
            [2.0, 1.0, 0.0],
            [0.0, 4.0, 0.0],
        ];
        let hes = ring(5);
        let mut t = Vec::new();
        triangulate_facet(&pts, &hes, &mut t);
        assert_eq!(t.len(), 3);
        let area = ccw_area(&pts, &t);
        assert_eq!(area, 16.0 - 6.0);
        assert!(balance(&t, &hes));
    }

    #[test]
    fn a_quadrilateral_with_a_corner_straight_to_rounding_is_split_at_that_corner() {
        // Corner 1 lies on the segment 0-2 up to 1e-15: of the two valid
        // diagonals, 0-2 would pass through it (a triangle of no area);
        // 1-3 gives two proper triangles. Both orders of the loop.
        let pts: Vec<Point3> = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 1e-15, 0.0],
            [1.0, 3.0, 0.0],
        ];
        for start in 0..4u32 {
            let hes: Vec<(u32, u32)> = (0..4)
                .map(|i| ((start + i) % 4, (start + i + 1) % 4))
                .collect();
            let mut t = Vec::new();
            triangulate_facet(&pts, &hes, &mut t);
            assert_eq!(t.len(), 2);
            assert!(balance(&t, &hes));
            for tri in &t {
                assert!(tri.contains(&1) && tri.contains(&3), "{t:?}");
            }
            assert!((ccw_area(&pts, &t) - 3.0).abs() < 1e-12);
        }
        // The real case: a piece of a sphere's facet inside another
        // sphere (a UV sphere of 40 slices minus its copy moved by
        // (0.289, 0.318, 0.260)), where the intersection curve crosses the
        // other sphere's edge at 511 on the straight chain 603-511-604;
        // the diagonal 603-604 made the mesh check count an intersection
        // with the facets meeting at 511.
        let pts: Vec<Point3> = vec![
            [-0.6023313895935549, 0.31754264805429433, 0.7137981208748785],
            [-0.5910664301889025, 0.3330475345136997, 0.73018957886674],
            [-0.5891029463565811, 0.32750303938550945, 0.7341057700806499],
            [-0.5855756518256511, 0.31754264805429433, 0.7411409998205201],
        ];
        let hes = ring(4);
        let mut t = Vec::new();
        triangulate_facet(&pts, &hes, &mut t);
        assert_eq!(t.len(), 2);
        for tri in &t {
            assert!(tri.contains(&0) && tri.contains(&2), "{t:?}");
        }
    }

    #[test]
    fn no_chord_runs_along_a_side_straight_to_rounding() {
        // A rectangle whose bottom side carries two vertices straight to
        // rounding (as the Boolean leaves them where a facet is cut along
        // a side): every triangle must have a proper area, whichever
        // vertex the loop starts at; a chord through 2 or 3 (such as 1-4,
        // or 2-4 over 3) would leave a flat one.
        let pts: Vec<Point3> = vec![
            [0.0, 3.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1e-16, 0.0],
            [2.0, -1e-16, 0.0],
            [3.0, 0.0, 0.0],
            [3.0, 3.0, 0.0],
        ];
        for start in 0..6u32 {
            let hes: Vec<(u32, u32)> = (0..6)
                .map(|i| ((start + i) % 6, (start + i + 1) % 6))
                .collect();
            let mut t = Vec::new();
            triangulate_facet(&pts, &hes, &mut t);
            assert_eq!(t.len(), 4);
            assert!(balance(&t, &hes));
            for tri in &t {
                let [a, b, c] = tri.map(|v| pts[v as usize]);
                let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                assert!(area > 0.5, "start {start}: {t:?}");
            }
        }
    }

    #[test]
    fn facet_with_hole_is_bridged() {
        let pts: Vec<Point3> = vec![
            [0.0, 0.0, 1.0],
            [4.0, 0.0, 1.0],
            [4.0, 4.0, 1.0],
            [0.0, 4.0, 1.0],
            [1.0, 1.0, 1.0],
            [3.0, 1.0, 1.0],
            [3.0, 3.0, 1.0],
            [1.0, 3.0, 1.0],
        ];
        let mut hes = ring(4);
        hes.extend([(4, 7), (7, 6), (6, 5), (5, 4)]);
        let mut t = Vec::new();
        triangulate_facet(&pts, &hes, &mut t);
        assert_eq!(t.len(), 8);
        let area = ccw_area(&pts, &t);
        assert_eq!(area, 12.0);
    }

    /// The area of triangles in the xy-plane, each asserted anticlockwise.
    fn ccw_area(pts: &[Point3], t: &[[u32; 3]]) -> f64 {
        let mut area = 0.0;
        for tri in t {
            let [a, b, c] = tri.map(|i| [pts[i as usize][0], pts[i as usize][1]]);
            let o = orient(a, b, c);
            assert!(o > 0.0, "{t:?}");
            area += o / 2.0;
        }
        area
    }

    fn total_abs_area(pts: &[Point3], t: &[[u32; 3]]) -> f64 {
        t.iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|i| [pts[i as usize][0], pts[i as usize][1]]);
                orient(a, b, c).abs() / 2.0
            })
            .sum()
    }

    /// A `w x h` rectangle with a 0.5 x 0.5 square hole in every unit
    /// cell, jittered by multiples of 1/64 (many holes share y values with
    /// their neighbours' vertices, the bridges' hard case).
    fn grid_of_holes(w: u32, h: u32) -> (Vec<Point3>, Vec<(u32, u32)>) {
        let mut pts: Vec<Point3> = vec![
            [0.0, 0.0, 1.0],
            [f64::from(w), 0.0, 1.0],
            [f64::from(w), f64::from(h), 1.0],
            [0.0, f64::from(h), 1.0],
        ];
        let mut hes = ring(4);
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut jitter = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            f64::from(((state >> 33) % 25) as u32) / 64.0 - 12.0 / 64.0
        };
        for i in 0..w {
            for j in 0..h {
                let x = f64::from(i) + 0.25 + jitter();
                let y = f64::from(j) + 0.25 + jitter();
                let b = pts.len() as u32;
                pts.extend([
                    [x, y, 1.0],
                    [x + 0.5, y, 1.0],
                    [x + 0.5, y + 0.5, 1.0],
                    [x, y + 0.5, 1.0],
                ]);
                // Clockwise: the facet's interior on the left.
                hes.extend([(b, b + 3), (b + 3, b + 2), (b + 2, b + 1), (b + 1, b)]);
            }
        }
        (pts, hes)
    }

    #[test]
    fn every_hole_of_a_grid_is_bridged() {
        // V + 2H - 2 triangles: no hole left on its own (each would save
        // 4 triangles and overlap the region around it), the signed area
        // exactly the facet's, and no triangle reversed (a bridge from the
        // wrong copy of a vertex reached twice would cross another one).
        let (w, h) = (16, 10);
        let (pts, hes) = grid_of_holes(w, h);
        let holes = (w * h) as usize;
        let mut t = Vec::new();
        triangulate_facet(&pts, &hes, &mut t);
        assert_eq!(t.len(), pts.len() + 2 * holes - 2);
        assert!(balance(&t, &hes));
        let mut area = 0.0;
        for tri in &t {
            let [a, b, c] = tri.map(|i| [pts[i as usize][0], pts[i as usize][1]]);
            area += orient(a, b, c) / 2.0;
            assert_ne!(
                robust_arith::orient2d(a, b, c),
                std::cmp::Ordering::Less,
                "{tri:?}"
            );
        }
        assert_eq!(area, f64::from(w * h) * 0.75);
    }

    #[test]
    fn concave_quadrilateral_takes_the_inner_diagonal() {
        let pts: Vec<Point3> = vec![
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [0.0, 2.0, 0.0],
            [1.0, 1.0, 0.0],
        ];
        let mut t = Vec::new();
        triangulate_facet(&pts, &ring(4), &mut t);
        assert_eq!(total_abs_area(&pts, &t), 3.0);
        assert!(balance(&t, &ring(4)));
    }

    #[test]
    fn figure_4_10_prefers_the_smaller_overlap() {
        // A self-overlapping quadrilateral (bow tie): diagonal a-c gives
        // triangles of areas 2 + 1.5, diagonal b-d 3.5 + 4.
        let pts: Vec<Point3> = vec![
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [3.0, 2.0, 0.0],
        ];
        for rot in 0..4 {
            let hes: Vec<(u32, u32)> = (0..4u32)
                .map(|i| ((i + rot) % 4, (i + rot + 1) % 4))
                .collect();
            let mut t = Vec::new();
            triangulate_facet(&pts, &hes, &mut t);
            assert_eq!(t.len(), 2);
            assert_eq!(total_abs_area(&pts, &t), 3.5);
            assert!(balance(&t, &hes));
        }
    }
}
