//! The cell structure computed by the sweep (the boundary self-intersection
//! of section 7.7 with winding numbers, section 7.4.3), its validity check,
//! and the simplified shape for a rule.

use crate::collection::EdgeCollection;
use crate::point::{Pt, SortKey};
use crate::winding::Winding;
use crate::SimplifyError;
use rayon::slice::ParallelSliceMut;
use robust_arith::intersection_error_bound;
use std::borrow::Cow;
use topology::{Edge2, PolygonSet2};

/// One edge of the cell structure, directed from `start` to `end` (the
/// logical leftmost and rightmost points at which the sweep processed it).
///
/// Convention: crossing the edge from its right side to its left side adds
/// `mult` to the winding number, so **`left == right + mult`**. For every
/// edge except the rare downward vertical ones of section 7.6.1 `start`
/// precedes `end` lexicographically, and the left side is the one above.
#[derive(Clone, Debug, PartialEq)]
pub struct CellEdge<W> {
    /// Vertex index of the start point (the logical leftmost point).
    pub start: u32,
    /// Vertex index of the end point (the logical rightmost point).
    pub end: u32,
    /// Multiplicity in the direction `start -> end` (section 6.5).
    pub mult: W,
    /// Winding number of the cell on the left (above).
    pub left: W,
    /// Winding number of the cell on the right (below).
    pub right: W,
    /// Adjustment count (section 8.4): the edge lies within `k * alpha` of
    /// the input edge it originates from.
    pub k: u32,
    /// Index of an input edge it originates from (for Booleans, edges of
    /// the first operand come first, then those of the second, and so on).
    pub origin: u32,
}

/// The rotation of the edges around one processed event point, as recorded
/// by the sweep: the edges that ended there (bottom to top, arriving from
/// the left) and those that started there (bottom to top, leaving to the
/// right), with the winding numbers of the cells below and above the point.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Fan<W> {
    pub(crate) vertex: u32,
    pub(crate) below: W,
    pub(crate) above: W,
    pub(crate) start: u32,
    pub(crate) mid: u32,
    pub(crate) end: u32,
}

/// Counters of one sweep run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SweepStats {
    /// Edges handed to the sweep (before merging identical ones).
    pub input_edges: usize,
    /// Distinct input segments after merging (section 7.1.2).
    pub merged_input_edges: usize,
    /// Event points processed (a point may be processed more than once).
    pub events: u64,
    /// Computed edge-edge intersections (Table 7.2 calls).
    pub intersections: u64,
    /// Edges split at a vertex found on their interior (section 6.5).
    pub vertex_on_edge_splits: u64,
    /// Edges split because they pass through the event point (figure 7.8).
    pub through_splits: u64,
    /// Edges split because they were incorrectly grouped (section 7.6.2).
    pub misgrouped_splits: u64,
    /// Events where the literal linear scans of section 7.6.2 were needed.
    pub full_scans: u64,
    /// The largest number of edges on the sweep line at once.
    pub max_sweep_len: usize,
}

/// The cell structure of an edge collection: every edge of the computed
/// arrangement with the winding numbers on both sides, and the adjustment
/// bound of section 8.4.
///
/// `W` is `i32` for a single input, `[i32; 2]` for a Boolean of two, and
/// `Vec<i32>` for n operands tracked separately.
#[derive(Clone, Debug)]
pub struct CellStructure<W> {
    vertices: Vec<[f64; 2]>,
    edges: Vec<CellEdge<W>>,
    /// The rotations around the vertices (the fans, and the edges they
    /// list), when the sweep recorded them.
    rotations: Option<(Vec<Fan<W>>, Vec<u32>)>,
    /// For a structure kept only for its shape (the sweep's
    /// `Output::Boundary`, never handed to a caller): the selected edges,
    /// keyed as [`CellStructure::selected`] gives them, in place of
    /// `edges` (empty then), 12 bytes an edge instead of a [`CellEdge`].
    boundary: Option<Keyed>,
    k_max: u32,
    alpha: f64,
    dims: usize,
    stats: SweepStats,
    extent: Extent,
}

/// Where a sweep's arrangement lies, every edge counted whether kept or
/// not: the x-range of its processed points and the x-range of its
/// vertical edges (what `strips.rs` needs to join strips: an arrangement
/// inside `[lo, hi]` has a vertical edge on `x = lo` exactly when its
/// vertical edges' least x is `lo`, and likewise for `hi`).
#[derive(Clone, Debug)]
pub(crate) struct Extent {
    pub(crate) x_min: f64,
    pub(crate) x_max: f64,
    pub(crate) vertical_min: f64,
    pub(crate) vertical_max: f64,
    /// Whether the points were processed in increasing lexicographic
    /// order, each once (no backward step of section 7.6.1): then the
    /// vertices of `Output::Boundary` are in lexicographic order.
    pub(crate) ordered: bool,
    /// The last point processed.
    pub(crate) last: [f64; 2],
}

impl Default for Extent {
    fn default() -> Self {
        Extent {
            x_min: f64::INFINITY,
            x_max: f64::NEG_INFINITY,
            vertical_min: f64::INFINITY,
            vertical_max: f64::NEG_INFINITY,
            ordered: true,
            last: [f64::NEG_INFINITY; 2],
        }
    }
}

