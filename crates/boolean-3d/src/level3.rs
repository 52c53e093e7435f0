//! Level 3 of the pyramid (Table 4.1): `X03(v_A, B)`, `X12(e_A, f_B)`,
//! `X21(f_A, e_B)`, `X30(A, v_B)` and the edge-facet intersection points
//! (eq. 4.2-4.6), with a conservative broad phase and winding-number
//! propagation along edges.
//!
//! # Why the broad phase is conservative
//!
//! Every point a level-1 or level-2 function computes is an interpolation
//! `p0 + lambda (p1 - p0)` with `|lambda| <= 1/2` (up to a few ulps) from
//! the closer end (Table 7.1, footnote 1 of section 4.5). Rounding is
//! monotone and the exact value lies strictly between the two end values,
//! so every computed coordinate lies in the closed range of the two values
//! it interpolates; by induction the y- and z-values a level-1 or level-2
//! hit assigns to an entity of A (of B) lie in the closed bounding box of
//! that entity (for `X02`/`X20`, of the facet). Now take an edge `e_A` and
//! a facet `f_B` whose closed boxes are disjoint:
//!
//! - disjoint in x: every `X01`/`X10` between their vertices and edges is
//!   0 (a vertex must lie in the half-open x-range of the edge), so every
//!   level-2 term and `X12` is 0;
//! - `e_A` below `f_B` in y (or z): every shadow term equals its X term
//!   (B is above at every hit), and Theorem 1 case (2) shows the X terms
//!   sum to 0 given facet boundary closure of `f_B`: `X12 = -X02(v_e) +
//!   X02(v_s) - sum_h X11(e_A, h) = 0`;
//! - `e_A` above `f_B` in y (or z): every shadow term is 0, so `X12 = 0`.
//!
//! The same holds for `X21`, and for the ray cast of `X03`: a facet whose
//! box misses the vertex in x or y has `X02 = 0`, and one wholly below the
//! vertex has `S02 = 0`. So closed-interval overlap on the exact
//! coordinates is exactly conservative. The facet boxes are stored in
//! single precision with every bound rounded outwards, which only enlarges
//! them, and are widened in y and z by `4 u L` (`L` the power of two
//! bounding all coordinates, the scale of the `y_at_x` bound of Table 8.1)
//! as defence in depth against a rounding step this argument overlooked;
//! both only add candidates, never remove one.
//!
//! # Propagation of winding numbers
//!
//! Summing `X12(e_A, f)` over every facet `f` of B, the `S11` terms cancel
//! in pairs because B satisfies shape boundary closure (`S11(e_A, h*) =
//! -S11(e_A, h)` for the reverse `h*` of `h`), leaving
//! `sum_f X12(e_A, f) = -X03(v_e(e_A), B) + X03(v_s(e_A), B)`, so
//!
//! `X03(v_e(e_A), B) = X03(v_s(e_A), B) - sum_f X12(e_A, f)`
//!
//! exactly, as integers; likewise `X30(A, v_e(e_B)) = X30(A, v_s(e_B)) -
//! sum_f X21(f, e_B)`. One ray cast per connected component of each
//! operand's edge graph therefore gives every winding number.

use crate::bvh::{Aabb, Bvh};
use crate::mesh::Flat;
use crate::par;
use crate::Boolean3Error;
use rayon::prelude::*;
use robust_arith::{power_of_two_bound, Point3, UNIT_ROUNDOFF};
use shadow_2d::{s02, s20, x02, x11, x20, Partners};

/// A non-zero level-3 edge-facet intersection: `X12(e_A, f_B)` (edge of A,
/// facet of B) or `X21(f_A, e_B)` (edge of B, facet of A), with its
/// intersection point (eq. 4.2-4.6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeFacetHit {
    /// The edge index (into `Level3Data::edges_a` or `edges_b`).
    pub edge: u32,
    /// The facet index in the other operand.
    pub facet: u32,
    /// The value of the intersection function for the edge in its forward
    /// direction (lower vertex index to higher); never 0.
    pub value: i32,
    /// The intersection point.
    pub point: Point3,
}

