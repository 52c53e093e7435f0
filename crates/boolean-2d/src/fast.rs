//! The fast evaluation of level 2 (Table 4.1): a sweep-line broad phase
//! before any `X11`, `X11` in parallel on the surviving pairs, and the
//! winding numbers `X02`/`X20` by one ray cast per connected component,
//! propagated along edges by the closure identity of Theorem 2.
//!
//! The result is the same [`LevelData`] as the brute force of
//! `reference.rs`, integer for integer and point for point: a pair is skipped
//! only when its `X` is provably 0, a sum over edges is only regrouped (never
//! approximated), and the propagation identity holds exactly for integers.
//!
//! Both sweeps first run with plain active lists, which are fastest on
//! well-spread input, and fall back to worst-case structures when the lists
//! do more than a constant times `n + output` work: an [`IntervalSet`] over
//! y for the broad phase, and for the ray casts a Fenwick tree over x plus
//! the same interval set. Either way the cost is `O((n + c) log n)` for `c`
//! overlapping box pairs.

use crate::error::BooleanError;
use crate::interval_set::IntervalSet;
use crate::level_data::LevelData;
use crate::timing::ms;
use rayon::prelude::*;
use robust_arith::total_order_key;
use shadow_1d::{s01, s10};
use shadow_2d::x11;
use std::time::Instant;
use topology::{Edge2, PolygonSet2};

/// Pair counts above which `X11` runs on the rayon pool; below it the
/// thread hand-off costs more than the work. The output is the same either
/// way (hits are sorted by edge indices afterwards).
const PARALLEL_PAIRS: usize = 2048;

/// Edge counts (both operands) above which the independent parts of level
/// 2 run side by side on the rayon pool: the two operands' edge boxes,
/// then the broad phase and `X11` beside the propagation orders and ray
/// casts (themselves one operand beside the other). The output is the same
/// either way.
const PARALLEL_EDGES: usize = 4096;

/// The plain active-list sweeps give up (and the worst-case structures take
/// over) once they have examined more than `LIST_WORK_FACTOR * (m + r) +
/// LIST_WORK_SLACK` list entries, where `m` counts the boxes entered (and,
/// for the ray casts, the casts answered) so far and `r` the pairs
/// reported. So a completed list sweep costs `O(n + c)`, and an abandoned
/// one no more than that (plus one scan, at most `n`) before the fallback
/// starts. The Table 7.4 n-gons examine about 1.5 entries per box or pair.
const LIST_WORK_FACTOR: usize = 8;

/// See [`LIST_WORK_FACTOR`].
const LIST_WORK_SLACK: usize = 1024;

/// The work limit of a list sweep: `(factor, slack)` as in
/// [`LIST_WORK_FACTOR`].
type Budget = (usize, usize);

/// The budget of production runs.
const LIST_BUDGET: Budget = (LIST_WORK_FACTOR, LIST_WORK_SLACK);

/// The running check of a [`Budget`]: `limit` is the budget at some
/// earlier progress, never more than the current one, so work within it is
/// within budget; only work beyond it recomputes the limit (`O(log n)`
/// times when the work stays a constant factor under budget).
struct BudgetCheck {
    budget: Budget,
    limit: usize,
}

impl BudgetCheck {
    fn new(budget: Budget) -> Self {
        BudgetCheck {
            budget,
            limit: budget.1,
        }
    }

    /// Whether `work` exceeds the budget for `progress` items handled plus
    /// outputs reported.
    #[inline]
    fn exceeded(&mut self, work: usize, progress: usize) -> bool {
        if work <= self.limit {
            return false;
        }
        self.limit = self
            .budget
            .0
            .saturating_mul(progress)
            .saturating_add(self.budget.1);
        work > self.limit
    }
}

/// One `X11` hit as [`LevelData::x11`] stores it: edge of A, edge of B,
/// value, intersection point.
type Hit11 = (u32, u32, i32, [f64; 2]);

/// Durations of the level-2 phases, in milliseconds.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Level2Times {
    pub broad_phase: f64,
    pub intersections: f64,
    pub winding: f64,
}

/// The closed box of one edge with non-zero multiplicity, its y range
/// widened by the broad-phase margin.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EdgeBox {
    pub(crate) x0: f64,
    pub(crate) x1: f64,
    pub(crate) y0: f64,
    pub(crate) y1: f64,
    pub(crate) index: u32,
}

/// Boxes of every edge with non-zero multiplicity, sorted by `x0`.
///
/// The y range is widened by `margin` on both sides. x is never widened:
/// `X01` and `X10` compare x coordinates exactly (`S00`, eq. 4.1), so an
/// edge whose closed x range misses a vertex's x has `X01 = X10 = 0` there.
pub(crate) fn edge_boxes(set: &PolygonSet2, margin: f64) -> Vec<EdgeBox> {
    let edges = set.edges();
    // Sort `(x0 by f64::total_cmp, edge index)` as integer keys (the same
    // order, cheaper to compare and move than whole boxes).
    let mut order: Vec<(u64, u32)> = edges
        .iter()
        .enumerate()
        .filter(|(_, e)| e.mult != 0)
        .map(|(i, e)| {
            let (p, q) = set.edge_points(e);
            (total_order_key(p[0].min(q[0])), i as u32)
        })
        .collect();
    // The keys are distinct (the index breaks ties), so any sort gives this
    // order; the stable one merges the few monotone runs of a polygon's
    // x-coordinates instead of partitioning.
    order.sort();
    order
        .into_iter()
        .map(|(_, i)| {
            let (p, q) = set.edge_points(&edges[i as usize]);
            EdgeBox {
                x0: p[0].min(q[0]),
                x1: p[0].max(q[0]),
                y0: p[1].min(q[1]) - margin,
                y1: p[1].max(q[1]) + margin,
                index: i,
            }
        })
        .collect()
}

