//! The min-heap of the buffer edges (section 7.4.1), keyed by left point.
//!
//! The sweep pops every buffer edge starting at an event point, one crossing
//! after another: two pops and two pushes per crossing on a heap of a few
//! hundred entries (random polygons), where the standard library's binary
//! heap spent a fifth of the sweep's time in `pop`, most of it in
//! mispredicted branches of its sift-down (one unpredictable comparison per
//! level). This is a 4-ary heap: half as many levels, the smallest of four
//! children chosen by comparisons on `u128` keys that compile to
//! conditional moves, and the std strategy for `pop` (move the hole to the
//! bottom along the smaller children, then sift the last entry up from
//! there, which rarely moves it).
//!
//! The sweep depends on the heap only through its minimum key
//! ([`BufferHeap::peek_key`]) and through the *set* of entries popped at an
//! event (all of those with the minimum key, whose edges it sorts by a
//! total order afterwards, `sweep.rs`), which any correct min-heap gives
//! alike: the order in which entries of equal key leave may differ from the
//! binary heap's and decides nothing.

use crate::point::SortKey;

/// One heap entry: the key (a [`SortKey`] split into its halves, so that
/// the entry is 24 bytes rather than the 32 of a 16-aligned `u128`) and two
/// payload words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    hi: u64,
    lo: u64,
    /// The buffer slab slot of the edge.
    pub(crate) slot: u32,
    /// The counting slot of its left point (`end_points.rs`).
    pub(crate) lslot: u32,
}

impl Entry {
    /// An entry with key `key`.
    #[inline]
    pub(crate) fn new(key: SortKey, slot: u32, lslot: u32) -> Self {
        Entry {
            hi: key.0,
            lo: key.1,
            slot,
            lslot,
        }
    }

    /// The key, ordered as the [`SortKey`] (x's key first).
    #[inline]
    fn k(&self) -> u128 {
        (u128::from(self.hi) << 64) | u128::from(self.lo)
    }

    /// The key as a [`SortKey`].
    #[inline]
    pub(crate) fn key(&self) -> SortKey {
        (self.hi, self.lo)
    }
}

/// A 4-ary min-heap of [`Entry`] by key.
#[derive(Debug, Default)]
pub(crate) struct BufferHeap {
    v: Vec<Entry>,
}

impl BufferHeap {
    /// The smallest key.
    #[inline]
    pub(crate) fn peek_key(&self) -> Option<SortKey> {
        self.v.first().map(Entry::key)
    }

    /// Adds an entry.
    #[inline]
    pub(crate) fn push(&mut self, e: Entry) {
        let mut i = self.v.len();
        self.v.push(e);
        let k = e.k();
        while i > 0 {
            let p = (i - 1) / 4;
            let parent = self.v[p];
            if parent.k() <= k {
                break;
            }
            self.v[i] = parent;
            i = p;
        }
        self.v[i] = e;
    }

    /// Removes and returns an entry of the smallest key.
    pub(crate) fn pop(&mut self) -> Option<Entry> {
        let last = self.v.pop()?;
        let Some(&top) = self.v.first() else {
            return Some(last);
        };
        let v = &mut self.v;
        let n = v.len();
        // Move the hole at the root down along the smallest children.
        let mut i = 0;
        loop {
            let c = 4 * i + 1;
            // One bounds check for the four children.
            if let Some(f) = v.get(c..c + 4) {
                let (k0, k1, k2, k3) = (f[0].k(), f[1].k(), f[2].k(), f[3].k());
                let (a, ka) = if k1 < k0 { (c + 1, k1) } else { (c, k0) };
                let (b, kb) = if k3 < k2 { (c + 3, k3) } else { (c + 2, k2) };
                let m = if kb < ka { b } else { a };
                v[i] = v[m];
                i = m;
            } else {
                if c < n {
                    // The last, partial family: its children lie beyond
                    // the end (4 c + 1 > n for c >= 1).
                    let mut m = c;
                    for j in c + 1..n {
                        if v[j].k() < v[m].k() {
                            m = j;
                        }
                    }
                    v[i] = v[m];
                    i = m;
                }
                break;
            }
        }
        // Sift the former last entry up from the hole.
        let k = last.k();
        while i > 0 {
            let p = (i - 1) / 4;
            let parent = v[p];
            if parent.k() <= k {
                break;
            }
            v[i] = parent;
            i = p;
        }
        v[i] = last;
        Some(top)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Reverse;
    use std::collections::BinaryHeap;
    use test_support::rng::Xorshift64;

    /// Random pushes and pops on keys from small ranges (many ties) and
    /// from the whole range, against the standard library's binary heap:
    /// every pop returns the smallest key, and the entries popped for one
    /// key are the same set.
    #[test]
    fn pops_the_minimum_like_a_binary_heap() {
        let mut g = Xorshift64::new(0x9E37_79B9_7F4A_7C15);
        let mut next = 0u32;
        for round in 0..200 {
            let mut heap = BufferHeap::default();
            let mut oracle: BinaryHeap<Reverse<(SortKey, u32, u32)>> = BinaryHeap::new();
            let range = [3, 50, u64::MAX][round % 3];
            let steps = 50 + g.below(3000);
            for _ in 0..steps {
                if g.below(3) > 0 || oracle.is_empty() {
                    let key = (g.below(range.min(7)), g.below(range));
                    next += 1;
                    let lslot = g.below(100) as u32;
                    heap.push(Entry::new(key, next, lslot));
                    oracle.push(Reverse((key, next, lslot)));
                } else {
                    // Pop every entry of the smallest key from both.
                    let min = oracle.peek().map(|r| r.0 .0);
                    assert_eq!(heap.peek_key(), min);
                    let mut a = Vec::new();
                    let mut b = Vec::new();
                    while heap.peek_key() == min && min.is_some() {
                        let e = heap.pop().expect("entry");
                        a.push((e.key(), e.slot, e.lslot));
                    }
                    while oracle.peek().map(|r| r.0 .0) == min && min.is_some() {
                        b.push(oracle.pop().expect("entry").0);
                    }
                    a.sort_unstable();
                    b.sort_unstable();
                    assert_eq!(a, b);
                }
                assert_eq!(heap.v.len(), oracle.len());
            }
            // Draining gives the keys in order.
            let mut last = None;
            while let Some(e) = heap.pop() {
                assert!(last <= Some(e.key()));
                last = Some(e.key());
            }
            assert_eq!(heap.pop(), None);
        }
    }
}
