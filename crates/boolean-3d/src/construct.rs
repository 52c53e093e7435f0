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

/// Offsets of the per-edge ranges of hits sorted by edge.
fn ranges(n_edges: usize, hits: &[crate::EdgeFacetHit]) -> Vec<u32> {
    let mut off = vec![0u32; n_edges + 1];
    for h in hits {
        off[h.edge as usize + 1] += 1;
    }
    for i in 0..n_edges {
        off[i + 1] += off[i];
    }
    off
}

/// Segments of every edge of one operand, in compressed rows.
struct EdgeSegments {
    off: Vec<u32>,
    seg: Vec<(u32, u32)>,
}

/// The retained parts of every edge of one operand (section 4.6): for A,
/// `I03(v_e)` at `v_e`, `-I03(v_s)` at `v_s` and `I12(e_A, f)` at each
/// intersection vertex; for B, `I21(f, e_B)` at each intersection vertex,
/// `I30(v_e)` at `v_e` and `-I30(v_s)` at `v_s`.
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
    let off = ranges(n, hits);
    let idx: Vec<u32> = (0..n as u32).collect();
    type Chunk = (Vec<(u32, u32)>, Vec<u32>, Vec<CompositeRecord>);
    let parts: Vec<Chunk> = idx
        .par_chunks(1024)
        .with_min_len(par::min_len(1024))
        .map(|chunk| {
            let mut segs = Vec::new();
            let mut counts = Vec::with_capacity(chunk.len());
            let mut recs = Vec::new();
            let mut c = CompositeEdge3::default();
            for &e in chunk {
                let (s, t) = mesh.edges[e as usize];
                let range = off[e as usize] as usize..off[e as usize + 1] as usize;
                // Fast path: an edge without intersections whose two ends
                // have the same inclusion value k in {-1, 0, 1} is retained
                // whole (k = 1), reversed (k = -1) or not at all (k = 0):
                // exactly what the composite edge would give.
                if !record && range.is_empty() && incl[s as usize] == incl[t as usize] {
                    match incl[t as usize] {
                        0 => {
                            counts.push(0);
                            continue;
                        }
                        1 => {
                            segs.push((vid[s as usize], vid[t as usize]));
                            counts.push(1);
                            continue;
                        }
                        -1 => {
                            segs.push((vid[t as usize], vid[s as usize]));
                            counts.push(1);
                            continue;
                        }
                        _ => {}
                    }
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
                for j in range {
                    let h = &hits[j];
                    // eq. 4.8 / 4.9: I = c_I X.
                    c.assign(hit_base + j as u32, h.point, ci * h.value);
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
                counts.push((segs.len() - before) as u32);
            }
            Ok((segs, counts, recs))
        })
        .collect::<Result<_, Boolean3Error>>()?;
    let mut out = EdgeSegments {
        off: Vec::with_capacity(n + 1),
        seg: Vec::new(),
    };
    let mut records = Vec::new();
    out.off.push(0);
    for (segs, counts, recs) in parts {
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

    // Level 5: the retained facets. A facet of A takes the retained parts
    // of its half-edges and the forward half-edges of its intersection
    // edges; a facet of B the backward half-edges of its intersection
    // edges and the retained parts of its half-edges. Zero-length
    // half-edges (start = end) are dropped: each is balanced by itself, so
    // facet and shape boundary closure are unaffected.
    let facets_a = retained_facets(a, &seg_a, |f, out| {
        for k in off_a[f as usize]..off_a[f as usize + 1] {
            let (_, _, s, e) = pair_segs[k as usize];
            out.push((s, e));
        }
    });
    let facets_b = retained_facets(b, &seg_b, |f, out| {
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
fn facet_ranges(n: usize, keys: impl Iterator<Item = u32>) -> Vec<u32> {
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
fn retained_facets(
    mesh: &Flat<'_>,
    segs: &EdgeSegments,
    intersections: impl Fn(u32, &mut Vec<(u32, u32)>) + Sync,
) -> Vec<FacetChunk> {
    let idx: Vec<u32> = (0..mesh.facet_count() as u32).collect();
    idx.par_chunks(1024)
        .with_min_len(par::min_len(1024))
        .map(|chunk| {
            let mut hes = Vec::new();
            let mut list = Vec::new();
            for &f in chunk {
                let before = hes.len();
                for h in mesh.facet_range(f) {
                    let e = mesh.he_edge[h] as usize;
                    let fwd = mesh.he_fwd(h as u32);
                    for &(s, t) in &segs.seg[segs.off[e] as usize..segs.off[e + 1] as usize] {
                        if s != t {
                            hes.push(if fwd { (s, t) } else { (t, s) });
                        }
                    }
                }
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
                if hes.len() > before {
                    list.push((f, (hes.len() - before) as u32));
                }
            }
            (hes, list)
        })
        .collect()
}
