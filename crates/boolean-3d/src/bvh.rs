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
///
/// Without branches on the comparison: it is true for about half of all
/// inputs, and a mispredicted branch per bound was most of the cost of
/// the broad phase's boxes.
#[inline]
fn down(x: f64) -> f32 {
    let f = x as f32;
    // The next `f32` below `f` (never taken for NaN or `-inf`, for
    // which the comparison is false): a zero steps to `-tiny`, other
    // values one unit of their bit pattern towards `-inf`.
    let bits = if f == 0.0 { 0x8000_0000 } else { f.to_bits() };
    let sign = (bits as i32) >> 31;
    let next = f32::from_bits(bits.wrapping_add((-2 * sign - 1) as u32));
    if f64::from(f) > x {
        next
    } else {
        f
    }
}

/// The smallest `f32` not below `x` (`+inf` above the range); like
/// [`down`], without branches.
#[inline]
fn up(x: f64) -> f32 {
    let f = x as f32;
    // The next `f32` above `f`: a zero steps to `+tiny`, other values
    // one unit of their bit pattern towards `+inf`.
    let bits = if f == 0.0 { 0 } else { f.to_bits() };
    let sign = (bits as i32) >> 31;
    let next = f32::from_bits(bits.wrapping_add((2 * sign + 1) as u32));
    if f64::from(f) < x {
        next
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

    /// Grows the box to hold `o`.
    #[inline]
    pub fn union(&mut self, o: &Aabb) {
        // Plain comparisons (one instruction each, where `f32::min` also
        // sorts out NaN): a bound of `o` that is NaN is never taken, so a
        // box without NaN stays without.
        for c in 0..3 {
            if o.lo[c] < self.lo[c] {
                self.lo[c] = o.lo[c];
            }
            if o.hi[c] > self.hi[c] {
                self.hi[c] = o.hi[c];
            }
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

#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    bb: Aabb,
    /// Leaf: first item; inner: index of the second child (the first child
    /// follows the node directly).
    a: u32,
    /// Leaf: number of items (> 0); inner: 0.
    count: u32,
}

/// A binary BVH over items sorted along a Morton (Z-order) curve of their
/// box centres, split at the middle of each range: a linear build (a radix
/// sort of the codes, then the nodes, the halves of large ranges in
/// parallel), the same hierarchy whatever the threads, deterministic for
/// a given input. The nodes are in pre-order in one array of the exact
/// size; a leaf holds up to [`LEAF`] items.
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

/// The most items in a leaf. Eight rather than four halves the nodes
/// (the build's time and the hierarchy's memory) for a few more box tests
/// in the pair search.
const LEAF: usize = 8;

impl Node {
    /// A placeholder, overwritten by the build.
    const PLACEHOLDER: Node = Node {
        bb: Aabb::EMPTY,
        a: 0,
        count: 0,
    };
}

impl Bvh {
    /// Builds the hierarchy over `boxes` (empty boxes are never reported).
    pub fn new(boxes: &[Aabb]) -> Bvh {
        let items = morton_order(boxes);
        // The exact node count: a realloc of a guessed capacity doubles
        // the largest array of the broad phase at the peak of memory use.
        let mut nodes = vec![Node::PLACEHOLDER; node_count(items.len())];
        if !items.is_empty() {
            build(boxes, &items, 0, &mut nodes, 0);
        }
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

/// The live items of `boxes` sorted by the Morton code of their box
/// centres within the bound of every live centre, ties by index.
fn morton_order(boxes: &[Aabb]) -> Vec<u32> {
    let quantiser = Quantiser::new(&centre_bound(boxes));
    let keys = radix_sort_codes(morton_keys(boxes, &quantiser));
    // A fresh allocation of the exact size (collecting in place would keep
    // the keys' buffer, twice the size, for the hierarchy's lifetime).
    let mut items = Vec::with_capacity(keys.len());
    items.extend(keys.iter().map(|&k| k as u32));
    items
}

/// The bound of the live boxes' centres, exact in double precision and
/// rounded outwards once (rounding is monotone: the same bound as rounding
/// every centre first). Minimum and maximum are exact, so the parallel
/// reduction does not depend on how the work was split.
fn centre_bound(boxes: &[Aabb]) -> Aabb {
    // In chunks, each bounded by a plain loop (a per-item fold does not
    // inline, and copies its state in and out for every box).
    const CHUNK: usize = 1024;
    let (lo, hi) = boxes
        .par_chunks(CHUNK)
        .with_min_len(par::min_len(CHUNK))
        .map(|chunk| {
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            for b in chunk.iter().filter(|b| live(b)) {
                let c = centroid(b);
                grow(&mut lo, &mut hi, &c, &c);
            }
            (lo, hi)
        })
        .reduce(
            || ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]),
            |(mut lo, mut hi), (l, h)| {
                grow(&mut lo, &mut hi, &l, &h);
                (lo, hi)
            },
        );
    Aabb::new(lo, hi)
}

/// `code << 32 | index` of every live box: distinct keys whose order is
/// (code, index).
fn morton_keys(boxes: &[Aabb], quantiser: &Quantiser) -> Vec<u64> {
    // `u64::MAX` (above every key) for the empty boxes, then dropped: an
    // indexed map collects in place, without the reallocations of a
    // filtered one.
    let mut keys: Vec<u64> = boxes
        .par_iter()
        .with_min_len(par::min_len(1))
        .enumerate()
        .map(|(i, b)| {
            if live(b) {
                (u64::from(quantiser.code(&centroid(b))) << 32) | i as u64
            } else {
                u64::MAX
            }
        })
        .collect();
    keys.retain(|&k| k != u64::MAX);
    keys
}

/// Grows the bound `[lo, hi]` to hold `[l, h]` by plain comparisons (NaN
/// is never taken; minimum and maximum are exact, so the order of the
/// growth does not matter).
#[inline]
fn grow(lo: &mut [f64; 3], hi: &mut [f64; 3], l: &[f64; 3], h: &[f64; 3]) {
    for c in 0..3 {
        if l[c] < lo[c] {
            lo[c] = l[c];
        }
        if h[c] > hi[c] {
            hi[c] = h[c];
        }
    }
}

/// Sorts `code << 32 | index` keys (30-bit codes) by a least-significant
/// digit radix sort of the code, three digits of 10 bits (a pass whose
/// digit is the same for every key is skipped). Stable, so the indices of
/// equal codes keep their (increasing) order: the keys end up in
/// increasing order, deterministically.
fn radix_sort_codes(mut keys: Vec<u64>) -> Vec<u64> {
    const BITS: u32 = 10;
    const DIGITS: usize = 1 << BITS;
    const PASSES: usize = 30usize.div_ceil(BITS as usize);
    let digit = |k: u64, pass: u32| ((k >> (32 + BITS * pass)) as usize) & (DIGITS - 1);
    // Every pass's histogram in one read of the keys.
    let mut count = vec![[0u32; DIGITS]; PASSES];
    for &k in &keys {
        for (pass, c) in count.iter_mut().enumerate() {
            c[digit(k, pass as u32)] += 1;
        }
    }
    let mut tmp = vec![0u64; keys.len()];
    for (pass, c) in count.iter().enumerate() {
        if c.iter().any(|&n| n as usize == keys.len()) {
            continue;
        }
        let mut next = [0u32; DIGITS];
        let mut sum = 0;
        for d in 0..DIGITS {
            next[d] = sum;
            sum += c[d];
        }
        for &k in &keys {
            let d = digit(k, pass as u32);
            tmp[next[d] as usize] = k;
            next[d] += 1;
        }
        std::mem::swap(&mut keys, &mut tmp);
    }
    keys
}

/// The Morton codes of points quantised to 10 bits per axis within a
/// box: the box's terms of the quantisation, computed once.
struct Quantiser {
    /// Half the box's lower corner.
    half_lo: [f64; 3],
    /// Half the box's extent (halves first so that huge coordinates
    /// cannot overflow).
    half_ext: [f64; 3],
}

impl Quantiser {
    fn new(cb: &Aabb) -> Quantiser {
        let half_lo = cb.lo.map(|x| f64::from(x) * 0.5);
        let mut half_ext = [0.0; 3];
        for c in 0..3 {
            half_ext[c] = f64::from(cb.hi[c]) * 0.5 - half_lo[c];
        }
        Quantiser { half_lo, half_ext }
    }

    /// The 30-bit Morton code of `p`.
    #[inline]
    fn code(&self, p: &[f64; 3]) -> u32 {
        // Every quotient computed (and dropped where the extent is not
        // positive): no branch between the divisions, which then pair up.
        let mut t = [0.0f64; 3];
        for c in 0..3 {
            let q = (p[c] * 0.5 - self.half_lo[c]) / self.half_ext[c];
            t[c] = if self.half_ext[c] > 0.0 { q } else { 0.0 };
        }
        let mut code = 0u32;
        for (c, t) in t.into_iter().enumerate() {
            // In 0..=1023 (NaN gives 0).
            let q = (t.clamp(0.0, 1.0) * 1023.0) as usize;
            code |= SPREAD[q & 1023] << c;
        }
        code
    }
}

/// [`spread`] of every 10-bit value.
static SPREAD: [u32; 1024] = {
    let mut t = [0u32; 1024];
    let mut i = 0;
    while i < 1024 {
        t[i] = spread(i as u64) as u32;
        i += 1;
    }
    t
};

/// Spreads the low 21 bits of `x` to every third bit.
const fn spread(mut x: u64) -> u64 {
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

/// Builds the subtree over `items` (which start at `start` in the whole
/// list) into `nodes`, exactly [`node_count`]`(items.len())` of them, in
/// pre-order (first child right after its parent), `base` being the index
/// of `nodes[0]` in the whole array; returns the subtree's box. The two
/// halves of a large range are built in parallel, into disjoint parts of
/// the array that the sequential build would fill the same way.
fn build(boxes: &[Aabb], items: &[u32], start: usize, nodes: &mut [Node], base: usize) -> Aabb {
    let n = items.len();
    let mid = n / 2;
    if n <= LEAF || !par::worth_splitting(mid) {
        let mut next = 0;
        let bb = build_seq(boxes, items, start, nodes, base, &mut next);
        debug_assert_eq!(next, nodes.len());
        return bb;
    }
    let (me, rest) = nodes.split_first_mut().expect("a node per range");
    let (first, second) = rest.split_at_mut(node_count(mid));
    let second_index = base + 1 + first.len();
    let (mut bb, b2) = par::join(
        mid,
        || build(boxes, &items[..mid], start, first, base + 1),
        || build(boxes, &items[mid..], start + mid, second, second_index),
    );
    bb.union(&b2);
    *me = Node {
        bb,
        a: second_index as u32,
        count: 0,
    };
    bb
}

/// [`build`] on one thread: the subtree over `items` goes to
/// `nodes[*next..]`, and `*next` moves past it.
fn build_seq(
    boxes: &[Aabb],
    items: &[u32],
    start: usize,
    nodes: &mut [Node],
    base: usize,
    next: &mut usize,
) -> Aabb {
    let me = *next;
    *next += 1;
    let n = items.len();
    let node = if n <= LEAF {
        let mut bb = Aabb::EMPTY;
        for &i in items {
            bb.union(&boxes[i as usize]);
        }
        Node {
            bb,
            a: start as u32,
            count: n as u32,
        }
    } else {
        let mid = n / 2;
        let mut bb = build_seq(boxes, &items[..mid], start, nodes, base, next);
        let second = base + *next;
        bb.union(&build_seq(
            boxes,
            &items[mid..],
            start + mid,
            nodes,
            base,
            next,
        ));
        Node {
            bb,
            a: second as u32,
            count: 0,
        }
    };
    nodes[me] = node;
    node.bb
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

/// Property tests of the hierarchy against brute force and against the
/// build it replaced, and of the rounding against the standard library.
#[cfg(test)]
mod props {
    use super::*;
    use crate::mesh::Flat;
    use crate::par::FORCE;
    use proptest::prelude::*;
    use std::sync::atomic::Ordering;
    use test_support::shapes::{tetra, uv_sphere};
    use test_support::strategies::{float_coord, garbage_coord, grid_coord};

    /// [`down`] by `f32::next_down`, with a branch.
    fn down_ref(x: f64) -> f32 {
        let f = x as f32;
        if f64::from(f) > x {
            f.next_down()
        } else {
            f
        }
    }

    /// [`up`] by `f32::next_up`, with a branch.
    fn up_ref(x: f64) -> f32 {
        let f = x as f32;
        if f64::from(f) < x {
            f.next_up()
        } else {
            f
        }
    }

    /// The 30-bit Morton code of `p` quantised to 10 bits per axis within
    /// `cb`, computed from the box's bounds.
    fn morton_ref(p: &[f64; 3], cb: &Aabb) -> u32 {
        let mut code = 0u64;
        for (c, &pc) in p.iter().enumerate() {
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

    /// The hierarchy as the plain recursive build makes it: the live items
    /// sorted by (Morton code, index) within the bound grown centre by
    /// centre (each rounded outwards), the nodes pushed in pre-order.
    fn reference(boxes: &[Aabb]) -> (Vec<Node>, Vec<u32>) {
        fn push(boxes: &[Aabb], items: &[u32], start: usize, end: usize, nodes: &mut Vec<Node>) {
            let me = nodes.len();
            nodes.push(Node {
                bb: Aabb::EMPTY,
                a: start as u32,
                count: (end - start) as u32,
            });
            if end - start <= LEAF {
                for &i in &items[start..end] {
                    nodes[me].bb.union(&boxes[i as usize]);
                }
            } else {
                let mid = start + (end - start) / 2;
                push(boxes, items, start, mid, nodes);
                let second = nodes.len();
                push(boxes, items, mid, end, nodes);
                let mut bb = nodes[me + 1].bb;
                bb.union(&nodes[second].bb);
                nodes[me] = Node {
                    bb,
                    a: second as u32,
                    count: 0,
                };
            }
        }
        let live: Vec<u32> = (0..boxes.len() as u32)
            .filter(|&i| live(&boxes[i as usize]))
            .collect();
        let mut cb = Aabb::EMPTY;
        for &i in &live {
            for (k, &c) in centroid(&boxes[i as usize]).iter().enumerate() {
                cb.lo[k] = cb.lo[k].min(down_ref(c));
                cb.hi[k] = cb.hi[k].max(up_ref(c));
            }
        }
        let mut items = live;
        items.sort_by_key(|&i| (morton_ref(&centroid(&boxes[i as usize]), &cb), i));
        let mut nodes = Vec::new();
        if !items.is_empty() {
            push(boxes, &items, 0, items.len(), &mut nodes);
        }
        (nodes, items)
    }

    /// Every pair of live boxes within `margin`, by brute force.
    fn brute(a: &[Aabb], b: &[Aabb], margin: f32) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                if live(x) && live(y) && x.within(y, margin) {
                    out.push((i as u32, j as u32));
                }
            }
        }
        out
    }

    fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
        v.sort_unstable();
        v
    }

    fn coord() -> BoxedStrategy<f64> {
        prop_oneof![
            3 => grid_coord(6),
            3 => float_coord().prop_map(|x| 6.0 * x),
            1 => garbage_coord(),
        ]
        .boxed()
    }

    /// Random boxes: small, flat (zero extent), inverted in some axis,
    /// huge (past the `f32` range), and empty.
    fn boxes() -> BoxedStrategy<Vec<Aabb>> {
        let extent = prop_oneof![
            4 => 0.0..1.5f64,
            1 => Just(0.0),
            1 => Just(-0.5),
            1 => Just(1e300),
        ];
        let one = prop_oneof![
            12 => ([coord(), coord(), coord()], [extent.clone(), extent.clone(), extent])
                .prop_map(|(p, e)| Aabb::new(p, [p[0] + e[0], p[1] + e[1], p[2] + e[2]])),
            1 => Just(Aabb::EMPTY),
        ];
        proptest::collection::vec(one, 0..200).boxed()
    }

    /// Builds with the parallel split thresholds forced to `mode`.
    fn forced_build(mode: u8, boxes: &[Aabb]) -> Bvh {
        FORCE.store(mode, Ordering::Relaxed);
        let t = Bvh::new(boxes);
        FORCE.store(0, Ordering::Relaxed);
        t
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(64)))]

        /// The build, sequential and split at every node, is the plain
        /// recursive build node for node (so every query and pair search
        /// visits the same nodes in the same order as before); pairs,
        /// with and without a margin, and queries are brute force's; a
        /// scanned side finds the same pairs.
        #[test]
        fn hierarchy_matches_reference_and_brute_force(a in boxes(), b in boxes()) {
            for x in [&a, &b] {
                let (nodes, items) = reference(x);
                for mode in [1, 2] {
                    let t = forced_build(mode, x);
                    prop_assert_eq!(&t.nodes, &nodes);
                    prop_assert_eq!(&t.items, &items);
                }
            }
            let (ta, tb) = (Bvh::new(&a), Bvh::new(&b));
            for margin in [0.0, 0.25] {
                let want = brute(&a, &b, margin);
                prop_assert_eq!(sorted(ta.pairs_within(&a, &tb, &b, margin)), want.clone());
                prop_assert_eq!(
                    sorted(Bvh::scan(&a).pairs_within(&a, &tb, &b, margin)),
                    want.clone()
                );
                prop_assert_eq!(sorted(ta.pairs_within(&a, &Bvh::scan(&b), &b, margin)), want);
            }
            for q in b.iter().take(20) {
                let mut got = Vec::new();
                ta.query(q, &a, |i| got.push(i));
                got.sort_unstable();
                let want: Vec<u32> = (0..a.len() as u32)
                    .filter(|&i| live(&a[i as usize]) && a[i as usize].overlaps(q))
                    .collect();
                prop_assert_eq!(got, want);
            }
        }

        /// The branch-free rounding is the standard library's, bit for bit.
        #[test]
        fn rounding_matches_next_up_and_down(x in any::<f64>(), g in garbage_coord()) {
            for v in [x, g, g * 1e-30, g * 1e-280] {
                prop_assert_eq!(down(v).to_bits(), down_ref(v).to_bits());
                prop_assert_eq!(up(v).to_bits(), up_ref(v).to_bits());
            }
        }

        /// The facet boxes of a triangle mesh (read three half-edges at a
        /// time) are those of the same facets as polygons, and contain the
        /// facets' exact boxes, widened in y and z.
        #[test]
        fn triangle_boxes_match_polygon_boxes(p in proptest::collection::vec([garbage_coord(), coord(), coord()], 4)) {
            let t = tetra([p[0], p[1], p[2], p[3]]);
            let poly = t.to_polygon_mesh();
            let (ft, fp) = (Flat::from_triangle_mesh(&t).unwrap(), Flat::from_polygon_mesh(&poly).unwrap());
            let margin = 2f64.powi(-20);
            let boxes = ft.facet_boxes(margin);
            prop_assert_eq!(&boxes, &fp.facet_boxes(margin));
            for (f, b) in t.triangles.iter().zip(&boxes) {
                for &v in f {
                    let q = t.vertices[v as usize];
                    let widen = [0.0, margin, margin];
                    for c in 0..3 {
                        prop_assert!(f64::from(b.lo[c]) <= q[c] - widen[c]);
                        prop_assert!(f64::from(b.hi[c]) >= q[c] + widen[c]);
                    }
                }
            }
        }
    }

    #[test]
    fn rounding_at_the_edges_of_f32() {
        let tiny = f64::from(f32::from_bits(1));
        let max = f64::from(f32::MAX);
        for v in [
            0.0,
            -0.0,
            tiny,
            -tiny,
            tiny / 2.0,
            -tiny / 2.0,
            tiny * 1.5,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::from(f32::MIN_POSITIVE) * (1.0 - f64::EPSILON),
            max,
            -max,
            max * (1.0 + f64::EPSILON),
            -max * (1.0 + f64::EPSILON),
            max * 2.0,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            1.0 + f64::EPSILON,
            1.0 - f64::EPSILON,
            -1.0 - f64::EPSILON,
            0.1,
            -0.1,
        ] {
            assert_eq!(down(v).to_bits(), down_ref(v).to_bits(), "{v:e}");
            assert_eq!(up(v).to_bits(), up_ref(v).to_bits(), "{v:e}");
            if !v.is_nan() {
                assert!(f64::from(down(v)) <= v && f64::from(up(v)) >= v, "{v:e}");
            }
        }
    }

    /// A mesh large enough for the parallel build and pair search to split
    /// with the default thresholds: the same hierarchy as the plain build,
    /// and the pairs a sweep along x finds.
    #[test]
    fn large_mesh_hierarchy_matches_reference() {
        let s = uv_sphere([0.0; 3], 1.0, 96, 64);
        let t = uv_sphere([0.3, 0.2, 0.1], 0.9, 64, 48);
        let (fs, ft) = (
            Flat::from_triangle_mesh(&s).unwrap(),
            Flat::from_triangle_mesh(&t).unwrap(),
        );
        let (bs, bt) = (fs.facet_boxes(1e-9), ft.facet_boxes(1e-9));
        assert!(bs.len() >= 2 * crate::par::SEQUENTIAL_BELOW);
        assert!(bt.len() >= crate::par::SEQUENTIAL_BELOW);
        let (rs, items) = reference(&bs);
        let (ts, tt) = (Bvh::new(&bs), Bvh::new(&bt));
        assert_eq!(ts.nodes, rs);
        assert_eq!(ts.items, items);
        // The sweep: B's boxes by lower x; those that can reach a box of A
        // start within the widest B box below its lower x.
        let mut by_x: Vec<u32> = (0..bt.len() as u32).collect();
        by_x.sort_by(|&i, &j| bt[i as usize].lo[0].total_cmp(&bt[j as usize].lo[0]));
        let widest = bt
            .iter()
            .map(|b| f64::from(b.hi[0]) - f64::from(b.lo[0]))
            .fold(0.0, f64::max);
        let mut want = Vec::new();
        for (i, a) in bs.iter().enumerate() {
            let reach = f64::from(a.lo[0]) - widest;
            let first = by_x.partition_point(|&j| f64::from(bt[j as usize].lo[0]) < reach);
            for &j in &by_x[first..] {
                if bt[j as usize].lo[0] > a.hi[0] {
                    break;
                }
                if a.overlaps(&bt[j as usize]) {
                    want.push((i as u32, j));
                }
            }
        }
        want.sort_unstable();
        assert!(!want.is_empty());
        assert_eq!(sorted(ts.pairs(&bs, &tt, &bt)), want);
    }

    /// The steps of the broad phase on one operand of the 1M-triangle
    /// sphere difference on one thread, each the mean of a few runs (`cargo test
    /// --release -p boolean-3d --lib broad_phase_timing -- --ignored
    /// --nocapture`).
    #[test]
    #[ignore = "timing, for release builds"]
    fn broad_phase_timing() {
        /// The CPU time of the current thread (from the scheduler's
        /// statistics) since the start, in ms; wall time where those are
        /// missing.
        struct Cpu(Option<u64>, std::time::Instant);
        fn on_cpu() -> Option<u64> {
            let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
            s.split_whitespace().next()?.parse().ok()
        }
        impl Cpu {
            fn now() -> Cpu {
                Cpu(on_cpu(), std::time::Instant::now())
            }
            fn elapsed_ms(&self) -> f64 {
                match (self.0, on_cpu()) {
                    (Some(a), Some(b)) => (b - a) as f64 * 1e-6,
                    _ => self.1.elapsed().as_secs_f64() * 1e3,
                }
            }
        }
        use Cpu as Instant;
        // The operands of `perf-table-3d`'s 1M row.
        let d = 0.5 / 3f64.sqrt();
        let m = uv_sphere([0.0; 3], 1.0, 1000, 500);
        let o = uv_sphere([d, d * 1.1, d * 0.9], 1.0, 1000, 500);
        let f = Flat::from_triangle_mesh(&m).unwrap();
        let g = Flat::from_triangle_mesh(&o).unwrap();
        let other = g.facet_boxes(1e-12);
        let other_bvh = Bvh::new(&other);
        // The mean of the runs (the scheduler's clock advances by ticks).
        const RUNS: usize = 8;
        let mut best = [0.0; 8];
        let mut time = |k: usize, t: Cpu| best[k] += t.elapsed_ms() / RUNS as f64;
        let mut found = (0, 0);
        // On one thread, timed by its CPU time: other processes on the
        // machine do not count.
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        pool.install(|| {
            for _ in 0..7 {
                let t = Instant::now();
                let boxes = f.facet_boxes(1e-12);
                time(0, t);
                let t = Instant::now();
                let cb = centre_bound(&boxes);
                time(1, t);
                let t = Instant::now();
                let keys = morton_keys(&boxes, &Quantiser::new(&cb));
                time(2, t);
                let t = Instant::now();
                let keys = radix_sort_codes(keys);
                time(3, t);
                drop(keys);
                let t = Instant::now();
                let bvh = Bvh::new(&boxes);
                time(4, t);
                let t = Instant::now();
                let mut nodes = vec![Node::PLACEHOLDER; node_count(bvh.items.len())];
                build(&boxes, &bvh.items, 0, &mut nodes, 0);
                time(5, t);
                assert_eq!(nodes, bvh.nodes);
                drop(nodes);
                let t = Instant::now();
                found.0 = bvh.pairs(&boxes, &other_bvh, &other).len();
                time(6, t);
                // Upward rays from every 10th vertex of the other operand.
                let t = Instant::now();
                found.1 = 0;
                for v in o.vertices.iter().step_by(10) {
                    let q = Aabb::new(*v, [v[0], v[1], f64::INFINITY]);
                    bvh.query(&q, &boxes, |_| found.1 += 1);
                }
                time(7, t);
            }
        });
        eprintln!(
            "{} facets: boxes {:.1} ms, centre bound {:.1}, keys {:.1}, sort {:.1}; \
             Bvh::new {:.1} (build {:.1}); {} pairs {:.1}; {} ray hits {:.1}",
            f.facet_count(),
            best[0],
            best[1],
            best[2],
            best[3],
            best[4],
            best[5],
            found.0,
            best[6],
            found.1,
            best[7],
        );
    }
}
