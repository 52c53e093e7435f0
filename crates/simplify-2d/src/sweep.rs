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
//! - the right end points of sweep-line edges, counted by slot
//!   (`end_points.rs`).
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
//!
//! What the output keeps ([`Output`]): a cell structure handed to the
//! caller keeps every edge and the rotations around the vertices; a
//! simplification or Boolean keeps only the edges its rule will select
//! (the edges separating an accepted cell from a rejected one, section
//! 7.4.3), decided as each edge leaves the sweep line. The sweep's
//! decisions never depend on the output, so both runs compute the same
//! arrangement; the second just does not hold the edges inside or outside
//! the result (most of a random polygon's arrangement, section 7.7), which
//! bounds its memory by the result instead of the arrangement.

use crate::buffer_heap::{BufferHeap, Entry};
use crate::cells::{CellEdge, CellStructure, Extent, Fan, Keyed, SweepStats};
use crate::end_points::{EndPoints, Slot};
use crate::point::{Pt, SortKey};
use crate::strips::{run_in_strips, strip_count, STRIP_MIN_EDGES};
use crate::sweep_line::SweepLine;
use crate::vertex_table::VertexTable;
use crate::winding::Winding;
use crate::SimplifyError;
use robust_arith::{interpolate, y_at_x};
use std::cmp::Ordering;

/// One directed input edge `a -> b` with multiplicity `mult`, and the index
/// of the original edge it stands for (provenance).
#[derive(Clone)]
pub(crate) struct InputEdge<W> {
    pub(crate) a: [f64; 2],
    pub(crate) b: [f64; 2],
    pub(crate) mult: W,
    pub(crate) origin: u32,
}

/// A pending (input or buffer) edge from `l` to `r` (`l ≺ r`): multiplicity
/// in the direction `l -> r`, adjustment count, provenance, and the order in
/// which it was added to the collection (`seq`; input edges are 0).
struct Pending<W> {
    l: Pt,
    r: Pt,
    seq: u64,
    m: W,
    k: u32,
    origin: u32,
    /// The counting slot of `r` (`end_points.rs`).
    rslot: Slot,
}

/// Merges pending edges in place, given sorted by `(l, r, seq)`, exactly
/// as the edge collection of section 7.1.2 would have merged them one at a
/// time in `seq` order: identical edges add their multiplicities and keep
/// the larger adjustment count and the first provenance; an edge whose
/// multiplicity cancels to zero is removed, and a later identical edge
/// starts afresh.
#[inline]
fn merge_identical<W: Winding>(items: &mut Vec<Pending<W>>) {
    // Most points start edges to distinct right points, none cancelled:
    // nothing to merge (checked here, inline, the merge apart).
    if items
        .windows(2)
        .all(|w| w[0].l != w[1].l || w[0].r != w[1].r)
        && items.iter().all(|e| !e.m.is_zero())
    {
        return;
    }
    merge_runs(items);
}

/// [`merge_identical`] when some edges are identical or cancelled.
#[inline(never)]
fn merge_runs<W: Winding>(items: &mut Vec<Pending<W>>) {
    // Items before `w` are the result; `open` while the last of them may
    // still absorb identical edges.
    let mut w: usize = 0;
    let mut open = false;
    for rd in 0..items.len() {
        let (done, rest) = items.split_at_mut(rd);
        let it = &rest[0];
        if open {
            if let Some(last) = done.get_mut(w.wrapping_sub(1)) {
                if last.l == it.l && last.r == it.r {
                    last.m.add_assign(&it.m);
                    last.k = last.k.max(it.k);
                    if last.m.is_zero() {
                        w -= 1;
                        open = false;
                    }
                    continue;
                }
            }
        }
        open = !it.m.is_zero();
        if open {
            items.swap(w, rd);
            w += 1;
        }
    }
    items.truncate(w);
}

/// Sorts `v` stably by `order`: by insertion when it holds a few items (as
/// at most events), else by the standard library's merge sort.
fn sort_small_by<T>(v: &mut [T], order: impl Fn(&T, &T) -> Ordering) {
    if v.len() <= 8 {
        for i in 1..v.len() {
            let mut j = i;
            while j > 0 && order(&v[j - 1], &v[j]) == Ordering::Greater {
                v.swap(j - 1, j);
                j -= 1;
            }
        }
    } else {
        v.sort_by(order);
    }
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
    /// The output vertex id of `l` (processed, so already a vertex).
    lid: u32,
    /// The counting slot of `r` (`end_points.rs`).
    rslot: Slot,
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

const NO_ID: u32 = u32::MAX;

/// An edge about to be inserted at the event point: its right point, the
/// gradient key of section 7.3 (non-vertical by slope, vertical last),
/// multiplicity, adjustment count, provenance.
struct NewEdge<W> {
    r: Pt,
    vertical: bool,
    slope: f64,
    m: W,
    k: u32,
    origin: u32,
    rslot: Slot,
}

struct Sweep<'k, W: Winding> {
    dims: usize,
    /// The input edges not reached yet, merged (section 7.1.2) and sorted
    /// by `(l, r)` in reverse: the next one last, the memory of those
    /// taken given back as the sweep goes.
    input: Vec<Pending<W>>,
    /// Buffer edges (section 7.4.1), by left point.
    buffer: BufferHeap,
    /// The buffer edges by slot, and the free slots.
    slab: Vec<Option<Pending<W>>>,
    /// The next slot of the buffer edges that share one heap entry (both
    /// right parts of a crossing start at its point), `NO_ID` at the end.
    links: Vec<u32>,
    free: Vec<u32>,
    next_seq: u64,
    line: SweepLine<SweepEdge<W>>,
    /// The right end points of the sweep-line edges.
    ends: EndPoints,
    points: VertexTable,
    scratch_block: Vec<NewEdge<W>>,
    scratch_new: Vec<SweepEdge<W>>,
    scratch_pending: Vec<Pending<W>>,
    /// The output edges.
    out: Emitted<'k, W>,
    /// Whether the rotations around the vertices are recorded (below), for
    /// [`CellStructure::check_cells`].
    record: bool,
    fans: Vec<Fan<W>>,
    fan_ids: Vec<u32>,
    x_s: f64,
    stats: SweepStats,
    /// Whether both right parts of a crossing share one heap entry
    /// ([`Sweep::add_pending`]): always, except in the tests that compare
    /// the sweep with and without.
    join: bool,
}

