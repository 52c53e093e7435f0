//! The position phases of 3D smoothing (Appendix A): vertex adjustment
//! (merging within `delta`), edge cracking between edges (once, over the
//! edges left after merging) and edge cracking by vertex (to a fixpoint,
//! over a vertex set that no longer changes). After [`crack_between_edges`]
//! no vertex is created or moved again: that is what makes the later
//! phases terminate (see the algorithm note `docs/algorithms/smooth.md`).

use crate::mesh::geom::{dist2, lerp, point_segment, segment_segment};
use crate::mesh::index::{
    grown_box, near_segment_pairs_marked, near_segment_pairs_where, BoxIndex, IdBox,
};
use crate::mesh::structure::{Origin, Work};
use crate::{merge_vertices, SmoothCounts};
use rayon::prelude::*;
use rustc_hash::FxHashSet;
use std::collections::HashMap;
use topology::Point3;

/// Vertex adjustment: every referenced vertex within `delta` of an earlier
/// accepted one is merged into it ([`merge_vertices`]); afterwards any two
/// referenced vertices lie more than `delta` apart.
pub(crate) fn merge_phase(w: &mut Work, delta: f64, counts: &mut SmoothCounts) {
    let referenced = w.referenced();
    let ids: Vec<u32> = (0..w.pos.len() as u32)
        .filter(|&v| referenced[v as usize])
        .collect();
    let pts: Vec<Point3> = ids.iter().map(|&v| w.pos[v as usize]).collect();
    let m = merge_vertices(&pts, delta);
    if m.merged == 0 {
        return;
    }
    let mut map: Vec<u32> = (0..w.pos.len() as u32).collect();
    for (local, &rep) in m.representative.iter().enumerate() {
        let (v, r) = (ids[local], ids[rep as usize]);
        if v != r {
            map[v as usize] = r;
            // The merged vertex moved (at most delta) onto r.
            w.adjustments[r as usize] = w.adjustments[r as usize].max(1);
        }
    }
    for r in w.representative.iter_mut() {
        *r = map[*r as usize];
    }
    w.rename(&map);
    counts.vertices_merged += m.merged;
}

/// The segment each current edge descends from (its end points when
/// cracking began); an edge missing here is its own root.
pub(crate) type Roots = rustc_hash::FxHashMap<(u32, u32), (Point3, Point3)>;

fn root_of(w: &Work, roots: &Roots, (a, b): (u32, u32)) -> (Point3, Point3) {
    roots
        .get(&(a, b))
        .copied()
        .unwrap_or((w.pos[a as usize], w.pos[b as usize]))
}

/// Whether splitting edge `(a, b)` at `p` gives two strictly shorter
/// edges and keeps `p` within `reach` of the edge's root.
fn may_split(w: &Work, roots: &Roots, e: (u32, u32), p: Point3, reach: f64) -> bool {
    let (pa, pb) = (w.pos[e.0 as usize], w.pos[e.1 as usize]);
    let l2 = dist2(pa, pb);
    let (ra, rb) = root_of(w, roots, e);
    dist2(pa, p) < l2 && dist2(p, pb) < l2 && point_segment(p, ra, rb).1 <= reach * reach
}

/// Applies `splits`, gives every sub-edge its parent's root and returns
/// the sub-edges.
fn split_with_roots(
    w: &mut Work,
    roots: &mut Roots,
    splits: HashMap<(u32, u32), Vec<u32>>,
) -> Vec<(u32, u32)> {
    // In edge order, not the map's (which varies from run to run): a
    // sub-edge two split edges share gets the root of the smaller edge,
    // and the sub-edges come back in one order.
    let mut parents: Vec<((u32, u32), (Point3, Point3))> =
        splits.keys().map(|&e| (e, root_of(w, roots, e))).collect();
    parents.sort_unstable_by_key(|p| p.0);
    let chains = w.split_edges(splits);
    let mut subs = Vec::new();
    for (e, root) in parents {
        let Some(chain) = chains.get(&e) else {
            continue;
        };
        let mut prev = e.0;
        for &v in chain.iter().chain(std::iter::once(&e.1)) {
            let key = (prev.min(v), prev.max(v));
            roots.entry(key).or_insert(root);
            subs.push(key);
            prev = v;
        }
    }
    subs
}

