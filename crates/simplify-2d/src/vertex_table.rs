//! The points of the sweep: ids (assigned in order when a point is first
//! processed as an event) and adjustment counts (section 8.4: a vertex's
//! count is the largest count of the edges created at it).
//!
//! Events are processed in lexicographic order except for the rare
//! backward steps of section 7.6.1, so the table keeps points apart by
//! state: points not processed yet (few: the computed intersections ahead
//! of the sweep line) in a short list or, when there are many, a hash map,
//! and processed points in the order they were processed, found by binary
//! search over those processed beyond every earlier one and by a second
//! hash map for the others.
//!
//! Only the processed points of the current *column* (the x of the largest
//! processed point) are kept. The sweep never goes backwards in x (a
//! crossing is clamped into the x-range right of the sweep line, every
//! right end of a sweep-line edge lies at or right of it, and the backward
//! steps of section 7.6.1 stay at one x), so every point it looks up or
//! processes lies at or right of the column: a point of an earlier column
//! is never asked for again. The table therefore holds no entry per point
//! of the arrangement (it held 24 bytes a point, position, count and
//! order, most of a simplification's memory on a random polygon); the
//! coordinates of the output vertices are the output's business
//! (`sweep.rs`). A look-up behind the column would be a bug: it is
//! recorded ([`VertexTable::behind`]) and the sweep reports it as an
//! internal error instead of deciding on a forgotten point.

use crate::point::{PointHasher, PointMap, Pt};
use std::hash::{BuildHasher, BuildHasherDefault};

/// Ids and adjustment counts of the points of the current column and of
/// the points ahead of the sweep.
#[derive(Debug, Default)]
pub(crate) struct VertexTable {
    /// The number of points processed: the next id.
    processed: u32,
    /// The points of the current column processed beyond every earlier
    /// one, increasing, with their ids and counts.
    column: Vec<Done>,
    /// The other processed points of the current column: id and count.
    late: PointMap<(u32, u32)>,
    /// The largest processed point.
    max_done: Option<Pt>,
    /// Adjustment counts of points not processed yet.
    ahead: Ahead,
    /// Whether a point behind the current column was looked up or
    /// processed (never, by the sweep's monotonicity in x).
    behind: bool,
}

/// A processed point with its id and adjustment count.
#[derive(Clone, Copy, Debug)]
struct Done {
    p: Pt,
    id: u32,
    k: u32,
}

/// Where a processed point's entry is.
#[derive(Clone, Copy)]
enum Found {
    Column(usize),
    Late,
}
/// The points ahead of the sweep with an adjustment count: a short list
/// while there are few (the usual case: the crossings just right of the
/// sweep line), an open-addressing table ([`PointTable`]) once there are
/// more than [`AHEAD_LIST_MAX`], until it empties again. A point is in one
/// of the two, never both.
#[derive(Debug, Default)]
struct Ahead {
    list: Vec<(Pt, u32)>,
    map: PointTable,
}

/// Up to this many points a scan of the list costs less than hashing.
const AHEAD_LIST_MAX: usize = 16;

impl Ahead {
    fn is_empty(&self) -> bool {
        self.list.is_empty() && self.map.is_empty()
    }

    fn get(&self, q: Pt) -> Option<u32> {
        if self.map.is_empty() {
            self.list.iter().find(|e| e.0 == q).map(|e| e.1)
        } else {
            self.map.get(q)
        }
    }

    /// The count of `q`, inserted as 0 if absent.
    #[inline]
    fn get_or_zero(&mut self, q: Pt) -> &mut u32 {
        if self.map.is_empty() {
            return self.list_get_or_zero(q);
        }
        self.map.get_or_zero(q)
    }

    /// [`Ahead::get_or_zero`] while the table is empty: in the list, or
    /// in the table once the list is full.
    #[inline(never)]
    fn list_get_or_zero(&mut self, q: Pt) -> &mut u32 {
        if let Some(i) = self.list.iter().position(|e| e.0 == q) {
            return &mut self.list[i].1;
        }
        if self.list.len() < AHEAD_LIST_MAX {
            self.list.push((q, 0));
            let last = self.list.len() - 1;
            return &mut self.list[last].1;
        }
        for (p, k) in self.list.drain(..) {
            *self.map.get_or_zero(p) = k;
        }
        self.map.get_or_zero(q)
    }

