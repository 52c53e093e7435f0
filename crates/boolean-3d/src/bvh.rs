//! The broad phase: a bounding-volume hierarchy over closed axis-aligned
//! boxes. It only ever skips pairs whose boxes are disjoint; see
//! [`crate::level3`] for why that is conservative for every X of Table 4.1.
//!
//! Against an operand of a few facets (one step of a chain of small
//! operations), building a hierarchy over the large operand costs more
//! than it saves: [`Bvh::scan`] stands for the plain list of boxes,
//! queried by testing every box. Queries and pair searches report the
//! same items and pairs either way (every live box that overlaps), only
//! in another order, and every caller sums or sorts what it is given.

use crate::par;
use rayon::prelude::*;
use smallvec::SmallVec;

/// A closed axis-aligned box `[lo, hi]` (empty when `lo > hi`) in single
/// precision, every bound rounded outwards from the double-precision value
/// it stands for, so the box always contains the exact box: testing the
/// overlap of such boxes stays conservative while halving the memory and
/// bandwidth of the broad phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    /// The lower corner.
    pub lo: [f32; 3],
    /// The upper corner.
    pub hi: [f32; 3],
}

/// The largest `f32` not above `x` (`-inf` below the range).
#[inline]
fn down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x {
        f.next_down()
    } else {
        f
    }
}

/// The smallest `f32` not below `x` (`+inf` above the range).
#[inline]
fn up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x {
        f.next_up()
    } else {
        f
    }
}

impl Aabb {
    /// The empty box.
    pub const EMPTY: Aabb = Aabb {
        lo: [f32::INFINITY; 3],
        hi: [f32::NEG_INFINITY; 3],
    };

    /// The smallest single-precision box containing `[lo, hi]`.
    #[inline]
    pub fn new(lo: [f64; 3], hi: [f64; 3]) -> Aabb {
        Aabb {
            lo: lo.map(down),
            hi: hi.map(up),
        }
    }

