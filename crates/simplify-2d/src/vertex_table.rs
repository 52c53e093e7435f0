//! The points of the sweep: output vertex ids (assigned when a point is
//! first processed as an event) and adjustment counts (section 8.4: a
//! vertex's count is the largest count of the edges created at it).
//!
//! Events are processed in lexicographic order except for the rare
//! backward steps of section 7.6.1, so the table keeps points apart by
//! state: points not processed yet (few: the computed intersections ahead
//! of the sweep line) in a short list or, when there are many, a hash map,
//! processed points in the order
//! they were processed, found by binary search over those processed beyond
//! every earlier one and by a second hash map for the others. A point is
//! looked up among the processed ones only when it does not lie beyond all
//! of them, which the sweep's order makes rare; the large table of every
//! vertex is never hashed on the hot path.

use crate::point::{PointMap, Pt};

/// Vertex ids and adjustment counts by point.
#[derive(Debug, Default)]
pub(crate) struct VertexTable {
    /// Output vertices, by id (the order in which they were processed).
    pub(crate) vertices: Vec<[f64; 2]>,
    /// Adjustment count by vertex id.
    k: Vec<u32>,
    /// Adjustment counts of points not processed yet.
    ahead: Ahead,
    /// Ids of the points processed beyond every earlier one: increasing.
    in_order: Vec<u32>,
    /// Ids of the other processed points.
    late: PointMap<u32>,
    /// The largest processed point.
    max_done: Option<Pt>,
}

/// The points ahead of the sweep with an adjustment count: a short list
/// while there are few (the usual case: the crossings just right of the
/// sweep line), a hash map once there are more than [`AHEAD_LIST_MAX`],
/// until it empties again. A point is in one of the two, never both.
#[derive(Debug, Default)]
struct Ahead {
    list: Vec<(Pt, u32)>,
    map: PointMap<u32>,
}

/// Up to this many points a scan of the list costs less than hashing
/// (about a hundred instructions per map operation).
const AHEAD_LIST_MAX: usize = 16;

impl Ahead {
    fn is_empty(&self) -> bool {
        self.list.is_empty() && self.map.is_empty()
    }

    fn get(&self, q: Pt) -> Option<u32> {
        if self.map.is_empty() {
            self.list.iter().find(|e| e.0 == q).map(|e| e.1)
        } else {
            self.map.get(&q).copied()
        }
    }

    /// The count of `q`, inserted as 0 if absent.
    fn get_or_zero(&mut self, q: Pt) -> &mut u32 {
        if self.map.is_empty() {
            if let Some(i) = self.list.iter().position(|e| e.0 == q) {
                return &mut self.list[i].1;
            }
            if self.list.len() < AHEAD_LIST_MAX {
                self.list.push((q, 0));
                let last = self.list.len() - 1;
                return &mut self.list[last].1;
            }
            self.map.extend(self.list.drain(..));
        }
        self.map.entry(q).or_insert(0)
    }

    fn remove(&mut self, q: Pt) -> Option<u32> {
        if self.map.is_empty() {
            let i = self.list.iter().position(|e| e.0 == q)?;
            Some(self.list.swap_remove(i).1)
        } else {
            self.map.remove(&q)
        }
    }
}

impl VertexTable {
    /// A table with room for about `n` vertices.
    pub(crate) fn with_capacity(n: usize) -> Self {
        VertexTable {
            vertices: Vec::with_capacity(n),
            k: Vec::with_capacity(n),
            in_order: Vec::with_capacity(n),
            ..VertexTable::default()
        }
    }

    /// The id of `q` if it has been processed.
    fn done_id(&self, q: Pt) -> Option<u32> {
        match self.max_done {
            Some(m) if q <= m => {}
            _ => return None,
        }
        let v = &self.vertices;
        let i = self
            .in_order
            .partition_point(|&id| Pt::new(v[id as usize]) < q);
        if let Some(&id) = self.in_order.get(i) {
            if Pt::new(v[id as usize]) == q {
                return Some(id);
            }
        }
        self.late.get(&q).copied()
    }

    /// The adjustment count of point `q` (0 for a point never adjusted).
    pub(crate) fn k(&self, q: Pt) -> u32 {
        match self.done_id(q) {
            Some(id) => self.k[id as usize],
            None => self.ahead.get(q).unwrap_or(0),
        }
    }