/// The level-3 data of section 4.9 (Theorem 1): every non-zero value with
/// its point.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Level3Data {
    /// A's edges as `[start, end]` vertex indices, `start <= end`.
    pub edges_a: Vec<[u32; 2]>,
    /// B's edges as `[start, end]` vertex indices, `start <= end`.
    pub edges_b: Vec<[u32; 2]>,
    /// `X03(v_A, B)` for every vertex of A (0 for vertices no half-edge
    /// refers to).
    pub x03: Vec<i32>,
    /// `X30(A, v_B)` for every vertex of B (0 for unreferenced vertices).
    pub x30: Vec<i32>,
    /// The non-zero `X12(e_A, f_B)`, sorted by edge then facet.
    pub x12: Vec<EdgeFacetHit>,
    /// The non-zero `X21(f_A, e_B)`, sorted by edge (of B) then facet (of A).
    pub x21: Vec<EdgeFacetHit>,
    /// The number of edge-facet pairs the broad phase let through.
    pub candidate_pairs: usize,
    /// The number of ray casts made for `X03`/`X30`.
    pub ray_casts: usize,
}

/// `X12(e_A, f_B) = -S02(v_e(e_A), f_B) + S02(v_s(e_A), f_B) - sum_{h in
/// f_B} S11(e_A, h)` (Table 4.1) with its point (eq. 4.2-4.6 with `k = 2`).
pub(crate) fn x12(
    as_: &Point3,
    ae: &Point3,
    facet: impl Iterator<Item = (Point3, Point3)> + Clone,
) -> Result<Option<(i32, Point3)>, Boolean3Error> {
    let mut partners = Partners::<3>::new(2);
    let mut value = 0;
    if let Some(h) = x02(ae, facet.clone())? {
        value += partners.offer(h.negated());
    }
    if let Some(h) = x02(as_, facet.clone())? {
        value += partners.offer(h);
    }
    for (s, e) in facet {
        if let Some(h) = x11(as_, ae, &s, &e)? {
            value += partners.offer(h.negated());
        }
    }
    finish(value, &partners, "X12")
}

/// `X21(f_A, e_B) = -sum_{h in f_A} S11(h, e_B) + S20(f_A, v_e(e_B)) -
/// S20(f_A, v_s(e_B))` (Table 4.1) with its point (eq. 4.2-4.6, `k = 2`).
pub(crate) fn x21(
    facet: impl Iterator<Item = (Point3, Point3)> + Clone,
    bs: &Point3,
    be: &Point3,
) -> Result<Option<(i32, Point3)>, Boolean3Error> {
    let mut partners = Partners::<3>::new(2);
    let mut value = 0;
    for (s, e) in facet.clone() {
        if let Some(h) = x11(&s, &e, bs, be)? {
            value += partners.offer(h.negated());
        }
    }
    if let Some(h) = x20(facet.clone(), be)? {
        value += partners.offer(h);
    }
    if let Some(h) = x20(facet, bs)? {
        value += partners.offer(h.negated());
    }
    finish(value, &partners, "X21")
}

fn finish(
    value: i32,
    partners: &Partners<3>,
    function: &str,
) -> Result<Option<(i32, Point3)>, Boolean3Error> {
    if value == 0 {
        return Ok(None);
    }
    // Theorem 1: a non-zero X has a partner of each shadow type; with
    // k = 2 and N = 3 the two interpolated points agree in all coordinates.
    match partners.interpolate() {
        Some((a, _)) => Ok(Some((value, a))),
        None => Err(Boolean3Error::Internal(format!(
            "Theorem 1 violated: {function} = {value} but an interpolation partner is missing"
        ))),
    }
}

/// The closed box of an edge.
#[inline]
fn edge_box(p: &Point3, q: &Point3) -> Aabb {
    Aabb::new(
        [p[0].min(q[0]), p[1].min(q[1]), p[2].min(q[2])],
        [p[0].max(q[0]), p[1].max(q[1]), p[2].max(q[2])],
    )
}

