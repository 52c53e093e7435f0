//! The broad phases of 2D smoothing, on R-trees (`rstar`), never over all
//! pairs: the pairs of edges whose boxes (widened by a margin) overlap,
//! from one self-join of the tree of edge boxes, and the vertices inside a
//! box. Boxes are closed and the margin is added outward, so a pair or a
//! vertex within the margin of an edge is never skipped.

use super::work::WEdge;
use robust_arith::Point2;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

type EdgeBox = GeomWithData<Rectangle<Point2>, usize>;

/// The box of segment `p q` widened by `margin` on every side.
pub fn segment_box(p: Point2, q: Point2, margin: f64) -> (Point2, Point2) {
    (
        [p[0].min(q[0]) - margin, p[1].min(q[1]) - margin],
        [p[0].max(q[0]) + margin, p[1].max(q[1]) + margin],
    )
}

/// Every pair `(i, j)`, `i < j`, of edges whose boxes widened by `margin`
/// overlap, sorted (a superset of the pairs within `2 * margin` of each
/// other; with `margin = 0`, of the pairs that touch).
pub fn edge_pairs(pts: &[Point2], edges: &[WEdge], margin: f64) -> Vec<(usize, usize)> {
    let boxes: Vec<EdgeBox> = edges
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let (lo, hi) = segment_box(pts[e.a as usize], pts[e.b as usize], margin);
            GeomWithData::new(Rectangle::from_corners(lo, hi), i)
        })
        .collect();
    let tree = RTree::bulk_load(boxes);
    let mut pairs: Vec<(usize, usize)> = tree
        .intersection_candidates_with_other_tree(&tree)
        .filter_map(|(x, y)| (x.data < y.data).then_some((x.data, y.data)))
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

/// The vertices of a fixed point set, for box queries.
pub struct VertexIndex {
    tree: RTree<GeomWithData<Point2, u32>>,
}

impl VertexIndex {
    /// Indexes `pts` (vertex `i` at `pts[i]`).
    pub fn new(pts: &[Point2]) -> Self {
        let items = pts
            .iter()
            .enumerate()
            .map(|(i, &p)| GeomWithData::new(p, i as u32))
            .collect();
        VertexIndex {
            tree: RTree::bulk_load(items),
        }
    }

    /// The vertices inside the closed box `[lo, hi]`, sorted by id.
    pub fn in_box(&self, lo: Point2, hi: Point2) -> Vec<u32> {
        let mut out: Vec<u32> = self
            .tree
            .locate_in_envelope(&AABB::from_corners(lo, hi))
            .map(|g| g.data)
            .collect();
        out.sort_unstable();
        out
    }
}
