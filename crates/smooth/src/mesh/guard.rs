//! The guard of 3D smoothing ([`crate::SmoothOptions::guard`]): smoothing
//! is kept only where it leaves no more defects than the input had. The
//! operations of Appendix A move vertices by up to the tolerance and
//! split edges at created vertices; where two surfaces lie within the
//! tolerance of each other at an angle (a solid minus a copy of itself
//! turned by a few degrees), a merge or a crack on one surface can push a
//! facet through the other, which the raw Boolean (Theorem 2: exact
//! topology, no such pair where its operands had none) did not do. The
//! guard counts intersecting facet pairs, non-manifold edges and
//! vertices, and open edges near the facets smoothing changed, in the
//! result and, only when the result has some, in the input near the
//! facets they replaced. The changed facets of both meshes form places
//! (patches joined where they share a vertex position); each place's
//! defects are counted on both sides, and at a place where the result is
//! worse by [`crate::MeshDefects::worse_than`] (more pairs, or as many
//! and more manifold defects) its input facets replace its result facets
//! ([`Verdict::Mixed`]). A mixed mesh that is not closed or is worse than
//! what would be returned otherwise, or a result worse at every place,
//! falls back to the whole decision: the input when the result is worse
//! near everything that changed, else the result. Outside the focus both
//! meshes are the same, so the comparison near it is the comparison of
//! the whole meshes.

use crate::mesh::region::Facets;
use crate::{MeshDefects, Reverted, SmoothReport};
use rayon::prelude::*;
use rustc_hash::{FxHashMap, FxHashSet};
use topology::{ManifoldReport, Point3, PolygonMesh, TriangleMesh};

/// A facet as the sorted list of its half-edges' end positions (bit
/// patterns): equal for the same facet in two meshes whatever the vertex
/// numbering and the order of its half-edges.
fn key<F: Facets + ?Sized>(pos: &[Point3], facets: &F, f: usize) -> Vec<[u64; 6]> {
    let bits = |v: u32| pos[v as usize].map(f64::to_bits);
    let mut k: Vec<[u64; 6]> = facets
        .half_edges(f)
        .map(|(s, e)| {
            let (a, b) = (bits(s), bits(e));
            [a[0], a[1], a[2], b[0], b[1], b[2]]
        })
        .collect();
    k.sort_unstable();
    k
}

/// The facets `f` with `mask[f]`, in order (found in parallel).
fn marked<F: Facets + ?Sized>(facets: &F, mask: &[bool]) -> Vec<usize> {
    (0..facets.count())
        .into_par_iter()
        .filter(|&f| mask[f])
        .collect()
}

/// The keys of the facets `ids`, computed in parallel (each a sort of a
/// facet's half-edges).
fn keys<F: Facets + ?Sized>(
    pos: &[Point3],
    facets: &F,
    ids: &[usize],
) -> Vec<(usize, Vec<[u64; 6]>)> {
    ids.par_iter().map(|&f| (f, key(pos, facets, f))).collect()
}

/// The facets smoothing changed: of the candidates `before_in` of the
/// input and `after_in` of the result, those with no equal facet (same
/// half-edges at the same positions, counted with multiplicity) on the
/// other side. Unchanged facets are the same in both meshes, so the
/// defects that differ all touch these.
pub(crate) fn changed<B: Facets + ?Sized, A: Facets + ?Sized>(
    before: (&[Point3], &B, &[bool]),
    after: (&[Point3], &A, &[bool]),
) -> (Vec<bool>, Vec<bool>) {
    let (bp, bf, bin) = before;
    let (ap, af, ain) = after;
    let (b_ids, a_ids) = (marked(bf, bin), marked(af, ain));
    let before_keys = keys(bp, bf, &b_ids);
    let after_keys = keys(ap, af, &a_ids);
    let mut count: FxHashMap<&[[u64; 6]], i64> = FxHashMap::default();
    for (_, k) in &before_keys {
        *count.entry(k.as_slice()).or_default() += 1;
    }
    // Matched facets of the result take one count each; what is left
    // over on the input side is the input's changed facets.
    let mut after_changed = vec![false; af.count()];
    for (f, k) in &after_keys {
        match count.get_mut(k.as_slice()) {
            Some(c) if *c > 0 => *c -= 1,
            _ => after_changed[*f] = true,
        }
    }
    let mut before_changed = vec![false; bf.count()];
    for (f, k) in &before_keys {
        if let Some(c) = count.get_mut(k.as_slice()) {
            if *c > 0 {
                *c -= 1;
                before_changed[*f] = true;
            }
        }
    }
    // A merge of vertices at one position leaves every facet's positions
    // as they were but not its topology (two cubes at one place, welded:
    // twelve edges then used four times each): the facets at a position
    // whose number of vertices differs between the meshes changed too.
    let moved = reidentified((bp, bf, &b_ids), (ap, af, &a_ids));
    if !moved.is_empty() {
        let at = |pos: &[Point3], v: u32| moved.contains(&pos[v as usize].map(f64::to_bits));
        for &f in &b_ids {
            before_changed[f] |= bf.starts(f).any(|v| at(bp, v));
        }
        for &f in &a_ids {
            after_changed[f] |= af.starts(f).any(|v| at(ap, v));
        }
    }
    (before_changed, after_changed)
}