/// Every `(edge of A, edge of B)` pair whose boxes overlap (closed ranges),
/// each exactly once, in no particular order.
///
/// Sort-and-sweep on x: boxes enter in order of `x0`; a box entering is
/// tested against the other operand's active boxes (those with
/// `x1 >= x0`, ties kept: the symbolic perturbation of eq. 4.1 decides
/// touching ranges). Each overlapping pair is found exactly once, by
/// whichever of its two boxes enters second. The active boxes are plain
/// lists ([`pairs_by_lists`]) unless those exceed their work budget, then
/// buckets over y ([`pairs_by_buckets`]) unless those do, then interval
/// sets over y ([`pairs_by_trees`]); all three report the same set.
///
/// Why a pair outside this set has `X11 = 0`: if the closed x ranges are
/// disjoint, every `X01`/`X10` of the pair is 0 (Table 4.1), hence every
/// level-1 shadow. If one edge lies wholly below the other with the `8 u L`
/// margin to spare, every computed y of the lower edge (within `4 u L` of
/// the true segment, section 8.2) is below every computed y of the upper
/// one, so each `S01`/`S10` equals its `X` or is 0 for the whole pair, and
/// the X terms of `X11` cancel by the closure of the two edges' end points
/// (the argument of Theorem 1, case 2).
pub(crate) fn overlapping_pairs(a: &[EdgeBox], b: &[EdgeBox]) -> Vec<(u32, u32)> {
    pairs_by_lists(a, b, LIST_BUDGET)
        .or_else(|| pairs_by_buckets(a, b, LIST_BUDGET))
        .unwrap_or_else(|| pairs_by_trees(a, b))
}

/// The boxes of `a` and `b` (each sorted by `x0`) merged by `x0`, A's
/// first on ties: the order in which every sweep of [`overlapping_pairs`]
/// enters them, as `(from A, position in its operand's slice, box)`.
fn by_x0<'s>(
    a: &'s [EdgeBox],
    b: &'s [EdgeBox],
) -> impl Iterator<Item = (bool, usize, EdgeBox)> + 's {
    let (mut i, mut j) = (0, 0);
    std::iter::from_fn(move || {
        if j == b.len() || (i < a.len() && a[i].x0 <= b[j].x0) {
            i += 1;
            a.get(i - 1).map(|bx| (true, i - 1, *bx))
        } else {
            j += 1;
            b.get(j - 1).map(|bx| (false, j - 1, *bx))
        }
    })
}

/// A pair found by a sweep, as `(edge of A, edge of B)`: `entering` is
/// A's when `from_a`.
fn oriented(from_a: bool, entering: u32, other: u32) -> (u32, u32) {
    if from_a {
        (entering, other)
    } else {
        (other, entering)
    }
}

/// Scans one list of active boxes for the `entering` box (A's when
/// `from_a`): drops the boxes that ended to its left (`x1 < x0`: no later
/// box can overlap them either, boxes enter by ascending `x0`) and
/// reports each other box that overlaps it in y and that `here` accepts.
#[inline]
fn scan(
    list: &mut Vec<EdgeBox>,
    entering: EdgeBox,
    from_a: bool,
    pairs: &mut Vec<(u32, u32)>,
    here: impl Fn(&EdgeBox) -> bool,
) {
    let mut m = 0;
    while m < list.len() {
        let o = list[m];
        if o.x1 < entering.x0 {
            list.swap_remove(m);
            continue;
        }
        if o.y0 <= entering.y1 && entering.y0 <= o.y1 && here(&o) {
            pairs.push(oriented(from_a, entering.index, o.index));
        }
        m += 1;
    }
}

/// Boxes per y-bucket of [`pairs_by_buckets`] (about), and the most
/// buckets.
const BUCKET_BOXES: usize = 32;
const MAX_BUCKETS: usize = 1 << 14;

/// The sweep of [`overlapping_pairs`] with each operand's active boxes in
/// buckets over y: `count` equal slices of the boxes' y range, a box in
/// every bucket its y range meets (the bucket of a y is a monotone
/// rounding of it, so two boxes whose y ranges meet have bucket ranges
/// that meet). An entering box scans only the other operand's buckets in
/// its own range, dropping the boxes that ended to its left, and reports
/// a pair in the first bucket the two share, so once. `O(n + c)` on real
/// maps, where a vertical line crosses hundreds of edges (the plain lists
/// then scan them all for every box and give up: New York's boroughs,
/// 75,000 edges each, 5,000 pairs) but few share a slice of y with one
/// edge; `None` as soon as the scans and insertions exceed `budget` (many
/// long edges spanning many buckets), then the interval sets take over.
fn pairs_by_buckets(a: &[EdgeBox], b: &[EdgeBox], budget: Budget) -> Option<Vec<(u32, u32)>> {
    let (lo, hi) = a
        .iter()
        .chain(b)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), bx| {
            (lo.min(bx.y0), hi.max(bx.y1))
        });
    let wanted = ((a.len() + b.len()) / BUCKET_BOXES).clamp(1, MAX_BUCKETS);
    let scale = wanted as f64 / (hi - lo);
    let (count, scale) = if scale.is_finite() && scale > 0.0 {
        (wanted, scale)
    } else {
        (1, 0.0)
    };
    // `y - lo` and the product round monotonically, the cast floors (and
    // saturates), so the bucket never decreases as y grows.
    let bucket = |y: f64| (((y - lo) * scale) as usize).min(count - 1);
    let mut active_a: Vec<Vec<EdgeBox>> = vec![Vec::new(); count];
    let mut active_b: Vec<Vec<EdgeBox>> = vec![Vec::new(); count];
    let mut pairs = Vec::new();
    let mut work = 0usize;
    let mut check = BudgetCheck::new(budget);
    for (entered, (from_a, _, entering)) in by_x0(a, b).enumerate() {
        let (others, own) = if from_a {
            (&mut active_b, &mut active_a)
        } else {
            (&mut active_a, &mut active_b)
        };
        let (first, last) = (bucket(entering.y0), bucket(entering.y1));
        for k in first..=last {
            work += others[k].len() + 1;
            scan(&mut others[k], entering, from_a, &mut pairs, |o| {
                k == first.max(bucket(o.y0))
            });
            own[k].push(entering);
        }
        if check.exceeded(work, entered + 1 + pairs.len()) {
            return None;
        }
    }
    Some(pairs)
}