    /// Grows the box to hold `p`.
    #[inline]
    pub fn add(&mut self, p: &[f64; 3]) {
        for (c, &v) in p.iter().enumerate() {
            self.lo[c] = self.lo[c].min(down(v));
            self.hi[c] = self.hi[c].max(up(v));
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

    /// Whether the closed boxes come within `margin` of each other in
    /// every axis (`margin >= 0`; with 0, [`Aabb::overlaps`]).
    #[inline]
    pub fn within(&self, o: &Aabb, margin: f32) -> bool {
        self.lo[0] - margin <= o.hi[0]
            && o.lo[0] - margin <= self.hi[0]
            && self.lo[1] - margin <= o.hi[1]
            && o.lo[1] - margin <= self.hi[1]
            && self.lo[2] - margin <= o.hi[2]
            && o.lo[2] - margin <= self.hi[2]
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

/// A binary BVH over items sorted along a Morton (Z-order) curve of their
/// box centres, split at the middle of each range: an `O(n log n)` build
/// dominated by one sort, deterministic for a given input.
pub(crate) struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
    /// For [`Bvh::scan`]: the box holding every live box (no nodes, no
    /// items).
    scan: Option<Aabb>,
}

/// Whether a box is live (not empty; empty boxes are never reported).
#[inline]
fn live(b: &Aabb) -> bool {
    b.lo[0] <= b.hi[0]
}

const LEAF: usize = 4;

impl Bvh {
    /// Builds the hierarchy over `boxes` (empty boxes are never reported).
    pub fn new(boxes: &[Aabb]) -> Bvh {
        let live: Vec<u32> = (0..boxes.len() as u32)
            .filter(|&i| boxes[i as usize].lo[0] <= boxes[i as usize].hi[0])
            .collect();
        let mut cb = Aabb::EMPTY;
        for &i in &live {
            cb.add(&centroid(&boxes[i as usize]));
        }
        let keys: Vec<u32> = live
            .par_iter()
            .with_min_len(par::min_len(1))
            .map(|&i| morton(&centroid(&boxes[i as usize]), &cb))
            .collect();
        let items = radix_sort_by_key(&live, &keys);
        // The exact node count: a realloc of a guessed capacity doubles
        // the largest array of the broad phase at the peak of memory use.
        let mut nodes = Vec::with_capacity(node_count(items.len()));
        if !items.is_empty() {
            build(boxes, &items, 0, items.len(), &mut nodes);
        }
        debug_assert_eq!(nodes.len(), node_count(items.len()));
        Bvh {
            nodes,
            items,
            scan: None,
        }
    }

    /// No hierarchy over `boxes`: queries test every box. For the large
    /// operand against a small one.
    pub fn scan(boxes: &[Aabb]) -> Bvh {
        let mut bound = Aabb::EMPTY;
        for b in boxes.iter().filter(|b| live(b)) {
            bound.union(b);
        }
        Bvh {
            nodes: Vec::new(),
            items: Vec::new(),
            scan: Some(bound),
        }
    }

    /// Calls `f` for every item whose box overlaps the closed box `q`, in a
    /// deterministic order.
    #[inline]
    pub fn query(&self, q: &Aabb, boxes: &[Aabb], mut f: impl FnMut(u32)) {
        if self.scan.is_some() {
            for (i, b) in boxes.iter().enumerate() {
                if live(b) && b.overlaps(q) {
                    f(i as u32);
                }
            }
            return;
        }
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

/// A stable least-significant-digit radix sort of `items` by the 30-bit
/// `keys` (three passes of 10 bits): linear time, and ties keep their input
/// order, so the result is deterministic.
fn radix_sort_by_key(items: &[u32], keys: &[u32]) -> Vec<u32> {
    let n = items.len();
    let mut idx: Vec<u32> = (0..n as u32).collect();
    let mut tmp = vec![0u32; n];
    for pass in 0..3 {
        let shift = 10 * pass;
        let mut count = [0usize; 1025];
        for &k in keys {
            count[((k >> shift) & 1023) as usize + 1] += 1;
        }
        for d in 0..1024 {
            count[d + 1] += count[d];
        }
        for &i in &idx {
            let d = ((keys[i as usize] >> shift) & 1023) as usize;
            tmp[count[d]] = i;
            count[d] += 1;
        }
        std::mem::swap(&mut idx, &mut tmp);
    }
    idx.into_iter().map(|i| items[i as usize]).collect()
}

/// The 30-bit Morton code of `p` quantised to 10 bits per axis within `cb`.
fn morton(p: &[f64; 3], cb: &Aabb) -> u32 {
    let mut code = 0u64;
    for (c, &pc) in p.iter().enumerate() {
        // Halves first so that huge coordinates cannot overflow.
        let (lo, hi) = (f64::from(cb.lo[c]), f64::from(cb.hi[c]));
        let ext = hi * 0.5 - lo * 0.5;
        let t = if ext > 0.0 {
            (pc * 0.5 - lo * 0.5) / ext
        } else {
            0.0
        };
        let q = (t.clamp(0.0, 1.0) * 1023.0) as u64;
        code |= spread(q) << c;
    }
    code as u32
}

/// Spreads the low 21 bits of `x` to every third bit.
fn spread(mut x: u64) -> u64 {
    x &= 0x1f_ffff;
    x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

/// The number of nodes `build` makes for `n` items: one leaf for at most
/// `LEAF` items, otherwise a node over the two halves. Sibling ranges
/// differ by at most one item, so each level has at most two distinct
/// sizes and the recursion follows `O(log n)` of them.
fn node_count(n: usize) -> usize {
    fn count(n: usize, memo: &mut Vec<(usize, usize)>) -> usize {
        if n == 0 {
            return 0;
        }
        if n <= LEAF {
            return 1;
        }
        if let Some(&(_, c)) = memo.iter().find(|&&(m, _)| m == n) {
            return c;
        }
        let c = 1 + count(n / 2, memo) + count(n - n / 2, memo);
        memo.push((n, c));
        c
    }
    count(n, &mut Vec::new())
}

/// Builds the subtree over `items[start..end]` in pre-order (first child
/// right after its parent) and returns its box.
fn build(boxes: &[Aabb], items: &[u32], start: usize, end: usize, nodes: &mut Vec<Node>) -> Aabb {
    let me = nodes.len();
    nodes.push(Node {
        bb: Aabb::EMPTY,
        a: start as u32,
        count: (end - start) as u32,
    });
    let bb = if end - start <= LEAF {
        let mut bb = Aabb::EMPTY;
        for &i in &items[start..end] {
            bb.union(&boxes[i as usize]);
        }
        bb
    } else {
        let mid = start + (end - start) / 2;
        let mut bb = build(boxes, items, start, mid, nodes);
        let second = nodes.len();
        bb.union(&build(boxes, items, mid, end, nodes));
        nodes[me].a = second as u32;
        nodes[me].count = 0;
        bb
    };
    nodes[me].bb = bb;
    bb
}

impl Bvh {
    /// Every pair `(i, j)` of an item `i` of `self` and `j` of `other`
    /// whose boxes overlap (closed), by a simultaneous descent of both
    /// hierarchies: `O(n + k)` node visits for `k` overlapping pairs in
    /// typical inputs. The top of the descent is expanded breadth first and
    /// the subtrees are descended in parallel; the result is concatenated
    /// in frontier order, so it is deterministic.
    pub fn pairs(&self, boxes: &[Aabb], other: &Bvh, other_boxes: &[Aabb]) -> Vec<(u32, u32)> {
        self.pairs_within(boxes, other, other_boxes, 0.0)
    }

    /// [`Bvh::pairs`] for boxes that come within `margin` (in every axis,
    /// `margin >= 0`) of each other instead of overlapping.
    pub fn pairs_within(
        &self,
        boxes: &[Aabb],
        other: &Bvh,
        other_boxes: &[Aabb],
        margin: f32,
    ) -> Vec<(u32, u32)> {
        if self.scan.is_some() || other.scan.is_some() {
            return self.scan_pairs(boxes, other, other_boxes, margin);
        }
        if self.nodes.is_empty() || other.nodes.is_empty() {
            return Vec::new();
        }
        let mut frontier: Vec<(u32, u32)> = vec![(0, 0)];
        for _ in 0..8 {
            if frontier.len() >= 64 {
                break;
            }
            let mut next = Vec::with_capacity(2 * frontier.len());
            for &(m, n) in &frontier {
                if self.node_pair_overlaps(other, m, n, margin) {
                    match self.split(other, m, n) {
                        Some((x, y)) => next.extend([x, y]),
                        None => next.push((m, n)),
                    }
                }
            }
            frontier = next;
        }
        let descend = |&start: &(u32, u32)| {
            let mut out = Vec::new();
            self.descend(boxes, other, other_boxes, margin, start, &mut out);
            out
        };
        // Subtrees in parallel only when both hierarchies are large.
        let parts: Vec<Vec<(u32, u32)>> =
            if par::worth_splitting(self.items.len().min(other.items.len())) {
                frontier.par_iter().map(descend).collect()
            } else {
                frontier.iter().map(descend).collect()
            };
        parts.concat()
    }

    /// [`Bvh::pairs_within`] when one side is a [`Bvh::scan`]: every live
    /// box of the scanned side near the other side's bound, against every
    /// live box of the other side (the small operand), by item order of
    /// the scanned side.
    fn scan_pairs(
        &self,
        boxes: &[Aabb],
        other: &Bvh,
        other_boxes: &[Aabb],
        margin: f32,
    ) -> Vec<(u32, u32)> {
        // The outer loop runs over the scanned side; `swap` when that is
        // `other`.
        let swap = self.scan.is_none();
        let (outer, inner, inner_bvh) = if swap {
            (other_boxes, boxes, self)
        } else {
            (boxes, other_boxes, other)
        };
        let bound = inner_bvh.bound();
        let inner_live: Vec<u32> = (0..inner.len() as u32)
            .filter(|&j| live(&inner[j as usize]))
            .collect();
        let mut out = Vec::new();
        for (i, bi) in outer.iter().enumerate() {
            if !live(bi) || !bi.within(&bound, margin) {
                continue;
            }
            for &j in &inner_live {
                if bi.within(&inner[j as usize], margin) {
                    out.push(if swap { (j, i as u32) } else { (i as u32, j) });
                }
            }
        }
        out
    }

    /// The box holding every live box.
    fn bound(&self) -> Aabb {
        match (self.scan, self.nodes.first()) {
            (Some(b), _) => b,
            (None, Some(root)) => root.bb,
            (None, None) => Aabb::EMPTY,
        }
    }

    #[inline]
    fn node_pair_overlaps(&self, other: &Bvh, m: u32, n: u32, margin: f32) -> bool {
        self.nodes[m as usize]
            .bb
            .within(&other.nodes[n as usize].bb, margin)
    }

    /// The two child pairs of node pair `(m, n)` (descending the node with
    /// the larger box when both are inner), or `None` for two leaves.
    #[inline]
    fn split(&self, other: &Bvh, m: u32, n: u32) -> Option<((u32, u32), (u32, u32))> {
        let (p, q) = (&self.nodes[m as usize], &other.nodes[n as usize]);
        match (p.count > 0, q.count > 0) {
            (true, true) => None,
            (false, true) => Some(((p.a, n), (m + 1, n))),
            (true, false) => Some(((m, q.a), (m, n + 1))),
            (false, false) => {
                if extent(&p.bb) >= extent(&q.bb) {
                    Some(((p.a, n), (m + 1, n)))
                } else {
                    Some(((m, q.a), (m, n + 1)))
                }
            }
        }
    }

    /// The sequential descent below one node pair.
    fn descend(
        &self,
        boxes: &[Aabb],
        other: &Bvh,
        other_boxes: &[Aabb],
        margin: f32,
        start: (u32, u32),
        out: &mut Vec<(u32, u32)>,
    ) {
        let mut stack: Vec<(u32, u32)> = vec![start];
        while let Some((m, n)) = stack.pop() {
            if !self.node_pair_overlaps(other, m, n, margin) {
                continue;
            }
            match self.split(other, m, n) {
                Some((x, y)) => {
                    stack.push(x);
                    stack.push(y);
                }
                None => {
                    let (p, q) = (&self.nodes[m as usize], &other.nodes[n as usize]);
                    let (ps, qs) = (p.a as usize, q.a as usize);
                    for &i in &self.items[ps..ps + p.count as usize] {
                        let bi = &boxes[i as usize];
                        if !bi.within(&q.bb, margin) {
                            continue;
                        }
                        for &j in &other.items[qs..qs + q.count as usize] {
                            if bi.within(&other_boxes[j as usize], margin) {
                                out.push((i, j));
                            }
                        }
                    }
                }
            }
        }
    }
}

/// The sum of a box's side lengths (halved first so nothing overflows).
#[inline]
fn extent(b: &Aabb) -> f64 {
    (0..3)
        .map(|k| f64::from(b.hi[k]) - f64::from(b.lo[k]))
        .sum()
}

#[inline]
fn centroid(b: &Aabb) -> [f64; 3] {
    // In double precision, halves first: nothing can overflow.
    let c = |k: usize| f64::from(b.lo[k]) * 0.5 + f64::from(b.hi[k]) * 0.5;
    [c(0), c(1), c(2)]
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
            boxes.push(Aabb::new(p, q));
        }
        let bvh = Bvh::new(&boxes);
        for _ in 0..50 {
            let p = [rnd(), rnd(), rnd()];
            let q = Aabb::new(p, [p[0] + 0.2, p[1] + 0.05, p[2] + 0.3]);
            let mut got = Vec::new();
            bvh.query(&q, &boxes, |i| got.push(i));
            got.sort_unstable();
            let want: Vec<u32> = (0..boxes.len() as u32)
                .filter(|&i| boxes[i as usize].overlaps(&q))
                .collect();
            assert_eq!(got, want);
        }
        // Pairs between two hierarchies equal the brute-force pairs.
        let other: Vec<Aabb> = boxes[..120]
            .iter()
            .map(|b| Aabb {
                lo: [b.lo[1], b.lo[2], b.lo[0]],
                hi: [b.hi[1], b.hi[2], b.hi[0]],
            })
            .collect();
        let bvh2 = Bvh::new(&other);
        let mut got = bvh.pairs(&boxes, &bvh2, &other);
        got.sort_unstable();
        let mut want = Vec::new();
        for i in 0..boxes.len() as u32 {
            for j in 0..other.len() as u32 {
                if boxes[i as usize].overlaps(&other[j as usize]) {
                    want.push((i, j));
                }
            }
        }
        assert_eq!(got, want);
        // A scanned side, either way round, with an empty box among the
        // scanned ones and a margin: the same queries and pairs (as sets).
        let mut scanned = boxes.clone();
        scanned[7] = Aabb::EMPTY;
        let (tree, flat) = (Bvh::new(&scanned), Bvh::scan(&scanned));
        for b in &other[..50] {
            let (mut x, mut y) = (Vec::new(), Vec::new());
            tree.query(b, &scanned, |i| x.push(i));
            flat.query(b, &scanned, |i| y.push(i));
            x.sort_unstable();
            assert_eq!(x, y);
        }
        let small = Bvh::new(&other[..20]);
        for margin in [0.0, 0.01] {
            let mut t = tree.pairs_within(&scanned, &small, &other[..20], margin);
            let mut f = flat.pairs_within(&scanned, &small, &other[..20], margin);
            t.sort_unstable();
            f.sort_unstable();
            assert!(!t.is_empty());
            assert_eq!(t, f);
            let mut t = small.pairs_within(&other[..20], &tree, &scanned, margin);
            let mut f = small.pairs_within(&other[..20], &flat, &scanned, margin);
            t.sort_unstable();
            f.sort_unstable();
            assert_eq!(t, f);
        }
    }
}