impl Extent {
    /// Notes a processed point.
    #[inline]
    pub(crate) fn add(&mut self, p: Pt) {
        self.x_min = self.x_min.min(p.x);
        self.x_max = self.x_max.max(p.x);
        let [x, y] = self.last;
        self.ordered &= p.x > x || (p.x == x && p.y > y);
        self.last = [p.x, p.y];
    }

    /// Notes a vertical edge at `x`.
    #[inline]
    pub(crate) fn add_vertical(&mut self, x: f64) {
        self.vertical_min = self.vertical_min.min(x);
        self.vertical_max = self.vertical_max.max(x);
    }
}

impl<W: Winding> CellStructure<W> {
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        vertices: Vec<[f64; 2]>,
        edges: Vec<CellEdge<W>>,
        rotations: Option<(Vec<Fan<W>>, Vec<u32>)>,
        boundary: Option<Keyed>,
        k_max: u32,
        max_abs: f64,
        dims: usize,
        stats: SweepStats,
    ) -> Self {
        CellStructure {
            vertices,
            edges,
            rotations,
            boundary,
            k_max,
            alpha: intersection_error_bound(max_abs),
            dims,
            stats,
            extent: Extent::default(),
        }
    }

    /// The structure with where its sweep's arrangement lies.
    pub(crate) fn with_extent(mut self, extent: Extent) -> Self {
        self.extent = extent;
        self
    }

    /// The vertex positions (every processed event point).
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// The edges. Exactly coincident edges may appear more than once (they
    /// co-exist on the sweep line and bound a cell of zero area, section
    /// 7.4.2). A zero-length edge (`start == end`) appears only in the
    /// degenerate inexact case where an event point is processed a second
    /// time with an edge already starting there in its group; it is kept
    /// because it is part of the rotations checked by
    /// [`Self::check_cells`], and it never reaches a simplified shape.
    pub fn edges(&self) -> &[CellEdge<W>] {
        &self.edges
    }

    /// The largest adjustment count of any edge (section 8.4).
    pub fn k_max(&self) -> u32 {
        self.k_max
    }

    /// `alpha = sqrt(153) u L` (eq. 8.17), `L` the power of two bounding
    /// the input coordinates.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// `eps = (k_max + 1) * alpha`: the sweep is epsilon-tolerant with this
    /// value (section 8.4).
    pub fn epsilon(&self) -> f64 {
        (f64::from(self.k_max) + 1.0) * self.alpha
    }

    /// The counters of the sweep run.
    pub fn stats(&self) -> SweepStats {
        self.stats
    }

    /// Checks that the cell structure is valid: winding numbers consistent
    /// across every edge and around every vertex.
    ///
    /// - every edge: `left == right + mult`, vertex indices in range;
    /// - every recorded event point: going around it, the edges that ended
    ///   there (bottom to top) chain the cell below the point to the cell
    ///   above it (`right` of the first is the cell below, `left` of each is
    ///   `right` of the next, `left` of the last is the cell above), and so
    ///   do the edges that start there; each such edge ends (starts) at that
    ///   vertex;
    /// - every edge ends at exactly one recorded event and starts at exactly
    ///   one (so the rotations cover the structure);
    /// - the first and last events see the unbounded cell (winding zero)
    ///   both below and above.
    ///
    /// Together these make the edges and rotations a cell structure on
    /// which every face has one winding number (section 6.3: the condition
    /// simplification needs beyond shape boundary closure).
    pub fn check_cells(&self) -> Result<(), SimplifyError> {
        let bad = |m: String| {
            Err(SimplifyError::Internal(format!(
                "invalid cell structure: {m}"
            )))
        };
        let nv = self.vertices.len() as u32;
        for (i, e) in self.edges.iter().enumerate() {
            if e.start >= nv || e.end >= nv {
                return bad(format!("edge {i} refers to a missing vertex"));
            }
            let mut l = e.right.clone();
            l.add_assign(&e.mult);
            if l != e.left {
                return bad(format!(
                    "edge {i}: left {:?} != right {:?} + mult {:?}",
                    e.left, e.right, e.mult
                ));
            }
        }
        let Some((fans, fan_edges)) = &self.rotations else {
            return bad("the sweep did not record the rotations".into());
        };
        let mut ended = vec![0u32; self.edges.len()];
        let mut started = vec![0u32; self.edges.len()];
        for (f_i, f) in fans.iter().enumerate() {
            let (s, m, t) = (f.start as usize, f.mid as usize, f.end as usize);
            let (Some(ending), Some(starting)) = (fan_edges.get(s..m), fan_edges.get(m..t)) else {
                return bad(format!("fan {f_i} out of range"));
            };
            for (list, is_end) in [(ending, true), (starting, false)] {
                let mut w = f.below.clone();
                for &ei in list {
                    let Some(e) = self.edges.get(ei as usize) else {
                        return bad(format!("fan {f_i} refers to missing edge {ei}"));
                    };
                    let at = if is_end { e.end } else { e.start };
                    if at != f.vertex {
                        return bad(format!(
                            "edge {ei} listed at vertex {} but not incident",
                            f.vertex
                        ));
                    }
                    if e.right != w {
                        return bad(format!(
                            "around vertex {} (event {f_i}): edge {ei} has {:?} on its right, the cell there has {:?}",
                            f.vertex, e.right, w
                        ));
                    }
                    w = e.left.clone();
                    if is_end {
                        ended[ei as usize] += 1;
                    } else {
                        started[ei as usize] += 1;
                    }
                }
                if w != f.above {
                    return bad(format!(
                        "around vertex {} (event {f_i}): edges reach {:?}, the cell above has {:?}",
                        f.vertex, w, f.above
                    ));
                }
            }
        }
        for i in 0..self.edges.len() {
            if ended[i] != 1 || started[i] != 1 {
                return bad(format!(
                    "edge {i} ends at {} and starts at {} recorded events",
                    ended[i], started[i]
                ));
            }
        }
        let zero = W::zero(self.dims);
        for f in [fans.first(), fans.last()].into_iter().flatten() {
            if f.below != zero || f.above != zero {
                return bad("the outermost events do not see the unbounded cell".into());
            }
        }
        Ok(())
    }

    /// The simplified shape: every edge separating a retained cell from a
    /// discarded one, directed with the retained cell on its left (section
    /// 7.4.3, figure 6.2). Identical edges are merged (section 7.1.2) and
    /// the vertical edges of each x are merged by 1D simplification (section
    /// 7.6.1). The result always satisfies shape boundary closure.
    pub fn shape_with(&self, keep: impl Fn(&W) -> bool) -> PolygonSet2 {
        let sel = match &self.boundary {
            Some(b) => b.clone(),
            None => self.selected(keep),
        };
        shape_of(Cow::Borrowed(&self.vertices), sel, self.boundary.is_some())
    }

    /// The selected edges of a structure kept only for its shape.
    #[cfg(test)]
    pub(crate) fn boundary(&self) -> Option<&Keyed> {
        self.boundary.as_ref()
    }

    /// [`CellStructure::shape_with`], consuming the structure: its edges
    /// are freed once the boundary is selected, which lowers the heap peak
    /// of a simplification by their size (a third on large outputs).
    pub(crate) fn into_shape_with(self, keep: impl Fn(&W) -> bool) -> PolygonSet2 {
        // Fields left out of a pattern would live to the end of the scope.
        let CellStructure {
            vertices,
            edges,
            rotations,
            boundary,
            ..
        } = self;
        // The vertices of a boundary structure are the ends of its
        // selected edges (`Output::Boundary`).
        let (sel, every_used) = match boundary {
            Some(b) => (b, true),
            None => (selected(&vertices, &edges, keep), false),
        };
        drop(edges);
        drop(rotations);
        shape_of(Cow::Owned(vertices), sel, every_used)
    }

    /// A structure kept for its shape only, taken apart (`None` for a
    /// complete structure).
    pub(crate) fn into_boundary_parts(self) -> Option<crate::strips::Part> {
        let CellStructure {
            vertices,
            boundary,
            k_max,
            stats,
            extent,
            ..
        } = self;
        boundary.map(|edges| crate::strips::Part {
            vertices,
            edges,
            k_max,
            stats,
            extent,
        })
    }

    /// The edges separating a retained cell from a discarded one, keyed as
    /// in the edge collection of section 7.1.2 on vertex ids.
    pub(crate) fn selected(&self, keep: impl Fn(&W) -> bool) -> Keyed {
        selected(&self.vertices, &self.edges, keep)
    }
}

