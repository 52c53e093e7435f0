//! The modified Bentley-Ottmann sweep of sections 7.3-7.6, run on the
//! current (not the original) data.
//!
//! State, as in section 7.4.1:
//!
//! - the *pending* edges: the input edges not yet reached and the buffer
//!   edges created by splitting, in one edge collection with multiplicity
//!   (section 7.1.2), keyed by (leftmost, rightmost) point;
//! - the *sweep line*: a vector of edges in logical bottom-to-top order, each
//!   holding the winding number of the cell below it (section 7.4.3);
//! - the multiset of right end points of sweep-line edges.
//!
//! The next event point is the smaller of the first pending left point and
//! the first sweep-line right point. Processing an event (section 7.6.2):
//! find the group of sweep-line edges that do not pass under nor over it,
//! split every edge of the group that does not end there, send the parts to
//! its left to the output (with the winding numbers on both sides), insert
//! the parts to its right together with the pending edges starting there,
//! ordered by gradient, and test each newly adjacent pair once for a
//! vertex-on-edge relation (section 6.5) or a crossing (Tables 7.1 and 7.2).
//! A pair found to cross is split at the computed point, the left parts
//! staying on the sweep line and the right parts going to the buffer
//! (section 7.4.1). Split parts are never re-tested (section 8.4, footnote
//! 2): the sweep never iterates to a fixed point (section 7.6.3).

use crate::cells::{CellEdge, CellStructure, Fan, SweepStats};
use crate::point::Pt;
use crate::winding::Winding;
use crate::SimplifyError;
use robust_arith::{interpolate, y_at_x};
use std::collections::{BTreeMap, HashMap};
use std::hash::{BuildHasherDefault, Hasher};

/// A small multiplicative hasher for point keys (two `u64` bit patterns):
/// the vertex map is on the hot path and needs no DoS resistance.
#[derive(Default)]
struct PointHasher(u64);

impl Hasher for PointHasher {
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    #[inline]
    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

type PointMap<V> = HashMap<Pt, V, BuildHasherDefault<PointHasher>>;

/// One directed input edge `a -> b` with multiplicity `mult`, and the index
/// of the original edge it stands for (provenance).
pub(crate) struct InputEdge<W> {
    pub(crate) a: [f64; 2],
    pub(crate) b: [f64; 2],
    pub(crate) mult: W,
    pub(crate) origin: u32,
}

/// A pending (input or buffer) edge: multiplicity in the direction
/// leftmost -> rightmost, adjustment count, provenance.
struct Pending<W> {
    m: W,
    k: u32,
    origin: u32,
}

/// A sweep-line edge from its logical left point `l` (already processed)
/// to its logical right point `r` (not yet processed). Normally `l ≺ r`;
/// a downward vertical edge (section 7.6.1) has `r ≺ l` with equal x.
#[derive(Clone, Debug)]
struct SweepEdge<W> {
    l: Pt,
    r: Pt,
    /// Multiplicity in the direction `l -> r`: the winding number above is
    /// `below + m`.
    m: W,
    /// The winding number of the cell below (section 7.4.3).
    below: W,
    k: u32,
    origin: u32,
    id: u32,
}

impl<W> SweepEdge<W> {
    #[inline]
    fn is_vertical(&self) -> bool {
        self.l.x == self.r.x
    }
}

/// How a sweep-line edge relates to the event point (section 7.5.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Ends,
    Under,
    Through,
    Over,
}

#[derive(Clone, Copy, Debug)]
struct VInfo {
    id: u32,
    k: u32,
}

const NO_ID: u32 = u32::MAX;

struct Sweep<W: Winding> {
    dims: usize,
    pending: BTreeMap<(Pt, Pt), Pending<W>>,
    line: Vec<SweepEdge<W>>,
    ends: BTreeMap<Pt, u32>,
    vinfo: PointMap<VInfo>,
    scratch_group: Vec<SweepEdge<W>>,
    scratch_block: Vec<(Pt, W, u32, u32)>,
    vertices: Vec<[f64; 2]>,
    edges: Vec<CellEdge<W>>,
    id_to_edge: Vec<u32>,
    fans: Vec<Fan<W>>,
    fan_ids: Vec<u32>,
    x_s: f64,
    stats: SweepStats,
}

