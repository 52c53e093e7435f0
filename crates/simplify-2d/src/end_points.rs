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
//!   vertical edge whose buffer part is reversed) go to a small heap.
//!
//! The counts are kept by *slot*, not by point, so that no point is ever
//! hashed: every distinct input right point has a slot, and every split
//! point gets one when it is created (a split at an existing right point
//! shares that point's slot). Each sweep-line edge carries the slot of its
//! right point. Two slots may stand for the same point (a computed crossing
//! that lands on an input point, say), so the count at an event point is
//! the sum over the slots *visited* there: the input right point's slot
//! when the sweep reaches it, the slots of the heap entries at the point,
//! and the slots the sweep hands in with the buffer edges that start there
//! ([`EndPoints::take`]). Every slot with a live edge is visited at its
//! point: an input slot is reached in order, a split slot through the
//! buffer edge created with it or the heap, and a slot whose point has
//! already been passed gets a heap entry when an edge is added to it. A
//! visit reads the count and zeroes it, since the event removes every edge
//! ending there.
//!
//! A candidate at which no edge ends and no pending edge starts (its edges
//! were shortened, or cancelled when merged) is passed over by the sweep
//! exactly as the exact multiset of right points would never have produced
//! it: every event point with work to do is still reached, in the same
//! order. Per event this costs a few array updates instead of a heap
//! operation per edge or a hash operation per update.

use crate::point::{Pt, SortKey};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// A slot: the index of a counter of sweep-line edges ending at one point.
pub(crate) type Slot = u32;

/// Counts of sweep-line edges by right point, and the queue of candidate
/// event points that covers them.
#[derive(Debug, Default)]
pub(crate) struct EndPoints {
    /// The right points of the input edges (as [`Pt::sort_key`]) with the
    /// positions they were given in, sorted by point (the first of a run
    /// of equal points is its slot); from [`EndPoints::start`] on, with
    /// their slots instead, in reverse, the points not passed yet, the next
    /// one last, the memory of those passed given back as the sweep goes.
    input: Vec<(SortKey, u32)>,
    /// Right points not covered by `input` or the pending edges, with
    /// their slots.
    extra: BinaryHeap<Reverse<(SortKey, Slot)>>,
    /// The number of sweep-line edges by slot.
    count: Vec<u32>,
    /// The largest candidate passed so far: a right point beyond it is
    /// still ahead in `input` or among the pending left points.
    passed: Option<Pt>,
}

impl EndPoints {
    /// The queue for `n` input edges whose right points `right(i)` are
    /// given by position (in any order, repeats allowed).
    pub(crate) fn new(n: usize, right: impl Fn(usize) -> Pt + Sync) -> Self {
        // One sort gives the points in order and, through the runs of
        // equal points, every position's slot (the index of its run's
        // first entry); the order within a run does not matter. The keys
        // are computed once and sorted in place with their positions, by
        // the key alone as one `u128` (a branch-free comparison): no
        // buffer, and no look-up of the points per comparison.
        let mut input: Vec<(SortKey, u32)> =
            (0..n).map(|i| (right(i).sort_key(), i as u32)).collect();
        let wide = |e: &(SortKey, u32)| (u128::from(e.0 .0) << 64) | u128::from(e.0 .1);
        crate::cells::sort_unstable_by(&mut input, |a, b| wide(a).cmp(&wide(b)));
        // Room for as many split points as input points, so that the
        // counters rarely move while the sweep allocates its output.
        let mut count = Vec::with_capacity(input.len() * 2);
        count.resize(input.len(), 0);
        EndPoints {
            count,
            input,
            ..EndPoints::default()
        }
    }