    fn remove(&mut self, q: Pt) -> Option<u32> {
        if self.map.is_empty() {
            let i = self.list.iter().position(|e| e.0 == q)?;
            Some(self.list.swap_remove(i).1)
        } else {
            self.map.remove(q)
        }
    }
}

/// A hash table from points to counts for the points ahead of the sweep:
/// open addressing with linear probing in a power-of-two array at most a
/// quarter full, removal by shifting the following entries back (no
/// tombstones), hashed as the sweep's [`PointMap`]s hash. One look-up is a
/// hash (a multiply) and, at this load, mostly a single probe comparing a
/// point (at half load, 0.5% more instructions on the random 1000-gon); the
/// standard library's map spent about a hundred instructions an operation
/// on the random polygons, where each crossing costs two.
///
/// An empty cell holds an x whose bit pattern ([`EMPTY_X`], a signalling
/// NaN) no coordinate of the sweep has (they are finite); a point with
/// that x, were there one, is kept in a plain map beside the array, so the
/// table is exact for every key.
#[derive(Debug, Default)]
struct PointTable {
    /// The cells: a power of two of them (or none), at most a quarter in use.
    cells: Vec<(Pt, u32)>,
    /// The number of cells in use.
    len: usize,
    /// Points whose x has the bit pattern [`EMPTY_X`].
    odd: PointMap<u32>,
}

/// The x bits of an empty cell of a [`PointTable`].
const EMPTY_X: u64 = 0x7FF4_A11C_E0DD_0001;

/// The content of an empty cell.
const EMPTY: (Pt, u32) = (
    Pt {
        x: f64::from_bits(EMPTY_X),
        y: 0.0,
    },
    0,
);

impl PointTable {
    fn is_empty(&self) -> bool {
        self.len == 0 && self.odd.is_empty()
    }

    /// The home cell of `q` under `mask` (the number of cells less one).
    #[inline]
    fn home(q: Pt, mask: usize) -> usize {
        BuildHasherDefault::<PointHasher>::default().hash_one(q) as usize & mask
    }

    /// The cell holding `q`, or the empty cell where it would go; the
    /// table must have cells.
    #[inline]
    fn find(&self, q: Pt) -> Result<usize, usize> {
        let mask = self.cells.len().wrapping_sub(1);
        let mut i = Self::home(q, mask);
        while let Some(c) = self.cells.get(i) {
            if c.0 == q {
                return Ok(i);
            }
            if c.0.x.to_bits() == EMPTY_X {
                return Err(i);
            }
            i = (i + 1) & mask;
        }
        Err(i)
    }

    fn get(&self, q: Pt) -> Option<u32> {
        if q.x.to_bits() == EMPTY_X {
            return self.odd.get(&q).copied();
        }
        if self.len == 0 {
            return None;
        }
        self.find(q)
            .ok()
            .and_then(|i| self.cells.get(i))
            .map(|c| c.1)
    }

    /// The count of `q`, inserted as 0 if absent.
    #[inline]
    fn get_or_zero(&mut self, q: Pt) -> &mut u32 {
        if q.x.to_bits() == EMPTY_X {
            return self.odd.entry(q).or_insert(0);
        }
        if (self.len + 1) * 4 > self.cells.len() {
            self.grow();
        }
        let i = match self.find(q) {
            Ok(i) => i,
            Err(i) => {
                self.len += 1;
                self.cells[i] = (q, 0);
                i
            }
        };
        &mut self.cells[i].1
    }

    /// Doubles the cells (64 at first) and places the entries again.
    #[cold]
    fn grow(&mut self) {
        let n = (self.cells.len() * 2).max(64);
        let old = std::mem::replace(&mut self.cells, vec![EMPTY; n]);
        for c in old {
            if c.0.x.to_bits() != EMPTY_X {
                if let Err(i) = self.find(c.0) {
                    self.cells[i] = c;
                }
            }
        }
    }

