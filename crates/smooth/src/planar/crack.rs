//! Edge cracking (Appendix A) on the working copy.
//!
//! - Between edges: two edges with four distinct vertices whose interiors
//!   cross (in the plane, two segments whose interiors come within the
//!   tolerance of each other either cross or have an end within the
//!   tolerance of the other, which is cracking by vertex) get a new vertex
//!   at the crossing point, snapped to an existing vertex within the
//!   tolerance (the first accepted, as in vertex merging). One pass: this
//!   is the only cracking that moves or creates positions.
//! - By vertex: an edge with a vertex (not its end) within the tolerance
//!   of its interior, or exactly on it, is split there provided both new
//!   edges are strictly shorter; repeated on the new edges until no edge
//!   qualifies. The vertex set is fixed meanwhile, so each split replaces
//!   one edge by two strictly shorter edges between vertices of a finite
//!   set, and the process ends (see the algorithm note).

use super::broad::{edge_pairs, segment_box, VertexIndex};
use super::budget::Budget;
use super::geom::{cracks_at, crossing_point, point_segment_dist2, properly_cross};
use super::work::{VertexRecord, WEdge, Work};
use crate::{merge_vertices, SmoothCounts, SmoothError};
use rayon::prelude::*;
use robust_arith::Point2;

/// Cracks every pair of properly crossing edges at their crossing point
/// (snapped to a vertex within `tol`). Returns whether it computed any
/// crossing point.
pub fn crack_between_edges(
    w: &mut Work,
    tol: f64,
    counts: &mut SmoothCounts,
    budget: &mut Budget,
) -> Result<bool, SmoothError> {
    let n = w.pts.len();
    let mut new_pts = Vec::new();
    let mut new_k = Vec::new();
    let mut cracks: Vec<Vec<u32>> = vec![Vec::new(); w.edges.len()];
    let p = |v: u32| w.pts[v as usize];
    let crossing = edge_pairs(&w.pts, &w.edges, 0.0, |i, j| {
        let (e, f) = (w.edges[i], w.edges[j]);
        let distinct = e.a != f.a && e.a != f.b && e.b != f.a && e.b != f.b;
        distinct && properly_cross(p(e.a), p(e.b), p(f.a), p(f.b))
    });
    for (i, j) in crossing {
        let (e, f) = (w.edges[i], w.edges[j]);
        let (a, b, c, d) = (p(e.a), p(e.b), p(f.a), p(f.b));
        if !budget.spend(1) {
            break;
        }
        counts.edges_cracked_between_edges += 1;
        let q = (n + new_pts.len()) as u32;
        new_pts.push(crossing_point(a, b, c, d));
        let k = [e.a, e.b, f.a, f.b]
            .iter()
            .map(|&v| w.rec[v as usize].k)
            .max()
            .unwrap_or(0);
        new_k.push(k.saturating_add(1));
        cracks[i].push(q);
        cracks[j].push(q);
    }
    if new_pts.is_empty() {
        return Ok(false);
    }
    // Snap: existing vertices (pairwise farther than `tol` apart after
    // merging) come first, so each is accepted and every new point joins
    // the first accepted vertex within `tol`, or is accepted itself.
    let mut all = w.pts.clone();
    all.extend_from_slice(&new_pts);
    let rep = merge_vertices(&all, tol).representative;
    if let Some(v) = (0..n).find(|&v| rep[v] as usize != v) {
        return Err(SmoothError::Internal(format!(
            "vertex {v} lies within the tolerance of vertex {} after merging",
            rep[v]
        )));
    }
    w.pts = all;
    for (q, &k) in new_k.iter().enumerate() {
        let q = n + q;
        let r = rep[q] as usize;
        if r == q {
            counts.vertices_created += 1;
            w.rec.push(VertexRecord { k });
        } else {
            w.rec.push(VertexRecord { k: 0 });
            w.rec[r].k = w.rec[r].k.max(k);
        }
    }
    let mut edges = Vec::with_capacity(w.edges.len() + 2 * new_pts.len());
    for (e, list) in w.edges.iter().zip(cracks) {
        if list.is_empty() {
            edges.push(*e);
            continue;
        }
        let (pa, pb) = (w.pts[e.a as usize], w.pts[e.b as usize]);
        let dir = [pb[0] - pa[0], pb[1] - pa[1]];
        let param = |v: u32| {
            let q = w.pts[v as usize];
            (q[0] - pa[0]) * dir[0] + (q[1] - pa[1]) * dir[1]
        };
        let mut ids: Vec<(f64, u32)> = list
            .iter()
            .map(|&q| rep[q as usize])
            .filter(|&v| v != e.a && v != e.b)
            .map(|v| (param(v), v))
            .collect();
        ids.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        ids.dedup_by_key(|x| x.1);
        let mut prev = e.a;
        for &(_, v) in &ids {
            edges.push(WEdge::directed(prev, v, e.m));
            prev = v;
        }
        edges.push(WEdge::directed(prev, e.b, e.m));
    }
    w.edges = edges;
    w.normalize(counts);
    w.remove_unreferenced(counts);
    Ok(true)
}