    /// The slot of every input right point, as (position given to
    /// [`EndPoints::new`], slot) pairs.
    pub(crate) fn input_slots(&self) -> impl Iterator<Item = (usize, Slot)> + '_ {
        let mut first = 0;
        self.input.iter().enumerate().map(move |(j, &(key, i))| {
            if self.input.get(first).is_none_or(|f| f.0 != key) {
                first = j;
            }
            (i as usize, first as Slot)
        })
    }

    /// Turns the positions of the input points into their slots and
    /// reverses the list, so that it is consumed from its end and shrinks
    /// as the sweep passes it; after [`EndPoints::input_slots`], before the
    /// sweep.
    pub(crate) fn start(&mut self) {
        let mut first = 0;
        for j in 0..self.input.len() {
            if self.input[first].0 != self.input[j].0 {
                first = j;
            }
            self.input[j].1 = first as Slot;
        }
        self.input.reverse();
    }

    /// A new slot, for a point at which an edge was split.
    pub(crate) fn new_slot(&mut self) -> Slot {
        self.count.push(0);
        (self.count.len() - 1) as Slot
    }

    /// The smallest candidate event point not passed yet, as its sort key.
    #[inline]
    pub(crate) fn candidate(&self) -> Option<SortKey> {
        let a = self.input.last().map(|e| e.0);
        let b = self.extra.peek().map(|r| r.0 .0);
        match (a, b) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (Some(k), None) | (None, Some(k)) => Some(k),
            (None, None) => None,
        }
    }

    /// Marks the event point `p` (sort key `key`), the smallest of all
    /// candidates and pending left points, as reached, and returns the number of
    /// sweep-line edges that end there in the slots visited here: the input
    /// right point's and the heap's. The caller adds the slots of the
    /// buffer edges starting at `p` ([`EndPoints::take`]). Also returns
    /// whether the heap held `p` (every uncovered split point is there).
    #[inline]
    pub(crate) fn reach(&mut self, p: Pt, key: SortKey) -> (u32, bool) {
        // Inline, the comparisons that usually find nothing to visit (a
        // crossing); the visits apart.
        let mut n = 0;
        if self.input.last().is_some_and(|e| e.0 == key) {
            n += self.reach_input(key);
        }
        let extra = self.extra.peek().is_some_and(|r| r.0 .0 == key);
        if extra {
            n += self.reach_extra(key);
        }
        if self.passed.is_none_or(|m| p > m) {
            self.passed = Some(p);
        }
        (n, extra)
    }

    /// [`EndPoints::reach`] at the next input right point, `key`.
    #[inline(never)]
    fn reach_input(&mut self, key: SortKey) -> u32 {
        let slot = self.input.last().map_or(Slot::MAX, |e| e.1);
        let n = self.take(slot);
        while self.input.last().is_some_and(|e| e.0 == key) {
            self.input.pop();
        }
        crate::cells::release_consumed(&mut self.input);
        n
    }

    /// [`EndPoints::reach`] at the smallest point of the heap, `key`.
    #[inline(never)]
    fn reach_extra(&mut self, key: SortKey) -> u32 {
        let mut n = 0;
        while let Some(&Reverse((k, slot))) = self.extra.peek() {
            if k != key {
                break;
            }
            self.extra.pop();
            n += self.take(slot);
        }
        n
    }

    /// Visits `slot` at its point: returns its count and zeroes it (the
    /// event removes every edge ending there).
    #[inline]
    pub(crate) fn take(&mut self, slot: Slot) -> u32 {
        self.count.get_mut(slot as usize).map_or(0, std::mem::take)
    }

    /// Adds a sweep-line edge ending at `r` (slot `slot`), whose end is
    /// already a candidate unless it lies at or behind a point reached
    /// before.
    #[inline]
    pub(crate) fn add(&mut self, r: Pt, slot: Slot) {
        if let Some(c) = self.count.get_mut(slot as usize) {
            *c += 1;
        }
        if self.passed.is_some_and(|m| r <= m) {
            self.extra.push(Reverse((r.sort_key(), slot)));
        }
    }

    /// Adds a sweep-line edge ending at `r` (slot `slot`) and makes `r` a
    /// candidate in any case (the upper end of a reversed buffer edge).
    pub(crate) fn add_uncovered(&mut self, r: Pt, slot: Slot) {
        if let Some(c) = self.count.get_mut(slot as usize) {
            *c += 1;
        }
        self.extra.push(Reverse((r.sort_key(), slot)));
    }

    /// Removes one sweep-line edge ending in slot `slot`.
    #[inline]
    pub(crate) fn remove(&mut self, slot: Slot) {
        if let Some(c) = self.count.get_mut(slot as usize) {
            debug_assert!(*c > 0, "slot {slot} has no edge to remove");
            *c = c.saturating_sub(1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random additions, splits and events, as the sweep makes them
    /// (events at the smallest candidate or pending left point, which may
    /// lie behind points reached before), against the plain list of live
    /// edge ends: the count visited at every event is exact, and every
    /// right point of a live edge stays a candidate until reached. Splits
    /// share a slot with an existing end (a vertex on an edge, section 6.5)
    /// or get a new one, sometimes at an input point, so that two slots
    /// stand for one point.
    #[test]
    fn counts_exactly_and_covers_every_live_end() {
        let mut rnd = {
            let mut g = test_support::rng::Xorshift64::new(0x2545_F491_4F6C_DD1Du64);
            move |n: u64| g.below(n)
        };
        let mut events = 0;
        for _round in 0..40 {
            let mut passed: Option<Pt> = None;
            // Input right points on a small grid, so that ties are everywhere.
            let input: Vec<Pt> = (0..200)
                .map(|_| Pt::new([rnd(40) as f64, rnd(5) as f64 * 0.5]))
                .collect();
            let mut e = EndPoints::new(input.len(), |i| input[i]);
            let mut input_slots = vec![Slot::MAX; input.len()];
            for (i, slot) in e.input_slots() {
                input_slots[i] = slot;
            }
            e.start();
            // Equal input points share a slot.
            for (i, p) in input.iter().enumerate() {
                for (j, q) in input.iter().enumerate() {
                    assert_eq!(p == q, input_slots[i] == input_slots[j]);
                }
            }
            // The right point and slot of every live sweep-line edge.
            let mut live: Vec<(Pt, Slot)> = Vec::new();
            // The pending left points of buffer edges, with their slots.
            let mut pending: Vec<(Pt, Slot)> = Vec::new();
            let mut unreached: Vec<(Pt, Slot)> = input.iter().copied().zip(input_slots).collect();
            for _ in 0..2_000 {
                match rnd(5) {
                    // An edge to an input right point not reached yet.
                    0 | 1 if !unreached.is_empty() => {
                        let j = rnd(unreached.len() as u64) as usize;
                        let (r, slot) = unreached[j];
                        e.add(r, slot);
                        live.push((r, slot));
                    }
                    // An edge to a point at or behind the points reached,
                    // with a new slot and no pending edge there: a backward
                    // step of section 7.6.1.
                    3 if rnd(4) == 0 && passed.is_some() => {
                        let r = Pt::new([rnd(40) as f64, rnd(5) as f64 * 0.5]);
                        let r = if passed.is_some_and(|m| r <= m) {
                            r
                        } else {
                            passed.unwrap_or(r)
                        };
                        let slot = e.new_slot();
                        e.add(r, slot);
                        live.push((r, slot));
                    }
                    // A split: one edge shortened to a point, which becomes a
                    // pending left point (or, reversed, uncovered).
                    2 if !live.is_empty() => {
                        let (_, old) = live.swap_remove(rnd(live.len() as u64) as usize);
                        e.remove(old);
                        let (q, slot) = match rnd(4) {
                            0 if !live.is_empty() => live[rnd(live.len() as u64) as usize],
                            1 if !unreached.is_empty() => (
                                unreached[rnd(unreached.len() as u64) as usize].0,
                                e.new_slot(),
                            ),
                            _ => (
                                Pt::new([rnd(40) as f64 + 0.25, rnd(5) as f64]),
                                e.new_slot(),
                            ),
                        };
                        if rnd(8) == 0 {
                            e.add_uncovered(q, slot);
                        } else {
                            e.add(q, slot);
                            pending.push((q, slot));
                        }
                        live.push((q, slot));
                    }
                    // An event at the smallest candidate or pending point.
                    _ => {
                        let pmin = pending.iter().map(|q| q.0).min();
                        let p = match (e.candidate().map(Pt::from_sort_key), pmin) {
                            (Some(a), Some(b)) => a.min(b),
                            (Some(a), None) | (None, Some(a)) => a,
                            (None, None) => continue,
                        };
                        // Every live end is covered: none lies before p.
                        for (q, _) in &live {
                            assert!(*q >= p, "live end {q:?} skipped before {p:?}");
                        }
                        let mut n = e.reach(p, p.sort_key()).0;
                        passed = passed.max(Some(p));
                        for &(q, slot) in &pending {
                            if q == p {
                                n += e.take(slot);
                            }
                        }
                        pending.retain(|q| q.0 != p);
                        unreached.retain(|q| q.0 != p);
                        let expected = live.iter().filter(|q| q.0 == p).count();
                        live.retain(|q| q.0 != p);
                        assert_eq!(n as usize, expected, "count at {p:?}");
                        events += 1;
                    }
                }
            }
        }
        assert!(events > 4_000, "{events} events");
    }

    /// On inputs long enough for the parallel sort and on short ones,
    /// with many repeated points: equal right points share a slot and
    /// distinct ones do not, and the candidates come in increasing order,
    /// each distinct point once.
    #[test]
    fn slots_follow_the_points_on_long_inputs() {
        let mut g = test_support::rng::Xorshift64::new(0x7A11_0C0D_E5EE_D001);
        for n in [0, 1, 7, 1000, 40_000] {
            for spread in [3u64, 300, 1 << 40] {
                let input: Vec<Pt> = (0..n)
                    .map(|_| Pt::new([g.below(spread) as f64 * 0.25, -(g.below(4) as f64)]))
                    .collect();
                let mut e = EndPoints::new(input.len(), |i| input[i]);
                let mut slot_of: std::collections::HashMap<(u64, u64), Slot> =
                    std::collections::HashMap::new();
                let mut point_of: std::collections::HashMap<Slot, (u64, u64)> =
                    std::collections::HashMap::new();
                let mut seen = 0;
                for (i, slot) in e.input_slots() {
                    let key = input[i].sort_key();
                    assert_eq!(*slot_of.entry(key).or_insert(slot), slot, "n {n}");
                    assert_eq!(*point_of.entry(slot).or_insert(key), key, "n {n}");
                    seen += 1;
                }
                assert_eq!(seen, n);
                e.start();
                let mut last: Option<Pt> = None;
                let mut distinct = 0;
                while let Some(key) = e.candidate() {
                    let p = Pt::from_sort_key(key);
                    assert!(last < Some(p), "n {n}: {p:?} after {last:?}");
                    e.reach(p, key);
                    last = Some(p);
                    distinct += 1;
                }
                assert_eq!(distinct, slot_of.len());
            }
        }
    }
}