/// Edge cracking between edges over the current edges: two edges with
/// four distinct vertices whose interiors pass within `delta` of each
/// other (with every end point farther than `delta` from the other edge:
/// closer ends are cracking by vertex's business) are both split at a
/// vertex at the mid-point of their closest points, snapped to an existing
/// vertex within `delta` or merged with an earlier created one. An edge
/// is split only into strictly shorter edges and at a point within `1.5
/// delta` of its root; a crack point failing that for either edge is not
/// created.
///
/// With `only`, just the pairs with an edge in that set are tested: the
/// edges made (or given a root) since the previous call. That is exact:
/// a pair of edges neither of which changed since then has the same end
/// points and roots, so the same test result; if it passed then and was
/// not split, its crack point was snapped to the earliest accepted point
/// within `delta` (`merge_vertices`), which is still the earliest now
/// (existing vertices come first, and the vertices created since are
/// later in order than it or were accepted after it), and neither edge
/// may split there, as before; such a point, never accepted, changes no
/// other point's snapping.
///
/// Returns the number of edge pairs cracked and the edges the splits made
/// (or gave a root).
pub(crate) fn crack_between_edges(
    w: &mut Work,
    delta: f64,
    counts: &mut SmoothCounts,
    roots: &mut Roots,
    only: Option<&FxHashSet<(u32, u32)>>,
) -> (u64, Vec<(u32, u32)>) {
    if delta <= 0.0 {
        return (0, Vec::new()); // exact crossings are the Boolean's business
    }
    let edges = w.edges();
    if edges.len() < 2 {
        return (0, Vec::new());
    }
    let reach = 1.5 * delta;
    let d2max = delta * delta;
    // Candidates by pieces of long edges (`near_segment_pairs`): every
    // pair within `delta` of each other is among them.
    let ends: Vec<(Point3, Point3)> = edges
        .iter()
        .map(|&(a, b)| (w.pos[a as usize], w.pos[b as usize]))
        .collect();
    // (edge i, edge j, crack point, the four end points)
    let w_ref: &Work = w;
    let roots_ref: &Roots = roots;
    let filter = |i: u32, j: u32| {
        let (i, j) = (i as usize, j as usize);
        let (a, b) = edges[i];
        let (pa, pb) = (w_ref.pos[a as usize], w_ref.pos[b as usize]);
        let (c, d) = edges[j];
        if c == a || c == b || d == a || d == b {
            return None;
        }
        let (pc, pd) = (w_ref.pos[c as usize], w_ref.pos[d as usize]);
        let (s, t, c1, c2) = segment_segment(pa, pb, pc, pd);
        if !(s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) || dist2(c1, c2) > d2max {
            return None;
        }
        let near_end = point_segment(pa, pc, pd).1 <= d2max
            || point_segment(pb, pc, pd).1 <= d2max
            || point_segment(pc, pa, pb).1 <= d2max
            || point_segment(pd, pa, pb).1 <= d2max;
        if near_end {
            return None;
        }
        let p = lerp(c1, c2, 0.5);
        if !may_split(w_ref, roots_ref, edges[i], p, reach)
            || !may_split(w_ref, roots_ref, edges[j], p, reach)
        {
            return None;
        }
        Some((i, j, p, [pa, pb, pc, pd]))
    };
    let mut found: Vec<(usize, usize, Point3, [Point3; 4])> = match only {
        None => near_segment_pairs_where(&ends, delta, filter),
        Some(set) => {
            let marked: Vec<bool> = edges.iter().map(|e| set.contains(e)).collect();
            near_segment_pairs_marked(&ends, delta, &marked, filter)
        }
    };
    found.sort_by_key(|f| (f.0, f.1));
    if found.is_empty() {
        return (0, Vec::new());
    }
    // Snap: existing referenced vertices first (pairwise farther than
    // delta apart after merging, so they stay), then the crack points in
    // order; a crack point goes to the earliest accepted point within
    // delta.
    let referenced = w.referenced();
    let existing: Vec<u32> = (0..w.pos.len() as u32)
        .filter(|&v| referenced[v as usize])
        .collect();
    let mut pts: Vec<Point3> = existing.iter().map(|&v| w.pos[v as usize]).collect();
    pts.extend(found.iter().map(|f| f.2));
    let m = merge_vertices(&pts, delta);
    let n_existing = existing.len();
    let mut created: HashMap<usize, u32> = HashMap::new();
    let mut splits: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
    let mut cracked = 0;
    for (k, &(i, j, p, ends)) in found.iter().enumerate() {
        let rep = m.representative[n_existing + k] as usize;
        let v = if rep < n_existing {
            existing[rep]
        } else if rep == n_existing + k {
            // Accepted: both edges may split at p (checked above).
            let v = w.add_vertex(p, Origin::Created(ends));
            counts.vertices_created += 1;
            created.insert(rep, v);
            v
        } else {
            created[&rep]
        };
        let q = w.pos[v as usize];
        let mut any = false;
        for e in [edges[i], edges[j]] {
            if v != e.0 && v != e.1 && may_split(w, roots, e, q, reach) {
                splits.entry(e).or_default().push(v);
                any = true;
            }
        }
        if any {
            cracked += 1;
            if rep != n_existing + k {
                // Snapped or merged: one more adjustment touches v.
                let k_v = &mut w.adjustments[v as usize];
                *k_v = (*k_v + 1).min(2);
            }
        }
    }
    // Several crack points on one edge: keep the chain only if all its
    // sub-edges are shorter than the edge, else the first point alone.
    for (e, vs) in splits.iter_mut() {
        vs.sort_unstable();
        vs.dedup();
        if vs.len() > 1 {
            let (pa, pb) = (w.pos[e.0 as usize], w.pos[e.1 as usize]);
            let l2 = dist2(pa, pb);
            let mut keyed: Vec<(f64, u32)> = vs
                .iter()
                .map(|&v| (crate::mesh::geom::projection(w.pos[v as usize], pa, pb), v))
                .collect();
            keyed.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
            let mut chain = vec![pa];
            chain.extend(keyed.iter().map(|k| w.pos[k.1 as usize]));
            chain.push(pb);
            if !chain.windows(2).all(|s| dist2(s[0], s[1]) < l2) {
                vs.truncate(1);
            }
        }
    }
    counts.edges_cracked_between_edges += cracked;
    let subs = split_with_roots(w, roots, splits);
    (cracked, subs)
}