/// The positions at which the candidate facets `ids` of the two meshes
/// use a different number of distinct vertices. Positions held by one
/// vertex on both sides (the usual case: smoothing leaves no two vertices
/// at one position) are found with one map entry per vertex; only
/// positions held by several vertices on either side are counted exactly.
fn reidentified<B: Facets + ?Sized, A: Facets + ?Sized>(
    before: (&[Point3], &B, &[usize]),
    after: (&[Point3], &A, &[usize]),
) -> FxHashSet<[u64; 3]> {
    /// The number of distinct vertices at each position that holds more
    /// than one (the first vertex of every position in a map, the others
    /// listed and counted apart: no allocation per position).
    fn several<F: Facets + ?Sized>(
        (pos, facets, ids): (&[Point3], &F, &[usize]),
    ) -> FxHashMap<[u64; 3], usize> {
        // The vertices the candidates use, each once, then one map entry
        // per vertex.
        let used = distinct_corners(pos.len(), facets, ids);
        let mut first: FxHashMap<[u64; 3], u32> = FxHashMap::default();
        let mut others: Vec<([u64; 3], u32)> = Vec::new();
        for v in used {
            let k = pos[v as usize].map(f64::to_bits);
            if *first.entry(k).or_insert(v) != v {
                others.push((k, v));
            }
        }
        let mut count: FxHashMap<[u64; 3], usize> = FxHashMap::default();
        for (k, _) in others {
            *count.entry(k).or_insert(1) += 1;
        }
        count
    }
    let (b, a) = (several(before), several(after));
    let held = |m: &FxHashMap<[u64; 3], usize>, k: &[u64; 3]| m.get(k).copied().unwrap_or(1);
    b.keys()
        .chain(a.keys())
        .filter(|k| held(&b, k) != held(&a, k))
        .copied()
        .collect()
}

/// The vertices of the facets `ids` (indices below `n`), each once,
/// ascending: sorted from the corners when the facets are few against the
/// vertices (a region in a large mesh, where a flag per vertex would cost
/// more than the facets), else by a flag per vertex.
fn distinct_corners<F: Facets + ?Sized>(n: usize, facets: &F, ids: &[usize]) -> Vec<u32> {
    if ids.len() < n / 16 {
        sorted_corners(facets, ids)
    } else {
        flagged_corners(n, facets, ids)
    }
}

/// [`distinct_corners`] by sorting the corners.
fn sorted_corners<F: Facets + ?Sized>(facets: &F, ids: &[usize]) -> Vec<u32> {
    let mut used: Vec<u32> = ids.iter().flat_map(|&f| facets.starts(f)).collect();
    used.par_sort_unstable();
    used.dedup();
    used
}

/// [`distinct_corners`] by a flag per vertex.
fn flagged_corners<F: Facets + ?Sized>(n: usize, facets: &F, ids: &[usize]) -> Vec<u32> {
    let mut flag = vec![false; n];
    for &f in ids {
        for v in facets.starts(f) {
            flag[v as usize] = true;
        }
    }
    (0..n as u32).filter(|&v| flag[v as usize]).collect()
}