/// Keyed edges `(l, r, m)` on vertex ids: `l` precedes `r`
/// lexicographically, `m` the multiplicity in the direction `l -> r`.
pub(crate) type Keyed = Vec<(u32, u32, i32)>;

/// The edges of `edges` separating a cell `keep` accepts from one it
/// rejects, keyed as in the edge collection of section 7.1.2 on the ids of
/// the vertices `v`.
fn selected<W>(v: &[[f64; 2]], edges: &[CellEdge<W>], keep: impl Fn(&W) -> bool) -> Keyed {
    let nv = v.len() as u32;
    let pt = |i: u32| Pt::new(v[i as usize]);
    // The edge collection of section 7.1.2 on vertex ids: every edge is
    // keyed by its lexicographically ordered end points (distinct ids are
    // distinct points), multiplicity negated for right-to-left edges.
    let mut sel: Vec<(u32, u32, i32)> = Vec::with_capacity(edges.len());
    for e in edges {
        if e.start == e.end || e.start >= nv || e.end >= nv {
            continue;
        }
        let (l, r) = (keep(&e.left), keep(&e.right));
        let (a, b) = if l && !r {
            (e.start, e.end)
        } else if r && !l {
            (e.end, e.start)
        } else {
            continue;
        };
        if pt(a) < pt(b) {
            sel.push((a, b, 1));
        } else {
            sel.push((b, a, -1));
        }
    }
    sel
}