/// The sweep of [`overlapping_pairs`] with each operand's active boxes in a
/// list: an entering box scans the whole list of the other operand,
/// dropping the boxes that ended to its left. `O(n + c)` on well-spread
/// input, but quadratic when many boxes share an x range without
/// overlapping in y (long horizontal edges stacked in y, many components
/// in one column); `None` as soon as the scans exceed `budget`.
fn pairs_by_lists(a: &[EdgeBox], b: &[EdgeBox], budget: Budget) -> Option<Vec<(u32, u32)>> {
    let mut pairs = Vec::new();
    let mut active_a: Vec<EdgeBox> = Vec::new();
    let mut active_b: Vec<EdgeBox> = Vec::new();
    let mut work = 0usize;
    let mut check = BudgetCheck::new(budget);
    for (entered, (from_a, _, entering)) in by_x0(a, b).enumerate() {
        let (others, own) = if from_a {
            (&mut active_b, &mut active_a)
        } else {
            (&mut active_a, &mut active_b)
        };
        work += others.len();
        scan(others, entering, from_a, &mut pairs, |_| true);
        own.push(entering);
        if check.exceeded(work, entered + 1 + pairs.len()) {
            return None;
        }
    }
    Some(pairs)
}

/// The sweep of [`overlapping_pairs`] with each operand's active boxes in
/// an [`IntervalSet`] over their (widened) y ranges: an entering box visits
/// only the other operand's members whose y range meets its own, in
/// `O((1 + r) log n)` for `r` visited. A visited member that ended to the
/// left of the entering box (`x1 < x0`) can overlap no later box either
/// (boxes enter by ascending `x0`), so it is removed there and then; every
/// other visited member overlaps the entering box in both ranges and is
/// reported. Each box is inserted and removed at most once, so the sweep
/// costs `O((n + c) log n)` in the worst case, `c` the number of
/// overlapping pairs.
fn pairs_by_trees(a: &[EdgeBox], b: &[EdgeBox]) -> Vec<(u32, u32)> {
    let y_ranges =
        |boxes: &[EdgeBox]| -> Vec<(f64, f64)> { boxes.iter().map(|bx| (bx.y0, bx.y1)).collect() };
    let mut set_a = IntervalSet::new(&y_ranges(a));
    let mut set_b = IntervalSet::new(&y_ranges(b));
    let mut pairs = Vec::new();
    let mut found = Vec::new();
    for (from_a, own_item, entering) in by_x0(a, b) {
        let (others, other_boxes, own) = if from_a {
            (&mut set_b, b, &mut set_a)
        } else {
            (&mut set_a, a, &mut set_b)
        };
        others.overlapping(entering.y0, entering.y1, &mut found);
        for &k in &found {
            let o = other_boxes[k as usize];
            if o.x1 < entering.x0 {
                others.remove(k);
            } else {
                pairs.push(oriented(from_a, entering.index, o.index));
            }
        }
        own.insert(own_item as u32);
    }
    pairs
}

/// The candidate pairs sorted by edge of A, then edge of B (each pair
/// occurs once): a counting sort by edge of A, `a_edges` the number of A's
/// edges, then an insertion sort of each edge's few partners. `O(n + c)`,
/// against `O(c log c)` for a comparison sort of the sweep's x order.
fn sort_pairs(pairs: &[(u32, u32)], a_edges: usize) -> Vec<(u32, u32)> {
    let mut start = vec![0u32; a_edges + 1];
    for &(ia, _) in pairs {
        start[ia as usize + 1] += 1;
    }
    for i in 0..a_edges {
        start[i + 1] += start[i];
    }
    let mut sorted = vec![(0u32, 0u32); pairs.len()];
    let mut fill = start.clone();
    for &p in pairs {
        let slot = &mut fill[p.0 as usize];
        sorted[*slot as usize] = p;
        *slot += 1;
    }
    for w in start.windows(2) {
        let bucket = &mut sorted[w[0] as usize..w[1] as usize];
        for i in 1..bucket.len() {
            let mut j = i;
            while j > 0 && bucket[j - 1].1 > bucket[j].1 {
                bucket.swap(j - 1, j);
                j -= 1;
            }
        }
    }
    sorted
}

/// The fewest candidate pairs per parallel task of [`intersections`].
const PAIRS_PER_TASK: usize = 4096;

/// `X11` on every candidate pair, given sorted by edge of A, then edge of
/// B; the non-zero ones in that order (the order [`LevelData::x11`]
/// documents). Long lists run in parallel by consecutive blocks, which
/// keeps the order without a sort of the hits.
fn intersections(
    a: &PolygonSet2,
    b: &PolygonSet2,
    pairs: &[(u32, u32)],
) -> Result<Vec<Hit11>, BooleanError> {
    // Each hit is written where it goes, field by field, rather than
    // returned as an `Option<Hit11>`: its padded layout went through the
    // stack with overlapping copies, a store-forwarding stall per pair.
    let (a_points, a_edges) = (a.vertices(), a.edges());
    let (b_points, b_edges) = (b.vertices(), b.edges());
    let eval = |ia: u32, ib: u32, out: &mut Hit11| -> Result<bool, BooleanError> {
        let ea = &a_edges[ia as usize];
        let eb = &b_edges[ib as usize];
        let (as_, ae) = (a_points[ea.start as usize], a_points[ea.end as usize]);
        let (bs, be) = (b_points[eb.start as usize], b_points[eb.end as usize]);
        match x11(&as_, &ae, &bs, &be) {
            Ok(Some(h)) => {
                out.0 = ia;
                out.1 = ib;
                out.2 = h.value;
                out.3[0] = h.a[0];
                out.3[1] = h.a[1];
                Ok(true)
            }
            Ok(None) => Ok(false),
            Err(e) => Err(BooleanError::Internal(format!("edges {ia}, {ib}: {e}"))),
        }
    };
    let threads = rayon::current_num_threads();
    if pairs.len() < PARALLEL_PAIRS || threads < 2 {
        // About two of three candidate pairs cross on the n-gons of Table
        // 7.4; the vector grows where more do.
        let mut hits = Vec::with_capacity(pairs.len() - pairs.len() / 4);
        let mut h: Hit11 = (0, 0, 0, [0.0; 2]);
        for &(ia, ib) in pairs {
            if eval(ia, ib, &mut h)? {
                hits.push(h);
            }
        }
        return Ok(hits);
    }
    // A few blocks per thread, so that a busy thread's share is taken over.
    // Each block writes its hits to the start of its own region of one
    // zeroed vector (fresh zeroed memory is mapped on first write, so the
    // regions' unused tails cost nothing), then the regions are closed up
    // in order: no second vector and no copy into one.
    let per_task = pairs.len().div_ceil(4 * threads).max(PAIRS_PER_TASK);
    let mut hits: Vec<Hit11> = vec![(0, 0, 0, [0.0; 2]); pairs.len()];
    let found: Vec<usize> = hits
        .par_chunks_mut(per_task)
        .zip(pairs.par_chunks(per_task))
        .map(|(region, pairs)| -> Result<usize, BooleanError> {
            let mut n = 0;
            for &(ia, ib) in pairs {
                if eval(ia, ib, &mut region[n])? {
                    n += 1;
                }
            }
            Ok(n)
        })
        .collect::<Result<_, _>>()?;
    let mut len = 0;
    for (k, &n) in found.iter().enumerate() {
        let start = k * per_task;
        hits.copy_within(start..start + n, len);
        len += n;
    }
    hits.truncate(len);
    Ok(hits)
}

