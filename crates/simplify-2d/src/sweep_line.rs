//! The sweep line of section 7.4.1: the sweep-line edges in logical bottom
//! to top order, as a chunked sequence.
//!
//! A plain vector moves its whole tail whenever an event inserts or removes
//! edges, which costs O(L) per event for a sweep line of L edges and makes
//! inputs with many edges active at once (nested rings, long parallel
//! strips) quadratic. Here the edges are kept in chunks of at most
//! `2 * CHUNK`, with the global index of each chunk's first edge, so that a
//! replacement moves at most one chunk plus the chunk index: O(sqrt L) with
//! the chunk size chosen, and no more than a vector's cost on short lines
//! (one chunk).
//!
//! Positions are global indices, exactly as in a vector, and
//! [`SweepLine::partition_point`] probes the same indices in the same order
//! as the standard library's `slice::partition_point`, so the sweep decides
//! exactly as it would on a vector even where the computed order of the
//! edges is inconsistent (section 7.2), when the predicate is not monotone.

use std::cell::Cell;

/// Target chunk length; a chunk is split beyond twice this.
const CHUNK: usize = 512;

/// A sequence addressed by global index, stored in chunks.
#[derive(Clone, Debug)]
pub(crate) struct SweepLine<T> {
    chunks: Vec<Vec<T>>,
    /// Global index of the first element of each chunk.
    starts: Vec<usize>,
    len: usize,
    /// The chunk of the last look-up: the probes of a search and the
    /// neighbour accesses of an event mostly fall in one chunk.
    last: Cell<usize>,
}

impl<T> Default for SweepLine<T> {
    fn default() -> Self {
        SweepLine {
            chunks: Vec::new(),
            starts: Vec::new(),
            len: 0,
            last: Cell::new(0),
        }
    }
}

impl<T: Clone> SweepLine<T> {
    /// The number of elements.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// `true` when there are no elements.
    #[inline]
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The chunk holding global index `i < len` and the offset in it.
    #[inline]
    fn locate(&self, i: usize) -> (usize, usize) {
        if self.chunks.len() == 1 {
            return (0, i);
        }
        let c = self.last.get();
        if let (Some(&s), Some(chunk)) = (self.starts.get(c), self.chunks.get(c)) {
            if s <= i && i < s + chunk.len() {
                return (c, i - s);
            }
        }
        let c = self.starts.partition_point(|&s| s <= i) - 1;
        self.last.set(c);
        (c, i - self.starts[c])
    }

    /// The element at global index `i`.
    #[inline]
    pub(crate) fn get(&self, i: usize) -> Option<&T> {
        if let [chunk] = self.chunks.as_slice() {
            return chunk.get(i);
        }
        if i >= self.len {
            return None;
        }
        let (c, o) = self.locate(i);
        self.chunks[c].get(o)
    }