/// Which operand's edges are being intersected with the other's facets.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Side {
    /// Edges of A against facets of B: `X12`.
    EdgesOfA,
    /// Edges of B against facets of A: `X21`.
    EdgesOfB,
}

/// Facets with more half-edges than this get an [`XIndex`] entry.
const INDEXED_FACET: usize = 64;

/// The half-edges of each large facet bucketed by x, so that an
/// edge-facet function visits only the half-edges whose closed x-range
/// meets the edge's. Skipping the others is exact: every level-1 term
/// between an edge of one operand and a half-edge of the other (`X01`,
/// `X10`, hence `X11`, `X02`, `X20`) needs a vertex of one inside the
/// x-range of the other, so a half-edge whose closed x-range misses the
/// edge's contributes no hit at all, and the hits that remain are offered
/// in facet order as before: the values and points are bit for bit those
/// of the full loop. (A plate cut by a thousand holes has a facet of
/// thousands of half-edges, and each edge crossing it meets a few.)
struct XIndex {
    /// For each facet, its entry in `entries`, or `u32::MAX` (small facet).
    slot: Vec<u32>,
    entries: Vec<FacetBuckets>,
}

/// One facet's buckets: bucket `i` covers `x` with `bucket(x) == i`.
struct FacetBuckets {
    x0: f64,
    scale: f64,
    n: usize,
    /// `off[i]..off[i + 1]` index `items`: the half-edges (absolute
    /// indices, increasing) whose closed x-range reaches bucket `i`.
    off: Vec<u32>,
    items: Vec<u32>,
}

impl FacetBuckets {
    /// The bucket of `x`, monotone in `x` (rounding of the subtraction and
    /// the product is monotone), so that closed ranges that overlap share
    /// a bucket.
    #[inline]
    fn bucket(&self, x: f64) -> usize {
        // The conversion truncates towards zero, which is the floor for
        // `b >= 0` (and saturates); below 0, and for NaN, bucket 0.
        let b = (x - self.x0) * self.scale;
        if b >= 0.0 {
            (b as usize).min(self.n - 1)
        } else {
            0
        }
    }

    fn new(mesh: &Flat<'_>, f: u32) -> Option<FacetBuckets> {
        let range = mesh.facet_range(f);
        let xr = |h: usize| {
            let (s, e) = mesh.he(h as u32);
            let (a, b) = (mesh.pos[s as usize][0], mesh.pos[e as usize][0]);
            (a.min(b), a.max(b))
        };
        let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
        for h in range.clone() {
            let (lo, hi) = xr(h);
            x0 = x0.min(lo);
            x1 = x1.max(hi);
        }
        let n = (range.len() / 8).clamp(1, 4096);
        let scale = n as f64 / (x1 - x0);
        if !(scale.is_finite() && scale > 0.0) || n == 1 {
            return None;
        }
        let mut fb = FacetBuckets {
            x0,
            scale,
            n,
            off: vec![0; n + 1],
            items: Vec::new(),
        };
        let mut total = 0usize;
        for h in range.clone() {
            let (lo, hi) = xr(h);
            let (b0, b1) = (fb.bucket(lo), fb.bucket(hi));
            total += b1 - b0 + 1;
            for b in b0..=b1 {
                fb.off[b + 1] += 1;
            }
        }
        // Long half-edges in many buckets: the index would not pay.
        if total > 8 * range.len() {
            return None;
        }
        for b in 0..n {
            fb.off[b + 1] += fb.off[b];
        }
        let mut fill = fb.off.clone();
        fb.items = vec![0; total];
        for h in range {
            let (lo, hi) = xr(h);
            let (b0, b1) = (fb.bucket(lo), fb.bucket(hi));
            for slot in &mut fill[b0..=b1] {
                fb.items[*slot as usize] = h as u32;
                *slot += 1;
            }
        }
        Some(fb)
    }
}