/// How a vertex's winding number is obtained: cast, or from a neighbour
/// across an edge.
#[derive(Clone, Copy)]
enum Source {
    /// The first vertex of a connected component: one ray cast.
    Cast,
    /// `value(v) = value(from) + delta`, with `delta` read from edge
    /// `edge`, traversed forwards (`from` is its start) or backwards.
    Across { from: u32, edge: u32, forward: bool },
}

/// A breadth-first order of every vertex of `set` over its edges of
/// non-zero multiplicity, each with its [`Source`].
fn propagation_order(set: &PolygonSet2) -> Vec<(u32, Source)> {
    let n = set.vertex_count();
    // Adjacency in compressed rows: (neighbour, edge, forward).
    let mut degree = vec![0u32; n + 1];
    for e in set.edges().iter().filter(|e| e.mult != 0) {
        degree[e.start as usize] += 1;
        degree[e.end as usize] += 1;
    }
    let mut offset = vec![0u32; n + 1];
    for v in 0..n {
        offset[v + 1] = offset[v] + degree[v];
    }
    let mut fill = offset.clone();
    let mut adj = vec![(0u32, 0u32, false); offset[n] as usize];
    for (i, e) in set.edges().iter().enumerate() {
        if e.mult == 0 {
            continue;
        }
        let (s, t) = (e.start as usize, e.end as usize);
        adj[fill[s] as usize] = (e.end, i as u32, true);
        fill[s] += 1;
        adj[fill[t] as usize] = (e.start, i as u32, false);
        fill[t] += 1;
    }
    let mut seen = vec![false; n];
    let mut order = Vec::with_capacity(n);
    for root in 0..n {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let head = order.len();
        order.push((root as u32, Source::Cast));
        let mut k = head;
        while k < order.len() {
            let v = order[k].0 as usize;
            for &(w, edge, forward) in &adj[offset[v] as usize..offset[v + 1] as usize] {
                if !seen[w as usize] {
                    seen[w as usize] = true;
                    order.push((
                        w,
                        Source::Across {
                            from: v as u32,
                            edge,
                            forward,
                        },
                    ));
                }
            }
            k += 1;
        }
    }
    order
}

/// Which winding number a ray cast computes, hence which edges can
/// contribute (Table 4.1, eq. 4.1: ties go to B above A).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ray {
    /// `X02(v, B) = -sum m S01(v, e_B)`: `S01` is `X01` when the edge is
    /// above the vertex of A and 0 when it is below.
    Up,
    /// `X20(A, w) = sum m S10(e_A, w)`: `S10` is `X10` when the edge is
    /// below the vertex of B and 0 when it is above.
    Down,
}

impl Ray {
    /// The exact term of one edge of non-zero multiplicity for a query
    /// vertex `v`: `-m S01(v, e)` or `m S10(e, v)`.
    fn term(self, v: &[f64; 2], e: &Edge2, (s, t): ([f64; 2], [f64; 2])) -> i64 {
        i64::from(match self {
            Ray::Up => -(e.mult * s01(v, &s, &t)),
            Ray::Down => e.mult * s10(&s, &t, v),
        })
    }
}

/// Casts one ray per query vertex of `own` through the edges of `other`
/// (`boxes` are their boxes, sorted by `x0`): the sum of [`Ray::term`]
/// over every edge of non-zero multiplicity, as the brute force sums it
/// (modulo `2^32`, like its wrapping `i32` sum). Plain active lists first
/// ([`cast_by_lists`]), the worst-case sweeps ([`cast_by_sweeps`]) when
/// the lists exceed their budget; both return the same integers.
fn cast_rays(
    queries: &[u32],
    own: &PolygonSet2,
    boxes: &[EdgeBox],
    other: &PolygonSet2,
    ray: Ray,
) -> Vec<i32> {
    cast_by_lists(queries, own, boxes, other, ray, LIST_BUDGET)
        .unwrap_or_else(|| cast_by_sweeps(queries, own, boxes, other, ray))
}

/// The query vertices' points and their indices sorted by x (ties by
/// index).
fn queries_by_x(queries: &[u32], own: &PolygonSet2) -> (Vec<[f64; 2]>, Vec<u32>) {
    let points: Vec<[f64; 2]> = queries.iter().map(|&v| own.vertex(v)).collect();
    let mut by_x: Vec<(f64, u32)> = points
        .iter()
        .enumerate()
        .map(|(k, p)| (p[0], k as u32))
        .collect();
    by_x.sort_unstable_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)));
    (points, by_x.into_iter().map(|p| p.1).collect())
}

