//! A bounding-volume hierarchy over closed axis-aligned boxes: the broad
//! phase of the self-intersection test. Built by median splits on the
//! longest axis of the boxes' centres (`O(n log n)`, `O(n)` memory); a
//! query visits the boxes overlapping one box in `O(log n + k)` for boxes
//! that are not themselves mutually overlapping in bulk; the queries of
//! all boxes visit each overlapping pair once.

use robust_arith::Point3;

/// Boxes per leaf.
const LEAF: usize = 4;

/// A node: its box, the range of `order` below it, and either two
/// children or (a leaf) that range itself.
#[derive(Clone, Copy)]
struct Node {
    lo: Point3,
    hi: Point3,
    /// The end of the node's range of `order` (its start is implied by
    /// the traversal and not needed).
    end: u32,
    /// Children (`left`, `left + 1`) when `count == 0`, else the first
    /// entry of `order`.
    first: u32,
    count: u32,
}

/// The hierarchy over a slice of boxes (`[lo, hi]` each).
pub(super) struct Bvh {
    nodes: Vec<Node>,
    /// Box ids, leaves' ranges contiguous.
    order: Vec<u32>,
}

/// `true` when the closed boxes meet.
#[inline]
pub(super) fn overlap(a: &[Point3; 2], b: &[Point3; 2]) -> bool {
    (0..3).all(|k| a[0][k] <= b[1][k] && b[0][k] <= a[1][k])
}

/// Ranges longer than this are split on two threads (the two halves'
/// hierarchies built at once and joined); shorter ones in one.
const PARALLEL_MIN: usize = 1 << 15;

/// A node not filled in yet.
const BLANK: Node = Node {
    lo: [0.0; 3],
    hi: [0.0; 3],
    end: 0,
    first: 0,
    count: 0,
};

/// The box of the boxes `ids`, and the axis along which their centres
/// spread the most (the split axis).
fn bounds(boxes: &[[Point3; 2]], ids: &[u32]) -> (Point3, Point3, usize) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let (mut clo, mut chi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for &i in ids {
        let b = &boxes[i as usize];
        for k in 0..3 {
            lo[k] = lo[k].min(b[0][k]);
            hi[k] = hi[k].max(b[1][k]);
            clo[k] = clo[k].min(centre(b, k));
            chi[k] = chi[k].max(centre(b, k));
        }
    }
    let axis = (0..3)
        .max_by(|&a, &b| (chi[a] - clo[a]).total_cmp(&(chi[b] - clo[b])))
        .unwrap_or(0);
    (lo, hi, axis)
}

/// The centre of box `b` along axis `k`.
#[inline]
fn centre(b: &[Point3; 2], k: usize) -> f64 {
    b[0][k] * 0.5 + b[1][k] * 0.5
}

/// Splits `ids` at its median along `axis` (the left half the smaller
/// centres); returns the length of the left half.
fn split(boxes: &[[Point3; 2]], ids: &mut [u32], axis: usize) -> usize {
    let mid = ids.len() / 2;
    ids.select_nth_unstable_by(mid, |&a, &b| {
        centre(&boxes[a as usize], axis).total_cmp(&centre(&boxes[b as usize], axis))
    });
    mid
}

/// The hierarchy over `ids`, which sit at `start..` of the whole order:
/// its root at index 0, children of a node adjacent, leaves' ranges and
/// ends as positions of the whole order. Long ranges build their halves
/// on two threads (`rayon::join`), then place the two subtrees' roots at
/// 1 and 2 and the rest of the left subtree before the rest of the right
/// one; the tree is the one a single thread builds, numbered apart.
fn build(boxes: &[[Point3; 2]], ids: &mut [u32], start: usize, parallel_min: usize) -> Vec<Node> {
    let len = ids.len();
    if len > parallel_min.max(LEAF) {
        let (lo, hi, axis) = bounds(boxes, ids);
        let mid = split(boxes, ids, axis);
        let (left, right) = ids.split_at_mut(mid);
        let (l, r) = rayon::join(
            || build(boxes, left, start, parallel_min),
            || build(boxes, right, start + mid, parallel_min),
        );
        let mut nodes = Vec::with_capacity(1 + l.len() + r.len());
        nodes.push(Node {
            lo,
            hi,
            end: (start + len) as u32,
            first: 1,
            count: 0,
        });
        // Subtree node `j` moves to `j + shift` (its root to `root`).
        let place = |node: &Node, shift: u32| Node {
            first: if node.count == 0 {
                node.first + shift
            } else {
                node.first
            },
            ..*node
        };
        let (ls, rs) = (2, l.len() as u32 + 1);
        nodes.push(place(&l[0], ls));
        nodes.push(place(&r[0], rs));
        nodes.extend(l[1..].iter().map(|n| place(n, ls)));
        nodes.extend(r[1..].iter().map(|n| place(n, rs)));
        return nodes;
    }
    let mut nodes = Vec::with_capacity(2 * len / LEAF + 1);
    nodes.push(BLANK);
    // (node, start, end) of `ids` still to split.
    let mut stack = vec![(0usize, 0usize, len)];
    while let Some((node, s, e)) = stack.pop() {
        let range = &mut ids[s..e];
        let (lo, hi, axis) = bounds(boxes, range);
        nodes[node].lo = lo;
        nodes[node].hi = hi;
        nodes[node].end = (start + e) as u32;
        if range.len() <= LEAF {
            nodes[node].first = (start + s) as u32;
            nodes[node].count = range.len() as u32;
            continue;
        }
        let mid = split(boxes, range, axis);
        let left = nodes.len();
        nodes.extend([BLANK, BLANK]);
        nodes[node].first = left as u32;
        stack.push((left, s, s + mid));
        stack.push((left + 1, s + mid, e));
    }
    nodes
}