/// Where the defects near a focus lie: the intersecting facet pairs and
/// the manifold report near it (the exact tests of `topology`).
pub(crate) struct Sites {
    pairs: Vec<[u32; 2]>,
    manifold: ManifoldReport,
}

impl Sites {
    fn new(pairs: Option<Vec<[u32; 2]>>, manifold: Option<ManifoldReport>) -> Sites {
        Sites {
            pairs: pairs.unwrap_or_default(),
            manifold: manifold.unwrap_or_default(),
        }
    }

    /// The counts the guard compares.
    fn counts(&self) -> MeshDefects {
        MeshDefects {
            intersecting_pairs: self.pairs.len(),
            non_manifold_edges: self.manifold.non_manifold_edges.len(),
            non_manifold_vertices: self.manifold.non_manifold_vertices.len(),
            open_edges: self.manifold.open_edges.len(),
        }
    }
}

/// A mesh the guard inspects: its positions and facets, its defects near
/// a focus, and how to build one from half-edge loops.
pub(crate) trait Guarded: Sized {
    /// The facets as the region code reads them.
    type Facets: Facets + ?Sized;
    /// The positions and the facets.
    fn parts(&self) -> (&[Point3], &Self::Facets);
    /// Where the defects near the facets `f` with `focus[f]` lie.
    fn sites_near(&self, focus: &[bool]) -> Sites;
    /// The mesh of `facets` (half-edge loops over `vertices`; a triangle
    /// mesh's are triangles), `None` when it is not closed (section 4.2).
    fn closed_mesh(vertices: Vec<Point3>, facets: Vec<Vec<(u32, u32)>>) -> Option<Self>;
}

impl Guarded for PolygonMesh {
    type Facets = [topology::Facet];
    fn parts(&self) -> (&[Point3], &Self::Facets) {
        (&self.vertices, &self.facets)
    }
    fn sites_near(&self, focus: &[bool]) -> Sites {
        Sites::new(
            topology::self_intersecting_pairs_near(self, focus),
            self.manifold_report_near(focus),
        )
    }
    fn closed_mesh(vertices: Vec<Point3>, facets: Vec<Vec<(u32, u32)>>) -> Option<Self> {
        let facets = facets
            .into_iter()
            .map(|f| topology::Facet {
                half_edges: f
                    .into_iter()
                    .map(|(start, end)| topology::HalfEdge { start, end })
                    .collect(),
            })
            .collect();
        let m = PolygonMesh::new(vertices, facets);
        m.check_topology().is_ok().then_some(m)
    }
}

impl Guarded for TriangleMesh {
    type Facets = [[u32; 3]];
    fn parts(&self) -> (&[Point3], &Self::Facets) {
        (&self.vertices, &self.triangles)
    }
    fn sites_near(&self, focus: &[bool]) -> Sites {
        Sites::new(
            topology::self_intersecting_triangle_pairs_near(self, focus),
            self.manifold_report_near(focus),
        )
    }
    fn closed_mesh(vertices: Vec<Point3>, facets: Vec<Vec<(u32, u32)>>) -> Option<Self> {
        let triangles = facets
            .iter()
            .map(|f| match *f.as_slice() {
                [(a, b), (b2, c), (c2, a2)] if b == b2 && c == c2 && a == a2 => Some([a, b, c]),
                _ => None,
            })
            .collect::<Option<Vec<[u32; 3]>>>()?;
        let m = TriangleMesh::new(vertices, triangles);
        m.check_topology().is_ok().then_some(m)
    }
}

/// What the guard decided on a smoothing run.
pub(crate) enum Verdict<M> {
    /// Keep the result.
    Keep,
    /// Hand the input back, with this report.
    Input(SmoothReport),
    /// The result with smoothing undone at some places, and its report.
    Mixed(M, SmoothReport),
}

impl<M: Clone> Verdict<M> {
    /// The shape and report to return for `input` smoothed into `result`
    /// with `report`.
    pub(crate) fn apply(self, input: &M, result: M, report: SmoothReport) -> (M, SmoothReport) {
        match self {
            Verdict::Keep => (result, report),
            Verdict::Input(back) => (input.clone(), back),
            Verdict::Mixed(m, r) => (m, r),
        }
    }
}