/// Runs the sweep on the given edges and returns the cell structure.
pub(crate) fn run<W: Winding>(
    input: Vec<InputEdge<W>>,
    dims: usize,
    max_abs: f64,
) -> Result<CellStructure<W>, SimplifyError> {
    let n = input.len();
    let mut s = Sweep {
        dims,
        pending: BTreeMap::new(),
        line: Vec::new(),
        ends: BTreeMap::new(),
        vinfo: PointMap::with_capacity_and_hasher(n * 2, Default::default()),
        scratch_group: Vec::new(),
        scratch_block: Vec::new(),
        vertices: Vec::with_capacity(n * 2),
        edges: Vec::with_capacity(n * 2),
        id_to_edge: Vec::with_capacity(n * 2),
        fans: Vec::with_capacity(n * 2),
        fan_ids: Vec::with_capacity(n * 4),
        x_s: f64::NEG_INFINITY,
        stats: SweepStats {
            input_edges: n,
            ..SweepStats::default()
        },
    };
    for e in input {
        s.add_pending(Pt::new(e.a), Pt::new(e.b), e.mult, 0, e.origin);
    }
    s.stats.merged_input_edges = s.pending.len();
    // Section 7.6.3 bounds the work polynomially; this cap only turns a bug
    // into an error instead of a hang.
    let m = s.pending.len() as u64 + 2;
    let cap = m
        .saturating_mul(m)
        .saturating_mul(8)
        .saturating_add(1 << 20);
    loop {
        let pe = s.pending.keys().next().map(|k| k.0);
        let se = s.ends.keys().next().copied();
        let p = match (pe, se) {
            (Some(a), Some(b)) => a.min(b),
            (Some(a), None) => a,
            (None, Some(b)) => b,
            (None, None) => break,
        };
        s.stats.events += 1;
        if s.stats.events > cap {
            return Err(SimplifyError::Internal(format!(
                "event limit {cap} exceeded (section 7.6.3 bound)"
            )));
        }
        s.process(p)?;
    }
    if !s.line.is_empty() {
        return Err(SimplifyError::Internal(format!(
            "{} edges left on the sweep line",
            s.line.len()
        )));
    }
    // Translate the fans from sweep-edge ids to cell-edge indices.
    let mut fan_edges = Vec::with_capacity(s.fan_ids.len());
    for &id in &s.fan_ids {
        let e = s.id_to_edge.get(id as usize).copied().unwrap_or(NO_ID);
        if e == NO_ID {
            return Err(SimplifyError::Internal(format!(
                "sweep edge {id} was never sent to the output"
            )));
        }
        fan_edges.push(e);
    }
    let k_max = s.edges.iter().map(|e| e.k).max().unwrap_or(0);
    s.stats.max_sweep_len = s.stats.max_sweep_len.max(s.line.len());
    Ok(CellStructure::new(
        s.vertices, s.edges, s.fans, fan_edges, k_max, max_abs, dims, s.stats,
    ))
}

impl<W: Winding> Sweep<W> {
    /// Adds the directed edge `a -> b` (multiplicity `m`) to the pending
    /// collection, merging with an identical edge (section 7.1.2; Table 7.3).
    /// A buffer edge going downwards vertically is thereby reversed with its
    /// multiplicity negated (section 7.6.1).
    fn add_pending(&mut self, a: Pt, b: Pt, m: W, k: u32, origin: u32) {
        let (key, m) = if a < b {
            ((a, b), m)
        } else if a != b {
            ((b, a), m.negated())
        } else {
            return;
        };
        match self.pending.entry(key) {
            std::collections::btree_map::Entry::Vacant(v) => {
                if !m.is_zero() {
                    v.insert(Pending { m, k, origin });
                }
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                let slot = o.get_mut();
                slot.m.add_assign(&m);
                slot.k = slot.k.max(k);
                if slot.m.is_zero() {
                    o.remove();
                }
            }
        }
    }

    fn ends_inc(&mut self, p: Pt) {
        *self.ends.entry(p).or_insert(0) += 1;
    }

    fn ends_dec(&mut self, p: Pt) {
        if let Some(c) = self.ends.get_mut(&p) {
            *c -= 1;
            if *c == 0 {
                self.ends.remove(&p);
            }
        }
    }

    fn vertex_k(&self, p: Pt) -> u32 {
        self.vinfo.get(&p).map_or(0, |v| v.k)
    }