    #[inline]
    fn remove(&mut self, q: Pt) -> Option<u32> {
        if q.x.to_bits() == EMPTY_X {
            return self.odd.remove(&q);
        }
        if self.len == 0 {
            return None;
        }
        let mut hole = self.find(q).ok()?;
        let k = self.cells[hole].1;
        self.len -= 1;
        // Move back every following entry of the run whose home does not
        // lie cyclically after the hole (between the hole and its cell),
        // so that each stays reachable from its home without a gap.
        let mask = self.cells.len() - 1;
        let mut j = hole;
        loop {
            j = (j + 1) & mask;
            let c = self.cells[j];
            if c.0.x.to_bits() == EMPTY_X {
                break;
            }
            let home = Self::home(c.0, mask);
            if j.wrapping_sub(home) & mask >= j.wrapping_sub(hole) & mask {
                self.cells[hole] = c;
                hole = j;
            }
        }
        self.cells[hole] = EMPTY;
        Some(k)
    }
}

impl VertexTable {
    /// The processed point `q` of the current column, if it is one. Notes
    /// a look-up behind the column.
    #[inline]
    fn find(&mut self, q: Pt) -> Option<Found> {
        match self.max_done {
            Some(m) if q <= m => {
                if q.x < m.x {
                    self.behind = true;
                    return None;
                }
            }
            _ => return None,
        }
        let i = self.column.partition_point(|d| d.p < q);
        if self.column.get(i).is_some_and(|d| d.p == q) {
            return Some(Found::Column(i));
        }
        self.late.contains_key(&q).then_some(Found::Late)
    }

    /// The id and count of a found point.
    fn entry(&mut self, q: Pt, at: Found) -> Option<(u32, &mut u32)> {
        match at {
            Found::Column(i) => self.column.get_mut(i).map(|d| (d.id, &mut d.k)),
            Found::Late => self.late.get_mut(&q).map(|e| (e.0, &mut e.1)),
        }
    }

    /// The adjustment count of point `q` (0 for a point never adjusted).
    pub(crate) fn k(&mut self, q: Pt) -> u32 {
        if let Some(at) = self.find(q) {
            if let Some((_, k)) = self.entry(q, at) {
                return *k;
            }
        }
        self.ahead.get(q).unwrap_or(0)
    }

    /// The adjustment count of point `q`, to read and raise in one look-up.
    pub(crate) fn k_mut(&mut self, q: Pt) -> &mut u32 {
        match self.find(q) {
            Some(at) => match at {
                Found::Column(i) => &mut self.column[i].k,
                Found::Late => match self.late.get_mut(&q) {
                    Some(e) => &mut e.1,
                    None => self.ahead.get_or_zero(q),
                },
            },
            None => self.ahead.get_or_zero(q),
        }
    }

