//! The right end points of the sweep-line edges (section 7.4.1): how many
//! sweep-line edges end at each point, and a queue of candidate event
//! points that holds every such point.
//!
//! The next event point of the sweep is the smallest left point of a
//! pending edge or right point of a sweep-line edge (section 7.4.1), and
//! the grouping of section 7.6.2 must find every edge that ends there. The
//! sweep needs the right points in order and their counts, not the edges
//! behind them, so no per-edge entry is kept:
//!
//! - every right point of a sweep-line edge is a right point of an input
//!   edge or a point at which an edge was split; a split point is the left
//!   point of the buffer edge created with it (section 7.4.1), so it is
//!   already an event through the pending edges, and the input right points
//!   are sorted once, before the sweep, into [`EndPoints::candidate`]'s
//!   list;
//! - the few right points that are neither (a point reached again after a
//!   backward step of section 7.6.1, the upper end of a split downward
//!   vertical edge whose buffer part is reversed) go to a small heap;
//! - the counts live in a hash map holding the distinct right points of the
//!   sweep line, kept only while the line is long: on a short line the
//!   sweep counts the edges ending at the event point by looking at each
//!   (a few comparisons per edge), which costs less than the hash updates
//!   of every insertion and split.
//!
//! A candidate at which no edge ends and no pending edge starts (its edges
//! were shortened, or cancelled when merged) is passed over by the sweep
//! exactly as the exact multiset of right points would never have produced
//! it: every event point with work to do is still reached, in the same
//! order. Per event this costs a few hash operations instead of a heap
//! operation per edge.

use crate::point::{PointMap, Pt};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// Counts of sweep-line edges by right point, and the queue of candidate
/// event points that covers them.
#[derive(Debug, Default)]
pub(crate) struct EndPoints {
    /// The distinct right points of the input edges (as [`Pt::sort_key`]),
    /// increasing; those before `next` have been passed.
    input: Vec<u128>,
    next: usize,
    /// Right points not covered by `input` or the pending edges.
    extra: BinaryHeap<Reverse<u128>>,
    /// The number of sweep-line edges ending at each point (no zeros),
    /// while `counting`.
    count: PointMap<u32>,
    counting: bool,
    /// The largest candidate passed so far: a right point beyond it is
    /// still ahead in `input` or among the pending left points.
    passed: Option<u128>,
}

impl EndPoints {
    /// The queue for input edges with the given right points (sort keys, in
    /// any order, repeats allowed).
    pub(crate) fn new(mut input: Vec<u128>) -> Self {
        crate::cells::sort_unstable(&mut input);
        input.dedup();
        EndPoints {
            input,
            ..EndPoints::default()
        }
    }

    /// The smallest candidate event point not passed yet.
    #[inline]
    pub(crate) fn candidate(&self) -> Option<Pt> {
        let a = self.input.get(self.next).copied();
        let b = self.extra.peek().map(|r| r.0);
        match (a, b) {
            (Some(a), Some(b)) => Some(Pt::from_sort_key(a.min(b))),
            (Some(k), None) | (None, Some(k)) => Some(Pt::from_sort_key(k)),
            (None, None) => None,
        }
    }

    /// `true` while the counts are kept.
    #[inline]
    pub(crate) fn counting(&self) -> bool {
        self.counting
    }

    /// Starts keeping the counts; the caller then [`EndPoints::add`]s the
    /// right point of every sweep-line edge.
    pub(crate) fn start_counting(&mut self) {
        self.count.clear();
        self.counting = true;
    }

    /// Stops keeping the counts.
    pub(crate) fn stop_counting(&mut self) {
        self.count.clear();
        self.counting = false;
    }

    /// Marks the event point `p`, the smallest of all candidates and
    /// pending left points, as reached, and returns the number of
    /// sweep-line edges that end there (all of which the event removes),
    /// or `None` when the counts are not kept.
    pub(crate) fn reach(&mut self, p: Pt) -> Option<u32> {
        let key = p.sort_key();
        if self.input.get(self.next) == Some(&key) {
            self.next += 1;
        }
        while self.extra.peek().is_some_and(|r| r.0 == key) {
            self.extra.pop();
        }
        if self.passed.is_none_or(|m| key > m) {
            self.passed = Some(key);
        }
        if !self.counting {
            return None;
        }
        if self.count.is_empty() {
            return Some(0);
        }
        Some(self.count.remove(&p).unwrap_or(0))
    }