/// The shape bounded by the selected keyed edges `sel` on the vertices
/// `v`: identical edges merged, vertical edges merged by 1D simplification,
/// vertices and edges in the canonical order of
/// `EdgeCollection::to_polygon_set`.
///
/// `v` is taken by value when the caller can give it up: when every vertex
/// is used and the ids are already in lexicographic order (the vertices of
/// the sweep's `Output::Boundary`, unless a backward step of section 7.6.1
/// intervened), the ids are the ranks and the vertices the output's, and
/// neither is copied or renumbered. `every_used` tells that every vertex
/// is an end of a selected edge (the vertices of `Output::Boundary`), so
/// that they need not be marked.
fn shape_of(v: Cow<'_, [[f64; 2]]>, sel: Vec<(u32, u32, i32)>, every_used: bool) -> PolygonSet2 {
    let nv = v.len() as u32;
    let pt = |i: u32| Pt::new(v[i as usize]);
    // The vertices the selected edges use (marked with 1 in `rank` until
    // they are ranked), in lexicographic order. Ids were given in event
    // order, which is lexicographic except after the backward steps of
    // section 7.6.1: check before sorting. Not marked when the caller
    // knows that every vertex is used.
    let marks = |rank: &mut Vec<u32>| {
        for &(a, b, _) in &sel {
            rank[a as usize] = 1;
            rank[b as usize] = 1;
        }
    };
    let mut rank = vec![u32::from(every_used); v.len()];
    if every_used {
        debug_assert!({
            let mut used = vec![0; v.len()];
            marks(&mut used);
            used == rank
        });
    } else {
        marks(&mut rank);
    }
    let all_used = every_used || rank.iter().all(|&r| r == 1);
    let (points, mut edges, cancelled) =
        if all_used && v.windows(2).all(|w| Pt::new(w[0]) < Pt::new(w[1])) {
            drop(rank);
            let (edges, cancelled) = merge_keyed(sel, v.len(), |i| i);
            (v.into_owned(), edges, cancelled)
        } else {
            let mut order: Vec<u32> = Vec::with_capacity(v.len());
            order.extend((0..nv).filter(|&i| rank[i as usize] == 1));
            if !order.windows(2).all(|w| pt(w[0]) < pt(w[1])) {
                let mut keyed: Vec<(SortKey, u32)> =
                    order.iter().map(|&i| (pt(i).sort_key(), i)).collect();
                sort_unstable(&mut keyed);
                order = keyed.into_iter().map(|(_, i)| i).collect();
            }
            for (r, &i) in order.iter().enumerate() {
                rank[i as usize] = r as u32;
            }
            let points: Vec<[f64; 2]> = order.iter().map(|&i| v[i as usize]).collect();
            // On ranks, sorting by key is the canonical edge order of
            // `EdgeCollection::to_polygon_set` (vertices lexicographic,
            // edges by key).
            let (edges, cancelled) = merge_keyed(sel, points.len(), |i| rank[i as usize]);
            (points, edges, cancelled)
        };
    let merged = merge_vertical_edges(&mut edges, &points);
    // Every point is used by a selected edge. Unless merging dropped an
    // edge, they all still are, and the points and ranks are the output's.
    let (vertices, edges) = if !cancelled && !merged {
        (points, edges)
    } else {
        // Keep the vertices some edge still uses; renumbering in order
        // keeps the edges sorted.
        let mut new_index = vec![u32::MAX; points.len()];
        for &(a, b, _) in &edges {
            new_index[a as usize] = 0;
            new_index[b as usize] = 0;
        }
        let mut vertices = Vec::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            if new_index[i] == 0 {
                new_index[i] = vertices.len() as u32;
                vertices.push(*p);
            }
        }
        let edges = edges
            .into_iter()
            .map(|(a, b, m)| (new_index[a as usize], new_index[b as usize], m))
            .collect();
        (vertices, edges)
    };
    let out = edges
        .into_iter()
        .map(|(a, b, m)| {
            if m > 0 || m == i32::MIN {
                Edge2 {
                    start: a,
                    end: b,
                    mult: m,
                }
            } else {
                Edge2 {
                    start: b,
                    end: a,
                    mult: -m,
                }
            }
        })
        .collect();
    PolygonSet2::from_parts(vertices, out)
}

impl<W: Winding> CellStructure<W> {
    /// The whole arrangement as a polygon set: every edge with its
    /// total multiplicity over the operands (identical edges merged, zero
    /// cancelled). Its winding numbers are the summed winding numbers of
    /// the input.
    pub fn arrangement(&self) -> EdgeCollection {
        let mut c = EdgeCollection::new();
        for e in &self.edges {
            if let (Some(&a), Some(&b)) = (
                self.vertices.get(e.start as usize),
                self.vertices.get(e.end as usize),
            ) {
                c.add_edge(a, b, e.mult.total());
            }
        }
        c
    }
}

