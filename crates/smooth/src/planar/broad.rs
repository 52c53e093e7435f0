//! The broad phases of 2D smoothing, never over all pairs: the pairs of
//! edges whose boxes (widened by a margin) meet, from one parallel
//! self-join, and the vertices inside a box. Both run on the bounding
//! volume hierarchy of 3D smoothing (`mesh::index::BoxIndex`), built in
//! Morton order (a sort and a linear pass: the vertices and edges of a
//! polygon set are small boxes spread over the plane), each 2D box lifted
//! to the plane `z = 0`; a query allocates nothing, and the self-join
//! tests the caller's exact predicate on the pairs in parallel. Boxes are closed and
//! the margin is added outward, so a pair or a vertex within the margin of
//! an edge is never skipped.

use super::work::WEdge;
use crate::mesh::index::{BoxIndex, IdBox};
use robust_arith::Point2;

/// The box of segment `p q` widened by `margin` on every side.
pub fn segment_box(p: Point2, q: Point2, margin: f64) -> (Point2, Point2) {
    (
        [p[0].min(q[0]) - margin, p[1].min(q[1]) - margin],
        [p[0].max(q[0]) + margin, p[1].max(q[1]) + margin],
    )
}

/// A 2D box lifted to `z = 0`.
fn lifted(lo: Point2, hi: Point2, id: u32) -> IdBox {
    IdBox {
        lo: [lo[0], lo[1], 0.0],
        hi: [hi[0], hi[1], 0.0],
        id,
    }
}

/// `f(i, j)` for every pair `i < j` of edges whose boxes widened by
/// `margin` meet (a superset of the pairs within `2 * margin` of each
/// other; with `margin = 0`, of the pairs that touch), keeping the `Some`
/// answers, in no particular order. `f` runs in parallel.
pub fn edge_pairs_where<T: Send>(
    pts: &[Point2],
    edges: &[WEdge],
    margin: f64,
    f: impl Fn(usize, usize) -> Option<T> + Sync,
) -> Vec<T> {
    let boxes = edges
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let (lo, hi) = segment_box(pts[e.a as usize], pts[e.b as usize], margin);
            lifted(lo, hi, i as u32)
        })
        .collect();
    BoxIndex::by_morton_order(boxes).pairs_where(|i, j| f(i as usize, j as usize))
}

/// Every pair `(i, j)`, `i < j`, of edges whose boxes widened by `margin`
/// meet and for which `keep(i, j)` holds, sorted.
pub fn edge_pairs(
    pts: &[Point2],
    edges: &[WEdge],
    margin: f64,
    keep: impl Fn(usize, usize) -> bool + Sync,
) -> Vec<(usize, usize)> {
    let mut pairs = edge_pairs_where(pts, edges, margin, |i, j| keep(i, j).then_some((i, j)));
    pairs.sort_unstable();
    pairs
}

/// The vertices of a fixed point set, for box queries.
pub struct VertexIndex {
    index: BoxIndex,
    len: usize,
}

impl VertexIndex {
    /// Indexes `pts` (vertex `i` at `pts[i]`).
    pub fn new(pts: &[Point2]) -> Self {
        let boxes = pts
            .iter()
            .enumerate()
            .map(|(i, &p)| lifted(p, p, i as u32))
            .collect();
        VertexIndex {
            index: BoxIndex::by_morton_order(boxes),
            len: pts.len(),
        }
    }

    /// The number of points indexed.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Calls `f` with every vertex inside the closed box `[lo, hi]`, in
    /// no particular order (callers reduce them by an order-independent
    /// rule: any, or the least by a total order).
    pub fn visit(&self, lo: Point2, hi: Point2, f: impl FnMut(u32)) {
        self.index
            .visit(&[lo[0], lo[1], 0.0], &[hi[0], hi[1], 0.0], f);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::SplitMix64;

    /// The broad phases against all pairs and all vertices, on random
    /// segments (short and long, some degenerate) with and without a
    /// margin.
    #[test]
    fn matches_brute_force() {
        let mut rng = SplitMix64::new(7);
        for round in 0..40 {
            let n = 1 + round * 5;
            let pts: Vec<Point2> = (0..n)
                .map(|_| {
                    let s = if rng.next_u64().is_multiple_of(4) {
                        100.0
                    } else {
                        10.0
                    };
                    [
                        (rng.unit() * s).round() / 4.0,
                        (rng.unit() * s).round() / 4.0,
                    ]
                })
                .collect();
            let edges: Vec<WEdge> = (0..n)
                .map(|i| WEdge::directed(i as u32, (rng.next_u64() % n as u64) as u32, 1))
                .collect();
            for margin in [0.0, 0.3] {
                let boxes: Vec<_> = edges
                    .iter()
                    .map(|e| segment_box(pts[e.a as usize], pts[e.b as usize], margin))
                    .collect();
                let meets = |a: &(Point2, Point2), b: &(Point2, Point2)| {
                    (0..2).all(|k| a.0[k] <= b.1[k] && b.0[k] <= a.1[k])
                };
                let mut expected = Vec::new();
                for i in 0..n {
                    for j in i + 1..n {
                        if meets(&boxes[i], &boxes[j]) && (i + j) % 3 != 0 {
                            expected.push((i, j));
                        }
                    }
                }
                let got = edge_pairs(&pts, &edges, margin, |i, j| (i + j) % 3 != 0);
                assert_eq!(got, expected, "round {round}, margin {margin}");
                let index = VertexIndex::new(&pts);
                for b in &boxes {
                    let mut got = Vec::new();
                    index.visit(b.0, b.1, |v| got.push(v));
                    got.sort_unstable();
                    let expected: Vec<u32> = (0..n as u32)
                        .filter(|&v| meets(&(pts[v as usize], pts[v as usize]), b))
                        .collect();
                    assert_eq!(got, expected);
                }
            }
        }
    }
}
