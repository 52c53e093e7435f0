//! Levels 4-6 (section 4.6): inclusion values (eq. 4.7-4.13), composite
//! edges with net end-vertex counts (retained parts of A's edges,
//! facet-facet intersection edges, retained parts of B's edges), retained
//! facets, and the shape.

use crate::composite::CompositeEdge3;
use crate::level3::Level3Data;
use crate::mesh::Flat;
use crate::par;
use crate::{Boolean3Error, BooleanOp, Operand};
use rayon::prelude::*;
use robust_arith::Point3;

/// Which level-4 operation built a composite edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompositeKind {
    /// The retained parts of edge `e_A` of A (`E13(e_A, B)`, eq. 4.21).
    EdgeA(u32),
    /// The intersection edges of facets `f_A` and `f_B` (`E22`, eq. 4.22).
    FacetPair(u32, u32),
    /// The retained parts of edge `e_B` of B (`E31(A, e_B)`, eq. 4.23).
    EdgeB(u32),
}

/// The vertex counts of one composite edge (Theorem 2 says they are equal).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompositeRecord {
    /// Which composite edge.
    pub kind: CompositeKind,
    /// The number of start-vertices.
    pub starts: u32,
    /// The number of end-vertices.
    pub ends: u32,
}

/// Where a retained facet of the result comes from (level 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FacetSource {
    /// The operand holding the original facet.
    pub operand: Operand,
    /// The original facet's index in that operand.
    pub facet: u32,
}

/// One chunk of retained facets: `(operand, half-edges, [(facet,
/// half-edge count)])`.
pub(crate) type RetainedChunk = (Operand, Vec<(u32, u32)>, Vec<(u32, u32)>);

/// The retained facets, in the chunks they were built in (A's facets, then
/// B's, each in facet order).
pub(crate) struct Retained {
    pub vertices: Vec<Point3>,
    /// `(operand, half-edges, [(facet, half-edge count)])` per chunk.
    pub chunks: Vec<RetainedChunk>,
    pub composites: Vec<CompositeRecord>,
    /// For each operand (A, B): the result vertex of each input vertex
    /// (`u32::MAX` when not retained), its inclusion value (eq. 4.7,
    /// 4.10), and the range of result vertex ids copied from it.
    pub maps: [VertexMap; 2],
}

/// Where one operand's vertices went in the result (the triangle-mesh
/// variant re-uses the input triangulation of untouched regions with it).
pub(crate) struct VertexMap {
    pub vid: Vec<u32>,
    pub incl: Vec<i32>,
    pub own: std::ops::Range<u32>,
}

impl Retained {
    /// The number of retained facets.
    pub fn facet_count(&self) -> usize {
        self.chunks.iter().map(|c| c.2.len()).sum()
    }

    /// Every retained facet with its source, in order.
    pub fn facets(&self) -> impl Iterator<Item = (FacetSource, &[(u32, u32)])> + '_ {
        self.chunks.iter().flat_map(|(operand, hes, list)| {
            let mut k = 0usize;
            list.iter().map(move |&(facet, n)| {
                let part = &hes[k..k + n as usize];
                k += n as usize;
                (
                    FacetSource {
                        operand: *operand,
                        facet,
                    },
                    part,
                )
            })
        })
    }
}

const NONE: u32 = u32::MAX;

fn unbalanced(kind: CompositeKind, c: &CompositeEdge3) -> Boolean3Error {
    Boolean3Error::Internal(format!(
        "Theorem 2 violated: composite edge {kind:?} has {} start- and {} end-vertices",
        c.starts.len(),
        c.ends.len()
    ))
}

/// Edges per parallel piece of [`edge_segments`] and facets per piece of
/// [`retained_facets`].
const CHUNK: usize = 1024;