/// Sorts keyed edges `(l, r, m)` on the ranks `rank(l), rank(r) < n` by
/// `(rank(l), rank(r))` and merges identical keys, adding the
/// multiplicities and dropping those that cancel (section 7.1.2); the
/// edges returned are on the ranks. Also returns whether a key cancelled
/// (then a vertex may have lost its last edge).
///
/// A counting sort by `l` (the ranks are dense), the ranks applied as the
/// edges are placed. Only when one was placed out of order, or a key
/// twice, or with multiplicity zero, the runs of equal `l` (the few edges
/// leaving one vertex rightwards) are sorted by `r` and identical keys
/// merged in one pass: the sweep's output edges come in order (it emits an
/// edge when it reaches its right end, so the edges leaving one vertex
/// come in the order of their right ends but for the backward steps of
/// section 7.6.1) and distinct but where coincident edges bound a cell of
/// zero area (section 7.4.2).
fn merge_keyed(
    sel: Vec<(u32, u32, i32)>,
    n: usize,
    rank: impl Fn(u32) -> u32,
) -> (Vec<(u32, u32, i32)>, bool) {
    // The start of the run of each `l`: the counts, then their exclusive
    // prefix sums.
    let mut next = vec![0u32; n];
    for &(a, _, _) in &sel {
        next[rank(a) as usize] += 1;
    }
    let mut sum = 0u32;
    for c in &mut next {
        (*c, sum) = (sum, sum + *c);
    }
    let mut out = vec![(0u32, 0u32, 0i32); sel.len()];
    // Whether the edges are placed in increasing key order (each after a
    // smaller key in its run: sorted, no key twice) with no zero
    // multiplicity: then there is nothing to sort or merge.
    let mut clean = true;
    for (a, b, m) in sel {
        let (a, b) = (rank(a), rank(b));
        let at = &mut next[a as usize];
        let i = *at as usize;
        // The runs fill from their start: the slot before holds the edge
        // placed before this one in the run of `a`, or is not in that run
        // (an earlier run's edge or zeros, `l < a`; nothing precedes the
        // run of `l = 0`).
        let after = i.checked_sub(1).and_then(|j| out.get(j));
        clean &= m != 0 && after.is_none_or(|e| e.0 != a || e.1 < b);
        out[i] = (a, b, m);
        *at += 1;
    }
    if clean {
        return (out, false);
    }
    // Now `next[l]` is where the edges of `l` end and those of `l + 1`
    // start.
    let mut from = 0;
    for &to in &next {
        let run = &mut out[from..to as usize];
        if run.len() > 1 {
            run.sort_unstable_by_key(|e| e.1);
        }
        from = to as usize;
    }
    // In place: the first `w` entries are the result so far.
    let (mut w, mut cancelled) = (0, false);
    for i in 0..out.len() {
        let (a, b, m) = out[i];
        if w > 0 && out[w - 1].0 == a && out[w - 1].1 == b {
            out[w - 1].2 = out[w - 1].2.wrapping_add(m);
        } else {
            if w > 0 && out[w - 1].2 == 0 {
                w -= 1;
                cancelled = true;
            }
            out[w] = (a, b, m);
            w += 1;
        }
    }
    if w > 0 && out[w - 1].2 == 0 {
        w -= 1;
        cancelled = true;
    }
    out.truncate(w);
    (out, cancelled)
}

/// Section 7.6.1, footnote 9: the vertical edges at each x are replaced by
/// their 1D simplification, the elementary intervals between their end
/// points with the summed multiplicity (as
/// [`EdgeCollection::merge_vertical_edges`], on vertex ids).
///
/// `edges` are keyed edges `(l, r, m)` sorted by `(l, r)` with distinct keys
/// and non-zero multiplicities, on the ranks of the lexicographically sorted
/// points `v` (as `merge_keyed` returns them), and they stay so: the
/// intervals take the place of the edges they replace in one pass, without
/// sorting again. The points at one x have consecutive ranks in y order, so
/// the edges leaving them form one run of `edges`, the vertical edges of
/// that x are those of the run whose right end lies at that x too, and the
/// break points of their 1D simplification are found by adding the
/// multiplicities at the ranks of their ends (as `merge_keyed` counts)
/// rather than by sorting marks by y. Returns whether there was an x with
/// two or more vertical edges (else `edges` is untouched).
fn merge_vertical_edges(edges: &mut Vec<(u32, u32, i32)>, v: &[[f64; 2]]) -> bool {
    let x_of = |i: u32| v[i as usize][0];
    // Most shapes have no x with two vertical edges: find the first such x
    // (its vertical edges are consecutive among the vertical edges) before
    // copying anything, then the start of its run.
    let mut last = None;
    let Some(second) = edges.iter().position(|&(l, r, _)| {
        let x = x_of(l);
        x == x_of(r) && last.replace(x) == Some(x)
    }) else {
        return false;
    };
    let x = x_of(edges[second].0);
    let mut i = second;
    while i > 0 && x_of(edges[i - 1].0) == x {
        i -= 1;
    }
    let mut out: Vec<(u32, u32, i32)> = Vec::with_capacity(edges.len());
    out.extend_from_slice(&edges[..i]);
    // The summed multiplicity at each rank from the lowest to the highest
    // end of the vertical edges of one x, `None` at ranks that are not an
    // end of one (they do not break an interval).
    let mut sums: Vec<Option<i32>> = Vec::new();
    while let Some(&(first, _, _)) = edges.get(i) {
        let x = x_of(first);
        let (mut j, mut vertical) = (i, 0);
        let (mut lowest, mut highest) = (u32::MAX, 0);
        while let Some(&(l, r, _)) = edges.get(j) {
            if x_of(l) != x {
                break;
            }
            if x_of(r) == x {
                vertical += 1;
                lowest = lowest.min(l);
                highest = highest.max(r);
            }
            j += 1;
        }
        let run = &edges[i..j];
        i = j;
        if vertical < 2 {
            out.extend_from_slice(run);
            continue;
        }
        sums.clear();
        sums.resize((highest - lowest) as usize + 1, None);
        for &(l, r, m) in run {
            if x_of(r) == x {
                for (end, m) in [(l, m), (r, m.wrapping_neg())] {
                    let s = &mut sums[(end - lowest) as usize];
                    *s = Some(s.unwrap_or(0).wrapping_add(m));
                }
            }
        }
        // Bottom to top, each interval between consecutive break points
        // with a non-zero running sum, after the non-vertical edges leaving
        // lower points and before those leaving its lower end (their right
        // ends lie further right).
        let mut k = 0;
        let mut below: Option<(u32, i32)> = None;
        for (at, s) in (lowest..).zip(&sums) {
            let Some(s) = *s else {
                continue;
            };
            let mut sum = s;
            if let Some((from, run_sum)) = below {
                sum = run_sum.wrapping_add(s);
                if run_sum != 0 {
                    while let Some(&e) = run.get(k) {
                        if e.0 >= from {
                            break;
                        }
                        if x_of(e.1) != x {
                            out.push(e);
                        }
                        k += 1;
                    }
                    out.push((from, at, run_sum));
                }
            }
            below = Some((at, sum));
        }
        out.extend(run[k..].iter().filter(|e| x_of(e.1) != x));
    }
    *edges = out;
    true
}