impl XIndex {
    fn new(mesh: &Flat<'_>) -> XIndex {
        let big: Vec<u32> = (0..mesh.facet_count() as u32)
            .filter(|&f| mesh.facet_range(f).len() > INDEXED_FACET)
            .collect();
        let built: Vec<Option<FacetBuckets>> = big
            .par_iter()
            .map(|&f| FacetBuckets::new(mesh, f))
            .collect();
        let mut slot = vec![
            u32::MAX;
            if big.is_empty() {
                0
            } else {
                mesh.facet_count()
            }
        ];
        let mut entries = Vec::new();
        for (f, b) in big.into_iter().zip(built) {
            if let Some(b) = b {
                slot[f as usize] = entries.len() as u32;
                entries.push(b);
            }
        }
        XIndex { slot, entries }
    }

    /// The half-edges of facet `f` that may meet the closed x-range
    /// `[lo, hi]`, in facet order, into `out`; `false` (and `out` left
    /// empty) when `f` has no index and the whole facet is to be used.
    fn select(&self, f: u32, lo: f64, hi: f64, out: &mut Vec<u32>) -> bool {
        out.clear();
        let Some(&slot) = self.slot.get(f as usize) else {
            return false;
        };
        let Some(fb) = self.entries.get(slot as usize) else {
            return false;
        };
        let (b0, b1) = (fb.bucket(lo), fb.bucket(hi));
        let items = &fb.items[fb.off[b0] as usize..fb.off[b1 + 1] as usize];
        out.extend_from_slice(items);
        if b0 != b1 {
            out.sort_unstable();
            out.dedup();
        }
        true
    }
}

/// Evaluates the candidate `(edge, facet)` pairs (sorted, distinct) in
/// parallel chunks whose results are concatenated in candidate order, so
/// the output is sorted by edge then facet and does not depend on the
/// thread count. No heap allocation happens per pair.
fn edge_facet_hits(
    edges: &Flat<'_>,
    facets: &Flat<'_>,
    cand: &[(u32, u32)],
    side: Side,
) -> Result<Vec<EdgeFacetHit>, Boolean3Error> {
    let index = XIndex::new(facets);
    let chunks: Vec<Vec<EdgeFacetHit>> = cand
        .par_chunks(256)
        .with_min_len(par::min_len(256))
        .map(|chunk| {
            let mut hits = Vec::new();
            let mut near = Vec::new();
            for &(e, f) in chunk {
                let (p, q) = edges.edge_points(e);
                let r = if index.select(f, p[0].min(q[0]), p[0].max(q[0]), &mut near) {
                    let pts = near.iter().map(|&h| {
                        let (s, t) = facets.he(h);
                        (facets.pos[s as usize], facets.pos[t as usize])
                    });
                    match side {
                        Side::EdgesOfA => x12(&p, &q, pts)?,
                        Side::EdgesOfB => x21(pts, &p, &q)?,
                    }
                } else {
                    match side {
                        Side::EdgesOfA => x12(&p, &q, facets.facet_points(f))?,
                        Side::EdgesOfB => x21(facets.facet_points(f), &p, &q)?,
                    }
                };
                if let Some((value, point)) = r {
                    hits.push(EdgeFacetHit {
                        edge: e,
                        facet: f,
                        value,
                        point,
                    });
                }
            }
            Ok(hits)
        })
        .collect::<Result<_, Boolean3Error>>()?;
    Ok(chunks.concat())
}

