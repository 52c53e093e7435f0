//! The triangles of the triangle-mesh variant's result: every retained
//! facet (a merged coplanar region, cut by the Boolean) is triangulated by
//! internal edges only (section 4.8), re-using the input triangles of the
//! part of the region the Boolean left untouched.
//!
//! For a retained facet `F'` of merged facet `F`:
//!
//! - `F` of one triangle: [`triangulate_facet`] of `F'` (as before the
//!   merge existed); when `F'` is one loop of three vertices (the triangle
//!   kept, or reversed), the same triangle is computed without the general
//!   triangulation's allocations (`one_triangle`).
//! - `F'` is `F` copied (or, for B in a difference, reversed) half-edge by
//!   half-edge and every vertex of `F`'s triangles is retained with the
//!   operand's inclusion value: the input triangles, mapped (reversed).
//! - Otherwise the *cut box* bounds every vertex of `F'` that is not one of
//!   the operand's retained vertices (intersection vertices) and every
//!   vertex of `F`'s triangles that is not retained with the operand's
//!   inclusion value. An input triangle with all vertices so retained and a
//!   bounding box disjoint from the cut box is *kept*; the rest of `F'`,
//!   the *residual* `F' - sum of the kept triangles' boundaries` (opposite
//!   half-edge pairs cancelled), is triangulated by [`triangulate_facet`].
//!
//! Vertices that the merge hid (inside a coplanar region, or subdividing a
//! straight edge) are given back to the merged facets kept whole that
//! hold them, when every facet around them is kept whole
//! (`keep_interior_vertices`): those facets then copy their input
//! triangles, so a Boolean leaves the surface it did not touch as it was.
//!
//! Topology holds whatever the geometry: the residual is a sum of closed
//! chains (F' by Theorem 3, each kept triangle reversed), so it satisfies
//! facet boundary closure; its triangulation adds internal edges in
//! opposite pairs; and the kept triangles plus the residual's triangles
//! have, up to opposite pairs, exactly the half-edges of `F'`. The result
//! thus satisfies shape boundary closure whenever the polygon result does
//! (Theorem 4). Geometry: every new boundary of `F'` (intersection edges,
//! cut parts of `F`'s edges, the parts around removed vertices) lies in
//! the cut box, so a kept triangle lies inside `F'`, and the residual is
//! the region the Boolean changed plus the input triangles around it.

use crate::construct::{facet_ranges, Retained, VertexMap};
use crate::contacts::exact_box;
use crate::merge::{Merged, NONE};
use crate::mesh::Flat;
use crate::par;
use rayon::prelude::*;
use robust_arith::Point3;
use rustc_hash::FxHashMap;
use topology::{triangulate_facet, FacetProjection, TriangleMesh};

/// One operand as the re-triangulation needs it.
pub(crate) struct Source<'a> {
    /// The input triangles.
    pub triangles: &'a [[u32; 3]],
    /// The input vertex positions.
    pub pos: &'a [Point3],
    /// The coplanar merge that built the Boolean's facets.
    pub merged: &'a Merged,
    /// The merged facets the Boolean ran on.
    pub facets: &'a Flat<'a>,
    /// The inclusion value of the operand's vertices retained outside the
    /// other operand's boundary: 1, or -1 for B in a difference
    /// (eq. 4.7-4.13 with `X = 0` for A and `X = 1` for B).
    pub sigma: i32,
}

/// Half-edges per piece of work in [`to_triangle_mesh`]: consecutive
/// retained facets of one chunk are grouped up to this size, and a larger
/// facet is a piece of its own, so that one large facet (a plate with a
/// thousand holes) does not hold up the facets after it in its chunk.
const PIECE_HALF_EDGES: usize = 4096;

/// One piece's triangles and the boxes of its regions re-triangulated
/// anew.
type Piece = (Vec<[u32; 3]>, Vec<[Point3; 2]>);