/// Below this length a sort runs on the calling thread.
const PARALLEL_SORT_MIN: usize = 1 << 14;

/// Sorts `v`, in parallel when it is long. Only used where equal elements
/// are indistinguishable, so the result does not depend on the threads.
pub(crate) fn sort_unstable<T: Ord + Send>(v: &mut [T]) {
    if v.len() >= PARALLEL_SORT_MIN {
        v.par_sort_unstable();
    } else {
        v.sort_unstable();
    }
}

/// Sorts `v` by a comparison, not stably, in parallel when it is long: for
/// callers to whom the order of equal items does not matter.
pub(crate) fn sort_unstable_by<T: Send>(
    v: &mut [T],
    cmp: impl Fn(&T, &T) -> std::cmp::Ordering + Sync,
) {
    if v.len() >= PARALLEL_SORT_MIN {
        v.par_sort_unstable_by(cmp);
    } else {
        v.sort_unstable_by(cmp);
    }
}

/// Sorts `v` by a comparison, stably, in parallel when it is long.
pub(crate) fn sort_stable_by<T: Send>(
    v: &mut [T],
    cmp: impl Fn(&T, &T) -> std::cmp::Ordering + Sync,
) {
    if v.len() >= PARALLEL_SORT_MIN {
        v.par_sort_by(cmp);
    } else {
        v.sort_by(cmp);
    }
}

/// The positions `0..n` in the order of a stable sort by `cmp` on
/// positions. Sorting 4-byte positions instead of the items keeps the
/// merge sort's buffer small (the sweep's 56-byte input records sorted
/// stably needed a buffer as large as the input, which set the memory
/// peak of a simplification with few crossings: 164 against 141 MiB on
/// the 1M-vertex n-gon union), while the merge sort still follows the
/// sorted runs of the input (the rings of a polygon), which an unstable
/// sort in place does not (8% more instructions on the 100k-vertex n-gon
/// union). Positions are `u32`, as the sweep's provenance.
pub(crate) fn stable_order(
    n: usize,
    cmp: impl Fn(usize, usize) -> std::cmp::Ordering + Sync,
) -> Vec<u32> {
    let mut order: Vec<u32> = (0..n as u32).collect();
    sort_stable_by(&mut order, |&a, &b| cmp(a as usize, b as usize));
    order
}

/// Reorders `v` so that its item `j` is the former item `order[j]`
/// (`order` a permutation of the positions of `v`), in place, following
/// the cycles of the permutation.
pub(crate) fn permute<T>(v: &mut [T], mut order: Vec<u32>) {
    const DONE: u32 = u32::MAX;
    for start in 0..order.len().min(v.len()) {
        if order[start] == DONE {
            continue;
        }
        let mut cur = start;
        loop {
            let src = order[cur] as usize;
            order[cur] = DONE;
            if src == start || src >= v.len() {
                break;
            }
            v.swap(cur, src);
            cur = src;
        }
    }
}

