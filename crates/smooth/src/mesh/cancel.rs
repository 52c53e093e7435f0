//! The cancellation operations of Appendix A: zero-length edge removal,
//! half-edge cancellation inside a facet, and facet cancellation in full
//! and in part by swapping the maximal subset of potentially-swappable
//! half-edges that forms closed loops (f1's half-edges with f2's
//! reversed; figure A.1). None of them creates or moves a vertex; each
//! keeps facet and shape boundary closure (section 4.2).

use crate::mesh::geom::{dot, lerp, point_segment};
use crate::mesh::index::{grown_box, opposed_pairs_where, BoxIndex, IdBox};
use crate::mesh::plane::{best_fit_plane, facet_normal, Plane};
use crate::mesh::structure::Work;
use crate::SmoothCounts;
use rayon::prelude::*;
use std::collections::btree_map::Entry;
use std::collections::{BTreeMap, HashMap, HashSet};
use topology::{HalfEdge, Point3};

/// Removes the facet's zero-length half-edges (each balances itself) and
/// cancels opposing half-edge pairs `a -> b`, `b -> a` (removing one of
/// each keeps both vertices balanced in the facet and the edge balanced in
/// the shape). Returns whether anything was removed.
pub(crate) fn cancel_in_facet(f: &mut Vec<HalfEdge>, counts: &mut SmoothCounts) -> bool {
    let before = f.len();
    f.retain(|h| h.start != h.end);
    counts.zero_length_edges_removed += (before - f.len()) as u64;
    let mut removed = vec![false; f.len()];
    let mut cancelled = 0u64;
    if f.len() <= 24 {
        for i in 0..f.len() {
            if removed[i] {
                continue;
            }
            for j in i + 1..f.len() {
                if !removed[j] && f[j].start == f[i].end && f[j].end == f[i].start {
                    removed[i] = true;
                    removed[j] = true;
                    cancelled += 1;
                    break;
                }
            }
        }
    } else {
        let mut open: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
        for i in 0..f.len() {
            let h = f[i];
            if let Some(j) = open.get_mut(&(h.end, h.start)).and_then(Vec::pop) {
                removed[i] = true;
                removed[j] = true;
                cancelled += 1;
            } else {
                open.entry((h.start, h.end)).or_default().push(i);
            }
        }
    }
    if cancelled > 0 {
        let mut k = 0;
        f.retain(|_| {
            k += 1;
            !removed[k - 1]
        });
        counts.half_edges_cancelled += cancelled;
    }
    f.len() != before
}

/// [`cancel_in_facet`] on every facet.
pub(crate) fn cancel_all(w: &mut Work, counts: &mut SmoothCounts) {
    cancel_all_marking(w, counts, &mut []);
}

/// [`cancel_all`], also setting `marks[f]` for every facet `f` it changes
/// (`marks` may be shorter than the facet list, even empty).
pub(crate) fn cancel_all_marking(w: &mut Work, counts: &mut SmoothCounts, marks: &mut [bool]) {
    for (f, (facet, changed)) in w.facets.iter_mut().zip(w.changed.iter_mut()).enumerate() {
        if cancel_in_facet(facet, counts) {
            *changed = true;
            if let Some(m) = marks.get_mut(f) {
                *m = true;
            }
        }
    }
}