/// [`cast_rays`] by a sweep over the queries in x order that keeps the
/// edges whose closed x range holds the current x in a list (all other
/// edges have `X01 = X10 = 0` at the query, so contribute nothing), and
/// sums the exact term over the whole list. Quadratic when many queries
/// share an x range with many edges (a column of components); `None` as
/// soon as the list scans exceed `budget`.
fn cast_by_lists(
    queries: &[u32],
    own: &PolygonSet2,
    boxes: &[EdgeBox],
    other: &PolygonSet2,
    ray: Ray,
    budget: Budget,
) -> Option<Vec<i32>> {
    let mut result = vec![0i32; queries.len()];
    let mut active: Vec<EdgeBox> = Vec::new();
    let mut next = 0;
    let mut work = 0usize;
    let mut check = BudgetCheck::new(budget);
    let (points, by_x) = queries_by_x(queries, own);
    for (handled, q) in by_x.into_iter().enumerate() {
        let v = points[q as usize];
        while next < boxes.len() && boxes[next].x0 <= v[0] {
            // A box that ended left of this query ends left of every later
            // one (the queries come by ascending x): never kept.
            if boxes[next].x1 >= v[0] {
                active.push(boxes[next]);
            }
            next += 1;
        }
        work += active.len();
        active.retain(|b| b.x1 >= v[0]);
        let mut sum = 0i64;
        for b in &active {
            let e = &other.edges()[b.index as usize];
            sum += ray.term(&v, e, other.edge_points(e));
        }
        // Truncation keeps the low 32 bits: the wrapping `i32` sum.
        result[q as usize] = sum as i32;
        if check.exceeded(work, next + handled + 1) {
            return None;
        }
    }
    Some(result)
}

/// A Fenwick tree over positions `0..n` holding a difference array:
/// `add_from(i, w)` adds `w` to every position `>= i`, `at(i)` reads
/// position `i`; both `O(log n)`.
struct Fenwick {
    tree: Vec<i64>,
}

impl Fenwick {
    fn new(n: usize) -> Self {
        Fenwick {
            tree: vec![0; n + 1],
        }
    }

    fn add_from(&mut self, i: usize, w: i64) {
        let mut k = i + 1;
        while k < self.tree.len() {
            self.tree[k] = self.tree[k].wrapping_add(w);
            k += k & k.wrapping_neg();
        }
    }

    fn at(&self, i: usize) -> i64 {
        let mut k = i + 1;
        let mut sum = 0i64;
        while k > 0 {
            sum = sum.wrapping_add(self.tree[k]);
            k -= k & k.wrapping_neg();
        }
        sum
    }
}

/// [`cast_rays`] in `O((n + q + c + s) log n)` for `q` queries, whatever
/// the input (`s` counts the pairs of an isolated query vertex and a box
/// holding it), by splitting the sum over the edges of `other` by where the edge
/// lies relative to the query vertex `v`, in its widened y range
/// (`[y0, y1]` of [`EdgeBox`], the true range plus the `8 u L` margin on
/// each side):
///
/// * **far side** (`y0 > v.y` for [`Ray::Up`], `y1 < v.y` for
///   [`Ray::Down`]): every computed y of the edge (within `4 u L` of the
///   true segment, section 8.2) is strictly above (below) `v.y`, so the
///   shadow equals its `X` (eq. 4.1) and the term is exactly
///   `-m X01(v, e) = -m [v.x <= t.x] + m [v.x <= s.x]` (Up) or
///   `m X10(e, v) = m [v.x >= s.x] - m [v.x >= t.x]` (Down), with
///   `S00(p, q) = [q.x >= p.x]` compared exactly (Table 4.1, `s`/`t` the
///   edge's start and end). That depends only on x: a sweep in y adds the
///   far edges, as they become far, to a [`Fenwick`] tree over the queries'
///   x ranks (each indicator is a prefix or suffix of the ranks), which is
///   read at each query;
/// * **near side** (`y0 <= v.y` and `y1 >= v.y`): the exact term, from
///   the edges reported by an x sweep with an [`IntervalSet`] over y (the
///   same lazy removal as [`pairs_by_trees`]);
/// * **other side**: the shadow is 0, nothing to add.
///
/// Integer sums are only regrouped, so the result is that of the brute
/// force. A near pair `(v, box)` with `v` on an edge of its own operand
/// means that edge's box overlaps `box`, and components have distinct
/// first vertices, so the near terms number at most `c` plus those of
/// isolated vertices.
fn cast_by_sweeps(
    queries: &[u32],
    own: &PolygonSet2,
    boxes: &[EdgeBox],
    other: &PolygonSet2,
    ray: Ray,
) -> Vec<i32> {
    let n = queries.len();
    let (points, by_x) = queries_by_x(queries, own);
    let xs: Vec<f64> = by_x.iter().map(|&k| points[k as usize][0]).collect();
    let mut rank = vec![0usize; n];
    for (r, &k) in by_x.iter().enumerate() {
        rank[k as usize] = r;
    }
    let mut sum = vec![0i64; n];

    // Far side. In the Fenwick tree over the queries' x ranks, an edge adds
    // `m` from rank `plus` on and `-m` from rank `minus` on. Up:
    // `plus = #{x <= t.x}` and `minus = #{x <= s.x}`, so rank `r` gets
    // `m [x_r > t.x] - m [x_r > s.x] = -m [x_r <= t.x] + m [x_r <= s.x]`,
    // which is `-m X01(v, e)`. Down: `plus = #{x < s.x}`,
    // `minus = #{x < t.x}`, so rank `r` gets
    // `m [x_r >= s.x] - m [x_r >= t.x] = m X10(e, v)`. (The counts are
    // prefixes of the ranks: the predicates are monotone along their total
    // order, the two zeros comparing equal.) An edge with `plus == minus`
    // (vertical, or spanning no query's x) adds nothing and is dropped.
    let count = |c: f64, inclusive: bool| {
        if inclusive {
            xs.partition_point(|&x| x <= c)
        } else {
            xs.partition_point(|&x| x < c)
        }
    };
    // `(key, plus, minus, m)`; the key is when the edge becomes far: Up,
    // for every query with `y < y0`; Down, for every query with `y > y1`.
    let mut far_edges: Vec<(f64, u32, u32, i64)> = boxes
        .iter()
        .filter_map(|b| {
            let e = &other.edges()[b.index as usize];
            let (s, t) = other.edge_points(e);
            let (plus, minus, key) = match ray {
                Ray::Up => (count(t[0], true), count(s[0], true), b.y0),
                Ray::Down => (count(s[0], false), count(t[0], false), b.y1),
            };
            (plus != minus).then_some((key, plus as u32, minus as u32, i64::from(e.mult)))
        })
        .collect();
    let mut by_y: Vec<(f64, u32)> = points
        .iter()
        .enumerate()
        .map(|(k, p)| (p[1], k as u32))
        .collect();
    by_y.sort_unstable_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)));
    far_edges.sort_unstable_by(|p, q| p.0.total_cmp(&q.0));
    if ray == Ray::Up {
        // Sweep downwards: queries by descending y, edges by descending y0.
        by_y.reverse();
        far_edges.reverse();
    }
    let mut fenwick = Fenwick::new(n);
    let mut next = 0;
    for &(vy, k) in &by_y {
        while let Some(&(key, plus, minus, m)) = far_edges.get(next) {
            let far = match ray {
                Ray::Up => key > vy,
                Ray::Down => key < vy,
            };
            if !far {
                break;
            }
            fenwick.add_from(plus as usize, m);
            fenwick.add_from(minus as usize, m.wrapping_neg());
            next += 1;
        }
        sum[k as usize] = fenwick.at(rank[k as usize]);
    }

    // Near side.
    let y_ranges: Vec<(f64, f64)> = boxes.iter().map(|b| (b.y0, b.y1)).collect();
    let mut set = IntervalSet::new(&y_ranges);
    let mut found = Vec::new();
    let mut next = 0;
    for &k in &by_x {
        let v = points[k as usize];
        while next < boxes.len() && boxes[next].x0 <= v[0] {
            set.insert(next as u32);
            next += 1;
        }
        set.overlapping(v[1], v[1], &mut found);
        for &i in &found {
            let b = boxes[i as usize];
            if b.x1 < v[0] {
                // Ended left of this query, so of every later one.
                set.remove(i);
            } else {
                let e = &other.edges()[b.index as usize];
                let t = ray.term(&v, e, other.edge_points(e));
                sum[k as usize] = sum[k as usize].wrapping_add(t);
            }
        }
    }
    // Truncation keeps the low 32 bits: the wrapping `i32` sum.
    sum.into_iter().map(|x| x as i32).collect()
}