/// Gives back the memory of the consumed end of `v`, a vector read from
/// its end: once an eighth of its capacity is unused, it shrinks to its
/// length (in place: the allocator shrinks a block without moving it), so
/// that what the sweep has passed no longer counts towards its peak.
#[inline]
pub(crate) fn release_consumed<T>(v: &mut Vec<T>) {
    let cap = v.capacity();
    if cap >= RELEASE_MIN && v.len() <= cap - cap / 8 {
        v.shrink_to_fit();
    }
}

/// Vectors shorter than this are not shrunk as they are consumed.
const RELEASE_MIN: usize = 1024;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collection::elementary_intervals;
    use std::collections::BTreeMap;
    use test_support::rng::Xorshift64;

    /// `stable_order` and `permute` give the order of a stable sort, on
    /// keys with many ties and runs, on every length around the parallel
    /// threshold.
    #[test]
    fn permuting_by_the_stable_order_is_a_stable_sort() {
        let mut g = Xorshift64::new(0x00DD_BA11_5EED);
        for n in [0, 1, 2, 3, 10, 1000, PARALLEL_SORT_MIN + 7] {
            for range in [2, 50, u64::MAX] {
                // Keys with runs: ascending stretches between random jumps.
                let mut key = 0u64;
                let items: Vec<(u64, usize)> = (0..n)
                    .map(|i| {
                        key = if g.below(8) == 0 {
                            g.below(range)
                        } else {
                            key.saturating_add(g.below(2))
                        };
                        (key % range.max(1), i)
                    })
                    .collect();
                let mut expected = items.clone();
                expected.sort_by_key(|e| e.0);
                let mut v = items.clone();
                let order = stable_order(v.len(), |a, b| items[a].0.cmp(&items[b].0));
                permute(&mut v, order);
                assert_eq!(v, expected, "n {n} range {range}");
            }
        }
    }

    /// Keyed edges `(l, r, m)` on ranks, as `shape_with` builds them.
    type Keyed = Vec<(u32, u32, i32)>;

    /// The unit tests' xorshift generator, reduced to `0..n`.
    struct Rng(Xorshift64);

    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0.below(n as u64) as usize
        }
    }

    /// Random keyed edges on the ranks of random points of a small grid
    /// (so that many points share an x), most of them vertical, some with
    /// multiplicities that wrap when summed.
    fn random_case(rng: &mut Rng) -> (Keyed, Vec<[f64; 2]>) {
        let (nx, ny) = (1 + rng.below(6), 1 + rng.below(9));
        let mut v: Vec<[f64; 2]> = Vec::new();
        for i in 0..nx {
            for j in 0..ny {
                if rng.below(4) > 0 {
                    v.push([i as f64 * 0.5 - 1.0, j as f64 - 3.0]);
                }
            }
        }
        let n = v.len();
        let mut sel = Vec::new();
        if n < 2 {
            return (sel, v);
        }
        for _ in 0..rng.below(60) {
            let a = rng.below(n);
            let b = if rng.below(4) > 0 {
                // A point at the same x, if there is another.
                let same: Vec<usize> = (0..n).filter(|&k| v[k][0] == v[a][0]).collect();
                same[rng.below(same.len())]
            } else {
                rng.below(n)
            };
            if a == b {
                continue;
            }
            let m = match rng.below(20) {
                0 => i32::MIN,
                1 => i32::MAX,
                k => k as i32 % 7 - 3,
            };
            sel.push((a.min(b) as u32, a.max(b) as u32, m));
        }
        (sel, v)
    }

    /// The shape output's previous vertical merge: the vertical edges of
    /// each x with two or more are removed, their elementary intervals
    /// appended, and the whole list sorted again.
    fn merge_vertical_edges_by_sorting(edges: &mut Keyed, v: &[[f64; 2]]) {
        let x_of = |e: &(u32, u32, i32)| v[e.0 as usize][0];
        let mut vertical: Vec<(u32, u32, i32)> = Vec::new();
        edges.retain(|e| {
            let keep = x_of(e) != v[e.1 as usize][0];
            if !keep {
                vertical.push(*e);
            }
            keep
        });
        vertical.sort_by(|a, b| x_of(a).total_cmp(&x_of(b)));
        for group in vertical.chunk_by(|a, b| x_of(a) == x_of(b)) {
            if group.len() < 2 {
                edges.extend_from_slice(group);
                continue;
            }
            let mut marks: Vec<(f64, u32, i32)> = Vec::new();
            for &(l, r, m) in group {
                marks.push((v[l as usize][1], l, m));
                marks.push((v[r as usize][1], r, m.wrapping_neg()));
            }
            elementary_intervals(&mut marks, |from, to, run| edges.push((from, to, run)));
        }
        edges.sort_unstable();
    }

    /// A random permutation of `0..n`.
    fn permutation(rng: &mut Rng, n: usize) -> Vec<u32> {
        let mut p: Vec<u32> = (0..n as u32).collect();
        for i in (1..n).rev() {
            p.swap(i, rng.below(i + 1));
        }
        p
    }

    /// `merge_keyed` sums and sorts as a map does, on the ranks it is
    /// given (the identity or a permutation), and tells whether a key
    /// cancelled.
    #[test]
    fn merge_keyed_sums_in_key_order() {
        let mut rng = Rng(Xorshift64::new(0x9E37_79B9_7F4A_7C15));
        let mut cancelled_cases = 0;
        let mut clean_cases = 0;
        for round in 0..6_000 {
            let (mut sel, v) = random_case(&mut rng);
            let rank: Vec<u32> = if round % 2 == 0 {
                (0..v.len() as u32).collect()
            } else {
                permutation(&mut rng, v.len())
            };
            if round % 3 == 0 {
                // In key order (as the sweep's output mostly is), then
                // sometimes without repeated keys and zero multiplicities:
                // nothing to sort or merge.
                sel.sort_by_key(|e| (rank[e.0 as usize], rank[e.1 as usize]));
                if round % 2 == 0 {
                    sel.dedup_by_key(|e| (e.0, e.1));
                    sel.retain(|e| e.2 != 0);
                    clean_cases += 1;
                }
            }
            let mut map: BTreeMap<(u32, u32), i32> = BTreeMap::new();
            for &(a, b, m) in &sel {
                let s = map.entry((rank[a as usize], rank[b as usize])).or_insert(0);
                *s = s.wrapping_add(m);
            }
            let cancelled = map.values().any(|&m| m == 0);
            let expect: Keyed = map
                .into_iter()
                .filter(|&(_, m)| m != 0)
                .map(|((a, b), m)| (a, b, m))
                .collect();
            let got = merge_keyed(sel, v.len(), |i| rank[i as usize]);
            assert_eq!(got, (expect, cancelled));
            cancelled_cases += usize::from(cancelled);
        }
        assert!(cancelled_cases > 500, "only {cancelled_cases} cancelled");
        assert!(clean_cases > 500);
    }

    /// `shape_of` gives the polygon set of the edge collection of section
    /// 7.1.2 (edges added, vertical edges merged), on ids in lexicographic
    /// order or permuted, with or without unused vertices, borrowed or
    /// owned: both its shortcut (every vertex used, ids in order) and its
    /// general path.
    #[test]
    fn shape_of_matches_the_edge_collection() {
        let mut rng = Rng(Xorshift64::new(0x51A9_E0F5_0000_0001));
        let mut shortcut = 0;
        for round in 0..3_000 {
            let (mut sel, mut v) = random_case(&mut rng);
            if round % 3 > 0 {
                // Only the used vertices, renumbered in order.
                let mut id = vec![u32::MAX; v.len()];
                for &(a, b, _) in &sel {
                    id[a as usize] = 0;
                    id[b as usize] = 0;
                }
                let mut used = Vec::new();
                for (i, p) in v.iter().enumerate() {
                    if id[i] == 0 {
                        id[i] = used.len() as u32;
                        used.push(*p);
                    }
                }
                for e in &mut sel {
                    (e.0, e.1) = (id[e.0 as usize], id[e.1 as usize]);
                }
                v = used;
            }
            if round % 3 == 2 {
                // Ids out of lexicographic order.
                let p = permutation(&mut rng, v.len());
                let mut moved = v.clone();
                for (i, &to) in p.iter().enumerate() {
                    moved[to as usize] = v[i];
                }
                v = moved;
                for e in &mut sel {
                    (e.0, e.1) = (p[e.0 as usize], p[e.1 as usize]);
                }
            }
            let mut c = EdgeCollection::new();
            for &(a, b, m) in &sel {
                c.add_edge(v[a as usize], v[b as usize], m);
            }
            c.merge_vertical_edges();
            let expect = c.to_polygon_set();
            let mut used = vec![false; v.len()];
            for &(a, b, _) in &sel {
                used[a as usize] = true;
                used[b as usize] = true;
            }
            if used.iter().all(|&u| u) && v.windows(2).all(|w| Pt::new(w[0]) < Pt::new(w[1])) {
                shortcut += 1;
            }
            assert_eq!(shape_of(Cow::Borrowed(&v), sel.clone(), false), expect);
            let every_used = used.iter().all(|&u| u);
            assert_eq!(shape_of(Cow::Owned(v.clone()), sel, every_used), expect);
        }
        assert!(shortcut > 500, "only {shortcut} took the shortcut");
    }

    /// The one-pass vertical merge gives exactly the edges and the order of
    /// removing, appending and sorting again.
    #[test]
    fn vertical_merge_matches_a_full_sort() {
        let mut rng = Rng(Xorshift64::new(0x2545_F491_4F6C_DD1D));
        let mut merged = 0;
        for _ in 0..5_000 {
            let (sel, v) = random_case(&mut rng);
            let (edges, _) = merge_keyed(sel, v.len(), |i| i);
            let mut expect = edges.clone();
            merge_vertical_edges_by_sorting(&mut expect, &v);
            let mut got = edges.clone();
            let changed = merge_vertical_edges(&mut got, &v);
            assert_eq!(got, expect, "edges {edges:?} on points {v:?}");
            // It says when it did not touch the edges.
            assert!(changed || got == edges);
            if got != edges {
                merged += 1;
            }
        }
        // The cases do exercise the merge.
        assert!(merged > 1_000, "only {merged} cases changed");
    }
}