/// The maximal subset of the directed edges `(from, to)` that forms
/// closed loops (every vertex entered as often as left): peel the edges
/// that cannot lie on a cycle (from a vertex nothing enters, or to a
/// vertex nothing leaves), walk from a remaining edge until a vertex
/// repeats, take that cycle out, and repeat. What remains when no edge is
/// left after peeling is acyclic, so no larger balanced subset exists (the
/// difference of two balanced subsets is balanced and would hold a
/// cycle). Peeling is incremental (a queue of vertices whose in- or
/// out-degree dropped to zero), so the whole is near-linear.
pub(crate) fn maximal_loops(edges: &[(u32, u32)]) -> Vec<bool> {
    let n = edges.len();
    let mut alive = vec![true; n];
    let mut chosen = vec![false; n];
    let mut outs: HashMap<u32, Vec<usize>> = HashMap::new();
    let mut ins: HashMap<u32, Vec<usize>> = HashMap::new();
    let mut out_deg: HashMap<u32, usize> = HashMap::new();
    let mut in_deg: HashMap<u32, usize> = HashMap::new();
    for (i, &(a, b)) in edges.iter().enumerate() {
        outs.entry(a).or_default().push(i);
        ins.entry(b).or_default().push(i);
        *out_deg.entry(a).or_default() += 1;
        *in_deg.entry(b).or_default() += 1;
        out_deg.entry(b).or_default();
        in_deg.entry(a).or_default();
    }
    let mut queue: Vec<u32> = {
        let mut q: Vec<u32> = out_deg.keys().copied().collect();
        q.sort_unstable();
        q
    };
    // Removes edge i from the live graph, queueing its ends.
    let remove = |i: usize,
                  alive: &mut [bool],
                  out_deg: &mut HashMap<u32, usize>,
                  in_deg: &mut HashMap<u32, usize>,
                  queue: &mut Vec<u32>| {
        alive[i] = false;
        let (a, b) = edges[i];
        *out_deg.get_mut(&a).expect("vertex of an edge") -= 1;
        *in_deg.get_mut(&b).expect("vertex of an edge") -= 1;
        queue.push(a);
        queue.push(b);
    };
    let mut cursor: HashMap<u32, usize> = HashMap::new();
    let mut next_start = 0;
    loop {
        // Peel.
        while let Some(v) = queue.pop() {
            if in_deg[&v] == 0 {
                for &i in outs.get(&v).map(Vec::as_slice).unwrap_or(&[]) {
                    if alive[i] {
                        remove(i, &mut alive, &mut out_deg, &mut in_deg, &mut queue);
                    }
                }
            }
            if out_deg[&v] == 0 {
                for &i in ins.get(&v).map(Vec::as_slice).unwrap_or(&[]) {
                    if alive[i] {
                        remove(i, &mut alive, &mut out_deg, &mut in_deg, &mut queue);
                    }
                }
            }
        }
        while next_start < n && !alive[next_start] {
            next_start += 1;
        }
        if next_start == n {
            return chosen;
        }
        // Every live vertex has a live out-edge: walk until a vertex
        // repeats, then take the cycle from its first visit.
        let first = next_start;
        let mut path: Vec<usize> = vec![first];
        let mut seen: HashMap<u32, usize> = HashMap::new();
        seen.insert(edges[first].0, 0);
        let mut at = edges[first].1;
        loop {
            if let Some(&k) = seen.get(&at) {
                for &i in &path[k..] {
                    chosen[i] = true;
                    remove(i, &mut alive, &mut out_deg, &mut in_deg, &mut queue);
                }
                break;
            }
            seen.insert(at, path.len());
            let list = outs.get(&at).map(Vec::as_slice).unwrap_or(&[]);
            let c = cursor.entry(at).or_default();
            while *c < list.len() && !alive[list[*c]] {
                *c += 1;
            }
            let Some(&next) = list.get(*c) else {
                // Not reachable after peeling; drop the edge into `at`.
                let last = path[path.len() - 1];
                remove(last, &mut alive, &mut out_deg, &mut in_deg, &mut queue);
                break;
            };
            path.push(next);
            at = edges[next].1;
        }
    }
}