/// What a sweep keeps (the sweep decides the same either way).
#[derive(Clone, Copy)]
pub(crate) enum Output<'k, W> {
    /// Every edge, and the rotation of the edges around every vertex (the
    /// fans that [`CellStructure::check_cells`] verifies): a structure
    /// handed to the caller.
    All,
    /// Only the edges separating a cell that `keep` accepts from one it
    /// rejects (`keep(left) != keep(right)`, zero-length edges dropped),
    /// and no rotations: the edges that
    /// [`CellStructure::into_shape_with`] with the same `keep` selects,
    /// for a simplification or Boolean that consumes the structure at once.
    Boundary(&'k (dyn Fn(&W) -> bool + Sync)),
}

/// The edges the sweep sends to the output, filtered by [`Output`], and the
/// largest adjustment count of every edge sent, kept or not (section 8.4:
/// the bound covers the whole arrangement, as when every edge is kept).
struct Emitted<'k, W> {
    /// Every edge ([`Output::All`]).
    edges: Vec<CellEdge<W>>,
    /// The kept edges ([`Output::Boundary`]), directed with the accepted
    /// cell on their left and keyed as [`CellStructure::selected`] keys
    /// them (all that the shape needs).
    sel: Keyed,
    /// The output vertices: every processed point by id ([`Output::All`]),
    /// or the ends of the kept edges ([`Output::Boundary`]).
    vertices: Vec<[f64; 2]>,
    /// For [`Output::Boundary`], the output vertex of each processed point
    /// (by id), `NO_ID` until a kept edge uses it: 4 bytes a point instead
    /// of the 16 of its position.
    out_id: Vec<u32>,
    /// The output edge of each sweep-line edge id, while recording.
    id_to_edge: Vec<u32>,
    keep: Option<&'k (dyn Fn(&W) -> bool + Sync)>,
    k_max: u32,
    /// Where the arrangement lies, kept or not (`strips.rs` checks it).
    extent: Extent,
}

impl<W: Winding> Emitted<'_, W> {
    /// Notes a newly processed point `p`, whose id is the next one.
    fn add_point(&mut self, p: Pt) {
        self.extent.add(p);
        if self.keep.is_none() {
            self.vertices.push(p.arr());
        } else {
            self.out_id.push(NO_ID);
        }
    }

    /// The output vertex of the processed point with id `id` at `p`.
    fn vertex(&mut self, id: u32, p: Pt) -> u32 {
        if self.keep.is_none() {
            return id;
        }
        match self.out_id.get_mut(id as usize) {
            Some(v) => {
                if *v == NO_ID {
                    *v = self.vertices.len() as u32;
                    self.vertices.push(p.arr());
                }
                *v
            }
            None => NO_ID,
        }
    }

    /// The output vertices and edges. For [`Output::Boundary`] the kept
    /// vertices are renumbered in the order of their ids (the order in
    /// which they were processed, lexicographic but for the backward steps
    /// of section 7.6.1), which is the order the complete structure gives
    /// them: the vertices of the structure are then its vertices that a
    /// kept edge uses, in its order. Linear: no sort, and the positions
    /// are permuted in place.
    #[allow(clippy::type_complexity)]
    fn finish(self) -> (Vec<[f64; 2]>, Vec<CellEdge<W>>, Option<Keyed>) {
        let Emitted {
            edges,
            mut sel,
            mut vertices,
            out_id,
            keep,
            ..
        } = self;
        if keep.is_none() {
            return (vertices, edges, None);
        }
        // The rank of every kept vertex among the kept ones, by id.
        let mut rank = vec![NO_ID; vertices.len()];
        let mut next = 0u32;
        for &v in &out_id {
            if let Some(r) = rank.get_mut(v as usize) {
                *r = next;
                next += 1;
            }
        }
        drop(out_id);
        let at = |v: u32| rank.get(v as usize).copied().unwrap_or(NO_ID);
        for e in &mut sel {
            (e.0, e.1) = (at(e.0), at(e.1));
        }
        // Move the position at `i` to `rank[i]`, following the cycles.
        for i in 0..rank.len() {
            loop {
                let j = rank[i] as usize;
                if j == i || j >= rank.len() {
                    break;
                }
                vertices.swap(i, j);
                rank.swap(i, j);
            }
        }
        (vertices, edges, Some(sel))
    }

    /// Sends a finished sweep-line edge (from `l` to the vertex `end` at
    /// `p`) to the output edges; it leaves the sweep line.
    fn emit(&mut self, e: &SweepEdge<W>, end: u32, p: Pt, k: u32) {
        self.k_max = self.k_max.max(k);
        if e.l.x == p.x && e.l.y != p.y {
            self.extent.add_vertical(p.x);
        }
        let start = e.lid;
        let mut left = e.below.clone();
        left.add_assign(&e.m);
        if let Some(keep) = self.keep {
            let accepted = keep(&left);
            if start == end || accepted == keep(&e.below) {
                return;
            }
            // Directed with the accepted cell on the left, keyed by the
            // lexicographic order of the ends (distinct ids are distinct
            // points), as `CellStructure::selected` keys it.
            let (a, b) = if accepted {
                ((start, e.l), (end, p))
            } else {
                ((end, p), (start, e.l))
            };
            let (ia, ib) = (self.vertex(a.0, a.1), self.vertex(b.0, b.1));
            self.sel
                .push(if a.1 < b.1 { (ia, ib, 1) } else { (ib, ia, -1) });
            return;
        }
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
}