/// The candidate `(edge, facet)` pairs of one side from the overlapping
/// facet pairs: an edge's box lies in the box of every facet holding one
/// of its half-edges, so every edge-facet pair with overlapping boxes is
/// found through some overlapping facet pair. Zero-length edges are left
/// out (their X is 0: the terms of Table 4.1 cancel). Sorted, distinct.
fn candidates(
    fpairs: &[(u32, u32)],
    edges: &Flat<'_>,
    facet_boxes: &[Aabb],
    side: Side,
) -> Vec<(u32, u32)> {
    let mut cand: Vec<(u32, u32)> = fpairs
        .par_chunks(1024)
        .with_min_len(par::min_len(1024))
        .flat_map_iter(|chunk| {
            let mut out = Vec::new();
            for &(fa, fb) in chunk {
                let (own, other) = match side {
                    Side::EdgesOfA => (fa, fb),
                    Side::EdgesOfB => (fb, fa),
                };
                let ob = &facet_boxes[other as usize];
                for h in edges.facet_range(own) {
                    let e = edges.he_edge[h];
                    let (s, t) = edges.edges[e as usize];
                    if s == t {
                        continue;
                    }
                    let (p, q) = edges.edge_points(e);
                    if edge_box(&p, &q).overlaps(ob) {
                        out.push((e, other));
                    }
                }
            }
            out
        })
        .collect();
    cand.par_sort_unstable();
    cand.dedup();
    cand
}

/// `X03(v, B) = sum_f S02(v, f)` by casting a ray upwards through the
/// broad phase (only facets whose box reaches the vertex's (x, y) and rises
/// to its z can shadow it).
fn x03_cast(v: &Point3, b: &Flat<'_>, bvh: &Bvh, boxes: &[Aabb]) -> Result<i32, Boolean3Error> {
    let q = Aabb::new(*v, [v[0], v[1], f64::INFINITY]);
    let mut sum = 0;
    let mut err = None;
    bvh.query(&q, boxes, |f| match s02(v, b.facet_points(f)) {
        Ok(s) => sum += s,
        Err(e) => err = Some(e),
    });
    match err {
        Some(e) => Err(e.into()),
        None => Ok(sum),
    }
}

/// `X30(A, v) = -sum_f S20(f, v)` by the same upward ray (a facet of A
/// wholly above `v` has `S20 = 0`, one that misses it in x or y has
/// `X20 = 0`); the facets that matter are those reaching down to `v`.
fn x30_cast(a: &Flat<'_>, v: &Point3, bvh: &Bvh, boxes: &[Aabb]) -> Result<i32, Boolean3Error> {
    // S20(f, v) is X20 when v is at or above the facet point: facets whose
    // lowest z exceeds v's cannot contribute.
    let q = Aabb::new([v[0], v[1], f64::NEG_INFINITY], *v);
    let mut sum = 0;
    let mut err = None;
    bvh.query(&q, boxes, |f| match s20(a.facet_points(f), v) {
        Ok(s) => sum -= s,
        Err(e) => err = Some(e),
    });
    match err {
        Some(e) => Err(e.into()),
        None => Ok(sum),
    }
}