/// Whether the half-edge `a b` lies in the interior of facet `f` in its
/// plane: the mid-point has winding number 1 and lies farther than
/// `delta / 2` from every half-edge of the facet (a mid-point on the
/// boundary is not in the interior).
fn in_interior(
    pos: &[Point3],
    plane: &Plane,
    f: &[HalfEdge],
    reach: &(Point3, Point3),
    a: Point3,
    b: Point3,
    delta: f64,
) -> bool {
    let m = lerp(a, b, 0.5);
    if (0..3).any(|k| m[k] < reach.0[k] || m[k] > reach.1[k]) {
        return false; // its projection misses the facet's projection
    }
    let lim = 0.25 * delta * delta;
    let on_boundary = f
        .iter()
        .any(|h| point_segment(m, pos[h.start as usize], pos[h.end as usize]).1 <= lim);
    !on_boundary && plane.winding(pos, f, m) == 1
}

/// The outcome of one facet pair.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum PairResult {
    Nothing,
    Partial,
    Full,
}

/// Facet cancellation between `i` and `j` (Appendix A), then half-edge
/// cancellation in both.
/// How many half-edges of `f` have both ends within `delta` of `p` (the
/// `near` test of [`cancel_pair`]), not counting those whose reverse is in
/// `other` when given (`cancel_pair` never takes such a half-edge of the
/// second facet). Fewer than two in both facets together close no loop
/// (no half-edge is a loop by itself: zero-length ones are gone before a
/// pass), so `cancel_pair` would find nothing.
fn swappable(
    pos: &[Point3],
    p: &Plane,
    f: &[HalfEdge],
    other: Option<&[HalfEdge]>,
    delta: f64,
) -> usize {
    f.iter()
        .filter(|h| {
            p.distance(pos[h.start as usize]).abs() <= delta
                && p.distance(pos[h.end as usize]).abs() <= delta
                && other.is_none_or(|o| !o.iter().any(|g| g.start == h.end && g.end == h.start))
        })
        .count()
}

fn cancel_pair(
    w: &mut Work,
    i: usize,
    j: usize,
    delta: f64,
    counts: &mut SmoothCounts,
) -> PairResult {
    let (f1, f2) = (&w.facets[i], &w.facets[j]);
    if f1.is_empty() || f2.is_empty() {
        return PairResult::Nothing;
    }
    let pos = &w.pos;
    let (Some(p1), Some(p2)) = (best_fit_plane(pos, f1), best_fit_plane(pos, f2)) else {
        return PairResult::Nothing;
    };
    if dot(p1.normal, p2.normal) >= 0.0 {
        return PairResult::Nothing;
    }
    let near = |p: &Plane, h: &HalfEdge| {
        p.distance(pos[h.start as usize]).abs() <= delta
            && p.distance(pos[h.end as usize]).abs() <= delta
    };
    // Only half-edges within `delta` of the other facet's plane can be
    // swapped: without any, nothing below applies (the usual case for
    // facets that merely face each other across a crease).
    if !f1.iter().any(|h| near(&p2, h)) && !f2.iter().any(|h| near(&p1, h)) {
        return PairResult::Nothing;
    }
    let in1: HashSet<(u32, u32)> = f1.iter().map(|g| (g.start, g.end)).collect();
    let in2: HashSet<(u32, u32)> = f2.iter().map(|g| (g.start, g.end)).collect();
    let counteracts = |h: &HalfEdge, other: &HashSet<(u32, u32)>| other.contains(&(h.end, h.start));
    // A mid-point within delta of a facet's plane whose projection lies in
    // the facet's projection is inside the facet's box grown by delta plus
    // the facet's largest vertex distance from its plane.
    let reach = |p: &Plane, f: &[HalfEdge]| {
        let warp = f
            .iter()
            .map(|h| p.distance(pos[h.start as usize]).abs())
            .fold(0.0, f64::max);
        grown_box(f.iter().map(|h| pos[h.start as usize]), delta + warp)
    };
    let (reach1, reach2) = (reach(&p1, f1), reach(&p2, f2));
    // Potentially swappable: (facet-local index, from f1?)
    let mut cand: Vec<(usize, bool)> = Vec::new();
    for (k, h) in f1.iter().enumerate() {
        if !near(&p2, h) {
            continue;
        }
        let (a, b) = (pos[h.start as usize], pos[h.end as usize]);
        if counteracts(h, &in2) || in_interior(pos, &p2, f2, &reach2, a, b, delta) {
            cand.push((k, true));
        }
    }
    for (k, h) in f2.iter().enumerate() {
        if !near(&p1, h) || counteracts(h, &in1) {
            continue;
        }
        let (a, b) = (pos[h.start as usize], pos[h.end as usize]);
        if in_interior(pos, &p1, f1, &reach1, a, b, delta) {
            cand.push((k, false));
        }
    }
    if cand.is_empty() {
        return PairResult::Nothing;
    }
    let directed: Vec<(u32, u32)> = cand
        .iter()
        .map(|&(k, first)| {
            if first {
                (f1[k].start, f1[k].end)
            } else {
                (f2[k].end, f2[k].start)
            }
        })
        .collect();
    let chosen = maximal_loops(&directed);
    if !chosen.iter().any(|&c| c) {
        return PairResult::Nothing;
    }
    let mut take1 = vec![false; f1.len()];
    let mut take2 = vec![false; f2.len()];
    for (&(k, first), &c) in cand.iter().zip(&chosen) {
        if c {
            if first {
                take1[k] = true;
            } else {
                take2[k] = true;
            }
        }
    }
    let split = |f: &[HalfEdge], take: &[bool]| {
        let (mut keep, mut give) = (Vec::new(), Vec::new());
        for (h, &t) in f.iter().zip(take) {
            if t {
                give.push(*h);
            } else {
                keep.push(*h);
            }
        }
        (keep, give)
    };
    let (mut keep1, give1) = split(f1, &take1);
    let (mut keep2, give2) = split(f2, &take2);
    keep1.extend(give2);
    keep2.extend(give1);
    cancel_in_facet(&mut keep1, counts);
    cancel_in_facet(&mut keep2, counts);
    let full = keep1.is_empty() && keep2.is_empty();
    w.facets[i] = keep1;
    w.facets[j] = keep2;
    w.changed[i] = true;
    w.changed[j] = true;
    if full {
        counts.facets_cancelled += 1;
        PairResult::Full
    } else {
        counts.facets_partially_cancelled += 1;
        PairResult::Partial
    }
}