/// Runs the sweep on the given edges (about `n` of them) and returns the
/// cell structure. A structure kept for its shape only
/// ([`Output::Boundary`]) of a large input is swept in vertical strips in
/// parallel (`strips.rs`).
pub(crate) fn run<W: Winding + Sync>(
    input: impl IntoIterator<Item = InputEdge<W>>,
    n: usize,
    dims: usize,
    max_abs: f64,
    output: Output<'_, W>,
) -> Result<CellStructure<W>, SimplifyError> {
    match output {
        Output::Boundary(keep) if n >= STRIP_MIN_EDGES => {
            let input: Vec<InputEdge<W>> = input.into_iter().collect();
            let strips = strip_count(&input);
            run_in_strips(input, strips, dims, max_abs, keep)
        }
        _ => run_with(input, n, dims, max_abs, output, true),
    }
}

/// [`run`], joining the right parts of a crossing in the buffer heap or
/// not (`join`; the tests compare both).
pub(crate) fn run_with<W: Winding + Sync>(
    input: impl IntoIterator<Item = InputEdge<W>>,
    n: usize,
    dims: usize,
    max_abs: f64,
    output: Output<'_, W>,
    join: bool,
) -> Result<CellStructure<W>, SimplifyError> {
    // The edge collection of section 7.1.2 for the input: keyed by
    // (leftmost, rightmost) point, negative multiplicity for edges running
    // right to left, zero-length edges dropped, identical edges merged in
    // input order.
    let mut keyed: Vec<Pending<W>> = Vec::with_capacity(n);
    let mut count = 0;
    for (i, e) in input.into_iter().enumerate() {
        count = i + 1;
        let (a, b) = (Pt::new(e.a), Pt::new(e.b));
        let (l, r, m) = match a.cmp(&b) {
            Ordering::Less => (a, b, e.mult),
            Ordering::Greater => (b, a, e.mult.negated()),
            Ordering::Equal => continue,
        };
        // The input position, for the sort below.
        keyed.push(Pending {
            l,
            r,
            seq: i as u64,
            m,
            k: 0,
            origin: e.origin,
            rslot: 0,
        });
    }
    sweep(keyed, count, dims, max_abs, output, join)
}

/// The sweep proper, on the keyed input edges (in input order, `seq` the
/// position) of `n` input edges. Not generic over the input's source, so
/// that one copy serves every entry point.
fn sweep<W: Winding + Sync>(
    mut keyed: Vec<Pending<W>>,
    n: usize,
    dims: usize,
    max_abs: f64,
    output: Output<'_, W>,
    join: bool,
) -> Result<CellStructure<W>, SimplifyError> {
    let (record, keep) = match output {
        Output::All => (true, None),
        Output::Boundary(keep) => (false, Some(keep)),
    };
    let log_cap = |c: usize| if record { c } else { 0 };
    // Sorted by key; identical edges stay in input order (a stable sort),
    // as the collection would have merged them one at a time. The stable
    // merge sort gives the order of an unstable sort with the position as
    // the tie-break, faster (1.0 against 1.5 ms on the checkerboards of
    // the simplification table). It sorts positions, and the edges are
    // moved once into place (`cells::stable_order`: a small buffer).
    let order = crate::cells::stable_order(keyed.len(), |a, b| {
        let (a, b) = (&keyed[a], &keyed[b]);
        a.l.cmp(&b.l).then_with(|| a.r.cmp(&b.r))
    });
    crate::cells::permute(&mut keyed, order);
    merge_identical(&mut keyed);
    // Input edges precede every buffer edge at their left point.
    for e in &mut keyed {
        e.seq = 0;
    }
    let mut merged = keyed;
    let mut ends = EndPoints::new(merged.len(), |i| merged[i].r);
    for (i, slot) in ends.input_slots() {
        if let Some(e) = merged.get_mut(i) {
            e.rslot = slot;
        }
    }
    ends.start();
    // Consumed from the end, shrinking as the sweep passes it.
    merged.reverse();
    let mut s = Sweep {
        dims,
        input: merged,
        buffer: BufferHeap::default(),
        slab: Vec::new(),
        links: Vec::new(),
        free: Vec::new(),
        next_seq: 1,
        line: SweepLine::default(),
        ends,
        points: VertexTable::default(),
        scratch_block: Vec::new(),
        scratch_new: Vec::new(),
        scratch_pending: Vec::new(),
        out: Emitted {
            // Every edge: room for one crossing per input edge (each adds
            // two edges), so that the largest output vector rarely moves.
            // The boundary: the input's size (it grows when the result
            // has more edges than the input).
            edges: Vec::with_capacity(if record { n * 3 } else { 0 }),
            sel: Vec::with_capacity(if record { 0 } else { n }),
            id_to_edge: Vec::with_capacity(log_cap(n * 3)),
            // Every processed point, or the ends of the kept edges (on an
            // n-gon union, every input point and one crossing per edge).
            vertices: Vec::with_capacity(n * 2),
            out_id: Vec::with_capacity(if record { 0 } else { n * 2 }),
            keep,
            k_max: 0,
            extent: Extent::default(),
        },
        record,
        fans: Vec::with_capacity(log_cap(n * 2)),
        fan_ids: Vec::with_capacity(log_cap(n * 6)),
        x_s: f64::NEG_INFINITY,
        stats: SweepStats {
            input_edges: n,
            ..SweepStats::default()
        },
        join,
    };
    s.stats.merged_input_edges = s.input.len();
    // Section 7.6.3 bounds the work polynomially; this cap only turns a bug
    // into an error instead of a hang.
    let m = s.input.len() as u64 + 2;
    let cap = m
        .saturating_mul(m)
        .saturating_mul(8)
        .saturating_add(1 << 20);
    loop {
        // The sources of the next event point compare as sort keys, and
        // the point is decoded once.
        let pe = s.first_pending();
        let se = s.ends.candidate();
        let key = match (pe, se) {
            (Some(a), Some(b)) => a.min(b),
            (Some(a), None) => a,
            (None, Some(b)) => b,
            (None, None) => break,
        };
        let p = Pt::from_sort_key(key);
        let mut pending = std::mem::take(&mut s.scratch_pending);
        pending.clear();
        let (mut ending, mut split_point) = s.ends.reach(p, key);
        if pe == Some(key) {
            let (n, buffered) = s.take_pending_at(p, key, &mut pending);
            ending += n;
            split_point |= buffered;
        }
        debug_assert_eq!(
            ending,
            Sweep::ending_in(&s.line, p, 0, s.line.len()),
            "end point count at ({}, {})",
            p.x,
            p.y
        );
        // Pending edges that cancelled out, and a candidate whose edges were
        // shortened or cancelled, never made `p` an event.
        if pending.is_empty() && ending == 0 {
            s.scratch_pending = pending;
            continue;
        }
        s.stats.events += 1;
        if s.stats.events > cap {
            return Err(SimplifyError::Internal(format!(
                "event limit {cap} exceeded (section 7.6.3 bound)"
            )));
        }
        let r = s.process(p, ending, split_point, &mut pending);
        s.scratch_pending = pending;
        r?;
    }
    if !s.line.is_empty() {
        return Err(SimplifyError::Internal(format!(
            "{} edges left on the sweep line",
            s.line.len()
        )));
    }
    // Translate the fans from sweep-edge ids to cell-edge indices, in
    // place (none were recorded when skipping the rotations).
    let mut fan_edges = std::mem::take(&mut s.fan_ids);
    for slot in &mut fan_edges {
        let id = *slot;
        let e = s.out.id_to_edge.get(id as usize).copied().unwrap_or(NO_ID);
        if e == NO_ID {
            return Err(SimplifyError::Internal(format!(
                "sweep edge {id} was never sent to the output"
            )));
        }
        *slot = e;
    }
    if s.points.behind() {
        return Err(SimplifyError::Internal(
            "a point behind the sweep line was looked up".into(),
        ));
    }
    s.stats.max_sweep_len = s.stats.max_sweep_len.max(s.line.len());
    let k_max = s.out.k_max;
    let extent = std::mem::take(&mut s.out.extent);
    let (vertices, edges, boundary) = s.out.finish();
    Ok(CellStructure::new(
        vertices,
        edges,
        record.then_some((s.fans, fan_edges)),
        boundary,
        k_max,
        max_abs,
        dims,
        s.stats,
    )
    .with_extent(extent))
}