/// The guard's rule on counts: the result's defects near what changed
/// (`smoothed`) are worse than the input's there (`input`, computed only
/// when the result has any).
fn worse(smoothed: MeshDefects, input: impl FnOnce() -> MeshDefects) -> bool {
    smoothed.any() && smoothed.worse_than(&input())
}

/// The guard on a mesh smoothed into `result`: the candidates `input_in`
/// of the input became the candidates `result_in` of the result (the
/// region and what replaced it, or everything).
///
/// When the result has defects near what changed, the changed facets of
/// both meshes are split into places (patches joined where they share a
/// vertex position), each place's defects counted on both sides, and
/// smoothing is undone at the places where it is worse than the input
/// there: their input facets replace their result facets (by position,
/// so the cut matches vertex for vertex). The mixed mesh must be closed
/// and, near everything that changed, no worse than what the guard would
/// return otherwise: the input when the result is worse than it near
/// everything that changed, else the result. When every place is worse,
/// or no place is and the whole is, the input is handed back whole.
pub(crate) fn guard<M: Guarded>(
    report: &SmoothReport,
    input: (&M, &[bool]),
    result: (&M, &[bool]),
) -> Verdict<M> {
    let ((i, i_in), (r, r_in)) = (input, result);
    let ((ip, ifacets), (rp, rfacets)) = (i.parts(), r.parts());
    let (before, after) = changed((ip, ifacets, i_in), (rp, rfacets, r_in));
    if !after.contains(&true) {
        return Verdict::Keep;
    }
    let smoothed = r.sites_near(&after);
    let smoothed_counts = smoothed.counts();
    if !smoothed_counts.any() {
        return Verdict::Keep;
    }
    let unsmoothed = i.sites_near(&before);
    let input_counts = unsmoothed.counts();
    let overall_worse = worse(smoothed_counts, || input_counts);
    let places = Places::new((ip, ifacets, &before), (rp, rfacets, &after));
    let otherwise = || {
        if !overall_worse {
            return Verdict::Keep;
        }
        Verdict::Input(SmoothReport {
            tolerance: report.tolerance,
            reverted: Some(Reverted {
                smoothed: smoothed_counts,
                input: input_counts,
                counts: report.counts,
                places: places.count,
                undone: places.count,
            }),
            ..SmoothReport::default()
        })
    };
    let (Some(at_result), Some(at_input)) = (
        places.attribute(&smoothed, rp, &places.result),
        places.attribute(&unsmoothed, ip, &places.input),
    ) else {
        return otherwise();
    };
    let undo: Vec<bool> = at_result
        .iter()
        .zip(&at_input)
        .map(|(s, u)| s.worse_than(u))
        .collect();
    let undone = undo.iter().filter(|&&u| u).count();
    if undone == 0 || undone == places.count {
        return otherwise();
    }
    let at =
        |of: &[u32]| -> Vec<bool> { of.iter().map(|&p| p != NONE && undo[p as usize]).collect() };
    let Some((mixed, focus)) = mix(r, &at(&places.result), &after, i, &at(&places.input)) else {
        return otherwise();
    };
    // The mixed mesh near everything that changed, against what would be
    // returned otherwise.
    let fallback = if overall_worse {
        input_counts
    } else {
        smoothed_counts
    };
    if mixed.sites_near(&focus).counts().worse_than(&fallback) {
        return otherwise();
    }
    let sum = |per: &[MeshDefects]| {
        per.iter()
            .zip(&undo)
            .filter(|(_, &u)| u)
            .fold(MeshDefects::default(), |a, (d, _)| MeshDefects {
                intersecting_pairs: a.intersecting_pairs + d.intersecting_pairs,
                non_manifold_edges: a.non_manifold_edges + d.non_manifold_edges,
                non_manifold_vertices: a.non_manifold_vertices + d.non_manifold_vertices,
                open_edges: a.open_edges + d.open_edges,
            })
    };
    let kept = SmoothReport {
        reverted: Some(Reverted {
            smoothed: sum(&at_result),
            input: sum(&at_input),
            counts: report.counts,
            places: places.count,
            undone,
        }),
        ..report.clone()
    };
    Verdict::Mixed(mixed, kept)
}

/// No place: a facet that did not change.
const NONE: u32 = u32::MAX;