/// One pass of facet cancellation over the candidate pairs: facets facing
/// opposite ways (best-fit normals with a negative dot product) whose
/// boxes, grown by `delta`, meet. The candidates are found once per pass
/// by the bounding-volume hierarchy (`index.rs`); a swap only moves half-edges between the two facets, and
/// a facet only loses region, so its box stays within the one indexed.
///
/// With `only`, the pass looks only at the pairs with a facet marked
/// there: the facets the previous pass (and the half-edge cancellation
/// after it) changed. That is exact, not a heuristic: a pair of facets
/// neither of which changed since the previous pass was a candidate there
/// with the same normals and boxes, and [`cancel_pair`] (which reads only
/// the two facets and the positions, and no vertex moves in this phase)
/// found nothing to do with them then, so it finds nothing now.
///
/// Returns the number of pairs that changed, whether the budget stopped
/// the pass, and which facets the pass changed. A pass over the marked
/// facets' pairs that ends over the budget reports it at its end (a pass
/// over all pairs would have at its next pair, which may have been after
/// its last change, so the report may then count one pass fewer; the
/// shape is the same).
pub(crate) fn facet_cancellation_pass(
    w: &mut Work,
    delta: f64,
    counts: &mut SmoothCounts,
    mut over_budget: impl FnMut(&SmoothCounts) -> bool,
    only: Option<&[bool]>,
) -> (u64, bool, Vec<bool>) {
    let mut boxes = Vec::new();
    let mut normals: Vec<Option<Point3>> = vec![None; w.facets.len()];
    for (i, f) in w.facets.iter().enumerate() {
        if f.is_empty() {
            continue;
        }
        let Some(n) = facet_normal(&w.pos, f) else {
            continue;
        };
        normals[i] = Some(n);
        let (lo, hi) = grown_box(f.iter().map(|h| w.pos[h.start as usize]), delta);
        boxes.push(IdBox {
            lo,
            hi,
            id: i as u32,
        });
    }
    let pos = &w.pos;
    let facets = &w.facets;
    // The `maybe` test of a pair (i, j), i < j, given its two planes: a
    // pair with no half-edge of either facet within `delta` of the other's
    // plane, or only one, is one `cancel_pair` leaves as it is (`maybe` is
    // false; [`swappable`]).
    let maybe = |i: usize, j: usize, p1: Option<Plane>, p2: Option<Plane>| match (p1, p2) {
        (Some(p1), Some(p2)) => {
            dot(p1.normal, p2.normal) < 0.0
                && swappable(pos, &p2, &facets[i], None, delta)
                    + swappable(pos, &p1, &facets[j], Some(&facets[i]), delta)
                    >= 2
        }
        _ => false,
    };
    let plane = |i: usize| normals[i].and(best_fit_plane(pos, &facets[i]));
    let mut touched = vec![false; w.facets.len()];
    let mut changed = 0;
    let Some(marked) = only else {
        // The planes `cancel_pair` would compute for facets no pair of
        // this pass has changed yet, for the `maybe` test in the parallel
        // join.
        let planes: Vec<Option<Plane>> = (0..w.facets.len()).into_par_iter().map(plane).collect();
        // Only facets facing opposite ways can cancel: the pairs come by
        // normal direction, not from every pair of meeting boxes.
        let filter = |i: u32, j: u32| {
            let (i, j) = (i as usize, j as usize);
            match (normals[i], normals[j]) {
                (Some(ni), Some(nj)) if dot(ni, nj) < 0.0 => {
                    Some((i, j, maybe(i, j, planes[i], planes[j])))
                }
                _ => None,
            }
        };
        let mut pairs: Vec<(usize, usize, bool)> = opposed_pairs_where(&boxes, &normals, filter);
        pairs.sort_unstable();
        for (i, j, maybe) in pairs {
            if over_budget(counts) {
                return (changed, true, touched);
            }
            if !maybe && !touched[i] && !touched[j] {
                continue; // `cancel_pair` would find nothing (see above)
            }
            if cancel_pair(w, i, j, delta, counts) != PairResult::Nothing {
                changed += 1;
                touched[i] = true;
                touched[j] = true;
            }
        }
        return (changed, false, touched);
    };
    // Over the marked facets: the pass over all pairs, in the same order,
    // leaving out the pairs it would find nothing in. Those are the pairs
    // it reaches while neither facet has changed since the previous pass
    // (see above). So the queue starts with the marked facets' pairs, and
    // a facet that this pass changes brings its pairs that come later in
    // the order. The candidates are those of the full pass: meeting boxes
    // and a negative dot product of the normals (which implies opposed
    // signs on some axis), both as at the start of the pass.
    let slot: Vec<Option<usize>> = {
        let mut slot = vec![None; w.facets.len()];
        for (k, b) in boxes.iter().enumerate() {
            slot[b.id as usize] = Some(k);
        }
        slot
    };
    let index = BoxIndex::new(boxes.clone());
    let pairs_of = |f: usize, out: &mut Vec<(usize, usize)>| {
        let (Some(k), Some(nf)) = (slot[f], normals[f]) else {
            return;
        };
        let q = &boxes[k];
        index.visit(&q.lo, &q.hi, |id| {
            let g = id as usize;
            if g != f && normals[g].is_some_and(|ng| dot(nf, ng) < 0.0) {
                out.push((f.min(g), f.max(g)));
            }
        });
    };
    let mut activated: Vec<bool> = (0..w.facets.len())
        .map(|f| marked.get(f).copied().unwrap_or(false))
        .collect();
    let mut queue: BTreeMap<(usize, usize), bool> = BTreeMap::new();
    let mut found = Vec::new();
    for f in (0..w.facets.len()).filter(|&f| activated[f]) {
        pairs_of(f, &mut found);
    }
    for (i, j) in found.drain(..) {
        if let Entry::Vacant(v) = queue.entry((i, j)) {
            v.insert(maybe(i, j, plane(i), plane(j)));
        }
    }
    while let Some(((i, j), maybe)) = queue.pop_first() {
        if over_budget(counts) {
            return (changed, true, touched);
        }
        if !maybe && !touched[i] && !touched[j] {
            continue;
        }
        if cancel_pair(w, i, j, delta, counts) == PairResult::Nothing {
            continue;
        }
        changed += 1;
        touched[i] = true;
        touched[j] = true;
        for f in [i, j] {
            if !activated[f] {
                activated[f] = true;
                pairs_of(f, &mut found);
            }
        }
        // A changed facet's pairs are never skipped, whatever `maybe`.
        for p in found.drain(..).filter(|&p| p > (i, j)) {
            queue.entry(p).or_insert(false);
        }
    }
    // A pass over all pairs would stop at its next pair once over the
    // budget; this one says so at its end (the shape is the same; the
    // report may count one pass fewer).
    (changed, over_budget(counts), touched)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opposing_pairs_and_zero_length_half_edges_cancel() {
        let mut c = SmoothCounts::default();
        let h = |start, end| HalfEdge { start, end };
        let mut f = vec![h(0, 1), h(1, 2), h(2, 0), h(3, 3), h(1, 0), h(0, 1)];
        assert!(cancel_in_facet(&mut f, &mut c));
        assert_eq!(f, vec![h(1, 2), h(2, 0), h(0, 1)]);
        assert_eq!(c.zero_length_edges_removed, 1);
        assert_eq!(c.half_edges_cancelled, 1);
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(test_support::cases(256)))]

        /// Random multigraphs: the chosen edges are balanced at every
        /// vertex and the rest holds no cycle (so the choice is maximal).
        #[test]
        fn maximal_loops_is_balanced_and_maximal(
            edges in proptest::collection::vec((0u32..6, 0u32..6), 0..30),
        ) {
            let chosen = maximal_loops(&edges);
            let mut balance = HashMap::new();
            for (e, &c) in edges.iter().zip(&chosen) {
                if c {
                    *balance.entry(e.0).or_insert(0i32) += 1;
                    *balance.entry(e.1).or_insert(0i32) -= 1;
                }
            }
            proptest::prop_assert!(balance.values().all(|&b| b == 0));
            // The rest is acyclic: repeatedly drop edges from vertices
            // nothing enters; everything must go.
            let mut rest: Vec<(u32, u32)> = edges
                .iter()
                .zip(&chosen)
                .filter(|(_, &c)| !c)
                .map(|(e, _)| *e)
                .collect();
            loop {
                let before = rest.len();
                let ends: Vec<u32> = rest.iter().map(|e| e.1).collect();
                rest.retain(|e| ends.contains(&e.0));
                if rest.len() == before {
                    break;
                }
            }
            proptest::prop_assert!(rest.is_empty(), "a cycle left: {:?}", rest);
        }
    }

    #[test]
    fn maximal_loops_drops_what_cannot_close() {
        // A triangle 0->1->2->0 plus a dangling 2->3 and a 2-cycle 4<->5.
        let e = [(0, 1), (1, 2), (2, 0), (2, 3), (4, 5), (5, 4)];
        assert_eq!(maximal_loops(&e), vec![true, true, true, false, true, true]);
        // Figure-eight: two cycles through vertex 0.
        let e = [(0, 1), (1, 0), (0, 2), (2, 0)];
        assert_eq!(maximal_loops(&e), vec![true; 4]);
        // A path only.
        assert_eq!(maximal_loops(&[(0, 1), (1, 2)]), vec![false, false]);
    }
}