    fn raise_vertex_k(&mut self, p: Pt, k: u32) {
        let v = self.vinfo.entry(p).or_insert(VInfo { id: NO_ID, k: 0 });
        v.k = v.k.max(k);
    }

    fn vertex_id(&mut self, p: Pt) -> u32 {
        let next = self.vertices.len() as u32;
        let v = self.vinfo.entry(p).or_insert(VInfo { id: NO_ID, k: 0 });
        if v.id == NO_ID {
            v.id = next;
            self.vertices.push(p.arr());
        }
        v.id
    }

    /// The relation of sweep-line edge `e` to event point `p`, decided with
    /// `y_at_x` (Table 7.1) exactly as the vertex-on-edge rule of section 6.5.
    fn classify(e: &SweepEdge<W>, p: Pt) -> Class {
        if e.r == p {
            return Class::Ends;
        }
        if e.is_vertical() {
            let (lo, hi) = if e.l.y < e.r.y {
                (e.l.y, e.r.y)
            } else {
                (e.r.y, e.l.y)
            };
            return if p.y < lo {
                Class::Over
            } else if p.y > hi {
                Class::Under
            } else {
                Class::Through
            };
        }
        // The sweep guarantees l.x <= p.x <= r.x; clamping only guards the
        // precondition of Table 7.1 against a bug.
        let x = p.x.clamp(e.l.x, e.r.x);
        let y = y_at_x(e.l.arr(), e.r.arr(), x);
        if y < p.y {
            Class::Under
        } else if y > p.y {
            Class::Over
        } else {
            Class::Through
        }
    }

    /// The group of sweep-line edges to be removed at `p`: the half-open
    /// index range `[lo, hi)`. Section 7.6.2 examines the edges from the
    /// bottom until one ends at `p` or does not pass under it, and from the
    /// top until one ends at `p` or does not pass over it. For O(log n) per
    /// event that scan is done by binary search, extended locally past any
    /// misgrouped neighbours; when the result does not hold every edge that
    /// ends at `p` (only possible with inconsistent data), the linear scans
    /// of section 7.6.2 are run instead.
    fn find_group(&mut self, p: Pt, expected_ends: u32) -> Result<(usize, usize), SimplifyError> {
        let line = &self.line;
        let len = line.len();
        let mut lo = line.partition_point(|e| Self::classify(e, p) == Class::Under);
        let mut hi = lo + line[lo..].partition_point(|e| Self::classify(e, p) != Class::Over);
        while lo > 0 && Self::classify(&line[lo - 1], p) != Class::Under {
            lo -= 1;
        }
        while hi < len && Self::classify(&line[hi], p) != Class::Over {
            hi += 1;
        }
        let count = line[lo..hi].iter().filter(|e| e.r == p).count();
        if count == expected_ends as usize {
            return Ok((lo, hi));
        }
        // Section 7.6.2, literally.
        self.stats.full_scans += 1;
        let lo = line
            .iter()
            .position(|e| Self::classify(e, p) != Class::Under)
            .unwrap_or(len);
        let hi = line
            .iter()
            .rposition(|e| Self::classify(e, p) != Class::Over)
            .map_or(0, |i| i + 1);
        let hi = hi.max(lo);
        let count = line[lo..hi].iter().filter(|e| e.r == p).count();
        if count != expected_ends as usize {
            return Err(SimplifyError::Internal(format!(
                "event ({}, {}): {count} of {expected_ends} ending edges found on the sweep line",
                p.x, p.y
            )));
        }
        Ok((lo, hi))
    }

    /// Sends a finished sweep-line edge (from `l` to `r`) to the output.
    fn emit(&mut self, e: &SweepEdge<W>, r: Pt, k: u32) {
        let start = self.vertex_id(e.l);
        let end = self.vertex_id(r);
        let mut left = e.below.clone();
        left.add_assign(&e.m);
        let idx = self.edges.len() as u32;
        self.edges.push(CellEdge {
            start,
            end,
            mult: e.m.clone(),
            left,
            right: e.below.clone(),
            k,
            origin: e.origin,
        });
        if let Some(slot) = self.id_to_edge.get_mut(e.id as usize) {
            *slot = idx;
        }
    }