/// Triangulates every retained facet, piece by piece in parallel (runs of
/// facets of one chunk, see [`PIECE_HALF_EDGES`]), concatenated in facet
/// order: the output does not depend on the thread count.
///
/// With `track`, also returns the exact bounding box of every region that was
/// re-triangulated although its merged facet held several input triangles
/// (a facet the Boolean cut, or one whose merge dropped a vertex that only
/// subdivided a straight edge): the places where the result's triangles
/// differ from the operands' besides the facets of one triangle, in piece
/// order.
pub(crate) fn to_triangle_mesh(
    mut r: Retained,
    sources: [Source<'_>; 2],
    track: bool,
) -> (TriangleMesh, Vec<[Point3; 2]>) {
    for (k, src) in sources.iter().enumerate() {
        keep_interior_vertices(&mut r, k, src);
    }
    // (chunk, facets lo..hi of its list, first half-edge of facet lo).
    let mut pieces: Vec<(usize, usize, usize, usize)> = Vec::new();
    for (c, (_, _, list)) in r.chunks.iter().enumerate() {
        let (mut lo, mut at, mut size) = (0usize, 0usize, 0usize);
        let mut start = 0usize;
        for (i, &(_, n)) in list.iter().enumerate() {
            let n = n as usize;
            if size > 0 && size + n > PIECE_HALF_EDGES {
                pieces.push((c, lo, i, start));
                (lo, start, size) = (i, at, 0);
            }
            size += n;
            at += n;
        }
        if lo < list.len() {
            pieces.push((c, lo, list.len(), start));
        }
    }
    // Pieces in parallel only when there is enough work for two threads.
    let total: usize = r.chunks.iter().map(|c| c.1.len()).sum();
    let split = if par::worth_splitting(total / 2) {
        1
    } else {
        usize::MAX
    };
    let parts: Vec<Piece> = pieces
        .par_iter()
        .with_min_len(split)
        .map(|&(c, lo, hi, start)| {
            let (operand, hes, list) = &r.chunks[c];
            let k = *operand as usize;
            let (src, map) = (&sources[k], &r.maps[k]);
            // One triangle per facet in the common case (a triangle kept).
            let mut tris = Vec::with_capacity(hi - lo);
            let mut scratch = Scratch::default();
            let mut changed = Vec::new();
            let mut at = start;
            for &(f, n) in &list[lo..hi] {
                let part = &hes[at..at + n as usize];
                at += n as usize;
                let before = tris.len();
                let fresh = facet(&r.vertices, src, map, f, part, &mut scratch, &mut tris);
                if track && fresh > 0 {
                    let made = tris[before..before + fresh].iter().flatten();
                    changed.push(exact_box(made.map(|&v| r.vertices[v as usize])));
                }
            }
            (tris, changed)
        })
        .collect();
    let (parts, changed): (Vec<_>, Vec<_>) = parts.into_iter().unzip();
    let changed = changed.into_iter().flatten().collect();
    // The retained facets and vertex maps are freed before the triangles
    // are gathered into one array.
    let Retained {
        vertices,
        chunks,
        maps,
        ..
    } = r;
    drop((chunks, maps));
    (TriangleMesh::new(vertices, gather(parts, split)), changed)
}

/// Whether the retained facet `part` of merged facet `f` is that facet
/// copied half-edge by half-edge through the vertex map (reversed for B
/// in a difference): the Boolean neither cut it nor moved its boundary.
fn copied_whole(src: &Source<'_>, map: &VertexMap, f: u32, part: &[(u32, u32)]) -> bool {
    if part.len() != src.facets.facet_range(f).len() {
        return false;
    }
    let vid = |v: u32| map.vid[v as usize];
    let whole = src.facets.facet_half_edges(f);
    if src.sigma == 1 {
        part.iter()
            .zip(whole)
            .all(|(&(s, e), (s0, e0))| s == vid(s0) && e == vid(e0))
    } else {
        part.iter()
            .zip(whole)
            .all(|(&(s, e), (s0, e0))| s == vid(e0) && e == vid(s0))
    }
}

/// Gives the vertices that the coplanar merge hid inside untouched merged
/// facets of operand `k` a place in the result, so that [`facet`] copies
/// those facets' input triangles instead of triangulating them afresh.
///
/// A vertex strictly inside a coplanar region (every edge around it a
/// merged pair), or one the merge dropped from a straight edge, is no
/// vertex of any merged facet, so the Boolean never saw it: it has no
/// result vertex, and a facet holding one failed the "every vertex
/// retained" test of a facet kept whole, whose input triangles were then
/// replaced by a new triangulation of its boundary (PyVista's nut minus a
/// disjoint box lost 216 of its 523 vertices). Here a retained facet of
/// operand `k` is *kept* when it is its merged facet copied (reversed for
/// B in a difference) with every boundary vertex retained with the
/// operand's inclusion value, and every hidden vertex of its triangles
/// has all its triangles in kept facets; the largest such set is found by
/// removing, until nothing changes, every candidate that shares a hidden
/// vertex with a facet that is not kept. The hidden vertices of the kept
/// facets are appended to the result's vertices (at their input
/// positions) and marked retained. Every facet using such a vertex then
/// copies its input triangles, which agree along every edge (they are the
/// operand's own triangles), so the result's closure is unchanged; a
/// hidden vertex next to a cut facet stays hidden (keeping it on one side
/// only would leave a T-junction). Vertices are appended in the result's
/// facet order, so they do not depend on the thread count.
fn keep_interior_vertices(r: &mut Retained, k: usize, src: &Source<'_>) {
    if !src.merged.any {
        return;
    }
    let sigma = src.sigma;
    let n_facets = src.facets.facet_count();
    let hidden = |map: &VertexMap, v: u32| map.vid[v as usize] == NONE;
    // Candidates: retained facets of several triangles copied whole, every
    // visible vertex of their triangles retained with the operand's value
    // (a vertex on the other operand's boundary rules a facet out); and
    // the operand's retained facets in the result's order.
    let mut kept = vec![false; n_facets];
    let mut order: Vec<u32> = Vec::new();
    let map = &r.maps[k];
    for (at, part) in r.facets().filter(|(at, _)| at.operand as usize == k) {
        let f = at.facet;
        order.push(f);
        let tris = src.merged.triangles(f);
        kept[f as usize] = tris.len() > 1
            && copied_whole(src, map, f, part)
            && tris.iter().all(|&t| {
                src.triangles[t as usize]
                    .iter()
                    .all(|&v| hidden(map, v) || map.incl[v as usize] == sigma)
            });
    }
    // (hidden vertex, facet of one of its triangles), each pair once.
    let mut around: Vec<(u32, u32)> = Vec::new();
    for f in 0..n_facets as u32 {
        for &t in src.merged.triangles(f) {
            for v in src.triangles[t as usize] {
                if hidden(map, v) {
                    around.push((v, f));
                }
            }
        }
    }
    if around.is_empty() {
        return;
    }
    around.sort_unstable();
    around.dedup();
    // The facets of each hidden vertex (`around` by vertex) and the hidden
    // vertices of each facet (`by_facet`), as offset tables.
    let v_off = facet_ranges(src.pos.len(), around.iter().map(|p| p.0));
    let mut by_facet: Vec<(u32, u32)> = around.iter().map(|&(v, f)| (f, v)).collect();
    by_facet.sort_unstable();
    let f_off = facet_ranges(n_facets, by_facet.iter().map(|p| p.0));
    let range = |off: &[u32], i: u32| off[i as usize] as usize..off[i as usize + 1] as usize;
    // Remove every candidate that shares a hidden vertex with a facet
    // that is not kept, spreading from the facets not kept (each facet
    // enters the queue at most once: linear in `around`).
    let mut queue: Vec<u32> = (0..n_facets as u32)
        .filter(|&f| !kept[f as usize] && !range(&f_off, f).is_empty())
        .collect();
    while let Some(f) = queue.pop() {
        for &(_, v) in &by_facet[range(&f_off, f)] {
            for &(_, g) in &around[range(&v_off, v)] {
                if kept[g as usize] {
                    kept[g as usize] = false;
                    queue.push(g);
                }
            }
        }
    }
    // The hidden vertices of the kept facets, in the result's facet order.
    let mut placed = vec![false; src.pos.len()];
    let Retained { vertices, maps, .. } = r;
    let map = &mut maps[k];
    for f in order.into_iter().filter(|&f| kept[f as usize]) {
        for &t in src.merged.triangles(f) {
            for v in src.triangles[t as usize] {
                if hidden(map, v) && !placed[v as usize] {
                    placed[v as usize] = true;
                    map.vid[v as usize] = vertices.len() as u32;
                    map.incl[v as usize] = sigma;
                    vertices.push(src.pos[v as usize]);
                }
            }
        }
    }
}

/// The pieces' triangles in piece order, in one array; the copies run in
/// parallel (each piece into its own part of the array) when `split`
/// allows, so the array's pages are also first touched in parallel.
fn gather(parts: Vec<Vec<[u32; 3]>>, split: usize) -> Vec<[u32; 3]> {
    let total = parts.iter().map(Vec::len).sum();
    if split == usize::MAX || parts.len() < 2 {
        let mut triangles = Vec::with_capacity(total);
        for p in parts {
            triangles.extend_from_slice(&p);
        }
        return triangles;
    }
    let mut triangles = vec![[0u32; 3]; total];
    let mut dests = Vec::with_capacity(parts.len());
    let mut rest = triangles.as_mut_slice();
    for p in &parts {
        let (d, r) = rest.split_at_mut(p.len());
        dests.push(d);
        rest = r;
    }
    dests
        .into_par_iter()
        .zip(parts.par_iter())
        .with_min_len(split)
        .for_each(|(d, p)| d.copy_from_slice(p));
    triangles
}

#[derive(Default)]
struct Scratch {
    kept: Vec<bool>,
    residual: Vec<(u32, u32, i32)>,
    net: FxHashMap<(u32, u32), i32>,
    hes: Vec<(u32, u32)>,
}

/// Residuals longer than this are netted through a hash map rather than
/// by sorting all of them.
const HASHED_RESIDUAL: usize = 256;

/// The net half-edges of the signed edges `residual` (lower id, higher id,
/// +1 for lower to higher), into `hes`: each edge with net `k != 0` gives
/// `|k|` half-edges in the direction of its sign, edges in increasing
/// (lower, higher) order. A large residual (a plate with many holes cut
/// near one of them: most of its entries cancel) is summed per edge in a
/// hash map and only the surviving edges are sorted; the result is the
/// same as sorting every entry (integer sums do not depend on order).
fn net_half_edges(
    residual: &mut Vec<(u32, u32, i32)>,
    net: &mut FxHashMap<(u32, u32), i32>,
    hes: &mut Vec<(u32, u32)>,
) {
    hes.clear();
    if residual.len() > HASHED_RESIDUAL {
        net.clear();
        net.reserve(residual.len());
        for &(a, b, sign) in residual.iter() {
            *net.entry((a, b)).or_insert(0) += sign;
        }
        residual.clear();
        residual.extend(
            net.iter()
                .filter(|(_, &k)| k != 0)
                .map(|(&(a, b), &k)| (a, b, k)),
        );
    }
    residual.sort_unstable_by_key(|&(a, b, _)| (a, b));
    let mut i = 0;
    while i < residual.len() {
        let (a, b, _) = residual[i];
        let mut k = 0i32;
        while i < residual.len() && residual[i].0 == a && residual[i].1 == b {
            k += residual[i].2;
            i += 1;
        }
        let he = if k > 0 { (a, b) } else { (b, a) };
        for _ in 0..k.unsigned_abs() {
            hes.push(he);
        }
    }
}

/// Triangulates the retained facet `part` of merged facet `f`. Returns how
/// many of the triangles it appends (the first ones) were made anew when
/// `f` held several input triangles (0 for a facet of one triangle, whose
/// triangulation is the Boolean's cut, and for input triangles taken
/// over).
fn facet(
    vertices: &[Point3],
    src: &Source<'_>,
    map: &VertexMap,
    f: u32,
    part: &[(u32, u32)],
    s: &mut Scratch,
    out: &mut Vec<[u32; 3]>,
) -> usize {
    let tris = src.merged.triangles(f);
    if tris.len() <= 1 {
        match one_triangle(vertices, part) {
            Some(t) => out.push(t),
            None => triangulate_facet(vertices, part, out),
        }
        return 0;
    }
    let sigma = src.sigma;
    let vid = |v: u32| map.vid[v as usize];
    let retained = |v: u32| map.incl[v as usize] == sigma;
    // The input triangle, mapped and oriented as the operand's facets are
    // retained.
    let oriented = |t: u32| {
        let [a, b, c] = src.triangles[t as usize].map(vid);
        if sigma == 1 {
            [a, b, c]
        } else {
            [a, c, b]
        }
    };
    let all_retained = || {
        tris.iter()
            .all(|&t| src.triangles[t as usize].iter().all(|&v| retained(v)))
    };
    if copied_whole(src, map, f, part) && all_retained() {
        out.extend(tris.iter().map(|&t| oriented(t)));
        return 0;
    }
    // The cut box.
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut grow = |p: Point3| {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    };
    for &(a, b) in part {
        for v in [a, b] {
            if !map.own.contains(&v) {
                grow(vertices[v as usize]);
            }
        }
    }
    for &t in tris {
        for v in src.triangles[t as usize] {
            if !retained(v) {
                grow(src.pos[v as usize]);
            }
        }
    }
    s.kept.clear();
    s.kept.extend(tris.iter().map(|&t| {
        let tri = src.triangles[t as usize];
        if !tri.iter().all(|&v| retained(v)) {
            return false;
        }
        (0..3).any(|c| {
            let (mut tlo, mut thi) = (f64::INFINITY, f64::NEG_INFINITY);
            for v in tri {
                let x = src.pos[v as usize][c];
                tlo = tlo.min(x);
                thi = thi.max(x);
            }
            thi < lo[c] || tlo > hi[c]
        })
    }));
    if !s.kept.iter().any(|&k| k) {
        let before = out.len();
        triangulate_facet(vertices, part, out);
        return out.len() - before;
    }
    // A merged partner lies in the same merged facet: its place in `tris`
    // is `tri_pos`.
    let kept = |t: u32| s.kept[src.merged.tri_pos(t) as usize];
    // The residual as signed edges (lower id, higher id, +1 for lower to
    // higher): F' plus the reversed boundary of the kept triangles, where
    // pairs between two kept triangles are skipped (they cancel).
    s.residual.clear();
    let mut push = |a: u32, b: u32, sign: i32| {
        if a < b {
            s.residual.push((a, b, sign));
        } else if a > b {
            s.residual.push((b, a, -sign));
        }
    };
    for &(a, b) in part {
        push(a, b, 1);
    }
    for (i, &t) in tris.iter().enumerate() {
        if !s.kept[i] {
            continue;
        }
        let [a, b, c] = oriented(t);
        for (k, (x, y)) in [(a, b), (b, c), (c, a)].into_iter().enumerate() {
            // Input half-edge of this side: sigma = 1 keeps k, -1 reverses
            // the triangle (a, c, b), whose sides are input sides 2, 1, 0.
            let h = if sigma == 1 {
                3 * t + k as u32
            } else {
                3 * t + 2 - k as u32
            };
            let p = src.merged.partner(h);
            if p != NONE && kept(p / 3) {
                continue;
            }
            push(y, x, 1);
        }
    }
    net_half_edges(&mut s.residual, &mut s.net, &mut s.hes);
    let before = out.len();
    triangulate_facet(vertices, &s.hes, out);
    let fresh = out.len() - before;
    out.extend(
        tris.iter()
            .zip(&s.kept)
            .filter(|(_, &k)| k)
            .map(|(&t, _)| oriented(t)),
    );
    fresh
}

/// What [`triangulate_facet`] gives for `half_edges` when they are one
/// loop of three distinct vertices (the common retained facet of a
/// triangle mesh: an input triangle kept whole, or reversed for B in a
/// difference), computed without its allocations; `None` otherwise.
///
/// A loop listed in order is the triangle itself. A loop listed out of
/// order, `r0 -> r1`, `r2 -> r0`, `r1 -> r2` (how a reversed triangle's
/// half-edges come out of level 5), is chained into the ring
/// `(r0, r1, r2)`, which [`triangulate_facet`] projects onto the
/// coordinate plane chosen by the Newell normal, summed over the
/// half-edges in the order given and relative to `r0`, and clips as one
/// ear, mirrored when the ring's projected area is negative: `(r2, r0,
/// r1)` then, else `(r0, r1, r2)`. The plane is [`FacetProjection`], as
/// there, and the area is summed operation for operation as there, so the
/// sign is the same bit for bit; a test compares the two on random,
/// degenerate and non-finite triangles.
fn one_triangle(positions: &[Point3], half_edges: &[(u32, u32)]) -> Option<[u32; 3]> {
    let &[h0, h1, h2] = half_edges else {
        return None;
    };
    let n_v = positions.len();
    if [h0, h1, h2]
        .iter()
        .any(|&(s, e)| s as usize >= n_v || e as usize >= n_v)
    {
        return None;
    }
    if h0.1 == h1.0 && h1.1 == h2.0 && h2.1 == h0.0 {
        // Over a repeated vertex the loop balances itself and
        // `triangulate_facet` gives nothing: let it.
        let distinct = h0.0 != h1.0 && h1.0 != h2.0 && h2.0 != h0.0;
        return distinct.then_some([h0.0, h1.0, h2.0]);
    }
    let (r0, r1, r2) = (h0.0, h0.1, h2.1);
    // The other order, over three distinct vertices (each starts exactly
    // one half-edge, so the ring is chained without a choice).
    if h2.0 != r1 || h1 != (r2, r0) || r0 == r1 || r1 == r2 || r2 == r0 {
        return None;
    }
    let plane = FacetProjection::new(positions, half_edges, r0);
    let proj = |v: u32| plane.project(positions[v as usize]);
    let ring = [proj(r0), proj(r1), proj(r2)];
    let mut area = 0.0;
    for i in 0..3 {
        let (p, q) = (ring[i], ring[(i + 1) % 3]);
        area += p[0] * q[1] - p[1] * q[0];
    }
    if area / 2.0 < 0.0 {
        Some([r2, r0, r1])
    } else {
        Some([r0, r1, r2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A coordinate: small integers (exact ties, zero-area triangles),
    /// unit-scale floats, mixed magnitudes, or a non-finite value.
    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            4 => (-3i32..=3).prop_map(f64::from),
            4 => -1.0f64..1.0,
            2 => (any::<bool>(), 0u64..(1 << 52), -300i32..=300).prop_map(|(neg, m, e)| {
                let v = (1.0 + m as f64 / 4_503_599_627_370_496.0) * 2f64.powi(e);
                if neg { -v } else { v }
            }),
            1 => prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e308]),
        ]
    }

    fn point() -> impl Strategy<Value = Point3> {
        [coord(), coord(), coord()]
    }

    /// [`one_triangle`] against [`triangulate_facet`]: the same triangle
    /// when it answers, and `None` only where the half-edges are not one
    /// loop of three distinct vertices listed either way.
    fn agrees(positions: &[Point3], hes: &[(u32, u32)]) -> Result<(), TestCaseError> {
        let mut general = Vec::new();
        triangulate_facet(positions, hes, &mut general);
        match one_triangle(positions, hes) {
            Some(t) => prop_assert_eq!(vec![t], general),
            None => {
                // Only non-loops, repeated vertices and dangling indices
                // are left to the general triangulation.
                let loop3 =
                    |h: &[(u32, u32)]| h[0].1 == h[1].0 && h[1].1 == h[2].0 && h[2].1 == h[0].0;
                let distinct = hes.len() == 3
                    && hes[0].0 != hes[1].0
                    && hes[1].0 != hes[2].0
                    && hes[2].0 != hes[0].0
                    && hes.iter().all(|&(s, e)| {
                        (s as usize) < positions.len() && (e as usize) < positions.len()
                    });
                prop_assert!(
                    !(distinct && (loop3(hes) || loop3(&[hes[0], hes[2], hes[1]]))),
                    "a loop was left out: {:?}",
                    hes
                );
            }
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(2000)))]

        /// A triangle kept (in order), reversed (out of order, as level 5
        /// lists a reversed triangle), rotated, or with a vertex repeated
        /// or out of range; any coordinates.
        #[test]
        fn one_triangle_is_what_triangulate_facet_gives(
            p in proptest::collection::vec(point(), 4),
            ids in [0u32..5, 0u32..5, 0u32..5],
            distinct in any::<bool>(),
            order in 0usize..6,
        ) {
            let [a, b, c] = if distinct { [0, 1, 2] } else { ids };
            let (ab, bc, ca) = ((a, b), (b, c), (c, a));
            let (ba, cb, ac) = ((b, a), (c, b), (a, c));
            let hes = match order {
                0 => [ab, bc, ca],
                1 => [bc, ca, ab],
                2 => [ba, cb, ac],
                3 => [ac, ba, cb],
                4 => [ab, ca, bc],
                _ => [ba, ac, cb],
            };
            agrees(&p, &hes)?;
            agrees(&p, &hes[..2])?;
        }
    }

    #[test]
    fn a_reversed_triangle_starts_at_its_first_half_edge() {
        // The reversed triangle of (0, 1, 2) as level 5 lists it: the ring
        // (1, 0, 2), projected so that it runs anticlockwise, is one ear.
        let p: Vec<Point3> = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        for hes in [[(1, 0), (2, 1), (0, 2)], [(1, 0), (0, 2), (2, 1)]] {
            let mut general = Vec::new();
            triangulate_facet(&p, &hes, &mut general);
            assert_eq!(general, vec![[1, 0, 2]]);
            assert_eq!(one_triangle(&p, &hes), Some([1, 0, 2]));
        }
        // Not a loop, or a vertex twice: left to the general path.
        assert_eq!(one_triangle(&p, &[(1, 0), (2, 1), (2, 0)]), None);
        assert_eq!(one_triangle(&p, &[(1, 0), (1, 1), (0, 1)]), None);
    }
}
