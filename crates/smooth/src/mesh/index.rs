//! Broad phases of 3D smoothing: a bounding-volume hierarchy over boxes
//! grown by the tolerance (median splits on the longest axis of the box
//! centres, `O(n log n)` to build, a query in `O(log n + hits)` for boxes
//! that do not overlap in bulk), so that vertex-near-edge,
//! edge-near-edge and facet-pair candidates are found without testing all
//! pairs. A grid would not do: one long edge would cover many cells. (An
//! R*-tree crate was measured here first: its bulk loading alone took
//! longer than the Boolean the smoothing follows.) Long edges are joined
//! by pieces ([`near_segment_pairs_where`]) and facets by opposed normal
//! directions ([`opposed_pairs_where`]), so that long triangles side by
//! side in a plane, whose boxes overlap in bulk, do not pair up. 2D
//! smoothing (`planar/broad.rs`) uses the same hierarchy with its boxes
//! lifted to `z = 0`, built in Morton order
//! ([`BoxIndex::by_morton_order`]: a sort and a linear pass), which suits
//! the small, evenly spread boxes of a polygon set's vertices and edges.

use rayon::prelude::*;
use topology::Point3;

/// The least number of parallel tasks of a self-join.
const TASKS: usize = 64;

/// A box with an id.
#[derive(Clone, Copy)]
pub(crate) struct IdBox {
    pub lo: Point3,
    pub hi: Point3,
    pub id: u32,
}

/// The box of `points` grown by `margin` on every side.
pub(crate) fn grown_box(points: impl IntoIterator<Item = Point3>, margin: f64) -> (Point3, Point3) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    for k in 0..3 {
        lo[k] -= margin;
        hi[k] += margin;
    }
    (lo, hi)
}

/// Boxes per leaf.
const LEAF: usize = 4;

/// A node: its box and either two children (`count == 0`, at `first`
/// and `second`) or a leaf: `count` boxes from `first` in leaf order.
struct Node {
    lo: Point3,
    hi: Point3,
    first: u32,
    second: u32,
    count: u32,
}

#[inline]
fn meets(alo: &Point3, ahi: &Point3, blo: &Point3, bhi: &Point3) -> bool {
    (0..3).all(|k| alo[k] <= bhi[k] && blo[k] <= ahi[k])
}

/// Boxes, queried by closed-box intersection.
pub(crate) struct BoxIndex {
    /// The boxes in the tree's leaf order (a leaf's boxes are contiguous).
    boxes: Vec<IdBox>,
    nodes: Vec<Node>,
}

/// Levels of the hierarchy built in parallel (`2^PAR_LEVELS` subtrees).
const PAR_LEVELS: u32 = 4;

/// The box around `boxes` and, for more than [`LEAF`] boxes, the split
/// point `mid = len / 2` after a median selection along the longest axis
/// of the box centres (tie-broken by input position), which permutes
/// `boxes` in place.
fn bound_and_split(boxes: &mut [(IdBox, u32)]) -> (Point3, Point3, Option<usize>) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let (mut clo, mut chi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (b, _) in boxes.iter() {
        for k in 0..3 {
            lo[k] = lo[k].min(b.lo[k]);
            hi[k] = hi[k].max(b.hi[k]);
            let c = 0.5 * b.lo[k] + 0.5 * b.hi[k];
            clo[k] = clo[k].min(c);
            chi[k] = chi[k].max(c);
        }
    }
    let n = boxes.len();
    if n <= LEAF {
        return (lo, hi, None);
    }
    let ext = [chi[0] - clo[0], chi[1] - clo[1], chi[2] - clo[2]];
    let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
        0
    } else if ext[1] >= ext[2] {
        1
    } else {
        2
    };
    let mid = n / 2;
    boxes.select_nth_unstable_by(mid, |(a, ia), (b, ib)| {
        let ca = a.lo[axis] + a.hi[axis];
        let cb = b.lo[axis] + b.hi[axis];
        ca.total_cmp(&cb).then(ia.cmp(ib))
    });
    (lo, hi, Some(mid))
}