    /// Adds a sweep-line edge ending at `r`, whose end is already a
    /// candidate unless it lies at or behind a point reached before.
    #[inline]
    pub(crate) fn add(&mut self, r: Pt) {
        if self.counting {
            self.increment(r);
        }
        let key = r.sort_key();
        if self.passed.is_some_and(|m| key <= m) {
            self.extra.push(Reverse(key));
        }
    }

    /// Adds a sweep-line edge ending at `r` and makes `r` a candidate in
    /// any case (the upper end of a reversed buffer edge).
    pub(crate) fn add_uncovered(&mut self, r: Pt) {
        if self.counting {
            self.increment(r);
        }
        self.extra.push(Reverse(r.sort_key()));
    }

    /// Removes one sweep-line edge ending at `r`.
    #[inline]
    pub(crate) fn remove(&mut self, r: Pt) {
        if self.counting {
            self.decrement(r);
        }
    }

    /// One more edge ending at `r` (out of line: the short-line path stays
    /// small where it is inlined).
    #[inline(never)]
    fn increment(&mut self, r: Pt) {
        *self.count.entry(r).or_insert(0) += 1;
    }

    /// One edge fewer ending at `r`.
    #[inline(never)]
    fn decrement(&mut self, r: Pt) {
        if let Some(n) = self.count.get_mut(&r) {
            *n -= 1;
            if *n == 0 {
                self.count.remove(&r);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    /// Random additions, removals and events, as the sweep makes them
    /// (events at the smallest candidate or at points behind it), against
    /// a plain multiset: the counts are exact and every right point of a
    /// live edge stays a candidate until reached.
    #[test]
    fn counts_exactly_and_covers_every_live_end() {
        let mut s = 0x2545_F491_4F6C_DD1Du64;
        let mut rnd = move |n: u64| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s % n
        };
        // Input right points on a small grid, so that ties are everywhere.
        let input: Vec<Pt> = (0..200)
            .map(|_| Pt::new([rnd(40) as f64, rnd(5) as f64 * 0.5]))
            .collect();
        let mut e = EndPoints::new(input.iter().map(|p| p.sort_key()).collect());
        e.start_counting();
        let mut plain: HashMap<Pt, u32> = HashMap::new();
        // Points made events by other means (the pending left points).
        let mut pending: Vec<Pt> = Vec::new();
        let mut unreached_inputs: Vec<Pt> = input.clone();
        for _ in 0..5_000 {
            match rnd(5) {
                // An edge to an input right point not reached yet.
                0 | 1 if !unreached_inputs.is_empty() => {
                    let r = unreached_inputs[rnd(unreached_inputs.len() as u64) as usize];
                    e.add(r);
                    *plain.entry(r).or_insert(0) += 1;
                }
                // A split: one edge shortened to a new point, which
                // becomes a pending left point (or, reversed, uncovered).
                2 => {
                    let live: Vec<Pt> = plain.keys().copied().collect();
                    if let Some(&old) = live.get(rnd(live.len().max(1) as u64) as usize) {
                        let q = Pt::new([rnd(40) as f64 + 0.25, rnd(5) as f64]);
                        e.remove(old);
                        let n = plain.get_mut(&old).unwrap();
                        *n -= 1;
                        if *n == 0 {
                            plain.remove(&old);
                        }
                        if rnd(8) == 0 {
                            e.add_uncovered(q);
                        } else {
                            e.add(q);
                            pending.push(q);
                        }
                        *plain.entry(q).or_insert(0) += 1;
                    }
                }
                // An event at the smallest candidate or pending point.
                _ => {
                    let pmin = pending.iter().min().copied();
                    let p = match (e.candidate(), pmin) {
                        (Some(a), Some(b)) => a.min(b),
                        (a, None) => a.unwrap_or(Pt::new([1e9, 0.0])),
                        (None, b) => b.unwrap_or(Pt::new([1e9, 0.0])),
                    };
                    // Every live end is covered: none lies before p.
                    for q in plain.keys() {
                        assert!(*q >= p, "live end {q:?} skipped before {p:?}");
                    }
                    pending.retain(|&q| q != p);
                    unreached_inputs.retain(|&q| q != p);
                    let n = e.reach(p);
                    assert_eq!(n, Some(plain.remove(&p).unwrap_or(0)));
                    // Counting stopped and restarted from the live ends.
                    if rnd(50) == 0 {
                        e.stop_counting();
                        assert_eq!(e.reach(Pt::new([-1.0, 0.0])), None);
                        e.start_counting();
                        for (&q, &n) in &plain {
                            for _ in 0..n {
                                e.add(q);
                            }
                        }
                    }
                }
            }
        }
    }
}