/// Winding numbers of every referenced vertex by propagation along edges
/// from one ray cast per connected component (identity in the module
/// documentation), with `sum_f X(e, f)` per edge `e` from `hits`.
///
/// The components and the differences `x[v] - x[root]` come from a
/// union-find whose links carry the difference between a vertex and its
/// parent (edge `e = (s, t)` says `x[t] = x[s] - sum_f X(e, f)`), so no
/// vertex-edge adjacency is built: two arrays of one word a vertex. The
/// root of a component is its lowest vertex (the lower of two roots
/// becomes the parent), where the ray is cast, in increasing order. The
/// identity holds along every edge (Theorem 1, which the audit checks
/// against one cast per vertex), so the values do not depend on the
/// edges chosen; they are integers, computed exactly (wrapping, so that
/// no intermediate sum can overflow on the way to a result that fits).
///
/// The two operands propagate in parallel; this step holds the heap peak
/// of the whole Boolean, hence the compact form.
fn propagate(
    mesh: &Flat<'_>,
    hits: &[EdgeFacetHit],
    cast: impl Fn(&Point3) -> Result<i32, Boolean3Error> + Sync,
) -> Result<(Vec<i32>, usize), Boolean3Error> {
    let n = mesh.pos.len();
    let dsum = edge_sums(mesh.edges.len(), hits);
    let mut parent: Vec<u32> = (0..n as u32).collect();
    // up[v] = x[v] - x[parent[v]].
    let mut up = vec![0i32; n];
    for (e, &(s, t)) in mesh.edges.iter().enumerate() {
        if s == t {
            continue;
        }
        let (rs, os) = find(&mut parent, &mut up, s);
        let (rt, ot) = find(&mut parent, &mut up, t);
        if rs == rt {
            continue;
        }
        // x[rt] - x[rs] = os - d - ot.
        let diff = os.wrapping_sub(dsum[e]).wrapping_sub(ot);
        if rs < rt {
            parent[rt as usize] = rs;
            up[rt as usize] = diff;
        } else {
            parent[rs as usize] = rt;
            up[rs as usize] = diff.wrapping_neg();
        }
    }
    drop(dsum);
    let referenced = &mesh.referenced;
    let roots: Vec<u32> = (0..n as u32)
        .filter(|&v| referenced[v as usize] && parent[v as usize] == v)
        .collect();
    // A ray cast costs a descent of the other operand's hierarchy: a few
    // dozen of them are worth a piece of their own.
    let cast_values: Vec<i32> = roots
        .par_iter()
        .with_min_len(par::min_len(64))
        .map(|&r| cast(&mesh.pos[r as usize]))
        .collect::<Result<_, _>>()?;
    let mut x = vec![0i32; n];
    for (&r, &c) in roots.iter().zip(&cast_values) {
        x[r as usize] = c;
    }
    for v in 0..n as u32 {
        if referenced[v as usize] && parent[v as usize] != v {
            let (r, o) = find(&mut parent, &mut up, v);
            x[v as usize] = x[r as usize].wrapping_add(o);
        }
    }
    Ok((x, roots.len()))
}

/// The root of `v`'s set and `x[v] - x[root]`, compressing the path.
fn find(parent: &mut [u32], up: &mut [i32], v: u32) -> (u32, i32) {
    let (mut r, mut acc) = (v, 0i32);
    while parent[r as usize] != r {
        acc = acc.wrapping_add(up[r as usize]);
        r = parent[r as usize];
    }
    // Every vertex on the path now hangs from the root directly.
    let (mut w, mut rest) = (v, acc);
    while parent[w as usize] != r && parent[w as usize] != w {
        let next = parent[w as usize];
        let step = up[w as usize];
        parent[w as usize] = r;
        up[w as usize] = rest;
        rest = rest.wrapping_sub(step);
        w = next;
    }
    (r, acc)
}

/// Per-edge sums of the hit values.
fn edge_sums(n_edges: usize, hits: &[EdgeFacetHit]) -> Vec<i32> {
    let mut d = vec![0i32; n_edges];
    for h in hits {
        d[h.edge as usize] += h.value;
    }
    d
}

impl Level3Data {
    /// Fills in the edge lists of both operands.
    pub(crate) fn with_edges(mut self, a: &Flat<'_>, b: &Flat<'_>) -> Self {
        self.edges_a = a.edges.iter().map(|&(s, t)| [s, t]).collect();
        self.edges_b = b.edges.iter().map(|&(s, t)| [s, t]).collect();
        self
    }
}

/// How the vertex winding numbers are obtained.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Winding {
    /// One ray cast per connected component, propagated along edges.
    Propagate,
    /// One ray cast per vertex (the audit's independent check).
    CastEach,
}

/// All level-3 data of two validated operands.
pub(crate) fn level3(
    a: &Flat<'_>,
    b: &Flat<'_>,
    winding: Winding,
) -> Result<Level3Data, Boolean3Error> {
    level3_with_contacts(a, b, winding, None).map(|(l3, _)| l3)
}

/// An operand with at most this many facets is met by a scan of the
/// other operand's facet boxes instead of a hierarchy over them: at most
/// this many box tests per facet of the larger operand, and at most this
/// many ray casts into it on the fast path (one per connected component
/// of the small one).
const SCAN_AGAINST: usize = 32;

/// The facets of A and of B near the other operand (sorted).
pub(crate) type NearFacets = [Vec<u32>; 2];

