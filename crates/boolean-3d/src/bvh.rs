//! The broad phase: a bounding-volume hierarchy over closed axis-aligned
//! boxes. It only ever skips pairs whose boxes are disjoint; see
//! [`crate::level3`] for why that is conservative for every X of Table 4.1.

use smallvec::SmallVec;

/// A closed axis-aligned box `[lo, hi]` (empty when `lo > hi`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    /// The lower corner.
    pub lo: [f64; 3],
    /// The upper corner.
    pub hi: [f64; 3],
}

impl Aabb {
    /// The empty box.
    pub const EMPTY: Aabb = Aabb {
        lo: [f64::INFINITY; 3],
        hi: [f64::NEG_INFINITY; 3],
    };

    /// Grows the box to hold `p`.
    #[inline]
    pub fn add(&mut self, p: &[f64; 3]) {
        for (c, &v) in p.iter().enumerate() {
            self.lo[c] = self.lo[c].min(v);
            self.hi[c] = self.hi[c].max(v);
        }
    }

    /// Grows the box to hold `o`.
    #[inline]
    pub fn union(&mut self, o: &Aabb) {
        for c in 0..3 {
            self.lo[c] = self.lo[c].min(o.lo[c]);
            self.hi[c] = self.hi[c].max(o.hi[c]);
        }
    }

    /// Whether the closed boxes share a point.
    #[inline]
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.lo[0] <= o.hi[0]
            && o.lo[0] <= self.hi[0]
            && self.lo[1] <= o.hi[1]
            && o.lo[1] <= self.hi[1]
            && self.lo[2] <= o.hi[2]
            && o.lo[2] <= self.hi[2]
    }

    /// The box widened by `m` in y and z (a safety margin, see
    /// [`crate::level3`]).
    #[inline]
    pub fn widened_yz(mut self, m: f64) -> Aabb {
        for c in 1..3 {
            self.lo[c] -= m;
            self.hi[c] += m;
        }
        self
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bb: Aabb,
    /// Leaf: first item; inner: index of the second child (the first child
    /// follows the node directly).
    a: u32,
    /// Leaf: number of items (> 0); inner: 0.
    count: u32,
}

/// A binary BVH built by median splits on the longest centroid axis.
pub(crate) struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
}

const LEAF: usize = 4;

impl Bvh {
    /// Builds the hierarchy over `boxes` (empty boxes are never reported).
    pub fn new(boxes: &[Aabb]) -> Bvh {
        let mut items: Vec<u32> = (0..boxes.len() as u32)
            .filter(|&i| boxes[i as usize].lo[0] <= boxes[i as usize].hi[0])
            .collect();
        let mut nodes = Vec::with_capacity(2 * items.len() / LEAF + 1);
        if !items.is_empty() {
            let n = items.len();
            build(boxes, &mut items, 0, n, &mut nodes);
        }
        Bvh { nodes, items }
    }

    /// Calls `f` for every item whose box overlaps the closed box `q`, in a
    /// deterministic order.
    #[inline]
    pub fn query(&self, q: &Aabb, boxes: &[Aabb], mut f: impl FnMut(u32)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack: SmallVec<[u32; 64]> = SmallVec::new();
        stack.push(0);
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n as usize];
            if !node.bb.overlaps(q) {
                continue;
            }
            if node.count > 0 {
                let s = node.a as usize;
                for &i in &self.items[s..s + node.count as usize] {
                    if boxes[i as usize].overlaps(q) {
                        f(i);
                    }
                }
            } else {
                stack.push(node.a);
                stack.push(n + 1);
            }
        }
    }
}

fn build(boxes: &[Aabb], items: &mut [u32], offset: usize, n: usize, nodes: &mut Vec<Node>) {
    let mut bb = Aabb::EMPTY;
    let mut cb = Aabb::EMPTY;
    for &i in items.iter() {
        let b = &boxes[i as usize];
        bb.union(b);
        cb.add(&centroid(b));
    }
    let me = nodes.len();
    nodes.push(Node {
        bb,
        a: offset as u32,
        count: n as u32,
    });
    if n <= LEAF {
        return;
    }
    let mut axis = 0;
    let mut ext = -1.0;
    for c in 0..3 {
        let e = cb.hi[c] - cb.lo[c];
        if e > ext {
            ext = e;
            axis = c;
        }
    }
    let mid = n / 2;
    items.select_nth_unstable_by(mid, |&p, &q| {
        centroid(&boxes[p as usize])[axis]
            .total_cmp(&centroid(&boxes[q as usize])[axis])
            .then(p.cmp(&q))
    });
    let (left, right) = items.split_at_mut(mid);
    build(boxes, left, offset, mid, nodes);
    let second = nodes.len();
    build(boxes, right, offset + mid, n - mid, nodes);
    nodes[me].a = second as u32;
    nodes[me].count = 0;
}

#[inline]
fn centroid(b: &Aabb) -> [f64; 3] {
    // Halves first so that huge coordinates cannot overflow.
    [
        b.lo[0] * 0.5 + b.hi[0] * 0.5,
        b.lo[1] * 0.5 + b.hi[1] * 0.5,
        b.lo[2] * 0.5 + b.hi[2] * 0.5,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn query_matches_brute_force() {
        let mut boxes = Vec::new();
        let mut s = 12345u64;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..300 {
            let p = [rnd(), rnd(), rnd()];
            let q = [p[0] + rnd() * 0.1, p[1] + rnd() * 0.1, p[2] + rnd() * 0.1];
            boxes.push(Aabb { lo: p, hi: q });
        }
        let bvh = Bvh::new(&boxes);
        for _ in 0..50 {
            let p = [rnd(), rnd(), rnd()];
            let q = Aabb {
                lo: p,
                hi: [p[0] + 0.2, p[1] + 0.05, p[2] + 0.3],
            };
            let mut got = Vec::new();
            bvh.query(&q, &boxes, |i| got.push(i));
            got.sort_unstable();
            let want: Vec<u32> = (0..boxes.len() as u32)
                .filter(|&i| boxes[i as usize].overlaps(&q))
                .collect();
            assert_eq!(got, want);
        }
    }
}
