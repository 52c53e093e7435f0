//! The multiset of right end points of the sweep-line edges (section
//! 7.4.1): one entry per sweep-line edge, keyed by its current right point,
//! in an indexed min-heap so that shortening an edge (a split,
//! section 7.4.1) moves its entry instead of leaving a stale one behind.
//!
//! The next event point of the sweep is the smaller of the first pending
//! left point and [`EndPoints::min`]; the number of edges that end at the
//! event point ([`EndPoints::count_equal_to_min`]) is what the grouping of
//! section 7.6.2 must find.

use crate::point::Pt;

const ABSENT: u32 = u32::MAX;

/// Children per heap node. A 4-ary heap halves the depth but compares more
/// per level; on the sweep's lines (hundreds to thousands of edges) the
/// binary heap measured 2-8% faster (random polygons, checkerboards).
const ARITY: usize = 2;

/// An indexed min-heap of `(right point, sweep edge id)`, the
/// points held as their [`Pt::sort_key`] so that comparisons are integer
/// comparisons.
#[derive(Debug, Default)]
pub(crate) struct EndPoints {
    heap: Vec<(u128, u32)>,
    /// Position of each edge id in `heap`, or `ABSENT`.
    pos: Vec<u32>,
}

impl EndPoints {
    /// Adds edge `id` ending at `p` (an id not present).
    pub(crate) fn insert(&mut self, id: u32, p: Pt) {
        let i = id as usize;
        // Ids are handed out in increasing order: usually one more slot.
        if self.pos.len() == i {
            self.pos.push(ABSENT);
        } else if self.pos.len() < i {
            self.pos.resize(i + 1, ABSENT);
        }
        debug_assert_eq!(self.pos[i], ABSENT);
        let at = self.heap.len();
        self.heap.push((p.sort_key(), id));
        self.pos[i] = at as u32;
        self.sift_up(at);
    }

    /// Moves the entry of edge `id` to the point `p`.
    pub(crate) fn update(&mut self, id: u32, p: Pt) {
        let Some(&at) = self.pos.get(id as usize) else {
            return self.insert(id, p);
        };
        if at == ABSENT {
            return self.insert(id, p);
        }
        let at = at as usize;
        let (old, key) = (self.heap[at].0, p.sort_key());
        self.heap[at].0 = key;
        if key < old {
            self.sift_up(at);
        } else {
            self.sift_down(at);
        }
    }

    /// Removes the entry of edge `id`, if present.
    pub(crate) fn remove(&mut self, id: u32) {
        let Some(&at) = self.pos.get(id as usize) else {
            return;
        };
        if at == ABSENT {
            return;
        }
        let at = at as usize;
        self.pos[id as usize] = ABSENT;
        let last = self.heap.len() - 1;
        if at != last {
            self.heap.swap_remove(at);
            let moved = self.heap[at].1 as usize;
            self.pos[moved] = at as u32;
            // The moved entry may belong above or below its new place.
            self.sift_up(at);
            self.sift_down(self.pos[moved] as usize);
        } else {
            self.heap.pop();
        }
    }

    /// The smallest right point.
    #[inline]
    pub(crate) fn min(&self) -> Option<Pt> {
        self.heap.first().map(|e| Pt::from_sort_key(e.0))
    }

    /// The number of entries equal to `p`, which must not exceed the
    /// minimum: they form a subtree at the root (heap order), so only
    /// they and their children are visited.
    pub(crate) fn count_equal_to_min(&self, p: Pt, stack: &mut Vec<u32>) -> u32 {
        stack.clear();
        let mut n = 0;
        let p = p.sort_key();
        if self.heap.first().is_some_and(|e| e.0 == p) {
            stack.push(0);
        }
        while let Some(i) = stack.pop() {
            n += 1;
            let first = ARITY * i as usize + 1;
            for c in first..first + ARITY {
                if self.heap.get(c).is_some_and(|e| e.0 == p) {
                    stack.push(c as u32);
                }
            }
        }
        n
    }

    /// Checks the heap order and the index (for tests).
    #[cfg(test)]
    fn check(&self) {
        for i in 1..self.heap.len() {
            assert!(
                self.heap[(i - 1) / ARITY].0 <= self.heap[i].0,
                "heap order at {i}"
            );
            let p = Pt::from_sort_key(self.heap[i].0);
            assert_eq!(p.sort_key(), self.heap[i].0, "key round trip");
        }
        for (i, e) in self.heap.iter().enumerate() {
            assert_eq!(self.pos[e.1 as usize] as usize, i, "index of edge {}", e.1);
        }
        let present = self.pos.iter().filter(|&&p| p != ABSENT).count();
        assert_eq!(present, self.heap.len());
    }

    /// Moves the entry at `at` up to its place (a hole moves instead of
    /// repeated swaps; the index is written once per move).
    fn sift_up(&mut self, mut at: usize) {
        let item = self.heap[at];
        while at > 0 {
            let parent = (at - 1) / ARITY;
            let up = self.heap[parent];
            if item.0 < up.0 {
                self.heap[at] = up;
                self.pos[up.1 as usize] = at as u32;
                at = parent;
            } else {
                break;
            }
        }
        self.heap[at] = item;
        self.pos[item.1 as usize] = at as u32;
    }

    /// Moves the entry at `at` down to its place.
    fn sift_down(&mut self, mut at: usize) {
        let len = self.heap.len();
        let item = self.heap[at];
        loop {
            let first = ARITY * at + 1;
            if first >= len {
                break;
            }
            let mut c = first;
            for k in first + 1..(first + ARITY).min(len) {
                if self.heap[k].0 < self.heap[c].0 {
                    c = k;
                }
            }
            let down = self.heap[c];
            if down.0 < item.0 {
                self.heap[at] = down;
                self.pos[down.1 as usize] = at as u32;
                at = c;
            } else {
                break;
            }
        }
        self.heap[at] = item;
        self.pos[item.1 as usize] = at as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random insertions, moves and removals against a plain multiset.
    #[test]
    fn matches_a_plain_multiset() {
        let mut s = 0x2545_F491_4F6C_DD1Du64;
        let mut rnd = move |n: u64| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s % n
        };
        let mut h = EndPoints::default();
        let mut plain: Vec<Option<Pt>> = Vec::new();
        let mut stack = Vec::new();
        for _ in 0..20_000 {
            // Few distinct points, so ties are everywhere.
            let p = Pt::new([rnd(5) as f64, rnd(3) as f64 * 0.5]);
            match rnd(4) {
                0 | 1 => {
                    let id = plain.len() as u32;
                    plain.push(Some(p));
                    h.insert(id, p);
                }
                2 if !plain.is_empty() => {
                    let id = rnd(plain.len() as u64) as usize;
                    if plain[id].is_some() {
                        plain[id] = Some(p);
                        h.update(id as u32, p);
                    }
                }
                _ if !plain.is_empty() => {
                    let id = rnd(plain.len() as u64) as usize;
                    plain[id] = None;
                    h.remove(id as u32);
                }
                _ => {}
            }
            h.check();
            let min = plain.iter().flatten().min().copied();
            assert_eq!(h.min(), min);
            if let Some(m) = min {
                let count = plain.iter().flatten().filter(|&&q| q == m).count() as u32;
                assert_eq!(h.count_equal_to_min(m, &mut stack), count);
                // A point below the minimum is at no edge's end.
                let below = Pt::new([-1.0, 0.0]);
                assert_eq!(h.count_equal_to_min(below, &mut stack), 0);
            }
        }
    }
}
