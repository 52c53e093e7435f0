//! A dynamic set of closed intervals over a fixed universe, reporting the
//! members that overlap a query interval in `O((1 + r) log n)` for `r`
//! reported members: the y-structure of the fast path's sweeps in x
//! (`fast.rs`), which must find the pairs of Table 4.1 whose `X` is not
//! provably 0 without visiting the others.
//!
//! The universe (every interval that may ever be a member) is known in
//! advance, so the structure is static: the intervals sit in slots sorted by
//! lower end, the slots are grouped in buckets of [`BUCKET`], and a complete
//! binary tree over the buckets holds, for each node, the largest upper end
//! of the present members below it (`-inf` when none). A query `[lo, hi]`
//! walks down from the root into the buckets whose first lower end is
//! `<= hi` (a prefix of the buckets) and prunes every node whose largest
//! upper end is `< lo`; in a bucket it reaches it tests each slot.
//! Every node or bucket it enters either holds a member it reports or
//! straddles the end of the prefix (one per level), hence the bound; the
//! buckets only shrink the tree (a constant factor, for the cache).
//! Comparisons are closed at both ends, so touching intervals overlap (the
//! symbolic perturbation of eq. 4.1 decides ties later, never the broad
//! phase).

use robust_arith::total_order_key;

/// Slots per leaf bucket of the tree.
const BUCKET: usize = 16;

/// A subset of a fixed list of closed intervals `[lo, hi]`, items numbered
/// by their position in that list.
#[derive(Clone, Debug)]
pub(crate) struct IntervalSet {
    /// Lower ends in slot order (ascending by `f64::total_cmp`).
    lo: Vec<f64>,
    /// Upper ends in slot order.
    hi: Vec<f64>,
    /// Upper ends in slot order of the present members, `-inf` elsewhere.
    live_hi: Vec<f64>,
    /// The item in each slot.
    item: Vec<u32>,
    /// The slot of each item.
    slot: Vec<u32>,
    /// The lower end of each bucket's first slot.
    bucket_lo: Vec<f64>,
    /// Number of tree leaves: the smallest power of two `>=` the number of
    /// buckets (at least 1).
    leaves: usize,
    /// Max tree: node 1 is the root, node `k` has children `2k` and
    /// `2k + 1`, leaf `leaves + b` is bucket `b`. Each node holds the largest
    /// upper end of the present members below it, or `-inf`.
    max_hi: Vec<f64>,
}

impl IntervalSet {
    /// An empty set over the universe `intervals` (item `i` is
    /// `intervals[i]`, with `lo <= hi` and neither NaN).
    pub(crate) fn new(intervals: &[(f64, f64)]) -> Self {
        let n = intervals.len();
        // Sort by the integer image of `f64::total_cmp` (the same order,
        // cheaper to compare), ties by item.
        let mut order: Vec<(u64, u32)> = intervals
            .iter()
            .enumerate()
            .map(|(i, iv)| (total_order_key(iv.0), i as u32))
            .collect();
        order.sort_unstable();
        let mut slot = vec![0u32; n];
        for (s, &(_, i)) in order.iter().enumerate() {
            slot[i as usize] = s as u32;
        }
        let lo: Vec<f64> = order.iter().map(|p| intervals[p.1 as usize].0).collect();
        let leaves = n.div_ceil(BUCKET).next_power_of_two().max(1);
        IntervalSet {
            bucket_lo: lo.iter().step_by(BUCKET).copied().collect(),
            lo,
            hi: order.iter().map(|p| intervals[p.1 as usize].1).collect(),
            live_hi: vec![f64::NEG_INFINITY; n],
            item: order.iter().map(|p| p.1).collect(),
            slot,
            leaves,
            max_hi: vec![f64::NEG_INFINITY; 2 * leaves],
        }
    }

    /// Makes item `i` a member (it must not be one).
    pub(crate) fn insert(&mut self, i: u32) {
        let s = self.slot[i as usize] as usize;
        debug_assert!(self.live_hi[s] == f64::NEG_INFINITY, "item already present");
        let value = self.hi[s];
        self.live_hi[s] = value;
        // A maximum only grows: stop at the first node that already covers
        // the new value.
        let mut node = self.leaves + s / BUCKET;
        while node >= 1 && self.max_hi[node] < value {
            self.max_hi[node] = value;
            node /= 2;
        }
    }

