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

impl Bvh {
    pub(super) fn new(boxes: &[[Point3; 2]]) -> Bvh {
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * boxes.len() / LEAF + 1),
            order: (0..boxes.len() as u32).collect(),
        };
        if boxes.is_empty() {
            return bvh;
        }
        bvh.nodes.push(Node {
            lo: [0.0; 3],
            hi: [0.0; 3],
            end: 0,
            first: 0,
            count: 0,
        });
        // (node, start, end) of `order` still to split.
        let mut stack = vec![(0usize, 0usize, boxes.len())];
        let centre = |i: u32, k: usize| {
            let b = &boxes[i as usize];
            b[0][k] * 0.5 + b[1][k] * 0.5
        };
        while let Some((node, start, end)) = stack.pop() {
            let ids = &mut bvh.order[start..end];
            let (mut lo, mut hi) = (boxes[ids[0] as usize][0], boxes[ids[0] as usize][1]);
            let (mut clo, mut chi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            for &i in ids.iter() {
                let b = &boxes[i as usize];
                for k in 0..3 {
                    lo[k] = lo[k].min(b[0][k]);
                    hi[k] = hi[k].max(b[1][k]);
                    clo[k] = clo[k].min(centre(i, k));
                    chi[k] = chi[k].max(centre(i, k));
                }
            }
            bvh.nodes[node].lo = lo;
            bvh.nodes[node].hi = hi;
            bvh.nodes[node].end = end as u32;
            if ids.len() <= LEAF {
                bvh.nodes[node].first = start as u32;
                bvh.nodes[node].count = ids.len() as u32;
                continue;
            }
            let axis = (0..3)
                .max_by(|&a, &b| (chi[a] - clo[a]).total_cmp(&(chi[b] - clo[b])))
                .unwrap_or(0);
            let mid = ids.len() / 2;
            ids.select_nth_unstable_by(mid, |&a, &b| centre(a, axis).total_cmp(&centre(b, axis)));
            let left = bvh.nodes.len();
            for _ in 0..2 {
                bvh.nodes.push(Node {
                    lo: [0.0; 3],
                    hi: [0.0; 3],
                    end: 0,
                    first: 0,
                    count: 0,
                });
            }
            bvh.nodes[node].first = left as u32;
            stack.push((left, start, start + mid));
            stack.push((left + 1, start + mid, end));
        }
        bvh
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
        let bvh = Bvh::new(&boxes);
        let mut got = Vec::new();
        for pos in 0..boxes.len() {
            let i = bvh.order()[pos];
            bvh.query_after(&boxes, pos, |j| got.push((i.min(j), i.max(j))));
        }
        got.sort_unstable();
        let mut want = Vec::new();
        for i in 0..boxes.len() as u32 {
            for j in i + 1..boxes.len() as u32 {
                if overlap(&boxes[i as usize], &boxes[j as usize]) {
                    want.push((i, j));
                }
            }
        }
        // Every overlapping pair exactly once.
        assert_eq!(got, want);
        let empty = Bvh::new(&[]);
        empty.query_after(&[], 0, |_| panic!("no boxes"));
    }
}
