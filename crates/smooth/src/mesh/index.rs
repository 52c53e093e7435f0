//! Broad phases of 3D smoothing: a bounding-volume hierarchy over boxes
//! grown by the tolerance (median splits on the longest axis of the box
//! centres, `O(n log n)` to build, a query in `O(log n + hits)` for boxes
//! that do not overlap in bulk), so that vertex-near-edge,
//! edge-near-edge and facet-pair candidates are found without testing all
//! pairs. A grid would not do: one long edge would cover many cells. (An
//! R*-tree crate was measured here first: its bulk loading alone took
//! longer than the Boolean the smoothing follows.)

use rayon::prelude::*;
use topology::Point3;

/// The least number of parallel tasks of a self-join.
const TASKS: usize = 64;

/// A box with an id.
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
            let index = BoxIndex::new(
                boxes
                    .iter()
                    .enumerate()
                    .map(|(i, &(lo, hi))| IdBox {
                        lo,
                        hi,
                        id: i as u32,
                    })
                    .collect(),
            );
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
}