/// The places smoothing changed: the changed facets of both meshes,
/// joined into connected patches where they share a vertex position.
struct Places {
    /// The place of every input facet (`NONE` when unchanged).
    input: Vec<u32>,
    /// The place of every result facet.
    result: Vec<u32>,
    /// The place of every corner position of a changed facet.
    at: FxHashMap<[u64; 3], u32>,
    /// The number of places.
    count: usize,
}

/// The root of `x` in a union-find forest, halving the path.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

impl Places {
    fn new<B: Facets + ?Sized, A: Facets + ?Sized>(
        before: (&[Point3], &B, &[bool]),
        after: (&[Point3], &A, &[bool]),
    ) -> Places {
        // Union-find over the changed facets (input, then result) and the
        // positions of their corners.
        let mut parent: Vec<u32> = Vec::new();
        let mut node_of_pos: FxHashMap<[u64; 3], u32> = FxHashMap::default();
        let mut join = |parent: &mut Vec<u32>, pos: &[Point3], starts: Vec<u32>| -> u32 {
            let node = parent.len() as u32;
            parent.push(node);
            for v in starts {
                let key = pos[v as usize].map(f64::to_bits);
                let p = *node_of_pos.entry(key).or_insert_with(|| {
                    parent.push(parent.len() as u32);
                    parent.len() as u32 - 1
                });
                let (x, y) = (find(parent, node), find(parent, p));
                parent[x as usize] = y;
            }
            node
        };
        let (bp, bf, bmask) = before;
        let (ap, af, amask) = after;
        let input_nodes: Vec<(usize, u32)> = (0..bf.count())
            .filter(|&f| bmask[f])
            .map(|f| (f, join(&mut parent, bp, bf.starts(f).collect())))
            .collect();
        let result_nodes: Vec<(usize, u32)> = (0..af.count())
            .filter(|&f| amask[f])
            .map(|f| (f, join(&mut parent, ap, af.starts(f).collect())))
            .collect();
        // Roots numbered in order of first appearance.
        let mut place_of_root: FxHashMap<u32, u32> = FxHashMap::default();
        let mut place = |parent: &mut Vec<u32>, node: u32| {
            let root = find(parent, node);
            let next = place_of_root.len() as u32;
            *place_of_root.entry(root).or_insert(next)
        };
        let mut input = vec![NONE; bf.count()];
        for (f, node) in input_nodes {
            input[f] = place(&mut parent, node);
        }
        let mut result = vec![NONE; af.count()];
        for (f, node) in result_nodes {
            result[f] = place(&mut parent, node);
        }
        let at = node_of_pos
            .into_iter()
            .map(|(k, node)| (k, place(&mut parent, node)))
            .collect();
        Places {
            input,
            result,
            at,
            count: place_of_root.len(),
        }
    }

    /// Each place's defects among `sites` of a mesh (positions `pos`, the
    /// place of each facet `of_facet`): a facet pair counts at the places
    /// of its changed facets, an edge or vertex at the place of its
    /// position. `None` when a site lies at no place (the guard then
    /// undoes everything).
    fn attribute(
        &self,
        sites: &Sites,
        pos: &[Point3],
        of_facet: &[u32],
    ) -> Option<Vec<MeshDefects>> {
        let mut per = vec![MeshDefects::default(); self.count];
        for pair in &sites.pairs {
            let places = pair.map(|f| of_facet.get(f as usize).copied().unwrap_or(NONE));
            if places == [NONE; 2] {
                return None;
            }
            for (k, &p) in places.iter().enumerate() {
                if p != NONE && (k == 0 || p != places[0]) {
                    per[p as usize].intersecting_pairs += 1;
                }
            }
        }
        let of_vertex = |v: u32| {
            pos.get(v as usize)
                .and_then(|p| self.at.get(&p.map(f64::to_bits)))
                .copied()
        };
        let of_edge = |a: u32, b: u32| of_vertex(a).or_else(|| of_vertex(b));
        let m = &sites.manifold;
        for e in &m.non_manifold_edges {
            per[of_edge(e.a, e.b)? as usize].non_manifold_edges += 1;
        }
        for e in &m.open_edges {
            per[of_edge(e.a, e.b)? as usize].open_edges += 1;
        }
        for &v in &m.non_manifold_vertices {
            per[of_vertex(v)? as usize].non_manifold_vertices += 1;
        }
        Some(per)
    }
}