    fn process(&mut self, p: Pt) -> Result<(), SimplifyError> {
        self.x_s = p.x;
        let vid = self.vertex_id(p);
        let k_p = self.vertex_k(p);
        let expected = self.ends.get(&p).copied().unwrap_or(0);
        let (lo, hi) = self.find_group(p, expected)?;
        let w_lo = if lo > 0 {
            let e = &self.line[lo - 1];
            let mut w = e.below.clone();
            w.add_assign(&e.m);
            w
        } else {
            W::zero(self.dims)
        };
        let fan_start = self.fan_ids.len() as u32;
        // Right parts of split edges and pending edges starting at p:
        // (right point, multiplicity, k, origin).
        let mut block = std::mem::take(&mut self.scratch_block);
        block.clear();
        let mut group = std::mem::take(&mut self.scratch_group);
        group.clear();
        group.extend(self.line.drain(lo..hi));
        let mut w_hi = w_lo.clone();
        for e in group.drain(..) {
            w_hi.add_assign(&e.m);
            self.fan_ids.push(e.id);
            if e.r == p {
                self.ends_dec(p);
                let k = e.k;
                self.emit(&e, p, k);
            } else {
                // Passes through p, or misgrouped (section 7.6.2): split at p.
                match Self::classify(&e, p) {
                    Class::Through | Class::Ends => self.stats.through_splits += 1,
                    Class::Under | Class::Over => self.stats.misgrouped_splits += 1,
                }
                let k = (e.k + 1).max(k_p);
                self.ends_dec(e.r);
                self.emit(&e, p, k);
                block.push((e.r, e.m.clone(), k, e.origin));
            }
        }
        let fan_mid = self.fan_ids.len() as u32;
        // Pending edges whose leftmost point is p (they are first in order).
        while let Some(entry) = self.pending.first_entry() {
            if entry.key().0 != p {
                break;
            }
            let r = entry.key().1;
            let d = entry.remove();
            block.push((r, d.m, d.k, d.origin));
        }
        // Order by gradient (section 7.3), vertical (upwards) last; identical
        // segments become adjacent and are merged (section 6.5).
        let key = |r: &Pt| -> (u8, f64) {
            if r.x > p.x {
                (0, (r.y - p.y) / (r.x - p.x))
            } else {
                (1, 0.0)
            }
        };
        block.sort_by(|a, b| {
            let (ka, kb) = (key(&a.0), key(&b.0));
            ka.0.cmp(&kb.0)
                .then(ka.1.total_cmp(&kb.1))
                .then(a.0.cmp(&b.0))
        });
        self.scratch_group = group;
        let mut merged: Vec<(Pt, W, u32, u32)> = Vec::with_capacity(block.len());
        for item in block.drain(..) {
            if let Some(last) = merged.last_mut() {
                if last.0 == item.0 {
                    last.1.add_assign(&item.1);
                    last.2 = last.2.max(item.2);
                    continue;
                }
            }
            merged.push(item);
        }
        self.scratch_block = block;
        merged.retain(|it| !it.1.is_zero());
        let mut w = w_lo.clone();
        let mut new_edges = Vec::with_capacity(merged.len());
        for (r, m, k, origin) in merged {
            let id = self.id_to_edge.len() as u32;
            self.id_to_edge.push(NO_ID);
            self.fan_ids.push(id);
            self.ends_inc(r);
            let below = w.clone();
            w.add_assign(&m);
            new_edges.push(SweepEdge {
                l: p,
                r,
                m,
                below,
                k,
                origin,
                id,
            });
        }
        let n_new = new_edges.len();
        self.line.splice(lo..lo, new_edges);
        self.stats.max_sweep_len = self.stats.max_sweep_len.max(self.line.len());
        self.fans.push(Fan {
            vertex: vid,
            below: w_lo,
            above: w_hi,
            start: fan_start,
            mid: fan_mid,
            end: self.fan_ids.len() as u32,
        });
        // Test each newly adjacent pair once.
        let len = self.line.len();
        if len >= 2 {
            let first = lo.saturating_sub(1);
            let last = (lo + n_new).min(len - 1);
            for j in first..last {
                self.test_pair(j);
            }
        }
        Ok(())
    }