/// Appends the subtree over `boxes` (the boxes `base..base + len` of the
/// leaf order) to `nodes` in pre-order; returns its root's index.
fn build_into(boxes: &mut [(IdBox, u32)], base: usize, nodes: &mut Vec<Node>) -> u32 {
    let (lo, hi, split) = bound_and_split(boxes);
    let me = nodes.len() as u32;
    nodes.push(Node {
        lo,
        hi,
        first: base as u32,
        second: 0,
        count: boxes.len() as u32,
    });
    if let Some(mid) = split {
        let (left, right) = boxes.split_at_mut(mid);
        let first = build_into(left, base, nodes);
        let second = build_into(right, base + mid, nodes);
        let node = &mut nodes[me as usize];
        node.first = first;
        node.second = second;
        node.count = 0;
    }
    me
}

/// The nodes of the subtree over `boxes` (the boxes `base..base + len` of
/// the leaf order) in pre-order, with node indices local to the returned
/// vector: the top [`PAR_LEVELS`] levels build their halves in parallel
/// and concatenate them, the levels below append to one vector.
fn build(boxes: &mut [(IdBox, u32)], base: usize, level: u32) -> Vec<Node> {
    if level >= PAR_LEVELS {
        let mut nodes = Vec::with_capacity(boxes.len() / 2 + 1);
        build_into(boxes, base, &mut nodes);
        return nodes;
    }
    let (lo, hi, split) = bound_and_split(boxes);
    let mut nodes = vec![Node {
        lo,
        hi,
        first: base as u32,
        second: 0,
        count: boxes.len() as u32,
    }];
    let Some(mid) = split else {
        return nodes;
    };
    let (left, right) = boxes.split_at_mut(mid);
    let (l, r) = rayon::join(
        || build(left, base, level + 1),
        || build(right, base + mid, level + 1),
    );
    nodes.reserve(l.len() + r.len());
    let second = 1 + l.len() as u32;
    for part in [l, r] {
        let shift = nodes.len() as u32;
        nodes.extend(part.into_iter().map(|mut node| {
            if node.count == 0 {
                node.first += shift;
                node.second += shift;
            }
            node
        }));
    }
    let me = &mut nodes[0];
    me.first = 1;
    me.second = second;
    me.count = 0;
    nodes
}