/// The retained parts of the edges of one operand that do not take the
/// fast path of [`edge_segments`] (the *slow* edges), in compressed rows.
/// A fast edge is not stored: [`fast_half_edge`] gives its retained
/// half-edge from the inclusion values of its ends.
struct EdgeSegments {
    /// The slow edges, ascending; empty when `dense`.
    edge: Vec<u32>,
    /// Whether every edge is slow (the audit's recording disables the
    /// fast path): slow edge `i` is edge `i`, found without a search.
    dense: bool,
    /// `off[i]..off[i + 1]` index `seg`: the segments of slow edge `i`.
    off: Vec<u32>,
    seg: Vec<(u32, u32)>,
}

impl EdgeSegments {
    /// The segments of edge `e` when it is slow, `None` when it is fast.
    #[inline]
    fn get(&self, e: u32) -> Option<&[(u32, u32)]> {
        let i = if self.dense {
            e as usize
        } else {
            self.edge.binary_search(&e).ok()?
        };
        Some(&self.seg[self.off[i] as usize..self.off[i + 1] as usize])
    }
}

/// Whether an edge with ends of inclusion values `i_s`, `i_t` and no
/// intersection vertex takes the fast path: equal values in {-1, 0, 1}.
#[inline]
fn fast_edge(i_s: i32, i_t: i32) -> bool {
    i_s == i_t && (-1..=1).contains(&i_s)
}

/// The retained half-edge of half-edge `a -> b` of a fast edge whose ends
/// have inclusion value `k` (see [`fast_edge`]): the half-edge itself,
/// mapped (`k = 1`), reversed (`k = -1`) or nothing (`k = 0`, and a
/// zero-length half-edge, which would be dropped).
#[inline]
fn fast_half_edge(a: u32, b: u32, k: i32, vid: &[u32]) -> Option<(u32, u32)> {
    if a == b {
        return None;
    }
    match k {
        1 => Some((vid[a as usize], vid[b as usize])),
        -1 => Some((vid[b as usize], vid[a as usize])),
        _ => None,
    }
}