    /// `true` when `q` lies in the interior of edge `e` by the rule of
    /// section 6.5: on a non-vertical edge when `q.y` equals the computed
    /// `y_at_x(q.x)` exactly; on a vertical edge when x is equal and y is
    /// strictly between.
    fn on_interior(q: Pt, e: &SweepEdge<W>) -> bool {
        if q == e.l || q == e.r {
            return false;
        }
        if e.is_vertical() {
            let (lo, hi) = if e.l.y < e.r.y {
                (e.l.y, e.r.y)
            } else {
                (e.r.y, e.l.y)
            };
            q.x == e.l.x && lo < q.y && q.y < hi
        } else {
            e.l.x <= q.x && q.x <= e.r.x && q.y == y_at_x(e.l.arr(), e.r.arr(), q.x)
        }
    }

    /// The y-values of `e` at the two ends of an x-range (Table 7.1); for a
    /// vertical edge its logical start and end y.
    fn y_range(e: &SweepEdge<W>, x_l: f64, x_r: f64) -> (f64, f64) {
        if e.is_vertical() {
            (e.l.y, e.r.y)
        } else {
            (
                y_at_x(e.l.arr(), e.r.arr(), x_l),
                y_at_x(e.l.arr(), e.r.arr(), x_r),
            )
        }
    }

    /// Shortens sweep-line edge `i` to end at `q`, sending the rest to the
    /// buffer (section 7.4.1). Returns the new adjustment count (section 8.4:
    /// one more than the edge's, at least the vertex's).
    fn split(&mut self, i: usize, q: Pt, k_q: u32) -> u32 {
        let (old_r, m, k, origin) = {
            let e = &mut self.line[i];
            let k = (e.k + 1).max(k_q);
            let old_r = e.r;
            e.r = q;
            e.k = k;
            (old_r, e.m.clone(), k, e.origin)
        };
        self.ends_dec(old_r);
        self.ends_inc(q);
        self.add_pending(q, old_r, m, k, origin);
        k
    }

    /// Tests the adjacent sweep-line edges `i` (logically below) and `i + 1`.
    fn test_pair(&mut self, i: usize) {
        let (a, b) = match (self.line.get(i), self.line.get(i + 1)) {
            (Some(a), Some(b)) => (a, b),
            _ => return,
        };
        if a.r == b.r {
            return;
        }
        // A limit point of one edge in the interior of the other (section
        // 6.5, figure 7.6): split the other there.
        if Self::on_interior(a.r, b) {
            let v = a.r;
            let kv = self.vertex_k(v);
            self.split(i + 1, v, kv);
            self.stats.vertex_on_edge_splits += 1;
            return;
        }
        if Self::on_interior(b.r, a) {
            let v = b.r;
            let kv = self.vertex_k(v);
            self.split(i, v, kv);
            self.stats.vertex_on_edge_splits += 1;
            return;
        }
        if a.is_vertical() && b.is_vertical() {
            return;
        }
        // The x-range both edges span to the right of the sweep line.
        let x_l = a.l.x.max(b.l.x).max(self.x_s);
        let x_r = a.r.x.min(b.r.x);
        if x_l > x_r {
            return;
        }
        let (y_al, y_ar) = Self::y_range(a, x_l, x_r);
        let (y_bl, y_br) = Self::y_range(b, x_l, x_r);
        // Table 7.2 precondition: A not above B on the left, strictly above
        // on the right (the opposite order to the logical one).
        let crosses = y_al <= y_bl && y_br < y_ar;
        if !crosses {
            return;
        }
        let q = interpolate(x_l, y_al, y_bl, x_r, y_ar, y_br);
        // Eq. 8.18-8.19 guarantee q lies in both bounding boxes; clamping
        // changes nothing then and keeps the sweep monotone in x otherwise.
        let (a_lo, a_hi) = (a.l.y.min(a.r.y), a.l.y.max(a.r.y));
        let (b_lo, b_hi) = (b.l.y.min(b.r.y), b.l.y.max(b.r.y));
        let qx = q[0].clamp(x_l, x_r);
        let (ylo, yhi) = (a_lo.max(b_lo), a_hi.min(b_hi));
        let qy = if ylo <= yhi {
            q[1].clamp(ylo, yhi)
        } else {
            q[1]
        };
        let q = Pt::new([qx, qy]);
        self.stats.intersections += 1;
        let split_a = q != a.l && q != a.r;
        let split_b = q != b.l && q != b.r;
        let k_q = self.vertex_k(q);
        let mut k_new = k_q;
        if split_a {
            k_new = k_new.max(self.split(i, q, k_q));
        }
        if split_b {
            k_new = k_new.max(self.split(i + 1, q, k_q));
        }
        self.raise_vertex_k(q, k_new);
    }
}