/// The result `r` with its facets `drop` replaced by the input's facets
/// `restore`, each input vertex taken to the vertex of the kept facets at
/// its position or appended; and the focus of the mixed mesh (its facets
/// that changed: the kept changed ones, `after`, and the restored ones).
/// `None` when positions do not name vertices one to one (two input
/// vertices of the restored facets at one kept vertex, or two result
/// vertices at one position) or the mixed mesh is not closed.
fn mix<M: Guarded>(
    r: &M,
    drop: &[bool],
    after: &[bool],
    i: &M,
    restore: &[bool],
) -> Option<(M, Vec<bool>)> {
    let ((rp, rf), (ip, ifacets)) = (r.parts(), i.parts());
    let bits = |p: &Point3| p.map(f64::to_bits);
    let mut at: FxHashMap<[u64; 3], u32> = FxHashMap::default();
    at.reserve(rp.len());
    for (v, p) in rp.iter().enumerate() {
        if at.insert(bits(p), v as u32).is_some() {
            return None;
        }
    }
    let mut vertices = rp.to_vec();
    let mut facets: Vec<Vec<(u32, u32)>> = Vec::with_capacity(rf.count());
    let mut focus = Vec::with_capacity(rf.count());
    let mut kept_uses = vec![false; rp.len()];
    for f in (0..rf.count()).filter(|&f| !drop[f]) {
        facets.push(rf.half_edges(f).collect());
        focus.push(after[f]);
        for v in rf.starts(f) {
            kept_uses[v as usize] = true;
        }
    }
    // An input vertex at the position of a vertex the kept facets use is
    // that vertex (the cut between a place and the rest); any other is a
    // vertex of its own, so coincident input vertices that smoothing
    // welded come back apart (their position is the place's alone, as
    // every facet there changed).
    let mut taken: FxHashMap<u32, u32> = FxHashMap::default();
    let mut owner: FxHashMap<[u64; 3], u32> = FxHashMap::default();
    let mut name = |v: u32, vertices: &mut Vec<Point3>| -> Option<u32> {
        if let Some(&u) = taken.get(&v) {
            return Some(u);
        }
        let key = bits(&ip[v as usize]);
        let u = match at.get(&key) {
            Some(&u) if kept_uses[u as usize] => {
                if *owner.entry(key).or_insert(v) != v {
                    return None;
                }
                u
            }
            _ => {
                vertices.push(ip[v as usize]);
                vertices.len() as u32 - 1
            }
        };
        taken.insert(v, u);
        Some(u)
    };
    for f in (0..ifacets.count()).filter(|&f| restore[f]) {
        let mut half_edges = Vec::new();
        for (s, e) in ifacets.half_edges(f) {
            half_edges.push((name(s, &mut vertices)?, name(e, &mut vertices)?));
        }
        facets.push(half_edges);
        focus.push(true);
    }
    // Vertices no facet uses any more are dropped, the rest renumbered in
    // order.
    let mut used = vec![false; vertices.len()];
    for &(s, e) in facets.iter().flatten() {
        used[s as usize] = true;
        used[e as usize] = true;
    }
    let mut map = vec![u32::MAX; vertices.len()];
    let mut kept = Vec::with_capacity(vertices.len());
    for (v, p) in vertices.into_iter().enumerate() {
        if used[v] {
            map[v] = kept.len() as u32;
            kept.push(p);
        }
    }
    for h in facets.iter_mut().flatten() {
        *h = (map[h.0 as usize], map[h.1 as usize]);
    }
    Some((M::closed_mesh(kept, facets)?, focus))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_clean_result_is_kept_without_looking_at_the_input() {
        assert!(!worse(MeshDefects::default(), || {
            panic!("the input is not inspected when the result is clean")
        }));
    }

    #[test]
    fn a_worse_result_is_undone() {
        let pinch = MeshDefects {
            non_manifold_vertices: 1,
            ..MeshDefects::default()
        };
        let pairs = MeshDefects {
            intersecting_pairs: 2,
            ..MeshDefects::default()
        };
        // Fewer pairs than the input had: kept, also at the price of a
        // pinch.
        let five = MeshDefects {
            intersecting_pairs: 5,
            ..pairs
        };
        assert!(!worse(pairs, || five));
        assert!(!worse(pinch, || pairs));
        // A pinch the clean input did not have: undone.
        assert!(worse(pinch, MeshDefects::default));
        // More pairs: undone even if the input had a pinch.
        let more = MeshDefects {
            intersecting_pairs: 1,
            ..MeshDefects::default()
        };
        assert!(worse(more, || pinch));
    }

    #[test]
    fn changed_facets_are_found_by_position_whatever_the_numbering() {
        let before_pos = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let before: Vec<[u32; 3]> = vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2], [0, 1, 3]];
        // The same positions numbered backwards; the third triangle moved
        // to a new vertex, one copy of the doubled one gone.
        let after_pos = [
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
        ];
        let after: Vec<[u32; 3]> = vec![[3, 1, 2], [2, 0, 3], [2, 1, 4], [0, 1, 3]];
        let all = |n: usize| vec![true; n];
        let (b, a) = changed(
            (&before_pos, before.as_slice(), &all(5)),
            (&after_pos, after.as_slice(), &all(4)),
        );
        assert_eq!(a, vec![false, false, true, false]);
        assert_eq!(b.iter().filter(|&&c| c).count(), 2);
        assert!(b[2] && (b[1] ^ b[4]));
        // Outside the candidates nothing is looked at.
        let (b, a) = changed(
            (
                &before_pos,
                before.as_slice(),
                &[false, false, true, false, false],
            ),
            (&after_pos, after.as_slice(), &[false, false, true, false]),
        );
        assert_eq!(
            (b, a),
            (
                vec![false, false, true, false, false],
                vec![false, false, true, false]
            )
        );
    }

    /// A fuzzing find: two unit cubes at one place (sixteen vertices),
    /// smoothed at a tolerance far below their size. Merging welds the
    /// coincident vertices and changes no facet's positions, so matching
    /// facets by position alone saw no change and kept a result with
    /// twelve edges used four times each; the vertex counts per position
    /// now mark those facets changed, and the guard hands the input back.
    #[test]
    fn both_ways_of_listing_corners_agree() {
        let mut rng = test_support::rng::SplitMix64::new(21);
        for n in [1usize, 7, 100, 3000] {
            let tris: Vec<[u32; 3]> = (0..2 * n)
                .map(|_| std::array::from_fn(|_| (rng.unit() * n as f64) as u32 % n as u32))
                .collect();
            for keep in [0.0, 0.01, 0.3, 1.0] {
                let ids: Vec<usize> = (0..tris.len()).filter(|_| rng.unit() < keep).collect();
                let sorted = sorted_corners(tris.as_slice(), &ids);
                assert_eq!(sorted, flagged_corners(n, tris.as_slice(), &ids));
                assert_eq!(sorted, distinct_corners(n, tris.as_slice(), &ids));
            }
        }
    }

    #[test]
    fn welding_coincident_vertices_is_a_change_the_guard_sees() {
        use crate::{smooth_mesh, SmoothOptions};
        // Two unit cubes at one place, each with its own vertices.
        let (mut vertices, mut facets) = (Vec::new(), Vec::new());
        for _ in 0..2 {
            test_support::shapes::push_box(&mut vertices, &mut facets, [0.0; 3], [1.0; 3], false);
        }
        let m = PolygonMesh::new(vertices, facets);
        let manifold = |m: &PolygonMesh| m.manifold_report().unwrap().non_manifold_edges.len();
        let tol = 2f64.powi(-48);
        let plain = smooth_mesh(&m, &SmoothOptions::new(tol)).unwrap();
        assert_eq!(plain.report.counts.vertices_merged, 8);
        assert_eq!(manifold(&plain.shape), 12);
        let guarded = smooth_mesh(&m, &SmoothOptions::new(tol).guarded()).unwrap();
        assert_eq!(guarded.shape, m);
        let undone = guarded.report.reverted.unwrap();
        assert_eq!(undone.smoothed.non_manifold_edges, 12);
        assert_eq!(undone.input.non_manifold_edges, 0);
    }
}