/// What [`crack_by_vertex`] did.
#[derive(Default)]
pub(crate) struct ByVertex {
    /// The rounds that split something.
    pub rounds: u32,
    /// Whether the budget stopped it before a fixpoint.
    pub budget_hit: bool,
    /// The edges its splits made (or gave a root).
    pub made: Vec<(u32, u32)>,
}

/// An edge's crack candidates: (parameter along the edge, squared
/// distance, vertex).
type Candidates = Vec<(f64, f64, u32)>;

/// Edge cracking by vertex, in rounds to a fixpoint: an edge whose
/// interior passes within `delta` of a vertex (not its end) is split at
/// it, provided both new edges are shorter than the edge (Appendix A).
/// No vertex moves; the sub-edges inherit the edge's root (for edge-edge
/// cracking's reach). Every qualifying vertex of an edge is taken at once
/// when the chain's sub-edges are all shorter than the edge, else the
/// nearest one. Each split replaces an edge by strictly shorter edges
/// between vertices of a fixed set: the multiset of edge lengths decreases,
/// so the rounds end. Stops early, before a fixpoint, when `budget` says
/// so.
///
/// With `since = (changed, first_new)`, the previous call ended at a
/// fixpoint, after which the edges in `changed` were made (or given a
/// root) and the vertices from `first_new` on were created: every other
/// edge was found to have no candidate among the vertices before
/// `first_new`, none of which has moved, so its first-round candidates are
/// looked for among the new vertices only (exact, and cheap when they are
/// few).
pub(crate) fn crack_by_vertex(
    w: &mut Work,
    delta: f64,
    counts: &mut SmoothCounts,
    mut over_budget: impl FnMut(&SmoothCounts) -> bool,
    roots: &mut Roots,
    since: Option<(&FxHashSet<(u32, u32)>, u32)>,
    mut after_round: impl FnMut(&Work) -> Result<(), crate::SmoothError>,
) -> Result<ByVertex, crate::SmoothError> {
    let mut made = Vec::new();
    if delta <= 0.0 {
        return Ok(ByVertex::default());
    }
    let d2max = delta * delta;
    let referenced = w.referenced();
    let points: Vec<(Point3, u32)> = (0..w.pos.len() as u32)
        .filter(|&v| referenced[v as usize])
        .map(|v| (w.pos[v as usize], v))
        .collect();
    let index = BoxIndex::new(
        points
            .iter()
            .map(|&(p, id)| IdBox { lo: p, hi: p, id })
            .collect(),
    );
    // The vertices created since the previous fixpoint, when given.
    let fresh = since.map(|(_, first_new)| {
        BoxIndex::new(
            points
                .iter()
                .filter(|&&(_, id)| id >= first_new)
                .map(|&(p, id)| IdBox { lo: p, hi: p, id })
                .collect(),
        )
    });
    let mut todo = w.edges();
    let mut rounds = 0;
    while !todo.is_empty() {
        if over_budget(counts) {
            return Ok(ByVertex {
                rounds,
                budget_hit: true,
                made,
            });
        }
        // In the first round after a fixpoint, an unchanged edge looks
        // among the new vertices only.
        let first_round = rounds == 0;
        let index_of = |e: &(u32, u32)| match (since, &fresh) {
            (Some((changed, _)), Some(fresh)) if first_round && !changed.contains(e) => fresh,
            _ => &index,
        };
        let mut splits: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        let mut inserted = 0u64;
        // The candidate vertices of each edge: those in its grown box
        // whose projection falls inside and within delta, and that leave
        // both parts shorter than the edge (queries and tests in
        // parallel, answers in edge order; edges without candidates are
        // dropped).
        let found: Vec<(usize, Candidates)> = todo
            .par_iter()
            .enumerate()
            .filter_map(|(e, &(a, b))| {
                let (pa, pb) = (w.pos[a as usize], w.pos[b as usize]);
                let l2 = dist2(pa, pb);
                let (lo, hi) = grown_box([pa, pb], delta);
                let mut cands: Candidates = Vec::new();
                index_of(&(a, b)).visit(&lo, &hi, |v| {
                    if v == a || v == b {
                        return;
                    }
                    let p = w.pos[v as usize];
                    let (t, d2) = point_segment(p, pa, pb);
                    if !(t > 0.0 && t < 1.0) || d2 > d2max {
                        return;
                    }
                    if dist2(pa, p) >= l2 || dist2(p, pb) >= l2 {
                        return;
                    }
                    cands.push((t, d2, v));
                });
                (!cands.is_empty()).then_some((e, cands))
            })
            .collect();
        for (e, mut cands) in found {
            let (a, b) = todo[e];
            let (pa, pb) = (w.pos[a as usize], w.pos[b as usize]);
            let l2 = dist2(pa, pb);
            cands.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.2.cmp(&y.2)));
            let mut chain: Vec<Point3> = vec![pa];
            chain.extend(cands.iter().map(|c| w.pos[c.2 as usize]));
            chain.push(pb);
            let all_shorter = chain.windows(2).all(|s| dist2(s[0], s[1]) < l2);
            let chosen: Vec<u32> = if all_shorter {
                cands.iter().map(|c| c.2).collect()
            } else {
                let best = cands
                    .iter()
                    .min_by(|x, y| x.1.total_cmp(&y.1).then(x.2.cmp(&y.2)))
                    .map(|c| c.2);
                best.into_iter().collect()
            };
            inserted += chosen.len() as u64;
            splits.insert((a, b), chosen);
        }
        if splits.is_empty() {
            break;
        }
        rounds += 1;
        counts.edges_cracked_by_vertex += inserted;
        // The sub-edges are checked next round; every other edge is
        // unchanged and was found uncrackable.
        let mut next = split_with_roots(w, roots, splits);
        next.sort_unstable();
        next.dedup();
        made.extend_from_slice(&next);
        todo = next;
        after_round(w)?;
    }
    Ok(ByVertex {
        rounds,
        budget_hit: false,
        made,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use topology::{Facet, PolygonMesh};

    /// Two edges split at one vertex share a sub-edge; it takes the root
    /// of the smaller edge and the sub-edges come back in one order,
    /// whatever order the map of splits iterates in (it varies from map to
    /// map: `std`'s hasher is seeded per map). Before, `umbra smooth` of a
    /// million-triangle Boolean result at a coarse tolerance could differ
    /// from run to run.
    #[test]
    fn shared_sub_edges_do_not_depend_on_the_map_order() {
        let v = vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 0.1, 0.0],
            [1.0, 0.05, 0.0],
        ];
        let mesh = PolygonMesh::new(
            v.clone(),
            vec![Facet::from_loop(&[0, 1, 2]), Facet::from_loop(&[0, 2, 1])],
        );
        let mut answers = std::collections::HashSet::new();
        for k in 0..64 {
            let mut w = Work::from_mesh(&mesh);
            let mut roots = Roots::default();
            let mut splits: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
            // Both insertion orders, and fresh hasher seeds each time.
            if k % 2 == 0 {
                splits.insert((0, 1), vec![3]);
                splits.insert((0, 2), vec![3]);
            } else {
                splits.insert((0, 2), vec![3]);
                splits.insert((0, 1), vec![3]);
            }
            let subs = split_with_roots(&mut w, &mut roots, splits);
            assert_eq!(roots[&(0, 3)], (v[0], v[1]));
            answers.insert(format!("{subs:?}"));
        }
        assert_eq!(answers.len(), 1, "{answers:?}");
    }
}