    /// The element at global index `i`, mutably.
    #[inline]
    pub(crate) fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        if self.chunks.len() == 1 {
            return self.chunks[0].get_mut(i);
        }
        if i >= self.len {
            return None;
        }
        let (c, o) = self.locate(i);
        self.chunks[c].get_mut(o)
    }

    /// The first index in `lo..hi` at which `pred` is false, assuming it is
    /// true before and false after. The probes are those of
    /// `slice::partition_point` on `line[lo..hi]` (Rust 1.88 and later:
    /// halve `size`, keep `base` where the predicate holds, then test
    /// `base`), so a non-monotone predicate gives the same answer too.
    pub(crate) fn partition_point(
        &self,
        lo: usize,
        hi: usize,
        mut pred: impl FnMut(&T) -> bool,
    ) -> usize {
        let hi = hi.min(self.len);
        if lo >= hi {
            return lo;
        }
        if let [chunk] = self.chunks.as_slice() {
            return lo + chunk[lo..hi].partition_point(pred);
        }
        let mut at = |i: usize| self.get(i).is_some_and(&mut pred);
        let mut size = hi - lo;
        let mut base = 0;
        while size > 1 {
            let half = size / 2;
            let mid = base + half;
            if at(lo + mid) {
                base = mid;
            }
            size -= half;
        }
        lo + base + usize::from(at(lo + base))
    }

    /// Calls `f` on the elements `lo..hi` in order.
    pub(crate) fn for_range(&self, lo: usize, hi: usize, mut f: impl FnMut(&T)) {
        let hi = hi.min(self.len);
        if lo >= hi {
            return;
        }
        let (mut c, mut o) = self.locate(lo);
        let mut left = hi - lo;
        while left > 0 {
            let chunk = &self.chunks[c];
            let take = (chunk.len() - o).min(left);
            chunk[o..o + take].iter().for_each(&mut f);
            left -= take;
            c += 1;
            o = 0;
        }
    }

    /// The first index whose element satisfies `pred`.
    pub(crate) fn position(&self, mut pred: impl FnMut(&T) -> bool) -> Option<usize> {
        let mut i = 0;
        for chunk in &self.chunks {
            for e in chunk {
                if pred(e) {
                    return Some(i);
                }
                i += 1;
            }
        }
        None
    }

    /// The last index whose element satisfies `pred`.
    pub(crate) fn rposition(&self, mut pred: impl FnMut(&T) -> bool) -> Option<usize> {
        let mut i = self.len;
        for chunk in self.chunks.iter().rev() {
            for e in chunk.iter().rev() {
                i -= 1;
                if pred(e) {
                    return Some(i);
                }
            }
        }
        None
    }

    /// Replaces the elements `lo..hi` by those of `new` (drained), like
    /// `Vec::splice`.
    pub(crate) fn replace(&mut self, lo: usize, hi: usize, new: &mut Vec<T>) {
        let hi = hi.clamp(lo, self.len);
        let lo = lo.min(self.len);
        let removed = hi - lo;
        // As many in as out (every crossing): overwrite in place.
        if removed == new.len() && removed > 0 {
            let mut items = new.drain(..);
            let mut i = lo;
            while i < hi {
                let (c, o) = self.locate(i);
                let chunk = &mut self.chunks[c];
                let take = (chunk.len() - o).min(hi - i);
                for (slot, item) in chunk[o..o + take].iter_mut().zip(&mut items) {
                    *slot = item;
                }
                i += take;
            }
            return;
        }
        // One chunk that stays within bounds: a plain splice (short lines).
        if let [chunk] = self.chunks.as_mut_slice() {
            let after = chunk.len() - removed + new.len();
            if after > 0 && after <= 2 * CHUNK {
                chunk.splice(lo..hi, new.drain(..));
                self.len = after;
                return;
            }
        }
        if self.chunks.is_empty() {
            if !new.is_empty() {
                self.len = new.len();
                self.chunks.push(std::mem::take(new));
                self.starts.push(0);
                self.rechunk(0, 1);
            }
            return;
        }
        // The chunk holding `lo` (the last chunk when appending at the end).
        let (c, o) = if lo == self.len {
            let c = self.chunks.len() - 1;
            (c, self.chunks[c].len())
        } else {
            self.locate(lo)
        };
        if o + removed <= self.chunks[c].len() {
            // Within one chunk: the usual case (a group is a few edges).
            let same = removed == new.len();
            self.chunks[c].splice(o..o + removed, new.drain(..));
            if !same {
                self.rechunk(c, c + 1);
            }
            return;
        }
        // Across chunks: gather the chunks concerned, splice, re-chunk.
        let (c_end, _) = self.locate(hi - 1);
        let mut joined: Vec<T> = Vec::new();
        for chunk in &mut self.chunks[c..=c_end] {
            joined.append(chunk);
        }
        joined.splice(o..o + removed, new.drain(..));
        self.chunks[c] = joined;
        self.chunks.drain(c + 1..=c_end);
        self.starts.truncate(self.chunks.len());
        self.rechunk(c, c + 1);
    }

    /// Splits oversized chunks and drops empty ones among `from..to`, merges
    /// a small chunk into its neighbour, and recomputes the chunk starts and
    /// the length from `from` on.
    fn rechunk(&mut self, from: usize, to: usize) {
        let mut c = from;
        let mut end = to;
        while c < end && c < self.chunks.len() {
            let n = self.chunks[c].len();
            if n == 0 {
                self.chunks.remove(c);
                end -= 1;
                continue;
            }
            if n > 2 * CHUNK {
                let tail = self.chunks[c].split_off(n / 2);
                self.chunks.insert(c + 1, tail);
                end += 1;
                continue;
            }
            if n < CHUNK / 8 {
                if let Some(next) = self.chunks.get(c + 1) {
                    if n + next.len() <= CHUNK {
                        let next = self.chunks.remove(c + 1);
                        self.chunks[c].extend(next);
                        if c + 1 < end {
                            end -= 1;
                        }
                        continue;
                    }
                }
            }
            c += 1;
        }
        self.starts.resize(self.chunks.len(), 0);
        let from = from.min(self.chunks.len());
        let mut s = if from == 0 {
            0
        } else {
            self.starts[from - 1] + self.chunks[from - 1].len()
        };
        for k in from..self.chunks.len() {
            self.starts[k] = s;
            s += self.chunks[k].len();
        }
        self.len = s;
    }

    /// All elements in order (for tests).
    #[cfg(test)]
    fn to_vec(&self) -> Vec<T> {
        self.chunks.iter().flatten().cloned().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random replacements of every shape against a plain vector, with
    /// lines long enough for many chunks, and the probe sequence of
    /// `partition_point` against the standard library's on non-monotone
    /// predicates.
    #[test]
    fn matches_a_vector() {
        let mut below = {
            let mut g = test_support::rng::Xorshift64::new(0x9E37_79B9_7F4A_7C15);
            move |n: u64| g.below(n)
        };
        let mut rnd = move |n: usize| below(n as u64) as usize;
        let mut line: SweepLine<u32> = SweepLine::default();
        let mut plain: Vec<u32> = Vec::new();
        let mut next = 0u32;
        for step in 0..30_000 {
            let len = plain.len();
            let lo = rnd(len + 1);
            let span = match rnd(4) {
                0 => 0,
                1 => rnd(3),
                2 => rnd(40),
                _ => rnd(2 * CHUNK + 50),
            };
            let hi = (lo + span).min(len);
            // Grow while small, then hover.
            let target = if step < 10_000 { 3000 } else { 1500 };
            let count = if len < target { rnd(6) } else { rnd(3) };
            let mut new: Vec<u32> = (0..count)
                .map(|_| {
                    next += 1;
                    next
                })
                .collect();
            plain.splice(lo..hi, new.clone());
            line.replace(lo, hi, &mut new);
            assert!(new.is_empty());
            assert_eq!(line.len(), plain.len());
            if step % 97 == 0 {
                assert_eq!(line.to_vec(), plain);
                for (k, &c) in line.starts.iter().enumerate() {
                    let before: usize = line.chunks[..k].iter().map(Vec::len).sum();
                    assert_eq!(c, before);
                }
                assert!(line
                    .chunks
                    .iter()
                    .all(|c| !c.is_empty() && c.len() <= 2 * CHUNK));
            }
            let i = rnd(plain.len() + 1);
            assert_eq!(line.get(i), plain.get(i));
            // A non-monotone predicate: the answers must agree exactly.
            let m = 1 + rnd(7) as u32;
            let pred = |v: &u32| !(v / m).is_multiple_of(3);
            let (a, b) = (rnd(plain.len() + 1), rnd(plain.len() + 1));
            let (a, b) = (a.min(b), a.max(b));
            assert_eq!(
                line.partition_point(a, b, pred),
                a + plain[a..b].partition_point(pred)
            );
            let mut seen = Vec::new();
            line.for_range(a, b, |v| seen.push(*v));
            assert_eq!(seen, plain[a..b]);
            assert_eq!(
                line.position(|v| v % 11 == 3),
                plain.iter().position(|v| v % 11 == 3)
            );
            assert_eq!(
                line.rposition(|v| v % 13 == 5),
                plain.iter().rposition(|v| v % 13 == 5)
            );
        }
    }
}