    /// The adjustment count of point `q`, to read and raise in one look-up.
    pub(crate) fn k_mut(&mut self, q: Pt) -> &mut u32 {
        match self.done_id(q) {
            Some(id) => &mut self.k[id as usize],
            None => self.ahead.get_or_zero(q),
        }
    }

    /// Processes point `p`: its vertex id (a new one the first time) and
    /// adjustment count. `adjusted` is `false` when the caller knows that
    /// `p` was never given a count ahead of the sweep ([`VertexTable::k_mut`]
    /// on a point not processed yet), which saves the look-up.
    pub(crate) fn process(&mut self, p: Pt, adjusted: bool) -> (u32, u32) {
        if let Some(id) = self.done_id(p) {
            return (id, self.k[id as usize]);
        }
        debug_assert!(
            adjusted || self.ahead.get(p).is_none(),
            "point {p:?} has an adjustment count it was not expected to have"
        );
        let k = if !adjusted || self.ahead.is_empty() {
            0
        } else {
            self.ahead.remove(p).unwrap_or(0)
        };
        let id = self.vertices.len() as u32;
        self.vertices.push(p.arr());
        self.k.push(k);
        if self.max_done.is_none_or(|m| p > m) {
            self.in_order.push(id);
            self.max_done = Some(p);
        } else {
            self.late.insert(p, id);
        }
        (id, k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    /// The points ahead, through the list and the map and back, against a
    /// plain map: every point in one place, counts exact.
    #[test]
    fn ahead_matches_a_plain_map_in_both_regimes() {
        let mut rnd = {
            let mut g = test_support::rng::Xorshift64::new(0x2545_F491_4F6C_DD1Du64);
            move |n: u64| g.below(n)
        };
        let mut a = Ahead::default();
        let mut plain: HashMap<Pt, u32> = HashMap::new();
        let mut spilled = false;
        for round in 0..40 {
            // Rounds alternate between few points (the list) and many
            // (beyond AHEAD_LIST_MAX: the map), draining in between.
            let range = if round % 2 == 0 { 6 } else { 60 };
            for _ in 0..500 {
                let p = Pt::new([rnd(range) as f64, rnd(3) as f64]);
                match rnd(3) {
                    0 => {
                        let k = rnd(9) as u32;
                        let slot = a.get_or_zero(p);
                        *slot = (*slot).max(k);
                        let e = plain.entry(p).or_insert(0);
                        *e = (*e).max(k);
                    }
                    1 => assert_eq!(a.remove(p), plain.remove(&p)),
                    _ => assert_eq!(a.get(p), plain.get(&p).copied()),
                }
                spilled |= !a.map.is_empty();
                assert!(a.list.is_empty() || a.map.is_empty());
                assert_eq!(a.is_empty(), plain.is_empty());
            }
            let keys: Vec<Pt> = plain.keys().copied().collect();
            for p in keys {
                assert_eq!(a.remove(p), plain.remove(&p));
            }
            assert!(a.is_empty());
        }
        assert!(spilled, "the map was never used");
    }

    /// Random operations, mostly increasing with backward steps and
    /// repeats, against a plain map.
    #[test]
    fn matches_a_plain_map() {
        let mut rnd = {
            let mut g = test_support::rng::Xorshift64::new(0x9E37_79B9_7F4A_7C15u64);
            move |n: u64| g.below(n)
        };
        let mut t = VertexTable::with_capacity(16);
        let mut ids: HashMap<Pt, u32> = HashMap::new();
        let mut ks: HashMap<Pt, u32> = HashMap::new();
        let mut x = 0.0;
        for _ in 0..20_000 {
            // The sweep position creeps forward; points near it.
            if rnd(3) == 0 {
                x += 1.0;
            }
            let p = Pt::new([x - rnd(3) as f64, rnd(4) as f64]);
            match rnd(3) {
                0 => {
                    let (id, k) = t.process(p, true);
                    let next = ids.len() as u32;
                    assert_eq!(id, *ids.entry(p).or_insert(next));
                    assert_eq!(k, ks.get(&p).copied().unwrap_or(0));
                }
                1 => {
                    let k = rnd(7) as u32;
                    let slot = t.k_mut(p);
                    *slot = (*slot).max(k);
                    let e = ks.entry(p).or_insert(0);
                    *e = (*e).max(k);
                }
                _ => assert_eq!(t.k(p), ks.get(&p).copied().unwrap_or(0)),
            }
        }
        assert_eq!(t.vertices.len(), ids.len());
        for (p, &id) in &ids {
            assert_eq!(Pt::new(t.vertices[id as usize]), *p);
        }
    }
}
