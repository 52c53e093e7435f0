//! Removal of straight-through vertices: a vertex with exactly two edges,
//! one in and one out (closure makes their multiplicities equal), lying
//! exactly on the open segment between its two neighbours (exact
//! `orient2d`), is dropped and its two edges become one. The edges cover
//! the same points before and after, so nothing moves and no crossing
//! appears; what it removes are the collinear vertices that merging and
//! cancellation leave on straight sides (two squares merged along an edge
//! give one ring of four edges). Each removal takes one vertex out of the
//! edges, so the phase ends.
//!
//! A vertex is kept, though straight-through, when another vertex would
//! crack the joined edge by Appendix A's rule although it cracks neither
//! part (a vertex within the tolerance of the joined edge whose parts
//! would both be shorter, but beside the end of a short part): the phase
//! runs after edge cracking by vertex, and must not undo what that phase
//! leaves, no vertex near an edge's interior (a property-test find: a
//! vertex at exactly the tolerance above a straight side, on coordinates
//! of `1.5 * 2^49` in steps of `1/8`).

use super::broad::{segment_box, VertexIndex};
use super::geom::{cracks_at, on_open_segment};
use super::work::{WEdge, Work};
use crate::SmoothCounts;

/// Removes the straight-through vertices (repeatedly along collinear
/// chains) whose joined edge no other vertex cracks at tolerance `tol`,
/// then normalises. Returns how many were removed. `index` is an index
/// of `w.pts` or `None`, then built at the first candidate (the points do
/// not move here, so the caller may keep it for later phases).
pub fn straighten(
    w: &mut Work,
    tol: f64,
    counts: &mut SmoothCounts,
    index: &mut Option<VertexIndex>,
) -> u64 {
    let n = w.pts.len();
    let tol2 = tol * tol;
    let mut edges: Vec<Option<WEdge>> = w.edges.iter().copied().map(Some).collect();
    let mut adj = Incidence::new(n, &w.edges);
    let mut stack: Vec<u32> = (0..n as u32).rev().collect();
    let mut removed = 0;
    while let Some(v) = stack.pop() {
        let vi = v as usize;
        let Some([i1, i2]) = adj.pair(vi) else {
            continue;
        };
        let (Some(e1), Some(e2)) = (edges[i1 as usize], edges[i2 as usize]) else {
            continue;
        };
        // The flow into `v` along each edge (`a -> b` counted `m`).
        let into = |e: WEdge| if e.b == v { e.m } else { -e.m };
        let other = |e: WEdge| if e.a == v { e.b } else { e.a };
        let (m1, m2) = (into(e1), into(e2));
        if m1 != -m2 || m1 == 0 {
            continue;
        }
        let (from, to, m) = if m1 > 0 {
            (other(e1), other(e2), m1)
        } else {
            (other(e2), other(e1), m2)
        };
        let (pa, pb) = (w.pts[from as usize], w.pts[to as usize]);
        if from == to || !on_open_segment(w.pts[vi], pa, pb) {
            continue;
        }
        let index = index.get_or_insert_with(|| VertexIndex::new(&w.pts));
        debug_assert_eq!(index.len(), w.pts.len());
        let (lo, hi) = segment_box(pa, pb, tol);
        let mut cracked = false;
        index.visit(lo, hi, |u| {
            cracked = cracked
                || (u != v
                    && u != from
                    && u != to
                    && adj.has_edges(u as usize)
                    && cracks_at(w.pts[u as usize], pa, pb, tol2));
        });
        if cracked {
            continue;
        }
        edges[i1 as usize] = None;
        edges[i2 as usize] = None;
        let idx = edges.len() as u32;
        edges.push(Some(WEdge::directed(from, to, m)));
        adj.join(vi, [from, to], [i1, i2], idx);
        stack.push(from);
        stack.push(to);
        removed += 1;
    }
    if removed > 0 {
        w.edges = edges.into_iter().flatten().collect();
        w.normalize(counts);
    }
    removed
}

/// The live edges at each vertex, as far as this phase needs them: how
/// many (counted up to three) and, for a vertex with at most two, which.
/// A removal takes both edges of its vertex and gives each of the two
/// neighbours the joined edge in place of the one it loses, so no other
/// vertex's count ever drops: a vertex with three edges or more is never
/// a candidate, and its edges need not be known.
struct Incidence {
    count: Vec<u8>,
    slots: Vec<[u32; 2]>,
}

impl Incidence {
    fn new(n: usize, edges: &[WEdge]) -> Incidence {
        let mut inc = Incidence {
            count: vec![0; n],
            slots: vec![[u32::MAX; 2]; n],
        };
        for (i, e) in edges.iter().enumerate() {
            for v in [e.a as usize, e.b as usize] {
                let c = &mut inc.count[v];
                if let Some(slot) = inc.slots[v].get_mut(usize::from(*c)) {
                    *slot = i as u32;
                }
                *c = (*c + 1).min(3);
            }
        }
        inc
    }

    /// The two edges of a vertex that has exactly two.
    fn pair(&self, v: usize) -> Option<[u32; 2]> {
        (self.count[v] == 2).then_some(self.slots[v])
    }

    /// Whether a vertex has an edge left.
    fn has_edges(&self, v: usize) -> bool {
        self.count[v] > 0
    }

    /// Vertex `v` removed, its edges `lost` joined into edge `idx` between
    /// its two neighbours `ends`.
    fn join(&mut self, v: usize, ends: [u32; 2], lost: [u32; 2], idx: u32) {
        self.count[v] = 0;
        for u in ends {
            let u = u as usize;
            if self.count[u] <= 2 {
                for s in &mut self.slots[u] {
                    if lost.contains(s) {
                        *s = idx;
                        break;
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topology::PolygonSet2;

    #[test]
    fn collinear_chain_becomes_one_edge_and_corners_stay() {
        let mut s = PolygonSet2::new();
        s.add_loop(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [0.0, 1.0],
        ]);
        let mut w = Work::from_set(&s);
        let mut c = SmoothCounts::default();
        w.normalize(&mut c);
        assert_eq!(straighten(&mut w, 0.1, &mut c, &mut None), 2);
        assert_eq!(w.edges.len(), 4);
        w.remove_unreferenced(&mut c);
        assert_eq!(w.to_set().signed_area(), 3.0);
        w.to_set().check_topology().unwrap();
        // A vertex off the line by one ulp is not straight-through.
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [1.0, f64::from_bits(1)], [2.0, 0.0], [2.0, 1.0]]);
        let mut w = Work::from_set(&s);
        w.normalize(&mut c);
        assert_eq!(straighten(&mut w, 0.1, &mut c, &mut None), 0);
    }

    #[test]
    fn vertex_that_would_crack_the_joined_edge_keeps_the_corner() {
        // The side (0,0) -> (1,0) -> (2,0) of a rectangle, and a triangle
        // with a vertex at (0.1, 0.5): within 0.5 of both parts, but beside
        // the far end of the first part only by sqrt(1.06) > 1, so it
        // cracks neither; the joined side (length 2) it would crack.
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, -1.0], [0.0, -1.0]]);
        s.add_loop(&[[0.1, 0.5], [0.1, 3.0], [-1.0, 3.0]]);
        let mut c = SmoothCounts::default();
        for (tol, removed) in [(0.5, 0), (0.49, 1)] {
            let mut w = Work::from_set(&s);
            w.normalize(&mut c);
            assert_eq!(
                straighten(&mut w, tol, &mut c, &mut None),
                removed,
                "tolerance {tol}"
            );
        }
    }
}
