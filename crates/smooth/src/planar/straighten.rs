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
/// then normalises. Returns how many were removed.
pub fn straighten(w: &mut Work, tol: f64, counts: &mut SmoothCounts) -> u64 {
    let n = w.pts.len();
    let tol2 = tol * tol;
    // Built at the first candidate: the points do not move here.
    let mut index: Option<VertexIndex> = None;
    let mut edges: Vec<Option<WEdge>> = w.edges.iter().copied().map(Some).collect();
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, e) in w.edges.iter().enumerate() {
        adj[e.a as usize].push(i);
        adj[e.b as usize].push(i);
    }
    let mut stack: Vec<u32> = (0..n as u32).rev().collect();
    let mut removed = 0;
    while let Some(v) = stack.pop() {
        let vi = v as usize;
        adj[vi].retain(|&i| edges[i].is_some());
        let [i1, i2] = adj[vi][..] else {
            continue;
        };
        let (Some(e1), Some(e2)) = (edges[i1], edges[i2]) else {
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
        let (lo, hi) = segment_box(pa, pb, tol);
        let cracked = index.in_box(lo, hi).into_iter().any(|u| {
            u != v
                && u != from
                && u != to
                && adj[u as usize].iter().any(|&i| edges[i].is_some())
                && cracks_at(w.pts[u as usize], pa, pb, tol2)
        });
        if cracked {
            continue;
        }
        edges[i1] = None;
        edges[i2] = None;
        adj[vi].clear();
        let idx = edges.len();
        edges.push(Some(WEdge::directed(from, to, m)));
        adj[from as usize].push(idx);
        adj[to as usize].push(idx);
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
        assert_eq!(straighten(&mut w, 0.1, &mut c), 2);
        assert_eq!(w.edges.len(), 4);
        w.remove_unreferenced(&mut c);
        assert_eq!(w.to_set().signed_area(), 3.0);
        w.to_set().check_topology().unwrap();
        // A vertex off the line by one ulp is not straight-through.
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [1.0, f64::from_bits(1)], [2.0, 0.0], [2.0, 1.0]]);
        let mut w = Work::from_set(&s);
        w.normalize(&mut c);
        assert_eq!(straighten(&mut w, 0.1, &mut c), 0);
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
            assert_eq!(straighten(&mut w, tol, &mut c), removed, "tolerance {tol}");
        }
    }
}