    /// Removes item `i` (it must be a member).
    pub(crate) fn remove(&mut self, i: u32) {
        let s = self.slot[i as usize] as usize;
        debug_assert!(self.live_hi[s] != f64::NEG_INFINITY, "item not present");
        self.live_hi[s] = f64::NEG_INFINITY;
        let b = s / BUCKET;
        let end = (b * BUCKET + BUCKET).min(self.live_hi.len());
        let mut value = f64::NEG_INFINITY;
        for &h in &self.live_hi[b * BUCKET..end] {
            if h > value {
                value = h;
            }
        }
        // Recompute the ancestors; once one keeps its value, so do all
        // above it.
        let mut node = self.leaves + b;
        loop {
            if self.max_hi[node] == value {
                break;
            }
            self.max_hi[node] = value;
            if node == 1 {
                break;
            }
            node /= 2;
            value = self.max_hi[2 * node].max(self.max_hi[2 * node + 1]);
        }
    }

    /// Appends to `out` (after clearing it) every member `i` whose interval
    /// overlaps the closed interval `[lo, hi]`: `lo_i <= hi` and
    /// `hi_i >= lo`, in slot order.
    pub(crate) fn overlapping(&self, lo: f64, hi: f64, out: &mut Vec<u32>) {
        out.clear();
        // A depth-first walk in slot order without a stack: `node` at depth
        // `d` covers the `leaves >> d` buckets from `(node - 2^d) *
        // (leaves >> d)` on. Only buckets whose first lower end is <= hi
        // can hold a member with `lo_i <= hi`; they form a prefix (the
        // predicate is monotone along the slots' total order, equal values
        // and the two zeros comparing equal under `<=`), so the walk stops
        // at the first node that starts beyond it.
        let mut node = 1usize;
        loop {
            let depth = node.ilog2();
            let width = self.leaves >> depth;
            let first = (node - (1 << depth)) * width;
            match self.bucket_lo.get(first) {
                Some(&l) if l <= hi => {}
                _ => return,
            }
            if self.max_hi[node] >= lo {
                if width > 1 {
                    node *= 2;
                    continue;
                }
                let slots = first * BUCKET..(first * BUCKET + BUCKET).min(self.lo.len());
                for s in slots {
                    if self.live_hi[s] >= lo && self.lo[s] <= hi {
                        out.push(self.item[s]);
                    }
                }
            }
            // Next node in depth-first order: climb while a right child,
            // then step to the right sibling.
            while node & 1 == 1 {
                node /= 2;
            }
            if node == 0 {
                return;
            }
            node += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::Xorshift64;

    #[test]
    fn matches_a_brute_force_list_with_ties() {
        let mut rng = Xorshift64::new(0x9e37_79b9_7f4a_7c15);
        for round in 0..200 {
            let n = 1 + rng.below(if round % 4 == 0 { 300 } else { 60 }) as usize;
            // Integer end points in a small range: ties everywhere, both
            // zeros, degenerate intervals.
            let range = 1 + rng.below(12) as i64;
            let coord = |rng: &mut Xorshift64| {
                let v = rng.below(2 * range as u64 + 1) as i64 - range;
                if v == 0 && rng.below(2) == 0 {
                    -0.0
                } else {
                    v as f64
                }
            };
            let intervals: Vec<(f64, f64)> = (0..n)
                .map(|_| {
                    let (p, q) = (coord(&mut rng), coord(&mut rng));
                    (p.min(q), p.max(q))
                })
                .collect();
            let mut set = IntervalSet::new(&intervals);
            let mut present = vec![false; n];
            let mut out = Vec::new();
            for _ in 0..4 * n + 100 {
                let i = rng.below(n as u64) as usize;
                match rng.below(3) {
                    0 if !present[i] => {
                        set.insert(i as u32);
                        present[i] = true;
                    }
                    1 if present[i] => {
                        set.remove(i as u32);
                        present[i] = false;
                    }
                    _ => {
                        let (p, q) = (coord(&mut rng), coord(&mut rng));
                        let (lo, hi) = (p.min(q), p.max(q));
                        set.overlapping(lo, hi, &mut out);
                        out.sort_unstable();
                        let want: Vec<u32> = (0..n)
                            .filter(|&k| present[k] && intervals[k].0 <= hi && intervals[k].1 >= lo)
                            .map(|k| k as u32)
                            .collect();
                        assert_eq!(out, want, "round {round}, query [{lo}, {hi}]");
                    }
                }
            }
        }
    }

    #[test]
    fn empty_universe_and_single_item() {
        let mut out = vec![7];
        IntervalSet::new(&[]).overlapping(0.0, 1.0, &mut out);
        assert!(out.is_empty());
        let mut set = IntervalSet::new(&[(1.0, 2.0)]);
        set.overlapping(2.0, 3.0, &mut out);
        assert!(out.is_empty());
        set.insert(0);
        set.overlapping(2.0, 3.0, &mut out);
        assert_eq!(out, [0]);
        set.overlapping(0.0, 0.5, &mut out);
        assert!(out.is_empty());
        set.remove(0);
        set.overlapping(2.0, 3.0, &mut out);
        assert!(out.is_empty());
    }
}