impl Bvh {
    pub(super) fn new(boxes: &[[Point3; 2]]) -> Bvh {
        Bvh::with_parallel_min(boxes, PARALLEL_MIN)
    }

    /// [`Bvh::new`], ranges longer than `parallel_min` split on two
    /// threads (the tests take it small).
    fn with_parallel_min(boxes: &[[Point3; 2]], parallel_min: usize) -> Bvh {
        let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
        let nodes = if boxes.is_empty() {
            Vec::new()
        } else {
            build(boxes, &mut order, 0, parallel_min)
        };
        Bvh { nodes, order }
    }

    /// The box ids in the hierarchy's order: position `p` holds box
    /// `order()[p]`.
    pub(super) fn order(&self) -> &[u32] {
        &self.order
    }

    /// `true` when some box meets `query` (closed).
    pub(super) fn any_overlap(&self, boxes: &[[Point3; 2]], query: &[Point3; 2]) -> bool {
        let mut stack = Vec::new();
        if !self.nodes.is_empty() {
            stack.push(0u32);
        }
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n as usize];
            if !overlap(&[node.lo, node.hi], query) {
                continue;
            }
            if node.count == 0 {
                stack.push(node.first);
                stack.push(node.first + 1);
            } else {
                let (s, e) = (node.first as usize, (node.first + node.count) as usize);
                if self.order[s..e]
                    .iter()
                    .any(|&i| overlap(&boxes[i as usize], query))
                {
                    return true;
                }
            }
        }
        false
    }

    /// Calls `visit` with every box id at a position after `pos` (in
    /// [`Bvh::order`]) whose box meets box `order()[pos]` (closed): called
    /// for every position, this visits each overlapping pair exactly once.
    pub(super) fn query_after(
        &self,
        boxes: &[[Point3; 2]],
        pos: usize,
        mut visit: impl FnMut(u32),
    ) {
        let Some(&me) = self.order.get(pos) else {
            return;
        };
        let query = &boxes[me as usize];
        let mut stack = vec![0u32];
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n as usize];
            if node.end as usize <= pos + 1 || !overlap(&[node.lo, node.hi], query) {
                continue;
            }
            if node.count == 0 {
                stack.push(node.first);
                stack.push(node.first + 1);
            } else {
                let (s, e) = (node.first as usize, (node.first + node.count) as usize);
                for &i in &self.order[s.max(pos + 1)..e] {
                    if overlap(&boxes[i as usize], query) {
                        visit(i);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn any_overlap_matches_brute_force() {
        let mut seed = 7u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % 1000) as f64 / 100.0
        };
        let mut random_box = || {
            let lo = [next(), next(), next()];
            [
                lo,
                [
                    lo[0] + next() / 5.0,
                    lo[1] + next() / 5.0,
                    lo[2] + next() / 5.0,
                ],
            ]
        };
        let boxes: Vec<[Point3; 2]> = (0..300).map(|_| random_box()).collect();
        let bvh = Bvh::new(&boxes);
        for _ in 0..500 {
            let q = random_box();
            let want = boxes.iter().any(|b| overlap(b, &q));
            assert_eq!(bvh.any_overlap(&boxes, &q), want);
        }
        assert!(!Bvh::new(&[]).any_overlap(&[], &boxes[0]));
    }

    #[test]
    fn queries_match_brute_force() {
        // Boxes on a jittered grid with some long thin ones and duplicates.
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut boxes = Vec::new();
        for i in 0..600 {
            let p = [next() * 10.0, next() * 10.0, next() * 10.0];
            let s = if i % 50 == 0 { 8.0 } else { 0.5 };
            let q = [p[0] + next() * s, p[1] + next() * 0.5, p[2] + next() * 0.5];
            boxes.push([p, q]);
            if i % 97 == 0 {
                boxes.push([p, q]);
            }
        }
        let mut want = Vec::new();
        for i in 0..boxes.len() as u32 {
            for j in i + 1..boxes.len() as u32 {
                if overlap(&boxes[i as usize], &boxes[j as usize]) {
                    want.push((i, j));
                }
            }
        }
        // Built on one thread, and with every range above 5, 16 or 100
        // boxes split on two (the subtrees joined): every overlapping
        // pair exactly once, and the same order of the boxes.
        let single = Bvh::with_parallel_min(&boxes, usize::MAX);
        for parallel_min in [usize::MAX, 5, 16, 100] {
            let bvh = Bvh::with_parallel_min(&boxes, parallel_min);
            assert_eq!(bvh.order(), single.order(), "{parallel_min}");
            assert_eq!(bvh.nodes.len(), single.nodes.len(), "{parallel_min}");
            let mut got = Vec::new();
            for pos in 0..boxes.len() {
                let i = bvh.order()[pos];
                bvh.query_after(&boxes, pos, |j| got.push((i.min(j), i.max(j))));
            }
            got.sort_unstable();
            assert_eq!(got, want, "{parallel_min}");
            for q in boxes.iter().step_by(7) {
                let grown = [q[0].map(|x| x - 0.3), q[1].map(|x| x + 0.3)];
                let far = [q[0].map(|x| x + 20.0), q[1].map(|x| x + 20.0)];
                assert!(bvh.any_overlap(&boxes, &grown));
                assert!(!bvh.any_overlap(&boxes, &far));
            }
        }
        let empty = Bvh::new(&[]);
        empty.query_after(&[], 0, |_| panic!("no boxes"));
    }
}