/// Sum of `weight(other edge) * X11` over the hits of each edge of one
/// operand: `per_edge[e]` for the A side (`by_a`) or the B side.
fn crossing_sums(hits: &[Hit11], edge_count: usize, by_a: bool, weights: &[Edge2]) -> Vec<i32> {
    let mut sums = vec![0i32; edge_count];
    for &(ia, ib, x, _) in hits {
        let (own, other) = if by_a { (ia, ib) } else { (ib, ia) };
        sums[own as usize] += weights[other as usize].mult * x;
    }
    sums
}

/// Fills winding numbers in propagation order: casts first, then
/// `value(to) = value(from) + sign * delta[edge]` where the sign is `+1`
/// for a forward traversal.
fn propagate(order: &[(u32, Source)], cast: &[i32], delta: &[i32], n: usize) -> Vec<i32> {
    let mut value = vec![0i32; n];
    let mut k = 0;
    for &(v, source) in order {
        value[v as usize] = match source {
            Source::Cast => {
                k += 1;
                cast[k - 1]
            }
            Source::Across {
                from,
                edge,
                forward,
            } => {
                let d = delta[edge as usize];
                value[from as usize] + if forward { d } else { -d }
            }
        };
    }
    value
}

/// [`margin_for`] the coordinates of `a` and `b`.
#[cfg(test)]
fn margin(a: &PolygonSet2, b: &PolygonSet2) -> f64 {
    margin_for(a.max_abs_coordinate().max(b.max_abs_coordinate()))
}

/// The widening of every edge box's y range, on each side, for operands
/// whose largest coordinate magnitude is `max_abs`: twice the `y_at_x`
/// bound `4 u L` of section 8.2 (defence in depth: a wider margin only adds
/// candidate pairs and near terms). It also covers the rounding of
/// `y0 - margin` and `y1 + margin` themselves (at most `u L` each), so a
/// computed `y0`/`y1` still clears the true end points' range by more than
/// `4 u L`.
fn margin_for(max_abs: f64) -> f64 {
    2.0 * robust_arith::y_at_x_error_bound(max_abs)
}

/// Level 2 by the fast path.
///
/// Winding numbers: along an edge `e_A` of non-zero multiplicity, Theorem 2
/// for its composite edge (starts equal ends, eq. 4.14-4.16 with the counts
/// of eq. 4.7-4.8) is the identity
/// `X02(v_e, B) = X02(v_s, B) - sum_{e_B} m_B X11(e_A, e_B)`, and for an
/// edge `e_B` of B (eq. 4.9-4.10)
/// `X20(A, v_e) = X20(A, v_s) + sum_{e_A} m_A X11(e_A, e_B)`. One vertex
/// per connected component gets a ray cast (`X02 = -sum m S01`,
/// `X20 = sum m S10`, Table 4.1); the rest follow exactly.
pub(crate) fn level2_fast(
    a: &PolygonSet2,
    b: &PolygonSet2,
    max_abs: f64,
) -> Result<(LevelData, Level2Times), BooleanError> {
    let mut times = Level2Times::default();
    let parallel = a.edge_count() + b.edge_count() >= PARALLEL_EDGES;
    let clock = Instant::now();
    let margin = margin_for(max_abs);
    let (boxes_a, boxes_b) = join(parallel, || edge_boxes(a, margin), || edge_boxes(b, margin));
    let boxes_time = ms(clock);

    // The candidate pairs and their `X11`, beside the propagation orders
    // and the ray casts, which need neither.
    let crossings = || -> Result<_, BooleanError> {
        let clock = Instant::now();
        let pairs = sort_pairs(&overlapping_pairs(&boxes_a, &boxes_b), a.edge_count());
        let broad_phase = ms(clock);
        let clock = Instant::now();
        let hits = intersections(a, b, &pairs)?;
        Ok((hits, broad_phase, ms(clock)))
    };
    let windings = || {
        let clock = Instant::now();
        let casts = |order: &[(u32, Source)]| -> Vec<u32> {
            order
                .iter()
                .filter(|(_, s)| matches!(s, Source::Cast))
                .map(|&(v, _)| v)
                .collect()
        };
        let side_a = || {
            let order = propagation_order(a);
            let cast = cast_rays(&casts(&order), a, &boxes_b, b, Ray::Up);
            (order, cast)
        };
        let side_b = || {
            let order = propagation_order(b);
            let cast = cast_rays(&casts(&order), b, &boxes_a, a, Ray::Down);
            (order, cast)
        };
        let sides = join(parallel, side_a, side_b);
        (sides, ms(clock))
    };
    let (crossings, ((order_cast_a, order_cast_b), cast_time)) =
        join(parallel, crossings, windings);
    let (hits, broad_phase, x11_time) = crossings?;
    times.broad_phase = boxes_time + broad_phase;
    times.intersections = x11_time;

    let clock = Instant::now();
    let ((order_a, x02_cast), (order_b, x20_cast)) = (order_cast_a, order_cast_b);
    let delta_a: Vec<i32> = crossing_sums(&hits, a.edge_count(), true, b.edges())
        .into_iter()
        .map(|d| -d)
        .collect();
    let delta_b = crossing_sums(&hits, b.edge_count(), false, a.edges());
    let x02 = propagate(&order_a, &x02_cast, &delta_a, a.vertex_count());
    let x20 = propagate(&order_b, &x20_cast, &delta_b, b.vertex_count());
    times.winding = cast_time + ms(clock);

    Ok((
        LevelData {
            x02,
            x20,
            x11: hits,
            composite_counts: Vec::new(),
        },
        times,
    ))
}