/// The retained parts of every edge of one operand (section 4.6): for A,
/// `I03(v_e)` at `v_e`, `-I03(v_s)` at `v_s` and `I12(e_A, f)` at each
/// intersection vertex; for B, `I21(f, e_B)` at each intersection vertex,
/// `I30(v_e)` at `v_e` and `-I30(v_s)` at `v_s`. Only the slow edges are
/// stored (see [`EdgeSegments`]); with `record`, every edge is slow and
/// recorded.
#[allow(clippy::too_many_arguments)]
fn edge_segments(
    mesh: &Flat<'_>,
    hits: &[crate::EdgeFacetHit],
    hit_base: u32,
    vid: &[u32],
    incl: &[i32],
    ci: i32,
    is_a: bool,
    record: bool,
) -> Result<(EdgeSegments, Vec<CompositeRecord>), Boolean3Error> {
    let n = mesh.edges.len();
    // (slow edges, their segment counts, their segments, records).
    type Chunk = (Vec<u32>, Vec<u32>, Vec<(u32, u32)>, Vec<CompositeRecord>);
    let parts: Vec<Chunk> = (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .with_min_len(par::min_len(CHUNK))
        .map(|piece| {
            let (lo, hi) = (piece * CHUNK, ((piece + 1) * CHUNK).min(n));
            let mut slow = Vec::new();
            let mut counts = Vec::new();
            let mut segs = Vec::new();
            let mut recs = Vec::new();
            let mut c = CompositeEdge3::default();
            // The hits are sorted by edge: those of this piece's edges
            // start here.
            let mut j = hits.partition_point(|h| (h.edge as usize) < lo);
            for e in lo as u32..hi as u32 {
                let (s, t) = mesh.edges[e as usize];
                let first = j;
                while j < hits.len() && hits[j].edge == e {
                    j += 1;
                }
                // Fast path: an edge without intersections whose two ends
                // have the same inclusion value k in {-1, 0, 1} is retained
                // whole (k = 1), reversed (k = -1) or not at all (k = 0):
                // exactly what the composite edge would give.
                if !record && first == j && fast_edge(incl[s as usize], incl[t as usize]) {
                    continue;
                }
                c.clear();
                let (ps, pt) = mesh.edge_points(e);
                let kind = if is_a {
                    CompositeKind::EdgeA(e)
                } else {
                    CompositeKind::EdgeB(e)
                };
                if is_a {
                    c.assign(vid[t as usize], pt, incl[t as usize]);
                    c.assign(vid[s as usize], ps, -incl[s as usize]);
                }
                for (k, h) in hits[first..j].iter().enumerate() {
                    // eq. 4.8 / 4.9: I = c_I X.
                    c.assign(hit_base + (first + k) as u32, h.point, ci * h.value);
                }
                if !is_a {
                    c.assign(vid[t as usize], pt, incl[t as usize]);
                    c.assign(vid[s as usize], ps, -incl[s as usize]);
                }
                if record {
                    recs.push(CompositeRecord {
                        kind,
                        starts: c.starts.len() as u32,
                        ends: c.ends.len() as u32,
                    });
                }
                let before = segs.len();
                if !c.pair_into(&mut segs) {
                    return Err(unbalanced(kind, &c));
                }
                slow.push(e);
                counts.push((segs.len() - before) as u32);
            }
            Ok((slow, counts, segs, recs))
        })
        .collect::<Result<_, Boolean3Error>>()?;
    let n_slow: usize = parts.iter().map(|p| p.0.len()).sum();
    let n_seg: usize = parts.iter().map(|p| p.2.len()).sum();
    let dense = n_slow == n;
    let mut out = EdgeSegments {
        edge: Vec::with_capacity(if dense { 0 } else { n_slow }),
        dense,
        off: Vec::with_capacity(n_slow + 1),
        seg: Vec::with_capacity(n_seg),
    };
    let mut records = Vec::new();
    out.off.push(0);
    for (slow, counts, segs, recs) in parts {
        if !dense {
            out.edge.extend(slow);
        }
        out.seg.extend(segs);
        let mut last = *out.off.last().unwrap_or(&0);
        for k in counts {
            last += k;
            out.off.push(last);
        }
        records.extend(recs);
    }
    Ok((out, records))
}

/// One net end-vertex count contributing to a facet-facet composite edge.
#[derive(Clone, Copy)]
struct PairEntry {
    fa: u32,
    fb: u32,
    id: u32,
    count: i32,
    pos: Point3,
}

/// Builds levels 4 and 5 from the level-3 data.
pub(crate) fn construct(
    a: &Flat<'_>,
    b: &Flat<'_>,
    l3: &Level3Data,
    op: BooleanOp,
    record: bool,
) -> Result<Retained, Boolean3Error> {
    let (ca, cb, ci) = op.coefficients();
    let ra = &a.referenced;
    let rb = &b.referenced;
    // Inclusion values of vertices, eq. 4.7 and 4.10.
    let i03: Vec<i32> = (0..a.pos.len())
        .map(|v| if ra[v] { ca + ci * l3.x03[v] } else { 0 })
        .collect();
    let i30: Vec<i32> = (0..b.pos.len())
        .map(|v| if rb[v] { cb + ci * l3.x30[v] } else { 0 })
        .collect();

    // The vertices of the result (section 4.6): retained vertices of A,
    // intersection vertices of X12 and X21 pairs (I = c_I X != 0 since
    // c_I = +-1), retained vertices of B.
    let total = i03.iter().filter(|&&i| i != 0).count()
        + l3.x12.len()
        + l3.x21.len()
        + i30.iter().filter(|&&i| i != 0).count();
    if total >= NONE as usize {
        return Err(Boolean3Error::TooLarge { what: "vertices" });
    }
    let mut vertices = Vec::with_capacity(total);
    let mut vid_a = vec![NONE; a.pos.len()];
    for v in 0..a.pos.len() {
        if i03[v] != 0 {
            vid_a[v] = vertices.len() as u32;
            vertices.push(a.pos[v]);
        }
    }
    let base12 = vertices.len() as u32;
    vertices.extend(l3.x12.iter().map(|h| h.point));
    let base21 = vertices.len() as u32;
    vertices.extend(l3.x21.iter().map(|h| h.point));
    let base_b = vertices.len() as u32;
    let mut vid_b = vec![NONE; b.pos.len()];
    for v in 0..b.pos.len() {
        if i30[v] != 0 {
            vid_b[v] = vertices.len() as u32;
            vertices.push(b.pos[v]);
        }
    }

    // Level 4: retained parts of the edges of A and of B.
    let ((seg_a, rec_a), (seg_b, rec_b)) = {
        let (x, y) = par::join(
            a.edges.len().min(b.edges.len()),
            || edge_segments(a, &l3.x12, base12, &vid_a, &i03, ci, true, record),
            || edge_segments(b, &l3.x21, base21, &vid_b, &i30, ci, false, record),
        );
        (x?, y?)
    };

    // Level 4: facet-facet intersection edges. For f_A and f_B, each
    // half-edge h of f_A contributes -I12(h, f_B) at its intersection
    // vertex and each half-edge h of f_B contributes I21(f_A, h); a
    // backward half-edge has the negated value of its edge (section 4.5).
    let mut entries: Vec<PairEntry> = Vec::new();
    for (j, hit) in l3.x12.iter().enumerate() {
        for &h in a.edge_half_edges(hit.edge) {
            let dir = if a.he_fwd(h) { 1 } else { -1 };
            entries.push(PairEntry {
                fa: a.he_facet(h),
                fb: hit.facet,
                id: base12 + j as u32,
                count: -(ci * hit.value * dir),
                pos: hit.point,
            });
        }
    }
    for (j, hit) in l3.x21.iter().enumerate() {
        for &h in b.edge_half_edges(hit.edge) {
            let dir = if b.he_fwd(h) { 1 } else { -1 };
            entries.push(PairEntry {
                fa: hit.facet,
                fb: b.he_facet(h),
                id: base21 + j as u32,
                count: ci * hit.value * dir,
                pos: hit.point,
            });
        }
    }
    // A stable sort: within a facet pair the order of assignment is the
    // order above, independent of threads.
    entries.par_sort_by_key(|e| (e.fa, e.fb));
    // (f_A, f_B, start, end) of every intersection segment, by f_A.
    let mut pair_segs: Vec<(u32, u32, u32, u32)> = Vec::new();
    let mut composites = rec_a;
    {
        let mut c = CompositeEdge3::default();
        let mut segs = Vec::new();
        let mut i = 0;
        while i < entries.len() {
            let (fa, fb) = (entries[i].fa, entries[i].fb);
            c.clear();
            while i < entries.len() && entries[i].fa == fa && entries[i].fb == fb {
                let e = &entries[i];
                c.assign(e.id, e.pos, e.count);
                i += 1;
            }
            let kind = CompositeKind::FacetPair(fa, fb);
            if record {
                composites.push(CompositeRecord {
                    kind,
                    starts: c.starts.len() as u32,
                    ends: c.ends.len() as u32,
                });
            }
            segs.clear();
            if !c.pair_into(&mut segs) {
                return Err(unbalanced(kind, &c));
            }
            pair_segs.extend(segs.iter().map(|&(s, e)| (fa, fb, s, e)));
        }
    }
    composites.extend(rec_b);
    let mut by_b: Vec<u32> = (0..pair_segs.len() as u32).collect();
    by_b.par_sort_by_key(|&k| pair_segs[k as usize].1);
    let off_a = facet_ranges(a.facet_count(), pair_segs.iter().map(|p| p.0));
    let off_b = facet_ranges(
        b.facet_count(),
        by_b.iter().map(|&k| pair_segs[k as usize].1),
    );

    // The facets with an intersection vertex on an edge or an
    // intersection edge: every such facet is in some pair above. The
    // others (almost all, on large operands) have only edges without
    // intersection vertices.
    let mut touched_a = vec![false; a.facet_count()];
    let mut touched_b = vec![false; b.facet_count()];
    for e in &entries {
        touched_a[e.fa as usize] = true;
        touched_b[e.fb as usize] = true;
    }
    drop(entries);

    // Level 5: the retained facets. A facet of A takes the retained parts
    // of its half-edges and the forward half-edges of its intersection
    // edges; a facet of B the backward half-edges of its intersection
    // edges and the retained parts of its half-edges. Zero-length
    // half-edges (start = end) are dropped: each is balanced by itself, so
    // facet and shape boundary closure are unaffected.
    let facets_a = retained_facets(a, &seg_a, (&vid_a, &i03), &touched_a, |f, out| {
        for k in off_a[f as usize]..off_a[f as usize + 1] {
            let (_, _, s, e) = pair_segs[k as usize];
            out.push((s, e));
        }
    });
    let facets_b = retained_facets(b, &seg_b, (&vid_b, &i30), &touched_b, |f, out| {
        for k in off_b[f as usize]..off_b[f as usize + 1] {
            let (_, _, s, e) = pair_segs[by_b[k as usize] as usize];
            out.push((e, s));
        }
    });
    let total: usize = facets_a
        .iter()
        .chain(facets_b.iter())
        .map(|c| c.0.len())
        .sum();
    if total >= NONE as usize {
        return Err(Boolean3Error::TooLarge { what: "half-edges" });
    }
    let chunks = facets_a
        .into_iter()
        .map(|(h, l)| (Operand::A, h, l))
        .chain(facets_b.into_iter().map(|(h, l)| (Operand::B, h, l)))
        .collect();
    let total = vertices.len() as u32;
    Ok(Retained {
        vertices,
        chunks,
        composites,
        maps: [
            VertexMap {
                vid: vid_a,
                incl: i03,
                own: 0..base12,
            },
            VertexMap {
                vid: vid_b,
                incl: i30,
                own: base_b..total,
            },
        ],
    })
}

/// Offsets of contiguous per-facet ranges from a sorted facet sequence.
pub(crate) fn facet_ranges(n: usize, keys: impl Iterator<Item = u32>) -> Vec<u32> {
    let mut off = vec![0u32; n + 1];
    for f in keys {
        off[f as usize + 1] += 1;
    }
    for i in 0..n {
        off[i + 1] += off[i];
    }
    off
}

type FacetChunk = (Vec<(u32, u32)>, Vec<(u32, u32)>);

/// The half-edges of each retained facet of one operand, in parallel
/// chunks concatenated in facet order: `(half-edges, [(facet, count)])`.
/// `map` is the operand's `(vid, incl)`; `touched[f]` says whether facet
/// `f` may have an edge with intersection vertices or intersection edges.
/// An untouched facet's half-edges on fast edges (see [`fast_edge`]) are
/// retained straight from the inclusion values of their ends, without
/// looking the edge up (the common case: a facet far from the other
/// operand, kept whole or dropped whole).
fn retained_facets(
    mesh: &Flat<'_>,
    segs: &EdgeSegments,
    (vid, incl): (&[u32], &[i32]),
    touched: &[bool],
    intersections: impl Fn(u32, &mut Vec<(u32, u32)>) + Sync,
) -> Vec<FacetChunk> {
    let n = mesh.facet_count();
    (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .with_min_len(par::min_len(CHUNK))
        .map(|piece| {
            let (lo, hi) = (piece * CHUNK, ((piece + 1) * CHUNK).min(n));
            // Room for the piece's facets kept whole, without regrowing;
            // what is not used is given back below.
            let start = |f: usize| {
                if f == n {
                    mesh.he_count()
                } else {
                    mesh.facet_range(f as u32).start
                }
            };
            let mut hes = Vec::with_capacity(start(hi) - start(lo));
            let mut list = Vec::with_capacity(hi - lo);
            for f in lo as u32..hi as u32 {
                let before = hes.len();
                let touched = touched[f as usize];
                for h in mesh.facet_range(f) {
                    let (a, b) = mesh.he(h as u32);
                    let (ia, ib) = (incl[a as usize], incl[b as usize]);
                    // An untouched facet's edge has no intersection vertex:
                    // it is slow only when the values say so.
                    let stored = if !touched && !segs.dense && fast_edge(ia, ib) {
                        None
                    } else {
                        segs.get(mesh.he_edge[h])
                    };
                    match stored {
                        Some(parts) => {
                            let fwd = a <= b;
                            for &(s, t) in parts {
                                if s != t {
                                    hes.push(if fwd { (s, t) } else { (t, s) });
                                }
                            }
                        }
                        None => {
                            if let Some(x) = fast_half_edge(a, b, ia, vid) {
                                hes.push(x);
                            }
                        }
                    }
                }
                if touched {
                    let mid = hes.len();
                    intersections(f, &mut hes);
                    // Drop zero-length intersection half-edges as well.
                    let mut w = mid;
                    for r in mid..hes.len() {
                        if hes[r].0 != hes[r].1 {
                            hes[w] = hes[r];
                            w += 1;
                        }
                    }
                    hes.truncate(w);
                }
                if hes.len() > before {
                    list.push((f, (hes.len() - before) as u32));
                }
            }
            hes.shrink_to_fit();
            list.shrink_to_fit();
            (hes, list)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level3::{level3_with_contacts, Winding};
    use crate::merge::Merged;
    use proptest::prelude::*;
    use test_support::rng::SplitMix64;
    use test_support::shapes::{
        box_mesh, box_triangles, uv_sphere, CUBE_FACES, OCTA_FACES, TETRA_FACES,
    };
    use topology::{Facet, PolygonMesh, TriangleMesh};

    /// Levels 4-5 of `a` and `b` for every operation, by the fast paths
    /// (fast edges not stored, untouched facets retained from inclusion
    /// values) and with recording on, which takes every edge through its
    /// composite edge and looks every half-edge up: the same vertices,
    /// vertex maps and retained facets, or the same error.
    fn paths_agree(a: &Flat<'_>, b: &Flat<'_>) {
        let Ok((l3, _)) = level3_with_contacts(a, b, Winding::Propagate, None) else {
            return;
        };
        for op in BooleanOp::BASIC {
            if op == BooleanOp::Xor {
                continue;
            }
            let fast = construct(a, b, &l3, op, false);
            let general = construct(a, b, &l3, op, true);
            match (fast, general) {
                (Ok(f), Ok(g)) => {
                    assert_eq!(f.vertices, g.vertices, "{op:?}");
                    assert_eq!(f.chunks, g.chunks, "{op:?}");
                    for (x, y) in f.maps.iter().zip(&g.maps) {
                        assert_eq!((&x.vid, &x.incl, &x.own), (&y.vid, &y.incl, &y.own));
                    }
                }
                (Err(f), Err(g)) => assert_eq!(f.to_string(), g.to_string(), "{op:?}"),
                (f, g) => panic!("{op:?}: fast {:?}, general {:?}", f.is_ok(), g.is_ok()),
            }
        }
    }

    /// [`paths_agree`] on polygon meshes and, triangulated and merged as
    /// the triangle-mesh variant does, on their triangles.
    fn both_variants(a: &PolygonMesh, b: &PolygonMesh) {
        if let (Ok(fa), Ok(fb)) = (Flat::from_polygon_mesh(a), Flat::from_polygon_mesh(b)) {
            paths_agree(&fa, &fb);
        }
        let (ta, tb) = (crate::triangulate_mesh(a), crate::triangulate_mesh(b));
        triangles_agree(&ta, &tb);
    }

    fn triangles_agree(a: &TriangleMesh, b: &TriangleMesh) {
        let (Ok(fa), Ok(fb)) = (Flat::from_triangle_mesh(a), Flat::from_triangle_mesh(b)) else {
            return;
        };
        let (Ok((_, ma)), Ok((_, mb))) = (Merged::new(fa), Merged::new(fb)) else {
            return;
        };
        paths_agree(&ma, &mb);
    }

    /// One to three shells (tetrahedra, octahedra, cubes), some inside
    /// out, with coordinates of mixed magnitude (`garbage`) or jittered
    /// around a unit-scale position: overlapping and inverted shells give
    /// inclusion values outside {-1, 0, 1} and edges whose ends differ.
    fn shells(r: &mut SplitMix64, garbage: bool) -> PolygonMesh {
        let mut v = Vec::new();
        let mut f = Vec::new();
        for _ in 0..r.range(1, 3) {
            let base = v.len() as u32;
            let flip = r.range(0, 3) == 0;
            let loops: Vec<Vec<u32>> = match r.range(0, 2) {
                0 => TETRA_FACES.iter().map(|t| t.to_vec()).collect(),
                1 => OCTA_FACES.iter().map(|t| t.to_vec()).collect(),
                _ => CUBE_FACES.iter().map(|q| q.to_vec()).collect(),
            };
            let n = loops.iter().flatten().max().map_or(0, |m| m + 1);
            let centre = [r.pm1(), r.pm1(), r.pm1()];
            for k in 0..n {
                v.push(if garbage {
                    [
                        r.magnitude(-60, 60),
                        r.magnitude(-60, 60),
                        r.magnitude(-60, 60),
                    ]
                } else {
                    // A unit shell's corners (the cube's numbering:
                    // coordinate j from bit j), jittered.
                    let s = |j: u32| if k >> j & 1 == 1 { 1.0 } else { -1.0 };
                    [
                        centre[0] + s(0) + r.pm1() / 8.0,
                        centre[1] + s(1) + r.pm1() / 8.0,
                        centre[2] + s(2) + r.pm1() / 8.0,
                    ]
                });
            }
            for l in loops {
                let mut l: Vec<u32> = l.iter().map(|k| k + base).collect();
                if flip {
                    l.reverse();
                }
                f.push(Facet::from_loop(&l));
            }
        }
        PolygonMesh::new(v, f)
    }

    #[test]
    fn fast_paths_equal_the_general_path_on_spheres_and_plates() {
        // Curved operands: most facets untouched, kept whole or dropped.
        let a = uv_sphere([0.0; 3], 1.0, 24, 12);
        let b = uv_sphere([0.4, 0.3, 0.2], 0.8, 20, 10);
        triangles_agree(&a, &b);
        // A plate cut by boxes, one difference at a time (merged facets,
        // cut and whole), against a cutter.
        let mut plate = box_triangles([0.0, 0.0, 0.0], [4.0, 3.0, 1.0]);
        for (x, y) in [(0.25, 0.25), (1.25, 2.25), (3.25, 1.25)] {
            let hole = box_triangles([x, y, -0.5], [x + 0.5, y + 0.5, 1.5]);
            triangles_agree(&plate, &hole);
            plate = crate::boolean_triangles(&plate, &hole, BooleanOp::Difference)
                .unwrap()
                .mesh;
        }
        triangles_agree(&plate, &box_triangles([1.5, 0.5, 0.5], [3.5, 2.5, 2.0]));
        both_variants(
            &box_mesh([0.0; 3], [2.0; 3]),
            &box_mesh([1.0; 3], [3.0, 3.0, 2.0]),
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(48)))]

        /// Random shells, jittered or garbage, both variants.
        #[test]
        fn fast_paths_equal_the_general_path_on_random_shells(seed in any::<u64>(),
                                                             garbage in any::<bool>()) {
            let mut r = SplitMix64::new(seed);
            let a = shells(&mut r, garbage);
            let b = shells(&mut r, garbage);
            both_variants(&a, &b);
        }
    }
}