/// Cracks edges at the vertices near their interiors until none
/// qualifies (or the budget is spent). `index` is an index of `w.pts` or
/// `None`, then built here (the vertex set is fixed: it stays valid).
pub fn crack_by_vertices(
    w: &mut Work,
    tol: f64,
    counts: &mut SmoothCounts,
    budget: &mut Budget,
    index: &mut Option<VertexIndex>,
) {
    let index = &*index.get_or_insert_with(|| VertexIndex::new(&w.pts));
    debug_assert_eq!(index.len(), w.pts.len());
    let tol2 = tol * tol;
    let pts = &w.pts;
    // Only the set's vertices crack: the index also holds the positions
    // that straight-through removal has just taken out of the edges
    // (exactly on the joined edge, each would split it again, and the
    // second removal would join it again). Splits keep this set: they
    // only give a vertex of the set more edges.
    let mut live = vec![false; pts.len()];
    for e in &w.edges {
        live[e.a as usize] = true;
        live[e.b as usize] = true;
    }
    let live = &live;
    // The vertex that cracks an edge depends on the edge and the fixed
    // vertex set alone, so it is found for every edge of the input in
    // parallel; the halves of split edges are looked up as they come.
    let first: Vec<Option<u32>> = w
        .edges
        .par_iter()
        .map(|&e| cracking_vertex(index, pts, live, e, tol, tol2))
        .collect();
    let mut stack: Vec<(WEdge, Option<Option<u32>>)> = w
        .edges
        .iter()
        .zip(first)
        .rev()
        .map(|(&e, v)| (e, Some(v)))
        .collect();
    let mut out = Vec::with_capacity(w.edges.len());
    while let Some((e, known)) = stack.pop() {
        if budget.exhausted() {
            out.push(e);
            continue;
        }
        let best = known.unwrap_or_else(|| cracking_vertex(index, &w.pts, live, e, tol, tol2));
        match best {
            Some(v) if budget.spend(1) => {
                counts.edges_cracked_by_vertex += 1;
                let ke = w.rec[e.a as usize].k.max(w.rec[e.b as usize].k);
                let kv = &mut w.rec[v as usize].k;
                *kv = (*kv).max(ke.saturating_add(1));
                // `e` is `a -> b` counted `m` (signed): so are its halves.
                stack.push((WEdge::directed(v, e.b, e.m), None));
                stack.push((WEdge::directed(e.a, v, e.m), None));
            }
            _ => out.push(e),
        }
    }
    w.edges = out;
    w.normalize(counts);
}

/// The vertex at which edge `e` is cracked: of the `live` vertices (not
/// its ends) that crack it by Appendix A's rule, the least by (squared
/// distance to the edge, id), the same whatever order the index gives them
/// in.
fn cracking_vertex(
    index: &VertexIndex,
    pts: &[Point2],
    live: &[bool],
    e: WEdge,
    tol: f64,
    tol2: f64,
) -> Option<u32> {
    let (pa, pb) = (pts[e.a as usize], pts[e.b as usize]);
    let (lo, hi) = segment_box(pa, pb, tol);
    let mut best: Option<(f64, u32)> = None;
    index.visit(lo, hi, |v| {
        if v == e.a || v == e.b || !live[v as usize] {
            return;
        }
        let pv = pts[v as usize];
        if cracks_at(pv, pa, pb, tol2) {
            let (d2, _) = point_segment_dist2(&pv, &pa, &pb);
            let d2 = if d2.is_nan() { 0.0 } else { d2 };
            if best.is_none_or(|(bd, bv)| (d2, v) < (bd, bv)) {
                best = Some((d2, v));
            }
        }
    });
    best.map(|(_, v)| v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use topology::PolygonSet2;

    /// A position no edge uses any more (as straight-through removal
    /// leaves one, exactly on the edge it joined) cracks nothing; the same
    /// position as a vertex of the set cracks the edge.
    #[test]
    fn only_vertices_of_the_set_crack() {
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]);
        let mut w = Work::from_set(&s);
        let mut counts = SmoothCounts::default();
        w.normalize(&mut counts);
        // An unreferenced vertex at the middle of the bottom side.
        w.pts.push([1.0, 0.0]);
        w.rec.push(VertexRecord { k: 0 });
        let edges = w.edges.clone();
        crack_by_vertices(&mut w, 0.1, &mut counts, &mut Budget::new(100), &mut None);
        assert_eq!(
            (w.edges.clone(), counts.edges_cracked_by_vertex),
            (edges, 0)
        );
        // A triangle with a corner there: now it is a vertex of the set.
        let mut s = s.clone();
        s.add_loop(&[[1.0, 0.0], [1.5, -1.0], [0.5, -1.0]]);
        let mut w = Work::from_set(&s);
        w.normalize(&mut counts);
        crack_by_vertices(&mut w, 0.1, &mut counts, &mut Budget::new(100), &mut None);
        assert_eq!(counts.edges_cracked_by_vertex, 1);
    }
}