/// One operand's broad phase: its facet boxes, widened in y and z by the
/// margin of the coordinate bound it was built for, and their hierarchy.
pub(crate) struct Broad {
    /// The power-of-two bound of the coordinates of both operands of the
    /// Boolean the boxes were built for.
    pub bound: f64,
    pub boxes: Vec<Aabb>,
    pub bvh: Bvh,
}

/// The power-of-two bound of an operand's largest coordinate magnitude.
pub(crate) fn coordinate_bound(m: &Flat<'_>) -> f64 {
    power_of_two_bound(m.max_abs())
}

impl Broad {
    /// The broad phase of `m` for a Boolean whose operands' coordinates
    /// are bounded by `bound`, against an operand of `other_facets`
    /// facets (a scan instead of a hierarchy against a few, see `bvh`).
    pub(crate) fn new(m: &Flat<'_>, bound: f64, other_facets: usize) -> Broad {
        // Facet boxes widened by the margin in y and z once, here: every
        // overlap test of the Boolean involves one facet box.
        let boxes = m.facet_boxes(4.0 * UNIT_ROUNDOFF * bound);
        let bvh = if other_facets <= SCAN_AGAINST && boxes.len() > other_facets {
            Bvh::scan(&boxes)
        } else {
            Bvh::new(&boxes)
        };
        Broad { bound, boxes, bvh }
    }
}

/// [`level3`], and with `Some(proximity)` also the facets of each operand
/// that come within `proximity` of a facet of the other
/// ([`crate::contacts`]), found by the same hierarchies.
pub(crate) fn level3_with_contacts(
    a: &Flat<'_>,
    b: &Flat<'_>,
    winding: Winding,
    proximity: Option<f64>,
) -> Result<(Level3Data, Option<NearFacets>), Boolean3Error> {
    let bound = coordinate_bound(a).max(coordinate_bound(b));
    let smaller = a.facet_count().min(b.facet_count());
    let (broad_a, broad_b) = par::join(
        smaller,
        || Broad::new(a, bound, b.facet_count()),
        || Broad::new(b, bound, a.facet_count()),
    );
    level3_broad(a, b, &broad_a, &broad_b, winding, proximity)
}

/// [`level3_with_contacts`] on broad phases built for both operands'
/// coordinate bound (the same boxes whatever else they were built with,
/// so the same level data: a hierarchy and a scan report the same pairs).
pub(crate) fn level3_broad(
    a: &Flat<'_>,
    b: &Flat<'_>,
    broad_a: &Broad,
    broad_b: &Broad,
    winding: Winding,
    proximity: Option<f64>,
) -> Result<(Level3Data, Option<NearFacets>), Boolean3Error> {
    let (boxes_a, bvh_a) = (&broad_a.boxes, &broad_a.bvh);
    let (boxes_b, bvh_b) = (&broad_b.boxes, &broad_b.bvh);
    // Overlapping facet pairs; with a proximity, the pairs within it (a
    // superset: `candidates` tests every edge box against the other facet
    // box, so the extra pairs add no candidate and change nothing), from
    // which the contacts come.
    let fpairs = match proximity {
        Some(p) => bvh_a.pairs_within(boxes_a, bvh_b, boxes_b, crate::contacts::margin(p)),
        None => bvh_a.pairs(boxes_a, bvh_b, boxes_b),
    };
    let contacts = proximity.map(|p| crate::contacts::near_facets(a, b, &fpairs, p));
    let (c12, c21) = par::join(
        fpairs.len(),
        || candidates(&fpairs, a, boxes_b, Side::EdgesOfA),
        || candidates(&fpairs, b, boxes_a, Side::EdgesOfB),
    );
    // Each temporary list is freed as soon as the next one is built: they
    // are the largest arrays of the Boolean, and would otherwise all stay
    // alive through the propagation below.
    drop(fpairs);
    let (r12, r21) = par::join(
        c12.len().min(c21.len()),
        || edge_facet_hits(a, b, &c12, Side::EdgesOfA),
        || edge_facet_hits(b, a, &c21, Side::EdgesOfB),
    );
    let (x12, x21) = (r12?, r21?);
    let (c12, c21) = {
        let counts = (c12.len(), c21.len());
        drop((c12, c21));
        counts
    };
    let cast03 = |v: &Point3| x03_cast(v, b, bvh_b, boxes_b);
    let cast30 = |v: &Point3| x30_cast(a, v, bvh_a, boxes_a);
    let (x03, x30, casts) = match winding {
        Winding::Propagate => {
            let (r03, r30) = par::join(
                a.edges.len().min(b.edges.len()),
                || propagate(a, &x12, cast03),
                || propagate(b, &x21, cast30),
            );
            let ((x03, n03), (x30, n30)) = (r03?, r30?);
            (x03, x30, n03 + n30)
        }
        Winding::CastEach => {
            let ra = &a.referenced;
            let rb = &b.referenced;
            let x03 = (0..a.pos.len())
                .into_par_iter()
                .map(|i| if ra[i] { cast03(&a.pos[i]) } else { Ok(0) })
                .collect::<Result<Vec<_>, _>>()?;
            let x30 = (0..b.pos.len())
                .into_par_iter()
                .map(|i| if rb[i] { cast30(&b.pos[i]) } else { Ok(0) })
                .collect::<Result<Vec<_>, _>>()?;
            let n = ra.iter().chain(rb.iter()).filter(|&&r| r).count();
            (x03, x30, n)
        }
    };
    // The edge lists are filled in by `with_edges` where the data leaves
    // the crate (the construction reads the flat meshes directly).
    let l3 = Level3Data {
        edges_a: Vec::new(),
        edges_b: Vec::new(),
        x03,
        x30,
        x12,
        x21,
        candidate_pairs: c12 + c21,
        ray_casts: casts,
    };
    Ok((l3, contacts))
}