    /// Processes point `p`: its id (a new one the first time, then `new`
    /// is `true`) and adjustment count, as `(id, k, new)`. `adjusted` is
    /// `false` when the caller knows that `p` was never given a count ahead
    /// of the sweep ([`VertexTable::k_mut`] on a point not processed yet),
    /// which saves the look-up.
    pub(crate) fn process(&mut self, p: Pt, adjusted: bool) -> (u32, u32, bool) {
        if let Some(at) = self.find(p) {
            if let Some((id, k)) = self.entry(p, at) {
                return (id, *k, false);
            }
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
        let id = self.processed;
        self.processed += 1;
        match self.max_done {
            Some(m) if p <= m => {
                // A backward step (section 7.6.1), within the column.
                if p.x < m.x {
                    self.behind = true;
                }
                self.late.insert(p, (id, k));
            }
            Some(m) if p.x == m.x => {
                self.column.push(Done { p, id, k });
                self.max_done = Some(p);
            }
            _ => {
                // A new column: the points of the earlier ones are never
                // asked for again.
                self.column.clear();
                if !self.late.is_empty() {
                    self.late.clear();
                }
                self.column.push(Done { p, id, k });
                self.max_done = Some(p);
            }
        }
        (id, k, true)
    }

    /// Whether a point behind the current column was ever looked up or
    /// processed (a bug: the sweep never goes backwards in x).
    pub(crate) fn behind(&self) -> bool {
        self.behind
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

    /// The open-addressing table against a plain map, through growth,
    /// long runs of colliding homes (points on a small grid, many
    /// removals shifting entries back) and points with the x of an empty
    /// cell: the same counts, every point in one place, and every
    /// remaining point still found after each removal.
    #[test]
    fn point_table_matches_a_plain_map() {
        let mut g = test_support::rng::Xorshift64::new(0x0DDB_A11C_E5EE_D042);
        let odd = f64::from_bits(EMPTY_X);
        for range in [4u64, 40, 400, 1 << 30] {
            let mut t = PointTable::default();
            let mut plain: HashMap<Pt, u32> = HashMap::new();
            for step in 0..20_000 {
                let x = if g.below(50) == 0 {
                    odd
                } else {
                    g.below(range) as f64 * 0.5
                };
                let p = Pt::new([x, g.below(4) as f64]);
                // Growing phases and shrinking ones.
                let grow = (step / 2000) % 2 == 0;
                match g.below(4) {
                    0 | 1 if grow => {
                        let k = g.below(1000) as u32;
                        let slot = t.get_or_zero(p);
                        *slot = (*slot).max(k);
                        let e = plain.entry(p).or_insert(0);
                        *e = (*e).max(k);
                    }
                    0..=2 => assert_eq!(t.remove(p), plain.remove(&p), "{p:?}"),
                    _ => assert_eq!(t.get(p), plain.get(&p).copied()),
                }
                assert_eq!(t.is_empty(), plain.is_empty());
                assert!(t.len * 4 <= t.cells.len().max(1));
                if step % 997 == 0 {
                    for (q, k) in &plain {
                        assert_eq!(t.get(*q), Some(*k));
                    }
                    let used = t.cells.iter().filter(|c| c.0.x.to_bits() != EMPTY_X);
                    assert_eq!(used.count(), t.len);
                }
            }
        }
    }

    /// Random operations as the sweep makes them (points processed and
    /// looked up at or right of the current column, with backward steps
    /// within it and repeats), against plain maps that keep every point:
    /// ids and counts agree, although the table forgets earlier columns.
    #[test]
    fn matches_a_plain_map() {
        let mut rnd = {
            let mut g = test_support::rng::Xorshift64::new(0x9E37_79B9_7F4A_7C15u64);
            move |n: u64| g.below(n)
        };
        let mut t = VertexTable::default();
        let mut ids: HashMap<Pt, u32> = HashMap::new();
        let mut ks: HashMap<Pt, u32> = HashMap::new();
        // The x of the largest processed point.
        let mut column = 0.0f64;
        let (mut late, mut columns) = (0, 0);
        for _ in 0..20_000 {
            let p = Pt::new([column + rnd(3) as f64 * 0.5, rnd(4) as f64]);
            match rnd(3) {
                0 => {
                    let (id, k, new) = t.process(p, true);
                    let next = ids.len() as u32;
                    assert_eq!(new, !ids.contains_key(&p));
                    assert_eq!(id, *ids.entry(p).or_insert(next));
                    assert_eq!(k, ks.get(&p).copied().unwrap_or(0));
                    late += usize::from(new && !t.late.is_empty());
                    if p.x > column {
                        columns += 1;
                        column = p.x;
                    }
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
            assert!(!t.behind());
            // Only the current column is held.
            assert!(t.column.iter().all(|d| d.p.x == column));
            assert!(t.late.keys().all(|q| q.x == column));
        }
        assert_eq!(t.processed as usize, ids.len());
        assert!(
            late > 100 && columns > 1000,
            "{late} late, {columns} columns"
        );
    }

    /// A look-up or an event behind the current column is recorded.
    #[test]
    fn notes_a_point_behind_the_column() {
        let mut t = VertexTable::default();
        t.process(Pt::new([1.0, 0.0]), false);
        t.process(Pt::new([2.0, 5.0]), false);
        t.process(Pt::new([2.0, 1.0]), false);
        assert_eq!(t.k(Pt::new([2.0, 0.0])), 0);
        assert!(!t.behind());
        assert_eq!(t.k(Pt::new([1.0, 0.0])), 0);
        assert!(t.behind());
        let mut t = VertexTable::default();
        t.process(Pt::new([2.0, 0.0]), false);
        t.process(Pt::new([1.0, 0.0]), false);
        assert!(t.behind());
    }
}