/// `(f(), g())`, side by side on the rayon pool when `parallel`.
fn join<A: Send, B: Send>(
    parallel: bool,
    f: impl FnOnce() -> A + Send,
    g: impl FnOnce() -> B + Send,
) -> (A, B) {
    if parallel {
        rayon::join(f, g)
    } else {
        (f(), g())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::Xorshift64;

    fn boxes(v: &[(f64, f64, f64, f64)]) -> Vec<EdgeBox> {
        let mut b: Vec<EdgeBox> = v
            .iter()
            .enumerate()
            .map(|(i, &(x0, x1, y0, y1))| EdgeBox {
                x0,
                x1,
                y0,
                y1,
                index: i as u32,
            })
            .collect();
        b.sort_unstable_by(|p, q| p.x0.total_cmp(&q.x0));
        b
    }

    #[test]
    fn sweep_finds_exactly_the_overlapping_pairs() {
        let a = boxes(&[
            (0.0, 1.0, 0.0, 1.0),
            (1.0, 2.0, 0.0, 1.0),
            (5.0, 6.0, 0.0, 1.0),
            (0.0, 10.0, 3.0, 4.0),
        ]);
        let b = boxes(&[
            (1.0, 1.0, 0.5, 0.5), // touches A0 and A1 at x = 1
            (2.0, 5.0, 1.0, 3.0), // touches A1, A2 and A3 at corners
            (7.0, 8.0, 5.0, 6.0), // above everything
        ]);
        let mut got = overlapping_pairs(&a, &b);
        got.sort_unstable();
        let mut want = Vec::new();
        for p in &a {
            for q in &b {
                if p.x0 <= q.x1 && q.x0 <= p.x1 && p.y0 <= q.y1 && q.y0 <= p.y1 {
                    want.push((p.index, q.index));
                }
            }
        }
        want.sort_unstable();
        assert_eq!(got, want);
        assert_eq!(got, vec![(0, 0), (1, 0), (1, 1), (2, 1), (3, 1)]);
    }

    /// Every pair of `a` and `b` whose closed boxes overlap, sorted.
    fn brute_pairs(a: &[EdgeBox], b: &[EdgeBox]) -> Vec<(u32, u32)> {
        let mut want = Vec::new();
        for p in a {
            for q in b {
                if p.x0 <= q.x1 && q.x0 <= p.x1 && p.y0 <= q.y1 && q.y0 <= p.y1 {
                    want.push((p.index, q.index));
                }
            }
        }
        want.sort_unstable();
        want
    }

    fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
        v.sort_unstable();
        v
    }

    /// No budget: the list sweeps always complete.
    const UNLIMITED: Budget = (usize::MAX, usize::MAX);

    /// How [`random_set`] draws coordinates.
    #[derive(Clone, Copy)]
    enum Coords {
        /// A small integer grid: exact ties, both zeros, vertical and
        /// horizontal edges, vertices on edges.
        Grid,
        /// Dyadic values in the unit square.
        Unit,
        /// Any magnitude from 1e-300 to 1e300, zeros, small integers.
        Garbage,
    }

    /// A random edge set of up to 40 vertices and 60 edges with
    /// multiplicities in `-2..=2` (0 included).
    fn random_set(rng: &mut Xorshift64, coords: Coords) -> PolygonSet2 {
        let n = 1 + rng.below(40) as usize;
        let coord = |rng: &mut Xorshift64| {
            let sign = if rng.below(2) == 0 { 1.0 } else { -1.0 };
            match coords {
                Coords::Grid => {
                    let v = rng.below(9) as i32 - 4;
                    if v == 0 && rng.below(2) == 0 {
                        -0.0
                    } else {
                        f64::from(v)
                    }
                }
                Coords::Unit => (rng.below(1 << 20) as f64) / f64::from(1 << 19) - 1.0,
                Coords::Garbage => match rng.below(5) {
                    0 => sign * 0.0,
                    1 => sign * 1e300 * (rng.below(1000) as f64 + 1.0) / 1000.0,
                    2 => sign * 1e-300 * (rng.below(1000) as f64 + 1.0) / 1000.0,
                    3 => sign * rng.below(1 << 20) as f64 / f64::from(1 << 20),
                    _ => f64::from(rng.below(9) as i32 - 4),
                },
            }
        };
        let mut set = PolygonSet2::new();
        for _ in 0..n {
            let p = [coord(rng), coord(rng)];
            set.add_vertex(p);
        }
        for _ in 0..rng.below(60) {
            let (s, t) = (rng.below(n as u64) as u32, rng.below(n as u64) as u32);
            set.add_edge_mult(s, t, rng.below(5) as i32 - 2);
        }
        set
    }

    const ALL_COORDS: [Coords; 3] = [Coords::Grid, Coords::Unit, Coords::Garbage];

    #[test]
    fn every_sweep_finds_exactly_the_overlapping_pairs() {
        let mut rng = Xorshift64::new(0x2545_f491_4f6c_dd1d);
        for round in 0..600 {
            let coords = ALL_COORDS[round % 3];
            let (a, b) = (random_set(&mut rng, coords), random_set(&mut rng, coords));
            let m = margin(&a, &b);
            let (ba, bb) = (edge_boxes(&a, m), edge_boxes(&b, m));
            let want = brute_pairs(&ba, &bb);
            let lists = pairs_by_lists(&ba, &bb, UNLIMITED).expect("no budget");
            assert_eq!(sorted(lists), want, "lists, round {round}");
            let buckets = pairs_by_buckets(&ba, &bb, UNLIMITED).expect("no budget");
            assert_eq!(sorted(buckets), want, "buckets, round {round}");
            assert_eq!(
                sorted(pairs_by_trees(&ba, &bb)),
                want,
                "trees, round {round}"
            );
            assert_eq!(sorted(overlapping_pairs(&ba, &bb)), want, "round {round}");
        }
    }

    #[test]
    fn list_sweeps_give_up_beyond_their_budget() {
        // Stacked long boxes: every entering box scans every active one.
        let a = boxes(
            &(0..64)
                .map(|i| (0.0, 9.0, 2.0 * f64::from(i), 2.0 * f64::from(i) + 0.5))
                .collect::<Vec<_>>(),
        );
        let b = boxes(
            &(0..64)
                .map(|i| (1.0, 9.0, 2.0 * f64::from(i) + 1.0, 2.0 * f64::from(i) + 1.5))
                .collect::<Vec<_>>(),
        );
        assert!(pairs_by_lists(&a, &b, (8, 0)).is_none());
        assert_eq!(pairs_by_lists(&a, &b, UNLIMITED), Some(Vec::new()));
        assert!(pairs_by_trees(&a, &b).is_empty());
    }

    /// Many stacked long boxes: the lists scan every active box and give
    /// up; the buckets scan only a slice of y and finish in the same
    /// budget with the same pairs. Boxes as tall as the whole range make
    /// every entering box visit every bucket: the buckets give up too.
    #[test]
    fn buckets_finish_where_lists_give_up() {
        let stack = |offset: f64| {
            boxes(
                &(0..4096)
                    .map(|i| {
                        let y = 2.0 * f64::from(i) + offset;
                        (offset, 9.0, y, y + 1.25)
                    })
                    .collect::<Vec<_>>(),
            )
        };
        let (a, b) = (stack(0.0), stack(1.0));
        let want = brute_pairs(&a, &b);
        assert_eq!(want.len(), 2 * 4096 - 1);
        assert!(pairs_by_lists(&a, &b, (16, 0)).is_none());
        let got = pairs_by_buckets(&a, &b, (16, 0)).expect("within budget");
        assert_eq!(sorted(got), want);
        assert_eq!(sorted(overlapping_pairs(&a, &b)), want);
        let tall = |offset: f64| {
            boxes(
                &(0..4096)
                    .map(|i| {
                        (
                            f64::from(i) * 3.0 + offset,
                            f64::from(i) * 3.0 + offset + 1.0,
                            0.0,
                            1e6,
                        )
                    })
                    .collect::<Vec<_>>(),
            )
        };
        let (a, b) = (tall(0.0), tall(1.5));
        assert!(pairs_by_buckets(&a, &b, (16, 0)).is_none());
        assert_eq!(sorted(overlapping_pairs(&a, &b)), brute_pairs(&a, &b));
    }

    /// The casts by brute force: the sum over every edge, as
    /// `reference.rs` computes it.
    fn brute_casts(queries: &[u32], own: &PolygonSet2, other: &PolygonSet2, ray: Ray) -> Vec<i32> {
        queries
            .iter()
            .map(|&q| {
                let v = own.vertex(q);
                other
                    .edges()
                    .iter()
                    .map(|e| ray.term(&v, e, other.edge_points(e)) as i32)
                    .sum()
            })
            .collect()
    }

    #[test]
    fn both_casts_equal_the_brute_force_sums() {
        let mut rng = Xorshift64::new(0x9e6c_63d0_676a_9a99);
        for round in 0..600 {
            let coords = ALL_COORDS[round % 3];
            let (own, other) = (random_set(&mut rng, coords), random_set(&mut rng, coords));
            let m = margin(&own, &other);
            let boxes = edge_boxes(&other, m);
            // Every vertex is a query (duplicates of x and y included).
            let queries: Vec<u32> = (0..own.vertex_count() as u32).collect();
            for ray in [Ray::Up, Ray::Down] {
                let want = brute_casts(&queries, &own, &other, ray);
                let lists = cast_by_lists(&queries, &own, &boxes, &other, ray, UNLIMITED);
                assert_eq!(lists.as_ref(), Some(&want), "lists, {ray:?}, round {round}");
                let sweeps = cast_by_sweeps(&queries, &own, &boxes, &other, ray);
                assert_eq!(sweeps, want, "sweeps, {ray:?}, round {round}");
            }
        }
    }

    #[test]
    fn pairs_sort_as_a_comparison_sort_does() {
        let mut rng = Xorshift64::new(0x51f1_5eed_0bad_cafe);
        for round in 0..200 {
            let a_edges = 1 + rng.below(50) as usize;
            let b_edges = 1 + rng.below(50);
            let mut all: Vec<(u32, u32)> = (0..rng.below(300))
                .map(|_| (rng.below(a_edges as u64) as u32, rng.below(b_edges) as u32))
                .collect();
            all.sort_unstable();
            all.dedup();
            // The sweep's order: any permutation.
            let mut shuffled = all.clone();
            for i in (1..shuffled.len()).rev() {
                shuffled.swap(i, rng.below(i as u64 + 1) as usize);
            }
            assert_eq!(sort_pairs(&shuffled, a_edges), all, "round {round}");
        }
    }

    #[test]
    fn fenwick_adds_suffixes() {
        let mut f = Fenwick::new(5);
        f.add_from(0, 3);
        f.add_from(2, -1);
        f.add_from(5, 100); // past the end: no position
        assert_eq!((0..5).map(|i| f.at(i)).collect::<Vec<_>>(), [3, 3, 2, 2, 2]);
    }
}