/// The 21 low bits of `q` moved to every third bit (bit `i` to `3 i`).
fn spread_bits(q: u64) -> u64 {
    let mut x = q & 0x1f_ffff;
    x = (x | (x << 32)) & 0x001f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x001f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

/// Appends the subtree over `boxes` (already in leaf order, the boxes
/// `base..base + len`) to `nodes` in pre-order, halving the run at every
/// level; returns its root's index.
fn build_halving(boxes: &[IdBox], base: usize, nodes: &mut Vec<Node>) -> u32 {
    let me = nodes.len() as u32;
    nodes.push(Node {
        lo: [f64::INFINITY; 3],
        hi: [f64::NEG_INFINITY; 3],
        first: base as u32,
        second: 0,
        count: boxes.len() as u32,
    });
    let (lo, hi) = if boxes.len() <= LEAF {
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for b in boxes {
            for k in 0..3 {
                lo[k] = lo[k].min(b.lo[k]);
                hi[k] = hi[k].max(b.hi[k]);
            }
        }
        (lo, hi)
    } else {
        let mid = boxes.len() / 2;
        let first = build_halving(&boxes[..mid], base, nodes);
        let second = build_halving(&boxes[mid..], base + mid, nodes);
        let (a, b) = (&nodes[first as usize], &nodes[second as usize]);
        let lo = std::array::from_fn(|k| a.lo[k].min(b.lo[k]));
        let hi = std::array::from_fn(|k| a.hi[k].max(b.hi[k]));
        let node = &mut nodes[me as usize];
        node.first = first;
        node.second = second;
        node.count = 0;
        (lo, hi)
    };
    let node = &mut nodes[me as usize];
    node.lo = lo;
    node.hi = hi;
    me
}

impl BoxIndex {
    pub fn new(boxes: Vec<IdBox>) -> BoxIndex {
        // Each box with its input position (the tie-break of the median
        // selections), permuted into leaf order by the build.
        let mut items: Vec<(IdBox, u32)> = boxes
            .into_iter()
            .enumerate()
            .map(|(i, b)| (b, i as u32))
            .collect();
        let nodes = if items.is_empty() {
            Vec::new()
        } else {
            build(&mut items, 0, 0)
        };
        BoxIndex {
            boxes: items.into_iter().map(|(b, _)| b).collect(),
            nodes,
        }
    }

    /// The index of `boxes` built by Morton order instead of median
    /// splits: the box centres quantised to 21 bits per axis over their
    /// bounding box, the boxes sorted by the interleaved code (tie-broken
    /// by input position), then the sorted run halved recursively, each
    /// node's box the union of its children's. `O(n log n)` for the sort
    /// and `O(n)` for the tree, several times cheaper to build than
    /// [`BoxIndex::new`] (whose median selections pass over every box at
    /// every level) and about as good to query where the boxes are small
    /// against their spread and about as numerous everywhere: the
    /// vertices and short edges of a map or a mesh's outline, which 2D
    /// smoothing indexes several times per pass. Queries answer the same
    /// ids either way; only the order of the answers differs.
    pub fn by_morton_order(boxes: Vec<IdBox>) -> BoxIndex {
        const BITS: u32 = 21;
        let (mut clo, mut chi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for b in &boxes {
            for k in 0..3 {
                let c = 0.5 * b.lo[k] + 0.5 * b.hi[k];
                clo[k] = clo[k].min(c);
                chi[k] = chi[k].max(c);
            }
        }
        let scale: [f64; 3] = std::array::from_fn(|k| {
            let ext = chi[k] - clo[k];
            let s = f64::from((1u32 << BITS) - 1) / ext;
            if s.is_finite() && s > 0.0 {
                s
            } else {
                0.0
            }
        });
        let code = |b: &IdBox| -> u64 {
            (0..3).fold(0u64, |acc, k| {
                let c = 0.5 * b.lo[k] + 0.5 * b.hi[k];
                // Saturating: a NaN or out-of-range product lands on an end.
                let q = (((c - clo[k]) * scale[k]) as u64).min((1 << BITS) - 1);
                acc | (spread_bits(q) << k)
            })
        };
        // The codes with the positions, sorted as one `u128` each (the
        // position in the low bits breaks ties), then the boxes gathered
        // once: a sort of 16-byte keys instead of 72-byte records.
        let mut keyed: Vec<u128> = boxes
            .par_iter()
            .enumerate()
            .map(|(i, b)| (u128::from(code(b)) << 32) | i as u128)
            .collect();
        keyed.par_sort_unstable();
        let boxes: Vec<IdBox> = keyed
            .par_iter()
            .map(|&k| boxes[(k & 0xffff_ffff) as usize])
            .collect();
        let mut nodes = Vec::with_capacity(boxes.len() / 2 + 1);
        if !boxes.is_empty() {
            build_halving(&boxes, 0, &mut nodes);
        }
        BoxIndex { boxes, nodes }
    }

    /// Calls `f` with the id of every box meeting `[lo, hi]` (closed), in
    /// no particular order. No allocation: the traversal stack is an
    /// array, as deep as the tree (median splits: `log2(n) + 1 < 64`
    /// levels for `n < 2^32`) plus one.
    pub fn visit(&self, lo: &Point3, hi: &Point3, mut f: impl FnMut(u32)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = [0u32; 66];
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if !meets(&node.lo, &node.hi, lo, hi) {
                continue;
            }
            if node.count == 0 {
                stack[top] = node.second;
                stack[top + 1] = node.first;
                top += 2;
            } else {
                let s = node.first as usize;
                for b in &self.boxes[s..s + node.count as usize] {
                    if meets(&b.lo, &b.hi, lo, hi) {
                        f(b.id);
                    }
                }
            }
        }
    }

    /// `f(i, j)` for every pair of ids `i < j` of boxes that meet, keeping
    /// the `Some` answers, in no particular order (the callers sort). A
    /// self-join of the tree with itself: node pairs whose boxes do not
    /// meet are skipped whole, and every pair of boxes is met once (a
    /// query per box would meet it twice). The node pairs are first split
    /// into at least [`TASKS`] disjoint tasks, run in parallel.
    pub fn pairs_where<T: Send>(&self, f: impl Fn(u32, u32) -> Option<T> + Sync) -> Vec<T> {
        if self.nodes.is_empty() {
            return Vec::new();
        }
        let mut tasks = vec![(0u32, 0u32)];
        while tasks.len() < TASKS {
            let mut next = Vec::with_capacity(4 * tasks.len());
            let mut split = false;
            for &(a, b) in &tasks {
                match self.children(a, b) {
                    Some(kids) => {
                        split = true;
                        next.extend(kids.into_iter().flatten());
                    }
                    None => next.push((a, b)),
                }
            }
            tasks = next;
            if !split {
                break;
            }
        }
        tasks
            .par_iter()
            .map(|&(a, b)| {
                let mut out = Vec::new();
                self.join(a, b, &f, &mut out);
                out
            })
            .flatten_iter()
            .collect()
    }

    /// The node pairs that cover the box pairs of `(a, b)` (`a <= b` in
    /// the sense of the tree's pre-order: `a == b` or disjoint subtrees)
    /// when the two nodes' boxes meet and one of them is internal: `None`
    /// when both are leaves or the boxes do not meet (then
    /// [`BoxIndex::join`] finishes the pair itself).
    fn children(&self, a: u32, b: u32) -> Option<[Option<(u32, u32)>; 3]> {
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        if !meets(&na.lo, &na.hi, &nb.lo, &nb.hi) || (na.count != 0 && nb.count != 0) {
            return None;
        }
        if a == b {
            return Some([
                Some((na.first, na.first)),
                Some((na.first, na.second)),
                Some((na.second, na.second)),
            ]);
        }
        // Split the internal node with the larger box (by the sum of its
        // extents), or the only internal one.
        let ext = |n: &Node| (0..3).map(|k| n.hi[k] - n.lo[k]).sum::<f64>();
        if na.count == 0 && (nb.count != 0 || ext(na) >= ext(nb)) {
            Some([Some((na.first, b)), Some((na.second, b)), None])
        } else {
            Some([Some((a, nb.first)), Some((a, nb.second)), None])
        }
    }

    /// The self-join below the node pair `(a, b)`.
    fn join<T>(&self, a: u32, b: u32, f: &impl Fn(u32, u32) -> Option<T>, out: &mut Vec<T>) {
        if let Some(kids) = self.children(a, b) {
            for (c, d) in kids.into_iter().flatten() {
                self.join(c, d, f, out);
            }
            return;
        }
        let (na, nb) = (&self.nodes[a as usize], &self.nodes[b as usize]);
        if na.count == 0 || nb.count == 0 || !meets(&na.lo, &na.hi, &nb.lo, &nb.hi) {
            return; // boxes apart (both leaves otherwise)
        }
        let la = &self.boxes[na.first as usize..(na.first + na.count) as usize];
        let lb = &self.boxes[nb.first as usize..(nb.first + nb.count) as usize];
        for (x, bi) in la.iter().enumerate() {
            let rest = if a == b { &lb[x + 1..] } else { lb };
            for bj in rest {
                if meets(&bi.lo, &bi.hi, &bj.lo, &bj.hi) {
                    out.extend(f(bi.id.min(bj.id), bi.id.max(bj.id)));
                }
            }
        }
    }

    /// Every pair of ids `(i, j)`, `i < j`, of boxes that meet, sorted.
    #[cfg(test)]
    pub fn pairs(&self) -> Vec<(u32, u32)> {
        let mut p = self.pairs_where(|i, j| Some((i, j)));
        p.sort_unstable();
        p
    }

    /// The ids of the boxes meeting `[lo, hi]` (closed), sorted.
    #[cfg(test)]
    pub fn meeting(&self, lo: Point3, hi: Point3) -> Vec<u32> {
        let mut ids = Vec::new();
        self.visit(&lo, &hi, |i| ids.push(i));
        ids.sort_unstable();
        ids
    }
}

/// The boxes of [`near_segment_pairs_where`]: one per segment, or one per
/// piece of a long segment, grown by `margin`; each box's segment
/// (`owner`), and whether each segment has one box (`whole`).
struct SegmentBoxes {
    boxes: Vec<IdBox>,
    owner: Vec<u32>,
    whole: Vec<bool>,
}

impl SegmentBoxes {
    fn new(ends: &[(Point3, Point3)], margin: f64) -> SegmentBoxes {
        let len = |&(a, b): &(Point3, Point3)| {
            (0..3)
                .map(|k| (b[k] - a[k]) * (b[k] - a[k]))
                .sum::<f64>()
                .sqrt()
        };
        let mut lengths: Vec<f64> = ends.iter().map(len).filter(|l| l.is_finite()).collect();
        let mut piece = if lengths.is_empty() {
            0.0
        } else {
            let mid = lengths.len() / 2;
            2.0 * *lengths.select_nth_unstable_by(mid, f64::total_cmp).1
        };
        if piece > 0.0 {
            let count =
                |piece: f64| -> f64 { lengths.iter().map(|l| (l / piece).ceil().max(1.0)).sum() };
            let most = 4.0 * ends.len() as f64;
            while count(piece) > most {
                piece *= 2.0;
            }
        }
        let mut boxes = Vec::with_capacity(ends.len());
        let mut owner: Vec<u32> = Vec::with_capacity(ends.len());
        let mut whole: Vec<bool> = Vec::with_capacity(ends.len());
        for (i, e) in ends.iter().enumerate() {
            let l = len(e);
            let k = if piece > 0.0 && l > piece && l.is_finite() {
                ((l / piece).ceil() as usize).clamp(1, 256)
            } else {
                1
            };
            whole.push(k == 1);
            let (a, b) = *e;
            if k == 1 {
                let (lo, hi) = grown_box([a, b], margin);
                let id = boxes.len() as u32;
                boxes.push(IdBox { lo, hi, id });
                owner.push(i as u32);
                continue;
            }
            // `a + (b - a) t` is within a few ulps of the true point; the
            // slack covers it, so the pieces' boxes cover the segment.
            let mag = (0..3)
                .map(|c| a[c].abs().max(b[c].abs()))
                .fold(0.0, f64::max);
            let slack = margin + 1e-12 * mag;
            let at = |t: f64| -> Point3 { std::array::from_fn(|c| a[c] + (b[c] - a[c]) * t) };
            for m in 0..k {
                let p = if m == 0 { a } else { at(m as f64 / k as f64) };
                let q = if m + 1 == k {
                    b
                } else {
                    at((m + 1) as f64 / k as f64)
                };
                let (lo, hi) = grown_box([p, q], slack);
                let id = boxes.len() as u32;
                boxes.push(IdBox { lo, hi, id });
                owner.push(i as u32);
            }
        }
        SegmentBoxes {
            boxes,
            owner,
            whole,
        }
    }
}

/// `f(i, j)` for pairs of ids `i < j` of segments `ends[i]` and `ends[j]`
/// whose boxes grown by `margin` meet, each pair once, keeping the `Some`
/// answers in no particular order (the callers sort): every pair of
/// segments within `margin` of each other is among them, and only pairs
/// whose grown whole-segment boxes meet (as [`BoxIndex::pairs_where`]
/// would give them, up to a bound of rounding). A segment longer than
/// twice the median is covered by pieces about that long (longer when
/// there would be more than four pieces per segment), each boxed and grown
/// (with a bound of the rounding of the split points), so that long
/// segments side by side in one plane (a slab's long triangles) pair only
/// where they come close instead of wherever their boxes overlap. Pairs
/// of unsplit segments are answered in the join; the others, which
/// several piece pairs may meet, once each after sorting.
pub(crate) fn near_segment_pairs_where<T: Send>(
    ends: &[(Point3, Point3)],
    margin: f64,
    f: impl Fn(u32, u32) -> Option<T> + Sync,
) -> Vec<T> {
    let SegmentBoxes {
        boxes,
        owner,
        whole,
    } = SegmentBoxes::new(ends, margin);
    // Answers are few (the pairs that do come close); boxed, they keep
    // the join's output small, as the split pairs are many.
    enum Found<T> {
        Answer(Box<T>),
        Split(u32, u32),
    }
    let found = BoxIndex::new(boxes).pairs_where(|p, q| {
        let (i, j) = (owner[p as usize], owner[q as usize]);
        if i == j {
            return None;
        }
        let (i, j) = (i.min(j), i.max(j));
        if whole[i as usize] && whole[j as usize] {
            f(i, j).map(|t| Found::Answer(Box::new(t)))
        } else {
            Some(Found::Split(i, j))
        }
    });
    let mut out = Vec::with_capacity(found.len());
    let mut split = Vec::new();
    for x in found {
        match x {
            Found::Answer(t) => out.push(*t),
            Found::Split(i, j) => split.push((i, j)),
        }
    }
    split.par_sort_unstable();
    split.dedup();
    out.par_extend(split.par_iter().filter_map(|&(i, j)| f(i, j)));
    out
}

/// [`near_segment_pairs_where`] restricted to the pairs with a segment
/// marked in `marked`: the same `Some` answers of `f` (each pair once, as
/// `i < j`) for exactly those pairs, found by querying the marked
/// segments' boxes instead of joining all boxes, so the cost follows the
/// marked segments.
pub(crate) fn near_segment_pairs_marked<T: Send>(
    ends: &[(Point3, Point3)],
    margin: f64,
    marked: &[bool],
    f: impl Fn(u32, u32) -> Option<T> + Sync,
) -> Vec<T> {
    let SegmentBoxes { boxes, owner, .. } = SegmentBoxes::new(ends, margin);
    let queries: Vec<IdBox> = boxes
        .iter()
        .filter(|b| {
            marked
                .get(owner[b.id as usize] as usize)
                .copied()
                .unwrap_or(false)
        })
        .copied()
        .collect();
    if queries.is_empty() {
        return Vec::new();
    }
    let index = BoxIndex::new(boxes);
    let mut pairs: Vec<(u32, u32)> = queries
        .par_iter()
        .flat_map_iter(|q| {
            let mut hits = Vec::new();
            let i = owner[q.id as usize];
            index.visit(&q.lo, &q.hi, |id| {
                let j = owner[id as usize];
                if i != j {
                    hits.push((i.min(j), i.max(j)));
                }
            });
            hits
        })
        .collect();
    pairs.par_sort_unstable();
    pairs.dedup();
    pairs.par_iter().filter_map(|&(i, j)| f(i, j)).collect()
}

/// `f(i, j)` for the pairs of ids `i < j` of boxes that meet and whose
/// `normals` have opposite signs on some axis, each pair once, keeping
/// the `Some` answers in no particular order (the callers sort): every
/// meeting pair whose normals' dot product is negative (one of its terms
/// is then negative) among them. Per axis, the boxes of normals pointing
/// one way are queried in an index of those pointing the other way (a
/// pair opposed on an earlier axis is left to that axis), so that the
/// many meeting pairs of facets facing the same way (a plane of long
/// triangles) are never met.
pub(crate) fn opposed_pairs_where<T: Send>(
    boxes: &[IdBox],
    normals: &[Option<Point3>],
    f: impl Fn(u32, u32) -> Option<T> + Sync,
) -> Vec<T> {
    let sign = |id: u32, k: usize| {
        normals[id as usize].map_or(0, |n| (n[k] > 0.0) as i8 - (n[k] < 0.0) as i8)
    };
    let opposed = |i: u32, j: u32, k: usize| sign(i, k) * sign(j, k) < 0;
    let mut out = Vec::new();
    for k in 0..3 {
        let up: Vec<IdBox> = boxes
            .iter()
            .filter(|b| sign(b.id, k) > 0)
            .copied()
            .collect();
        let down: Vec<&IdBox> = boxes.iter().filter(|b| sign(b.id, k) < 0).collect();
        if up.is_empty() || down.is_empty() {
            continue;
        }
        let index = BoxIndex::new(up);
        let found: Vec<T> = down
            .par_iter()
            .flat_map_iter(|b| {
                let mut hits = Vec::new();
                index.visit(&b.lo, &b.hi, |id| {
                    let (i, j) = (id.min(b.id), id.max(b.id));
                    if (0..k).any(|e| opposed(i, j, e)) {
                        return; // met on an earlier axis
                    }
                    hits.extend(f(i, j));
                });
                hits
            })
            .collect();
        out.extend(found);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::SplitMix64;

    /// The index answers exactly what testing every pair answers.
    #[test]
    fn pairs_and_points_equal_all_pairs() {
        let mut rng = SplitMix64::new(5);
        for n in [0usize, 1, 3, 17, 200] {
            let boxes: Vec<(Point3, Point3)> = (0..n)
                .map(|_| {
                    let lo: Point3 = std::array::from_fn(|_| rng.unit());
                    let hi: Point3 = std::array::from_fn(|k| lo[k] + 0.2 * rng.unit());
                    (lo, hi)
                })
                .collect();
            let id_boxes: Vec<IdBox> = boxes
                .iter()
                .enumerate()
                .map(|(i, &(lo, hi))| IdBox {
                    lo,
                    hi,
                    id: i as u32,
                })
                .collect();
            for index in [
                BoxIndex::new(id_boxes.clone()),
                BoxIndex::by_morton_order(id_boxes),
            ] {
                check_against_all_pairs(&index, &boxes, &mut rng);
            }
        }
    }

    fn check_against_all_pairs(index: &BoxIndex, boxes: &[(Point3, Point3)], rng: &mut SplitMix64) {
        let n = boxes.len();
        {
            let mut want = Vec::new();
            for i in 0..n {
                for j in i + 1..n {
                    if meets(&boxes[i].0, &boxes[i].1, &boxes[j].0, &boxes[j].1) {
                        want.push((i as u32, j as u32));
                    }
                }
            }
            assert_eq!(index.pairs(), want);
            let pts: Vec<(Point3, u32)> = (0..50)
                .map(|v| (std::array::from_fn(|_| rng.unit()), v))
                .collect();
            let mut want = Vec::new();
            for (i, b) in boxes.iter().enumerate() {
                for &(q, v) in &pts {
                    if meets(&b.0, &b.1, &q, &q) {
                        want.push((i as u32, v));
                    }
                }
            }
            want.sort_unstable();
            let mut got = Vec::new();
            for &(q, v) in &pts {
                got.extend(index.meeting(q, q).into_iter().map(|b| (b, v)));
            }
            got.sort_unstable();
            assert_eq!(got, want);
        }
    }

    /// Segments of a slab-like scene: long ones across a plane (fans from
    /// corners, near-parallel strips) and short ones, some off the plane.
    fn segments(rng: &mut SplitMix64, n: usize) -> Vec<(Point3, Point3)> {
        (0..n)
            .map(|i| {
                let p: Point3 = [
                    40.0 * rng.unit(),
                    25.0 * rng.unit(),
                    f64::from(i.is_multiple_of(3)),
                ];
                // Three in five short: the long ones are split in pieces.
                let q: Point3 = match i % 5 {
                    0 => [0.0, 0.0, p[2]],
                    1 => [40.0 * rng.unit(), 25.0 * rng.unit(), p[2]],
                    2 => [p[0] + 30.0, p[1] + 1e-3 * rng.unit(), p[2]],
                    _ => [
                        p[0] + 0.3 * rng.unit(),
                        p[1] + 0.3 * rng.unit(),
                        p[2] + 0.1 * rng.unit(),
                    ],
                };
                (p, q)
            })
            .collect()
    }

    /// Near-segment pairs: every pair whose segments come within the
    /// margin (brute force over all pairs, by the closest points) is
    /// answered, once, and only pairs whose grown whole boxes meet.
    #[test]
    fn near_segment_pairs_hold_every_close_pair_once() {
        use crate::mesh::geom::{dist2, segment_segment};
        let mut rng = SplitMix64::new(11);
        for (n, margin) in [(0usize, 0.1), (2, 0.1), (60, 0.05), (400, 0.02), (400, 0.5)] {
            let segs = segments(&mut rng, n);
            let mut got = near_segment_pairs_where(&segs, margin, |i, j| Some((i, j)));
            got.sort_unstable();
            let mut unique = got.clone();
            unique.dedup();
            assert_eq!(got, unique, "a pair answered twice");
            for i in 0..n {
                for j in i + 1..n {
                    let (a, b) = segs[i];
                    let (c, d) = segs[j];
                    let close = {
                        let (_, _, p, q) = segment_segment(a, b, c, d);
                        dist2(p, q) <= margin * margin
                    };
                    let (alo, ahi) = grown_box([a, b], margin);
                    let (blo, bhi) = grown_box([c, d], margin);
                    let boxes_meet = meets(&alo, &ahi, &blo, &bhi);
                    let found = got.binary_search(&(i as u32, j as u32)).is_ok();
                    assert!(!close || found, "close pair {i} {j} missed");
                    assert!(!found || boxes_meet, "pair {i} {j} beyond the boxes");
                }
            }
        }
    }

    /// Opposed pairs: exactly the meeting pairs with normals of opposite
    /// signs on some axis, each once.
    #[test]
    fn opposed_pairs_are_the_meeting_opposed_pairs() {
        let mut rng = SplitMix64::new(13);
        let n = 300;
        let mut normals = Vec::new();
        let mut boxes = Vec::new();
        for i in 0..n {
            let lo: Point3 = std::array::from_fn(|_| rng.unit());
            let hi: Point3 = std::array::from_fn(|k| lo[k] + 0.3 * rng.unit());
            boxes.push(IdBox {
                lo,
                hi,
                id: i as u32,
            });
            // Axis-aligned normals (zeros on two axes), general ones, none.
            normals.push(match i % 5 {
                0 => None,
                1 => Some([0.0, 0.0, if rng.unit() < 0.5 { 1.0 } else { -1.0 }]),
                _ => Some(std::array::from_fn(|_| rng.unit() - 0.5)),
            });
        }
        let mut got = opposed_pairs_where(&boxes, &normals, |i, j| Some((i, j)));
        got.sort_unstable();
        let mut want = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                let opposed = match (normals[i], normals[j]) {
                    (Some(a), Some(b)) => (0..3).any(|k| a[k] * b[k] < 0.0),
                    _ => false,
                };
                if opposed && meets(&boxes[i].lo, &boxes[i].hi, &boxes[j].lo, &boxes[j].hi) {
                    want.push((i as u32, j as u32));
                }
            }
        }
        assert_eq!(got, want);
    }
}