/// Level 3 by brute force straight from Table 4.1: every edge against every
/// facet, every vertex against every facet, no broad phase and no
/// propagation. Quadratic; for tests and audits of small inputs.
pub(crate) fn level3_brute(a: &Flat<'_>, b: &Flat<'_>) -> Result<Level3Data, Boolean3Error> {
    let mut x12v = Vec::new();
    for e in 0..a.edges.len() as u32 {
        let (p, q) = a.edge_points(e);
        for f in 0..b.facet_count() as u32 {
            if let Some((value, point)) = x12(&p, &q, b.facet_points(f))? {
                x12v.push(EdgeFacetHit {
                    edge: e,
                    facet: f,
                    value,
                    point,
                });
            }
        }
    }
    let mut x21v = Vec::new();
    for e in 0..b.edges.len() as u32 {
        let (p, q) = b.edge_points(e);
        for f in 0..a.facet_count() as u32 {
            if let Some((value, point)) = x21(a.facet_points(f), &p, &q)? {
                x21v.push(EdgeFacetHit {
                    edge: e,
                    facet: f,
                    value,
                    point,
                });
            }
        }
    }
    let ra = &a.referenced;
    let rb = &b.referenced;
    let mut x03 = vec![0; a.pos.len()];
    for (i, v) in a.pos.iter().enumerate() {
        if ra[i] {
            for f in 0..b.facet_count() as u32 {
                x03[i] += s02(v, b.facet_points(f))?; // X03 = sum_f S02
            }
        }
    }
    let mut x30 = vec![0; b.pos.len()];
    for (i, v) in b.pos.iter().enumerate() {
        if rb[i] {
            for f in 0..a.facet_count() as u32 {
                x30[i] -= s20(a.facet_points(f), v)?; // X30 = -sum_f S20
            }
        }
    }
    Ok(Level3Data {
        edges_a: a.edges.iter().map(|&(s, t)| [s, t]).collect(),
        edges_b: b.edges.iter().map(|&(s, t)| [s, t]).collect(),
        x03,
        x30,
        candidate_pairs: a.edges.len() * b.facet_count() + b.edges.len() * a.facet_count(),
        ray_casts: 0,
        x12: x12v,
        x21: x21v,
    })
}