impl<W: Winding> Sweep<'_, W> {
    /// Adds the directed buffer edge `a -> b` (multiplicity `m`) to the
    /// pending edges (section 7.4.1). It is keyed like the edge collection
    /// of section 7.1.2, so a buffer edge going downwards vertically is
    /// reversed with its multiplicity negated (section 7.6.1); identical
    /// pending edges merge when their left point is reached.
    ///
    /// The new edge joins to the heap entry of
    /// the buffer edge in slab slot `join` when that edge starts at the
    /// same point with the same counting slot (the two right parts of one
    /// crossing): one heap entry stands for both, which the sweep pops
    /// together, as it would have popped the two entries of one key at the
    /// same event. Returns the slab slot of the new edge when it has one
    /// and is keyed by its first point `a` (not reversed), so that a later
    /// edge from `a` may join it.
    fn add_pending(
        &mut self,
        a: (Pt, Slot),
        b: (Pt, Slot),
        m: W,
        k: u32,
        origin: u32,
        join: Option<u32>,
    ) -> Option<u32> {
        let forward = match a.0.cmp(&b.0) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => return None,
        };
        let (l, r, m) = if forward {
            (a, b, m)
        } else {
            (b, a, m.negated())
        };
        let ((l, lslot), (r, rslot)) = (l, r);
        let seq = self.next_seq;
        self.next_seq += 1;
        let edge = Some(Pending {
            l,
            r,
            seq,
            m,
            k,
            origin,
            rslot,
        });
        let slot = match self.free.pop() {
            Some(slot) => {
                self.slab[slot as usize] = edge;
                self.links[slot as usize] = NO_ID;
                slot
            }
            None => {
                self.slab.push(edge);
                self.links.push(NO_ID);
                (self.slab.len() - 1) as u32
            }
        };
        // The edge in `join` starts at `a` with the counting slot of `a`
        // (the caller passes only such a slot): this one does too when
        // forward, so it rides on that entry, at the end of its chain.
        if let (true, Some(first)) = (forward, join) {
            let mut at = first as usize;
            while let Some(&next) = self.links.get(at) {
                if next == NO_ID {
                    break;
                }
                at = next as usize;
            }
            if let Some(link) = self.links.get_mut(at) {
                *link = slot;
                return Some(slot);
            }
        }
        self.buffer.push(Entry::new(l.sort_key(), slot, lslot));
        forward.then_some(slot)
    }

    /// The smallest left point of a pending edge, as its sort key.
    #[inline]
    fn first_pending(&self) -> Option<SortKey> {
        let a = self.input.last().map(|e| e.l.sort_key());
        let b = self.buffer.peek_key();
        match (a, b) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, None) => a,
            (None, b) => b,
        }
    }

    /// Removes the pending edges whose left point is `p` and returns them
    /// merged (section 7.1.2), sorted by right point, non-zero, in `out`
    /// (empty on entry). Returns the number of sweep-line edges ending at
    /// `p` in the counting slots the buffer edges cover (`end_points.rs`),
    /// and whether any buffer edge started at `p`, whose sort key is `key`.
    fn take_pending_at(&mut self, p: Pt, key: SortKey, out: &mut Vec<Pending<W>>) -> (u32, bool) {
        // Input edges are already merged; move them out (the last ones
        // of the reversed list, taken in key order).
        if self.input.last().is_some_and(|e| e.l == p) {
            while self.input.last().is_some_and(|e| e.l == p) {
                out.extend(self.input.pop());
            }
            crate::cells::release_consumed(&mut self.input);
        }
        let mut ending = 0;
        let mut buffered = false;
        while self.buffer.peek_key() == Some(key) {
            buffered = true;
            if let Some(e) = self.buffer.pop() {
                ending += self.ends.take(e.lslot);
                let mut slot = e.slot;
                while slot != NO_ID {
                    if let Some(edge) = self.slab.get_mut(slot as usize).and_then(Option::take) {
                        out.push(edge);
                    }
                    self.free.push(slot);
                    slot = self.links.get(slot as usize).copied().unwrap_or(NO_ID);
                }
            }
        }
        // The input edges alone are merged and sorted by right point
        // already.
        if buffered {
            sort_small_by(out, |a, b| a.r.cmp(&b.r).then(a.seq.cmp(&b.seq)));
            merge_identical(out);
        }
        (ending, buffered)
    }

    /// The number of edges `lo..hi` of `line` that end at `p`.
    fn ending_in(line: &SweepLine<SweepEdge<W>>, p: Pt, lo: usize, hi: usize) -> u32 {
        let mut n = 0;
        line.for_range(lo, hi, |e| n += u32::from(e.r == p));
        n
    }

    fn vertex_k(&mut self, p: Pt) -> u32 {
        self.points.k(p)
    }

    /// The relation of sweep-line edge `e` to event point `p`, decided with
    /// `y_at_x` (Table 7.1) exactly as the vertex-on-edge rule of section 6.5.
    #[inline]
    fn classify(e: &SweepEdge<W>, p: Pt) -> Class {
        // An edge whose y-range lies wholly below or above `p` passes under
        // or over it; this decides most edges first. It is exact for
        // vertical edges and for an edge ending at `p` (whose range holds
        // `p.y`). For the others, Table 7.1 interpolates from the closer
        // end with |lambda| <= 1/2 (up to rounding), so its result never
        // leaves the edge's y-range (robust-arith's `tests/it/table_7_1.rs`
        // checks this over every magnitude and on the coarse grids of
        // section 7.7): outside that range the answer is known without the
        // division.
        if e.l.y < p.y && e.r.y < p.y {
            return Class::Under;
        }
        if e.l.y > p.y && e.r.y > p.y {
            return Class::Over;
        }
        if e.r == p {
            return Class::Ends;
        }
        if e.is_vertical() {
            // The y-range holds `p.y`.
            return Class::Through;
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
    /// event the lower end is found by binary search, extended locally past
    /// any misgrouped neighbours, and the upper end by scanning up from
    /// there to the first edge passing over `p` (the scan costs no more
    /// than removing the group). When the result does not hold every edge
    /// that ends at `p` (only possible with inconsistent data), the linear
    /// scans of section 7.6.2 are run instead.
    fn find_group(&mut self, p: Pt, expected_ends: u32) -> Result<(usize, usize), SimplifyError> {
        let line = &self.line;
        let len = line.len();
        let class = |i: usize| line.get(i).map(|e| Self::classify(e, p));
        let mut lo = line.partition_point(0, len, |e| Self::classify(e, p) == Class::Under);
        while lo > 0 && class(lo - 1) != Some(Class::Under) {
            lo -= 1;
        }
        // The group's upper end is found by a linear scan from its lower
        // end, counting the edges that end at `p`: every edge it passes is
        // in the group, which the event removes anyway.
        let mut hi = lo;
        let mut count = 0;
        while let Some(c) = class(hi) {
            match c {
                Class::Over => break,
                Class::Ends => count += 1,
                Class::Under | Class::Through => {}
            }
            hi += 1;
        }
        if count == expected_ends {
            return Ok((lo, hi));
        }
        // Inconsistent data (section 7.2) can put an edge passing over `p`
        // below one that ends there: a binary search for the upper end
        // looks past such an edge.
        let mut hi = line.partition_point(lo, len, |e| Self::classify(e, p) != Class::Over);
        while hi < len && class(hi) != Some(Class::Over) {
            hi += 1;
        }
        if Self::ending_in(line, p, lo, hi) == expected_ends {
            return Ok((lo, hi));
        }
        // Section 7.6.2, literally.
        self.stats.full_scans += 1;
        let lo = line
            .position(|e| Self::classify(e, p) != Class::Under)
            .unwrap_or(len);
        let hi = line
            .rposition(|e| Self::classify(e, p) != Class::Over)
            .map_or(0, |i| i + 1);
        let hi = hi.max(lo);
        let count = Self::ending_in(line, p, lo, hi);
        if count != expected_ends {
            return Err(SimplifyError::Internal(format!(
                "event ({}, {}): {count} of {expected_ends} ending edges found on the sweep line",
                p.x, p.y
            )));
        }
        Ok((lo, hi))
    }

    /// Processes event point `p` (section 7.6.2), at which `expected`
    /// sweep-line edges end, with the pending edges starting there (merged,
    /// sorted by right point). `split_point` is `false` when no edge was
    /// split at `p` (no buffer edge or uncovered end starts there), so that
    /// it has no adjustment count yet.
    fn process(
        &mut self,
        p: Pt,
        expected: u32,
        split_point: bool,
        pending: &mut Vec<Pending<W>>,
    ) -> Result<(), SimplifyError> {
        self.x_s = p.x;
        let (vid, k_p, new) = self.points.process(p, split_point);
        if new {
            self.out.add_point(p);
        }
        let (lo, hi) = self.find_group(p, expected)?;
        let w_lo = if lo > 0 {
            match self.line.get(lo - 1) {
                Some(e) => {
                    let mut w = e.below.clone();
                    w.add_assign(&e.m);
                    w
                }
                None => W::zero(self.dims),
            }
        } else {
            W::zero(self.dims)
        };
        let fan_start = self.fan_ids.len() as u32;
        // Right parts of split edges and pending edges starting at p.
        // Scratch vectors, borrowed as fields beside the others.
        let block = &mut self.scratch_block;
        block.clear();
        let mut w_hi = w_lo.clone();
        let gradient = |r: Pt| -> (bool, f64) {
            if r.x > p.x {
                (false, (r.y - p.y) / (r.x - p.x))
            } else {
                (true, 0.0)
            }
        };
        // The group leaves the sweep line (replaced below); its edges are
        // read in place.
        let (out, fan_ids) = (&mut self.out, &mut self.fan_ids);
        let (ends, stats, record) = (&mut self.ends, &mut self.stats, self.record);
        self.line.for_range(lo, hi, |e| {
            if record {
                w_hi.add_assign(&e.m);
                fan_ids.push(e.id);
            }
            if e.r == p {
                out.emit(e, vid, p, e.k);
            } else {
                // Passes through p, or misgrouped (section 7.6.2): split at p.
                match Self::classify(e, p) {
                    Class::Through | Class::Ends => stats.through_splits += 1,
                    Class::Under | Class::Over => stats.misgrouped_splits += 1,
                }
                let k = (e.k + 1).max(k_p);
                out.emit(e, vid, p, k);
                // Its right part is inserted again below (or merged away).
                ends.remove(e.rslot);
                let (vertical, slope) = gradient(e.r);
                block.push(NewEdge {
                    r: e.r,
                    vertical,
                    slope,
                    m: e.m.clone(),
                    k,
                    origin: e.origin,
                    rslot: e.rslot,
                });
            }
        });
        let fan_mid = self.fan_ids.len() as u32;
        for d in pending.drain(..) {
            let (vertical, slope) = gradient(d.r);
            block.push(NewEdge {
                r: d.r,
                vertical,
                slope,
                m: d.m,
                k: d.k,
                origin: d.origin,
                rslot: d.rslot,
            });
        }
        // Order by gradient (section 7.3), vertical (upwards) last; identical
        // segments become adjacent and are merged (section 6.5).
        if block.len() > 1 {
            let order = |a: &NewEdge<W>, b: &NewEdge<W>| {
                a.vertical
                    .cmp(&b.vertical)
                    .then(a.slope.total_cmp(&b.slope))
                    .then(a.r.cmp(&b.r))
            };
            // A stable sort: identical segments keep their order, so the
            // first one's provenance is kept.
            sort_small_by(block, order);
            block.dedup_by(|item, last| {
                if last.r == item.r {
                    last.m.add_assign(&item.m);
                    last.k = last.k.max(item.k);
                    true
                } else {
                    false
                }
            });
        }
        let mut w = w_lo.clone();
        let new_edges = &mut self.scratch_new;
        new_edges.clear();
        for it in block.drain(..) {
            if it.m.is_zero() {
                continue;
            }
            let id = self.out.id_to_edge.len() as u32;
            if self.record {
                self.out.id_to_edge.push(NO_ID);
                self.fan_ids.push(id);
            }
            self.ends.add(it.r, it.rslot);
            let below = w.clone();
            w.add_assign(&it.m);
            new_edges.push(SweepEdge {
                l: p,
                r: it.r,
                m: it.m,
                below,
                k: it.k,
                origin: it.origin,
                id,
                lid: vid,
                rslot: it.rslot,
            });
        }
        let n_new = new_edges.len();
        // One move of the line's tail at most, none when as many edges are
        // inserted as removed (every crossing).
        self.line.replace(lo, hi, new_edges);
        self.stats.max_sweep_len = self.stats.max_sweep_len.max(self.line.len());
        if self.record {
            self.fans.push(Fan {
                vertex: vid,
                below: w_lo,
                above: w_hi,
                start: fan_start,
                mid: fan_mid,
                end: self.fan_ids.len() as u32,
            });
        }
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
            // The computed y never leaves the edge's y-range (see
            // `classify`), so a point outside it is not on the edge.
            e.l.x <= q.x
                && q.x <= e.r.x
                && q.y >= e.l.y.min(e.r.y)
                && q.y <= e.l.y.max(e.r.y)
                && q.y == y_at_x(e.l.arr(), e.r.arr(), q.x)
        }
    }

    /// The y-values of `e` at the two ends of an x-range (Table 7.1); for a
    /// vertical edge its logical start and end y.
    fn y_range(e: &SweepEdge<W>, x_l: f64, x_r: f64) -> (f64, f64) {
        if e.is_vertical() {
            (e.l.y, e.r.y)
        } else {
            (Self::y_at(e, x_l), Self::y_at(e, x_r))
        }
    }

    /// `y_at_x` (Table 7.1) on a non-vertical sweep-line edge. At the end
    /// points it returns their y bit for bit (section 7.1.1; robust-arith
    /// tests it), which is taken directly there without the division.
    #[inline]
    fn y_at(e: &SweepEdge<W>, x: f64) -> f64 {
        if x == e.l.x {
            e.l.y
        } else if x == e.r.x {
            e.r.y
        } else {
            y_at_x(e.l.arr(), e.r.arr(), x)
        }
    }

    /// Shortens sweep-line edge `i` to end at `q`, sending the rest to the
    /// buffer (section 7.4.1). Both parts get the adjustment count of
    /// section 8.4: one more than the edge's, at least the vertex's `k_q`.
    /// `q_slot` is the counting slot of `q` (`end_points.rs`). The buffer
    /// part joins the heap entry of the buffer edge in slab slot `join`, an
    /// edge from `q` with counting slot `q_slot` too, when it can
    /// ([`Sweep::add_pending`]), and its own slab slot is returned
    /// when another part from `q` may join it.
    fn split(&mut self, i: usize, q: Pt, q_slot: Slot, k_q: u32, join: Option<u32>) -> Option<u32> {
        let e = self.line.get_mut(i)?;
        let (old_r, old_slot, m, k, origin) = {
            let k = (e.k + 1).max(k_q);
            let old = (e.r, e.rslot);
            e.r = q;
            e.rslot = q_slot;
            e.k = k;
            (old.0, old.1, e.m.clone(), k, e.origin)
        };
        self.ends.remove(old_slot);
        // The buffer edge from q makes q an event (section 7.4.1), unless
        // it runs downwards vertically and is keyed from its other end
        // (section 7.6.1).
        if q < old_r {
            self.ends.add(q, q_slot);
        } else {
            self.ends.add_uncovered(q, q_slot);
        }
        self.add_pending((q, q_slot), (old_r, old_slot), m, k, origin, join)
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
            let (v, v_slot) = (a.r, a.rslot);
            let kv = self.vertex_k(v);
            self.split(i + 1, v, v_slot, kv, None);
            self.stats.vertex_on_edge_splits += 1;
            return;
        }
        if Self::on_interior(b.r, a) {
            let (v, v_slot) = (b.r, b.rslot);
            let kv = self.vertex_k(v);
            self.split(i, v, v_slot, kv, None);
            self.stats.vertex_on_edge_splits += 1;
            return;
        }
        if a.is_vertical() && b.is_vertical() {
            return;
        }
        // Disjoint y-ranges cannot cross: every y-value below lies in its
        // edge's y-range (see `classify`).
        let (a_lo, a_hi) = (a.l.y.min(a.r.y), a.l.y.max(a.r.y));
        let (b_lo, b_hi) = (b.l.y.min(b.r.y), b.l.y.max(b.r.y));
        if a_hi < b_lo || b_hi < a_lo {
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
        if !split_a && !split_b {
            return;
        }
        // The counting slot of q: an end point's when q is one, else new.
        let q_slot = if q == a.r {
            a.rslot
        } else if q == b.r {
            b.rslot
        } else {
            self.ends.new_slot()
        };
        // One look-up for the vertex's adjustment count: the new edges get
        // `max(k + 1, k_q)` (section 8.4), the vertex the larger of those.
        let info = self.points.k_mut(q);
        let k_q = *info;
        let mut k_new = k_q;
        if split_a {
            k_new = k_new.max(a.k + 1);
        }
        if split_b {
            k_new = k_new.max(b.k + 1);
        }
        *info = k_new;
        // Both right parts start at q with its counting slot: one heap
        // entry carries them.
        let mut join = None;
        if split_a {
            join = self.split(i, q, q_slot, k_q, None).filter(|_| self.join);
        }
        if split_b {
            self.split(i + 1, q, q_slot, k_q, join);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use test_support::strategies::{float_coord, garbage_coord, grid_coord};
    use topology::PolygonSet2;

    /// The cell structure (with the rotations) of the rings, by the sweep
    /// with or without joined crossings, as text (every `f64` in its
    /// shortest round-trip form, so equal text is equal bits); `None` when
    /// the input is not valid (the public entry points reject it first).
    fn cells_text(rings: &[Vec<[f64; 2]>], join: bool) -> Option<String> {
        let set = valid_set(rings)?;
        let cells = run_on(&set, Output::All, join);
        if let Ok(c) = &cells {
            assert!(c.check_cells().is_ok(), "{:?}", c.check_cells());
        }
        Some(format!("{cells:?}"))
    }

    /// The rings as a polygon set, `None` when it is not valid input.
    fn valid_set(rings: &[Vec<[f64; 2]>]) -> Option<PolygonSet2> {
        let mut set = PolygonSet2::new();
        for r in rings {
            set.add_loop(r);
        }
        set.validate_coordinates().ok()?;
        set.check_topology().ok()?;
        Some(set)
    }

    /// The sweep on a valid set, keeping what `output` says.
    fn run_on(
        set: &PolygonSet2,
        output: Output<'_, i32>,
        join: bool,
    ) -> Result<CellStructure<i32>, SimplifyError> {
        let v = set.vertices();
        let input = set
            .edges()
            .iter()
            .enumerate()
            .filter(|(_, e)| e.mult != 0)
            .map(|(i, e)| InputEdge {
                a: v[e.start as usize],
                b: v[e.end as usize],
                mult: e.mult,
                origin: i as u32,
            });
        let max_abs = set.max_abs_coordinate();
        run_with(input, set.edge_count(), 1, max_abs, output, join)
    }

    /// For every fill rule, the structure the sweep keeps for a
    /// simplification ([`Output::Boundary`]) is the complete structure
    /// restricted to the edges the rule selects: those edges in the same
    /// order, keyed as [`CellStructure::selected`] keys them, on the
    /// vertices they use, numbered in the complete structure's order (so
    /// that the shape is assembled exactly as from the complete
    /// structure), with the same `k_max` and counters. Returns whether the
    /// rings were valid input.
    fn boundary_is_the_complete_structure_restricted(rings: &[Vec<[f64; 2]>]) -> bool {
        use crate::FillRule;
        let Some(set) = valid_set(rings) else {
            return false;
        };
        let all = run_on(&set, Output::All, true);
        for rule in [
            FillRule::Positive,
            FillRule::NonZero,
            FillRule::EvenOdd,
            FillRule::Negative,
            FillRule::AtLeast2,
        ] {
            let keep = |w: &i32| rule.contains(*w);
            let kept = run_on(&set, Output::Boundary(&keep), true);
            let (all, kept) = match (&all, kept) {
                (Ok(a), Ok(k)) => (a, k),
                (a, k) => {
                    assert_eq!(format!("{a:?}"), format!("{k:?}"));
                    continue;
                }
            };
            let edges: Vec<&CellEdge<i32>> = all
                .edges()
                .iter()
                .filter(|e| e.start != e.end && keep(&e.left) != keep(&e.right))
                .collect();
            let mut rank = vec![NO_ID; all.vertices().len()];
            for e in &edges {
                rank[e.start as usize] = 0;
                rank[e.end as usize] = 0;
            }
            let mut vertices = Vec::new();
            for (i, r) in rank.iter_mut().enumerate() {
                if *r == 0 {
                    *r = vertices.len() as u32;
                    vertices.push(all.vertices()[i]);
                }
            }
            // Keyed as `CellStructure::selected` keys them.
            let keyed: Keyed = edges
                .into_iter()
                .map(|e| {
                    let (a, b) = if keep(&e.left) {
                        (e.start, e.end)
                    } else {
                        (e.end, e.start)
                    };
                    let (pa, pb) = (all.vertices()[a as usize], all.vertices()[b as usize]);
                    let (a, b) = (rank[a as usize], rank[b as usize]);
                    if Pt::new(pa) < Pt::new(pb) {
                        (a, b, 1)
                    } else {
                        (b, a, -1)
                    }
                })
                .collect();
            let bits = |v: &[[f64; 2]]| -> Vec<[u64; 2]> {
                v.iter().map(|p| [p[0].to_bits(), p[1].to_bits()]).collect()
            };
            assert_eq!(bits(kept.vertices()), bits(&vertices), "{rule:?}");
            assert!(kept.edges().is_empty());
            assert_eq!(kept.boundary(), Some(&keyed), "{rule:?}");
            assert_eq!(kept.k_max(), all.k_max());
            assert_eq!(kept.stats(), all.stats());
            assert_eq!(
                format!("{:?}", kept.shape_with(keep)),
                format!("{:?}", all.shape_with(keep))
            );
        }
        true
    }

    /// One to three rings of 3 to `max_extra + 2` points: small integers
    /// (`case % 3 == 0`, exact ties), unit-scale values on a 1e-6 grid, or
    /// mixed magnitudes around 1e9.
    fn seeded_rings(
        g: &mut test_support::rng::Xorshift64,
        case: usize,
        max_extra: u64,
    ) -> Vec<Vec<[f64; 2]>> {
        let n_rings = 1 + g.below(3) as usize;
        (0..n_rings)
            .map(|_| {
                let n = 3 + g.below(max_extra) as usize;
                (0..n)
                    .map(|_| match case % 3 {
                        0 => [g.below(7) as f64 - 3.0, g.below(7) as f64 - 3.0],
                        1 => [
                            g.below(1 << 20) as f64 * 1e-6,
                            g.below(1 << 20) as f64 * 1e-6,
                        ],
                        _ => [
                            (g.below(1000) as f64).sqrt() * 1e9,
                            (g.below(1000) as f64).ln_1p() * 1e9,
                        ],
                    })
                    .collect()
            })
            .collect()
    }

    /// The same comparison on seeded cases, checking that they do
    /// exercise the joined entries: most are valid and cross.
    #[test]
    fn joined_crossings_decide_alike_on_seeded_cases() {
        let mut g = test_support::rng::Xorshift64::new(0x5EED_C0DE_1234_5678);
        let (mut valid, mut crossing) = (0, 0);
        for case in 0..400 {
            let rings = seeded_rings(&mut g, case, 20);
            let joined = cells_text(&rings, true);
            assert_eq!(joined, cells_text(&rings, false), "rings {rings:?}");
            if let Some(t) = joined {
                valid += 1;
                crossing += usize::from(!t.contains("intersections: 0,"));
            }
        }
        assert!(
            valid > 300 && crossing > 200,
            "{valid} valid, {crossing} crossing"
        );
    }

    /// The restriction on seeded cases of the three kinds of
    /// [`joined_crossings_decide_alike_on_seeded_cases`], with many
    /// crossings.
    #[test]
    fn boundary_output_is_the_restriction_on_seeded_cases() {
        let mut g = test_support::rng::Xorshift64::new(0xB0DA_55E1_7E57_0001);
        let mut valid = 0;
        for case in 0..150 {
            let rings = seeded_rings(&mut g, case, 40);
            valid += usize::from(boundary_is_the_complete_structure_restricted(&rings));
        }
        assert!(valid > 100, "{valid} valid");
    }

    fn rings(coord: BoxedStrategy<f64>) -> impl Strategy<Value = Vec<Vec<[f64; 2]>>> {
        prop::collection::vec(prop::collection::vec([coord.clone(), coord], 3..24), 1..4)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(300)))]

        /// Joining the two right parts of a crossing in one heap entry
        /// changes no decision: the cell structure, its rotations and the
        /// counters are those of the sweep with one entry per edge, on
        /// grid (degenerate: shared points, overlaps, vertices on edges),
        /// random and garbage coordinates.
        #[test]
        fn joined_crossings_decide_alike_on_grids(r in rings(grid_coord(3))) {
            prop_assert_eq!(cells_text(&r, true), cells_text(&r, false));
        }

        #[test]
        fn joined_crossings_decide_alike_on_floats(r in rings(float_coord())) {
            prop_assert_eq!(cells_text(&r, true), cells_text(&r, false));
        }

        #[test]
        fn joined_crossings_decide_alike_on_garbage(r in rings(garbage_coord())) {
            prop_assert_eq!(cells_text(&r, true), cells_text(&r, false));
        }

        /// [`boundary_is_the_complete_structure_restricted`] on grid
        /// (degenerate), random and garbage coordinates.
        #[test]
        fn boundary_output_is_the_restriction_on_grids(r in rings(grid_coord(3))) {
            boundary_is_the_complete_structure_restricted(&r);
        }

        #[test]
        fn boundary_output_is_the_restriction_on_floats(r in rings(float_coord())) {
            boundary_is_the_complete_structure_restricted(&r);
        }

        #[test]
        fn boundary_output_is_the_restriction_on_garbage(r in rings(garbage_coord())) {
            boundary_is_the_complete_structure_restricted(&r);
        }
    }
}
