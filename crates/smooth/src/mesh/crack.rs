//! The position phases of 3D smoothing (Appendix A): vertex adjustment
//! (merging within `delta`), edge cracking between edges (once, over the
//! edges left after merging) and edge cracking by vertex (to a fixpoint,
//! over a vertex set that no longer changes). After [`crack_between_edges`]
//! no vertex is created or moved again: that is what makes the later
//! phases terminate (see the algorithm note `docs/algorithms/smooth.md`).

use crate::mesh::geom::{dist2, lerp, point_segment, segment_segment};
use crate::mesh::index::{grown_box, BoxIndex, IdBox, PointIndex};
use crate::mesh::structure::{Origin, Work};
use crate::{merge_vertices, SmoothCounts};
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

/// Edge cracking between edges, once over the current edges: two edges
/// with four distinct vertices whose interiors pass within `delta` of each
/// other (with every end point farther than `delta` from the other edge:
/// closer ends are cracking by vertex's business) are both split at a
/// vertex at the mid-point of their closest points, snapped to an existing
/// vertex within `delta` or merged with an earlier created one.
pub(crate) fn crack_between_edges(w: &mut Work, delta: f64, counts: &mut SmoothCounts) {
    if delta <= 0.0 {
        return; // exact crossings are the Boolean's business
    }
    let edges = w.edges();
    if edges.len() < 2 {
        return;
    }
    let d2max = delta * delta;
    let boxes = edges
        .iter()
        .enumerate()
        .map(|(i, &(a, b))| {
            let (lo, hi) = grown_box([w.pos[a as usize], w.pos[b as usize]], delta);
            IdBox {
                lo,
                hi,
                id: i as u32,
            }
        })
        .collect();
    let index = BoxIndex::new(boxes);
    // (edge i, edge j, crack point, the four end points)
    let mut found: Vec<(usize, usize, Point3, [Point3; 4])> = Vec::new();
    for (i, &(a, b)) in edges.iter().enumerate() {
        let (pa, pb) = (w.pos[a as usize], w.pos[b as usize]);
        let (lo, hi) = grown_box([pa, pb], 0.0);
        for j in index.meeting(lo, hi) {
            let j = j as usize;
            if j <= i {
                continue;
            }
            let (c, d) = edges[j];
            if c == a || c == b || d == a || d == b {
                continue;
            }
            let (pc, pd) = (w.pos[c as usize], w.pos[d as usize]);
            let (s, t, c1, c2) = segment_segment(pa, pb, pc, pd);
            if !(s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) || dist2(c1, c2) > d2max {
                continue;
            }
            let near_end = point_segment(pa, pc, pd).1 <= d2max
                || point_segment(pb, pc, pd).1 <= d2max
                || point_segment(pc, pa, pb).1 <= d2max
                || point_segment(pd, pa, pb).1 <= d2max;
            if near_end {
                continue;
            }
            found.push((i, j, lerp(c1, c2, 0.5), [pa, pb, pc, pd]));
        }
    }
    if found.is_empty() {
        return;
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
    for (k, &(i, j, p, ends)) in found.iter().enumerate() {
        let rep = m.representative[n_existing + k] as usize;
        let v = if rep < n_existing {
            let v = existing[rep];
            w.adjustments[v as usize] = w.adjustments[v as usize].max(1);
            v
        } else if rep == n_existing + k {
            let v = w.add_vertex(p, Origin::Created(ends));
            counts.vertices_created += 1;
            created.insert(rep, v);
            v
        } else {
            let v = created[&rep];
            w.adjustments[v as usize] = 2;
            v
        };
        splits.entry(edges[i]).or_default().push(v);
        splits.entry(edges[j]).or_default().push(v);
        counts.edges_cracked_between_edges += 1;
    }
    w.split_edges(splits);
}

/// Edge cracking by vertex, in rounds to a fixpoint: an edge whose
/// interior passes within `delta` of a vertex (not its end) is split at
/// it, provided both new edges are shorter than the edge (Appendix A) and
/// the vertex lies within `delta` of the edge the round-0 edge it descends
/// from (so that chains of cracks never carry an edge farther than `delta`
/// from where it was). Every qualifying vertex of an edge is taken at once
/// when the chain's sub-edges are all shorter than the edge, else the
/// nearest one. Each split replaces an edge by strictly shorter edges
/// between vertices of a fixed set: the multiset of edge lengths decreases,
/// so the rounds end. Returns the number of rounds that split something;
/// stops early (returning `true` as second value) when `budget` says so.
pub(crate) fn crack_by_vertex(
    w: &mut Work,
    delta: f64,
    counts: &mut SmoothCounts,
    mut over_budget: impl FnMut(&SmoothCounts) -> bool,
    mut after_round: impl FnMut(&Work) -> Result<(), crate::SmoothError>,
) -> Result<(u32, bool), crate::SmoothError> {
    if delta <= 0.0 {
        return Ok((0, false));
    }
    let d2max = delta * delta;
    let referenced = w.referenced();
    let index = PointIndex::new(
        (0..w.pos.len() as u32)
            .filter(|&v| referenced[v as usize])
            .map(|v| (w.pos[v as usize], v)),
    );
    let mut todo = w.edges();
    let mut roots: HashMap<(u32, u32), (Point3, Point3)> = HashMap::new();
    let mut rounds = 0;
    while !todo.is_empty() {
        if over_budget(counts) {
            return Ok((rounds, true));
        }
        let mut splits: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        let mut inserted = 0u64;
        for &(a, b) in &todo {
            let (pa, pb) = (w.pos[a as usize], w.pos[b as usize]);
            let (ra, rb) = roots.get(&(a, b)).copied().unwrap_or((pa, pb));
            let l2 = dist2(pa, pb);
            let (lo, hi) = grown_box([pa, pb], delta);
            let mut cands: Vec<(f64, f64, u32)> = Vec::new();
            for v in index.inside(lo, hi) {
                if v == a || v == b {
                    continue;
                }
                let p = w.pos[v as usize];
                let (t, d2) = point_segment(p, pa, pb);
                if !(t > 0.0 && t < 1.0) || d2 > d2max {
                    continue;
                }
                if dist2(pa, p) >= l2 || dist2(p, pb) >= l2 {
                    continue;
                }
                if point_segment(p, ra, rb).1 > d2max {
                    continue;
                }
                cands.push((t, d2, v));
            }
            if cands.is_empty() {
                continue;
            }
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
        let chains = w.split_edges(splits);
        let mut next = Vec::new();
        for ((a, b), chain) in chains {
            let root = roots
                .get(&(a, b))
                .copied()
                .unwrap_or((w.pos[a as usize], w.pos[b as usize]));
            let mut prev = a;
            for &v in chain.iter().chain(std::iter::once(&b)) {
                let key = (prev.min(v), prev.max(v));
                roots.entry(key).or_insert(root);
                next.push(key);
                prev = v;
            }
        }
        next.sort_unstable();
        next.dedup();
        todo = next;
        after_round(w)?;
    }
    Ok((rounds, false))
}
